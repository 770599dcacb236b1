"""The departure rule's compiled kernels (numba), one pass per option row each, for the
voyage plan of many options (:mod:`jls.assessment.voyage_plan`,
:mod:`jls.assessment.departure_rule`, whose rules they compute hour for hour):

* :func:`hour_utilisation`: the hours' utilisation from the unit MPM interpolated in Tz
  (as :func:`jls.assessment.hourly.at_hours`), the worst heading, over the limits;
* :func:`window_verdicts`: for every start hour of a stretch, over the hours of its
  forecast windows and of its sailed windows (per leg: (leg, first hour, length)), counts
  from running counts of each leg's hours (one pass per leg and row, then one difference
  per window) of: forecast hours unrecorded (NaN) or beyond 1 (none: the stretch is
  *allowed*, the largest forecast with an unrecorded hour taken as infinite being at most
  1); unrecorded forecast hours (a *gap*); sailed hours unrecorded, infinite, beyond 1 and
  above -inf (the start *exceeds* when none is unrecorded and one is beyond 1, and is
  *known* when none is unrecorded or infinite and one is above -inf: the largest sailed
  utilisation, NaN when an hour is, is finite). These are exactly the comparisons of the
  windows' maxima (counts are whole numbers), whatever the windows' lengths;
* :func:`compose_stretch`: the departures sailed through one stretch;
* :func:`group_counts`, :func:`group_histogram`, :func:`whole_range`: the plan's counts
  per departure month and the histograms of its whole-hour waits and transits.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def _running_counts(x, limit, c):
    """Running counts along x (m,) into c (5, m + 1): NaN, NaN or beyond ``limit``, +inf,
    beyond ``limit`` (not NaN), above -inf."""
    m = x.shape[0]
    c0 = c1 = c2 = c3 = c4 = 0
    c[:, 0] = 0
    for j in range(m):
        v = x[j]
        nan = v != v
        c0 += nan
        c1 += nan or v > limit
        c2 += v == np.inf
        c3 += (not nan) and v > limit
        c4 += (not nan) and v > -np.inf
        c[0, j + 1] = c0
        c[1, j + 1] = c1
        c[2, j + 1] = c2
        c[3, j + 1] = c3
        c[4, j + 1] = c4


@njit(cache=True, nogil=True)
def window_verdicts(util, forecast, win, sail, n_start, same):
    """(allowed, exceeds, known, gap) (rows, n_start) of util, forecast (rows, legs,
    time) over the forecast windows ``win`` and sailed windows ``sail`` ((n, 3) int64:
    leg, first hour, length): module docstring. ``same``: forecast is util (its running
    counts serve both)."""
    rows, legs, m = util.shape
    allowed = np.empty((rows, n_start), np.bool_)
    exceeds = np.empty((rows, n_start), np.bool_)
    known = np.empty((rows, n_start), np.bool_)
    gap = np.empty((rows, n_start), np.bool_)
    c = np.empty((5, m + 1), np.int64)
    f_bad = np.empty(n_start, np.int64)
    f_nan = np.empty(n_start, np.int64)
    u_nan = np.empty(n_start, np.int64)
    u_inf = np.empty(n_start, np.int64)
    u_over = np.empty(n_start, np.int64)
    u_real = np.empty(n_start, np.int64)
    for r in range(rows):
        f_bad[:] = 0
        f_nan[:] = 0
        u_nan[:] = 0
        u_inf[:] = 0
        u_over[:] = 0
        u_real[:] = 0
        for k in range(legs):
            used_f, used_u = False, False
            for w in range(win.shape[0]):
                used_f = used_f or win[w, 0] == k
            for w in range(sail.shape[0]):
                used_u = used_u or sail[w, 0] == k
            if used_f:
                _running_counts(forecast[r, k], 1.0, c)
                for w in range(win.shape[0]):
                    if win[w, 0] == k:
                        s, n = win[w, 1], win[w, 2]
                        for t in range(n_start):
                            f_bad[t] += c[1, t + s + n] - c[1, t + s]
                            f_nan[t] += c[0, t + s + n] - c[0, t + s]
            if used_u:
                if not (same and used_f):
                    _running_counts(util[r, k], 1.0, c)
                for w in range(sail.shape[0]):
                    if sail[w, 0] == k:
                        s, n = sail[w, 1], sail[w, 2]
                        for t in range(n_start):
                            u_nan[t] += c[0, t + s + n] - c[0, t + s]
                            u_inf[t] += c[2, t + s + n] - c[2, t + s]
                            u_over[t] += c[3, t + s + n] - c[3, t + s]
                            u_real[t] += c[4, t + s + n] - c[4, t + s]
        for t in range(n_start):
            allowed[r, t] = f_bad[t] == 0
            gap[r, t] = f_nan[t] > 0
            exceeds[r, t] = u_nan[t] == 0 and u_over[t] > 0
            known[r, t] = u_nan[t] == 0 and u_inf[t] == 0 and u_real[t] > 0
    return allowed, exceeds, known, gap


@njit(cache=True, nogil=True)
def compose_stretch(allowed, exceeds_at, known_at, gap, first, max_wait_h, sail_h, ready, status, exceeds,
                    unknown, wait, immediate, ref, ref_known, ref_at):
    """Sail one stretch from every departure's ``ready`` hour (rows, departure), updating
    the departures' state in place (:func:`jls.assessment.departure_rule.simulate_departures`,
    whose rule it is, hour for hour): the first allowed start hour at or after the ready
    hour (one backward pass per row), the wait, the verdicts of the hour sailed from, and
    the reference voyage that leaves at once. ``first``: the stretch is the route's first
    (``immediate`` is set). status: -1 not judged, 0 not sailed, 1 sailed."""
    rows, n_start = allowed.shape
    nd = ready.shape[1]
    nxt = np.empty(n_start, np.int64)
    counted = np.empty(n_start + 1, np.int64)
    for r in range(rows):
        nx = n_start
        for t in range(n_start - 1, -1, -1):
            if allowed[r, t]:
                nx = t
            nxt[t] = nx
        counted[0] = 0
        for t in range(n_start):
            counted[t + 1] = counted[t] + gap[r, t]
        for i in range(nd):
            rd = ready[r, i]
            live = status[r, i] == 1
            inside = live and rd < n_start
            at = rd if inside else 0
            start = nxt[at] if inside else n_start
            w = start - rd
            found = inside and start < n_start
            over = live and ((found and w > max_wait_h) or ((not found) and rd + max_wait_h < n_start))
            lost = live and (not found) and (not over)          # the answer lies beyond the record
            end = start if (found and not over) else rd + max_wait_h + 1
            end = min(max(end, 0), n_start)
            if live and inside and (not lost) and counted[end] - counted[at] > 0:
                lost = True                                     # a wait through an unrecorded forecast
            over = over and not lost
            ok = found and (not over) and (not lost)
            if first:
                g = gap[r, at] if n_start > 0 else True
                unknown_at = inside and w != 0 and g
                immediate[r, i] = (1 if w == 0 else 0) if (inside and not unknown_at) else -1
            if over:
                status[r, i] = 0
            if lost:
                status[r, i] = -1
            wait[r, i] = w if ok else np.nan
            go = start if ok else 0
            if n_start > 0:
                if ok and exceeds_at[r, go]:
                    exceeds[r, i] = True
                if ok and not known_at[r, go]:
                    unknown[r, i] = True
                ref_in = ref_known[r, i] and ref_at[r, i] < n_start
                ra = ref_at[r, i] if ref_in else 0
                if ref_in and exceeds_at[r, ra]:
                    ref[r, i] = True
                ref_known[r, i] = ref_in and known_at[r, ra]
            else:
                ref_known[r, i] = False
            if ok:
                ready[r, i] = start + sail_h
            ref_at[r, i] += sail_h


@njit(cache=True, nogil=True)
def group_counts(masks, group, n_group):
    """(k, rows, n_group) counts of the True entries of masks (k, rows, n) per group of
    their last axis (``group`` (n,) in 0..n_group-1)."""
    k_n, rows, n = masks.shape
    out = np.zeros((k_n, rows, n_group), np.int64)
    for k in range(k_n):
        for r in range(rows):
            for i in range(n):
                if masks[k, r, i]:
                    out[k, r, group[i]] += 1
    return out


@njit(cache=True, nogil=True)
def group_histogram(x, group, n_group, lo, n_values):
    """(rows, n_group, n_values) counts of the finite values of x (rows, n), whole
    numbers from ``lo``, per group of the last axis."""
    rows, n = x.shape
    out = np.zeros((rows, n_group, n_values), np.int64)
    for r in range(rows):
        for i in range(n):
            v = x[r, i]
            if np.isfinite(v):
                out[r, group[i], int(v - lo)] += 1
    return out


@njit(cache=True, nogil=True, error_model="numpy")
def hour_utilisation(mpm, bad, heads, lower, upper, w_lower, w_upper, hs, limit, strict, row0, n_options):
    """The hours' utilisation (options, legs, time) of ``n_options`` options from option
    row ``row0`` (rows: option x criterion, the criterion last): per criterion the unit MPM
    ``mpm`` (heading, rows, tz) interpolated in Tz at the hours (``lower``, ``upper``,
    ``w_lower``, ``w_upper`` (legs, time) of :func:`jls.assessment.hourly.tz_weights`;
    a row with a non-finite entry, ``bad`` (heading, rows), uses only its neighbours of
    weight above 0, as :func:`jls.assessment.hourly.at_hours`), the worst of the leg's
    ``heads`` (legs, n; -1 beyond its own), times the hour's Hs, over its ``limit`` (a
    ``strict`` criterion at exactly its limit counts as beyond it), the largest over the
    criteria (NaN when one is). :func:`jls.assessment.voyage_plan.hourly_level` and
    :func:`jls.assessment.voyage_plan.utilisation` in one pass."""
    n_crit = limit.shape[0]
    legs, m = hs.shape
    out = np.empty((n_options, legs, m))
    beyond = np.nextafter(1.0, 2.0)
    best = np.empty(m)
    u_max = np.empty(m)
    nan = np.empty(m, np.bool_)
    for o in range(n_options):
        for k in range(legs):
            u_max[:] = -np.inf
            nan[:] = False
            for c in range(n_crit):
                row = row0 + o * n_crit + c
                for n in range(heads.shape[1]):
                    h = heads[k, n]
                    if h < 0:
                        break
                    a = mpm[h, row]
                    for t in range(m):
                        i, j, wl, wu = lower[k, t], upper[k, t], w_lower[k, t], w_upper[k, t]
                        if bad[h, row]:
                            at = (a[i] * wl if wl > 0 else 0.0) + (a[j] * wu if wu > 0 else 0.0)
                        else:
                            at = a[i] * wl + a[j] * wu
                        if n == 0 or at > best[t]:
                            best[t] = at
                lim, st = limit[c], strict[c]
                for t in range(m):
                    u = best[t] * hs[k, t] / lim
                    if st and u == 1.0:
                        u = beyond
                    if u != u:
                        nan[t] = True
                    elif u > u_max[t]:
                        u_max[t] = u
            for t in range(m):
                out[o, k, t] = np.nan if nan[t] else u_max[t]
    return out


@njit(cache=True, nogil=True)
def whole_range(x):
    """(any finite, smallest, largest, every finite value a whole number) of x (rows, n)."""
    lo, hi, whole, seen = np.inf, -np.inf, True, False
    rows, n = x.shape
    for r in range(rows):
        for i in range(n):
            v = x[r, i]
            if np.isfinite(v):
                seen = True
                lo = min(lo, v)
                hi = max(hi, v)
                whole = whole and v == np.floor(v)
    return seen, lo, hi, whole
