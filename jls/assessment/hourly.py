"""The hours of a record against statistics per metre of Hs: interpolation in Tz and
each hour's utilisation of every criterion.

A recorded hour (Hs, Tz) is assessed as a scatter cell is (:mod:`jls.assessment.workability`),
on statistics given per metre of Hs on a Tz grid:

* **Interpolation in Tz**, stated once: linear between the grid's two neighbours of the
  hour's Tz, held at the grid's ends (the count of hours beyond them is returned, and
  what happens to them is the caller's rule, ``tz_outside``). A statistic that is not
  finite stays what it is wherever an hour uses it (weight above 0): NaN is unknown, +inf
  a limit broken at rest; a neighbour of weight 0 is not used. An hour without a record
  (NaN Tz) gets 0, and its NaN Hs makes every product with it NaN.
* **Utilisation**: ``Hs u(Tz)`` per criterion, with ``u`` the unit utilisation of
  :func:`jls.assessment.workability.unit_utilisation`; interpolating the utilisation,
  which is the largest over the wires for a tension criterion, is conservative against
  interpolating each wire. No steepness cap applies: these are recorded sea states.
* **Measured spectra**: an hour of a leg given by measured spectra carries the ratio of
  its relative-sway sigma over the measured spectrum to that over the JONSWAP on its own
  (Hs, Tz) (``measured_response.nc``, :mod:`jls.stages.measured_response`). The relative
  sway's utilisation is scaled by it (``sway_scale``): the MPM is sigma sqrt(2 ln N), and
  the number N of response cycles in the exposure is held at the JONSWAP's (the sway is
  narrow-banded about the pendulum period, which the spectrum's shape hardly moves). The
  other criteria keep the JONSWAP's statistics.
* **Own seas**: where ``measured_response.nc`` carries ``utilisation`` (every criterion of
  the hour on its own directional sea, :mod:`jls.stages.hourly_seas`), it replaces the
  JONSWAP's utilisation of those hours (``own``; :func:`leg_own_utilisation`,
  :func:`route_own_utilisation` for the route and departure simulations).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import SWAY_M

TZ_OUTSIDE = ("error", "nearest", "unworkable")

#: What the stages that take hourly verdicts from the sway ratio alone (the weather windows,
#: the route simulation and voyage extremes, the departure simulation) do with the hours
#: of a leg given by its own seas (dataset attribute ``own_sea_not_used``, the report's
#: chapter "Wave spectra"); the workability judges those hours on their own sea.
OWN_SEA_NOT_USED = (
    "does not use the hour's own directional sea for every criterion: each hour of such a leg "
    "is judged on the JONSWAP of its (Hs, Tz = Tm02), its relative sway scaled by the hour's "
    "ratio of the sway over its own sea to that over the JONSWAP (measured_response.nc), the "
    "other criteria (heave, roll, yaw, wire tension, tip clearance) on the JONSWAP")

__all__ = ["RouteOwnRows", "route_own_rows", "own_sigma", "own_hour_statistics", "OWN_SEA_NOT_USED", "route_own_utilisation", "route_own_heading_utilisation", "leg_own_utilisation", "TZ_OUTSIDE", "tz_weights", "at_hours", "hourly_utilisation", "sway_ratio", "route_sway_scale"]


def own_sigma(level, own_tz, exposure_h, cycles="response"):
    """The own sea's sigma of a criterion level (utilisation x limit for a relative motion,
    the utilisation for the others) at its own up-crossing period ``own_tz`` [s]
    (``measured_response.nc`` ``tz_response_own``): the sigma whose MPM over
    ``exposure_h`` [h] is the level (:func:`jls.response.statistics.sigma_from_mpm`, the
    inverse of ``from_moments``; ``cycles`` as ``assessment.mpm_cycles``). NaN where the
    level or the period is unknown (and the level not 0). Any equal shapes."""
    from jls.response.statistics import FIXED_CYCLES_STUDY, sigma_from_mpm
    n = "response" if cycles == "response" else FIXED_CYCLES_STUDY
    return sigma_from_mpm(level, own_tz, float(exposure_h) * 3600.0, n)


def own_hour_statistics(level, sigma, mpm, tz_response, own_tz=None, exposure_h=None, cycles="response"):
    """(sigma, tz_response) of hours judged on their own seas, for the up-crossings of the
    route simulation and of the voyage extremes (one rule for both): an hour with an
    own-sea ``level`` (not NaN) takes its own sea's response period as
    ``measured_response.nc`` stores it (``tz_response_own``) and the sigma whose MPM over
    ``exposure_h`` at that period is the level (:func:`own_sigma`; the JONSWAP's period
    and moved sigma where its own is unknown); without it (an older dataset), the
    JONSWAP's sigma moved by level / MPM at the JONSWAP's period, and NaN (unknown) where
    the JONSWAP has no response to move and the level is not 0. An hour without an
    own-sea level keeps the JONSWAP's ``sigma`` and ``tz_response``. Any equal shapes."""
    have = ~np.isnan(level)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        moved = np.where(mpm > 0, sigma * (level / np.where(mpm > 0, mpm, 1.0)),
                         np.where(level == 0, 0.0, np.nan))
    if own_tz is None:
        return np.where(have, moved, sigma), tz_response
    if exposure_h is None:
        raise ValueError("own_tz needs exposure_h")
    own_s = own_sigma(level, own_tz, exposure_h, cycles)
    mine = have & ~np.isnan(own_s)
    s = np.where(mine, own_s, np.where(have, moved, sigma))
    t = np.where(mine & np.isfinite(own_tz) & (own_tz > 0), own_tz, tz_response)
    return s, t


def tz_weights(tz, grid):
    """Interpolation of a Tz grid at the hours: (lower index, upper index, lower weight,
    upper weight), each (n_time,), and the count of hours with Tz beyond the grid.
    ``grid`` strictly increasing; hours without a record (NaN) have both weights 0."""
    tz, grid = np.asarray(tz, float), np.asarray(grid, float)
    known = np.isfinite(tz)
    t = np.clip(np.where(known, tz, grid[0]), grid[0], grid[-1])
    i = np.clip(np.searchsorted(grid, t, side="right") - 1, 0, max(grid.size - 2, 0))
    j = np.minimum(i + 1, grid.size - 1)
    f = np.where(j > i, (t - grid[i]) / np.where(j > i, grid[j] - grid[i], 1.0), 0.0)
    w_lo, w_hi = np.where(known, 1.0 - f, 0.0), np.where(known, f, 0.0)
    return i, j, w_lo, w_hi, int((known & ((tz < grid[0]) | (tz > grid[-1]))).sum())


def at_hours(a, weights):
    """The statistics ``a`` (..., n_grid) at the hours (..., n_time) with the weights of
    :func:`tz_weights`; a non-finite entry is kept wherever an hour uses it."""
    i, j, w_lo, w_hi = weights[:4]
    a = np.asarray(a, float)
    out = np.take(a, i, axis=-1)
    hi = np.take(a, j, axis=-1)
    with np.errstate(invalid="ignore"):              # 0 x inf: repaired below
        out *= w_lo
        hi *= w_hi
    out += hi
    bad = ~np.isfinite(a)
    if bad.any():                     # a 0 weight must not turn inf into NaN, nor spread NaN
        rows = np.flatnonzero(bad.reshape(-1, a.shape[-1]).any(-1))
        flat = a.reshape(-1, a.shape[-1])[rows]
        with np.errstate(invalid="ignore"):
            fix = np.where(w_lo > 0, flat[:, i] * w_lo, 0.0) + np.where(w_hi > 0, flat[:, j] * w_hi, 0.0)
        out.reshape(-1, out.shape[-1])[rows] = fix
    return out


def hourly_utilisation(hs, tz, unit_util: xr.DataArray, tz_outside="error", source=None,
                       sway_scale: xr.DataArray | None = None, own: xr.DataArray | None = None):
    """Utilisation of every criterion in each hour (module docstring).

    hs, tz: (n_time,) arrays (NaN for gaps); unit_util: (..., tz, criterion);
    sway_scale: the hour's measured-over-JONSWAP relative-sway ratio, over ``time`` and any
    of unit_util's other dims (NaN where the hour has none: an error for a recorded hour);
    own: the hours' utilisation on their own seas (:func:`leg_own_utilisation`, over
    ``time``, ``criterion`` and any of unit_util's other dims), which replaces the
    JONSWAP's where it is not NaN (a criterion it lacks keeps the JONSWAP's).
    Returns (utilisation (..., time, criterion), outside (n_time,) bool: Tz beyond the
    statistics' range). ``tz_outside``: ``error`` stops on such an hour, ``nearest``
    holds the end value, ``unworkable`` makes the hour infinitely utilised.
    """
    if tz_outside not in TZ_OUTSIDE:
        raise ValueError(f"tz_outside must be one of {', '.join(TZ_OUTSIDE)}, got {tz_outside!r}")
    hs, tz = np.asarray(hs, float), np.asarray(tz, float)
    u = unit_util.sortby("tz")
    grid = u["tz"].values
    outside = np.isfinite(tz) & ((tz < grid.min()) | (tz > grid.max()))
    if outside.any() and tz_outside == "error":
        k = int(np.flatnonzero(outside)[0])
        raise InputError(f"{int(outside.sum())} hours have Tz outside the statistics' range "
                         f"{grid.min():g}-{grid.max():g} s; widen the Tz grid (assessment.operability_tz_s) "
                         "or set weather_windows.tz_outside to 'nearest' or 'unworkable'",
                         file=source, field="tz",
                         value=float(tz[k]))
    lead = [d for d in u.dims if d not in ("tz", "criterion")]
    u = u.transpose(*lead, "criterion", "tz")
    at = at_hours(u.values, tz_weights(tz, grid))                  # (..., criterion, time)
    with np.errstate(invalid="ignore"):          # 0 x inf: a limit broken at rest, NaN fails
        prod = at * hs
    util = xr.DataArray(prod, dims=(*lead, "criterion", "time"),
                        coords={d: u[d] for d in (*lead, "criterion")})
    if sway_scale is not None and SWAY_M in util["criterion"].values:
        scale = sway_scale.transpose(*[d for d in (*lead, "time") if d in sway_scale.dims])
        if scale.sizes["time"] != hs.size:
            raise ValueError("sway_scale must be given on the hours of hs and tz")
        finite = np.isfinite(scale.values).reshape(-1, hs.size).all(0)
        missing = np.isfinite(hs) & ~finite
        if missing.any():
            k = int(np.flatnonzero(missing)[0])
            when = scale["time"].values[k] if "time" in scale.coords else k
            raise InputError("a recorded hour has no measured-spectrum sway ratio", file=source,
                             field="measured_response.sigma_measured", value=str(when))
        scale = scale.drop_vars("time", errors="ignore")
        util = xr.where(util["criterion"] == SWAY_M, util * scale, util)
    if own is not None:                        # the hours' own seas, where they have one
        o = own.reindex(criterion=util["criterion"].values).drop_vars("time", errors="ignore")
        if o.sizes["time"] != hs.size:
            raise ValueError("own must be given on the hours of hs and tz")
        util = xr.where(o.notnull(), o, util)
    if tz_outside == "unworkable":
        util = xr.where(xr.DataArray(outside, dims="time"), np.inf, util)
    util = util.transpose(*lead, "time", "criterion")
    return util.assign_coords({c: unit_util[c] for c in ("strict", "response", "criterion_units")
                               if c in unit_util.coords}), outside


def sway_ratio(measured: xr.Dataset, leg: str) -> xr.DataArray:
    """The hourly relative-sway ratio of a spectra leg, measured spectrum over the JONSWAP
    on the hour's (Hs, Tz) (candidate, tugger, time; ``measured_response.nc``), on the hours
    the leg records (an hour whose JONSWAP sigma is 0 has no sway either way: ratio 1)."""
    m = measured.sel(leg=leg, drop=True)
    m = m.isel(time=np.flatnonzero(np.isfinite(m["hs"].values)))
    num, den = m["sigma_measured"], m["sigma_jonswap"]
    ratio = xr.where(den > 0, num / den.where(den > 0), xr.where(num > 0, np.inf, 1.0))
    return ratio.transpose("candidate", "tugger", "time")


def route_sway_scale(measured: xr.Dataset | None, hours: xr.Dataset) -> xr.DataArray | None:
    """The sway ratio (candidate, tugger, leg, time) on a route's common hours
    (:func:`jls.assessment.route_hours.common_hours`): each spectra leg's
    :func:`sway_ratio`, 1 on the other legs and on hours without a record; None without
    a spectra leg on the route."""
    legs_measured = {str(leg) for leg in measured["leg"].values} if measured is not None else set()
    if not legs_measured & {str(leg) for leg in hours["leg"].values}:
        return None
    times = hours["time"].values
    legs = [str(leg) for leg in hours["leg"].values]
    parts = [sway_ratio(measured, leg).reindex(time=times).expand_dims(leg=[leg])
             for leg in legs if leg in legs_measured]
    scale = xr.concat(parts, dim="leg").reindex(leg=legs)       # the other legs: NaN, then 1
    return scale.fillna(1.0).transpose("candidate", "tugger", "leg", "time")


def leg_own_utilisation(measured: xr.Dataset | None, leg: str) -> xr.DataArray | None:
    """Every criterion's utilisation of each recorded hour of a leg on its own sea
    (candidate, tugger, heading, time, criterion; ``measured_response.nc`` utilisation,
    :mod:`jls.stages.hourly_seas`), at each of the leg's headings: where the hour is not
    met at a heading, the largest over the headings it is met at; None without it."""
    if measured is None or "utilisation" not in measured or leg not in measured["leg"].values:
        return None
    u = measured["utilisation"].sel(leg=leg, drop=True)
    u = u.isel(time=np.flatnonzero(np.isfinite(measured["hs"].sel(leg=leg).values)))
    return u.fillna(u.max("heading")).transpose("candidate", "tugger", "heading", "time", "criterion")


def _own_legs(measured: xr.Dataset | None, hours: xr.Dataset) -> tuple[list, list]:
    """(the route's legs, those of them with hours judged on their own seas)."""
    legs = [str(leg) for leg in hours["leg"].values]
    if measured is None or "utilisation" not in measured:
        return legs, []
    return legs, [leg for leg in legs if leg in {str(x) for x in measured["leg"].values}]


def route_own_heading_utilisation(measured: xr.Dataset | None, hours: xr.Dataset,
                                  headings) -> xr.Dataset | None:
    """The hours' utilisation on their own seas at each of ``headings`` (candidate, tugger,
    criterion, leg, heading, time) on a route's common hours, for the voyage extremes that
    weigh the headings (:func:`jls.assessment.voyage.hindcast_long_term`): at a heading the
    hour is not met at (or the leg has not), the largest over the headings it is met at
    (as :func:`leg_own_utilisation`); NaN on the other legs and on hours met at none
    (they keep the JONSWAP); None without such a leg on the route. A Dataset as
    :func:`route_own_utilisation`'s, with dim ``heading``."""
    legs, mine = _own_legs(measured, hours)
    if not mine:
        return None
    times, headings = hours["time"].values, np.asarray(headings, float)
    parts = []
    for leg in mine:
        worst = _at_worst_heading(measured, leg)
        names = {"utilisation": "utilisation", "tz_response_own": "tz_response"}
        d = xr.Dataset({names[v]: measured[v].sel(leg=leg, drop=True) for v in names if v in measured})
        d = d.drop_vars([c for c in d.coords if c not in d.dims])
        d = d.reindex(heading=headings).fillna(worst)
        parts.append(d.reindex(time=times).expand_dims(leg=[leg]))
    out = xr.concat(parts, dim="leg").reindex(leg=legs)
    return out.transpose("candidate", "tugger", "criterion", "leg", "heading", "time")


def _at_worst_heading(measured: xr.Dataset, leg):
    """The leg's own-sea ``utilisation`` and, where stored, ``tz_response_own`` (as
    ``tz_response``) at the heading of the hour's largest utilisation (time, candidate,
    tugger, criterion)."""
    u = measured["utilisation"].sel(leg=leg, drop=True)
    out = xr.Dataset({"utilisation": u.max("heading")})
    if "tz_response_own" in measured:
        worst = u.fillna(-np.inf).argmax("heading")
        for v, name in (("tz_response_own", "tz_response"),):
            out[name] = measured[v].sel(leg=leg, drop=True).isel(heading=worst).where(out["utilisation"].notnull())
    return out.drop_vars([c for c in out.coords if c not in out.dims])


def route_own_utilisation(measured: xr.Dataset | None, hours: xr.Dataset) -> xr.Dataset | None:
    """The hours' utilisation on their own seas (candidate, tugger, criterion, leg, time) on
    a route's common hours (:func:`jls.assessment.route_hours.common_hours`): each such
    leg's largest over the headings the hour is met at, NaN on the other legs and hours
    (they keep the JONSWAP); None without such a leg on the route. A Dataset:
    ``utilisation``, and where ``measured_response.nc`` stores it the own sea's
    ``tz_response`` at that heading (its sigma follows from the level,
    :func:`own_hour_statistics`)."""
    legs, mine = _own_legs(measured, hours)
    if not mine:
        return None
    import pandas as pd
    times = hours["time"].values
    ut = measured["utilisation"]
    dims = ("candidate", "tugger", "criterion")
    names = {"utilisation": "utilisation"}
    if "tz_response_own" in measured:
        names.update(tz_response_own="tz_response")
    shape = [ut.sizes[d] for d in dims] + [len(legs), times.size]
    out = {name: np.full(shape, np.nan, measured[v].dtype) for v, name in names.items()}
    at = pd.Index(measured["time"].values).get_indexer(times)     # the record's hour of each (-1: none)
    have = np.flatnonzero(at >= 0)
    for leg in mine:                           # a block of hours at a time: no hour-level copy
        k, j = legs.index(leg), int(np.flatnonzero(ut["leg"].values == leg)[0])
        for b in range(0, have.size, ROUTE_BLOCK):
            t = have[b:b + ROUTE_BLOCK]
            block = {v: measured[v].isel(leg=j, time=at[t]).transpose("time", "heading", *dims).values
                     for v in names}
            u = block["utilisation"]
            top = np.fmax.reduce(u, axis=1)                         # the largest over the headings met
            out["utilisation"][..., k, t] = np.moveaxis(top, 0, -1)
            if len(names) > 1:                 # the own sea's period at that heading
                worst = np.argmax(np.where(np.isnan(u), -np.inf, u), axis=1)[:, None]
                for v in ("tz_response_own",):
                    x = np.take_along_axis(block[v], worst, axis=1)[:, 0]
                    out[names[v]][..., k, t] = np.moveaxis(np.where(np.isnan(top), np.nan, x), 0, -1)
    return xr.Dataset({name: ((*dims, "leg", "time"), a) for name, a in out.items()},
                      coords={**{d: ut[d].values for d in dims}, "leg": legs, "time": times})


#: hours of the route's own-sea utilisation formed at a time (bounded memory)
ROUTE_BLOCK = 4096


class RouteOwnRows:
    """:func:`route_own_utilisation` formed a block of options at a time, for the route
    simulation (:func:`jls.assessment.route_simulation.route_simulation`, ``own``): the
    route's own-sea ``utilisation`` and ``tz_response`` of any rows of options are read
    from ``measured_response.nc`` when they are sailed, never held for every option at
    once (ten years of hours x options). The same numbers as :func:`route_own_utilisation`."""

    def __init__(self, measured: xr.Dataset, hours: xr.Dataset, legs: list, mine: list):
        import pandas as pd
        self.dims = ("candidate", "tugger", "criterion")
        self.labels = {d: measured[d].values for d in self.dims}
        self.names = ["utilisation"] + (["tz_response_own"] if "tz_response_own" in measured else [])
        self.arrays = {v: measured[v].transpose("leg", "time", "heading", *self.dims).values for v in self.names}
        self.n_legs, self.n_time = len(legs), hours["time"].size
        at = pd.Index(measured["time"].values).get_indexer(hours["time"].values)
        self.have = np.flatnonzero(at >= 0)
        self.at = at[self.have]
        self.legs = [(legs.index(leg), int(np.flatnonzero(measured["leg"].values == leg)[0])) for leg in mine]
        self.flat, self.measured = None, measured

    def bind(self, opt, coords: dict) -> bool:
        """Lay the rows out as the options ``opt`` (dims) on ``coords``; False where the
        options have a dim the own seas have not (the caller takes :func:`route_own_utilisation`)."""
        import pandas as pd
        if sorted(opt) != sorted(self.dims):
            return False
        self.sizes = sizes = [self.labels[d].size for d in self.dims]
        idx = [pd.Index(self.labels[d]).get_indexer(np.asarray(coords[d])) for d in opt]
        grid = np.meshgrid(*idx, indexing="ij")
        by = {d: g.ravel() for d, g in zip(opt, grid)}
        miss = np.any([by[d] < 0 for d in self.dims], axis=0)
        self.flat = np.where(miss, -1, np.ravel_multi_index([np.maximum(by[d], 0) for d in self.dims], sizes))
        return True

    def rows(self, r: slice) -> tuple:
        """(utilisation, tz_response or None), each (rows, leg, time), of the option rows ``r``."""
        idx = self.flat[r]
        out = {v: np.full((idx.size, self.n_legs, self.n_time), np.nan, self.arrays[v].dtype) for v in self.names}
        c, t, q = np.unravel_index(np.maximum(idx, 0), self.sizes)
        for k, j in self.legs:
            block = {v: a[j][:, :, c, t, q][self.at] for v, a in self.arrays.items()}
            u = block["utilisation"]                                     # (hours, heading, rows)
            top = np.fmax.reduce(u, axis=1)
            out["utilisation"][:, k, self.have] = top.T
            if "tz_response_own" in block:       # the period at the heading of the largest utilisation
                worst = np.argmax(np.where(np.isnan(u), -np.inf, u), axis=1)[:, None]
                x = np.take_along_axis(block["tz_response_own"], worst, axis=1)[:, 0]
                out["tz_response_own"][:, k, self.have] = np.where(np.isnan(top), np.nan, x).T
        for a in out.values():
            a[idx < 0] = np.nan
        return out["utilisation"], out.get("tz_response_own")


def route_own_rows(measured: xr.Dataset | None, hours: xr.Dataset) -> RouteOwnRows | None:
    """:class:`RouteOwnRows` of a route (None without a leg judged on its own seas)."""
    legs, mine = _own_legs(measured, hours)
    return RouteOwnRows(measured, hours, legs, mine) if mine else None
