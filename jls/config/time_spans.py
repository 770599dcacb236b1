"""Time spans the configuration and the legs' files both state, compared when the
configuration is read (before any job).

* **A scatter table and the records it was binned from** (a leg's ``records.file``
  beside its ``scatter``): a table whose header states ``first_record`` and
  ``last_record`` (or ``years``, "1996-2005") must span the same hours as the records
  file, within :data:`SPAN_TOLERANCE` (the voyage plan sails the records and compares
  them with the table; from another period they describe another sea).
* **The season against the records**: ``operation.departure_rule.months`` names the
  departure months; the design check fits each leg's records in those months and the
  departure rule departs in them. A leg's record that holds no hour of those months
  (the voyage-plan job stopped on it, after the response datasets were written: "no sea
  state with a positive Hs and Tz to fit the design contour to", naming neither the
  months nor the key), or legs whose records leave no departure in them, are refused
  here naming the file, the key and both spans.
* **The voyage against the records' common span**: when every leg has records the
  departure rule needs a departure from which every leg's hours lie within its record
  (:func:`jls.assessment.route_hours.departure_range`, the job's own rule, applied to the
  records' first and last hours).

Spans come from what the readers already read at parse time: an hourly leg's binned
dataset (attributes ``first_record``, ``last_record``) and, for a table's records, the
first and last time of the records file (:func:`records_span`; the job reads it whole).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd

from jls.errors import InputError

#: Largest difference between a table's stated first or last record and its records' [h].
SPAN_TOLERANCE = pd.Timedelta("1h")
ALL_MONTHS = tuple(range(1, 13))


def _time(text: str):
    text = str(text).replace("UTC", "").strip()
    t = pd.to_datetime(text, format="%Y-%m-%d-%H", errors="coerce", utc=True)
    if pd.isna(t):
        t = pd.to_datetime(text, format="ISO8601", errors="coerce", utc=True)
    return None if pd.isna(t) else t


def records_span(path) -> tuple[pd.Timestamp, pd.Timestamp, int, int]:
    """(first time, last time, line of the first, line of the last) of an hourly records
    file (:func:`jls.sea.hindcast.read_hindcast` format: a column-name row, then
    ``time; hs; tz[; direction]`` lines); the job reads and checks it whole."""
    from jls.sea.scatter import read_utf8
    _, text = read_utf8(path, "hindcast")
    body = [(i, s) for i, s in enumerate((ln.strip() for ln in text.splitlines()), 1)
            if s and not s.startswith("#")]
    if len(body) < 2:
        raise InputError("hindcast has no records", file=str(path))
    (i0, first), (i1, last) = body[1], body[-1]
    t0, t1 = (_time(s.split(";")[0]) for s in (first, last))
    for t, i, s in ((t0, i0, first), (t1, i1, last)):
        if t is None:
            raise InputError(f"line {i}: unparsable time (YYYY-MM-DD-HH)", file=str(path),
                             field="time", value=s.split(";")[0])
    return t0, t1, i0, i1


def _months_in(first, last) -> set[int]:
    """Calendar months holding an hour between first and last (UTC)."""
    if last - first >= pd.Timedelta(days=366):
        return set(ALL_MONTHS)
    months = pd.period_range(first.tz_convert(None), last.tz_convert(None), freq="M").month
    return {int(m) for m in months}


def _fmt(t) -> str:
    return f"{pd.Timestamp(t):%Y-%m-%d %H:%M} UTC"


def _stated_span(attrs: dict):
    """(first, last, the header's words) a table states for its records, or None."""
    if "first_record" in attrs and "last_record" in attrs:
        a, b = _time(attrs["first_record"]), _time(attrs["last_record"])
        if a is not None and b is not None:
            return a, b, f"first_record {attrs['first_record']}, last_record {attrs['last_record']}"
    m = re.fullmatch(r"\s*(\d{4})\s*(?:-|to|–)?\s*(\d{4})?\s*", str(attrs.get("years", "")))
    if m:
        y0, y1 = int(m.group(1)), int(m.group(2) or m.group(1))
        return (pd.Timestamp(f"{y0}-01-01", tz="UTC"), pd.Timestamp(f"{y1}-12-31 23:00", tz="UTC"),
                f"years {attrs['years']}")
    return None


def leg_span(leg: dict, ds, base_dir=".") -> tuple | None:
    """(first, last, file, key) of the leg's hourly record, or None (a table only). A
    table whose header states its records' span is compared with its records file."""
    if "first_record" in ds.attrs and ("hindcast" in leg or "metocean" in leg or "spectra" in leg):
        kind = next(k for k in ("hindcast", "metocean", "spectra") if k in leg)
        return (_time(ds.attrs["first_record"]), _time(ds.attrs["last_record"]), leg[kind]["file"],
                f"legs[{leg['name']}].{kind}.file")
    if "records" not in leg:
        return None
    path = Path(base_dir) / leg["records"]["file"]
    if not path.is_file():
        return None                   # the voyage-plan job names the missing file
    first, last, i0, i1 = records_span(path)
    stated = _stated_span(ds.attrs)
    if stated is not None:
        a, b, words = stated
        if abs(a - first) > SPAN_TOLERANCE or abs(b - last) > SPAN_TOLERANCE:
            raise InputError(
                f"the table {leg['scatter']} states that its records run {_fmt(a)} to {_fmt(b)} "
                f"({words}), and its records file runs {_fmt(first)} (line {i0}) to {_fmt(last)} "
                f"(line {i1}): the two describe different periods; give the records the table was "
                f"binned from (the file given by legs[{leg['name']}].records.file)",
                file=str(leg["records"]["file"]), field="time", value=f"{_fmt(first)} to {_fmt(last)}")
    return first, last, leg["records"]["file"], f"legs[{leg['name']}].records.file"


def check_time_spans(cfg: dict, route: str, datasets: list, layers=(), base_dir=".") -> None:
    """Every check of the module docstring for one route; ``datasets``: the legs' tables
    as :func:`jls.sea.legs.read_leg` returned them, in sailing order. The error names the
    route, the leg, the leg's file and the configuration key that gives it."""
    from jls.config.naming import given_by, leg_error
    legs = cfg["routes"][route]["legs"]
    spans = []
    for i, (leg, ds) in enumerate(zip(legs, datasets)):
        try:
            spans.append(leg_span(leg, ds, base_dir))
        except InputError as exc:
            raise leg_error(exc, route, i, leg, layers) from None
    try:
        check_route_spans(cfg, route, spans, given_by("operation.departure_rule.months", layers))
    except _LegError as exc:
        raise leg_error(exc.error, route, exc.index, legs[exc.index], layers) from None


class _LegError(Exception):
    def __init__(self, error: InputError, index: int):
        super().__init__(str(error))
        self.error, self.index = error, index


def check_route_spans(cfg: dict, route: str, spans: list, months_given: str = "") -> None:
    """``spans``: per leg in sailing order, :func:`leg_span`'s tuple or None. Raises
    (:class:`_LegError`: the InputError and the leg's index) naming the leg's file, the
    key ``operation.departure_rule.months`` (set where ``months_given`` says) and both
    spans."""
    from jls.assessment.route_hours import leg_hours
    months = sorted(int(m) for m in cfg["operation"]["departure_rule"]["months"])
    field = "operation.departure_rule.months"
    given = f" ({months_given})" if months_given else ""
    legs = cfg["routes"][route]["legs"]
    for i, span in enumerate(spans):
        if span is None:
            continue
        first, last, file, key = span
        have = _months_in(first, last)
        if not have & set(months):
            raise _LegError(InputError(
                f"the leg's records ({file}) run {_fmt(first)} to {_fmt(last)}, months "
                f"{' '.join(map(str, sorted(have)))}, and hold no hour of the departure months "
                f"{field} {months}{given}: the design check fits the leg's sea states in those "
                f"months; give records that cover the season, or the season the records cover "
                f"(the file given by {key})", file=str(file), field=field, value=months), i)
    if any(s is None for s in spans):
        return                           # no departure simulation: the dataset says why
    hours = leg_hours([float(leg["duration_h"]) for leg in legs])
    off = np.concatenate([[0], np.cumsum(hours)[:-1]])
    step = pd.Timedelta("1h")
    first_dep = max(s[0] - int(o) * step for s, o in zip(spans, off))
    last_dep = min(s[1] - int(o + h - 1) * step for s, o, h in zip(spans, off, hours))
    if last_dep < first_dep:
        k = int(np.argmin([s[1] - int(o + h - 1) * step for s, o, h in zip(spans, off, hours)]))
        first, last, file, key = spans[k]
        raise _LegError(InputError(
            f"the voyage ({int(np.sum(hours))} h) cannot depart: departing at the earliest hour "
            f"every leg's record allows, {_fmt(first_dep)}, it needs the leg's record up to "
            f"{_fmt(first_dep + int(off[k] + hours[k] - 1) * step)}, and the record ({file}) ends "
            f"at {_fmt(last)}: give records of the legs over a common period (the file given by "
            f"{key})", file=str(file), field="time", value=f"{_fmt(first)} to {_fmt(last)}"), k)
    if not _months_in(first_dep, last_dep) & set(months):
        raise _LegError(InputError(
            f"the legs' records allow departures from {_fmt(first_dep)} to {_fmt(last_dep)} only, "
            f"months {' '.join(map(str, sorted(_months_in(first_dep, last_dep))))}, none of the "
            f"departure months {field} {months}{given}: the departure rule would sail no voyage"
            f" (the file given by {spans[0][3]})", file=str(spans[0][2]), field=field,
            value=months), 0)


__all__ = ["check_time_spans", "check_route_spans", "leg_span", "records_span", "SPAN_TOLERANCE"]
