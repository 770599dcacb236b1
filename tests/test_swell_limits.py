"""The master's table per swell system (jls.assessment.swell_limits): the swell OP_LIM with
the wind sea at the leg's typical state, every criterion of the forecast counted (relative
motions, tip clearance, wire tension). Checked against the forecast's own evaluation of
the combined sea (no superposition there): at the swell limit the largest utilisation is 1
exactly; a larger wind sea lowers the limit; with no wind sea it is the single system's
OP_LIM; OP_WF takes the operation's alpha as the master's table does."""

import numpy as np
import pandas as pd
import pytest

from jls.assessment.operation import AlphaTable
from jls.assessment.swell_limits import (
    HS_SEARCH_M,
    WindSea,
    swell_limits,
    typical_wind_sea,
)
from jls.sea.sea_state import SeaState, WaveSystem, parse_spreading
from jls.stages.swell_limits import criteria_of
from jls.stages.voyage_plan import master_periods

COURSE, SWELL_FROM, WIND_FROM = 200.0, 290.0, 230.0
TPS = [9.0, 14.0]


@pytest.fixture(scope="module")
def setup(cfg):
    from jls.commands.forecast import options_transfer
    tr, _ = options_transfer(cfg, "default", ".", "no-results")
    spread = {k: parse_spreading(v) for k, v in cfg["sea"]["spreading"].items()}
    return cfg, tr, criteria_of(cfg, tr.plant), spread


def _limits(setup, wind, alpha=None):
    cfg, tr, crit, spread = setup
    return swell_limits(tr, wind, TPS, SWELL_FROM, COURSE, crit, gamma=float(cfg["sea"]["gamma"]),
                        spreading=spread, period_h=48.0, alpha=alpha)


def _forecast_utilisation(setup, systems):
    """Largest utilisation (candidate, tugger) over the criteria of one sea state, by the
    forecast's functions (relative motions' MPM over the limit, _tip_tension)."""
    from jls.response.sea_state import sea_state_statistics
    from jls.stages.forecast import _tip_tension
    cfg, tr, crit, _ = setup
    state = SeaState(tuple(systems))
    a = cfg["assessment"]
    ds = sea_state_statistics(tr, [state], COURSE, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"])
    u = np.zeros((len(tr.candidates), len(tr.tuggers)))
    for c, lim in crit.motions.items():
        u = np.maximum(u, ds["mpm"].sel(criterion=c).values[0] / lim)
    configured = {k for k, v in a["criteria"].items() if v is not None}
    extra = _tip_tension(tr, cfg, [state], np.array([COURSE]), configured, None)
    assert {"tip_air_gap_m", "wire_tension"} <= set(extra)            # every criterion counts
    for c in crit.names():
        if c in extra:
            u = np.maximum(u, extra[c][0][0])
    return u


def _swell(setup, hs, tp):
    cfg, _, _, spread = setup
    return WaveSystem("jonswap", float(hs), float(tp), SWELL_FROM, spread["swell"], "swell", float(cfg["sea"]["gamma"]))


def _wind(setup, wind):
    cfg, _, _, spread = setup
    return WaveSystem("jonswap", wind.hs, wind.tp, wind.from_deg, spread["wind"], "wind", float(cfg["sea"]["gamma"]))


def test_the_swell_limit_meets_the_governing_limit_exactly(setup):
    wind = WindSea(1.2, 6.0, WIND_FROM)
    lim = _limits(setup, wind)
    h = lim["swell_hs_oplim"].values                                   # (candidate, tugger, swell_tp)
    assert np.all(np.isfinite(h)) and np.all(h > 0) and np.all(h < HS_SEARCH_M)
    for k, tp in enumerate(TPS):
        for c in range(h.shape[0]):
            for t in range(h.shape[1]):
                u = _forecast_utilisation(setup, [_wind(setup, wind), _swell(setup, h[c, t, k], tp)])
                assert u[c, t] == pytest.approx(1.0, rel=1e-6)
                # and a swell 2 % higher is beyond a limit
                u2 = _forecast_utilisation(setup, [_wind(setup, wind), _swell(setup, 1.02 * h[c, t, k], tp)])
                assert u2[c, t] > 1.0


def test_a_larger_wind_sea_lowers_the_swell_limit(setup):
    small = _limits(setup, WindSea(0.5, 5.0, WIND_FROM))["swell_hs_oplim"].values
    large = _limits(setup, WindSea(1.5, 6.5, WIND_FROM))["swell_hs_oplim"].values
    assert np.all(large < small)


def test_a_wind_sea_beyond_a_limit_alone_leaves_no_swell(setup):
    lim = _limits(setup, WindSea(8.0, 8.0, SWELL_FROM))["swell_hs_oplim"].values
    assert np.all(lim == 0.0)


def test_with_no_wind_sea_the_swell_limit_is_the_single_systems_oplim(setup):
    lim = _limits(setup, WindSea(0.0, float("nan"), float("nan")))["swell_hs_oplim"].values
    for k, tp in enumerate(TPS):
        u = _forecast_utilisation(setup, [_swell(setup, 2.0, tp)])     # criteria linear in Hs
        np.testing.assert_allclose(lim[..., k], 2.0 / u, rtol=1e-6)


def test_opwf_takes_the_operations_alpha_as_the_masters_table(setup):
    table = AlphaTable(source="test table", period_h=[12.0, 72.0], hs_m=[1.0, 6.0],
                       alpha=[[0.7, 0.9], [0.6, 0.8]])
    none = WindSea(0.0, float("nan"), float("nan"))
    lim = _limits(setup, none, alpha=table)
    oplim, a, opwf = (lim[v].values for v in ("swell_hs_oplim", "swell_alpha", "swell_hs_opwf"))
    np.testing.assert_allclose(a, table.factor(48.0, oplim))
    np.testing.assert_allclose(opwf, a * oplim, rtol=1e-6)             # no wind sea: alpha OP_LIM
    assert np.all(a < 1) and np.all(opwf < oplim)
    # with a wind sea alpha is read at the limiting sea's total Hs and OP_WF stays below OP_LIM
    wind = WindSea(1.0, 6.0, WIND_FROM)
    lim = _limits(setup, wind, alpha=table)
    total = np.sqrt(1.0 + lim["swell_hs_oplim"].values ** 2)
    np.testing.assert_allclose(lim["swell_alpha"].values, table.factor(48.0, total))
    assert np.all(lim["swell_hs_opwf"].values < lim["swell_hs_oplim"].values)


def test_the_typical_wind_sea_is_the_median_of_the_recorded_hours():
    t = pd.date_range("2020-01-01", periods=5, freq="h", tz="UTC")
    f = pd.DataFrame({"hs_wind": [1.0, 2.0, 0.0, 3.0, np.nan], "tp_wind": [5.0, 6.0, np.nan, 7.0, np.nan],
                      "dir_wind": [80.0, 100.0, np.nan, 90.0, np.nan],
                      "hs_swell": [1.0, 1.0, 1.0, 1.0, np.nan], "tp_swell": [12.0] * 4 + [np.nan],
                      "dir_swell": [300.0] * 4 + [np.nan]}, index=t)
    w = typical_wind_sea(f)                  # the gap hour left out; the swell-only hour counts as 0
    assert w.hs == pytest.approx(1.5) and w.tp == pytest.approx(6.0)
    assert 80.0 < w.from_deg < 100.0


def _plan(alpha_source=""):
    import xarray as xr
    tps = [10.0, 12.0, 14.0]
    legs = ["table_leg", "parts"]
    wf = np.full((2, 1, 2, 3), np.nan)
    wf[0, 0, 1] = [1.234, 0.0, np.inf]
    wf[1, 0, 1] = [2.5, 1.75, 0.5]
    dims = ("candidate", "tugger", "leg", "swell_tp")
    p = xr.Dataset({"swell_hs_opwf": (dims, wf), "swell_alpha": (dims, np.where(np.isnan(wf), np.nan, 0.8)),
                    "wind_sea_hs": ("leg", [np.nan, 1.025]), "wind_sea_tp": ("leg", [np.nan, 6.0]),
                    "wind_sea_heading_deg": ("leg", [np.nan, 313.0]), "swell_heading_deg": ("leg", [np.nan, 277.0]),
                    "swell_tp_min": ("leg", [np.nan, 11.5]), "swell_tp_max": ("leg", [np.nan, 16.0])},
                   coords={"candidate": ["baseline", "detuned"], "tugger": ["none"], "leg": legs, "swell_tp": tps})
    p.attrs["alpha_source"] = alpha_source
    return p


def test_page_ones_swell_table_prints_the_datasets_numbers():
    from types import SimpleNamespace

    from jls.report.swell_table import swell_cell, swell_table
    p = _plan()
    cx = SimpleNamespace(plan=p, dg=SimpleNamespace(best=("baseline", "none")))
    text = swell_table(cx)
    assert "table_leg" not in text                        # partitioned legs only
    assert "parts (wind 1.02 m, 6.0 s at 313°; swell at 277°)" in text
    for x in p["swell_hs_opwf"].sel(candidate="baseline", tugger="none", leg="parts").values:
        assert swell_cell(float(x)) in text
    assert [swell_cell(x) for x in (1.234, 0.0, np.inf, np.nan)] == ["1.23", "none", "no limit", "–"]
    assert "α" not in text.split("header")[1]            # no alpha row without a table
    cx.dg.best = ("detuned", "none")
    assert "2.50" in swell_table(cx) and "1.23" not in swell_table(cx)
    # with an alpha table its row is printed; a plan without the swell table prints nothing
    assert "0.80" in swell_table(SimpleNamespace(plan=_plan("test table"), dg=cx.dg))
    assert swell_table(SimpleNamespace(plan=p.drop_vars("swell_hs_opwf"), dg=cx.dg)) == ""


def test_the_stage_tables_the_partitioned_legs_of_the_example_route(setup):
    """config/examples/partitions_route.yaml: its two partitioned legs get the swell table
    (the wind sea the median of the CSV's hours, the swell periods its own), its
    Torsethaugen table leg none."""
    from pathlib import Path

    import yaml

    from jls.stages.swell_limits import swell_table
    cfg, tr, _, _ = setup
    root = Path(__file__).resolve().parents[1]
    route = yaml.safe_load((root / "config/examples/partitions_route.yaml").read_text())["routes"]["synthetic_partitions"]
    names = [leg["name"] for leg in route["legs"]]
    ds = swell_table(route, names, [48.0] * 3, cfg, tr, list(tr.candidates), list(tr.tuggers),
                     gamma=float(cfg["sea"]["gamma"]), alpha=None, periods=master_periods, base_dir=root)
    assert ds["swell_hs_opwf"].dims == ("candidate", "tugger", "leg", "swell_tp")
    assert ds["swell_hs_opwf"].sel(leg="torsethaugen_table").isnull().all()
    csv = pd.read_csv(root / "tests/data/partitions/partitions_synthetic.csv", skipinitialspace=True, comment="#")
    csv.columns = [c.split("(")[0].strip() for c in csv.columns]
    rec = csv[(csv[["hs_wind", "hs_swell"]].fillna(0) > 0).any(axis=1)]
    assert float(ds["wind_sea_hs"].sel(leg="csv_partitions")) == pytest.approx(rec["hs_wind"].fillna(0).median())
    sw = rec[rec["hs_swell"] > 0]["tp_swell"]
    assert float(ds["swell_tp_min"].sel(leg="csv_partitions")) == pytest.approx(sw.min())
    tps = ds["swell_tp"].values
    assert tps[0] <= sw.min() and tps[-1] >= sw.max()
    wf = ds["swell_hs_opwf"].sel(leg="csv_partitions").values
    assert np.all(np.isfinite(wf)) and np.all(wf >= 0)
    assert np.array_equal(wf, ds["swell_hs_oplim"].sel(leg="csv_partitions").values)        # no alpha table


def test_a_leg_of_relative_headings_takes_its_governing_heading(setup):
    """No course: wind sea and swell met at each of the leg's headings, the lowest OP_WF
    taken, and the heading that gives it stored."""
    from pathlib import Path

    from jls.stages.swell_limits import swell_table
    cfg, tr, _, _ = setup
    root = Path(__file__).resolve().parents[1]
    base = {"name": "p", "duration_h": 12, "spectrum": "partitions",
            "metocean": {"file": "tests/data/partitions/partitions_synthetic.csv", "format": "partitions",
                         "period": "tp"}}

    def table(headings, prob):
        leg = {**base, "headings_deg": headings, "heading_probability": prob}
        return swell_table({"legs": [leg]}, ["p"], [12.0], cfg, tr, list(tr.candidates), list(tr.tuggers),
                           gamma=float(cfg["sea"]["gamma"]), alpha=None, periods=master_periods, base_dir=root).sel(leg="p")

    both, beam, head = table([90.0, 0.0], [0.5, 0.5]), table([90.0], [1.0]), table([0.0], [1.0])
    np.testing.assert_array_equal(both["swell_hs_opwf"], np.minimum(beam["swell_hs_opwf"], head["swell_hs_opwf"]))
    governing = np.where(head["swell_hs_opwf"] < beam["swell_hs_opwf"], 0.0, 90.0)
    np.testing.assert_array_equal(both["swell_heading_governing_deg"], governing)
    assert np.isnan(float(both["swell_heading_deg"])) and float(beam["swell_heading_governing_deg"].max()) == 90.0
    assert (beam["swell_hs_opwf"] != head["swell_hs_opwf"]).any()        # the heading decides somewhere


def test_the_block_bisection_is_each_options_own_brentq_root(setup, monkeypatch):
    """largest_swell bisects a block of candidates at once, each option with its own
    bracket: every limit is the root of that option's utilisation alone (scipy's brentq
    on the per-candidate evaluation) within the bisection's HS_SEARCH_M / 2**BISECTIONS,
    with a target per option (alpha) as with 1; blocks of one candidate give the same bits."""
    from scipy.optimize import brentq

    import jls.assessment.swell_limits as sl
    cfg, tr, crit, spread = setup
    wind = WindSea(1.2, 6.0, WIND_FROM)
    w, unit = sl.leg_moments(tr, wind, TPS, SWELL_FROM, COURSE, crit, gamma=float(cfg["sea"]["gamma"]),
                             spreading=spread)
    n_p, n_c, n_t = len(TPS), len(tr.candidates), len(tr.tuggers)
    assert n_c >= 2 and sl.block_size(unit, n_t) >= n_c                 # the options in one block
    target = np.linspace(0.6, 1.0, n_p * n_c * n_t).reshape(n_p, n_c, n_t)
    tol = HS_SEARCH_M / 2**sl.BISECTIONS
    for tgt in (1.0, target):
        h = sl.largest_swell(w, unit, crit, n_t, target=tgt)
        goal = np.broadcast_to(tgt, h.shape)
        for p, c, t in [(0, 0, 0), (1, 1, n_t - 1), (0, n_c - 1, 1), (1, 0, 2 % n_t)]:
            def excess(x):
                return sl.utilisation(w, unit, np.full((n_p, n_t), x), crit, c)[p, t] - goal[p, c, t]
            assert excess(0.0) < 0 < excess(HS_SEARCH_M)
            root = brentq(excess, 0.0, HS_SEARCH_M, xtol=1e-14, rtol=1e-15)
            assert abs(h[p, c, t] - root) <= 2 * tol + 1e-14 * root
        monkeypatch.setattr(sl, "BLOCK_ELEMENTS", 1)                    # one candidate a block
        assert sl.block_size(unit, n_t) == 1
        assert np.array_equal(sl.largest_swell(w, unit, crit, n_t, target=tgt), h)
        monkeypatch.undo()
    # the two ends: a wind sea alone beyond the target (0), no swell up to the search's end (inf)
    assert np.all(sl.largest_swell(w, unit, crit, n_t, target=1e-6) == 0.0)
    assert np.all(np.isinf(sl.largest_swell(w, unit, crit, n_t, target=1e6)))


def test_tip_utilisation_of_a_sea_per_option_is_each_options_own():
    """sea_state_criteria.tip_utilisation with the sea's statistics per option (n_s, c, t)
    gives each option exactly what the same sea given per sea state (n_s,) gives it."""
    from jls.assessment.sea_state_criteria import tip_utilisation
    rng = np.random.default_rng(7)
    n_s, n_c, n_t, n_k = 4, 3, 2, 3
    shape = (n_s, n_c, n_t)
    sea = {"hs": rng.uniform(0.5, 4.0, shape), "wave_m0": rng.uniform(0.05, 0.8, shape),
           "wave_t1": rng.uniform(5.0, 12.0, shape)}
    sea["wave_m2"] = sea["wave_m0"] * rng.uniform(0.3, 0.8, shape)
    tip = {"tip_m0": rng.uniform(0.05, 0.6, shape + (n_k,))}
    tip["tip_m2"] = tip["tip_m0"] * rng.uniform(0.2, 0.6, shape + (n_k,))
    tip["tip_m0"][1, 1, 0, 1] = np.nan                                     # unknown statistics: NaN
    heights = np.array([7.5, 9.0, 1.0])                                   # the last below the gap
    for crest in ("linear", "forristall_long_crested"):
        period = {}
        u, clearance = tip_utilisation({**sea, **tip, "tip_height": heights}, 1.5, crest, exposure_h=3.0,
                                       cycles="response", g=9.81, period=period)
        assert u.shape == clearance.shape == shape
        for c, t in np.ndindex(n_c, n_t):
            one = {k: v[:, c, t] for k, v in sea.items()}
            one.update({k: v[:, c:c + 1, t:t + 1] for k, v in tip.items()}, tip_height=heights[c:c + 1])
            own = {}
            u1, c1 = tip_utilisation(one, 1.5, crest, exposure_h=3.0, cycles="response", g=9.81, period=own)
            assert np.array_equal(u[:, c, t], u1[:, 0, 0], equal_nan=True)
            assert np.array_equal(clearance[:, c, t], c1[:, 0, 0], equal_nan=True)
            assert np.array_equal(period["tip_air_gap_m"][:, c, t], own["tip_air_gap_m"][:, 0, 0], equal_nan=True)
        assert np.isinf(u[:, 2]).all() and np.isnan(u[1, 1, 0]) and np.isfinite(u[:, 0]).all()
