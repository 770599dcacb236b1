"""Route simulation through hourly hindcasts: sail the route from every recorded hour.

For legs given by hourly records (one record per leg, or the same record for every leg),
the voyage is sailed from every departure hour with the legs' durations in sequence (leg
k occupies the ``ceil(D_k)`` hours after the legs before it), and each hour is judged by
its own sea state from the unit-Hs statistics (``operability.nc``, interpolated linearly
in Tz):

* **The hour's MPM** (``level``): ``Hs MPM(Hs = 1 m; Tz)``, the most probable maximum
  over the assessment exposure (3 h) of the hour's sea state, the quantity the criteria
  limit. A departure's *voyage maximum* is the largest over the voyage's hours, and the
  voyage *passes* when it stays inside every criterion: the persistence test of the
  weather windows applied to the whole voyage.
* **Short-term Rayleigh within the hour** (``sigma``, ``tz_response``): the hour adds
  3600 / Tz_r exp(-L^2 / (2 sigma^2)) expected up-crossings of the limit L, and the
  departure's *exceedance probability* is 1 - exp(-sum over the voyage's hours). Hours are
  treated as independent given their sea states; their persistence is in the record.

Both are computed for all departures in O(n) per option: a sliding maximum (and sum)
over each leg's window (:mod:`jls.assessment.sliding_windows`: O(n) whatever the
window length). :func:`route_simulation`
does it all from ``operability.nc``'s statistics, a few options at a time;
:func:`simulate_route` from given hourly values. The hourly records on one grid and the
departures they allow are :mod:`jls.assessment.route_hours`'.

**Gaps.** A departure whose voyage needs an hour the leg's record lacks is not judged:
it is left out of every share and counted (``departures_month`` minus
``judged_month``). Departures are the hours from which the voyage lies within every
leg's record span; a record too short for that is an InputError naming the leg.
"""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.hourly import (
    RouteOwnRows,
    at_hours,
    own_hour_statistics,
    route_own_utilisation,
    tz_weights,
)
from jls.assessment.route_hours import STEP, departure_range, leg_hours
from jls.assessment.sliding_windows import sliding_max, sliding_sum
from jls.errors import InputError
from jls.names import SWAY_M
from jls.threads import thread_map

PASS_FLAGS = "not_judged fails passes"
#: option rows averaged over the departures at a time (no copy of every row's departures)
MEAN_ROWS = 64


class _Hours:
    """The hours of a route's records against unit statistics: per leg the interpolation
    weights and Hs, the headings the leg meets, and the statistics as (heading, option,
    tz) arrays, so that the hourly values of any rows of options can be formed."""

    NAMES = ("mpm", "sigma", "tz_response")

    def __init__(self, stats: xr.Dataset, hours: xr.Dataset, heading_probability: xr.DataArray,
                 sway_scale: xr.DataArray | None = None, own: xr.DataArray | None = None, limit=None,
                 exposure=(None, "response")):
        st = stats.sortby("tz")
        grid = st["tz"].values.astype(float)
        self.hs = hours["hs"].transpose("leg", "time").values
        tz = hours["tz"].transpose("leg", "time").values
        self.opt = [d for d in st["mpm"].dims if d not in ("heading", "tz")]
        self.shape = [st.sizes[d] for d in self.opt]
        self.coords = {d: st[d] for d in self.opt if d in st.coords}
        hp = heading_probability.transpose("leg", "heading").sel(leg=hours["leg"])
        for leg, p in zip(hp["leg"].values, hp.values):
            missing = sorted(set(hp["heading"].values[p > 0].tolist()) - set(st["heading"].values.tolist()))
            if missing or not (p > 0).any():
                raise InputError("no statistics at the leg's heading(s)", field=f"legs[{leg}].headings_deg",
                                 value=missing)
        hp = hp.reindex(heading=st["heading"], fill_value=0.0).values
        self.heads = [np.flatnonzero(p > 0) for p in hp]
        n = int(np.prod(self.shape))
        self.arrays = {v: st[v].transpose("heading", *self.opt, "tz").values.reshape(-1, n, grid.size)
                       for v in self.NAMES}
        self.weights = [tz_weights(t, grid) for t in tz]
        outside = [w[-1] for w in self.weights]
        self.outside = xr.DataArray(list(outside), dims="leg", coords={"leg": hours["leg"]})
        self.scale = None
        if sway_scale is not None and SWAY_M in st["criterion"].values:
            rest = [d for d in self.opt if d != "criterion"]
            self.axis = self.opt.index("criterion")
            self.sway = int(np.flatnonzero(st["criterion"].values == SWAY_M)[0])
            self.scale = sway_scale.sel({d: st[d] for d in rest}).sel(leg=hours["leg"], time=hours["time"]) \
                .transpose(*rest, "leg", "time").values
        self.own = self.own_tz = self.own_rows = None
        self.exposure = exposure
        if isinstance(own, RouteOwnRows):        # read a block of options at a time
            if own.bind(self.opt, {d: st[d].values for d in self.opt}):
                self.own_rows = own
                if "tz_response_own" in own.names and exposure[0] is None:
                    raise ValueError("own tz_response needs exposure_h")
                self.limit = _flat_limit(limit, self.opt, self.shape, self.coords)
                own = None
            else:
                own = route_own_utilisation(own.measured, hours)
        if own is not None:                    # the hours' utilisation on their own seas
            own = own if isinstance(own, xr.Dataset) else own.to_dataset(name="utilisation")
            own = _aligned(own, st, self.opt, hours)
            flat = {v: own[v].transpose(*self.opt, "leg", "time").values.reshape(n, *self.hs.shape)
                    for v in ("utilisation", "tz_response") if v in own}
            self.own = flat.pop("utilisation")
            self.own_tz = flat.get("tz_response")  # the own sea's period where stored
            if self.own_tz is not None and exposure[0] is None:
                raise ValueError("own tz_response needs exposure_h")
            self.limit = _flat_limit(limit, self.opt, self.shape, self.coords)

    def release(self):
        """Drop the hours' own-sea and scale arrays (after the last :meth:`rows`)."""
        self.own = self.own_tz = self.own_rows = self.scale = None

    def factor(self, r, n):
        """(rows, leg, time) multiplier of the option rows ``r``: the hour's sway ratio on
        the relative-sway rows, 1 elsewhere."""
        idx = np.unravel_index(np.arange(int(np.prod(self.shape)))[r], self.shape)
        out = np.ones((n, *self.hs.shape))
        sway = idx[self.axis] == self.sway
        rest = tuple(ix[sway] for a, ix in enumerate(idx) if a != self.axis)
        out[sway] = self.scale[rest]
        return out

    def rows(self, r):
        """level = Hs MPM, sigma = Hs sigma and tz_response (rows, leg, time) for the
        option rows ``r`` (a slice), at the worst heading of each leg in each hour."""
        n = len(range(*r.indices(self.arrays["mpm"].shape[1])))
        out = {v: np.empty((n, *self.hs.shape)) for v in self.NAMES}
        for k, W in enumerate(self.weights):
            best = None
            for h in self.heads[k]:
                at = {v: at_hours(a[h, r], W) for v, a in self.arrays.items()}
                if best is not None:
                    worse = at["mpm"] > best["mpm"]
                    at = {v: np.where(worse, at[v], best[v]) for v in self.NAMES}
                best = at
            out["mpm"][:, k] = best["mpm"] * self.hs[k]
            out["sigma"][:, k] = best["sigma"] * self.hs[k]
            out["tz_response"][:, k] = best["tz_response"]
        if self.scale is not None:
            f = self.factor(r, n)
            out["mpm"] *= f
            out["sigma"] *= f
        if self.own is not None or self.own_rows is not None:   # level = utilisation x limit; period its own
            u, own_tz = self.own_rows.rows(r) if self.own_rows is not None else \
                (self.own[r], None if self.own_tz is None else self.own_tz[r])
            with np.errstate(invalid="ignore", over="ignore"):
                level = u * self.limit[r][:, None, None]
            out["sigma"], out["tz_response"] = own_hour_statistics(
                level, out["sigma"], out["mpm"], out["tz_response"],
                own_tz, *self.exposure)
            out["mpm"] = np.where(np.isnan(u), out["mpm"], level)
        return out["mpm"], out["sigma"], out["tz_response"]


def _aligned(own: xr.Dataset, st: xr.Dataset, opt, hours: xr.Dataset) -> xr.Dataset:
    """``own`` on the statistics' criteria (NaN where it has none) and options and on the
    route's legs and hours (NaN where it has none); a dimension already on those labels is
    left as it is (ten years of hours x options are not copied to be put in order)."""
    same = lambda d, v: np.array_equal(own[d].values, np.asarray(v))  # noqa: E731
    if not same("criterion", st["criterion"].values):
        own = own.reindex(criterion=st["criterion"].values)
    other = {d: st[d] for d in opt if d != "criterion" and not same(d, st[d].values)}
    if other:
        own = own.sel(other)
    at = {d: hours[d].values for d in ("leg", "time") if not same(d, hours[d].values)}
    return own.reindex(at) if at else own


def hourly_statistics(stats: xr.Dataset, hours: xr.Dataset, heading_probability: xr.DataArray,
                      sway_scale: xr.DataArray | None = None):
    """Each hour's statistics per option and criterion at the worst of the leg's headings.

    stats: :func:`jls.assessment.criterion_levels.criterion_statistics` (``sigma``,
    ``tz_response``, ``mpm`` per m of Hs over heading and tz); hours:
    :func:`jls.assessment.route_hours.common_hours` (leg, time); heading_probability: (leg,
    heading). Tz is interpolated linearly and held at the
    grid's ends. Of the headings with non-zero probability on the leg, the one with the
    highest MPM in the hour is taken (the heading is not known hour by hour: the worst is
    the conservative choice). ``sway_scale`` (candidate, tugger, leg, time): the hour's
    relative-sway ratio of a leg given by measured spectra (1 on the other legs,
    :func:`jls.assessment.hourly.sway_ratio`), which scales the relative sway's MPM and
    sigma. Returns (Dataset (..., leg, time) of ``level`` = Hs MPM, ``sigma`` = Hs sigma,
    ``tz_response``; hours outside the Tz grid per leg).
    """
    h = _Hours(stats, hours, heading_probability, sway_scale)
    dims = (*h.opt, "leg", "time")
    coords = {**h.coords, "leg": hours["leg"], "time": hours["time"]}
    arrays = h.rows(slice(None))
    ds = xr.Dataset({v: (dims, a.reshape(*h.shape, *h.hs.shape))
                     for v, a in zip(("level", "sigma", "tz_response"), arrays)}, coords=coords)
    return ds, h.outside


class _Voyage:
    """A route's legs against a common hourly grid: hours and offsets per leg, the
    departures (first index, count) and which of them are judged."""

    def __init__(self, known, duration_h, legs, times, sources=None):
        self.hours = leg_hours(duration_h)
        self.off = np.concatenate([[0], np.cumsum(self.hours)[:-1]])
        self.known = np.asarray(known, bool)
        self.d0, self.n = departure_range(self.known, self.hours, legs, sources, times)
        self.cuts = [slice(self.d0 + o, self.d0 + o + self.n + h - 1) for o, h in zip(self.off, self.hours)]
        self.judged = np.ones(self.n, bool)
        for k, h in enumerate(self.hours):
            self.judged &= sliding_sum(self.known[k, self.cuts[k]].astype(np.int64), h) == h
        self.departure = pd.DatetimeIndex(times)[self.d0:self.d0 + self.n]

    def sail(self, level, limit=None, sigma=None, tz_response=None, out=None):
        """Voyage maximum (rows, departures) of the hourly ``level`` (rows, legs, time) and,
        with sigma and tz_response, the expected up-crossings of ``limit`` (rows,);
        ``out``: (vmax, lam) arrays to write them into (the rows of the whole result)."""
        if out is None:
            vmax = np.full((level.shape[0], self.n), -np.inf)
            lam = None if sigma is None else np.zeros((level.shape[0], self.n))
        else:
            vmax, lam = out
            vmax.fill(-np.inf)
            if sigma is not None:
                lam.fill(0.0)
        for k, (c, h) in enumerate(zip(self.cuts, self.hours)):
            known = self.known[k, c]
            np.maximum(vmax, sliding_max(np.where(known, level[:, k, c], -np.inf), h), out=vmax)
            if sigma is not None:
                s, t = sigma[:, k, c], tz_response[:, k, c]
                with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                    rate = 3600.0 / t * np.exp(-0.5 * np.square(limit[:, None] / s))
                lam += sliding_sum(np.where(known & (s != 0), rate, 0.0), h)
        vmax[:, ~self.judged] = np.nan
        return vmax, lam


def _flat_limit(limit, opt_dims, shape, coords):
    like = xr.DataArray(np.empty(shape), dims=opt_dims, coords=coords)
    return xr.DataArray(limit).broadcast_like(like).transpose(*opt_dims).values.reshape(-1)


def route_simulation(stats: xr.Dataset, hours: xr.Dataset, heading_probability: xr.DataArray,
                     duration_h: xr.DataArray, limit, *, strict=None, non_exceedance=(0.5, 0.9),
                     min_judged=1, sources=None, rows=16, sway_scale=None, own=None,
                     threads=None, exposure_h=None, cycles="response") -> xr.Dataset:
    """Sail the route through its hindcast from every departure hour (module docstring).

    stats: :func:`jls.assessment.criterion_levels.criterion_statistics` of
    ``operability.nc`` (unit-Hs ``mpm``, ``sigma``, ``tz_response`` per candidate, tugger,
    criterion, heading, tz); hours: :func:`jls.assessment.route_hours.common_hours` (leg,
    time); heading_probability: (leg, heading) (each hour is judged at the worst heading
    the leg meets, :func:`hourly_statistics`); duration_h: (leg) [h], sailed in the order
    of ``hours.leg``; limit: (criterion) [level units]; strict: (criterion) bool; sources:
    leg -> file name, for errors.
    Options are processed ``rows`` at a time (the hourly values of all options are never
    held at once). ``sway_scale``: as :func:`hourly_statistics`; ``own`` (candidate,
    tugger, criterion, leg, time): the hour's utilisation on its own sea where a leg has
    one (:func:`jls.assessment.hourly.route_own_utilisation`; NaN elsewhere), which sets
    the hour's level (utilisation x limit), with its own sea's period where given and the
    sigma whose MPM over ``exposure_h`` [h] at that period is the level (``cycles`` as
    ``assessment.mpm_cycles``; :func:`jls.assessment.hourly.own_hour_statistics`).
    ``threads``: the blocks of option rows on that many threads (each block's numbers its
    own: the same whatever the threads). Returns
    :func:`simulate_route`'s variables and ``hours_outside_tz`` (leg).
    """
    h = _Hours(stats, hours, heading_probability, sway_scale, own, limit, (exposure_h, cycles))
    legs = [str(x) for x in hours["leg"].values]
    voyage = _Voyage((hours["hs"].notnull() & hours["tz"].notnull()).transpose("leg", "time").values,
                     duration_h.sel(leg=legs).values, legs, hours["time"].values, sources)
    lim = _flat_limit(limit, h.opt, h.shape, h.coords)
    vmax = np.empty((lim.size, voyage.n))
    lam = np.empty((lim.size, voyage.n))
    def block(r0):
        r = slice(r0, r0 + rows)
        level, sigma, tzr = h.rows(r)
        voyage.sail(level, lim[r], sigma, tzr, out=(vmax[r], lam[r]))

    thread_map(block, range(0, lim.size, rows), threads)
    del own                                    # the hours' arrays are sailed: not held through the summary
    h.release()
    ds = _summary(vmax, lam, voyage, h.opt, h.shape, h.coords, limit, strict, non_exceedance, min_judged)
    ds["hours_outside_tz"] = h.outside
    return ds


def simulate_route(level: xr.DataArray, known: xr.DataArray, duration_h: xr.DataArray, limit, *,
                   strict=None, sigma: xr.DataArray | None = None,
                   tz_response: xr.DataArray | None = None, non_exceedance=(0.5, 0.9),
                   min_judged=1, sources=None) -> xr.Dataset:
    """Sail the route from every departure hour given the hourly values (module docstring).

    level: (..., criterion, leg, time) the hour's statistic per option [level units] (the
    sea state's MPM, :func:`hourly_statistics`), time a regular hourly datetime64
    coordinate; known: (leg, time) the leg's record has the hour; duration_h: (leg) [h],
    sailed in the order of ``leg``; limit: broadcastable over the option dims (e.g.
    (criterion)) [level units]; strict: (criterion) bool, the level must stay strictly
    below the limit; sigma, tz_response: (..., criterion, leg, time) [level units, s] for
    the departures' exceedance probabilities (short-term Rayleigh within each hour);
    sources: leg -> file name, for errors.

    Returns over the option dims ``(...)``: ``departure_max`` (..., criterion,
    departure; NaN: not judged), ``departure_passes`` (..., departure; 1 passes every
    criterion, 0 fails, -1 not judged), ``pass_probability_month`` (..., month; NaN: no
    judged departure), ``pass_probability`` (...), ``exceedance_fraction`` (...,
    criterion; share of judged departures beyond the limit), ``departure_max_quantile``
    (..., criterion, month, non_exceedance: the level that share of the month's judged
    departures stays below), ``best_month``, ``worst_month`` (...; 1-12 by pass
    probability among the months of at least ``min_judged`` judged departures, earliest
    of ties; 0: no such month), ``departures_month``,
    ``judged_month`` (month); with sigma: ``departure_exceedance`` (..., criterion,
    departure) and its mean over the judged departures ``mean_departure_exceedance``.
    A judged departure whose statistics are unknown (NaN) fails. Attributes
    ``voyage_hours``, ``leg_hours``, ``departures``, ``departures_judged``.
    """
    legs = [str(x) for x in level["leg"].values]
    times = pd.DatetimeIndex(level["time"].values)
    if len(times) > 1 and not (times[1:] - times[:-1] == STEP).all():
        raise ValueError("level needs a regular hourly time coordinate")
    voyage = _Voyage(known.transpose("leg", "time").sel(leg=legs).values, duration_h.sel(leg=legs).values,
                     legs, times, sources)
    opt = [d for d in level.dims if d not in ("leg", "time")]
    shape = [level.sizes[d] for d in opt]
    coords = {d: level[d] for d in opt if d in level.coords}
    flat = lambda a: a.transpose(*opt, "leg", "time").values.reshape(-1, len(legs), len(times))  # noqa: E731
    lim = _flat_limit(limit, opt, shape, coords)
    if sigma is None:
        vmax, lam = voyage.sail(flat(level))
    else:
        vmax, lam = voyage.sail(flat(level), lim, flat(sigma), flat(tz_response.broadcast_like(sigma)))
    return _summary(vmax, lam, voyage, opt, shape, coords, limit, strict, non_exceedance, min_judged)


def _summary(vmax, lam, voyage, opt, shape, coords, limit, strict, non_exceedance, min_judged):
    """The dataset of :func:`simulate_route` from the voyage maxima and up-crossings."""
    n_dep, judged = voyage.n, voyage.judged
    vmax = xr.DataArray(vmax.reshape(*shape, n_dep), dims=(*opt, "departure"),
                        coords={**coords, "departure": voyage.departure})
    lim = xr.DataArray(limit)
    strict = xr.zeros_like(lim, bool) if strict is None else xr.DataArray(strict)
    inside = xr.where(strict, vmax < lim, vmax <= lim)
    passes = inside.all("criterion")
    rest = [d for d in passes.dims if d != "departure"]
    month = voyage.departure.month.to_numpy()
    onehot = ((month[:, None] == np.arange(1, 13)) & judged[:, None]).astype(float)   # (n_dep, 12)
    n_month = onehot.sum(0)
    n_judged = int(judged.sum()) or np.nan
    pb = passes.transpose(*rest, "departure").values.reshape(-1, n_dep)
    # counts of 0/1 are exact in float32 below 2^24 departures (half the memory of float64)
    counts = (pb.astype(np.float32) @ onehot.astype(np.float32)).astype(float)
    with np.errstate(invalid="ignore", divide="ignore"):
        p_month = np.where(n_month > 0, counts / np.where(n_month > 0, n_month, 1.0), np.nan)
    ranked = n_month >= max(min_judged, 1)                # months ranked for best and worst
    best = np.where(ranked.any(), np.argmax(np.where(ranked, np.nan_to_num(p_month), -1.0), -1) + 1, 0)
    worst = np.where(ranked.any(), np.argmin(np.where(ranked, np.nan_to_num(p_month), 2.0), -1) + 1, 0)
    rshape = [passes.sizes[d] for d in rest]
    flat = vmax.values.reshape(-1, n_dep)
    q = np.full((flat.shape[0], 12, len(non_exceedance)), np.nan)
    for m in np.flatnonzero(n_month > 0):
        q[:, m, :] = np.quantile(flat[:, onehot[:, m] > 0], non_exceedance, axis=-1).T
    jd = xr.DataArray(judged, dims="departure")
    ds = xr.Dataset({
        "departure_max": vmax,
        "departure_passes": xr.where(jd, passes.astype(np.int8), np.int8(-1)).astype(np.int8)
                              .transpose(*rest, "departure"),
        "pass_probability_month": ((*rest, "month"), p_month.reshape(*rshape, 12)),
        "pass_probability": (tuple(rest), (np.count_nonzero(pb[:, judged], axis=-1) / n_judged).reshape(rshape)),
        "exceedance_fraction": ((~inside) & jd).sum("departure") / n_judged,
        "departure_max_quantile": ((*vmax.dims[:-1], "month", "non_exceedance"),
                                   q.reshape(*vmax.shape[:-1], 12, -1)),
        "best_month": (tuple(rest), best.reshape(rshape)),
        "worst_month": (tuple(rest), worst.reshape(rshape)),
        "departures_month": ("month", np.bincount(month, minlength=13)[1:]),
        "judged_month": ("month", n_month.astype(np.int64)),
    }, coords={"month": np.arange(1, 13), "non_exceedance": list(non_exceedance)})
    ds["departure_passes"].attrs.update(flag_values=np.array([-1, 0, 1], np.int8), flag_meanings=PASS_FLAGS)
    if lam is not None:
        p = np.negative(np.expm1(np.negative(lam, out=lam), out=lam), out=lam)     # in place
        p[:, ~judged] = np.nan
        ds["departure_exceedance"] = vmax.copy(data=p.reshape(vmax.shape))
        with warnings.catch_warnings():        # a row of no judged departure: NaN
            warnings.simplefilter("ignore", RuntimeWarning)
            mean = np.concatenate([np.nanmean(p[b:b + MEAN_ROWS], axis=-1) for b in range(0, p.shape[0], MEAN_ROWS)])
        ds["mean_departure_exceedance"] = (vmax.dims[:-1], mean.reshape(vmax.shape[:-1]))
    ds.attrs.update(voyage_hours=int(voyage.hours.sum()), leg_hours=" ".join(map(str, voyage.hours)),
                    departures=int(n_dep), departures_judged=int(judged.sum()))
    return ds
