"""Hourly wave forecasts as wave systems: the sea state of every forecast hour, from a
partitioned forecast (wind sea and swell: Hs, Tp, direction).

Formats (``FORMATS``):

* ``partitions-csv``: a CSV with the columns ``time, hs_wind, tp_wind, dir_wind, hs_swell,
  tp_swell, dir_swell``; times ISO 8601 with their UTC offset (``2026-01-05T00:00Z`` or
  ``+00:00``; another offset is converted to UTC, a time without one is refused); Hs in
  metres, Tp (peak period) in seconds, directions in degrees true, the direction the waves
  come FROM. Lines starting with ``#`` are comments; a comment ``# direction: to`` or
  ``# period: tz`` (anything but ``tp``) declares another convention and is refused. A
  system whose Hs is 0 is absent that hour.
* ``era5``: ECMWF's wave-model parameters (ERA5 or the forecast model's, the same names):
  ``shww, mpww, mdww`` (wind sea) and ``shts, mpts, mdts`` (total swell), read by
  :func:`jls.sea.metocean.read_era5_parameters` (units checked); their mean periods are Te
  (:mod:`jls.sea.periods`), turned into Tp by the JONSWAP relation of the system's gamma.
* ``ww3``: WAVEWATCH III point output with partitions ``phs<k>, ptp<k>, pdir<k>`` (k = 0
  the wind sea, k >= 1 swells), read by :func:`jls.sea.metocean.read_ww3_parameters`.

Every format gives a :class:`Forecast`: its hours (UTC, hourly, no gap, no duplicate) and
per hour the systems as :class:`jls.sea.sea_state.WaveSystem` (JONSWAP, the gamma of its
kind, the spreading of its kind: the configuration's ``sea.gamma`` and ``sea.spreading``
unless given). Bad files fail with the file, the column or line, and the value: a missing
or duplicated hour, a time without offset, a direction column in radians (every value
within 0-2 pi and not all whole), a period column of another kind than Tp.
"""

from __future__ import annotations

import hashlib
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from jls.errors import InputError
from jls.sea import periods
from jls.sea.sea_state import WaveSystem, parse_spreading

__all__ = ["FORMATS", "CSV_COLUMNS", "Forecast", "read_forecast", "forecast_systems"]

FORMATS = ("partitions-csv", "era5", "ww3")
CSV_COLUMNS = ("time", "hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell")
KINDS = ("wind", "swell")
MAX_BYTES = 50_000_000
_OTHER_PERIODS = ("tz", "tm01", "tm02", "te", "tm", "t01", "t02", "tm10", "mwp", "period")


@dataclass(frozen=True)
class Forecast:
    """``times`` (n,) UTC hourly; ``hs``, ``tp``, ``dir_from`` (n, n_systems) with NaN or 0
    where a system is absent; ``kinds`` (n_systems,) wind or swell; ``file``, ``sha256``."""

    file: str
    format: str
    sha256: str
    times: pd.DatetimeIndex
    kinds: tuple
    hs: np.ndarray
    tp: np.ndarray
    dir_from: np.ndarray


def _check_file(path) -> Path:
    p = Path(path)
    if not str(path).strip():
        raise InputError("no forecast file given", field="FILE", value=str(path))
    if not p.is_file():
        raise InputError("no such file (or not a regular file)", file=path)
    size = p.stat().st_size
    if size > MAX_BYTES:
        raise InputError(f"a forecast file is at most {MAX_BYTES / 1e6:g} MB", file=path, value=size)
    return p


def _utc_times(texts, file, first_line):
    out = []
    for k, t in enumerate(texts):
        s = str(t).strip()
        try:
            ts = pd.Timestamp(s)
        except (ValueError, TypeError):
            raise InputError("not an ISO 8601 time", file=file, field=f"line {first_line + k}, column time",
                             value=s) from None
        if ts.tzinfo is None:
            raise InputError("a time without its UTC offset (write e.g. 2026-01-05T00:00Z)", file=file,
                             field=f"line {first_line + k}, column time", value=s)
        out.append(ts.tz_convert("UTC"))
    return pd.DatetimeIndex(out, name="time")


def _check_hours(times, file, where):
    """Hourly, increasing, no duplicate and no gap."""
    if len(times) < 1:
        raise InputError("the forecast has no hour", file=file)
    if np.any(times.minute != 0) or np.any(times.second != 0):
        k = int(np.flatnonzero((times.minute != 0) | (times.second != 0))[0])
        raise InputError("forecast times are whole hours", file=file, field=where(k), value=str(times[k]))
    step = np.asarray((times[1:] - times[:-1]).total_seconds(), float) / 3600.0
    for k, d in enumerate(step):
        if d == 1:
            continue
        what = ("a duplicated hour" if d == 0 else "times out of order" if d < 0
                else f"{d - 1:g} missing hour{'s' if d > 2 else ''} after {times[k].isoformat()}")
        raise InputError(f"the forecast must be hourly without gaps: {what}", file=file, field=where(k + 1),
                         value=times[k + 1].isoformat())


def _check_directions(values, file, column):
    v = values[np.isfinite(values)]
    if v.size and v.max() <= 2 * math.pi + 1e-9 and np.any(np.abs(v - np.round(v)) > 1e-6):
        raise InputError("directions look like radians (all within 0-2 pi with fractions); give degrees "
                         "true, the direction the waves come from", file=file, field=column,
                         value=float(v.max()))
    bad = np.isfinite(values) & ((values < 0) | (values > 360))
    if bad.any():
        raise InputError("a direction is in degrees, 0-360 (from, true)", file=file, field=column,
                         value=float(values[bad][0]))


def _read_csv(path) -> Forecast:
    file = str(path)
    raw = _check_file(path).read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError("not UTF-8 text", file=file) from None
    lines = text.splitlines()
    header, first = None, 0
    for i, line in enumerate(lines):
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            m = re.match(r"#\s*([A-Za-z_ ]+?)\s*:\s*(.+)$", s)
            if m:
                key, val = m.group(1).strip().lower(), m.group(2).strip().lower()
                if key in ("direction", "directions", "direction_convention") and val not in ("from", "coming from"):
                    raise InputError("this format takes directions the waves come FROM (degrees true)",
                                     file=file, field=f"line {i + 1}, {key}", value=val)
                if key in ("period", "periods") and val not in ("tp", "peak"):
                    raise InputError("this format takes the peak period Tp of each system", file=file,
                                     field=f"line {i + 1}, {key}", value=val)
                if key in ("timezone", "time_zone", "tz") and val not in ("utc", "z", "+00:00"):
                    raise InputError("forecast times are UTC (or carry their offset)", file=file,
                                     field=f"line {i + 1}, {key}", value=val)
            continue
        header, first = [c.strip().lower() for c in s.split(",")], i + 1
        break
    if header is None:
        raise InputError("no header line", file=file)
    for c in header:
        kind = c.rsplit("_", 1)
        if len(kind) == 2 and kind[0] in _OTHER_PERIODS and kind[1] in KINDS:
            raise InputError("a period column of another kind than the peak period: this format takes "
                             f"tp_{kind[1]}", file=file, field=f"line {first}, column {c}", value=c)
    missing = [c for c in CSV_COLUMNS if c not in header]
    if missing:
        raise InputError(f"missing column{'s' if len(missing) > 1 else ''} {', '.join(missing)} (expected "
                         f"{', '.join(CSV_COLUMNS)})", file=file, field=f"line {first}, header",
                         value=",".join(header))
    rows = [(first + 1 + k, r) for k, r in enumerate(lines[first:]) if r.strip() and not r.lstrip().startswith("#")]
    cells = [[x.strip() for x in r.split(",")] for _, r in rows]
    for (n, _), c in zip(rows, cells):
        if len(c) != len(header):
            raise InputError(f"{len(c)} fields where the header has {len(header)}", file=file,
                             field=f"line {n}", value=",".join(c))
    line_of = [n for n, _ in rows]
    col = {name: [c[header.index(name)] for c in cells] for name in CSV_COLUMNS}
    times = _utc_times(col["time"], file, line_of[0] if line_of else first + 1)
    _check_hours(times, file, lambda k: f"line {line_of[k]}, column time")
    data = {}
    for name in CSV_COLUMNS[1:]:
        vals = np.empty(len(rows))
        for k, s in enumerate(col[name]):
            try:
                vals[k] = float(s) if s else np.nan
            except ValueError:
                raise InputError("not a number", file=file, field=f"line {line_of[k]}, column {name}",
                                 value=s) from None
            if s and not math.isfinite(vals[k]):
                raise InputError("not a finite number", file=file, field=f"line {line_of[k]}, column {name}",
                                 value=s)
        data[name] = vals
    for kind in KINDS:
        hs, tp, d = data[f"hs_{kind}"], data[f"tp_{kind}"], data[f"dir_{kind}"]
        _check_directions(d, file, f"dir_{kind}")
        for name, v, lo, hi in ((f"hs_{kind}", hs, 0.0, 30.0), (f"tp_{kind}", tp, 0.0, 40.0)):
            bad = np.isfinite(v) & ((v < lo) | (v > hi) | ((v <= 0) & name.startswith("tp")))
            if bad.any():
                k = int(np.flatnonzero(bad)[0])
                raise InputError(f"outside {lo:g}-{hi:g} {'m' if name.startswith('hs') else 's'}", file=file,
                                 field=f"line {line_of[k]}, column {name}", value=float(v[k]))
        present = np.isfinite(hs) & (hs > 0)
        lack = present & ~(np.isfinite(tp) & np.isfinite(d))
        if lack.any():
            k = int(np.flatnonzero(lack)[0])
            which = f"tp_{kind}" if not np.isfinite(tp[k]) else f"dir_{kind}"
            raise InputError(f"a {kind} system with Hs {hs[k]:g} m has no {which.split('_')[0]}", file=file,
                             field=f"line {line_of[k]}, column {which}", value=col[which][k])
        blank = ~np.isfinite(hs)
        if blank.any():
            k = int(np.flatnonzero(blank)[0])
            raise InputError(f"a missing {kind} Hs (write 0 for no {kind} system)", file=file,
                             field=f"line {line_of[k]}, column hs_{kind}", value=col[f"hs_{kind}"][k])
    stack = lambda p: np.stack([data[f"{p}_{k}"] for k in KINDS], axis=1)  # noqa: E731
    return Forecast(file, "partitions-csv", hashlib.sha256(raw).hexdigest(), times, KINDS,
                    stack("hs"), stack("tp"), stack("dir"))


def _read_netcdf(path, fmt, gamma) -> Forecast:
    from jls.sea import metocean
    file = str(path)
    p = _check_file(path)
    df = metocean.read_era5_parameters(p) if fmt == "era5" else metocean.read_ww3_parameters(p)
    times = pd.DatetimeIndex(df.index, name="time")
    _check_hours(times, file, lambda k: f"time {k}")
    if fmt == "era5":
        need = ("wind_hs", "wind_te", "wind_direction", "swell_hs", "swell_te", "swell_direction")
        missing = [c for c in need if c not in df.columns]
        if missing:
            raise InputError("an ERA5 forecast needs the wind-sea and swell partitions (shww, mpww, mdww, "
                             "shts, mpts, mdts)", file=file, field="partitions", value=missing)
        parts = [(k, df[f"{k}_hs"].to_numpy(float), df[f"{k}_te"].to_numpy(float),
                  df[f"{k}_direction"].to_numpy(float)) for k in KINDS]
        out = []
        for kind, hs, te, d in parts:
            tp = np.full_like(te, np.nan)
            ok = np.isfinite(te) & (te > 0)
            tp[ok] = [periods.tp_from_period("jonswap", "te", float(t), gamma=gamma[kind]) for t in te[ok]]
            out.append((kind, hs, tp, d))
    else:
        ks = sorted({int(c[1:].split("_")[0]) for c in df.columns if re.match(r"p\d+_hs$", c)})
        if not ks:
            raise InputError("a WAVEWATCH III forecast needs its partitions (phs<k>, ptp<k>, pdir<k>)",
                             file=file, field="partitions", value=sorted(df.columns))
        out = []
        for k in ks:
            cols = [f"p{k}_{f}" for f in ("hs", "tp", "direction")]
            if any(c not in df.columns for c in cols):
                raise InputError(f"partition {k} lacks one of phs{k}, ptp{k}, pdir{k}", file=file,
                                 field=f"partition {k}", value=[c for c in cols if c not in df.columns])
            out.append(("wind" if k == 0 else "swell", *(df[c].to_numpy(float) for c in cols)))
    for kind, hs, tp, d in out:
        _check_directions(d, file, f"{kind} direction")
        gap = ~np.isfinite(hs)
        if gap.any():
            k = int(np.flatnonzero(gap)[0])
            raise InputError(f"a missing {kind} Hs: a forecast hour without its sea state", file=file,
                             field=f"{kind} hs at {times[k].isoformat()}", value=float(hs[k]))
    hs = np.stack([o[1] for o in out], axis=1)
    tp = np.stack([o[2] for o in out], axis=1)
    d = np.stack([o[3] for o in out], axis=1)
    lack = (hs > 0) & ~(np.isfinite(tp) & np.isfinite(d))
    if lack.any():
        k, j = (int(x[0]) for x in np.nonzero(lack))
        raise InputError("a wave system without its period or direction", file=file,
                         field=f"{out[j][0]} at {times[k].isoformat()}", value=float(hs[k, j]))
    return Forecast(file, fmt, df.attrs["sha256"], times, tuple(o[0] for o in out), hs, tp, d)


def read_forecast(path, fmt: str, *, gamma: dict) -> Forecast:
    """The :class:`Forecast` of ``path`` in format ``fmt`` (:data:`FORMATS`); ``gamma``:
    {"wind": .., "swell": ..}, the JONSWAP gamma of each kind (ERA5's mean periods are
    turned into Tp with it)."""
    if fmt not in FORMATS:
        raise InputError(f"unknown forecast format (known: {', '.join(FORMATS)})", file=path, field="--format",
                         value=fmt)
    if fmt == "partitions-csv":
        return _read_csv(path)
    return _read_netcdf(path, fmt, gamma)


def forecast_systems(fc: Forecast, hour: int, *, gamma: dict, spreading: dict) -> list[WaveSystem]:
    """The wave systems of forecast hour ``hour`` (index): JONSWAP with the gamma and the
    spreading of their kind; a system of zero Hs is left out (an hour of no sea has none)."""
    out = []
    for j, kind in enumerate(fc.kinds):
        hs = float(fc.hs[hour, j])
        if hs > 0:
            out.append(WaveSystem("jonswap", hs, float(fc.tp[hour, j]), float(fc.dir_from[hour, j]) % 360.0,
                                  parse_spreading(spreading[kind], f"sea.spreading.{kind}"), kind,
                                  float(gamma[kind])))
    return out
