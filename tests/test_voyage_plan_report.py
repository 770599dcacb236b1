"""The voyage as it will be sailed in the report: page 1's first paragraph ("Acceptable"
or "Not acceptable") on every path -- unrestricted acceptable or not, weather-restricted
that sails or that never departs, a route of tables only -- the master's forecast table
and the chapter "Voyage plan" equal to voyage_plan.nc, and levels beyond the linear model
never printed as figures."""

import numpy as np
import pytest
import report_fixtures as fx
from test_report_checks import chapter, context, flat, headings, pdf_text

from jls.report import plan_verdict as pv
from jls.report import voyage_plan as vp
from jls.report.document import render_report

BIG = {"relative_sway_m": 1000.0, "relative_yaw_deg": 1000.0}
TIGHT = {"relative_sway_m": 0.6, "relative_yaw_deg": 1000.0}
SHORT = {"north_sea": 30.0, "biscay": 40.0}


@pytest.fixture(scope="module")
def data():
    return fx.datasets()


@pytest.fixture(scope="module")
def records(tmp_path_factory):
    return fx.write_records(tmp_path_factory.mktemp("records"))


def plain(markup: str) -> str:
    """Markup as the reader sees its words: no escapes, plain spaces."""
    return markup.replace("\\", "").replace("\u00a0", " ").replace("\u2009", " ")


def first_paragraph(markup: str) -> str:
    return plain(markup).strip().split("\n")[0]


def test_tables_only_route_not_acceptable_and_says_why_no_simulation(data):
    plan = fx.voyage_plan(data)
    cx = context(data, plan=plan)
    text = plain(pv.verdict(cx))
    assert first_paragraph(text).startswith("Not acceptable as an unrestricted transit")
    assert "Not acceptable as a weather-restricted transit either" in text
    assert "leg biscay (96 h) is longer than 72 h" in text
    assert "No departure simulation" in text and "scatter table only" in text
    # the governing design level is beyond the linear model: stated, not printed
    best = cx.dg.best
    c, leg = pv.governing(plan, best)
    x = float(plan["design_level"].sel(candidate=best[0], tugger=best[1], criterion=c, leg=leg))
    if x > 6.0 and c == "relative_sway_m":
        assert "beyond the model" in text and f"{x:.2f}" not in text


def test_unrestricted_acceptable(data):
    cx = context(data, plan=fx.voyage_plan(data, criteria=BIG))
    text = plain(pv.verdict(cx))
    assert first_paragraph(text).startswith("Acceptable as an unrestricted transit")
    assert "As a weather-restricted transit it would not qualify" in text


def test_weather_restricted_sails_and_the_numbers_equal_the_dataset(data, records):
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT, criteria=TIGHT)
    cx = context(data, plan=plan)
    best = cx.dg.best
    text = flat(plain(pv.verdict(cx)))
    assert text.startswith("Not acceptable as an unrestricted transit")
    assert "Acceptable as a weather-restricted transit in 2 stretches (hold point: biscay)" in text
    sel = {"candidate": best[0], "tugger": best[1]}
    frac = float(plan["plan_departure_fraction"].sel(sel))
    w50, w90 = (float(plan["plan_wait_h"].sel(sel).sel(quantile=q)) for q in (0.5, 0.9))
    exc = float(plan["plan_exceedance_probability"].sel(sel))
    assert f"{100 * frac:.1f} % of hours allow departure from the first hold point" in text
    assert f"median wait {w50:.0f} h (90 %: {w90:.0f} h)" in text
    assert f"exceeds a limit {exc:.2f}" in text
    # the synthetic records were not binned into the tables: page 1 says so
    assert "disagree" in text
    # the master's table: OP_WF per leg and peak period, the dataset's values
    tab = plain(pv.master_table(cx))
    wf = plan["master_hs_opwf"].sel(sel)
    for tp in (6.0, 10.0):
        row = [f"{float(wf.sel(leg=leg, tp=tp)):.2f}" for leg in ("north_sea", "biscay")]
        assert all(v in tab for v in row)
    assert "α = 1" in tab


def test_weather_restricted_that_never_departs_is_not_acceptable(data, records):
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT,
                          criteria={"relative_sway_m": 0.001, "relative_yaw_deg": 1000.0},
                          operation={"departure_rule": {"max_wait_h": 48}})
    cx = context(data, plan=plan)
    text = plain(pv.verdict(cx))
    assert first_paragraph(text).startswith("Not acceptable as an unrestricted transit")
    assert "Not acceptable as a weather-restricted transit either: no departure of the season sails" in text


def test_chapter_greys_levels_beyond_the_model(data, records):
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",))
    cx = context(data, plan=plan)
    ch = plain(vp.chapter(cx))
    lv = plan["design_level"].sel(criterion="relative_sway_m")
    beyond = float(lv.max()) > 6.0
    assert ("fill: luma(225)" in ch) == beyond
    for x in lv.values.ravel():
        if x > 6.0:
            assert f"{x:.2f} m" not in ch
    for c, tg in cx.dg.table.combos:
        exc = float(plan["plan_exceedance_probability"].sel(candidate=c, tugger=tg))
        assert f"{exc:.3f}" in ch


@pytest.mark.slow
def test_rendered_report_opens_with_the_verdict(data, records, tmp_path):
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT, criteria=TIGHT)
    out = render_report(tmp_path / "r.pdf", route="r", voyage=fx.voyage(data), voyage_plan=plan,
                        provenance=dict(fx.provenance(), route_description="North Sea to Biscay"), **data)
    text = pdf_text(out)
    assert "Voyage plan" in headings(text)
    page1 = flat(chapter(text, "Summary"))
    assert page1.strip().startswith("Not acceptable as an unrestricted transit")
    assert "Forecast limits for the master" in page1
    assert np.isfinite(float(plan["plan_exceedance_probability"].max()))


def test_page_1_recommendation_ranked_by_the_plan(data, records):
    from jls.report.summary import recommendation
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT, criteria=TIGHT)
    w = data["workability"].copy()
    w.attrs["recommendation_objective"] = "voyage_plan"
    p = plan["plan_exceedance_probability"].sel(candidate=w["candidate"], tugger=w["tugger"])
    # constructed so that the ranking is known: the detuned rigging with the reference
    # tugger exceeds least
    p = p.copy(data=np.where((p["candidate"] == "detuned") & (p["tugger"] == "reference"), 0.01, 0.2))
    w["plan_inside_probability"] = 1 - p
    w["plan_wait_median_h"] = plan["plan_wait_h"].sel(quantile=0.5, drop=True)
    w["plan_wait_p90_h"] = plan["plan_wait_h"].sel(quantile=0.9, drop=True)
    cx = context(dict(data, workability=w), plan=plan)
    assert cx.dg.best == ("detuned", "reference")
    text = plain(recommendation(cx))
    assert "probability that a sailed voyage exceeds a limit 0.010 against 0.200" in text
    assert "stays a planning figure" in text


def test_page_1_says_why_a_route_without_records_ranks_by_workability(data):
    from jls.report.summary import recommendation
    w = data["workability"].copy()
    w.attrs["recommendation_objective"] = "voyage_plan"
    cx = context(dict(data, workability=w), plan=fx.voyage_plan(data))
    text = plain(recommendation(cx))
    assert "route workability" in text
    assert "no departure simulation on this route" in text and "ranked by route workability" in text
