"""Integrated sea-state parameters per record: NDBC standard meteorological text, ERA5
single-level NetCDF and WAVEWATCH III point or field output.

Every reader returns a ``pandas.DataFrame`` indexed by UTC time (``time``, strictly
increasing) with the columns the file holds, NaN where a record has no value (a gap):

| column | units | NDBC stdmet | ERA5 | WW3 |
|---|---|---|---|---|
| ``hs`` | m | WVHT | swh | hs |
| ``tp`` | s | DPD | pp1d | tp, or 1/fp |
| ``tz`` | s (Tm02) | APD | | t02 |
| ``te`` | s (Tm-10) | | mwp | t0m1 |
| ``direction`` | deg true, from | MWD | mwd | dir |
| ``wind_hs``, ``wind_te``, ``wind_direction`` | | | shww, mpww, mdww | |
| ``swell_hs``, ``swell_te``, ``swell_direction`` | | | shts, mpts, mdts | |
| ``p<k>_hs``, ``p<k>_tp``, ``p<k>_direction`` | | | | phs<k>, ptp<k>, pdir<k> (0: wind sea) |

(the periods as defined in :mod:`jls.sea.periods`: ERA5's mean periods are Te). NetCDF
variables are found by their CF ``standard_name`` where the file gives one, else by the
names above; their ``units`` are checked (m, s, degree, Hz). NDBC's missing-value codes
(99.00 for WVHT, DPD, APD; 999 for MWD; ``MM`` in real-time files) are gaps.
``df.attrs``: source, sha256, path, format, units, and ``gaps`` (records without Hs).
:func:`hindcast_series` turns a frame into the series :mod:`jls.sea.hindcast` bins and the
weather windows use (gap records dropped, the missing hours are then gaps).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.io.netcdf import ENGINE
from jls.sea import ndbc

__all__ = ["FORMATS", "read_metocean", "read_ndbc_stdmet", "read_era5_parameters",
           "read_ww3_parameters", "hindcast_series"]

FORMATS = ("ndbc_stdmet", "era5", "ww3")
UNITS = {"hs": "m", "tp": "s", "tz": "s", "te": "s", "direction": "degree"}
# NDBC stdmet column -> (column, missing-value codes)
_STDMET = {"WVHT": ("hs", (99.0,)), "DPD": ("tp", (99.0,)), "APD": ("tz", (99.0,)),
           "MWD": ("direction", (999.0,))}
# field -> (standard names, variable names, kind)
_ERA5 = {
    "hs": (["sea_surface_wave_significant_height"], ["swh"], "m"),
    "tp": (["sea_surface_wave_period_at_variance_spectral_density_maximum"], ["pp1d"], "s"),
    "te": (["sea_surface_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment"],
           ["mwp"], "s"),
    "direction": (["sea_surface_wave_from_direction"], ["mwd"], "degree"),
    "wind_hs": (["sea_surface_wind_wave_significant_height"], ["shww"], "m"),
    "wind_te": (["sea_surface_wind_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment",
                 "sea_surface_wind_wave_mean_period"], ["mpww"], "s"),
    "wind_direction": (["sea_surface_wind_wave_from_direction"], ["mdww"], "degree"),
    "swell_hs": (["sea_surface_swell_wave_significant_height"], ["shts"], "m"),
    "swell_te": (["sea_surface_swell_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment",
                  "sea_surface_swell_wave_mean_period"], ["mpts"], "s"),
    "swell_direction": (["sea_surface_swell_wave_from_direction"], ["mdts"], "degree"),
}
_WW3 = {
    "hs": (["sea_surface_wave_significant_height"], ["hs"], "m"),
    "tp": (["sea_surface_wave_peak_period", "sea_surface_wave_period_at_variance_spectral_density_maximum"],
           ["tp"], "s"),
    "fp": (["sea_surface_wave_peak_frequency"], ["fp"], "hz"),
    "tz": (["sea_surface_wind_wave_mean_period_from_variance_spectral_density_second_frequency_moment",
            "sea_surface_wave_mean_period_from_variance_spectral_density_second_frequency_moment"],
           ["t02"], "s"),
    "te": (["sea_surface_wind_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment",
            "sea_surface_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment"],
           ["t0m1"], "s"),
    "direction": (["sea_surface_wave_from_direction"], ["dir"], "degree"),
}
_WW3_PARTS = {"hs": ("phs", "m"), "tp": ("ptp", "s"), "direction": ("pdir", "degree")}
_UNIT_FORMS = {
    "m": {"m", "metre", "metres", "meter", "meters"},
    "s": {"s", "sec", "second", "seconds"},
    "degree": {"degree", "degrees", "deg", "degreetrue", "degree_true", "degrees_true", "degreestrue",
               "degree(true)"},
    "hz": {"hz", "s-1", "s^-1", "1/s", "s**-1"},
}
RANGES = {"m": (0.0, 30.0), "s": (0.0, 40.0), "degree": (0.0, 360.0), "hz": (0.0, 2.0)}


def _check_series(file, df):
    idx = df.index
    if len(idx) > 1 and np.any(np.diff(idx.asi8) <= 0):
        k = int(np.flatnonzero(np.diff(idx.asi8) <= 0)[0]) + 1
        raise InputError("times not strictly increasing (a duplicate or out-of-order record)",
                         file=file, field="time", value=idx[k].isoformat())
    for col in df.columns:
        kind = "degree" if col.endswith("direction") else "m" if col.endswith("hs") else "s"
        lo, hi = RANGES[kind]
        v = df[col].to_numpy(float)
        bad = np.isfinite(v) & ((v < lo) | (v > hi) | ((v <= 0) & (kind == "s")))
        if bad.any():
            k = int(np.flatnonzero(bad)[0])
            raise InputError(f"{col} outside {lo:g}-{hi:g} {UNITS.get(col, kind)} ({int(bad.sum())} "
                             "such records)", file=file, field=f"{col} at {idx[k].isoformat()}",
                             value=float(v[k]))


def _finish(df, file, raw, fmt):
    df.index.name = "time"
    _check_series(file, df)
    df.attrs.update(source=Path(file).name, sha256=hashlib.sha256(raw).hexdigest(), path=str(file),
                    format=fmt, gaps=int(df["hs"].isna().sum()) if "hs" in df else 0,
                    units={c: ("degree" if c.endswith("direction") else "m" if c.endswith("hs") else "s")
                           for c in df.columns})
    return df


def read_ndbc_stdmet(path) -> pd.DataFrame:
    """NDBC standard meteorological file (historical ``41010h2019.txt[.gz]`` or real-time
    ``41010.txt``) -> hs, tp, tz, direction; the 99/999/MM codes are gaps (NaN)."""
    t = ndbc.read_table(path, "NDBC standard meteorological file")
    names = [c.upper() for c in t.columns]
    if "WVHT" not in names:
        raise InputError("no WVHT column: not an NDBC standard meteorological file", file=t.path,
                         field="header", value=t.columns)
    data = {}
    for name, (col, codes) in _STDMET.items():
        if name in names:
            v = t.values[:, names.index(name)].copy()
            v[ndbc.is_fill(v, codes)] = np.nan
            data[col] = v
    df = pd.DataFrame(data, index=t.times)
    return _finish(df, t.path, Path(path).read_bytes(), "ndbc_stdmet")


def _unit_kind(u):
    s = str(u).strip().lower().replace(" ", "")
    for kind, forms in _UNIT_FORMS.items():
        if s in forms:
            return kind
    return None


def _find(ds, file, field, spec):
    std_names, var_names, kind = spec
    hit = [v for v in ds.data_vars if ds[v].attrs.get("standard_name") in std_names]
    hit = hit or [v for v in var_names if v in ds.data_vars]
    if not hit:
        return None
    name = hit[0]
    u = ds[name].attrs.get("units")
    if _unit_kind(u) != kind:
        raise InputError(f"units of {field} must be {kind}", file=file, field=name, value=u)
    std = str(ds[name].attrs.get("standard_name", ""))
    if kind == "degree" and "_to_direction" in std:     # found by its name, stated "going to"
        raise InputError(f"the file states that {name} is the direction the waves travel TO "
                         f"(its standard_name); jls reads {field} as where the waves come FROM "
                         "(ERA5's mwd, NDBC's MWD; the legs' dir_edges_deg and a course's relative "
                         "headings): give the directions they come from (+180 deg) with standard_name "
                         f"{std.replace('_to_direction', '_from_direction')}", file=file, field=name,
                         value=std)
    return name


def _select_point(da, file, site_dims, index):
    for d in [d for d in da.dims if d in site_dims]:
        if da.sizes[d] == 1:
            da = da.isel({d: 0})
        elif index is None or d not in index:
            raise InputError(f"the file holds {da.sizes[d]} values along {d}; choose one", file=file,
                             field=d, value=da.sizes[d])
        else:
            da = da.sel({d: index[d]}, method="nearest") if d in ("latitude", "longitude") \
                else da.isel({d: int(index[d])})
    extra = [d for d in da.dims if d != "time"]
    if extra:
        raise InputError(f"unexpected dimensions {extra}", file=file, field=da.name, value=extra)
    return da.values.astype(float)


def _read_netcdf(path, fmt, spec, site_dims, index, extra=None):
    file = str(path)
    try:
        ds = xr.open_dataset(file, engine=ENGINE)
    except FileNotFoundError:
        raise InputError("cannot read: no such file", file=file) from None
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read as NetCDF ({exc})", file=file) from None
    with ds:
        if "valid_time" in ds.dims or "valid_time" in ds.coords:
            ds = ds.rename({"valid_time": "time"})
        if "time" not in ds.coords and "time" not in ds.variables:
            raise InputError("no time coordinate ('time' or 'valid_time')", file=file, field="time",
                             value=sorted(map(str, ds.variables)))
        found = {f: _find(ds, file, f, s) for f, s in spec.items()}
        found.update(extra(ds, file) if extra else {})
        if found.get("hs") is None:
            raise InputError(f"no significant wave height: none of the variables "
                             f"{', '.join(sorted(map(str, ds.data_vars)))} is {spec['hs'][1][0]} or has "
                             f"standard_name {spec['hs'][0][0]}", file=file, field="hs")
        data = {f: _select_point(ds[v], file, site_dims, index) for f, v in found.items() if v}
        times = pd.DatetimeIndex(pd.to_datetime(ds["time"].values), name="time").tz_localize("UTC")
    if "fp" in data:
        fp = data.pop("fp")
        if "tp" not in data:
            with np.errstate(divide="ignore"):
                data["tp"] = np.where(fp > 0, 1.0 / fp, np.nan)
    df = pd.DataFrame(data, index=times)
    return _finish(df, file, Path(file).read_bytes(), fmt)


def read_era5_parameters(path, *, point=None) -> pd.DataFrame:
    """ERA5 single-level wave parameters (swh, pp1d, mwp, mwd; partitions shww, mpww,
    mdww, shts, mpts, mdts) at one grid point; ``point={"latitude": .., "longitude": ..}``
    picks the nearest when the file holds several."""
    return _read_netcdf(path, "era5", _ERA5, ("latitude", "longitude", "lat", "lon"), point)


def _ww3_partitions(ds, file):
    out = {}
    for k in range(10):
        for field, (prefix, kind) in _WW3_PARTS.items():
            name = f"{prefix}{k}"
            if name in ds.data_vars:
                u = ds[name].attrs.get("units")
                if _unit_kind(u) != kind:
                    raise InputError(f"units of partition {k} {field} must be {kind}", file=file,
                                     field=name, value=u)
                out[f"p{k}_{field}"] = name
    return out


def read_ww3_parameters(path, *, station=None) -> pd.DataFrame:
    """WAVEWATCH III point (``station`` dimension) or single-point field output: hs, tp (or
    1/fp), t02, t0m1, dir and the partitions phs<k>, ptp<k>, pdir<k>. ``station``: the
    station index when the file holds several."""
    index = None if station is None else {"station": station, "site": station}
    return _read_netcdf(path, "ww3", _WW3, ("station", "site", "latitude", "longitude", "node"),
                        index, extra=_ww3_partitions)


def read_metocean(path, format, **options) -> pd.DataFrame:
    """Read an integrated-parameter file of ``format`` (one of :data:`FORMATS`)."""
    readers = {"ndbc_stdmet": read_ndbc_stdmet, "era5": read_era5_parameters, "ww3": read_ww3_parameters}
    if format not in readers:
        raise InputError(f"unknown metocean format (known: {', '.join(FORMATS)})", file=path,
                         field="format", value=format)
    return readers[format](path, **options)


def hindcast_series(df: pd.DataFrame, period="tz") -> pd.DataFrame:
    """The hourly series of :mod:`jls.sea.hindcast` (columns hs, tz[, direction]) from a
    metocean frame: ``period`` names the column that is the series' period (declared,
    e.g. "tp" for a Tp table; it is written as column ``tz`` only when it is Tz, else
    kept under its own name). Records without Hs or that period are dropped; attrs
    ``n_gap_records`` counts them."""
    if period not in df.columns:
        raise InputError(f"the file has no {period} column (has {', '.join(df.columns)})",
                         file=df.attrs.get("source"), field="period", value=period)
    cols = ["hs", period] + (["direction"] if "direction" in df.columns else [])
    out = df[cols].copy()
    keep = out["hs"].notna() & out[period].notna()
    out = out[keep]
    if "direction" in out.columns and out["direction"].isna().all():
        out = out.drop(columns="direction")      # the file gives no direction at all
    # a record without a direction (999) stays: a table binned by direction leaves that
    # hour out (jls.sea.hindcast.bin_hindcast), one hour, not the whole column
    out.attrs = dict(df.attrs)
    out.attrs.update(n_gap_records=int((~keep).sum()), period=period,
                     units={c: UNITS.get(c, "s") for c in out.columns})
    return out
