"""The departure rule's compiled kernels against their definitions: the windows' verdicts
against sliding maxima, the hours' utilisation against the interpolation of every
criterion's statistics (non-finite statistics, several headings, a strict criterion at
its limit), the plan's quantiles and monthly counts against numpy's per row and month,
and a plan of whole hours against one whose values are not (the general path)."""

import numpy as np
import xarray as xr

from jls.assessment.departure_kernels import hour_utilisation
from jls.assessment.departure_rule import (
    NOT_JUDGED,
    SAILED,
    WAIT_STEPS_H,
    Departures,
    simulate_departures,
    stretch_arrays,
    stretches,
    summarise,
)
from jls.assessment.route_simulation import _Hours
from jls.assessment.sliding_windows import sliding_max
from jls.assessment.voyage_plan import _compiled, hourly_level, utilisation


def _record(rng, rows, legs, m):
    u = rng.gamma(2.0, 0.4, (rows, legs, m))
    u[rng.random(u.shape) < 0.03] = np.nan                 # unrecorded hours
    u[rng.random(u.shape) < 0.005] = np.inf                # a limit broken at rest
    u[rng.random(u.shape) < 0.01] = 1.0                    # exactly at the limit: allowed, not exceeding
    return u


def test_window_verdicts_are_those_of_the_windows_maxima():
    rng = np.random.default_rng(3)
    for trial in range(20):
        legs, m = int(rng.integers(1, 4)), int(rng.integers(60, 400))
        u = _record(rng, 3, legs, m)
        fc = u / 0.8 if trial % 2 else u
        for st in stretches(rng.random(legs) < 0.5, rng.uniform(1, 20, legs), [4.0] * legs):
            horizon = int(rng.integers(1, 40))
            allowed, exc, known, gap = stretch_arrays(u, fc, st, horizon)
            n = allowed.shape[-1]
            fmax, amax = np.full((3, n), -np.inf), np.full((3, n), -np.inf)
            nan_f = np.zeros((3, n), bool)
            for k, s, w in st.windows(horizon):
                f = fc[:, k, s: s + n + w - 1]
                fmax = np.fmax(fmax, sliding_max(np.where(np.isnan(f), np.inf, f), w))
                nan_f |= sliding_max(np.isnan(f).astype(np.int8), w) > 0
            for k, s, w in st.sailed():
                x = sliding_max(u[:, k, s: s + n + w - 1], w)
                amax = np.where(np.isnan(x) | np.isnan(amax), np.nan, np.maximum(amax, x))
            np.testing.assert_array_equal(allowed, fmax <= 1.0)
            np.testing.assert_array_equal(gap, nan_f)
            np.testing.assert_array_equal(exc, amax > 1.0)
            np.testing.assert_array_equal(known, np.isfinite(amax))


def _case(rng, n_cand=3, n_tug=2, headings=(0.0, 90.0, 180.0)):
    crits = ["relative_sway_m", "heave_m", "roll_deg"]
    tz = np.arange(3.0, 14.01, 0.5)
    shape = (n_cand, n_tug, len(crits), len(headings), tz.size)
    mpm = rng.uniform(0.1, 2.0, shape)
    mpm[0, 0, 1, -1, 4] = np.nan                           # unknown at one Tz of one heading
    mpm[-1, -1, 2, 0, -1] = np.inf                          # broken at rest at the grid's end
    dims = ("candidate", "tugger", "criterion", "heading", "tz")
    coords = {"candidate": [f"c{i}" for i in range(n_cand)], "tugger": [f"t{i}" for i in range(n_tug)],
              "criterion": crits, "heading": list(headings), "tz": tz}
    stats = xr.Dataset({v: (dims, mpm * f) for v, f in (("mpm", 1.0), ("sigma", 0.3), ("tz_response", 9.0))},
                       coords=coords)
    m = 500
    hs = rng.uniform(0.2, 4.0, (2, m))
    t = rng.uniform(2.0, 15.0, (2, m))                      # some beyond the grid: held at its ends
    hs[:, 7], t[:, 7] = np.nan, np.nan                      # an unrecorded hour
    t[0, 10] = 4.0                                          # exactly on a grid point
    hours = xr.Dataset({"hs": (("leg", "time"), hs), "tz": (("leg", "time"), t)},
                       coords={"leg": ["a", "b"], "time": np.arange(m)})
    p = np.ones((2, len(headings))) / len(headings)
    if len(headings) > 1:                                   # leg a never meets the last heading
        p[0, -1], p[0, 0] = 0.0, p[0, 0] + p[0, -1]
    hp = xr.DataArray(p, dims=("leg", "heading"), coords={"leg": ["a", "b"], "heading": list(headings)})
    return stats.transpose(..., "criterion", "heading", "tz"), hours, hp


def test_the_hours_utilisation_in_one_pass_equals_the_interpolated_levels_over_their_limits():
    rng = np.random.default_rng(4)
    stats, hours, hp = _case(rng)
    h = _Hours(stats, hours, hp)
    n_crit = stats.sizes["criterion"]
    n_opt = stats.sizes["candidate"] * stats.sizes["tugger"]
    args = _compiled(h)
    for lim, strict in (([1.0, 1.5, 2.0], [False, False, False]), ([1.0, 1.5, 2.0], [True, False, True])):
        lim, strict = np.array(lim), np.array(strict)
        # a strict criterion exactly at its limit in one hour: beyond it
        level = hourly_level(h, slice(None))
        np.testing.assert_array_equal(level, h.rows(slice(None))[0])
        want = utilisation(level.reshape(n_opt, n_crit, *level.shape[1:]), lim, strict)
        got = hour_utilisation(*args, lim, strict, 0, n_opt)
        np.testing.assert_array_equal(got, want)
        part = hour_utilisation(*args, lim, strict, 2 * n_crit, 3)          # options 2..4 alone
        np.testing.assert_array_equal(part, want[2:5])
    assert np.isnan(want).any() and np.isinf(want).any()                      # both reached the kernel


def test_a_strict_criterion_at_exactly_its_limit_is_beyond_it_in_the_compiled_pass():
    rng = np.random.default_rng(5)
    stats, hours, hp = _case(rng, n_cand=1, n_tug=1, headings=(90.0,))
    stats["mpm"][:] = 0.5                                   # level Hs x 0.5: 1.0 at Hs 2 m
    hours["hs"][:] = 2.0
    h = _Hours(stats, hours, hp)
    u = hour_utilisation(*_compiled(h), np.array([1.0, 4.0, 4.0]), np.array([True, False, False]), 0, 1)
    recorded = np.ones(u.shape[-1], bool)
    recorded[7] = False                                     # no Tz: no level
    assert (u[..., recorded] == np.nextafter(1.0, 2.0)).all() and (u[..., 7] == 0.0).all()
    u = hour_utilisation(*_compiled(h), np.array([1.0, 4.0, 4.0]), np.array([False, False, False]), 0, 1)
    assert (u[..., recorded] == 1.0).all()


def _reference(d, months, q):
    """summarise's shares and quantiles by their definitions, row by row and month by month."""
    sailed = d.status == SAILED
    total = np.where(sailed, np.nansum(d.wait_h, axis=1), np.nan)
    out = {}
    for r in range(d.status.shape[0]):
        for mo in [None, *range(1, 13)]:
            sel = np.ones(months.size, bool) if mo is None else months == mo
            w = total[r][sel & sailed[r]]
            t = d.transit_h[r][sel & sailed[r]]
            out[(r, mo)] = {
                "sailed": int((sailed[r] & sel).sum()), "judged": int(((d.status[r] != NOT_JUDGED) & sel).sum()),
                "wait_h": np.quantile(w, q, method="inverted_cdf") if w.size else np.full(len(q), np.nan),
                "transit_h": np.quantile(t, q, method="inverted_cdf") if t.size else np.full(len(q), np.nan)}
    return out


def test_the_plans_quantiles_and_monthly_counts_are_numpys_per_row_and_month():
    rng = np.random.default_rng(6)
    t = np.arange(3000)
    period = np.array([150.0, 190.0, 230.0, 270.0])[:, None, None]     # storms every 6-11 days
    u = 0.5 + 0.6 * np.sin(2 * np.pi * t / period) + rng.uniform(0.0, 0.1, (4, 2, t.size))
    u[:, :, 1000:1003] = np.nan                             # one gap: departures around it not judged
    st = stretches([True, True], [20.0, 30.0], [6.0, 6.0])
    dep = np.arange(2500)
    months = rng.integers(1, 13, dep.size)
    d = simulate_departures(u, u / 0.9, st, dep, horizon_h=48, max_wait_h=200)
    s = summarise(d, months, (0.5, 0.9))
    ref = _reference(d, months, (0.5, 0.9))
    assert (d.status == SAILED).any() and (d.status == NOT_JUDGED).any()
    for (r, mo), want in ref.items():
        for key, x in want.items():
            got = s[key][r] if mo is None else s[key + "_month"][r, mo - 1]
            np.testing.assert_array_equal(got, x, err_msg=f"{key} row {r} month {mo}")
    total = np.where(d.status == SAILED, np.nansum(d.wait_h, axis=1), np.nan)
    n_sailed = (d.status == SAILED).sum(-1)
    assert (n_sailed > 0).all() and (np.nanmax(total, axis=-1) > 24).all()   # waits to count in every row
    for i, x in enumerate(WAIT_STEPS_H):
        np.testing.assert_array_equal(s["wait_cdf"][:, i], (total <= x).sum(-1) / n_sailed)


def test_waits_that_are_not_whole_hours_take_the_general_path_to_the_same_quantiles():
    rng = np.random.default_rng(7)
    rows, nd = 3, 400
    status = rng.choice([NOT_JUDGED, 0, SAILED], size=(rows, nd), p=[0.1, 0.2, 0.7]).astype(np.int8)
    wait = rng.integers(0, 300, (rows, 1, nd)).astype(float)
    months = rng.integers(1, 13, nd)
    flags = rng.choice([-1, 0, 1], size=(rows, nd)).astype(np.int8)

    def plan(w):
        return Departures(status, rng.random((rows, nd)) < 0.1, w, w[:, 0] + 50.0, flags, flags)

    whole, half = summarise(plan(wait), months), summarise(plan(wait + 0.5), months)
    for key in ("wait_h", "wait_h_month", "transit_h", "transit_h_month", "wait_hold_h"):
        np.testing.assert_array_equal(half[key], whole[key] + 0.5, err_msg=key)
    np.testing.assert_array_equal(half["sailed_month"], whole["sailed_month"])
