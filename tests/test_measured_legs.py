"""Legs given by measured spectra judged hour by hour: the interpolation in Tz shared by
the hourly verdicts, the measured-over-JONSWAP sway ratio in the weather windows and the
workability, the hours' headings, and the leg's workability in the workability dataset."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from jls.assessment.hourly import at_hours, hourly_utilisation, sway_ratio, tz_weights
from jls.assessment.measured_legs import apply_measured_legs, leg_workability
from jls.assessment.windows import windows_dataset
from jls.assessment.workability import criteria_array, unit_utilisation
from jls.errors import InputError
from jls.names import FREQUENCY_DOMAIN, SATURATED_FAIL

RESPONSES = ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]
CRIT = {"relative_sway_m": 3.0, "relative_roll_deg": 2.0}
TZ = np.array([4.0, 6.0, 8.0, 10.0])


def curve(headings=(90.0, 120.0)):
    """Unit-Hs MPM on a Tz grid: sway 1.0 m/m at 90 deg and 1.5 m/m at 120 deg, rising
    with Tz by 0.1 per s; roll 0.5 deg/m everywhere. Two candidates, one tugger."""
    mpm = np.zeros((2, 1, len(headings), 4, TZ.size))
    for k, h in enumerate(headings):
        mpm[:, :, k, 0, :] = (1.0 if h == 90.0 else 1.5) + 0.1 * (TZ - 4.0)
    mpm[1, :, :, 0, :] *= 0.5                            # the second candidate sways half as much
    mpm[:, :, :, 2, :] = 0.5
    return xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                      coords={"candidate": ["a", "b"], "tugger": ["none"], "heading": list(headings),
                              "response": RESPONSES, "tz": TZ})


def measured(hs, tz, ratio, weight, headings=(90.0, 120.0), start="2019-01-01"):
    """measured_response.nc of one leg "m": hours with Hs, Tz, a sway ratio per hour
    (the same for both candidates) and heading weights (n_time, n_heading)."""
    hs, tz, ratio = (np.asarray(v, float) for v in (hs, tz, ratio))
    n = hs.size
    times = pd.date_range(start, periods=n, freq="1h").to_numpy()
    jons = np.ones((n, 2, 1))
    ds = xr.Dataset({"sigma_measured": (("time", "candidate", "tugger"), jons * ratio[:, None, None]),
                     "sigma_jonswap": (("time", "candidate", "tugger"), jons),
                     "hs": ("time", hs), "tz": ("time", tz),
                     "heading_weight": (("time", "heading"), np.asarray(weight, float))},
                    coords={"time": times, "candidate": ["a", "b"], "tugger": ["none"],
                            "heading": list(headings)})
    return ds.expand_dims(leg=["m"])


def route_case():
    """Unit statistics with MPM / sigma = 3 and a 12-s response period, as criterion
    levels, and two legs "m" and "s" of five hours at Hs 1.5 m, Tz 6 s, met at 90 deg."""
    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.route_hours import common_hours
    stats = curve(headings=(90.0,))
    stats["sigma"] = stats["mpm"] / 3.0
    stats["tz_response"] = xr.full_like(stats["mpm"], 12.0)
    crit = criterion_statistics(stats, criteria_array(CRIT))
    idx = pd.date_range("2019-01-01", periods=5, freq="1h", tz="UTC", name="time")
    rec = pd.DataFrame({"hs": np.full(5, 1.5), "tz": np.full(5, 6.0)}, index=idx)
    hours = common_hours({"m": rec, "s": rec})
    hp = xr.DataArray(np.ones((2, 1)), dims=("leg", "heading"), coords={"leg": ["m", "s"], "heading": [90.0]})
    return crit, hours, hp


def test_interpolation_is_linear_held_at_the_ends_and_keeps_non_finite_statistics_where_used():
    grid = np.array([4.0, 6.0, 8.0])
    a = np.array([[1.0, 3.0, np.inf], [np.nan, 2.0, 4.0]])
    w = tz_weights([5.0, 6.0, 3.0, 9.0, np.nan, 7.0], grid)
    out = at_hours(a, w)
    assert w[4] == 2                                     # 3 s and 9 s lie beyond the grid
    np.testing.assert_allclose(out[0, :3], [2.0, 3.0, 1.0])            # linear; held at 4 s
    assert np.isinf(out[0, 3]) and np.isinf(out[0, 5])                 # 8 s's +inf used
    assert out[0, 4] == 0.0                                            # no record
    assert np.isnan(out[1, 0]) and out[1, 1] == 2.0                     # NaN at 4 s: used at 5 s only
    np.testing.assert_allclose(out[1, 5], 3.0)
    # on finite statistics the same as numpy's interp
    rng = np.random.default_rng(1)
    b, t = rng.uniform(0, 2, (3, grid.size)), rng.uniform(4, 8, 50)
    np.testing.assert_allclose(at_hours(b, tz_weights(t, grid)), [np.interp(t, grid, r) for r in b], rtol=1e-14)


def test_a_limit_broken_at_rest_fails_even_a_calm_hour():
    stats = curve()
    stats["mpm"][:] = np.inf
    util, _ = hourly_utilisation([0.0, 1.0], [6.0, 6.0], unit_utilisation(stats, criteria_array(CRIT)))
    assert not bool((util <= 1.0).any())


def test_the_sway_ratio_scales_the_sway_only():
    u = unit_utilisation(curve(), criteria_array(CRIT)).sel(heading=[90.0])
    hs, tz = np.array([1.0, 2.0]), np.array([6.0, 6.0])
    scale = xr.DataArray(np.array([[2.0, 0.5]] * 2)[:, None, :], dims=("candidate", "tugger", "time"),
                         coords={"candidate": ["a", "b"], "tugger": ["none"]})
    base, _ = hourly_utilisation(hs, tz, u)
    scaled, _ = hourly_utilisation(hs, tz, u, sway_scale=scale)
    ratio = (scaled / base).transpose("candidate", "tugger", "heading", "time", "criterion")
    np.testing.assert_allclose(ratio.sel(criterion="relative_sway_m").values.squeeze(), [[2.0, 0.5]] * 2)
    np.testing.assert_allclose(ratio.sel(criterion="relative_roll_deg").values, 1.0)
    # sway at 6 s: 1.2 m/m over 3 m; Hs 1 m with twice the sway: 0.8
    assert float(scaled.sel(candidate="a", tugger="none", heading=90.0, criterion="relative_sway_m").isel(time=0)) == \
        pytest.approx(2 * 1.2 / 3.0)
    gap = scale.copy()
    gap[0, 0, 1] = np.nan
    with pytest.raises(InputError, match="no measured-spectrum sway ratio"):
        hourly_utilisation(hs, tz, u, sway_scale=gap)


def test_hourly_workability_is_a_hand_count_over_hours_and_their_headings():
    # Sway at 6 s: 1.2 m/m at 90 deg, 1.7 m/m at 120 deg (candidate a); limit 3 m.
    # hour 1: Hs 2.0 at 90 deg: 2.4 m passes; hour 2: Hs 2.0 at 120 deg: 3.4 m fails;
    # hour 3: Hs 2.0 at 90 deg with ratio 1.5: 3.6 m fails; hour 4: Hs 1.0 half at each: passes
    m = measured([2.0, 2.0, 2.0, 1.0], [6.0] * 4, [1.0, 1.0, 1.5, 1.0],
                 [[1, 0], [0, 1], [1, 0], [0.5, 0.5]])
    u = unit_utilisation(curve(), criteria_array(CRIT))
    r = leg_workability(m, "m", u)
    assert float(r["workability"].sel(candidate="a", tugger="none")) == pytest.approx(2 / 4)
    assert float(r["workability"].sel(candidate="b", tugger="none")) == pytest.approx(1.0)
    share = r["governing_share"].sel(candidate="a", tugger="none")
    assert float(share.sel(criterion="relative_sway_m")) == pytest.approx(2 / 4)
    assert float(share.sel(criterion="relative_roll_deg")) == 0.0
    assert float(r["hours"]) == 4
    # an hour beyond the Tz grid is an error by default, held at the end on request
    far = measured([1.0], [12.0], [1.0], [[1, 0]])
    with pytest.raises(InputError, match="outside the statistics' range"):
        leg_workability(far, "m", u)
    assert int(leg_workability(far, "m", u, tz_outside="nearest")["hours_outside_tz"]) == 1


def test_the_hourly_workability_is_the_windows_workable_fraction_of_the_same_hours():
    rng = np.random.default_rng(3)
    n = 200
    hs, tz = rng.uniform(0.5, 3.0, n), rng.uniform(4.5, 9.5, n)
    ratio = rng.uniform(0.8, 1.6, n)
    leg = {"name": "m", "duration_h": 6, "headings_deg": [90.0, 120.0], "heading_probability": [0.3, 0.7],
           "spectra": {"file": "x", "format": "ndbc"}}
    m = measured(hs, tz, ratio, np.tile([0.3, 0.7], (n, 1)))
    series = pd.DataFrame({"hs": hs, "tz": tz},
                          index=pd.date_range("2019-01-01", periods=n, freq="1h", tz="UTC", name="time"))
    win = windows_dataset([leg], {"m": series}, curve(), CRIT, measured=m)
    work = leg_workability(m, "m", unit_utilisation(curve(), criteria_array(CRIT)))
    np.testing.assert_allclose(win["workable_fraction"].sel(leg="m").values, work["workability"].values,
                               rtol=1e-12)
    assert win.attrs["measured_sway_legs"] == "m"
    # the ratio counts: with every ratio 1 more hours pass
    ones = measured(hs, tz, np.ones(n), np.tile([0.3, 0.7], (n, 1)))
    plain = windows_dataset([leg], {"m": series}, curve(), CRIT, measured=ones)
    assert float(plain["workable_fraction"].sel(leg="m", candidate="a", tugger="none")) > \
        float(win["workable_fraction"].sel(leg="m", candidate="a", tugger="none"))
    # a spectra leg without its measured response stops
    with pytest.raises(InputError, match="measured-spectrum response"):
        windows_dataset([leg], {"m": series}, curve(), CRIT)


def test_sway_ratio_of_an_hour_without_sway_is_one():
    m = measured([1.0, 1.0], [6.0, 6.0], [1.2, 0.0], [[1, 0], [1, 0]])
    m["sigma_jonswap"][:, 1] = 0.0
    r = sway_ratio(m, "m")
    np.testing.assert_allclose(r.isel(candidate=0, tugger=0).values, [1.2, 1.0])


def _work(sea_legs=("m", "s")):
    """A workability dataset of two legs (binned figures 0.9 and 0.8) with bands."""
    shape = (2, 1, 2)
    coords = {"candidate": ["a", "b"], "tugger": ["none"], "leg": list(sea_legs)}
    dims = ("candidate", "tugger", "leg")
    leg = xr.DataArray(np.broadcast_to([0.9, 0.8], shape).copy(), dims=dims, coords=coords)
    var = leg.expand_dims(damping_factor=[0.5, 2.0], sway_frequency_factor=[1.0], hs_in_bin=["centre"]) \
        .transpose(*dims, "damping_factor", "sway_frequency_factor", "hs_in_bin") + \
        xr.DataArray([-0.05, 0.02], dims="damping_factor", coords={"damping_factor": [0.5, 2.0]})
    weight = xr.DataArray([0.5, 0.5], dims="leg", coords={"leg": list(sea_legs)})
    route = (leg * weight).sum("leg")
    route_var = (var * weight).sum("leg")
    bands = ("damping_factor", "sway_frequency_factor", "hs_in_bin")
    crit = criteria_array(CRIT)
    work = xr.Dataset({"workability_leg": leg, "workability_route": route,
                       "governing_share": xr.zeros_like(leg).expand_dims(criterion=crit["criterion"].values)
                       .transpose(*dims, "criterion").copy(),
                       "workability_leg_variant": var, "workability_route_variant": route_var,
                       "workability_leg_min": np.minimum(var.min(bands), leg),
                       "workability_leg_max": np.maximum(var.max(bands), leg),
                       "workability_route_min": np.minimum(route_var.min(bands), route),
                       "workability_route_max": np.maximum(route_var.max(bands), route)})
    edges = {"hs_lower": (("leg", "hs"), [[0.0, 1.5]] * 2), "hs_upper": (("leg", "hs"), [[1.5, 3.0]] * 2),
             "tz_lower": (("leg", "tz"), [[4.0, 7.0]] * 2), "tz_upper": (("leg", "tz"), [[7.0, 10.0]] * 2)}
    sea = xr.Dataset({**edges, "leg_weight": weight}, coords={"leg": list(sea_legs), "hs": [0.75, 2.25],
                                                              "tz": [5.5, 8.5]})
    return work, sea


def test_the_workability_dataset_takes_the_hourly_leg_and_keeps_the_binned_one():
    work, sea = _work()
    m = measured([2.0, 2.0, 2.0, 1.0], [6.0] * 4, [1.0, 1.0, 1.5, 1.0], [[1, 0], [0, 1], [1, 0], [0.5, 0.5]])
    out = apply_measured_legs(work.copy(deep=True), sea, curve(), m, CRIT)
    np.testing.assert_allclose(out["workability_leg_binned"].values, work["workability_leg"].values)
    np.testing.assert_allclose(out["workability_leg"].sel(leg="m").values.ravel(), [0.5, 1.0])
    np.testing.assert_allclose(out["workability_leg"].sel(leg="s").values, work["workability_leg"].sel(leg="s").values)
    np.testing.assert_allclose(out["workability_route"].values,
                               (out["workability_leg"] * sea["leg_weight"]).sum("leg").values)
    assert out["leg_hourly"].values.tolist() == [True, False]
    # the band moved with the leg, the nominal inside it
    assert np.all(out["workability_route_min"] <= out["workability_route"])
    assert np.all(out["workability_route"] <= out["workability_route_max"])
    moved = out["workability_leg_variant"].sel(leg="m", candidate="a") - \
        work["workability_leg_variant"].sel(leg="m", candidate="a")
    np.testing.assert_allclose(moved.values, 0.5 - 0.9)
    assert float(out["governing_share"].sel(leg="m", candidate="a", tugger="none", criterion="relative_sway_m")) == 0.5
    # a cell that fails on its winch fails the hours in it: hour 4 (Hs 1.0, Tz 6) is in
    # cell (hs 0.75, tz 5.5); the others in (hs 2.25, tz 5.5)
    fails = xr.zeros_like(xr.DataArray(np.zeros((2, 1, 2, 2, 2, 2)), dims=(
        "candidate", "tugger", "leg", "heading", "hs", "tz")), dtype=bool).assign_coords(
        candidate=["a", "b"], tugger=["none"], leg=["m", "s"], heading=[90.0, 120.0], hs=[0.75, 2.25], tz=[5.5, 8.5])
    fails.loc[dict(candidate="b", leg="m", hs=0.75, tz=5.5)] = True
    work2, _ = _work()
    work2["verdict_source"] = xr.where(fails, SATURATED_FAIL, FREQUENCY_DOMAIN).astype(np.int8)
    out2 = apply_measured_legs(work2, sea, curve(), m, CRIT)
    assert float(out2["workability_leg"].sel(leg="m", candidate="b", tugger="none")) == pytest.approx(0.75)
    # the hour failing on its winch alone is no criterion's: the criteria's shares stay 0
    assert float(out2["governing_share"].sel(leg="m", candidate="b", tugger="none").sum()) == 0.0
    with pytest.raises(InputError, match="legs the route does not have"):
        apply_measured_legs(_work(("x", "s"))[0], _work(("x", "s"))[1], curve(), m, CRIT)


def test_the_route_simulation_scales_the_sway_of_a_spectra_legs_hours():
    """A leg's hours with a measured-spectrum sway ratio of 2 double the relative sway's
    hourly MPM and sigma in the route simulation; the roll and the other leg stay."""
    from jls.assessment.hourly import route_sway_scale
    from jls.assessment.route_simulation import hourly_statistics
    crit, hours, hp = route_case()
    m = measured(np.full(5, 1.5), np.full(5, 6.0), np.full(5, 2.0), np.ones((5, 1)), headings=(90.0,))
    scale = route_sway_scale(m, hours)
    assert float(scale.sel(leg="s").max()) == 1.0 and float(scale.sel(leg="m").min()) == 2.0
    plain, _ = hourly_statistics(crit, hours, hp)
    scaled, _ = hourly_statistics(crit, hours, hp, sway_scale=scale)
    ratio = scaled / plain
    np.testing.assert_allclose(ratio["level"].sel(criterion="relative_sway_m", leg="m").values, 2.0)
    np.testing.assert_allclose(ratio["sigma"].sel(criterion="relative_sway_m", leg="m").values, 2.0)
    np.testing.assert_allclose(ratio["level"].sel(criterion="relative_sway_m", leg="s").values, 1.0)
    np.testing.assert_allclose(ratio["level"].sel(criterion="relative_roll_deg").values, 1.0)
    np.testing.assert_allclose(ratio["tz_response"].values, 1.0)
    assert route_sway_scale(None, hours) is None
