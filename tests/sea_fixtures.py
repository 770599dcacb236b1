"""Small metocean files written by the tests: NDBC real-time spectral files made from the
committed historical ones, and ERA5-like and WAVEWATCH III-like NetCDF files with the
published variable names, units and CF attributes."""

from __future__ import annotations

import gzip
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

NDBC_DIR = Path(__file__).parent / "data" / "spectra" / "ndbc_41010_2019"
NDBC_DENSITY = NDBC_DIR / "41010w2019part.txt.gz"
KINDS = {"w": ".data_spec", "d": ".swdir", "i": ".swdir2", "j": ".swr1", "k": ".swr2"}


def historical_rows(kind):
    """(header tokens, rows of tokens) of a committed historical file."""
    text = gzip.decompress((NDBC_DIR / f"41010{kind}2019part.txt.gz").read_bytes()).decode()
    lines = [ln.split() for ln in text.splitlines() if ln.strip()]
    return lines[0], lines[1:]


def write_realtime(out_dir, n=None):
    """The committed records as NDBC real-time files (newest first, r1 and r2 as 0-1,
    ``value (frequency)`` pairs); returns the path of the ``.data_spec`` file."""
    out_dir = Path(out_dir)
    for kind, suffix in KINDS.items():
        header, rows = historical_rows(kind)
        rows = rows[:n] if n else rows
        freqs = header[5:]
        name = {"w": "spec", "d": "alpha1", "i": "alpha2", "j": "r1", "k": "r2"}[kind]
        head = "#YY  MM DD hh mm" + (" Sep_Freq" if kind == "w" else "") + \
            f"  < {name}_1 (freq_1) {name}_2 (freq_2) ... >"
        lines = [head]
        for r in reversed(rows):
            vals = [float(v) for v in r[5:]]
            if kind in "jk":
                vals = [v / 100 for v in vals]
            fmt = "{:.3f}" if kind in "wjk" else "{:.1f}"
            pairs = " ".join(f"{fmt.format(v)} ({float(f):.3f})" for v, f in zip(vals, freqs))
            lines.append(" ".join(r[:5]) + (" 9.999" if kind == "w" else "") + " " + pairs)
        (out_dir / f"41010{suffix}").write_text("\n".join(lines) + "\n")
    return out_dir / "41010.data_spec"


def write_historical(out_dir, edit=None, kinds="wdijk", n=None):
    """Copies of the committed historical files (plain text) into ``out_dir``;
    ``edit(kind, header, rows)`` may change them. Returns the density file's path."""
    out_dir = Path(out_dir)
    for kind in kinds:
        header, rows = historical_rows(kind)
        rows = [list(r) for r in (rows[:n] if n else rows)]
        if edit:
            header, rows = edit(kind, header, rows)
        text = "\n".join(" ".join(t) for t in [header] + rows) + "\n"
        (out_dir / f"41010{kind}2019part.txt").write_text(text)
    return out_dir / "41010w2019part.txt"


def hourly(n, start="2019-02-06T00:00"):
    return pd.date_range(start, periods=n, freq="h").values


def era5_parameters(path, values, *, names=None, units=None, point_dims=True, time="valid_time",
                    standard_names=True):
    """An ERA5 single-level NetCDF like the Copernicus Climate Data Store writes: variables
    swh, pp1d, mwp, mwd, shww, mpww, mdww, shts, mpts, mdts on (valid_time, latitude,
    longitude) with long_name, units and (where CF has one) standard_name."""
    meta = {
        "swh": ("Significant height of combined wind waves and swell", "m",
                "sea_surface_wave_significant_height"),
        "pp1d": ("Peak wave period", "s", "sea_surface_wave_period_at_variance_spectral_density_maximum"),
        "mwp": ("Mean wave period", "s",
                "sea_surface_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment"),
        "mwd": ("Mean wave direction", "degree", "sea_surface_wave_from_direction"),
        "shww": ("Significant height of wind waves", "m", "sea_surface_wind_wave_significant_height"),
        "mpww": ("Mean period of wind waves", "s", None),
        "mdww": ("Mean direction of wind waves", "degree", "sea_surface_wind_wave_from_direction"),
        "shts": ("Significant height of total swell", "m", "sea_surface_swell_wave_significant_height"),
        "mpts": ("Mean period of total swell", "s", None),
        "mdts": ("Mean direction of total swell", "degree", "sea_surface_swell_wave_from_direction"),
    }
    n = len(next(iter(values.values())))
    ds = xr.Dataset(coords={time: hourly(n), "latitude": [28.9], "longitude": [-78.5]})
    for short, v in values.items():
        long_name, unit, std = meta[short]
        name = (names or {}).get(short, short)
        data = np.asarray(v, float)[:, None, None] if point_dims else np.asarray(v, float)
        dims = (time, "latitude", "longitude") if point_dims else (time,)
        attrs = {"long_name": long_name, "units": (units or {}).get(short, unit), "GRIB_shortName": short}
        if std and standard_names:
            attrs["standard_name"] = std
        ds[name] = (dims, data, attrs)
    ds.attrs.update(Conventions="CF-1.7", institution="European Centre for Medium-Range Weather Forecasts")
    ds.to_netcdf(path)
    return path


def ww3_parameters(path, values, *, n_station=1):
    """A WAVEWATCH III point-output NetCDF (ww3_ounp-like): hs, fp, t02, t0m1, dir, dp and
    partitions phs0/ptp0/pdir0 (wind sea), phs1/ptp1/pdir1 on (time, station)."""
    meta = {
        "hs": ("significant height of wind and swell waves", "m", "sea_surface_wave_significant_height"),
        "fp": ("wave peak frequency", "s-1", None),
        "t02": ("mean period t02", "s",
                "sea_surface_wind_wave_mean_period_from_variance_spectral_density_second_frequency_moment"),
        "t0m1": ("mean period t0m1", "s",
                 "sea_surface_wind_wave_mean_period_from_variance_spectral_density_inverse_frequency_moment"),
        "dir": ("wave mean direction", "degree", "sea_surface_wave_from_direction"),
        "phs0": ("wave significant height partition 0", "m", "sea_surface_wind_wave_significant_height"),
        "ptp0": ("peak period partition 0", "s", "sea_surface_wind_wave_period_at_variance_spectral_density_maximum"),
        "pdir0": ("wave mean direction partition 0", "degree", "sea_surface_wind_wave_from_direction"),
        "phs1": ("wave significant height partition 1", "m", "sea_surface_primary_swell_wave_significant_height"),
        "ptp1": ("peak period partition 1", "s",
                 "sea_surface_primary_swell_wave_period_at_variance_spectral_density_maximum"),
        "pdir1": ("wave mean direction partition 1", "degree", "sea_surface_primary_swell_wave_from_direction"),
    }
    n = len(next(iter(values.values())))
    ds = xr.Dataset(coords={"time": hourly(n), "station": np.arange(n_station)})
    for name, v in values.items():
        long_name, unit, std = meta[name]
        data = np.repeat(np.asarray(v, float)[:, None], n_station, axis=1)
        attrs = {"long_name": long_name, "units": unit, "_FillValue": 9.96921e36}
        if std:
            attrs["standard_name"] = std
        ds[name] = (("time", "station"), data, {k: a for k, a in attrs.items() if k != "_FillValue"})
        ds[name].encoding["_FillValue"] = 9.96921e36
    ds.to_netcdf(path)
    return path


def ww3_spectra(path, freq, dirs_to, efth_rad, *, units="m2 s rad-1"):
    """A WAVEWATCH III spectral point output: efth (time, station, frequency, direction)
    in m2 s rad-1 on directions the waves travel TO, one station."""
    n = efth_rad.shape[0]
    ds = xr.Dataset(
        {"efth": (("time", "station", "frequency", "direction"), efth_rad[:, None],
                  {"long_name": "sea surface wave directional variance spectral density",
                   "standard_name": "sea_surface_wave_directional_variance_spectral_density",
                   "units": units}),
         "longitude": (("time", "station"), np.full((n, 1), -78.5), {"units": "degree_east"}),
         "latitude": (("time", "station"), np.full((n, 1), 28.9), {"units": "degree_north"})},
        coords={"time": hourly(n), "station": [1], "frequency": ("frequency", freq, {"units": "s-1"}),
                "direction": ("direction", dirs_to, {"units": "degree",
                                                      "long_name": "sea surface wave to direction"})})
    ds.to_netcdf(path)
    return path


def era5_spectra(path, log10_d2fd):
    """An ERA5 2-D spectra NetCDF: d2fd (valid_time, directionNumber, frequencyNumber,
    latitude, longitude) as log10 of m2 s radian-1, 24 x 30 bins."""
    n = log10_d2fd.shape[0]
    ds = xr.Dataset(
        {"d2fd": (("valid_time", "direction", "frequency", "latitude", "longitude"),
                  log10_d2fd[..., None, None], {"units": "m**2 s radian**-1",
                                                "long_name": "2D wave spectra (single)"})},
        coords={"valid_time": hourly(n), "direction": np.arange(1, 25), "frequency": np.arange(1, 31),
                "latitude": [28.9], "longitude": [-78.5]})
    ds.to_netcdf(path)
    return path
