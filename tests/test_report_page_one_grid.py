"""A report with a 10 000-candidate grid still has a one-page first page (issue 34,
Tests): page 1 counts exclusions and ties rather than listing them, and its tables run
per leg, not per option.

The full report of 10 000 candidates takes many minutes (its appendix tables and
figures); page 1 is built here by the report's own functions alone: the Typst source's
title block and chapter 1 (:func:`jls.report.document.source` with the chapters cut to
the first), compiled by :func:`jls.report.document.compile_pdf`. Every reference page 1
makes to a later chapter, table or figure gets a bare target after a page break, so the
source compiles; page 1 fits when the PDF has exactly one page before that break."""

from __future__ import annotations

import re
import shutil
from importlib import resources

import numpy as np
import pypdf
import pytest
import report_fixtures as rf
from test_report_checks import context

from jls.report import document
from jls.report.chapters import CHAPTERS, present_chapters

N_CANDIDATES = 10_000


def page_one_pdf(cx, tmp_path, monkeypatch):
    """Page 1 of the report of ``cx`` compiled alone, then a page of reference targets."""
    monkeypatch.setattr(document, "CHAPTERS", CHAPTERS[:1])
    src = document.source(cx)
    targets = []
    for label in sorted(set(re.findall(r"@([A-Za-z0-9_:.-]+)\[", src))):
        targets.append(f"= Target <{label}>" if not label.startswith(("tab-", "fig-")) else
                       f"#figure([], kind: {'table' if label.startswith('tab-') else 'image'}) <{label}>")
    src += "\n#pagebreak()\n#metadata(\"targets\")\n" + "\n".join(targets) + "\n"
    with resources.as_file(resources.files("jls.report").joinpath("template.typ")) as tpl:
        shutil.copyfile(tpl, tmp_path / "template.typ")
    (tmp_path / "page1.typ").write_text(src, encoding="utf-8")
    out = tmp_path / "page1.pdf"
    document.compile_pdf(tmp_path / "page1.typ", out, cx.prov.get("created"))
    return src, pypdf.PdfReader(out)


@pytest.mark.slow
def test_a_ten_thousand_candidate_grid_keeps_page_one_to_one_page(tmp_path, monkeypatch):
    # a 100 x 100 grid of top spread and drop height, 1.5 cm and 2 cm apart: every
    # candidate another rigging (recommendation.same_rigging_tolerance_m is 1 cm)
    y, d = np.meshgrid(36.0 + 0.015 * np.arange(100), 56.0 + 0.02 * np.arange(100), indexing="ij")
    grid = {f"g{i:05d}": {"top_spread_y": float(a), "drop_height": float(b)}
            for i, (a, b) in enumerate(zip(y.ravel(), d.ravel()))}
    cands = {**rf.CANDIDATES, **dict(list(grid.items())[:N_CANDIDATES - len(rf.CANDIDATES)])}
    data = rf.datasets(candidates=cands, tuggers={"none": 0.0})
    assert data["workability"].sizes["candidate"] == N_CANDIDATES
    cx = context(data, voy=rf.voyage(data), plan=rf.voyage_plan(data))
    cx.sections = present_chapters(cx)
    src, pdf = page_one_pdf(cx, tmp_path, monkeypatch)
    pages = [p.extract_text() for p in pdf.pages]
    # the targets' page is the last; everything before it is page 1
    assert "Target" in pages[-1] and "Target" not in pages[0]
    assert len(pages) == 2, f"page 1 of a {N_CANDIDATES}-candidate report runs to {len(pages) - 1} pages"
    text = re.sub(r"\s+", " ", pages[0].replace("\u00a0", " "))
    assert "Summary" in text and "Recommendation:" in text and "Binding criteria:" in text
    assert "Forecast limits for the master" in text                  # the master's table is on it
