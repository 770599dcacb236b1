"""Hourly records of wave partitions (wind sea and swell systems) and the sea states they
make: the CSV format ``partitions``, and the partition variables of ERA5 and WW3
(:mod:`jls.sea.metocean`).

**CSV** (``format: partitions``): a header row and one row per hour::

    time, hs_wind, tp_wind, dir_wind, hs_swell, tp_swell, dir_swell
    2019-02-06T00:00Z, 1.2, 6.5, 240, 0.8, 14.0, 300

time UTC (ISO 8601), Hs [m], Tp [s] (the PEAK period of each partition), direction [deg
true, from]. A column may carry its unit in parentheses (``dir_wind (deg)``). Refused with
the file, column and value: a missing partition column; a direction in radians (a unit
``rad``, or a whole column within 0-2 pi while the waves come from all around: a record of
24 hours or more whose largest direction is below 2 pi); a period column of another kind
(``tz_wind``, ``te_swell``, ``tm01_...``: the format reads Tp); a partition with Hs > 0 and
no period or direction. An hour without any value is a gap.

**ERA5** gives each partition's Hs, its mean period Te (``mpww``, ``mpts``, Tm-10) and its
mean direction; Te is turned into Tp with the JONSWAP relation of the leg's gamma
(:func:`jls.sea.periods.tp_from_period`). **WW3** gives ``phs<k>, ptp<k>, pdir<k>``
(partition 0: the wind sea, the others swells) with Tp as it is.

Every partition is a JONSWAP system of the leg's gamma (the wind sea and the swells alike),
spread by the leg's spreading of its kind (:class:`jls.sea.sea_state.WaveSystem`).
:func:`directional_spectra` lays the hours' systems out as E(t, f, dir) on a geometric
frequency grid and a 10-deg direction grid, the input of the measured-spectrum machinery
(:mod:`jls.response.directional`).
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.sea.directional import direction_widths
from jls.sea.measured import spectra_array
from jls.sea.periods import tp_from_period
from jls.sea.scatter import read_utf8
from jls.sea.sea_state import DIRECTIONS, SeaState, WaveSystem, parse_spreading

__all__ = ["PARTITION_COLUMNS", "read_partitions", "partition_frame", "sea_states", "directional_spectra",
           "FREQ_HZ", "DIRS_DEG"]

PARTITION_COLUMNS = ("hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell")
#: frequency grid of the laid-out spectra [Hz]: 1 % steps from 0.02 to 1 Hz
FREQ_HZ = 0.02 * 1.01 ** np.arange(int(np.ceil(np.log(50.0) / np.log(1.01))) + 1)
DIRS_DEG = np.arange(DIRECTIONS) * (360.0 / DIRECTIONS)
_OTHER = {"tz": "the zero-up-crossing period Tz", "tm02": "the zero-up-crossing period Tz",
          "te": "the energy period Te", "tm10": "the energy period Te", "tm01": "the mean period Tm01",
          "t01": "the mean period Tm01", "tm": "a mean period"}


def _columns(header, file):
    names, units = [], []
    for raw in header:
        m = re.match(r"^\s*([^()]*?)\s*(?:\(([^)]*)\))?\s*$", raw)
        names.append(m.group(1).strip().lower())
        units.append((m.group(2) or "").strip().lower())
    if not names or names[0] != "time":
        raise InputError("the first column of a partitions file is time", file=file, field="header",
                         value=header[0] if header else "")
    for name, unit in zip(names, units):
        kind, _, part = name.partition("_")
        if part in ("wind", "swell") and kind in _OTHER:
            raise InputError(f"column {name} is {_OTHER[kind]}; the partitions format reads each "
                             f"partition's peak period tp_{part}: convert it", file=file, field=name, value=name)
        if kind == "dir" and unit.startswith("rad"):
            raise InputError("directions in radians: jls reads degrees (from, true)", file=file,
                             field=name, value=unit)
    missing = [c for c in PARTITION_COLUMNS if c not in names]
    if missing:
        raise InputError("missing partition column(s) " + ", ".join(missing) + " (a partitions file has "
                         + ", ".join(("time",) + PARTITION_COLUMNS) + ")", file=file, field=missing[0],
                         value=names)
    return names


def read_partitions(path) -> pd.DataFrame:
    """The partitions CSV (module docstring) -> frame indexed by UTC time with the columns
    :data:`PARTITION_COLUMNS`; attrs source, sha256, path, format."""
    file = str(path)
    raw, text = read_utf8(path, "partitions")
    lines = [(i, s) for i, s in enumerate(text.splitlines(), 1) if s.strip() and not s.startswith("#")]
    if len(lines) < 2:
        raise InputError("a partitions file needs a header row and records", file=file)
    names = _columns([c for c in lines[0][1].split(",")], file)
    rows = [[c.strip() for c in s.split(",")] for _, s in lines[1:]]
    bad = [k for k, r in enumerate(rows) if len(r) != len(names)]
    if bad:
        k = bad[0]
        raise InputError(f"expected {len(names)} fields, got {len(rows[k])}", file=file,
                         field=f"line {lines[k + 1][0]}", value=lines[k + 1][1])
    df = pd.DataFrame(rows, columns=names)
    time = pd.to_datetime(df["time"], utc=True, format="ISO8601", errors="coerce")
    if time.isna().any():
        k = int(np.flatnonzero(time.isna())[0])
        raise InputError("unparsable time (ISO 8601, UTC)", file=file, field=f"line {lines[k + 1][0]}",
                         value=df["time"][k])
    out = pd.DataFrame(index=pd.DatetimeIndex(time, name="time"))
    for c in PARTITION_COLUMNS:
        v = pd.to_numeric(df[c].replace("", np.nan), errors="coerce").to_numpy(float)
        unparsable = np.isnan(v) & (df[c].replace("", np.nan).notna().to_numpy())
        if unparsable.any():
            k = int(np.flatnonzero(unparsable)[0])
            raise InputError("not a number", file=file, field=f"{c}, line {lines[k + 1][0]}", value=df[c][k])
        out[c] = v
    if np.any(np.diff(out.index.asi8) <= 0):
        k = int(np.flatnonzero(np.diff(out.index.asi8) <= 0)[0]) + 1
        raise InputError("times not strictly increasing", file=file, field=f"line {lines[k + 1][0]}",
                         value=str(out.index[k]))
    out.attrs.update(source=Path(file).name, sha256=hashlib.sha256(raw).hexdigest(), path=file,
                     format="partitions")
    _check(out, file, lambda k: f"line {lines[k + 1][0]}")
    return out


def _check(df, file, where):
    """Ranges of the partition columns, radians, and partitions without period or direction."""
    for c in PARTITION_COLUMNS:
        v = df[c].to_numpy(float)
        kind = c.split("_")[0]
        lo, hi = {"hs": (0.0, 30.0), "tp": (0.0, 40.0), "dir": (0.0, 360.0)}[kind]
        bad = np.isfinite(v) & ((v < lo) | (v > hi) | ((v <= 0) & (kind == "tp")))
        if bad.any():
            k = int(np.flatnonzero(bad)[0])
            raise InputError(f"{c} outside {lo:g}-{hi:g} {dict(hs='m', tp='s', dir='deg')[kind]}",
                             file=file, field=f"{c}, {where(k)}", value=float(v[k]))
        if kind == "dir":
            ok = v[np.isfinite(v)]
            if ok.size >= 24 and ok.max() <= 2 * np.pi and np.unique(np.round(ok, 3)).size > 3:
                raise InputError("every direction lies within 0-2 pi: radians? jls reads degrees "
                                 "(from, true)", file=file, field=c, value=float(ok.max()))
    for part in ("wind", "swell"):
        hs, tp, d = (df[f"{k}_{part}"].to_numpy(float) for k in ("hs", "tp", "dir"))
        bad = np.isfinite(hs) & (hs > 0) & ~(np.isfinite(tp) & np.isfinite(d))
        if bad.any():
            k = int(np.flatnonzero(bad)[0])
            col = f"tp_{part}" if not np.isfinite(tp[k]) else f"dir_{part}"
            raise InputError(f"a {part} partition with Hs > 0 needs its period and direction",
                             file=file, field=f"{col}, {where(k)}", value=None)


def partition_frame(df: pd.DataFrame, fmt: str, gamma: float, file=None) -> pd.DataFrame:
    """The partitions of a metocean frame (:func:`jls.sea.metocean.read_metocean`) or of a
    partitions CSV as columns hs_<p>, tp_<p>, dir_<p> with p = wind, swell (ERA5), or wind,
    swell, swell2 ... (WW3 partition 0 is the wind sea). ERA5's Te is turned into Tp by the
    JONSWAP relation of ``gamma``. A missing partition is refused naming its variable."""
    if fmt == "partitions":
        return df
    out = pd.DataFrame(index=df.index)
    if fmt == "era5":
        ratio = tp_from_period("jonswap", "te", 1.0, gamma=float(gamma))
        for part, var in (("wind", "shww/mpww/mdww"), ("swell", "shts/mpts/mdts")):
            cols = [f"{part}_hs", f"{part}_te", f"{part}_direction"]
            miss = [c for c in cols if c not in df.columns]
            if miss:
                raise InputError(f"the {part} partition is missing ({var} needed)", file=file,
                                 field=miss[0], value=sorted(df.columns))
            out[f"hs_{part}"], out[f"tp_{part}"], out[f"dir_{part}"] = (
                df[cols[0]], df[cols[1]] * ratio, df[cols[2]])
        out.attrs["period_conversion"] = f"Tp = {ratio:.4f} x Te of each partition (JONSWAP, gamma {gamma:g})"
    elif fmt == "ww3":
        ks = sorted({int(c[1:].split("_")[0]) for c in df.columns if re.match(r"^p\d+_hs$", c)})
        if 0 not in ks or len(ks) < 2:
            raise InputError("WW3 partitions need phs0 (the wind sea) and at least one swell (phs1)",
                             file=file, field="phs0" if 0 not in ks else "phs1", value=sorted(df.columns))
        for k in ks:
            name = "wind" if k == 0 else ("swell" if k == 1 else f"swell{k}")
            for a, b in (("hs", "hs"), ("tp", "tp"), ("dir", "direction")):
                if f"p{k}_{b}" not in df.columns:
                    raise InputError(f"partition {k} has no {b}", file=file, field=f"p{k}_{b}", value=None)
                out[f"{a}_{name}"] = df[f"p{k}_{b}"]
        out.attrs["period_conversion"] = "Tp of each partition as given"
    else:
        raise InputError("partitions come from a partitions CSV, ERA5 or WW3", file=file, field="format", value=fmt)
    out.attrs.update({k: v for k, v in df.attrs.items() if k in ("source", "sha256", "path")}, format=fmt)
    return out


def _parts(frame):
    return [c[3:] for c in frame.columns if c.startswith("hs_")]


def sea_states(frame: pd.DataFrame, *, gamma: float, spreading: dict) -> tuple[list, np.ndarray]:
    """(sea states, kept): one :class:`SeaState` per hour with any partition of Hs > 0 (the
    rest are gaps, ``kept`` False); each partition a JONSWAP of ``gamma`` spread by
    ``spreading[kind]`` (kind: wind for the wind partition, swell for the others)."""
    parts = _parts(frame)
    spreads = {p: parse_spreading(spreading["wind" if p == "wind" else "swell"], f"spreading.{p}") for p in parts}
    vals = {p: frame[[f"hs_{p}", f"tp_{p}", f"dir_{p}"]].to_numpy(float) for p in parts}
    out, kept = [], np.zeros(len(frame), bool)
    for t in range(len(frame)):
        systems = []
        for p in parts:
            hs, tp, d = vals[p][t]
            if np.isfinite(hs) and hs > 0 and np.isfinite(tp) and np.isfinite(d):
                systems.append(WaveSystem("jonswap", float(hs), float(tp), float(d) % 360.0, spreads[p],
                                          "wind" if p == "wind" else "swell", float(gamma)))
        if systems:
            out.append(SeaState(tuple(systems)))
            kept[t] = True
    return out, kept


def directional_spectra(states, times, *, freq=FREQ_HZ, dirs=DIRS_DEG, attrs=None) -> xr.DataArray:
    """E(t, f, dir) [m^2/(Hz deg)] of the sea states on ``freq`` [Hz] x ``dirs`` [deg, from]:
    each system's S(omega) 2 pi times its spreading on the grid (normalised there to sum 1;
    a long-crested system in its nearest bin)."""
    f = np.asarray(freq, float)
    d = np.asarray(dirs, float)
    width = direction_widths(d)
    E = np.zeros((len(states), f.size, d.size))
    for k, s in enumerate(states):
        for sys in s.systems:
            if sys.spreading.long_crested:
                D = np.zeros(d.size)
                i = int(np.argmin(np.abs(np.mod(d - sys.from_deg + 180.0, 360.0) - 180.0)))
                D[i] = 1.0
            else:
                D = sys.spreading.density(d - sys.from_deg) * width
                D = D / D.sum()
            E[k] += (2 * np.pi * sys.spectrum(2 * np.pi * f))[:, None] * (D / width)[None, :]
    return spectra_array(E, times, f, d, attrs=attrs or {})
