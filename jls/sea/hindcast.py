"""Hourly sea-state hindcasts: reader, gap summary and binning into a scatter table.

File format (the NDBC / OMAE 2019 benchmark files; see docs/sea.md)::

    time (YYYY-MM-DD-HH); significant wave height (m); zero-up-crossing period (s)
    1996-01-01-00; 0.2845; 4.7252

* separator ``;`` (spaces around it are ignored); first non-blank line is the column-name
  row and its first name must start with ``time``; ``#`` lines are comments;
* columns by position: time (UTC, ``YYYY-MM-DD-HH`` or ISO 8601), Hs [m], Tz [s], and
  an optional fourth column whose name contains ``dir``: direction [deg], 0-360;
* times strictly increasing; missing hours are gaps (reported, see :func:`hindcast_gaps`).

Bad rows (wrong field count, unparsable time or number, non-finite, negative Hs,
Tz <= 0, Hs >= 30 m or Tz >= 30 s -- e.g. an NDBC missing-value code 99 -- duplicate or
decreasing time) raise InputError naming the file and line; nothing is dropped.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.sea.scatter import read_utf8, scatter_dataset

__all__ = ["read_hindcast", "hindcast_gaps", "GapSummary", "direction_bins", "bin_hindcast", "record_summary",
           "record_warnings", "HS_MAX", "TZ_MAX"]

HS_MAX = 30.0  # m; larger values are treated as bad data (NDBC uses 99 for missing)
TZ_MAX = 30.0  # s
UNITS = {"hs": "m", "tz": "s", "direction": "deg"}


def _bad(file, line, message, value):
    return InputError(message, file=file, field=f"line {line}", value=value)


def read_hindcast(path) -> pd.DataFrame:
    """Read an hourly hindcast into a DataFrame indexed by UTC time (index name "time").

    Columns ``hs`` [m], ``tz`` [s] and ``direction`` [deg] if the file has it.
    ``df.attrs`` holds source (file name), sha256, path and units.  The full series is
    returned so it can be used for weather-window (persistence) analysis.
    """
    file = str(path)
    raw, text = read_utf8(path, "hindcast")
    lines = text.splitlines()
    body = [(i, s) for i, s in enumerate((ln.strip() for ln in lines), 1) if s and not s.startswith("#")]
    if not body:
        raise InputError("empty hindcast file", file=file)
    hline, htext = body[0]
    names = [n.strip() for n in htext.split(";")]
    if not names[0].lower().startswith("time") or len(names) not in (3, 4) or \
            (len(names) == 4 and "dir" not in names[3].lower()):
        raise _bad(file, hline, "expected a column-name row 'time; Hs; Tz[; direction]'", htext)
    cols = ["hs", "tz"] + (["direction"] if len(names) == 4 else [])
    _check_column_names(names, file, hline)
    if len(body) < 2:
        raise InputError("hindcast has no records", file=file)
    lineno = np.array([i for i, _ in body[1:]])
    fields = [[p.strip() for p in s.split(";")] for _, s in body[1:]]
    nf = np.array([len(f) for f in fields])
    wrong = np.flatnonzero(nf != len(names))
    if wrong.size:
        k = wrong[0]
        raise _bad(file, lineno[k], f"expected {len(names)} fields separated by ';', got {nf[k]}"
                   f" ({wrong.size} such lines)", body[k + 1][1])
    table = list(zip(*fields))
    ttext = pd.Series(table[0])
    time = pd.to_datetime(ttext, format="%Y-%m-%d-%H", errors="coerce", utc=True)
    nat = time.isna().to_numpy()
    if nat.any():  # ISO 8601; parse naive and offset-carrying texts apart (pandas mixes them)
        aware = ttext.str.contains(r"(?:Z|[+-]\d\d:?\d\d)$", regex=True).to_numpy()
        for part in (nat & aware, nat & ~aware):
            if part.any():
                time[part] = pd.to_datetime(ttext[part], format="ISO8601", errors="coerce", utc=True)
        nat = time.isna().to_numpy()
    if nat.any():
        k = np.flatnonzero(nat)[0]
        raise _bad(file, lineno[k], f"unparsable time (YYYY-MM-DD-HH) ({nat.sum()} such lines)", ttext[k])
    data = {}
    for j, name in enumerate(cols, start=1):
        text = pd.Series(table[j])
        v = pd.to_numeric(text, errors="coerce").to_numpy(dtype=float)
        if name == "hs":
            ok = (v >= 0) & (v < HS_MAX)
        elif name == "tz":
            ok = (v > 0) & (v < TZ_MAX)
        else:
            ok = (v >= 0) & (v <= 360)
        if not ok.all():
            k = np.flatnonzero(~ok)[0]
            try:
                float(text[k])
                why = {"hs": f"Hs must be finite, >= 0 and < {HS_MAX:g} m",
                       "tz": f"Tz must be finite, > 0 and < {TZ_MAX:g} s",
                       "direction": "direction must be finite and within 0-360 deg"}[name]
            except ValueError:
                why = f"unparsable number in column {name}"
            raise _bad(file, lineno[k], f"{why} ({(~ok).sum()} such lines)", text[k])
        data[name] = v
    step = np.diff(pd.DatetimeIndex(time).asi8)
    if (step <= 0).any():
        k = np.flatnonzero(step <= 0)[0] + 1
        raise _bad(file, lineno[k], "time not strictly increasing (duplicate or out of order)", ttext[k])
    df = pd.DataFrame(data, index=pd.DatetimeIndex(time, name="time"))
    df.attrs.update(source=Path(path).name, sha256=hashlib.sha256(raw).hexdigest(), path=file,
                    units=dict((c, UNITS[c]) for c in cols))
    return df


_UNITS_OK = {1: {"m", "metre", "metres", "meter", "meters"}, 2: {"s", "sec", "second", "seconds"},
             3: {"deg", "degree", "degrees", "deg true", "degrees true"}}


def _check_column_names(names, file, line) -> None:
    """The column-name row's units (in parentheses) and period: m, s, degrees and the
    zero-up-crossing period; a column named for another period or unit is refused."""
    for j, name in enumerate(names[1:], start=1):
        unit = re.search(r"\(([^)]*)\)", name)
        text = unit.group(1).strip().lower() if unit else None
        if text is not None and j in _UNITS_OK and text not in _UNITS_OK[j] and not (
                j == 3 and text.startswith("deg")):
            raise _bad(file, line, f"column {j + 1} is in {unit.group(1)!r}; jls reads Hs in m, Tz "
                       "in s and directions in degrees: convert the record", name)
    words = re.findall(r"[a-z][a-z0-9]*", names[2].lower().replace("tm-10", "tm10"))
    other = [w for w in words if w in _OTHER_PERIODS]
    if other:
        raise _bad(file, line, f"column 3 is named for {_OTHER_PERIODS[other[0]]}, not the "
                   "zero-up-crossing period Tz jls reads there: convert it to Tz", names[2])


_OTHER_PERIODS = {"tp": "the peak period", "peak": "the peak period", "tpeak": "the peak period",
                  "te": "the energy period", "energy": "the energy period",
                  "tm01": "the mean period Tm01", "t01": "the mean period Tm01",
                  "tm10": "the energy period Tm-10", "mean": "a mean period"}


def record_summary(series: pd.DataFrame) -> dict:
    """What a record covers, as dataset attributes: first and last time (UTC), the span
    [h], the step (the most common interval between records [h]), the records, the
    coverage of the span at that step, and the calendar months with and without a record."""
    idx = pd.DatetimeIndex(series.index)
    idx = idx.tz_localize("UTC") if idx.tz is None else idx.tz_convert("UTC")
    span = float((idx[-1] - idx[0]) / pd.Timedelta("1h")) if len(idx) else 0.0
    steps = np.diff(idx.as_unit("ns").asi8) / 3.6e12
    if steps.size:
        values, counts = np.unique(np.round(steps, 6), return_counts=True)
        step = float(values[np.argmax(counts)])
    else:
        step = 1.0
    months = sorted({int(m) for m in idx.month})
    expected = int(round(span / step)) + 1 if step > 0 else len(idx)
    return {"record_start": idx[0].isoformat() if len(idx) else "",
            "record_end": idx[-1].isoformat() if len(idx) else "",
            "record_span_h": span, "record_step_h": step, "record_count": int(len(idx)),
            "record_coverage": len(idx) / expected if expected else 0.0,
            "record_months": " ".join(_MONTHS[m - 1] for m in months),
            "record_missing_months": " ".join(_MONTHS[m - 1] for m in range(1, 13) if m not in months)}


_MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


def record_warnings(summary: dict, source: str) -> list[str]:
    """The warnings a report prints on its first page about a record: a step that is not
    hourly, calendar months without a record, a span mostly without records."""
    out = []
    step = summary["record_step_h"]
    if abs(step - 1.0) > 1e-6:
        out.append(f"hindcast {source}: records every {step:g} h, not hourly; its Hs-Tz table weighs "
                   "each record alike, but hourly persistence (weather windows) would count the "
                   f"hours between records as gaps ({100 * (1 - 1 / step):.0f} % of the hours)"
                   if step > 1 else
                   f"hindcast {source}: records every {step:g} h, not hourly")
    missing = summary["record_missing_months"].split()
    if missing:
        out.append(f"hindcast {source}: covers {12 - len(missing)} of the 12 calendar months "
                   f"({summary['record_months']}; none in {' '.join(missing)}), from "
                   f"{summary['record_start'][:10]} to {summary['record_end'][:10]}: its table is "
                   "seasonal, and so is the workability assessed from it")
    if summary["record_coverage"] < 0.5:
        out.append(f"hindcast {source}: records cover {100 * summary['record_coverage']:.0f} % of "
                   f"the {summary['record_span_h'] / 24:.0f} days from its first to its last record")
    return out


@dataclass(frozen=True)
class GapSummary:
    """Gaps in an hourly series.  Durations in hours; coverage is a fraction [0-1]."""

    n_records: int
    start: pd.Timestamp
    end: pd.Timestamp
    missing_hours: int
    n_gaps: int
    longest_gap_hours: int
    longest_gap_start: pd.Timestamp | None
    coverage: float

    def as_dict(self) -> dict:
        """Plain dict (timestamps as ISO text) for headers and attrs."""
        return {k: (v.isoformat() if isinstance(v, pd.Timestamp) else v) for k, v in asdict(self).items()}


def _utc(t):
    t = pd.Timestamp(t)
    return t.tz_localize("UTC") if t.tzinfo is None else t.tz_convert("UTC")


def hindcast_gaps(series: pd.DataFrame, *, start=None, end=None, step="1h") -> GapSummary:
    """Summarise the missing records of a regular series (default hourly).

    Expected records run from `start` to `end` inclusive (default: first and last
    record).  A gap is a run of missing time steps; ``longest_gap_start`` is the first
    missing time of the longest gap.  Coverage = records / expected records.  Durations
    are in hours (step multiples, so whole hours for an hourly series).
    """
    idx = pd.DatetimeIndex(series.index)
    if len(idx) == 0:
        raise InputError("series is empty", field="time")
    idx = idx.tz_localize("UTC") if idx.tz is None else idx.tz_convert("UTC")
    idx = idx.as_unit("ns")        # asi8 below counts nanoseconds whatever pandas parsed
    if not idx.is_monotonic_increasing or not idx.is_unique:
        raise InputError("time index must be strictly increasing", field="time")
    dt = pd.Timedelta(step)
    start = idx[0] if start is None else _utc(start)
    end = idx[-1] if end is None else _utc(end)
    if idx[0] < start or idx[-1] > end:
        raise InputError("records lie outside start/end", field="time", value=f"{idx[0]} .. {idx[-1]}")
    ns = np.concatenate([[(start - dt).value], idx.asi8, [(end + dt).value]])
    missing_steps = np.round(np.diff(ns) / dt.value).astype(np.int64) - 1
    gap = missing_steps > 0
    hours = dt / pd.Timedelta("1h")
    as_hours = lambda n: int(n * hours) if float(n * hours).is_integer() else float(n * hours)  # noqa: E731
    k = int(np.argmax(missing_steps))
    return GapSummary(
        n_records=len(idx), start=start, end=end,
        missing_hours=as_hours(missing_steps[gap].sum()), n_gaps=int(gap.sum()),
        longest_gap_hours=as_hours(missing_steps[k]) if gap.any() else 0,
        longest_gap_start=pd.Timestamp(ns[k], tz="UTC") + dt if gap.any() else None,
        coverage=len(idx) / (int(round((end - start) / dt)) + 1),
    )


def _edges(name, e, *, nonneg=True):
    e = np.asarray(e, dtype=float)
    if e.ndim != 1 or e.size < 2 or not np.all(np.isfinite(e)) or not np.all(np.diff(e) > 0) \
            or (nonneg and e[0] < 0):
        raise InputError("bin edges must be a 1-D, finite, strictly increasing array of >= 2 "
                         "values" + (", >= 0" if nonneg else ""), field=name, value=e.tolist())
    return e


def _index(x, edges):
    """Bin index of x: [lower, upper) except the last bin, which is closed; -1 outside."""
    i = np.searchsorted(edges, x, side="right") - 1
    i[x == edges[-1]] = edges.size - 2
    i[(x < edges[0]) | (x > edges[-1])] = -1
    return i


def direction_bins(direction, dir_edges):
    """(bin index per record, -1 outside; bin centres [deg, 0-360)) of directions [deg]
    on direction edges spanning at most 360 deg, which may start below 0 (a sector
    centred on north): each direction is wrapped into the edges' span first."""
    de = np.asarray(dir_edges, float)
    d = de[0] + np.mod(np.asarray(direction, float) - de[0], 360.0)
    return _index(d, de), np.mod(0.5 * (de[1:] + de[:-1]), 360.0)


def bin_hindcast(series: pd.DataFrame, hs_edges, tz_edges, dir_edges=None, *,
                 outside="error") -> xr.Dataset:
    """Count the records of a hindcast into Hs-Tz(-direction) bins: the scatter Dataset.

    Bins are [lower, upper), the last one closed.  Records outside the bins raise
    InputError (outside="error", default) or, with outside="report", are left out of the
    table but counted in attrs ``n_outside`` (``n_records`` = all records, ``total`` =
    records binned).  dir_edges [deg] span at most 360 and may start below 0 (e.g. -22.5
    for a sector centred on north); directions are wrapped into that span.
    """
    if outside not in ("error", "report"):
        raise InputError("outside must be 'error' or 'report'", field="outside", value=outside)
    src = series.attrs.get("source")
    he, te = _edges("hs_edges", hs_edges), _edges("tz_edges", tz_edges)
    ih, it = _index(series["hs"].to_numpy(float), he), _index(series["tz"].to_numpy(float), te)
    shape, flat, out = (he.size - 1, te.size - 1), ih * (te.size - 1) + it, (ih < 0) | (it < 0)
    direction = None
    if dir_edges is not None:
        de = _edges("dir_edges", dir_edges, nonneg=False)
        if de[-1] - de[0] > 360 + 1e-9:
            raise InputError("direction bins span more than 360 deg", field="dir_edges", value=de.tolist())
        if "direction" not in series:
            raise InputError("series has no direction column", file=src, field="direction")
        no_dir = series["direction"].isna().to_numpy()
        if no_dir.all():
            raise InputError("no record of the series has a direction (every value missing)",
                             file=src, field="direction")
        if no_dir.any():            # one missing direction drops its hour, not the column
            series = series[~no_dir]
            ih, it = ih[~no_dir], it[~no_dir]
            flat, out = flat[~no_dir], out[~no_dir]
        idr, direction = direction_bins(series["direction"].to_numpy(float), de)
        shape, flat, out = shape + (de.size - 1,), flat * (de.size - 1) + idr, out | (idr < 0)
    n_out = int(out.sum())
    if n_out and outside == "error":
        k = int(np.flatnonzero(out)[0])
        row = series.iloc[k]
        raise InputError(f"{n_out} records lie outside the bins; first at {series.index[k]}; "
                         "widen the bin edges, or set the leg's hindcast.outside: report to "
                         "leave them out and count them",
                         file=src, field="bins", value={c: float(row[c]) for c in series.columns})
    counts = np.bincount(flat[~out], minlength=int(np.prod(shape))).reshape(shape)
    n_no_dir = int(no_dir.sum()) if dir_edges is not None else 0
    attrs = {"source": src or "", "sha256": series.attrs.get("sha256", ""), "layout": "hindcast",
             "hs_bins": "edges", "tz_bins": "edges", "n_records": len(series), "n_outside": n_out,
             "outside_policy": outside, "n_missing_direction": n_no_dir}
    if len(series):
        attrs.update(first_record=series.index[0].isoformat(), last_record=series.index[-1].isoformat())
        summary = record_summary(series)
        attrs.update(summary)
        lines = record_warnings(summary, src or "record") + list(series.attrs.get("warnings", []))
        if n_no_dir:
            lines.append(f"hindcast {src or 'record'}: {n_no_dir} record(s) without a wave "
                         "direction (missing-value code) left out of the direction-resolved "
                         "table, as gaps")
        attrs["warnings"] = "\n".join(lines)   # one a line
    return scatter_dataset(counts, hs_lower=he[:-1], hs_upper=he[1:], tz_lower=te[:-1], tz_upper=te[1:],
                           direction=direction, values_kind="counts", attrs=attrs, file=src)
