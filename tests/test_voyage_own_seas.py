"""The hindcast long-term voyage extreme of legs given by their own seas: each hour's level
is its own-sea utilisation times the limit (jls.assessment.voyage_own_seas)."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from scipy.optimize import brentq

from jls.assessment.hourly import at_hours, tz_weights
from jls.assessment.voyage import hindcast_long_term
from jls.response.statistics import from_moments

EXPOSURE_H = 3.0
CRITERIA = ["relative_sway_m", "relative_roll_deg"]
LIMIT = xr.DataArray([1.5, 2.0], dims="criterion", coords={"criterion": CRITERIA})


def statistics(seed=0):
    """Unit-Hs statistics (candidate, criterion, heading, tz) with the MPM of the exposure."""
    rng = np.random.default_rng(seed)
    grid = np.arange(4.0, 14.5)
    coords = {"candidate": ["a", "b"], "criterion": CRITERIA, "heading": [60.0, 90.0], "tz": grid}
    shape = (2, 2, 2, grid.size)
    m0 = rng.uniform(0.01, 0.2, shape)
    tzr = rng.uniform(8.0, 18.0, shape)
    st = from_moments(m0, m0 * (2 * np.pi / tzr) ** 2, EXPOSURE_H * 3600.0)
    dims = tuple(coords)
    return (xr.DataArray(st["sigma"], dims=dims, coords=coords),
            xr.DataArray(st["tz_response"], dims=dims, coords=coords),
            xr.DataArray(st["mpm"], dims=dims, coords=coords))


def record(n=400, seed=1):
    rng = np.random.default_rng(seed)
    hs = np.exp(rng.normal(0.3, 0.5, (2, n)))
    tz = rng.uniform(4.5, 13.5, (2, n))
    hs[1, :20] = np.nan                                   # a gap in the second leg
    tz[1, :20] = np.nan
    legs = ["open", "coast"]
    hours = xr.Dataset({"hs": (("leg", "time"), hs), "tz": (("leg", "time"), tz)},
                       coords={"leg": legs, "time": pd.date_range("2010", periods=n, freq="h")})
    dur = xr.DataArray([40.0, 25.0], dims="leg", coords={"leg": legs})
    hp = xr.DataArray([[0.3, 0.7], [1.0, 0.0]], dims=("leg", "heading"),
                      coords={"leg": legs, "heading": [60.0, 90.0]})
    return hours, dur, hp


def jonswap_utilisation(mpm, hours):
    """Each hour's utilisation on the JONSWAP of its (Hs, Tz) (leg, time, candidate,
    criterion, heading): what hourly_utilisation gives those hours."""
    out = []
    for k in range(hours.sizes["leg"]):
        w = tz_weights(hours["tz"].values[k], mpm["tz"].values)
        at = at_hours(mpm.transpose("candidate", "criterion", "heading", "tz").values, w)
        out.append(at * hours["hs"].values[k] / LIMIT.values[None, :, None, None])
    return xr.DataArray(np.stack(out), dims=("leg", "candidate", "criterion", "heading", "time"),
                        coords={"leg": hours["leg"], "time": hours["time"], "candidate": mpm["candidate"],
                                "criterion": CRITERIA, "heading": mpm["heading"]})


def solve(own=None, scale=1.0, q=(0.5, 0.9, 0.99)):
    sigma, tzr, mpm = statistics()
    hours, dur, hp = record()
    kw = {} if own is None else dict(own=own, mpm_unit=mpm, exposure_h=EXPOSURE_H)
    return hindcast_long_term(sigma * scale, tzr, hours, dur, hp, LIMIT, non_exceedance=list(q), **kw)


def test_own_hours_equal_to_their_jonswap_give_the_same_voyage_distribution():
    sigma, tzr, mpm = statistics()
    hours, _, _ = record()
    own = jonswap_utilisation(mpm, hours)
    a, b = solve(), solve(own)
    for v in ("expected_exceedances", "exceedance_probability", "voyage_level"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=1e-9)
    # without a heading dim (the worst heading) the voyage can only be as high or higher
    c = solve(own.max("heading"))
    assert (c["voyage_level"] >= a["voyage_level"] * (1 - 1e-12)).all()
    assert (c["voyage_level"] > a["voyage_level"] * 1.0001).any()


def test_a_leg_without_own_hours_keeps_its_jonswap():
    _, _, mpm = statistics()
    hours, _, _ = record()
    own = jonswap_utilisation(mpm, hours) * 3.0
    own.loc[{"leg": "coast"}] = np.nan
    only_open = solve(own)
    both = solve(jonswap_utilisation(mpm, hours) * 3.0)
    base = solve()
    assert (only_open["voyage_level"] > base["voyage_level"]).all()
    assert (only_open["voyage_level"] < both["voyage_level"]).all()


def test_own_utilisation_scales_the_voyage_level_as_the_sigma_does():
    # every hour's own-sea utilisation 2.5 x its JONSWAP's (a swell the JONSWAP misses):
    # the voyage levels are those of the JONSWAP with sigma x 2.5 (same up-crossing periods)
    _, _, mpm = statistics()
    hours, _, _ = record()
    own = jonswap_utilisation(mpm, hours) * 2.5
    np.testing.assert_allclose(solve(own)["voyage_level"].values, solve(scale=2.5)["voyage_level"].values,
                               rtol=1e-9)
    np.testing.assert_allclose(solve(own)["voyage_level"].values, 2.5 * solve()["voyage_level"].values,
                               rtol=1e-9)


def test_one_swell_hour_sets_the_largest_level_as_its_short_term_distribution():
    # one leg, one hour with sea, the others calm (own utilisation 0): the voyage max is the
    # short-term maximum of that hour over the leg's time in it, D / n_hours, at Tz_r:
    # P(max <= x) = exp(-(D 3600 / n) / Tz_r exp(-x^2 / (2 s^2))), s = u L / sqrt(2 ln N)
    sigma, tzr, mpm = statistics()
    hours, dur, hp = record()
    hours = hours.isel(leg=[0])
    hours["tz"][0, 7] = 9.0               # on the grid: sigma / MPM there is exactly 1 / sqrt(2 ln N)
    dur, hp = dur.isel(leg=[0]), hp.isel(leg=[0])
    own = jonswap_utilisation(mpm, hours)
    u = np.zeros(own.shape)
    u[..., 7] = 1.8                                        # hour 7: a swell hour at 1.8 x the limit
    own = own.copy(data=u)
    q = np.array([0.5, 0.9])
    got = hindcast_long_term(sigma, tzr, hours, dur, hp, LIMIT, non_exceedance=list(q), own=own,
                             mpm_unit=mpm, exposure_h=EXPOSURE_H)["voyage_level"]
    n = hours.sizes["time"]
    w = tz_weights(hours["tz"].values[0, [7]], tzr["tz"].values)
    t_r = at_hours(tzr.transpose("candidate", "criterion", "heading", "tz").values, w)[..., 0]  # (c, crit, h)
    s = 1.8 * LIMIT.values[None, :, None] / np.sqrt(2 * np.log(EXPOSURE_H * 3600.0 / t_r))
    # two headings met 0.3 / 0.7 of the time: Lambda = sum_h p_h D 3600 / n / Tz_r,h exp(-x^2 / 2 s_h^2)
    p = hp.values[0]
    for c in range(2):
        for j in range(2):
            for iq, qq in enumerate(q):
                lam = lambda x: sum(p[h] * float(dur[0]) * 3600.0 / n / t_r[c, j, h]
                                    * np.exp(-x * x / (2 * s[c, j, h] ** 2)) for h in range(2)) + np.log(qq)
                x = brentq(lam, 1e-9, 50.0, xtol=1e-14)
                assert float(got.isel(candidate=c, criterion=j, non_exceedance=iq)) == pytest.approx(x, rel=1e-8)
    assert (got.sel(non_exceedance=0.9) < 1.8 * LIMIT).all()          # a 1/n share of one hour


def test_an_hour_beyond_the_limit_at_rest_breaks_the_voyage():
    _, _, mpm = statistics()
    hours, _, _ = record()
    own = jonswap_utilisation(mpm, hours)
    own.loc[{"leg": "open", "candidate": "a", "criterion": CRITERIA[1]}] = np.inf
    ds = solve(own)
    assert np.isinf(ds["voyage_level"].sel(candidate="a", criterion=CRITERIA[1])).all()
    assert float(ds["exceedance_probability"].sel(candidate="a", criterion=CRITERIA[1])) == 1.0
    assert np.isfinite(ds["voyage_level"].sel(candidate="b")).all()


def test_the_route_own_utilisation_by_heading_fills_unmet_headings_with_the_worst():
    from jls.assessment.hourly import route_own_heading_utilisation
    hours, _, _ = record(n=3)
    u = np.array([[[0.4], [np.nan]], [[np.nan], [np.nan]], [[0.2], [0.9]]])      # (time, heading, candidate)
    m = xr.Dataset({"utilisation": (("leg", "time", "heading", "candidate", "tugger", "criterion"),
                                    u[None, :, :, :, None, None])},
                   coords={"leg": ["open"], "time": hours["time"].values, "heading": [60.0, 90.0],
                           "candidate": ["a"], "tugger": ["none"], "criterion": ["relative_sway_m"]})
    out = route_own_heading_utilisation(m, hours, [30.0, 60.0, 90.0])["utilisation"]
    assert out.dims == ("candidate", "tugger", "criterion", "leg", "heading", "time")
    got = out.sel(leg="open").isel(candidate=0, tugger=0, criterion=0).transpose("time", "heading").values
    np.testing.assert_array_equal(got[0], [0.4, 0.4, 0.4])           # met at 60 only: the worst everywhere
    assert np.isnan(got[1]).all()                                    # met nowhere: keeps the JONSWAP
    np.testing.assert_array_equal(got[2], [0.9, 0.2, 0.9])           # 30 not the leg's: the worst
    assert out.sel(leg="coast").isnull().all()                       # not an own-sea leg
    assert route_own_heading_utilisation(None, hours, [60.0]) is None
