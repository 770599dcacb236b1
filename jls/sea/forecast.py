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

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from jls.errors import InputError
from jls.sea.sea_state import WaveSystem, parse_spreading

__all__ = ["FORMATS", "CSV_COLUMNS", "Forecast", "read_forecast", "forecast_systems"]

FORMATS = ("partitions-csv", "era5", "ww3", "spectra")
SPECTRA_FORMATS = ("ww3", "era5", "ndbc")
CSV_COLUMNS = ("time", "hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell")
KINDS = ("wind", "swell")
MAX_BYTES = 50_000_000
_OTHER_PERIODS = ("tz", "tm01", "tm02", "te", "tm", "t01", "t02", "tm10", "mwp", "period")


@dataclass(frozen=True)
class Forecast:
    """``times`` (n,) UTC hourly; ``hs``, ``tp``, ``dir_from`` (n, n_systems) with NaN or 0
    where a system is absent; ``kinds`` (n_systems,) wind or swell; ``file``, ``sha256``.
    A directional spectra forecast has one long-crested measured system per direction bin:
    kinds "measured", ``omega`` (n_w,) [rad/s] and ``density`` (n, n_systems, n_w) [m^2 s/rad]
    of each bin (its width included)."""

    file: str
    format: str
    sha256: str
    times: pd.DatetimeIndex
    kinds: tuple
    hs: np.ndarray
    tp: np.ndarray
    dir_from: np.ndarray
    omega: np.ndarray | None = None
    density: np.ndarray | None = None


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


def _declarations(text, file):
    """The line of the header row, after refusing header comments that declare a
    convention this format does not take (``# direction: to``, ``# period: tz``, a time
    zone other than UTC)."""
    for i, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        if not s:
            continue
        if not s.startswith("#"):
            return i
        m = re.match(r"#\s*([A-Za-z_ ]+?)\s*:\s*(.+)$", s)
        if not m:
            continue
        key, val = m.group(1).strip().lower(), m.group(2).strip().lower()
        if key in ("direction", "directions", "direction_convention") and val not in ("from", "coming from"):
            raise InputError("this format takes directions the waves come FROM (degrees true)",
                             file=file, field=f"line {i}, {key}", value=val)
        if key in ("period", "periods") and val not in ("tp", "peak"):
            raise InputError("this format takes the peak period Tp of each system", file=file,
                             field=f"line {i}, {key}", value=val)
        if key in ("timezone", "time_zone", "tz") and val not in ("utc", "z", "+00:00"):
            raise InputError("forecast times are UTC (or carry their offset)", file=file,
                             field=f"line {i}, {key}", value=val)
    raise InputError("no header line", file=file)


def _frame(path, fmt, gamma):
    """(partition frame with columns hs_<p>, tp_<p>, dir_<p>; where each hour is in the
    file) of a forecast, read by :mod:`jls.sea.partitions` (the legs' reader) after the
    checks only a forecast needs: the declarations, and times with their UTC offset."""
    from jls.sea import metocean, partitions
    file = str(path)
    p = _check_file(path)
    if fmt == "partitions-csv":
        try:
            text = p.read_bytes().decode("utf-8")
        except UnicodeDecodeError:
            raise InputError("not UTF-8 text", file=file) from None
        header_line = _declarations(text, file)
        rows = [(i, s) for i, s in enumerate(text.splitlines(), 1)
                if i > header_line and s.strip() and not s.lstrip().startswith("#")]
        for i, s in rows:
            stamp = s.split(",", 1)[0].strip()
            try:
                naive = pd.Timestamp(stamp).tzinfo is None
            except (ValueError, TypeError):
                raise InputError("not an ISO 8601 time", file=file, field=f"line {i}, column time",
                                 value=stamp) from None
            if naive:
                raise InputError("a time without its UTC offset (write e.g. 2026-01-05T00:00Z)", file=file,
                                 field=f"line {i}, column time", value=stamp)
        return partitions.read_partitions(p), [f"line {i}, column time" for i, _ in rows]
    if gamma["wind"] != gamma["swell"]:
        raise InputError("ERA5's mean periods are turned into Tp with one gamma for every partition",
                         file=file, field="gamma", value=gamma)
    df = metocean.read_era5_parameters(p) if fmt == "era5" else metocean.read_ww3_parameters(p)
    frame = partitions.partition_frame(df, fmt, gamma["wind"], file=file)
    return frame, [f"time {t.isoformat()}" for t in df.index]


def _read_spectra(path, spectra_format) -> Forecast:
    """A directional spectra forecast (:func:`jls.sea.measured.read_spectra`): each hour's
    E(f, dir) as one long-crested measured system per direction bin (its share of the
    spectrum, the bin's width included), so that the response integrates the measured
    directions; a 1-D spectrum (no directions) is refused."""
    from jls.sea.directional import direction_widths
    from jls.sea.measured import read_spectra
    file = str(path)
    if spectra_format not in SPECTRA_FORMATS:
        raise InputError(f"unknown spectra format (known: {', '.join(SPECTRA_FORMATS)})", file=file,
                         field="--spectra-format", value=spectra_format)
    efth = read_spectra(_check_file(path), spectra_format)
    if "dir" not in efth.dims:
        raise InputError("a forecast spectrum without directions cannot be met at the vessel's heading: give "
                         "a directional spectrum or the partitions", file=file, field="dir", value=dict(efth.sizes))
    times = pd.DatetimeIndex(pd.to_datetime(efth["time"].values), name="time").tz_localize("UTC")
    _check_hours(times, file, lambda k: f"record {k} ({times[k].isoformat()})")
    f, d = efth["freq"].values.astype(float), efth["dir"].values.astype(float)
    E = efth.transpose("time", "dir", "freq").values.astype(float)
    bad = ~np.isfinite(E)
    if bad.any():
        k = int(np.flatnonzero(bad.any(axis=(1, 2)))[0])
        raise InputError("a missing value in the spectrum", file=file, field=f"record {times[k].isoformat()}",
                         value="NaN")
    omega = 2 * np.pi * f
    density = E * direction_widths(d)[None, :, None] / (2 * np.pi)          # m^2 s/rad per bin
    m0 = np.trapezoid(density, omega, axis=-1)
    hs = 4.0 * np.sqrt(np.clip(m0, 0.0, None))
    tp = 2 * np.pi / omega[np.argmax(density, axis=-1)]
    n = len(times)
    kinds = tuple(f"measured from {v:g}" for v in np.mod(d, 360.0))
    return Forecast(file, "spectra", str(efth.attrs.get("sha256", "")), times, kinds, hs, tp,
                    np.broadcast_to(np.mod(d, 360.0), (n, d.size)).copy(), omega, density)


def read_forecast(path, fmt: str, *, gamma: dict, spectra_format: str = "ww3") -> Forecast:
    """The :class:`Forecast` of ``path`` in format ``fmt`` (:data:`FORMATS`); ``gamma``:
    {"wind": .., "swell": ..}, the JONSWAP gamma of each kind (ERA5's mean periods are
    turned into Tp with it); ``spectra_format``: the reader of a ``spectra`` forecast."""
    if fmt not in FORMATS:
        raise InputError(f"unknown forecast format (known: {', '.join(FORMATS)})", file=path, field="--format",
                         value=fmt)
    if fmt == "spectra":
        return _read_spectra(path, spectra_format)
    file = str(path)
    frame, where = _frame(path, fmt, gamma)
    times = pd.DatetimeIndex(frame.index, name="time").tz_convert("UTC")
    _check_hours(times, file, lambda k: where[k])
    parts = [c[3:] for c in frame.columns if c.startswith("hs_")]
    hs, tp, d = (np.stack([frame[f"{x}_{k}"].to_numpy(float) for k in parts], axis=1) for x in ("hs", "tp", "dir"))
    for j, part in enumerate(parts):
        _check_directions(d[:, j], file, f"dir_{part}")
        gap = ~np.isfinite(hs[:, j])
        if gap.any():
            k = int(np.flatnonzero(gap)[0])
            raise InputError(f"a missing {part} Hs: a forecast hour without its sea state (write 0 for no "
                             f"{part} system)", file=file, field=f"{where[k]}, hs_{part}", value=None)
    return Forecast(file, fmt, str(frame.attrs.get("sha256", "")), times,
                    tuple("wind" if k == "wind" else "swell" for k in parts), hs, tp, d)


def forecast_systems(fc: Forecast, hour: int, *, gamma: dict, spreading: dict) -> list[WaveSystem]:
    """The wave systems of forecast hour ``hour`` (index): JONSWAP with the gamma and the
    spreading of their kind; a system of zero Hs is left out (an hour of no sea has none)."""
    out = []
    if fc.density is not None:                       # a directional spectrum: a system per bin
        long = parse_spreading("long-crested")
        for j in np.flatnonzero(fc.hs[hour] > 0):
            out.append(WaveSystem("measured", float(fc.hs[hour, j]), float(fc.tp[hour, j]),
                                  float(fc.dir_from[hour, j]), long, "swell", 1.0, fc.omega, fc.density[hour, j]))
        return out
    for j, kind in enumerate(fc.kinds):
        hs = float(fc.hs[hour, j])
        if hs > 0:
            out.append(WaveSystem("jonswap", hs, float(fc.tp[hour, j]), float(fc.dir_from[hour, j]) % 360.0,
                                  parse_spreading(spreading[kind], f"sea.spreading.{kind}"), kind,
                                  float(gamma[kind])))
    return out
