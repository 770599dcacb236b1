"""Voyage extremes and route simulation: the long-term formula against Monte Carlo and the
short-term distribution, monotonicity, storms met by departures, gaps, record errors,
the sliding window reductions against brute force."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from scipy.optimize import brentq

from jls.assessment import voyage
from jls.assessment.criterion_levels import criterion_statistics
from jls.assessment.route_hours import common_hours
from jls.assessment.route_simulation import (
    hourly_statistics,
    route_simulation,
    simulate_route,
)
from jls.assessment.sliding_windows import sliding_max, sliding_sum
from jls.assessment.voyage import hindcast_long_term, long_term_extreme, voyage_dataset
from jls.errors import InputError
from jls.response.statistics import from_moments

RESPONSES = ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]


def table(cells, duration_h=10.0, option_sigma=None):
    """A one-leg table from cells (hs [m], tz [s], p, sigma per m Hs, Tz_r [s]) at beam seas:
    unit statistics (option, heading, tz) and the cell arrays of long_term_extreme."""
    hs = sorted({c[0] for c in cells})
    tz = sorted({c[1] for c in cells})
    p = np.zeros((1, 1, len(hs), len(tz)))
    sig = np.zeros((1, len(tz)))
    tzr = np.full((1, len(tz)), 10.0)
    for h, t, prob, s, r in cells:
        p[0, 0, hs.index(h), tz.index(t)] += prob
        sig[0, tz.index(t)], tzr[0, tz.index(t)] = s, r
    scale = np.asarray([1.0] if option_sigma is None else option_sigma, float)
    coords = {"option": np.arange(scale.size), "heading": [90.0], "tz": tz}
    with np.errstate(invalid="ignore"):                   # inf x 0: a cell without response
        scaled = np.where(sig[None] == 0, 0.0, scale[:, None, None] * sig[None])
    sigma = xr.DataArray(scaled, dims=("option", "heading", "tz"), coords=coords)
    tz_r = xr.DataArray(np.broadcast_to(tzr[None], sigma.shape), dims=("option", "heading", "tz"),
                        coords=coords)
    cp = xr.DataArray(p, dims=voyage.CELL_DIMS, coords={"leg": ["leg"], "heading": [90.0], "hs": hs, "tz": tz})
    hs_da = xr.DataArray([hs], dims=("leg", "hs"), coords={"leg": ["leg"], "hs": hs})
    dur = xr.DataArray([float(duration_h)], dims="leg", coords={"leg": ["leg"]})
    return sigma, tz_r, cp, hs_da, dur


def extreme(cells, limit, duration_h=10.0, q=voyage.NON_EXCEEDANCE, **kw):
    return long_term_extreme(*table(cells, duration_h, kw.pop("option_sigma", None)), limit,
                             non_exceedance=q, **kw)


# ---- long-term extreme -------------------------------------------------------------------

def test_one_cell_is_the_short_term_distribution_of_the_maximum():
    # Hs 2 m, sigma 0.8 m per m, Tz_r 15 s over the 3-h exposure: N = 720 cycles.
    s, n = 1.6, 3 * 3600 / 15.0
    x = np.linspace(3.0, 9.0, 25)
    cell = [(2.0, 8.0, 1.0, 0.8, 15.0)]
    p = np.array([float(extreme(cell, xi, 3.0)["exceedance_probability"].squeeze()) for xi in x])
    np.testing.assert_allclose(p, 1 - np.exp(-n * np.exp(-x ** 2 / (2 * s ** 2))), rtol=1e-12)
    q = np.array([np.exp(-1), 0.5, 0.9, 0.99])
    level = extreme(cell, 3.0, 3.0, q)["voyage_level"].squeeze().values
    np.testing.assert_allclose(level, s * np.sqrt(2 * np.log(n / -np.log(q))), rtol=1e-12)
    # the level at probability exp(-1) is the project's MPM of that sea state
    stats = from_moments(s ** 2, s ** 2 * (2 * np.pi / 15.0) ** 2, 3 * 3600.0, "response")
    assert level[0] == pytest.approx(float(stats["mpm"]), rel=1e-12)
    assert level[0] == pytest.approx(s * np.sqrt(2 * np.log(n)), rel=1e-12)


def test_the_mode_of_the_maximum_is_sigma_sqrt_2_ln_n():
    # F(x) = exp(-N exp(-u)), u = x^2 / (2 sigma^2): u is Gumbel with mode ln N exactly, so
    # x = sigma sqrt(2 ln N) is the mode of u; the density in x peaks slightly higher,
    # where N exp(-u) = 1 - 1 / (2u) (0.5 % above for N = 720).
    s, n = 1.6, 720.0
    cell = [(2.0, 8.0, 1.0, 0.8, 15.0)]
    x = np.linspace(4.0, 8.0, 4001)
    F = 1 - extreme(cell, xr.DataArray(x, dims="x"), 3.0)["exceedance_probability"].squeeze().values
    u = x ** 2 / (2 * s ** 2)
    mode_u = u[1:-1][np.argmax(np.diff(F[:-1]) / np.diff(u[:-1]) + np.diff(F[1:]) / np.diff(u[1:]))]
    assert mode_u == pytest.approx(np.log(n), abs=2e-3)
    mode_x = x[1:-1][np.argmax(F[2:] - F[:-2])]
    exact = s * np.sqrt(2 * brentq(lambda v: n * np.exp(-v) - 1 + 1 / (2 * v), 1.0, 20.0))
    assert mode_x == pytest.approx(exact, abs=2e-3)
    assert mode_x == pytest.approx(s * np.sqrt(2 * np.log(n)), rel=0.01)


def test_two_cell_table_against_a_monte_carlo_of_independent_rayleigh_maxima():
    # 14 h: 90 % at Hs 2 m (sigma 1.0 m, Tz_r 12 s: 3780 peaks), 10 % at Hs 4 m (sigma
    # 2.0 m, Tz_r 14 s: 360 peaks); each peak Rayleigh, all independent.
    cells = [(2.0, 7.0, 0.9, 0.5, 12.0), (4.0, 9.0, 0.1, 0.5, 14.0)]
    q = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
    ds = extreme(cells, 6.5, 14.0, q)
    rng = np.random.default_rng(7)
    trials, maxima = 10000, []
    for _ in range(trials // 1000):
        calm = 1.0 * np.sqrt(-2 * np.log(rng.random((1000, 3780)))).max(-1)
        storm = 2.0 * np.sqrt(-2 * np.log(rng.random((1000, 360)))).max(-1)
        maxima.append(np.maximum(calm, storm))
    maxima = np.concatenate(maxima)
    level = ds["voyage_level"].squeeze().values
    empirical = (maxima[:, None] <= level[None, :]).mean(0)
    np.testing.assert_allclose(empirical, q, atol=4 * np.sqrt(0.25 / trials))
    p = float(ds["exceedance_probability"].squeeze())
    assert (maxima > 6.5).mean() == pytest.approx(p, abs=4 * np.sqrt(p * (1 - p) / trials))
    share = ds["crossing_share"].squeeze().sel(hs=4.0, tz=9.0)
    expected = 360 * np.exp(-6.5 ** 2 / 8) / (360 * np.exp(-6.5 ** 2 / 8) + 3780 * np.exp(-6.5 ** 2 / 2))
    assert float(share) == pytest.approx(expected, rel=1e-6)      # the storm cell dominates
    assert float(ds["crossing_share"].sum()) == pytest.approx(1.0, rel=1e-6)


def scatter_cells(rng, n_cells=30):
    return [(float(rng.choice(np.arange(0.25, 8, 0.5))), float(t), float(rng.random()),
             float(rng.uniform(0.05, 0.6)), float(rng.uniform(8, 20)))
            for t in rng.choice(np.arange(3.5, 15), n_cells)]


def test_exceedance_falls_with_the_level_and_rises_with_the_duration():
    rng = np.random.default_rng(3)
    cells = scatter_cells(rng)
    total = sum(c[2] for c in cells)
    cells = [(h, t, p / total, s, r) for h, t, p, s, r in cells]
    x = xr.DataArray(np.linspace(0.5, 12.0, 60), dims="x")
    short, long = (extreme(cells, x, d)["exceedance_probability"].squeeze().values for d in (50.0, 125.0))
    assert (np.diff(short) <= 0).all() and (np.diff(short)[(short[1:] > 1e-12) & (short[1:] < 1 - 1e-12)] < 0).all()
    assert (long >= short).all() and (long > short)[(short > 1e-12) & (short < 1 - 1e-12)].all()
    lv = [extreme(cells, 3.0, d)["voyage_level"].squeeze().values for d in (50.0, 125.0)]
    assert (lv[1] > lv[0]).all() and lv[0][1] > lv[0][0]


def test_the_curve_at_levels_equals_the_long_term_extreme_at_each_limit():
    """exceedance_at_levels forms each option's terms once for all the levels: the same
    probabilities as long_term_extreme with the limit swept, options of any scale, a
    cell without response and an option whose limit is broken at rest (sigma inf)."""
    rng = np.random.default_rng(5)
    cells = scatter_cells(rng) + [(1.25, 9.0, 0.0, 0.0, 10.0)]
    total = sum(c[2] for c in cells)
    cells = [(h, t, p / total, s, r) for h, t, p, s, r in cells]
    sigma, tz_r, cp, hs, dur = table(cells, 125.0, option_sigma=[0.5, 1.0, 2.0, np.inf])
    levels = np.geomspace(0.05, 20.0, 40)
    limit = xr.DataArray([3.0, 3.0, 2.0, 3.0], dims="option")
    got = voyage.exceedance_at_levels(sigma, tz_r, cp, hs, dur, limit, levels, threads=2)
    swept = long_term_extreme(sigma, tz_r, cp, hs, dur, limit * xr.DataArray(levels, dims="level"),
                              non_exceedance=(), shares=False)["exceedance_probability"]
    np.testing.assert_allclose(got.transpose("option", "level").values,
                               swept.transpose("option", "level").values, rtol=1e-12, atol=0)
    assert (got.sel(option=3) == 1.0).all()                 # broken at rest: certain
    assert (np.diff(got.sel(option=1).values) <= 0).all()


def test_levels_invert_the_exceedance_for_hard_tables():
    # sigma spread over two decades (a kinked log Lambda), cells without response, a
    # limit broken at rest (sigma = inf) and an unknown statistic (NaN)
    rng = np.random.default_rng(11)
    cells = [(h, t, p, s * 10 ** rng.uniform(-1, 1), r) for h, t, p, s, r in scatter_cells(rng, 40)]
    cells.append((3.0, 16.0, 0.05, 0.0, 10.0))
    scale = [1.0, 0.3, 3.0, 0.0, np.inf, np.nan]
    q = np.array([0.01, 0.5, 0.9, 0.999])
    ds = extreme(cells, 3.0, 125.0, q, option_sigma=scale)
    level = ds["voyage_level"].values
    for k, lv in enumerate(level[:3]):
        back = extreme(cells, xr.DataArray(lv, dims="q"), 125.0, option_sigma=[scale[k]])
        np.testing.assert_allclose(1 - back["exceedance_probability"].squeeze().values, q, rtol=1e-9)
    np.testing.assert_array_equal(level[3], 0.0)                  # no response: never exceeded
    assert np.isinf(level[4]).all() and float(ds["exceedance_probability"][4]) == 1.0
    assert np.isnan(level[5]).all() and np.isnan(ds["exceedance_probability"][5])
    total = ds["crossing_share"].sum(("leg", "heading", "hs", "tz"), skipna=False).values
    np.testing.assert_allclose(total[[0, 1, 2, 4]], 1.0, rtol=1e-6)
    assert total[3] == 0.0 and np.isnan(total[5])                   # no up-crossings; unknown


def test_hindcast_hours_as_cells_reproduce_the_table():
    # 1000 hours: 900 in one sea state, 100 in another, at Tz grid points
    cells = [(2.0, 7.0, 0.9, 0.5, 12.0), (4.0, 9.0, 0.1, 0.6, 14.0)]
    sigma, tz_r, cp, hs, dur = table(cells, 125.0)
    hours = xr.Dataset({"hs": (("leg", "time"), [np.r_[np.full(900, 2.0), np.full(100, 4.0)]]),
                        "tz": (("leg", "time"), [np.r_[np.full(900, 7.0), np.full(100, 9.0)]])},
                       coords={"leg": ["leg"], "time": pd.date_range("2001", periods=1000, freq="h")})
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["leg"], "heading": [90.0]})
    a = long_term_extreme(sigma, tz_r, cp, hs, dur, 5.0)
    b = hindcast_long_term(sigma, tz_r, hours, dur, hp, 5.0)
    for v in ("exceedance_probability", "voyage_level"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=1e-10)


def test_levels_invert_the_exceedance_for_many_small_cells():
    # 5000 hindcast hours, each a cell of probability 1 / 5000 (a few without record):
    # no single cell bounds the root well; the group bound and the Newton steps must
    rng = np.random.default_rng(4)
    hs = np.exp(rng.normal(0.0, 0.6, (2, 5000)))
    tz = rng.uniform(3.0, 14.0, (2, 5000))
    hs[0, :30] = np.nan
    hours = xr.Dataset({"hs": (("leg", "time"), hs), "tz": (("leg", "time"), tz)},
                       coords={"leg": ["a", "b"], "time": pd.date_range("2001", periods=5000, freq="h")})
    grid = np.arange(3.0, 14.5)
    coords = {"option": [0, 1], "heading": [90.0], "tz": grid}
    sigma = xr.DataArray(rng.uniform(0.05, 0.4, (2, 1, grid.size)), dims=("option", "heading", "tz"),
                         coords=coords)
    tz_r = xr.DataArray(rng.uniform(8.0, 15.0, (2, 1, grid.size)), dims=sigma.dims, coords=coords)
    dur = xr.DataArray([50.0, 75.0], dims="leg", coords={"leg": ["a", "b"]})
    hp = xr.DataArray([[1.0], [1.0]], dims=("leg", "heading"), coords={"leg": ["a", "b"], "heading": [90.0]})
    q = np.array([0.5, 0.9, 0.99])
    level = hindcast_long_term(sigma, tz_r, hours, dur, hp, 3.0, non_exceedance=q)["voyage_level"]
    back = hindcast_long_term(sigma, tz_r, hours, dur, hp, level.rename(non_exceedance="q"))
    np.testing.assert_allclose(1 - back["exceedance_probability"].transpose("option", "q").values,
                               np.broadcast_to(q, (2, 3)), rtol=1e-9)


# ---- sliding windows ---------------------------------------------------------------------

@pytest.mark.parametrize("m", [1, 2, 7, 50, 101])
def test_sliding_max_and_sum_equal_brute_force(m):
    rng = np.random.default_rng(m)
    a = rng.normal(size=(3, m))
    a[1, rng.integers(0, m)] = np.nan
    for n in sorted({n for n in (1, 2, 3, m // 2, m - 1, m) if 1 <= n <= m}):
        brute_max = np.array([[r[i:i + n].max() for i in range(m - n + 1)] for r in a])
        brute_sum = np.array([[r[i:i + n].sum() for i in range(m - n + 1)] for r in a])
        np.testing.assert_array_equal(sliding_max(a, n), brute_max)
        np.testing.assert_allclose(sliding_sum(a, n), brute_sum, rtol=1e-12, atol=1e-12)
        ints = rng.integers(0, 2, (2, m))
        np.testing.assert_array_equal(sliding_sum(ints, n),
                                      [[r[i:i + n].sum() for i in range(m - n + 1)] for r in ints])


def test_sliding_sum_keeps_small_windows_accurate_after_large_values():
    a = np.r_[np.full(1000, 1e8), np.full(1000, 1e-8)]
    np.testing.assert_allclose(sliding_sum(a, 10)[-5:], 1e-7, rtol=1e-12)


# ---- route simulation --------------------------------------------------------------------

def unit_stats(sway_mpm=0.5, sway_sigma=0.15, tz_r=12.0, tz=(3.0, 15.0)):
    shape = (1, 1, 1, 4, len(tz))
    data = {"mpm": np.zeros(shape), "sigma": np.zeros(shape), "tz_response": np.full(shape, tz_r)}
    data["mpm"][..., 0, :], data["sigma"][..., 0, :] = sway_mpm, sway_sigma
    return xr.Dataset({k: (("candidate", "tugger", "heading", "response", "tz"), v) for k, v in data.items()},
                      coords={"candidate": ["baseline"], "tugger": ["none"], "heading": [90.0],
                              "response": RESPONSES, "tz": list(tz)})


def sway_limit(value=3.0):
    return xr.DataArray([value], dims="criterion",
                        coords={"criterion": ["relative_sway_m"], "response": ("criterion", ["relative_sway"]),
                                "criterion_units": ("criterion", ["m"]), "strict": ("criterion", [False])})


def record(hs, start="2001-01-01 00:00", tz=6.0, source="synthetic.txt"):
    hs = np.asarray(hs, float)
    idx = pd.date_range(start, periods=hs.size, freq="1h", tz="UTC", name="time")
    df = pd.DataFrame({"hs": hs, "tz": np.full(hs.size, tz)}, index=idx).dropna()
    df.attrs["source"] = source
    return df


def simulate(records, durations, stats=None, limit=None):
    limit = sway_limit() if limit is None else limit
    crit = criterion_statistics(unit_stats() if stats is None else stats, limit)
    hours = common_hours(records)
    legs = list(records)
    hp = xr.DataArray(np.ones((len(legs), 1)), dims=("leg", "heading"), coords={"leg": legs, "heading": [90.0]})
    h, _ = hourly_statistics(crit, hours, hp)
    dur = xr.DataArray(list(durations), dims="leg", coords={"leg": legs})
    sources = {k: r.attrs["source"] for k, r in records.items()}
    out = route_simulation(crit, hours, hp, dur, crit["limit"], strict=limit["strict"], sources=sources,
                           rows=1)
    # the same from the hourly values of every option at once
    whole = simulate_route(h["level"], hours["hs"].notnull(), dur, crit["limit"], strict=limit["strict"],
                           sigma=h["sigma"], tz_response=h["tz_response"], sources=sources)
    xr.testing.assert_identical(out.drop_vars(["hours_outside_tz", "leg"]), whole)
    # and the blocks of options on threads: the same numbers
    threaded = route_simulation(crit, hours, hp, dur, crit["limit"], strict=limit["strict"], sources=sources,
                                rows=1, threads=2)
    xr.testing.assert_identical(threaded, out)
    return out, crit, hours, hp, dur


def flags(ds):
    return ds["departure_passes"].sel(candidate="baseline", tugger="none").values


def test_a_storm_fails_exactly_the_departures_whose_voyage_meets_it():
    # calm 1 m (MPM 0.5 m), a ten-hour storm of 8 m (MPM 4 m) at hours 500-509; legs of
    # 50 h and 75.5 h (76 hourly records): the voyage of 126 h meets the storm when it
    # departs at hours 375 to 509.
    hs = np.ones(2000)
    hs[500:510] = 8.0
    shared = record(hs)
    ds, *_ = simulate({"north": shared, "south": shared}, (50.0, 75.5))
    f = flags(ds)
    assert f.size == 2000 - 126 + 1 and ds.attrs["voyage_hours"] == 126
    np.testing.assert_array_equal(np.flatnonzero(f == 0), np.arange(375, 510))
    vmax = ds["departure_max"].squeeze().values
    assert vmax[375] == pytest.approx(4.0) and vmax[374] == pytest.approx(0.5)
    # the storm only on the second leg's record: it is met from hours 375 to 459
    calm = record(np.ones(2000))
    ds, *_ = simulate({"north": calm, "south": shared}, (50.0, 75.5))
    np.testing.assert_array_equal(np.flatnonzero(flags(ds) == 0), np.arange(375, 460))
    # the departures' own probability is that of ten storm hours (sigma 1.2 m, Tz_r 12 s)
    p = ds["departure_exceedance"].squeeze().values
    expected = -np.expm1(-10 * 300 * np.exp(-9 / (2 * 1.2 ** 2)) - 116 * 300 * np.exp(-9 / (2 * 0.15 ** 2)))
    assert p[400] == pytest.approx(expected, rel=1e-9) and p[600] < 1e-80


def test_departures_across_a_gap_are_not_judged_but_counted():
    hs = np.ones(24 * 60)                                  # January and February 2001
    hs[1000] = np.nan                                      # 2001-02-11 16:00 missing
    ds, *_ = simulate({"only": record(hs)}, (48.0,))
    f = flags(ds)
    np.testing.assert_array_equal(np.flatnonzero(f == -1), np.arange(953, 1001))
    assert (f[f != -1] == 1).all()
    assert ds.attrs["departures"] == 24 * 60 - 47 and ds.attrs["departures_judged"] == 24 * 60 - 47 - 48
    np.testing.assert_array_equal(ds["departures_month"].values[:3], [744, 672 - 23, 0])
    np.testing.assert_array_equal(ds["judged_month"].values[:3], [744, 672 - 23 - 48, 0])
    assert np.isnan(ds["departure_max"].squeeze().values[953:1001]).all()
    assert float(ds["pass_probability"].squeeze()) == 1.0
    assert np.isnan(ds["pass_probability_month"].squeeze().values[2:]).all()


def test_months_best_and_worst_and_quantiles():
    jan, feb, mar = 31 * 24, 28 * 24, 31 * 24
    hs = np.r_[np.full(jan, 1.0), np.full(feb, 7.0), np.full(mar, 2.0)]      # February: MPM 3.5 m
    ds, *_ = simulate({"only": record(hs)}, (24.0,))
    p = ds["pass_probability_month"].squeeze().values
    assert p[0] == pytest.approx((jan - 23) / jan) and p[1] == 0.0 and p[2] == 1.0
    assert int(ds["best_month"].squeeze()) == 3 and int(ds["worst_month"].squeeze()) == 2
    # a month of few judged departures is not ranked when asked: February's 672 are too few
    hours = common_hours({"only": record(hs)})
    crit = criterion_statistics(unit_stats(), sway_limit())
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["only"], "heading": [90.0]})
    dur = xr.DataArray([24.0], dims="leg", coords={"leg": ["only"]})
    few = route_simulation(crit, hours, hp, dur, crit["limit"], min_judged=700)
    assert int(few["best_month"].squeeze()) == 3 and int(few["worst_month"].squeeze()) == 1
    none = route_simulation(crit, hours, hp, dur, crit["limit"], min_judged=10_000)
    assert int(none["best_month"].squeeze()) == 0
    q = ds["departure_max_quantile"].squeeze().values                        # (month, 0.5 / 0.9)
    np.testing.assert_allclose(q[1], 3.5)
    np.testing.assert_allclose(q[2], 1.0)
    assert float(ds["exceedance_fraction"].squeeze()) == pytest.approx((feb + 23) / (jan + feb + mar - 23))


def test_route_simulation_of_one_leg_agrees_with_the_weather_windows():
    from jls.assessment.windows import window_starts
    from jls.assessment.workability import cell_passes, unit_utilisation
    rng = np.random.default_rng(5)
    hs = np.clip(1.5 + 1.5 * np.sin(np.arange(3000) / 80.0) + rng.normal(0, 0.3, 3000), 0.1, None)
    hs[rng.integers(0, 3000, 20)] = np.nan
    stats = unit_stats(sway_mpm=np.array([0.6, 1.2]))
    rec = record(hs)
    rec["tz"] = rng.uniform(3.0, 15.0, len(rec))
    ds, _, hours, *_ = simulate({"only": rec}, (30.0,), stats=stats)
    util = unit_utilisation(stats, sway_limit()).interp(tz=xr.DataArray(hours["tz"].values[0], dims="time"))
    ok = cell_passes(util * xr.DataArray(hours["hs"].values[0], dims="time")).squeeze().values
    known = np.isfinite(hours["hs"].values[0])
    windows, judged = window_starts(ok & known, known, 30)
    f = flags(ds)
    np.testing.assert_array_equal(f == -1, ~judged)
    np.testing.assert_array_equal(f == 1, windows)
    assert 0.4 < (f == 1).mean() < 0.6 and (f == 0).mean() > 0.2      # both outcomes occur


def test_independent_hours_overestimate_the_exceedance_of_a_persistent_record():
    # Storms persist: the hindcast hours taken as independent cells give a higher
    # exceedance probability than the departures' own (Jensen); shuffled hours, whose
    # voyages all see a similar mix, come closer.
    rng = np.random.default_rng(2)
    n = 24 * 365
    log_hs = np.zeros(n)
    for i in range(1, n):
        log_hs[i] = 0.995 * log_hs[i - 1] + rng.normal(0, 0.05)
    hs = np.exp(log_hs)                                   # median 1 m, up to about 4 m
    results = []
    for series in (hs, rng.permutation(hs)):
        ds, crit, hours, hp, dur = simulate({"only": record(series)}, (125.0,),
                                            stats=unit_stats(sway_sigma=0.25), limit=sway_limit(3.0))
        lt = hindcast_long_term(crit["sigma"], crit["tz_response"], hours, dur, hp, crit["limit"])
        results.append((float(lt["exceedance_probability"].squeeze()),
                        float(ds["mean_departure_exceedance"].squeeze())))
    (lt_p, dep_p), (lt_s, dep_s) = results
    assert lt_p == pytest.approx(lt_s, rel=1e-9)                   # the same hours
    assert 0.05 < dep_p < lt_p < 0.95
    assert lt_p - dep_p > 3 * (lt_s - dep_s) >= 0


def test_a_record_shorter_than_the_voyage_is_an_error_naming_the_leg():
    shared = record(np.ones(100), source="ndbc_short.txt")
    with pytest.raises(InputError, match=r"ndbc_short\.txt: legs\[south\]: the voyage runs past"):
        simulate({"north": shared, "south": shared}, (50.0, 75.0))
    with pytest.raises(InputError, match=r"legs\[north\]: the hourly record spans 100 h, shorter"):
        simulate({"north": shared, "south": record(np.ones(500))}, (120.0, 75.0))
    late = record(np.ones(200), start="2002-01-01")
    with pytest.raises(InputError, match=r"legs\[north\]: .*ends at 2001-01-09 07:00:00, before"):
        simulate({"north": record(np.ones(200)), "south": late}, (50.0, 75.0))


# ---- criteria and the dataset ------------------------------------------------------------

def test_tension_criteria_use_the_dynamic_part_against_the_allowance():
    from jls.assessment.workability import criteria_array
    stats = unit_stats()
    wires = ["a", "b"]
    dims = ("candidate", "tugger", "heading", "tz", "wire")
    stats["tension_sigma"] = (dims, np.array([100.0, 300.0]) * np.ones((1, 1, 1, 2, 2)))
    stats["tension_mpm"] = (dims, np.array([400.0, 1200.0]) * np.ones((1, 1, 1, 2, 2)))
    stats["tension_tz_response"] = (dims, np.array([11.0, 13.0]) * np.ones((1, 1, 1, 2, 2)))
    stats["tension_static"] = (("candidate", "wire"), [[21000.0, 20000.0]])
    stats = stats.assign_coords(wire=wires)
    limit = criteria_array({"relative_sway_m": 3.0, "max_wire_tension_kN": 25000.0})
    crit = criterion_statistics(stats, limit)
    t = crit.sel(criterion="max_wire_tension_kN").squeeze()
    # utilisation per m Hs: 400 / 4000 on wire a, 1200 / 5000 on wire b (governs)
    np.testing.assert_allclose(t["sigma"].values, 300.0 / 5000.0)
    np.testing.assert_allclose(t["tz_response"].values, 13.0)
    assert float(crit["limit"].sel(criterion="max_wire_tension_kN")) == 1.0
    assert crit["level_units"].values.tolist() == ["m", "1"]
    broken = criterion_statistics(stats, criteria_array({"max_wire_tension_kN": 20500.0}))
    assert np.isinf(broken["sigma"]).all()


def test_voyage_dataset_holds_the_contract_and_writes(tmp_path):
    cells = [(2.0, 7.0, 0.9, 0.5, 12.0), (4.0, 9.0, 0.1, 0.6, 14.0)]
    _, _, cp, hs, dur = table(cells, 125.0)
    crit = criterion_statistics(unit_stats(tz=(7.0, 9.0)), sway_limit())
    lt = long_term_extreme(crit["sigma"], crit["tz_response"], cp, hs, dur, crit["limit"])
    ds = voyage_dataset(lt, crit["limit"], attrs={"route": "test", "hs_in_bin": "centre"})
    assert ds["exceedance_probability"].dims == ("candidate", "tugger", "criterion")
    assert ds["voyage_level"].dims == ("candidate", "tugger", "criterion", "non_exceedance")
    assert ds["non_exceedance"].values.tolist() == [0.5, 0.9]
    assert ds["voyage_level"].attrs["units_from"] == "level_units"
    assert ds["level_units"].values.tolist() == ["m"]
    # with a hindcast: the route simulation and the same hours' long-term extreme
    hs_hours = np.ones(24 * 40)
    hs_hours[300:310] = 8.0
    route, crit, hours, hp, dur = simulate({"leg": record(hs_hours)}, (125.0,))
    hind = hindcast_long_term(crit["sigma"], crit["tz_response"], hours, dur, hp, crit["limit"])
    full = voyage_dataset(lt, crit["limit"], route=route, hindcast=hind, attrs={"route": "test"})
    for var in ("departure_max", "departure_passes", "pass_probability_month", "best_month",
                "hindcast_exceedance_probability", "hindcast_voyage_level", "hours_outside_tz"):
        assert var in full and "long_name" in full[var].attrs
    assert full.attrs["departures"] == 24 * 40 - 125 + 1
    assert full["departure_passes"].attrs["flag_meanings"] == "not_judged fails passes"
    full.to_netcdf(tmp_path / "voyage.nc")
    back = xr.open_dataset(tmp_path / "voyage.nc")
    np.testing.assert_allclose(back["voyage_level"].values, ds["voyage_level"].values)
    np.testing.assert_array_equal(back["departure_passes"].values, full["departure_passes"].values)
