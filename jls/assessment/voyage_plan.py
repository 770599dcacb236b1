"""The voyage plan of a route given by hourly records: the departure rule
(:mod:`jls.assessment.departure_rule`) sailed through the records for every option,
from the unit statistics of ``operability.nc`` by the route simulation's hourly
interpolation in Tz (:mod:`jls.assessment.route_simulation`).

Per option the hour's *utilisation* is the largest over the criteria of the hour's 3-h
MPM (at the worst of the leg's headings) over its limit. The *forecast utilisation* is
that over alpha: with an alpha table (DNV-ST-N001, configured with its source) alpha is
read at the planned period of the stretch the leg belongs to and at the hour's limiting
Hs, Hs / utilisation (the criteria are linear in Hs), so that "utilisation <= alpha" is
"Hs <= alpha OP_LIM" of the master's table; without a table alpha is 1.

Options are processed a few at a time (their hourly values are never held at once).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.departure_rule import (
    QUANTILES,
    WAIT_STEPS_H,
    simulate_departures,
    stretches,
    summarise,
)
from jls.assessment.hourly import at_hours
from jls.assessment.operation import AlphaTable
from jls.assessment.route_hours import departure_range, leg_hours
from jls.assessment.route_simulation import _Hours

#: per-option shares and quantiles of :func:`jls.assessment.departure_rule.summarise` ->
#: the dataset's variables
NAMES = {"exceedance_probability": "plan_exceedance_probability",
         "departure_fraction": "plan_departure_fraction",
         "not_sailed_fraction": "plan_not_sailed_fraction",
         "wait_h": "plan_wait_h", "transit_h": "plan_transit_h",
         "reference_exceedance_probability": "reference_exceedance_probability",
         "sailed": "plan_sailed", "judged": "plan_judged"}


def hourly_level(h: _Hours, r: slice) -> np.ndarray:
    """The level (Hs MPM, rows, leg, time) of the option rows ``r`` alone: ``h.rows(r)[0]``
    (the worst heading's, scaled by the sway ratio, an hour's own sea taken where it has
    one) without the sigma and response period the rule does not use."""
    n = len(range(*r.indices(h.arrays["mpm"].shape[1])))
    out = np.empty((n, *h.hs.shape))
    mpm = h.arrays["mpm"]
    for k, w in enumerate(h.weights):
        best = None
        for head in h.heads[k]:
            at = at_hours(mpm[head, r], w)
            best = at if best is None else np.where(at > best, at, best)
        out[:, k] = best * h.hs[k]
    if h.scale is not None:
        out *= h.factor(r, n)
    if h.own is not None:
        u = h.own[r]
        with np.errstate(invalid="ignore", over="ignore"):
            out = np.where(~np.isnan(u), u * h.limit[r][:, None, None], out)
    return out


def _compiled(h: _Hours):
    """The arguments of :func:`jls.assessment.departure_kernels.hour_utilisation` before
    the limits: the unit MPM, its rows with a non-finite entry, each leg's headings and
    the hours' interpolation weights and Hs."""
    mpm = np.ascontiguousarray(h.arrays["mpm"], float)
    heads = np.full((len(h.heads), max(len(x) for x in h.heads)), -1, np.int64)
    for k, x in enumerate(h.heads):
        heads[k, :len(x)] = x
    lower, upper, w_lower, w_upper = (np.ascontiguousarray(np.stack([w[n] for w in h.weights]))
                                      for n in range(4))
    return (mpm, ~np.isfinite(mpm).all(-1), heads, lower.astype(np.int64), upper.astype(np.int64),
            w_lower.astype(float), w_upper.astype(float), np.ascontiguousarray(h.hs, float))


def utilisation(level, limit, strict):
    """The hour's utilisation (groups, legs, time) from ``level`` (groups, criterion, legs,
    time): the largest over the criteria of level over limit; a strict criterion at its
    limit counts as beyond it; an unknown (NaN) level makes the hour unknown."""
    with np.errstate(invalid="ignore", divide="ignore"):
        u = level / np.asarray(limit, float)[None, :, None, None]
    s = np.asarray(strict, bool)
    if s.any():
        u[:, s] = np.where(u[:, s] == 1.0, np.nextafter(1.0, 2.0), u[:, s])
    return np.max(u, axis=1)


def forecast_utilisation(util, hs, leg_period_h, alpha: AlphaTable | None):
    """Utilisation over alpha (groups, legs, time): alpha at the planned period of each
    leg's stretch and the hour's limiting Hs (Hs / utilisation); 1 without a table."""
    if alpha is None:
        return util
    out = np.empty_like(util)
    for k, period in enumerate(alpha_periods(leg_period_h, alpha)):
        with np.errstate(invalid="ignore", divide="ignore"):
            hs_lim = np.where(util[:, k] > 0, hs[k] / util[:, k], np.inf)
        a = alpha.factor(float(period), np.where(np.isnan(hs_lim), 0.0, hs_lim))
        out[:, k] = np.where(np.isnan(util[:, k]), np.nan, util[:, k] / a)
    return out


def alpha_periods(leg_period_h, alpha: AlphaTable):
    """The planned periods alpha is read at: each leg's stretch's, held at the table's
    ends (a stretch longer than the table's longest period is no weather-restricted
    operation; the stage states it)."""
    p = np.asarray(alpha.period_h, float)
    return np.clip(np.asarray(leg_period_h, float), p[0], p[-1])


def forecast_table(stats: xr.Dataset, heading_probability: xr.DataArray, legs, limit, strict, tz,
                   leg_period_h, alpha: AlphaTable | None) -> xr.Dataset:
    """The master's table per leg: OP_LIM, the limiting Hs at each Tz of ``tz`` (the Hs at
    which the hour's utilisation reaches 1, from the same interpolation and worst heading
    as the rule), alpha (1 without a table) and OP_WF = alpha OP_LIM, over (..., leg, tz)."""
    tz = np.asarray(tz, float)
    hours = xr.Dataset({"hs": (("leg", "time"), np.ones((len(legs), tz.size))),
                        "tz": (("leg", "time"), np.broadcast_to(tz, (len(legs), tz.size)).copy())},
                       coords={"leg": list(legs)})
    st = stats.transpose(..., "criterion", "heading", "tz")
    h = _Hours(st, hours, heading_probability)
    n_crit = h.shape[-1]
    lead, lead_shape = h.opt[:-1], h.shape[:-1]
    level, _, _ = h.rows(slice(None))
    crits = [str(c) for c in st["criterion"].values]
    lim = np.asarray(limit.sel(criterion=crits).values, float)
    strict = np.asarray(strict.sel(criterion=crits).values if isinstance(strict, xr.DataArray) else
                        np.broadcast_to(np.asarray(bool(strict)), (n_crit,)), bool)
    u = utilisation(level.reshape(-1, n_crit, *level.shape[1:]), lim, strict)    # (options, leg, tz)
    with np.errstate(divide="ignore"):
        oplim = np.where(u > 0, 1.0 / u, np.inf)
    a = np.ones_like(oplim)
    if alpha is not None:
        for k, period in enumerate(alpha_periods(leg_period_h, alpha)):
            a[:, k] = alpha.factor(float(period), np.where(np.isfinite(oplim[:, k]), oplim[:, k], 1e3))
    dims = (*lead, "leg", "tz")
    shape = (*lead_shape, len(legs), tz.size)
    return xr.Dataset({"master_hs_oplim": (dims, oplim.reshape(shape)), "master_alpha": (dims, a.reshape(shape)),
                       "master_hs_opwf": (dims, (a * oplim).reshape(shape))},
                      coords={**{d: h.coords[d] for d in lead if d in h.coords}, "leg": list(legs), "tz": tz})


def voyage_plan(stats: xr.Dataset, hours: xr.Dataset, heading_probability: xr.DataArray,
                duration_h, limit: xr.DataArray, *, strict, hold_point, contingency_h,
                horizon_h: float, max_wait_h: float, months, alpha: AlphaTable | None = None,
                quantiles=QUANTILES, sources=None, sway_scale=None, own=None, groups=8) -> xr.Dataset:
    """The plan of every option (module docstring).

    stats: :func:`jls.assessment.criterion_levels.criterion_statistics` of
    ``operability.nc``; hours: :func:`jls.assessment.route_hours.common_hours` (leg,
    time); heading_probability (leg, heading); duration_h, hold_point, contingency_h: per
    leg in sailing order (contingency None: none); limit, strict: (criterion); months:
    the departure months (1-12); alpha: the alpha table or None. Departures are the hours
    of those months from which every leg's record span holds the voyage
    (:func:`jls.assessment.route_hours.departure_range`). ``own``: the hours' utilisation
    on their own seas (:func:`jls.assessment.route_simulation.route_simulation`)."""
    legs = [str(x) for x in hours["leg"].values]
    st = stats.transpose(..., "criterion", "heading", "tz")
    h = _Hours(st, hours, heading_probability, sway_scale, own, limit)
    if h.opt[-1] != "criterion":
        raise ValueError("the statistics need a criterion dimension")
    n_crit = h.shape[-1]
    lead, lead_shape = h.opt[:-1], h.shape[:-1]
    n_opt = int(np.prod(lead_shape))
    crits = [str(c) for c in st["criterion"].values]
    lim = np.asarray(limit.sel(criterion=crits).values, float)
    strict = np.asarray(xr.DataArray(strict).sel(criterion=crits).values if isinstance(strict, xr.DataArray)
                        else np.broadcast_to(np.asarray(strict if strict is not None else False), (n_crit,)), bool)
    dur = np.asarray(duration_h, float)
    stl = stretches(hold_point, dur, contingency_h)
    leg_period = np.empty(len(legs))
    for s in stl:
        leg_period[list(s.legs)] = float(dur[list(s.legs)].sum())
    known = (hours["hs"].notnull() & hours["tz"].notnull()).transpose("leg", "time").values
    times = pd.DatetimeIndex(hours["time"].values)
    first, n = departure_range(known, leg_hours(dur), legs, sources, times)
    dep = np.arange(first, first + n)
    month = times.month.to_numpy()
    dep = dep[np.isin(month[dep], np.asarray(months, int))]
    hs = hours["hs"].transpose("leg", "time").values
    parts = []
    from jls.assessment.departure_kernels import hour_utilisation  # numba: imported where used
    compiled = _compiled(h) if h.scale is None and h.own is None else None
    for g0 in range(0, n_opt, groups):
        g1 = min(g0 + groups, n_opt)
        if compiled is not None:
            util = hour_utilisation(*compiled, lim, strict, g0 * n_crit, g1 - g0)
        else:
            level = hourly_level(h, slice(g0 * n_crit, g1 * n_crit))
            util = utilisation(level.reshape(g1 - g0, n_crit, *level.shape[1:]), lim, strict)
        fc = forecast_utilisation(util, hs, leg_period, alpha)
        d = simulate_departures(util, fc, stl, dep, horizon_h=int(np.floor(horizon_h)),
                                max_wait_h=int(np.floor(max_wait_h)))
        parts.append(summarise(d, month[dep], quantiles))
    s = {k: np.concatenate([p[k] for p in parts], axis=0) for k in parts[0]}
    return _dataset(s, lead, lead_shape, h.coords, stl, legs, quantiles, month[dep])


def _dataset(s, lead, shape, coords, stl, legs, quantiles, dep_month) -> xr.Dataset:
    q = list(quantiles)
    holds = [legs[st.legs[0]] for st in stl]
    out = {}
    for key, name in NAMES.items():
        a = s[key]
        extra = ("quantile",) if a.ndim == 2 else ()
        out[name] = ((*lead, *extra), a.reshape(*shape, *a.shape[1:]))
        am = s[key + "_month"]
        extra = ("month", "quantile") if am.ndim == 3 else ("month",)
        out[name + "_month"] = ((*lead, *extra), am.reshape(*shape, *am.shape[1:]))
    w = s["wait_hold_h"]
    out["plan_wait_hold_h"] = ((*lead, "hold_point", "quantile"), w.reshape(*shape, *w.shape[1:]))
    c = s["wait_cdf"]
    out["plan_wait_cdf"] = ((*lead, "wait_step"), c.reshape(*shape, c.shape[-1]))
    out["departures_month"] = ("month", np.bincount(dep_month, minlength=13)[1:].astype(np.int64))
    ds = xr.Dataset(out, coords={**{d: coords[d] for d in lead if d in coords}, "quantile": q,
                                 "month": np.arange(1, 13), "hold_point": holds,
                                 "wait_step": np.asarray(WAIT_STEPS_H, float)})
    return ds
