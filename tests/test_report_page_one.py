"""Page 1 is one page that decides (issue 34, Build item 1): the summary ends on the
first page (its text holds the heading of chapter 2, "Assessment in detail") on the
synthetic route and on a grid of many options, and page 1 names every criterion that binds
the recommendation with its figure: "tip" when the tip clearance binds, "tension" when
the wire tension binds or its dynamic amplification exceeds the design value."""

from __future__ import annotations

import re
from types import SimpleNamespace

import pypdf
import report_fixtures as rf
import xarray as xr

from jls.names import TIP_AIR_GAP_M, WIRE_TENSION_CRITERION
from jls.report import page_one
from jls.report.document import render_report


def first_page(path) -> str:
    text = pypdf.PdfReader(path).pages[0].extract_text()
    return re.sub(r"\s+", " ", text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", ""))


def summary_ends_on_page_one(path) -> bool:
    return "2. Assessment in detail" in first_page(path)


def test_the_summary_of_the_synthetic_route_fits_on_page_one(tmp_path):
    data = rf.datasets()
    w = data["workability"].copy()
    w.attrs["warnings"] = ("leg north_sea: the record covers 6 of the 12 calendar months\n"
                           "RAO file: the heading 80 deg is interpolated")
    out = render_report(tmp_path / "r.pdf", route="r", voyage=rf.voyage(data), provenance=dict(
        rf.provenance(), route_description="North Sea to Biscay, two legs"), **dict(data, workability=w))
    assert summary_ends_on_page_one(out)
    page = first_page(out).split("2. Assessment in detail")[0]             # the summary
    assert "Recommendation:" in page and "Binding criteria:" in page
    assert "Vessel:" in page and "Sea model:" in page and "nonlinear reference" in page
    assert "covers 6 of the 12 calendar months" in page           # the inputs' warnings reach page 1
    # what moved: the route description, table 1 and the selection rule, after page 1
    assert "North Sea to Biscay" not in page and "Workability per leg and for the route" not in page
    assert "((" not in page.replace(" ", "")                         # no nested parentheses opened at once


def test_many_input_warnings_are_counted_on_page_one_and_listed_after(tmp_path):
    data = rf.datasets()
    w = data["workability"].copy()
    lines = [f"leg north_sea: record line {k} has no wave direction and is left out of the table" for k in range(30)]
    w.attrs["warnings"] = "\n".join(lines)
    out = render_report(tmp_path / "r.pdf", route="r", provenance=rf.provenance(), **dict(data, workability=w))
    assert summary_ends_on_page_one(out)
    page = first_page(out).split("2. Assessment in detail")[0]
    assert "Input warnings: 30, listed in full in section 2" in page and "record line 0" not in page
    rest = " ".join(p.extract_text() for p in pypdf.PdfReader(out).pages[1:4])
    assert "record line 29 has no wave direction" in re.sub(r"\s+", " ", rest)


def test_a_grid_of_many_options_keeps_page_one_to_one_page(tmp_path):
    """Page 1 counts exclusions and ties rather than listing them: a grid of many rigging
    candidates and tugger settings still ends its summary on page 1."""
    cands = {**rf.CANDIDATES, **{f"c{i}": {"top_spread_y": 36.0 + 0.5 * i, "drop_height": 56.0 + 0.75 * i}
                                 for i in range(14)}}
    tugs = {"none": 0.0, "a": 250.0, "b": 500.0, "reference": 1000.0, "high": 2000.0}
    data = rf.datasets(candidates=cands, tuggers=tugs)
    assert data["workability"].sizes["candidate"] * data["workability"].sizes["tugger"] == 80
    out = render_report(tmp_path / "r.pdf", route="r", voyage=rf.voyage(data), provenance=rf.provenance(), **data)
    assert summary_ends_on_page_one(out)


def _cx(shares: dict, daf: float = 1.0, criteria=None):
    """A context of one option whose route-weighted governing shares are ``shares``."""
    crit = list(criteria or shares)
    best = ("detuned", "none")
    g = xr.DataArray([[[[shares.get(c, 0.0) for c in crit]]]], dims=("candidate", "tugger", "leg", "criterion"),
                     coords={"candidate": [best[0]], "tugger": [best[1]], "leg": ["a"], "criterion": crit})
    work = xr.Dataset({"governing_share": g, "dynamic_amplification": (("candidate", "tugger"), [[daf]])},
                      coords={"candidate": [best[0]], "tugger": [best[1]]}, attrs={"daf_limit": 1.1})
    dg = SimpleNamespace(criteria=crit, best=best, governing={best: dict(shares)},
                         limits={WIRE_TENSION_CRITERION: 0.1})
    return SimpleNamespace(work=work, dg=dg, sea=xr.Dataset({"leg_weight": ("leg", [1.0])}, coords={"leg": ["a"]}),
                           plan=None, voyage=None, sec=lambda key: f"section {key}", has=lambda key: True)


def test_page_one_names_the_tip_clearance_when_it_binds():
    text = page_one.binding(_cx({"relative_sway_m": 0.02, TIP_AIR_GAP_M: 0.013}))
    assert "tip air gap fails 1.3 %" in text.replace("\u00a0", " ")
    assert "relative sway fails 2.0 %" in text.replace("\u00a0", " ")
    assert "tip" not in page_one.binding(_cx({"relative_sway_m": 0.02, TIP_AIR_GAP_M: 0.0}))


def test_page_one_names_the_wire_tension_when_it_binds_or_its_daf_exceeds_the_design_value():
    from jls.report.wire_loads import binding_figures
    crit = ["relative_sway_m", WIRE_TENSION_CRITERION]
    binds = _cx({"relative_sway_m": 0.02, WIRE_TENSION_CRITERION: 0.01})
    text = page_one.binding(binds) + binding_figures(binds)
    assert "tension" in text and text.count("1.0\u00a0%") + text.count("1.0 %") == 1   # stated once
    daf = _cx({"relative_sway_m": 0.02, WIRE_TENSION_CRITERION: 0.0}, daf=1.28)
    assert "1.28, above the design value 1.10" in binding_figures(daf)
    neither = _cx({"relative_sway_m": 0.02}, daf=1.05, criteria=crit)
    assert "tension" not in page_one.binding(neither) + binding_figures(neither)


def test_nothing_binds_a_recommendation_that_fails_no_sea_state():
    text = page_one.binding(_cx({"relative_sway_m": 0.0}))
    assert "Binding criteria:* none" in text and "fails 0" not in text
