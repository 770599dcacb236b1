"""The hourly record of a route leg, whatever file gives it.

A leg's wave statistics come from one of four keys (the configuration's ``routes``):

========== ===================================================== ===========================
key        file                                                  hourly record
========== ===================================================== ===========================
scatter    scatter table CSV (:mod:`jls.sea.scatter`)             none
hindcast   two/three-column text (:mod:`jls.sea.hindcast`)        (Hs, Tz[, direction])
metocean   NDBC stdmet, ERA5, WW3 parameters                      (Hs, declared period as Tz
           (:mod:`jls.sea.metocean`)                              [, direction])
spectra    NDBC, WW3, ERA5 spectra (:mod:`jls.sea.measured`)      (Hs, Tm02[, mean direction])
========== ===================================================== ===========================

Every leg with an hourly record is assessed as a hindcast leg: the record is binned to
the leg's Hs-Tz(-direction) scatter with the leg's edges, and the weather windows and
the route simulation read the record itself. What each file's period is, is declared:

* a metocean leg names the column its ``period`` is (``tz``, ``tp``, ``te`` or ``tm01``).
  Tz is used as it is; another period is converted to the Tz of the pipeline's JONSWAP
  with the configured gamma (:func:`jls.sea.periods.tp_from_period` and the DNV-RP-C205
  relation ``tz_from_tp``): Tz = value x Tz/Tp(gamma) / (period/Tp)(gamma). Which
  conversion was made is recorded in the record's ``attrs["period_conversion"]``;
* a spectra leg's period is the spectrum's own Tm02 = sqrt(m0/m2) (the Tz of the
  pipeline), its direction the energy-weighted circular mean of the directional spectrum
  (the direction the waves come from), Hs = 4 sqrt(m0) (:func:`jls.sea.measured.integrated_parameters`).

Records without a value (NDBC's 99/999/MM, a spectrum without energy) are gaps: dropped
from the series, whose missing hours the weather windows then treat as gaps.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_TABLE_BYTES, regular_file
from jls.sea import ndbc
from jls.sea.directional import direction_widths
from jls.sea.hindcast import read_hindcast
from jls.sea.measured import integrated_parameters, read_spectra
from jls.sea.metocean import hindcast_series, read_metocean
from jls.sea.periods import tp_from_period
from jls.sea.spectra import tz_from_tp

#: the keys of a leg that give an hourly record
HOURLY = ("hindcast", "metocean", "spectra")
#: the keys of a leg that give its wave statistics
KINDS = ("scatter",) + HOURLY

__all__ = ["HOURLY", "KINDS", "SEA_MODELS", "leg_kind", "is_hourly", "leg_source", "source_field", "leg_files",
           "leg_series", "spectra_series", "mean_direction", "read_leg_spectra", "sea_model", "model_legs",
           "leg_spreading", "leg_partitions", "partition_series", "integrated_directly"]

#: the sea models a leg declares (``spectrum``)
SEA_MODELS = ("jonswap", "torsethaugen", "partitions", "measured")
PARTITION_FORMATS = ("partitions", "era5", "ww3")


def leg_kind(leg: dict) -> str:
    """Which key gives the leg's wave statistics."""
    kinds = [k for k in KINDS if k in leg]
    if len(kinds) != 1:
        raise InputError(f"a leg needs exactly one of {', '.join(KINDS)}", field=f"legs[{leg.get('name')}]",
                         value=kinds)
    return kinds[0]


def is_hourly(leg: dict) -> bool:
    """The leg gives an hourly record (hindcast, metocean or spectra)."""
    return leg_kind(leg) in HOURLY


def leg_source(leg: dict) -> Path:
    """The file the leg's statistics are read from."""
    kind = leg_kind(leg)
    return Path(leg[kind] if kind == "scatter" else leg[kind]["file"])


def source_field(leg: dict) -> str:
    """The configuration field naming the leg's file (for errors)."""
    kind = leg_kind(leg)
    return f"legs[{leg['name']}]." + ("scatter" if kind == "scatter" else f"{kind}.file")


def leg_files(leg: dict, base_dir=".") -> list[str]:
    """Every file the leg reads: its source and, for NDBC spectra, the direction files
    beside the density file that exist (they make it directional)."""
    src = leg_source(leg)
    out = [str(src)]
    if leg_kind(leg) == "spectra" and "parameters_file" in leg["spectra"]:   # optional key
        out.append(str(leg["spectra"]["parameters_file"]))
    elif leg_kind(leg) == "spectra" and leg["spectra"]["format"] == "ndbc":
        found = ndbc.stdmet_beside(Path(base_dir) / src)
        if found is not None:                  # checked against the spectra when read
            out.append(str(src.parent / found.name))
    if leg_kind(leg) == "spectra" and leg["spectra"]["format"] == "ndbc":
        for k in ("d", "i", "j", "k"):
            p = ndbc.sibling(src, k)
            if p is not None and (Path(base_dir) / p).is_file():
                out.append(str(p))
    return out


def _checked_path(leg, base_dir) -> Path:
    path = Path(base_dir) / leg_source(leg)
    field = source_field(leg)
    if not path.exists():
        raise InputError("file not found", file=path, field=field)
    regular_file(path, "file", MAX_TABLE_BYTES, field=field)
    return path


def leg_series(leg: dict, base_dir=".", *, gamma: float) -> pd.DataFrame:
    """The leg's hourly record: columns ``hs`` [m], ``tz`` [s] and, when the file gives
    it, ``direction`` [deg, from]; attrs ``source``, ``sha256``, ``path``, ``kind`` and
    ``period_conversion`` (module docstring). ``gamma``: the JONSWAP gamma a declared
    period other than Tz is converted with."""
    kind = leg_kind(leg)
    if kind not in HOURLY:
        raise InputError("a scatter-table leg has no hourly record", field=source_field(leg))
    path = _checked_path(leg, base_dir)
    if kind == "hindcast":
        out = read_hindcast(path)
        out.attrs.update(period_conversion="Tz as given")
    elif kind == "metocean":
        out = _metocean_series(leg, path, gamma)
    else:
        out = spectra_series(read_leg_spectra(leg, base_dir))
    out.attrs["kind"] = kind
    return out


def _metocean_series(leg, path, gamma) -> pd.DataFrame:
    if sea_model(leg) == "partitions":
        return partition_series(leg, path, gamma)
    m = leg["metocean"]
    field = f"legs[{leg['name']}].metocean"
    try:
        df = read_metocean(path, m["format"])
        series = hindcast_series(df, m["period"])
    except InputError as exc:
        raise InputError(exc.message, file=exc.file or path,
                         field=f"{field}.{exc.field}" if exc.field in ("period", "format") else exc.field,
                         value=exc.value) from None
    period = m["period"]
    if period == "tz":
        series.attrs["period_conversion"] = "Tz (Tm02) as given"
        return series
    # Tz of the JONSWAP whose `period` is the file's value: linear in the value.
    ratio = float(tz_from_tp(tp_from_period("jonswap", period, 1.0, gamma=gamma), float(gamma)))
    out = series.rename(columns={period: "tz"})
    out["tz"] = out["tz"] * ratio
    out.attrs = dict(series.attrs)
    out.attrs["period_conversion"] = (f"Tz = {ratio:.4f} x {period} (JONSWAP, gamma {float(gamma):g}, "
                                      "DNV-RP-C205 period relations)")
    return out


def read_leg_spectra(leg: dict, base_dir=".") -> xr.DataArray:
    """The leg's spectra (``efth``, :func:`jls.sea.measured.read_spectra`), errors naming
    the leg's field."""
    path = _checked_path(leg, base_dir)
    s = leg["spectra"]
    try:
        return read_spectra(path, s["format"])
    except InputError as exc:
        raise InputError(exc.message, file=exc.file or path,
                         field=f"legs[{leg['name']}].spectra.{exc.field}" if exc.field == "format"
                         else exc.field, value=exc.value) from None


def mean_direction(efth: xr.DataArray) -> np.ndarray:
    """Energy-weighted circular mean of the direction the waves come from [deg true] per
    record of a directional spectrum (NaN for a record without energy)."""
    w = direction_widths(efth["dir"].values)
    e = np.einsum("tfd,d->td", efth.transpose("time", "freq", "dir").values, w)   # (time, dir)
    rad = np.radians(efth["dir"].values)
    s, c = e @ np.sin(rad), e @ np.cos(rad)
    out = np.mod(np.degrees(np.arctan2(s, c)), 360.0)
    return np.where(e.sum(axis=1) > 0, out, np.nan)


def spectra_series(efth: xr.DataArray) -> pd.DataFrame:
    """The hourly record (hs, tz = Tm02[, direction]) of spectra ``efth``: a record
    without energy is a gap (dropped, counted in attrs ``n_gap_records``)."""
    ip = integrated_parameters(efth)
    cols = {"hs": ip["hs"].values, "tz": ip["tm02"].values}
    if "dir" in efth.dims:
        cols["direction"] = mean_direction(efth)
    idx = pd.DatetimeIndex(efth["time"].values)
    idx = idx.tz_localize("UTC") if idx.tz is None else idx
    df = pd.DataFrame(cols, index=idx)
    df.index.name = "time"
    keep = np.isfinite(df["hs"]) & np.isfinite(df["tz"]) & (df["hs"] > 0)
    out = df[keep].copy()
    out.attrs = {k: efth.attrs[k] for k in ("source", "sha256", "path", "format") if k in efth.attrs}
    if efth.attrs.get("fill_records"):
        out.attrs["warnings"] = [str(efth.attrs["fill_records"])]
    out.attrs.update(n_gap_records=int((~keep).sum()), period="tm02",
                     period_conversion="Tz = Tm02 of the spectrum",
                     units={c: "degree" if c == "direction" else "m" if c == "hs" else "s" for c in out.columns})
    return out


def sea_model(leg: dict) -> str:
    """The leg's sea model (``spectrum``), declared or implied by its file, checked against
    what the file can give: ``measured`` is a spectra leg's (and only its); ``partitions`` a
    metocean leg's of format partitions (which has no other), era5 or ww3; ``torsethaugen`` a
    scatter table in Hs-Tp (``period: tp``); ``jonswap`` (absent) any other leg."""
    kind = leg_kind(leg)
    field = f"legs[{leg['name']}].spectrum"
    fmt = leg["metocean"]["format"] if kind == "metocean" else None
    implied = "measured" if kind == "spectra" else "partitions" if fmt == "partitions" else "jonswap"
    model = leg["spectrum"] if "spectrum" in leg else implied
    if model not in SEA_MODELS:
        raise InputError(f"spectrum must be one of {', '.join(SEA_MODELS)}", field=field, value=model)
    if (model == "measured") != (kind == "spectra"):
        raise InputError("a spectra leg is assessed on its measured spectra (spectrum: measured), and "
                         "only a spectra leg is", field=field, value=model)
    if model == "partitions" and fmt not in PARTITION_FORMATS:
        raise InputError("spectrum: partitions needs an hourly file with partitions (metocean format "
                         f"{', '.join(PARTITION_FORMATS)})", field=field, value=fmt or kind)
    if fmt == "partitions" and model != "partitions":
        raise InputError("a partitions file is assessed on its partitions (spectrum: partitions)",
                         field=field, value=model)
    if fmt == "partitions" and leg["metocean"]["period"] != "tp":
        raise InputError("the partitions format gives each partition's peak period: declare period: tp",
                         field=f"legs[{leg['name']}].metocean.period", value=leg["metocean"]["period"])
    period = leg["period"] if "period" in leg else "tz"
    if "period" in leg and kind != "scatter":
        raise InputError("period is the axis of a scatter table; an hourly file declares its own",
                         field=f"legs[{leg['name']}].period", value=leg["period"])
    if model == "torsethaugen" and not (kind == "scatter" and period == "tp"):
        raise InputError("spectrum: torsethaugen needs a scatter table in Hs-Tp (period: tp)", field=field,
                         value=f"{kind}, period {period}")
    return model


def integrated_directly(leg: dict) -> bool:
    """Whether the leg's sea is integrated directly (:func:`model_legs`); a leg mapping
    without any file (a test's or a caller's bare leg) is not."""
    return any(k in leg for k in KINDS) and sea_model(leg) != "jonswap"


def model_legs(legs) -> list:
    """The legs whose sea is not the pipeline's JONSWAP on (Hs, Tz): measured spectra,
    partitions and Torsethaugen tables (their hours or cells integrated directly,
    ``measured_response.nc``)."""
    return [leg for leg in legs if sea_model(leg) != "jonswap"]


def leg_spreading(leg: dict, sea: dict) -> dict:
    """The leg's spreading by kind: its own ``spreading`` over the configuration's
    ``sea.spreading``."""
    own = leg["spreading"] if "spreading" in leg else {}
    return {**sea["spreading"], **own}


def leg_partitions(leg: dict, base_dir=".", *, gamma: float) -> pd.DataFrame:
    """The leg's partitions (hs_<p>, tp_<p>, dir_<p> per hour, :mod:`jls.sea.partitions`)."""
    return _partitions(leg, _checked_path(leg, base_dir), gamma)


def _partitions(leg, path, gamma):
    from jls.sea.partitions import partition_frame, read_partitions
    fmt = leg["metocean"]["format"]
    try:
        df = read_partitions(path) if fmt == "partitions" else read_metocean(path, fmt)
        return partition_frame(df, fmt, gamma, file=path)
    except InputError as exc:
        raise InputError(exc.message, file=exc.file or path, field=exc.field, value=exc.value) from None


def partition_series(leg: dict, path, gamma) -> pd.DataFrame:
    """The hourly record (hs, tz, direction) of a partitions leg: the total Hs, the Tz of
    the sum of its JONSWAP partitions (exact moments) and the energy-weighted circular mean
    of their directions; hours without any partition are gaps."""
    from jls.sea.spectra import jonswap_shape_moment
    frame = _partitions(leg, path, gamma)
    parts = [c[3:] for c in frame.columns if c.startswith("hs_")]
    m0 = np.zeros(len(frame))
    m2 = np.zeros(len(frame))
    vec = np.zeros(len(frame), complex)
    for p in parts:
        hs, tp, d = (frame[f"{k}_{p}"].to_numpy(float) for k in ("hs", "tp", "dir"))
        ok = np.isfinite(hs) & (hs > 0) & np.isfinite(tp) & np.isfinite(d)
        e = np.where(ok, np.nan_to_num(hs) ** 2 / 16, 0.0)
        wp = np.where(ok, 2 * np.pi / np.where(ok, tp, 1.0), 0.0)
        m0 += e
        m2 += e * wp**2 * float(jonswap_shape_moment(2, gamma))
        vec += e * np.exp(1j * np.radians(np.where(ok, d, 0.0)))
    keep = m0 > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        df = pd.DataFrame({"hs": 4 * np.sqrt(m0), "tz": 2 * np.pi * np.sqrt(m0 / m2),
                           "direction": np.mod(np.degrees(np.angle(vec)), 360.0)}, index=frame.index)
    out = df[keep].copy()
    out.attrs = {k: v for k, v in frame.attrs.items() if k in ("source", "sha256", "path", "format")}
    out.attrs.update(n_gap_records=int((~keep).sum()), period="tz",
                     period_conversion="Hs and Tz of the sum of the partitions (JONSWAP, gamma "
                                       f"{float(gamma):g}); " + frame.attrs.get("period_conversion", "Tp as given"),
                     units={"hs": "m", "tz": "s", "direction": "degree"})
    return out

