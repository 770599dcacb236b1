"""A route's hours: the legs' hourly records on one hourly grid, the hours each leg
occupies, and the departures those records allow (:func:`common_hours`,
:func:`leg_hours`, :func:`departure_range`), for the route simulation
(:mod:`jls.assessment.route_simulation`) and the hindcast long-term extreme
(:func:`jls.assessment.voyage.hindcast_long_term`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError

STEP = pd.Timedelta("1h")


def leg_hours(duration_h) -> np.ndarray:
    """Hours of record each leg occupies: ceil(D / 1 h) (a part hour takes a whole one)."""
    return np.array([math.ceil(float(d) - 1e-9) for d in np.atleast_1d(duration_h)], int)


def common_hours(records: Mapping[str, pd.DataFrame]) -> xr.Dataset:
    """The legs' hourly records (leg name -> DataFrame indexed by time with ``hs`` [m],
    ``tz`` [s], :func:`jls.sea.hindcast.read_hindcast`) on one hourly UTC grid from the
    earliest to the latest record: ``hs``, ``tz`` (leg, time), NaN where the leg has no
    record (a gap, or outside its record); attrs ``source_<leg>``. The same record may
    serve several legs (one record for the whole route)."""
    idx = {}
    for leg, df in records.items():
        t = pd.DatetimeIndex(df.index)
        t = t.tz_localize("UTC") if t.tz is None else t.tz_convert("UTC")
        if len(t) == 0:
            raise InputError("hindcast has no records", file=df.attrs.get("source"), field=f"legs[{leg}]")
        off = (t - t[0]) % STEP
        if (off != pd.Timedelta(0)).any() or not t.is_monotonic_increasing:
            k = int(np.flatnonzero((off != pd.Timedelta(0)) | ~np.r_[True, np.diff(t.asi8) > 0])[0])
            raise InputError("records are not on an increasing hourly grid", file=df.attrs.get("source"),
                             field=f"legs[{leg}].time", value=str(t[k]))
        idx[leg] = t
    start, end = min(t[0] for t in idx.values()), max(t[-1] for t in idx.values())
    if any((t[0] - start) % STEP != pd.Timedelta(0) for t in idx.values()):
        raise InputError("the legs' records are not on the same hourly grid", field="legs")
    grid = pd.date_range(start, end, freq=STEP)
    out = {v: np.full((len(records), grid.size), np.nan) for v in ("hs", "tz")}
    for k, (leg, df) in enumerate(records.items()):
        pos = ((idx[leg] - start) // STEP).to_numpy()
        for v in out:
            out[v][k, pos] = df[v].to_numpy(float)
    ds = xr.Dataset({v: (("leg", "time"), a) for v, a in out.items()},
                    coords={"leg": list(records), "time": grid.tz_convert(None).to_numpy()})
    ds["hs"].attrs.update(units="m", long_name="significant wave height")
    ds["tz"].attrs.update(units="s", long_name="zero-up-crossing period")
    ds.attrs.update({f"source_{leg}": str(df.attrs.get("source", "")) for leg, df in records.items()})
    return ds


def departure_range(known, hours, legs, sources=None, times=None) -> tuple[int, int]:
    """First departure index and number of departures for which each leg's hours lie
    within the span of its record; InputError naming the leg when there is none.

    known: (n_legs, n_time) bool; hours: hours per leg (:func:`leg_hours`); sources: leg
    -> file name; times: the hours (for messages)."""
    sources = sources or {}
    known = np.asarray(known, bool)
    at = (lambda i: str(times[0] + int(i) * STEP)) if times is not None else (lambda i: f"hour {i}")  # noqa: E731
    off = np.concatenate([[0], np.cumsum(hours)[:-1]])
    span = []
    for k, leg in enumerate(legs):
        rec = np.flatnonzero(known[k])
        if rec.size == 0:
            raise InputError("the leg's hourly record is empty", file=sources.get(leg), field=f"legs[{leg}]")
        span.append((int(rec[0]), int(rec[-1])))
        if rec[-1] - rec[0] + 1 < hours[k]:
            raise InputError(f"the hourly record spans {rec[-1] - rec[0] + 1} h, shorter than the "
                             f"leg's {hours[k]} h", file=sources.get(leg), field=f"legs[{leg}]",
                             value=int(rec[-1] - rec[0] + 1))
    first = max(s - o for (s, _), o in zip(span, off))
    for k, leg in enumerate(legs):
        if first + off[k] + hours[k] - 1 <= span[k][1]:
            continue
        why = (f"the leg's record ends at {at(span[k][1])}, before the earliest departure the "
               f"other legs' records allow ({at(first)}) reaches the leg"
               if first + off[k] > span[k][1] else
               f"departing at {at(first)}, the voyage ({int(np.sum(hours))} h) needs the leg's record "
               f"up to {at(first + off[k] + hours[k] - 1)}; it ends at {at(span[k][1])}")
        raise InputError(f"the voyage runs past the end of the leg's hourly record: {why}",
                         file=sources.get(leg), field=f"legs[{leg}]",
                         value=f"{span[k][1] - span[k][0] + 1} h")
    last = min(e - o - h + 1 for (_, e), o, h in zip(span, off, hours))
    return int(first), int(last - first + 1)
