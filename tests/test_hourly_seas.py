"""Every criterion of an hour of a measured or partitioned leg on the hour's own sea
(jls.stages.hourly_seas): a long-crested single-system hour equals the JONSWAP path (the
workflow's unit-Hs statistics times Hs) for every criterion; a swell at the sway period
raises the sway utilisation as the transfer function predicts; a partitioned hour equals
``jls response`` for the same systems and vessel heading; the workability judges the hours
on them."""

import copy
import json

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from jls.assessment import tip_clearance
from jls.assessment import wire_tension as wt
from jls.assessment.measured_legs import leg_workability
from jls.cli import main
from jls.config.builders import tip_settings_from_config
from jls.names import RESPONSES
from jls.response.moments import unit_moments
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments
from jls.response.tip import tip_response
from jls.response.wire_loads import tension_response
from jls.sea.partitions import sea_states
from jls.sea.sea_state import SeaState, Spreading, WaveSystem
from jls.sea.spectra import tp_from_tz
from jls.stages.hourly_seas import leg_utilisation, sea_state_utilisation

LONG = Spreading("long-crested")
TZ = 8.0


@pytest.fixture(scope="module")
def tr(cfg):
    from jls.commands.response import transfer_from_config
    return transfer_from_config(cfg, ".")


def _cycles(a):
    return FIXED_CYCLES_STUDY if a["mpm_cycles"] == "fixed" else "response"


def test_a_long_crested_single_system_hour_is_the_jonswap_path_for_every_criterion(cfg, tr):
    a, v = cfg["assessment"], cfg["vessel"]
    tp = float(tp_from_tz(TZ, 3.3))
    hs = 2.5
    # from 290 deg true on a course of 200 deg: relative heading 90 deg, an RAO heading
    period = {}
    crit, u, _ = sea_state_utilisation(tr, cfg, [SeaState((WaveSystem("jonswap", hs, tp, 290.0, LONG, "swell", 3.3),))],
                                       [200.0], period=period)
    assert {"relative_sway_m", "tip_air_gap_m", "wire_tension"} <= set(crit)
    # the voyage extremes' statistics of the own sea (sigma of the level, its period) are the
    # binned path's (jls.assessment.criterion_levels) on the same JONSWAP: the consistency limit
    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.workability import criteria_array
    from jls.response.statistics import sigma_from_mpm
    from jls.stages.hourly_seas import LEVEL_IS_MOTION
    lim = np.array([a["criteria"][c] if c in LEVEL_IS_MOTION else 1.0 for c in crit])
    own_sigma = sigma_from_mpm(u[0] * lim, period["tz_response"][0], a["exposure_h"] * 3600.0, _cycles(a))
    i = tr.exc.headings.tolist().index(90.0)
    u0, u2, _ = unit_moments(tr.plant, tr.exc, [TZ], list(tr.tuggers.values()), 3.3)
    st = from_moments(hs**2 * u0[:, :, i, :, 0], hs**2 * u2[:, :, i, :, 0], a["exposure_h"] * 3600.0, _cycles(a))
    checked = set()
    for j, c in enumerate(crit):
        if c.startswith("relative_"):
            r = RESPONSES.index({"relative_sway_m": "relative_sway", "relative_heave_m": "relative_heave",
                                 "relative_roll_deg": "relative_roll", "relative_yaw_deg": "relative_yaw"}[c])
            np.testing.assert_allclose(u[0, ..., j], st["mpm"][..., r] / a["criteria"][c], rtol=1e-6)
            checked.add(c)
    lever = np.subtract(v["hinge_m"], v["rao_reference_point_m"])[:2]
    tip = tip_settings_from_config(cfg)
    ts = tip_response(tr.plant, tr.exc, lever, [TZ], tr.tuggers, tip, gamma=3.3, exposure_h=a["exposure_h"],
                      cycles=a["mpm_cycles"], g=cfg["g_m_per_s2"])
    ts.attrs["tip_crest"] = tip.crest
    unit = tip_clearance.unit_utilisation(ts, a["criteria"]["tip_air_gap_m"]).sel(heading=90.0, tz=TZ)
    np.testing.assert_allclose(u[0, ..., crit.index("tip_air_gap_m")],
                               hs * unit.transpose("candidate", "tugger").values, rtol=1e-6)
    ws = tension_response(tr.plant, tr.exc, [TZ], tr.tuggers, gamma=3.3, exposure_h=a["exposure_h"],
                          cycles=a["mpm_cycles"])
    floor, ceiling = wt.settings(a["criteria"]["wire_tension"])
    unit = wt.unit_utilisation(ws, floor, ceiling).sel(heading=90.0, tz=TZ)
    np.testing.assert_allclose(u[0, ..., crit.index("wire_tension")],
                               hs * unit.transpose("candidate", "tugger").values, rtol=1e-6)
    checked |= {"tip_air_gap_m", "wire_tension"}
    merged = xr.merge([_motion_stats(tr, u0, u2, i, a), ts.sel(heading=[90.0]), ws.sel(heading=[90.0])],
                      join="exact", combine_attrs="override")
    merged.attrs["tip_crest"] = tip.crest
    binned = criterion_statistics(merged, criteria_array(a["criteria"])).sel(heading=90.0, tz=TZ)
    for j, c in enumerate(crit):
        b = binned.sel(criterion=c).transpose("candidate", "tugger")
        np.testing.assert_allclose(period["tz_response"][0, ..., j], b["tz_response"].values, rtol=1e-6)
        np.testing.assert_allclose(own_sigma[..., j], hs * b["sigma"].values, rtol=1e-6)
    assert checked == set(crit)                  # every criterion the configuration holds


def _motion_stats(tr, u0, u2, i, a):
    """response.nc's relative-motion statistics at Hs = 1 m (candidate, tugger, heading,
    tz, response) of the RAO heading ``i`` and the one Tz of ``u0``, ``u2``."""
    st = from_moments(u0[:, :, i], u2[:, :, i], a["exposure_h"] * 3600.0, _cycles(a))   # (c, t, response, tz)
    dims = ("candidate", "tugger", "response", "tz")
    return xr.Dataset({k: (dims, st[k]) for k in ("sigma", "tz_response", "mpm")},
                      coords={"candidate": tr.candidates, "tugger": list(tr.tuggers), "response": list(RESPONSES),
                              "tz": [TZ]}).expand_dims(heading=[float(tr.exc.headings[i])])


def test_a_swell_at_the_sway_period_raises_the_sway_utilisation_as_the_transfer_function_predicts(cfg, tr):
    wind = WaveSystem("jonswap", 1.5, 6.0, 290.0, LONG, "wind", 3.3)
    i = tr.exc.headings.tolist().index(90.0)
    # the sway period of the baseline, no tugger: the peak of its relative-sway |H|^2 at 90 deg
    from jls.response.solver import relative_power
    p = tr.plant
    P = relative_power(p["M"].values[:1], p["K"].values[:1], p["Kb"].values[:1], p["C"].values[:1], tr.exc.omega,
                       tr.exc.qb, tr.exc.fairlead_sway, [0.0])[0, 0, i, 0]
    tp = 2 * np.pi / float(tr.exc.omega[np.argmax(P)])
    swell = WaveSystem("jonswap", 0.5, tp, 290.0, LONG, "swell", 3.3)
    crit, u, v = sea_state_utilisation(tr, cfg, [SeaState((wind,)), SeaState((wind, swell)), SeaState((swell,))],
                                       [200.0] * 3)
    j = crit.index("relative_sway_m")
    sway = v[:, 0, 0, j]
    assert u[1, 0, 0, j] > 1.5 * u[0, 0, 0, j]     # 0.5 m of swell outweighs 1.5 m of wind sea
    # the variances add (the MPM is sigma sqrt(2 ln N), N of the combined sea's Tz): the
    # two-system sigma^2 is the sum of the systems' sigma^2 integrated over the same |H|^2
    w = np.gradient(tr.exc.omega)
    m0 = [float(np.sum(P * s.spectrum(tr.exc.omega) * w)) for s in (wind, swell)]
    assert m0[1] > 10 * m0[0]
    ratio = sway[1] / sway[0]
    assert ratio > np.sqrt((m0[0] + m0[1]) / m0[0]) * 0.9


def _partitions_frame(rows):
    cols = ["hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell"]
    idx = pd.date_range("2026-01-05", periods=len(rows), freq="1h", tz="UTC")
    return pd.DataFrame(rows, index=idx, columns=cols)


def test_partitioned_leg_hours_are_jls_response(cfg, tr, capsys):
    frame = _partitions_frame([[0.8, 6.0, 150.0, 0.6, 13.0, 260.0], [1.2, 7.0, 200.0, 0.9, 15.0, 290.0]])
    spread = {"wind": "cos2s:4", "swell": "cos2s:13"}
    states, kept = sea_states(frame, gamma=3.3, spreading=spread)
    assert kept.all()
    leg = {"name": "p", "course_deg": 200.0, "headings_deg": [90.0, 120.0], "heading_probability": [0.5, 0.5]}
    ds = leg_utilisation(tr, cfg, leg, states, np.array([[1.0, 0.0], [0.0, 1.0]]), directional=True)
    assert np.isnan(ds["utilisation"].values[0, 1]).all() and np.isnan(ds["utilisation"].values[1, 0]).all()
    for t, k in ((0, 0), (1, 1)):
        args = [f"--system={h},{p},{d},3.3,{spread[kind]}"
                for (h, p, d), kind in zip(frame.iloc[t].to_numpy().reshape(2, 3), ("wind", "swell"))]
        assert main(["response", *args, "--vessel-heading", "200", "--json"]) == 0
        resp = json.loads(capsys.readouterr().out)["candidates"]
        for c, per in resp.items():
            for g, crit in per.items():
                for name, stats in crit.items():
                    if cfg["assessment"]["criteria"].get(name) is None:
                        continue
                    got = float(ds["utilisation"].sel(candidate=c, tugger=g, criterion=name)[t, k])
                    assert got == pytest.approx(stats["mpm"] / cfg["assessment"]["criteria"][name], rel=1e-9)


def test_a_leg_of_relative_headings_meets_the_hours_largest_system_at_each_heading(cfg, tr):
    frame = _partitions_frame([[0.3, 5.0, 10.0, 1.0, 14.0, 100.0]])
    states, _ = sea_states(frame, gamma=3.3, spreading={"wind": "long-crested", "swell": "long-crested"})
    leg = {"name": "r", "headings_deg": [90.0, 180.0], "heading_probability": [0.7, 0.3]}
    ds = leg_utilisation(tr, cfg, leg, states, np.array([[0.7, 0.3]]), directional=True)
    # the swell (the larger) met at 90 deg: on a course of 100 + 90 - 180 = 10 deg
    crit, u, _ = sea_state_utilisation(tr, cfg, states, [10.0])
    np.testing.assert_allclose(ds["utilisation"].values[0, 0], u[0], rtol=1e-12)
    beam, head = (ds["utilisation"].sel(criterion="relative_sway_m").values[0, k] for k in (0, 1))
    assert (beam > head).all()


def test_the_workability_judges_each_hour_on_its_own_sea(cfg, tr):
    """An hour that a JONSWAP on its (Hs, Tz) passes fails on its own sea's utilisation."""
    crit = ["relative_sway_m", "relative_heave_m"]
    cand, tug = tr.candidates[:1], list(tr.tuggers)[:1]
    tzs = np.array([4.0, 8.0, 12.0])
    unit = xr.DataArray(np.full((1, 1, 1, 3, 2), 0.1), dims=("candidate", "tugger", "heading", "tz", "criterion"),
                        coords={"candidate": cand, "tugger": tug, "heading": [90.0], "tz": tzs, "criterion": crit,
                                "strict": ("criterion", [False, False])})
    times = pd.date_range("2026-01-01", periods=4, freq="1h").to_numpy()
    own = np.full((1, 4, 1, 1, 1, 2), 0.5)
    own[0, 2, 0, 0, 0, 1] = 1.5                    # hour 2 fails on its heave
    measured = xr.Dataset(
        {"hs": (("leg", "time"), np.full((1, 4), 2.0)), "tz": (("leg", "time"), np.full((1, 4), 8.0)),
         "heading_weight": (("leg", "time", "heading"), np.ones((1, 4, 1))),
         "sigma_measured": (("leg", "time", "candidate", "tugger"), np.ones((1, 4, 1, 1))),
         "sigma_jonswap": (("leg", "time", "candidate", "tugger"), np.ones((1, 4, 1, 1))),
         "utilisation": (("leg", "time", "heading", "candidate", "tugger", "criterion"), own)},
        coords={"leg": ["p"], "time": times, "heading": [90.0], "candidate": cand, "tugger": tug, "criterion": crit})
    r = leg_workability(measured, "p", unit)
    assert float(r["workability"].values[0, 0]) == pytest.approx(0.75)   # the JONSWAP (u = 0.2) passes all
    assert float(r["governing_share"].sel(criterion="relative_heave_m").values[0, 0]) == pytest.approx(0.25)
    without = leg_workability(measured.drop_vars("utilisation"), "p", unit)
    assert float(without["workability"].values[0, 0]) == 1.0


def test_the_own_sea_is_not_the_long_crested_jonswap_when_spread(cfg, tr):
    """Spreading lowers the beam-sea sway of a swell (not every direction is the beam)."""
    c = copy.deepcopy(cfg)
    tp = 14.0
    lc = SeaState((WaveSystem("jonswap", 1.0, tp, 290.0, LONG, "swell", 3.3),))
    sc = SeaState((WaveSystem("jonswap", 1.0, tp, 290.0, Spreading("cos2s", 4.0), "swell", 3.3),))
    crit, u, _ = sea_state_utilisation(tr, c, [lc, sc], [200.0, 200.0])
    j = crit.index("relative_sway_m")
    assert (u[1, ..., j] < u[0, ..., j]).all()


def test_holding_the_candidates_powers_gives_the_same_moments_as_holding_the_hours_spectra(cfg, tr):
    """More hours than candidates: the powers are held and each group's spectra dropped
    (memory in candidates); the same numbers as the hours' products formed first."""
    from jls.response.sea_state import heading_products, hold_powers, sea_state_moments
    from jls.response.sea_state_tip_tension import tip_tension_moments
    rng = np.random.default_rng(3)
    states = [SeaState((WaveSystem("jonswap", float(h), float(t), float(d), Spreading("cos2s", 6.0), "swell", 3.3),))
              for h, t, d in zip(rng.uniform(0.5, 3, 70), rng.uniform(6, 16, 70), rng.uniform(0, 360, 70))]
    course = rng.uniform(0, 360, 70)
    assert hold_powers(tr, len(states), None) and not hold_powers(tr, len(states), "given")
    products = heading_products(tr, states, course)
    for a, b in zip(sea_state_moments(tr, states, course), sea_state_moments(tr, states, course, products=products)):
        np.testing.assert_allclose(a, b, rtol=1e-10)
    tip = tip_settings_from_config(cfg)
    lever = np.subtract(cfg["vessel"]["hinge_m"], cfg["vessel"]["rao_reference_point_m"])[:2]
    x = tip_tension_moments(tr, states, course, tip=tip, hinge_xy=lever)
    y = tip_tension_moments(tr, states, course, tip=tip, hinge_xy=lever, products=products)
    for key in ("tip_m0", "tip_m2", "tension_m0", "tension_m2", "wave_m0", "wave_m2"):
        np.testing.assert_allclose(x[key], y[key], rtol=1e-10)


def _own(m, util):
    """measured_response ``m`` with every hour's own-sea utilisation ``util`` (time,
    heading, candidate, tugger, criterion) added."""
    from test_measured_legs import CRIT
    m = m.copy()
    m["utilisation"] = (("leg", "time", "heading", "candidate", "tugger", "criterion"), util[None])
    return m.assign_coords(criterion=list(CRIT))


def test_the_weather_windows_and_the_workability_judge_the_same_own_sea_hours():
    """The windows' workable fraction of a leg's hours is the hourly workability, both on
    the hours' own seas; a heave-like failure the JONSWAP does not see counts in both."""
    from test_measured_legs import CRIT, curve, measured

    from jls.assessment.windows import windows_dataset
    from jls.assessment.workability import criteria_array, unit_utilisation
    rng = np.random.default_rng(5)
    n = 120
    hs, tz = rng.uniform(0.5, 1.0, n), rng.uniform(4.5, 9.5, n)
    leg = {"name": "m", "duration_h": 6, "headings_deg": [90.0, 120.0], "heading_probability": [0.3, 0.7],
           "spectra": {"file": "x", "format": "ndbc"}}
    m = measured(hs, tz, np.ones(n), np.tile([0.3, 0.7], (n, 1)))
    util = rng.uniform(0.2, 1.3, (n, 2, 2, 1, 2))
    m = _own(m, util)
    series = pd.DataFrame({"hs": hs, "tz": tz},
                          index=pd.date_range("2019-01-01", periods=n, freq="1h", tz="UTC", name="time"))
    win = windows_dataset([leg], {"m": series}, curve(), CRIT, measured=m)
    work = leg_workability(m, "m", unit_utilisation(curve(), criteria_array(CRIT)))
    np.testing.assert_allclose(win["workable_fraction"].sel(leg="m").values, work["workability"].values, rtol=1e-12)
    # the share of hours x heading weights whose every criterion is <= 1 on the own sea
    ok = (util <= 1).all(-1)                                        # (time, heading, candidate, tugger)
    expect = np.einsum("thcg,h->cg", ok, [0.3, 0.7]) / n
    np.testing.assert_allclose(work["workability"].values, expect, rtol=1e-12)
    assert win.attrs["own_sea_not_used"] == ""


def test_the_route_simulation_takes_the_hours_level_from_their_own_sea():
    """An hour of the own-sea leg at utilisation u has level u x limit (and its sigma moved
    alike); the other leg keeps the JONSWAP; a criterion the own sea lacks keeps it too."""
    from test_measured_legs import CRIT, measured, route_case

    from jls.assessment.hourly import route_own_utilisation
    from jls.assessment.route_simulation import _Hours
    crit, hours, hp = route_case()
    m = measured(np.full(5, 1.5), np.full(5, 6.0), np.ones(5), np.ones((5, 1)), headings=(90.0,))
    util = np.full((5, 1, 2, 1, 2), 0.4)
    util[2, ..., 0] = 1.7                                           # hour 2: the sway at 1.7 x its limit
    util[..., 1] = np.nan                                           # the roll: not on the own sea
    own = route_own_utilisation(_own(m, util), hours)
    assert own.sel(leg="s").isnull().all()
    plain = _Hours(crit, hours, hp).rows(slice(None))
    got = _Hours(crit, hours, hp, own=own, limit=crit["limit"]).rows(slice(None))
    rows = crit["mpm"].isel(heading=0, tz=0).transpose("candidate", "tugger", "criterion")
    sway = [k for k, c in enumerate(np.broadcast_to(rows["criterion"].values, rows.shape).reshape(-1))
            if c == "relative_sway_m"]
    roll = [k for k in range(rows.size) if k not in sway]
    np.testing.assert_allclose(got[0][sway, 0, 2], 1.7 * CRIT["relative_sway_m"])
    np.testing.assert_allclose(got[0][sway, 0, 0], 0.4 * CRIT["relative_sway_m"])
    np.testing.assert_allclose(got[1][sway, 0] / plain[1][sway, 0], got[0][sway, 0] / plain[0][sway, 0])
    np.testing.assert_allclose(got[0][:, 1], plain[0][:, 1])        # the other leg
    np.testing.assert_allclose(got[0][roll], plain[0][roll])        # the roll keeps the JONSWAP


def test_an_hours_every_criterion_is_jls_forecasts_for_the_same_systems(cfg, tmp_path):
    """The leg's hourly utilisation and ``jls forecast``'s (alpha 1) of the same hour's
    systems met on the same course: every criterion, motions, tip and wires alike."""
    from test_forecast import _answer, _forecast

    from jls.sea.sea_state import parse_spreading
    from jls.stages.hourly_seas import leg_utilisation
    path = _forecast(tmp_path / "fc.csv", 60, wind=(0.9, 6.0, 150.0), swell=(0.7, 14.0, 260.0))
    ds, _ = _answer(cfg, path)
    gamma, spread = float(cfg["sea"]["gamma"]), cfg["sea"]["spreading"]
    k = 7
    systems = [WaveSystem("jonswap", float(ds["hs"].values[k, j]), float(ds["tp"].values[k, j]),
                          float(ds["dir_from"].values[k, j]) % 360.0, parse_spreading(spread[kind]), kind, gamma)
               for j, kind in enumerate(ds["system"].values.tolist()) if ds["hs"].values[k, j] > 0]
    assert len(systems) == 2
    from jls.commands.forecast import options_transfer
    tr, _ = options_transfer(cfg, "default", ".", "no-results")
    leg = {"name": "p", "course_deg": float(ds["course_deg"].values[k]), "headings_deg": [90.0],
           "heading_probability": [1.0]}
    mine = leg_utilisation(tr, cfg, leg, [SeaState(tuple(systems))], np.ones((1, 1)), directional=True)
    crit = ds["criterion"].values.tolist()
    assert set(mine["criterion"].values) == set(crit) and len(crit) >= 3
    for c in crit:
        np.testing.assert_allclose(mine["utilisation"].sel(criterion=c).values[0, 0],
                                   ds["criterion_utilisation"].sel(criterion=c).values[k], rtol=1e-9)


def test_an_own_sea_hour_where_the_jonswap_has_no_response_still_counts_its_up_crossings():
    """Sway in head seas: the long-crested JONSWAP gives none, a spread swell does. The
    hour's level is its own, and so are its sigma and up-crossing period
    (measured_response.nc tz_response_own; the sigma whose 3-h MPM at it is the level), never 0 (which would drop the hour's
    up-crossings of the limit from the route simulation); without them stored the sigma is
    unknown (NaN), not guessed. The hindcast extreme takes the same (one rule)."""
    from test_measured_legs import CRIT, curve, measured

    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.hourly import own_hour_statistics, route_own_utilisation
    from jls.assessment.route_hours import common_hours
    from jls.assessment.route_simulation import _Hours
    from jls.assessment.workability import criteria_array
    from jls.response.statistics import sigma_from_mpm
    stats = curve(headings=(90.0,))
    stats["sigma"] = stats["mpm"] / 3.0
    stats["tz_response"] = xr.full_like(stats["mpm"], 12.0)
    crit = criterion_statistics(stats, criteria_array(CRIT))
    idx = pd.date_range("2019-01-01", periods=3, freq="1h", tz="UTC", name="time")
    rec = pd.DataFrame({"hs": [1.5, 0.0, 1.5], "tz": np.full(3, 6.0)}, index=idx)   # hour 1: no JONSWAP
    hours = common_hours({"m": rec})
    hp = xr.DataArray(np.ones((1, 1)), dims=("leg", "heading"), coords={"leg": ["m"], "heading": [90.0]})
    m = measured(rec["hs"].values, rec["tz"].values, np.ones(3), np.ones((3, 1)), headings=(90.0,))
    util = np.full((3, 1, 2, 1, 2), 0.8)
    lim = np.broadcast_to(crit["limit"].values, (2, 2)).reshape(-1)          # rows: (candidate, criterion)
    bare = route_own_utilisation(_own(m, util), hours)
    _, sigma, _ = _Hours(crit, hours, hp, own=bare, limit=crit["limit"]).rows(slice(None))
    assert np.isnan(sigma[:, 0, 1]).all()                                    # nothing to move: unknown
    np.testing.assert_allclose(sigma[:, 0, 0], 0.8 * lim / 3.0)              # moved: MPM / sigma = 3
    with_own = _own(m, util)
    levels = util * np.array([CRIT[c] for c in CRIT])
    with_own["tz_response_own"] = with_own["utilisation"] * 0 + 15.0
    own = route_own_utilisation(with_own, hours)
    with pytest.raises(ValueError, match="exposure_h"):
        _Hours(crit, hours, hp, own=own, limit=crit["limit"])
    mpm, sigma, tzr = _Hours(crit, hours, hp, own=own, limit=crit["limit"], exposure=(3.0, "response")).rows(
        slice(None))
    expect = 0.8 * lim / np.sqrt(2 * np.log(3 * 3600.0 / 15.0))
    np.testing.assert_allclose(expect.reshape(2, 2)[:, 1], sigma_from_mpm(levels, 15.0)[0, 0, :, 0, 1], rtol=1e-12)
    np.testing.assert_allclose(mpm[:, 0, 1], 0.8 * lim)
    for h in (0, 1):                                                         # with and without a JONSWAP
        np.testing.assert_allclose(sigma[:, 0, h], expect, rtol=1e-12)
        np.testing.assert_allclose(tzr[:, 0, h], 15.0)
    s, t = own_hour_statistics(np.array([np.nan]), np.array([2.0]), np.array([5.0]), np.array([9.0]),
                               np.array([15.0]), 3.0)
    assert (s[0], t[0]) == (2.0, 9.0)                                        # no own level: the JONSWAP


def test_the_route_simulation_reads_the_own_seas_a_block_of_options_at_a_time_to_the_same_numbers():
    """route_own_rows gives any rows of options the numbers route_own_utilisation holds for
    all of them (the largest over the headings met, the period at that heading; NaN on a
    criterion the own seas lack, on hours without a record), and the route simulation on it
    is the same to the last bit."""
    from test_measured_legs import CRIT, curve, measured

    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.hourly import route_own_rows, route_own_utilisation
    from jls.assessment.route_hours import common_hours
    from jls.assessment.route_simulation import route_simulation
    from jls.assessment.workability import criteria_array
    rng = np.random.default_rng(5)
    stats = curve(headings=(90.0, 120.0))
    stats["sigma"] = stats["mpm"] / 3.0
    stats["tz_response"] = xr.full_like(stats["mpm"], 12.0)
    crit = criterion_statistics(stats, criteria_array(CRIT))
    n = 60
    idx = pd.date_range("2019-01-01", periods=n + 5, freq="1h", tz="UTC", name="time")
    rec = pd.DataFrame({"hs": rng.uniform(0.5, 2.5, n + 5), "tz": rng.uniform(5.0, 9.0, n + 5)}, index=idx)
    hours = common_hours({"m": rec})
    hp = xr.DataArray([[0.5, 0.5]], dims=("leg", "heading"), coords={"leg": ["m"], "heading": [90.0, 120.0]})
    weight = (rng.uniform(size=(n, 2)) > 0.3).astype(float)
    m = measured(rec["hs"].values[:n], rec["tz"].values[:n], np.ones(n), weight)     # 5 hours without
    util = np.where(weight[:, :, None, None, None] > 0, rng.uniform(0.1, 1.4, (n, 2, 2, 1, 2)), np.nan)
    own = _own(m, util)
    own["tz_response_own"] = own["utilisation"].copy(data=rng.uniform(6.0, 16.0, own["utilisation"].shape))
    own = own.isel(criterion=[1])                                  # one criterion without own seas
    full = route_own_utilisation(own, hours).reindex(criterion=crit["criterion"].values)
    rows = route_own_rows(own, hours)
    opt = ["candidate", "tugger", "criterion"]
    assert not rows.bind(["candidate", "criterion"], {d: crit[d].values for d in opt})   # then formed whole
    assert rows.bind(opt, {d: crit[d].values for d in opt})
    u, tz = rows.rows(slice(None))
    np.testing.assert_array_equal(u, full["utilisation"].transpose(*opt, "leg", "time").values.reshape(u.shape))
    np.testing.assert_array_equal(tz, full["tz_response"].transpose(*opt, "leg", "time").values.reshape(u.shape))
    assert np.isnan(u[:, 0, -5:]).all() and np.isnan(u.reshape(2, 1, 2, -1)[:, :, 0]).all()
    kw = {"exposure_h": 3.0, "cycles": "response", "rows": 3}
    a = route_simulation(crit, hours, hp, xr.DataArray([20.0], dims="leg", coords={"leg": ["m"]}), crit["limit"],
                         own=route_own_utilisation(own, hours), **kw)
    b = route_simulation(crit, hours, hp, xr.DataArray([20.0], dims="leg", coords={"leg": ["m"]}), crit["limit"],
                         own=route_own_rows(own, hours), threads=2, **kw)
    jonswap = route_simulation(crit, hours, hp, xr.DataArray([20.0], dims="leg", coords={"leg": ["m"]}),
                               crit["limit"], **kw)
    assert not np.array_equal(jonswap["departure_exceedance"].values, a["departure_exceedance"].values)
    xr.testing.assert_identical(a, b)
