"""The PDF assessment report rendered from small synthetic datasets (tests/report_fixtures.py)."""

from __future__ import annotations

import os
import re

import numpy as np
import pypdf
import pytest
import xarray as xr

import report_fixtures as rf
from jls.errors import InputError
from jls.netcdf import merge_complex, split_complex
from jls.report import ReportError, document, figures, render_report
from jls.report.contract import check, digest
from jls.report.markup import cell, t, table

HEADINGS = ["Summary", "Inputs and provenance", "Plant", "Vessel and hinge motion", "Sea states",
            "Operability", "Workability", "Assumptions and validity"]


@pytest.fixture(scope="module")
def data():
    return rf.datasets()


@pytest.fixture(scope="module")
def rendered(data, tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "test_route.pdf"
    path = render_report(out, route="test_route", provenance=rf.provenance(), **data)
    reader = pypdf.PdfReader(path)
    text = "\n".join(page.extract_text() for page in reader.pages)
    text = text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", "")
    return path, reader, text


def section(text, name):
    """Text of one numbered section (from its heading to the next)."""
    k = HEADINGS.index(name)
    start = re.search(rf"^{k + 1}\. {name}$", text, re.M).end()
    if k + 1 == len(HEADINGS):
        return text[start:]
    return text[start:re.search(rf"^{k + 2}\. {HEADINGS[k + 1]}$", text, re.M).start()]


def test_pdf_is_a4_and_has_every_section_in_order(rendered):
    path, reader, text = rendered
    assert path.exists() and path.stat().st_size > 10_000
    w, h = (float(x) for x in reader.pages[0].mediabox[2:])
    assert (round(w), round(h)) == (595, 842)
    positions = []
    for k, name in enumerate(HEADINGS):
        m = re.search(rf"^{k + 1}\. {name}$", text, re.M)
        assert m, f"heading {name!r} missing"
        positions.append(m.start())
    assert positions == sorted(positions)


def test_headline_numbers_equal_workability_dataset(rendered, data):
    text = section(rendered[2], "Summary")
    wr = data["workability"]["workability_route"]
    base = 100 * float(wr.sel(candidate="baseline", tugger="none"))
    m = re.search(r"Route workability, baseline rigging, no tugger\s+(\d+\.\d) %", text)
    assert m and m.group(1) == f"{base:.1f}"
    feasible = data["plant"]["feasible"].astype(bool)
    best = float(wr.where(feasible).max())
    m = re.search(r"Route workability, best combination\s+(\d+\.\d) %", text)
    assert m and m.group(1) == f"{100 * best:.1f}"
    # the summary table carries every candidate x tugger, legs and route
    for c in wr["candidate"].values:
        for tg in wr["tugger"].values:
            assert f"{100 * float(wr.sel(candidate=c, tugger=tg)):.1f} %" in text
            for leg in data["sea_states"]["leg"].values:
                w = data["workability"]["workability_leg"].sel(candidate=c, tugger=tg, leg=leg)
                assert f"{100 * float(w):.1f} %" in text
    assert "Governing criterion: relative sway" in text


def test_provenance_hashes_and_vessel_source_appear(rendered):
    text = section(rendered[2], "Inputs and provenance")
    prov = rf.provenance()
    assert prov["config_sha256"] in text
    for item in prov["inputs"].values():                  # on two lines of 32
        assert item["sha256"][:32] in text and item["sha256"][32:] in text
    assert "synthetic_beam_sea.nc" in text
    assert "representative" in text.lower()
    assert rf.OUTSIDE_REASON in " ".join(text.split())
    for name, version in prov["packages"].items():
        assert name in text and version in text


def test_plant_sea_operability_and_validity_content(rendered, data):
    text = rendered[2]
    plant = section(text, "Plant")
    for c in ("baseline", "detuned"):
        t1 = float(data["plant"]["natural_period"].sel(candidate=c).isel(mode=0))
        assert f"{t1:.3f}" in plant
    assert "21 400" in plant                                   # baseline forward wire tension
    sea = section(text, "Sea states")
    for leg in ("north_sea", "biscay"):
        steep = float(data["sea_states"]["steep_probability"].sel(leg=leg))
        assert f"{100 * steep:.1f} %" in sea
    oper = section(text, "Operability")
    assert "steepness ceiling" in oper and "relative sway" in oper
    valid = section(text, "Assumptions and validity")
    for phrase in ("Linear frequency-domain model", "Rayleigh", "without winch limits",
                   "No structural check", "in air", "16.8 %", "33.4 %", "centre"):
        assert phrase in valid


def test_linear_range_flags_match_an_independent_count(rendered, data):
    sea, resp, work = data["sea_states"], data["response"], data["workability"]
    dg = digest("test_route", sea, data["vessel_motion"], data["plant"], resp, work, rf.provenance())
    unit = resp["mpm"].sel(candidate="baseline", tugger="none", heading=90.0).sel(tz=sea["tz"])
    hs = sea["hs"].broadcast_like(sea["hs_upper"])
    big = ((hs * unit.sel(response="relative_sway") > 6.0)
           | (hs * unit.sel(response="relative_yaw") > 5.0)
           | (hs * unit.sel(response="relative_roll") > 5.0))
    live = sea["probability"] > 0
    lin = dg.linear[("baseline", "none")]
    assert lin["cells"] == int((big & live).sum()) > 0
    prob = float(((sea["probability"] * (big & live)).sum(("hs", "tz")) * sea["leg_weight"]).sum())
    assert lin["route_probability"] == pytest.approx(prob)
    valid = section(rendered[2], "Assumptions and validity")
    assert f"{lin['cells']} cells carrying {100 * prob:.1f} %" in valid


def test_missing_variable_is_a_clear_error_and_leaves_no_pdf(data, tmp_path):
    broken = dict(data, workability=data["workability"].drop_vars("hs_limit"))
    out = tmp_path / "report.pdf"
    with pytest.raises(InputError, match=r"workability: missing variable\(s\) hs_limit"):
        render_report(out, route="r", provenance=rf.provenance(), **broken)
    assert list(tmp_path.iterdir()) == []


def test_wrong_dimensions_are_named(data):
    work = data["workability"].copy()
    work["workability_route"] = work["workability_route"].expand_dims(extra=[0])
    with pytest.raises(InputError, match="workability: wrong dimensions workability_route"):
        check(dict(data, workability=work))


def test_failure_mid_render_keeps_the_previous_report(data, tmp_path, monkeypatch):
    out = tmp_path / "report.pdf"
    out.write_bytes(b"previous report")

    def broken(*args, **kwargs):
        raise RuntimeError("figure failed")
    monkeypatch.setattr(figures, "operability", broken)
    with pytest.raises(RuntimeError, match="figure failed"):
        render_report(out, route="r", provenance=rf.provenance(), **data)
    assert out.read_bytes() == b"previous report"
    assert [p.name for p in tmp_path.iterdir()] == ["report.pdf"]


def test_typesetting_failure_is_a_report_error_without_partial_file(data, tmp_path, monkeypatch):
    monkeypatch.setattr(figures, "rigging", lambda *a, **k: tmp_path / "rigging.svg")
    for name in ("hinge_raos", "relative_transfer", "operability", "workability_bars", "scatter"):
        monkeypatch.setattr(figures, name, lambda *a, **k: tmp_path / "x.svg")
    monkeypatch.setattr(document, "source", lambda cx: "#let x = (\n")
    out = tmp_path / "sub" / "report.pdf"
    with pytest.raises(ReportError, match="typesetting the report failed"):
        render_report(out, route="r", provenance=rf.provenance(), **data)
    assert list((tmp_path / "sub").iterdir()) == []


def test_provenance_must_carry_the_config_hash(data, tmp_path):
    prov = rf.provenance()
    del prov["config_sha256"]
    with pytest.raises(InputError, match="provenance lacks config_sha256"):
        render_report(tmp_path / "r.pdf", route="r", provenance=prov, **data)


def test_complex_variables_whole_or_split(data):
    whole = {k: merge_complex(v) for k, v in data.items()}
    split = {k: split_complex(v) for k, v in data.items()}
    assert "rao_re" in split["vessel_motion"] and "rao" in whole["vessel_motion"]
    check(whole)                                     # no error either way
    check(split)


def test_fixture_is_self_consistent(data):
    sea, work = data["sea_states"], data["workability"]
    np.testing.assert_allclose(sea["probability"].sum(("hs", "tz")), 1.0)
    passes = work["passes"].sel(tz=sea["tz"]).fillna(0) > 0.5
    leg = (sea["probability"] * sea["heading_probability"] * passes).sum(("heading", "hs", "tz"))
    xr.testing.assert_allclose(leg.transpose(*work["workability_leg"].dims), work["workability_leg"])
    assert 0.5 < float(work["workability_route"].min()) < float(work["workability_route"].max()) < 1.0
    assert bool(data["plant"]["feasible"].all())


def test_markup_escapes_data_text():
    assert t("a_b #c *d* $e$ [f] <g> @h") == r"a\_b \#c \*d\* \$e\$ \[f\] \<g\> \@h"
    assert t("x_y=1", wrap=True) == "x\\_\u200by\\=\u200b1"
    src = table("cap_tion", ["a", cell("*b*", raw=True)], [["1_2", cell("z")]])
    assert "cap\\_tion" in src and "[1\\_\u200b2]" in src and "[*b*]" in src


def test_report_is_readable_like_other_outputs(rendered):
    mask = os.umask(0)
    os.umask(mask)
    assert rendered[0].stat().st_mode & 0o777 == 0o666 & ~mask
