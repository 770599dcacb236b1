"""Weather windows: how often a workable window of a leg's duration opens in a hindcast.

A scatter table says how much of the time the sea is workable; a transit also needs the
workable time to come in one piece. Following the persistence analysis of DNV-ST-N001
for weather-restricted operations, the hourly record of a leg's hindcast is scanned:

1. **Hourly flag.** Each hour's sea state (Hs, Tz) is assessed as a scatter cell is
   (:mod:`jls.assessment.hourly`): with ``u(Tz)`` the unit utilisation of each criterion
   (per metre of Hs, interpolated linearly in Tz between the statistics' Tz values),
   the hour is workable when ``Hs u(Tz) <= alpha`` for every criterion (``< alpha``
   for the strict tension floor). ``alpha`` is the factor between the design limit and
   the operational limit (DNV-ST-N001: OP_WF = alpha OP_LIM; 1 uses the design limit
   itself, smaller values keep a margin for forecast uncertainty). With the operation's
   alpha table (``operation.alpha_factors``) alpha is the voyage plan's, hour by hour
   (:func:`table_alpha`): OP_WF of the master's table and the windows use one alpha.
   On a leg given by
   measured spectra the relative sway's utilisation is scaled by the hour's ratio of
   the sway over its measured spectrum to that over the JONSWAP
   (:func:`jls.assessment.hourly.sway_ratio`). No steepness cap applies: these are
   recorded sea states.
2. **Persistence.** A window of duration D (the leg's duration; include any
   contingency time in it) needs ``n = ceil(D / 1 h)`` consecutive workable hours. For
   every start hour whose window lies inside the record, the window is workable when
   all its hours are. The probability that a workable window starts at a random time
   is the workable share of the start hours, per calendar month of the start and over
   the whole record.
3. **Gaps.** The record is put on a regular hourly grid; missing hours are gaps and are
   never guessed. With ``gaps="exclude"`` (default) a window containing a gap cannot be
   judged and is left out of both counts (the probability is conditional on a complete
   record, and the number of judged starts is reported per month); with
   ``gaps="unworkable"`` a gap hour counts as not workable (a lower bound).
4. **Headings.** The relative wave heading of a leg is uncertain but taken as constant
   along a leg (as in the scatter assessment); probabilities are averaged over the
   leg's headings with their probabilities.

DNV-ST-N001 treats an operation whose reference period (planned duration plus
contingency) exceeds 72 hours as weather-unrestricted, to be designed for the season's
extremes; for such a leg the window probability is a planning figure, not a substitute
for that design.

Hours whose Tz lies outside the statistics' Tz range are an error by default
(``tz_outside="error"``); ``"nearest"`` holds the end value, ``"unworkable"`` counts
them as not workable. Their number is reported.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.hourly import hourly_utilisation, leg_own_utilisation, sway_ratio
from jls.assessment.operation import AlphaTable
from jls.assessment.voyage_plan import alpha_periods
from jls.assessment.workability import cell_passes, criteria_array, unit_utilisation
from jls.errors import InputError
from jls.io import registry
from jls.names import FLAG_MEANINGS
from jls.sea.hindcast import hindcast_gaps
from jls.sea.records import integrated_directly, is_hourly, leg_series

STEP = pd.Timedelta("1h")
#: the variables evaluated for every option (candidate, tugger); the route's file keeps them
#: as ``<name>_options`` beside the assessed option's
PER_OPTION = ("window_probability", "window_probability_all", "workable_fraction", "workable_hourly")


def read_route_hindcasts(route: dict, base_dir=".", *, gamma: float) -> dict:
    """Leg name -> hourly record (:func:`jls.sea.records.leg_series`: hindcast, metocean
    or spectra legs, columns hs, tz[, direction]) for the legs of a route that give one;
    legs given by a scatter table have no hourly record and are left out. ``gamma``: the
    JONSWAP gamma a declared period other than Tz is converted with."""
    return {leg["name"]: leg_series(leg, base_dir, gamma=gamma)
            for leg in route["legs"] if is_hourly(leg)}


def regular_hours(series: pd.DataFrame) -> pd.DataFrame:
    """The record on a complete hourly grid from its first to its last time; missing
    hours are rows of NaN. Times off the hourly grid of the first record are an error."""
    idx = pd.DatetimeIndex(series.index)
    if len(idx) == 0:
        raise InputError("hindcast has no records", file=series.attrs.get("source"), field="time")
    idx = idx.tz_localize("UTC") if idx.tz is None else idx.tz_convert("UTC")
    off = (idx - idx[0]) % STEP
    if (off != pd.Timedelta(0)).any():
        k = int(np.flatnonzero(off != pd.Timedelta(0))[0])
        raise InputError("records are not on an hourly grid", file=series.attrs.get("source"),
                         field="time", value=str(idx[k]))
    grid = pd.date_range(idx[0], idx[-1], freq=STEP)
    out = series.set_axis(idx).reindex(grid)
    out.index.name = "time"
    out.attrs = dict(series.attrs)
    return out


def window_starts(workable, known, n: int, gaps="exclude"):
    """Which start hours open a workable window of ``n`` hours.

    workable, known: (..., n_time) bool on a regular hourly grid (known: the hour has a
    record). Returns (ok, judged), each (..., n_time - n + 1) bool: the window starting at
    that hour is workable, and it can be judged (``gaps="exclude"``: no gap inside;
    ``"unworkable"``: always, a gap counting as not workable).
    """
    if gaps not in ("exclude", "unworkable"):
        raise ValueError(f"gaps must be 'exclude' or 'unworkable', got {gaps!r}")
    workable = np.asarray(workable, bool) & np.asarray(known, bool)
    known = np.broadcast_to(np.asarray(known, bool), workable.shape)
    n_time = workable.shape[-1]
    if n < 1 or n > n_time:
        empty = np.zeros(workable.shape[:-1] + (max(n_time - n + 1, 0),), bool)
        return empty, empty.copy()
    pad = [(0, 0)] * (workable.ndim - 1) + [(1, 0)]
    cw = np.pad(np.cumsum(workable, axis=-1), pad)
    ck = np.pad(np.cumsum(known, axis=-1), pad)
    n_work = cw[..., n:] - cw[..., :-n]
    n_known = ck[..., n:] - ck[..., :-n]
    ok = n_work == n
    judged = n_known == n if gaps == "exclude" else np.ones_like(ok)
    return ok & judged, judged


def window_probability(ok, judged, months):
    """Workable share of the judged starts per calendar month (12,) and overall.

    ok, judged: (..., n_start) bool; months: (n_start,) 1-12. Months without a judged
    start are NaN. Returns (per_month (..., 12), overall (...), judged starts (12,)).
    """
    months = np.asarray(months)
    onehot = months[:, None] == np.arange(1, 13)[None, :]                 # (n_start, 12)
    judged_m = np.asarray(judged, float) @ onehot
    ok_m = np.asarray(ok & judged, float) @ onehot
    with np.errstate(invalid="ignore", divide="ignore"):
        per_month = np.where(judged_m > 0, ok_m / np.where(judged_m > 0, judged_m, 1.0), np.nan)
        total = np.asarray(judged).sum(-1)
        overall = np.where(total > 0, np.asarray(ok & judged).sum(-1) / np.maximum(total, 1), np.nan)
    judged = np.asarray(judged, int)
    first = judged.reshape(-1, months.size)[0] if judged.size else np.zeros(months.size, int)
    n_judged = first @ onehot            # the same for every option: gaps do not depend on it
    return per_month, overall, n_judged


def table_alpha(util: xr.DataArray, hs, table: AlphaTable, planned_h: float) -> xr.DataArray:
    """The hour's alpha from the operation's table, as the voyage plan reads it
    (:func:`jls.assessment.voyage_plan.forecast_utilisation`): at the planned period of
    the leg's stretch (held at the table's ends) and the hour's limiting Hs, Hs over its
    largest utilisation (the criteria are linear in Hs). util: (..., time, criterion)."""
    period = float(alpha_periods([planned_h], table)[0])
    u = util.max("criterion")
    hs = xr.DataArray(np.asarray(hs, float), dims="time")
    with np.errstate(invalid="ignore", divide="ignore"):
        lim = xr.where(u > 0, hs / u, np.inf)
    lim = lim.fillna(0.0)
    return xr.apply_ufunc(lambda x: table.factor(period, x), lim)


def leg_windows(series: pd.DataFrame, unit_util: xr.DataArray, duration_h: float, *, alpha=1.0,
                gaps="exclude", tz_outside="error", sway_scale: xr.DataArray | None = None,
                own: xr.DataArray | None = None, alpha_factors: AlphaTable | None = None,
                planned_h: float | None = None) -> xr.Dataset:
    """Weather windows of one leg for every candidate, tugger and heading of ``unit_util``
    (``own``: the hours' utilisation on their own seas, :func:`jls.assessment.hourly.leg_own_utilisation`).

    series: the leg's hindcast (:func:`jls.sea.hindcast.read_hindcast`); unit_util:
    (candidate, tugger, heading, tz, criterion) from :func:`jls.assessment.workability.unit_utilisation`.
    alpha_factors: the operation's alpha table, read per hour as the voyage plan reads it
    (:func:`table_alpha`, at ``planned_h``, the planned period of the leg's stretch), in
    place of the constant ``alpha`` (which must then be 1).
    Returns a dataset over time (the leg's hourly grid) and month; see
    :func:`windows_dataset` for the variables (here per heading, without the leg).
    """
    if not 0.0 < float(alpha) <= 1.0:
        raise InputError("the alpha factor must lie in (0, 1]", field="alpha", value=alpha)
    if alpha_factors is not None and float(alpha) != 1.0:
        raise InputError(f"two alphas for the weather windows: the operation's table ({alpha_factors.source}) "
                         "and a constant; the windows use the table, as the voyage plan does (remove the "
                         "constant)", field="weather_windows.alpha", value=alpha)
    if not float(duration_h) > 0:
        raise InputError("the window duration must be positive", field="duration_h", value=duration_h)
    source = series.attrs.get("source")
    hours = regular_hours(series)
    hs, tz = hours["hs"].to_numpy(float), hours["tz"].to_numpy(float)
    known = np.isfinite(hs) & np.isfinite(tz)
    if sway_scale is not None:                 # on the hourly grid; NaN where no hour is recorded
        sway_scale = sway_scale.reindex(time=hours.index.tz_convert(None).to_numpy())
    if own is not None:
        own = own.sel(candidate=unit_util["candidate"], tugger=unit_util["tugger"],
                      heading=unit_util["heading"]).reindex(time=hours.index.tz_convert(None).to_numpy())
    util, outside = hourly_utilisation(hs, tz, unit_util, tz_outside, source, sway_scale, own)
    a = float(alpha) if alpha_factors is None else table_alpha(util, hs, alpha_factors, planned_h)
    flags = cell_passes(util / a) & xr.DataArray(known, dims="time")
    flags = flags.transpose("candidate", "tugger", "heading", "time")
    n = math.ceil(float(duration_h) / (STEP / pd.Timedelta("1h")) - 1e-9)
    ok, judged = window_starts(flags.values, known, n, gaps)
    months = hours.index.month.to_numpy()[: ok.shape[-1]]
    per_month, overall, n_judged = window_probability(ok, judged, months)
    lead = ("candidate", "tugger", "heading")
    coords = {d: flags[d].values for d in lead}
    code = np.where(known, flags.values.astype(np.int8), np.int8(-1))
    gap = hindcast_gaps(series)
    ds = xr.Dataset(
        {"workable_hourly": (lead + ("time",), code),
         "window_probability": (lead + ("month",), per_month),
         "window_probability_all": (lead, overall),
         "workable_fraction": (lead, flags.values.sum(-1) / max(int(known.sum()), 1)),
         "window_starts": ("month", n_judged),
         "window_duration_h": ((), float(duration_h)),
         "window_hours": ((), n),
         "hours_outside_tz": ((), int(outside.sum())),
         "missing_hours": ((), int(gap.missing_hours)),
         "record_coverage": ((), float(gap.coverage))},
        coords={**coords, "time": hours.index.tz_convert(None).to_numpy(),
                "month": np.arange(1, 13)})
    return ds


def _leg_sway_scale(leg: dict, measured: xr.Dataset | None, unit_util: xr.DataArray):
    """The hourly sway ratio of a spectra leg on the options of ``unit_util``; None for
    another leg. A spectra leg without its measured response is an error."""
    if not integrated_directly(leg):
        return None
    name = leg["name"]
    if measured is None or name not in measured["leg"].values:
        raise InputError("a leg given by spectra needs its measured-spectrum response "
                         "(measured_response.nc) for its hourly verdicts", field=f"legs[{name}].spectra")
    return sway_ratio(measured, name).sel(candidate=unit_util["candidate"], tugger=unit_util["tugger"])


def windows_dataset(legs: list[dict], hindcasts: dict, stats: xr.Dataset, criteria: dict, *,
                    alpha=1.0, gaps="exclude", tz_outside="error",
                    measured: xr.Dataset | None = None, alpha_factors: AlphaTable | None = None,
                    leg_period_h: dict | None = None) -> xr.Dataset:
    """The weather-window dataset of a route's hindcast legs.

    legs: leg mappings of the route (``name``, ``duration_h``, optional ``headings_deg``
    and ``heading_probability``, as in the configuration); hindcasts: leg name -> hourly
    DataFrame (:func:`jls.sea.hindcast.read_hindcast`); stats: unit-Hs statistics per
    (candidate, tugger, heading, tz) (``operability.nc``: ``mpm``, and the tension
    statistics for tension criteria); criteria: the configuration's criteria; measured:
    ``measured_response.nc``, needed when a leg is given by spectra (its hours' sway ratio,
    :func:`jls.assessment.hourly.sway_ratio`); alpha_factors, leg_period_h: the operation's
    alpha table and leg name -> the planned period of its stretch, the alpha of the voyage
    plan's OP_WF (:func:`table_alpha`; absent: the constant ``alpha``).

    Variables:

    ========================== ================================ ===== =========================
    ``window_probability``     candidate, tugger, leg, month    1     share of judged starts
                                                                      in the calendar month
                                                                      (1-12) that open a
                                                                      workable window (NaN:
                                                                      no judged start)
    ``window_probability_all`` candidate, tugger, leg           1     the same over the record
    ``workable_fraction``      candidate, tugger, leg           1     share of recorded hours
                                                                      that are workable (no
                                                                      persistence)
    ``workable_hourly``        candidate, tugger, heading, leg, flag  1 workable, 0 not,
                               time                                   -1 no record (gap, or
                                                                      outside the leg's record)
    ``window_starts``          leg, month                       1     judged start hours
    ``window_duration_h``      leg                              h     window duration
    ``window_hours``           leg                              1     hours a window needs
    ``hours_outside_tz``       leg                              1     hours with Tz outside
                                                                      the statistics' range
    ``missing_hours``          leg                              1     gap hours in the record
    ``record_coverage``        leg                              1     records / hours spanned
    ========================== ================================ ===== =========================

    Probabilities are averaged over each leg's headings with their probabilities.
    Attributes: ``alpha``, ``gaps``, ``tz_outside``, ``source_<leg>``, ``measured_sway_legs``
    (the legs whose sway was scaled by the measured spectra).
    """
    limit = criteria_array(criteria)
    unit_util = unit_utilisation(stats, limit)
    parts = []
    for leg in legs:
        name = leg["name"]
        if name not in hindcasts:
            raise InputError("weather windows need the leg's hourly hindcast", field=f"legs[{name}]")
        hdg = [float(h) for h in leg["headings_deg"]]
        hp = np.asarray(leg["heading_probability"], float)
        missing = sorted(set(hdg) - set(unit_util["heading"].values.tolist()))
        if missing:
            raise InputError("no statistics at the leg's heading(s)", field=f"legs[{name}].headings_deg",
                             value=missing)
        part = leg_windows(hindcasts[name], unit_util.sel(heading=hdg), leg["duration_h"],
                           alpha=alpha, gaps=gaps, tz_outside=tz_outside,
                           sway_scale=_leg_sway_scale(leg, measured, unit_util),
                           own=leg_own_utilisation(measured, name), alpha_factors=alpha_factors,
                           planned_h=None if alpha_factors is None else _period(leg_period_h, name))
        p = xr.DataArray(hp, dims="heading", coords={"heading": hdg})
        for var in ("window_probability", "window_probability_all", "workable_fraction"):
            part[var] = (part[var] * p).sum("heading", skipna=False)
        part = part.reindex(heading=sorted(unit_util["heading"].values.tolist()), fill_value=-1)
        parts.append(part.expand_dims(leg=[name]))
    ds = xr.concat(parts, dim="leg", join="outer", fill_value={"workable_hourly": -1})
    ds["workable_hourly"] = ds["workable_hourly"].astype(np.int8).transpose(
        "candidate", "tugger", "heading", "leg", "time")
    ds["window_starts"] = ds["window_starts"].astype(np.int64)
    for var in ("window_probability", "window_probability_all", "workable_fraction"):
        ds[var] = ds[var].transpose("candidate", "tugger", "leg", ...)
    # units and long names from the registry: the per-option variables are the file's
    # ``*_options`` (jls.stages.weather_windows)
    per_option = {v: f"{v}_options" for v in PER_OPTION}
    ds = registry.annotate(ds.rename(per_option), "weather_windows").rename({b: a for a, b in per_option.items()})
    ds["workable_hourly"].attrs.update(flag_values=np.array([-1, 0, 1], np.int8),
                                       flag_meanings=FLAG_MEANINGS)
    ds.attrs.update(alpha=float(alpha), gaps=gaps, tz_outside=tz_outside,
                    alpha_source=alpha_factors.source if alpha_factors is not None else "",
                    alpha_periods_h=" ".join(f"{leg['name']}:{_period(leg_period_h, leg['name']):g}"
                                             for leg in legs) if alpha_factors is not None else "",
                    measured_sway_legs=" ".join(leg["name"] for leg in legs if integrated_directly(leg)),
                    own_sea_not_used=_own_sea_not_used(legs, measured),
                    criteria=" ".join(limit["criterion"].values.tolist()))
    for leg in legs:
        ds.attrs[f"source_{leg['name']}"] = str(hindcasts[leg["name"]].attrs.get("source", ""))
    return ds


def _own_sea_not_used(legs, measured) -> str:
    from jls.assessment.hourly import OWN_SEA_NOT_USED
    names = [leg["name"] for leg in legs if integrated_directly(leg)
             and leg_own_utilisation(measured, leg["name"]) is None]
    return f"the weather windows of leg(s) {', '.join(names)} {OWN_SEA_NOT_USED}" if names else ""


def _period(leg_period_h, name) -> float:
    if not leg_period_h or name not in leg_period_h:
        raise InputError("the alpha table needs the planned period of the leg's stretch", field=f"legs[{name}]")
    return float(leg_period_h[name])


__all__ = ["table_alpha", "read_route_hindcasts", "regular_hours", "window_starts",
           "window_probability", "leg_windows", "windows_dataset"]
