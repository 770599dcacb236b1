"""A report that reads cleanly: dataset file names and configuration keys only in the
provenance chapter and the appendix (at most 3 pages, never page 1); long tables in the
appendix with the body's selection rule; a short feasibility cell; the recommended
rigging drawn; comparisons at the governing heading; the title block's `document:` block
shown in the shipped configuration."""

import copy
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pypdf
import pytest
import report_fixtures as rf
import xarray as xr
import yaml
from test_report_checks import context

from jls.config.loader import load, schema, validate
from jls.report import control, long_tables, plant
from jls.report.context import governing_heading
from jls.report.document import render_report

ROOT = Path(__file__).resolve().parents[1]
PROVENANCE, APPENDIX = "Inputs and provenance", "Appendix: every heading, datasets and configuration keys"


def config_keys() -> set:
    """Every property name of the configuration schema with an underscore (a word of
    prose has none)."""
    out = set()

    def walk(node):
        if isinstance(node, dict):
            for k, v in node.get("properties", {}).items():
                out.add(k)
                walk(v)
            for k in ("items", "additionalProperties"):
                walk(node.get(k))
            for k in ("oneOf", "anyOf"):
                for v in node.get(k, []):
                    walk(v)
            for v in node.get("$defs", {}).values():
                walk(v)
    walk(schema())
    return {k for k in out if "_" in k}


def names_outside(pages: list[str]) -> dict:
    """{page number: names} of dataset files and configuration keys outside the provenance
    chapter and the appendix: each page is split at its chapter headings, the text before
    the first belonging to the chapter the previous page ended in."""
    keys = config_keys()
    out, chapter = {}, ""
    for i, text in enumerate(pages, 1):
        parts = re.split(r"^\d+\. (\S[^\n]*)$", text, flags=re.M)
        segments = [(chapter, parts[0])] + [(parts[k].strip(), parts[k + 1]) for k in range(1, len(parts), 2)]
        chapter = segments[-1][0]
        found = set()
        for name, seg in segments:
            if name in (PROVENANCE, APPENDIX):
                continue
            found |= set(re.findall(r"\b[\w-]+\.nc\b", seg))
            found |= {k for k in keys if re.search(rf"(?<![\w/.-]){re.escape(k)}(?!\w)", seg)}
        if found:
            out[i] = sorted(found)
    return out


def appendix_pages(pages: list[str]) -> int:
    first = next(i for i, p in enumerate(pages) if re.search(rf"^\d+\. {re.escape(APPENDIX)}$", p, re.M))
    return len(pages) - first


def pages_of(path) -> list[str]:
    return [p.extract_text().replace("\xa0", " ") for p in pypdf.PdfReader(path).pages]


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    data = rf.datasets()
    out = render_report(tmp_path_factory.mktemp("clean") / "r.pdf", route="r", voyage=rf.voyage(data),
                        provenance=rf.provenance(), **data)
    return pages_of(out)


def test_no_dataset_file_or_configuration_key_in_the_body(pages):
    assert names_outside(pages) == {}
    assert 1 <= appendix_pages(pages) <= 3
    assert not re.search(r"\.nc\b", pages[0])


def test_the_scan_finds_a_name_in_the_body():
    pages = ["1. Summary\nfrom workability.nc", "3. Inputs and provenance\nresponse.nc",
             "4. Plant\nsea hs_in_bin centre"]
    assert names_outside(pages) == {1: ["workability.nc"], 3: ["hs_in_bin"]}


def test_the_document_block_shown_in_the_configuration_fills_the_title_block():
    text = (ROOT / "config" / "config.yaml").read_text()
    block = re.search(r"^# document:\n((?:#   .*\n)+)", text, re.M)
    assert block, "config/config.yaml shows no commented document: block"
    doc = yaml.safe_load("document:\n" + "".join(line[2:] for line in block.group(1).splitlines(True)))
    cfg = copy.deepcopy(load(ROOT / "config" / "config.yaml"))
    cfg.update(doc)
    out = validate(cfg)
    info = control.document_info({"document": out["document"]})
    assert info["number"] and info["client"] and info["approved"]
    assert "document" in (ROOT / "docs" / "report.md").read_text()


def test_the_recommended_rigging_is_always_drawn():
    dg = SimpleNamespace(plot=SimpleNamespace(candidates=["baseline"]), best=("detuned", "none"))
    assert plant.drawn(dg) == ["baseline", "detuned"]
    dg.plot.candidates = ["baseline", "detuned"]
    assert plant.drawn(dg) == ["baseline", "detuned"]


def test_governing_heading_is_the_least_workable():
    curve = xr.DataArray(np.array([[[[4.0, 3.0], [2.0, 1.0], [3.0, 3.0]]]]),
                         dims=("candidate", "tugger", "heading", "tz_curve"),
                         coords={"candidate": ["baseline"], "tugger": ["none"], "heading": [0.0, 90.0, 180.0],
                                 "tz_curve": [6.0, 7.0]})
    cx = SimpleNamespace(work=xr.Dataset({"hs_limit_curve": curve}),
                         dg=SimpleNamespace(baseline="baseline", no_tugger="none"))
    assert governing_heading(cx) == 90.0


def test_long_peak_table_goes_to_the_appendix():
    cx = context(rf.datasets())
    rows = long_tables.peak_rows(cx, cx.vessel["heading"].values)
    assert len(rows) == 4 * cx.vessel.sizes["heading"]
    assert long_tables.is_long(rows * 5) and not long_tables.is_long(rows[:4])


def test_feasibility_cell_is_short_with_the_details_below(pages):
    text = "\n".join(pages)
    assert "Feasibility in full:" in text or "at limit" not in text
