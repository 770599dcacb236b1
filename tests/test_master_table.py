"""The master's table in forecast terms (issue 34, Build item 5): its peak periods cover
every leg's seas (the Tz of the table's columns holding probability and of the records,
as Tp of the JONSWAP), no figure is printed for a period beyond the statistics' Tz range
(a held end value would be a silent extrapolation), and the report's cells equal
voyage_plan.nc."""

import numpy as np
import pytest
import report_fixtures as fx
from test_report_checks import context
from test_voyage_plan_report import SHORT, data, records  # noqa: F401 (the same plan fixtures)

from jls.report import plan_verdict as pv
from jls.sea.spectra import tp_from_tz
from jls.stages.voyage_plan import MASTER_MAX_COLUMNS, master_periods


def plain(markup: str) -> str:
    return markup.replace("\\", "").replace("\u00a0", " ").replace("\u2009", " ").replace("\u200b", "")


def test_the_periods_cover_every_legs_seas_tables_and_records(data, records):
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT)
    tp = plan["tp"].values
    sea = data["sea_states"]
    for leg in ("north_sea", "biscay"):
        p = sea["probability"].sel(leg=leg).fillna(0).sum("hs").values
        tz = np.r_[sea["tz"].values[p > 0], np.loadtxt(records[leg], delimiter=";", skiprows=1,
                                                        usecols=2)]
        lo, hi = tp_from_tz(tz.min(), fx.GAMMA), tp_from_tz(tz.max(), fx.GAMMA)
        assert float(plan["leg_tp_min"].sel(leg=leg)) == pytest.approx(lo, rel=1e-4)
        assert float(plan["leg_tp_max"].sel(leg=leg)) == pytest.approx(hi, rel=1e-4)
        assert tp[0] <= lo and tp[-1] >= hi                   # the whole Tp range of the leg's seas
    assert np.all(np.diff(tp) == 1.0) and tp.size <= MASTER_MAX_COLUMNS
    # the Tz of each column is that of its Tp: the JONSWAP of the assessment
    np.testing.assert_allclose(tp_from_tz(plan["tz"].values, fx.GAMMA), tp, rtol=1e-9)


def test_a_wide_range_widens_the_step_and_still_covers_it():
    tp = master_periods({"wind": (3.2, 9.0), "swell": (8.0, 24.6)})
    assert tp[0] <= 3.2 and tp[-1] >= 24.6 and tp.size <= MASTER_MAX_COLUMNS
    assert np.all(np.diff(tp) == 2.0)
    assert master_periods({"a": (5.4, 8.7)}).tolist() == [5.0, 6.0, 7.0, 8.0, 9.0]


def test_no_figure_beyond_the_statistics_periods_and_the_cells_equal_the_dataset(data, records):
    # records whose Tz runs past the statistics' grid (fx.RESPONSE_TZ ends at 10.5 s)
    long = {k: v for k, v in records.items()}
    path = records["biscay"].replace(".txt", "_long.txt")
    lines = open(records["biscay"]).read().splitlines()
    lines[1] = lines[1].rsplit(";", 1)[0] + "; 13.0000"                 # one hour at Tz 13 s
    open(path, "w").write("\n".join(lines) + "\n")
    long["biscay"] = path
    plan = fx.voyage_plan(data, records=long, hold_points=("biscay",), durations=SHORT)
    assert float(plan["leg_tp_max"].sel(leg="biscay")) == pytest.approx(tp_from_tz(13.0, fx.GAMMA), rel=1e-4)
    assert plan["tp"].values[-1] >= tp_from_tz(13.0, fx.GAMMA)
    beyond = plan["tz"].values > fx.RESPONSE_TZ[-1] + 1e-9
    assert beyond.any() and (~beyond).any()
    wf = plan["master_hs_opwf"]
    assert wf.isel(tp=np.flatnonzero(beyond)).isnull().all()
    assert wf.isel(tp=np.flatnonzero(~beyond)).notnull().all()
    cx = context(data, plan=plan)
    tab = plain(pv.master_table(cx))
    assert "– beyond the statistics' periods" in tab
    best = cx.dg.best
    for leg in ("north_sea", "biscay"):
        row = tab.split(f"[{leg}: OP_WF [m]]")[1].split("\n")[0]
        for tp in plan["tp"].values[~beyond]:
            x = float(wf.sel(candidate=best[0], tugger=best[1], leg=leg, tp=tp))
            assert f"{x:.2f}" in row
    # north_sea's seas end below the last columns: those are greyed for it, not for biscay
    assert "luma(225)" in tab.split("[north_sea: OP_WF [m]]")[1].split("[biscay")[0]


def _windows(data, records, **alpha):
    from jls.sea.hindcast import read_hindcast
    from jls.stages.weather_windows import route_windows
    legs = [dict(leg, duration_h=SHORT[leg["name"]], hold_point=leg["name"] == "biscay")
            for leg in fx.route_config()["legs"]]
    hind = {n: read_hindcast(records[n]) for n in SHORT}
    ds = route_windows(legs, hind, data["response"], fx.CRITERIA, ("baseline", "none"), **alpha)
    ds.attrs["route"] = "test_route"
    return ds


def test_page_one_says_the_weather_windows_use_the_alpha_of_the_table(data, records):
    from test_windows_alpha import TABLE

    from jls.report.weather_windows import window_alpha_text
    from jls.stages.weather_windows import operational_alpha
    op = {"alpha_factors": TABLE}
    plan = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=SHORT, operation=op)
    route = [dict(leg, duration_h=SHORT[leg["name"]], hold_point=leg["name"] == "biscay")
             for leg in fx.route_config()["legs"]]
    table, periods = operational_alpha(route, op)
    assert periods == {"north_sea": 30.0, "biscay": 40.0}
    same = _windows(data, records, alpha_factors=table, leg_period_h=periods)
    tab = plain(pv.master_table(context(data, plan=plan, windows=same)))
    assert f"α from {TABLE['source']}" in tab and "the weather windows use the same α" in tab
    assert "north_sea 30 h, biscay 40 h" in plain(window_alpha_text(same))
    # a constant alpha in the windows and none in the plan: page 1 says they differ
    other = _windows(data, records, alpha=0.9)
    tab = plain(pv.master_table(context(data, plan=fx.voyage_plan(data, records=records, hold_points=("biscay",),
                                                                     durations=SHORT), windows=other)))
    assert "α = 1" in tab and "the weather windows use another: operational factor α = 0.9, a constant" in tab
