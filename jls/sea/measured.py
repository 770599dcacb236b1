"""Measured and hindcast wave spectra per record: readers and integrated parameters.

Every reader returns one ``xarray.DataArray`` named ``efth``:

| dims | units | meaning |
|---|---|---|
| ``time, freq`` | m2 Hz-1 | frequency spectrum E(f) per record (1-D) |
| ``time, freq, dir`` | m2 Hz-1 degree-1 | directional spectrum E(f, dir) per record |

``time`` UTC (numpy datetime64, strictly increasing), ``freq`` [Hz] strictly increasing,
``dir`` [deg true] the direction the waves come FROM, each bin standing for its width
(:func:`jls.sea.directional.direction_widths`). attrs: ``source`` (file name), ``sha256``,
``path``, ``format``, and what the reader did (``directional``, ``r_scale``, ...).

**Integration rule, stated once**: each value is the density of a band centred on its
frequency, of width ``numpy.gradient(freq)`` (half-way to each neighbour; the end bands
mirrored), as NDBC reports its bands and as wavespectra integrates; a direction bin
stands for its width. So m_n = sum f^n E(f) df (moments in Hz), Hs = 4 sqrt(m0),
Tm02 = sqrt(m0/m2), Tm01 = m0/m1, Te = m_-1/m0 (the periods of :mod:`jls.sea.periods`)
and Tp = 1/f of the largest E(f) (the band NDBC's DPD reports). The response integral
(:mod:`jls.response.directional`) interpolates the spectrum linearly between the band
centres and holds it over the outer halves of the end bands, which keeps m0 exactly and
the higher moments to second order in the band width.

Formats (:data:`FORMATS`):

* ``ndbc``: NDBC spectral density files, historical (``41010w2019.txt[.gz]``) and real-time
  (``41010.data_spec``); the direction files beside it (historical ``d``, ``i``, ``j``,
  ``k``; real-time ``.swdir``, ``.swdir2``, ``.swr1``, ``.swr2``) make it directional
  by the Fourier reconstruction of :mod:`jls.sea.directional` on ``dirs`` (24 bins of
  15 deg by default). Historical r1, r2 files hold hundredths (values above 1 are
  divided by 100, recorded in ``r1_scale``, ``r2_scale``). Real-time files print the
  frequencies to three decimals (0.033 for the 0.0325 Hz band); they are kept as
  printed, which moves Hs by up to 0.5 % against the historical file of the same
  records. A missing-value code (999) in the density,
  or in a direction file where the band holds energy, drops that record (one hour, a gap;
  attrs ``n_fill_records``, ``fill_records``); more than half the records so is an error.
* ``ww3``: WAVEWATCH III spectral point output (``efth`` [m2 s rad-1] on ``frequency``,
  ``direction`` going-to, per ``station``), read with wavespectra's ``read_ww3``.
* ``era5``: ECMWF ERA5 2-D spectra (``d2fd``, log10 of m2 s rad-1, 30 frequencies from
  0.03453 Hz by factors of 1.1, 24 directions), read with wavespectra's ``read_era5``.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_TABLE_BYTES, regular_file
from jls.io.netcdf import ENGINE
from jls.sea import ndbc
from jls.sea.directional import DEFAULT_DIRS, direction_widths, fourier_spreading

__all__ = ["FORMATS", "read_spectra", "read_ndbc_spectra", "read_ww3_spectra", "read_era5_spectra",
           "spectra_array", "frequency_spectrum", "band_widths", "spectral_moments",
           "integrated_parameters"]

FORMATS = ("ndbc", "ww3", "era5")
F_MAX = 2.0   # Hz; a larger "frequency" is a period or an angular frequency


def spectra_array(values, times, freq, dirs=None, *, attrs=None, file=None) -> xr.DataArray:
    """The checked ``efth`` DataArray of (n_time, n_freq[, n_dir]) values [m2 Hz-1
    (degree-1)]; errors name ``file``."""
    v = np.asarray(values, float)
    f = np.asarray(freq, float)
    t = pd.DatetimeIndex(times)
    t = t.tz_convert("UTC").tz_localize(None) if t.tz is not None else t
    if f.ndim != 1 or f.size < 2 or not np.all(np.isfinite(f)) or f[0] <= 0 or np.any(np.diff(f) <= 0) \
            or f[-1] > F_MAX:
        raise InputError(f"frequencies must be > 0, strictly increasing, in Hz (<= {F_MAX:g})",
                         file=file, field="frequency", value=f.tolist()[:6])
    if len(t) > 1 and np.any(np.diff(t.asi8) <= 0):
        k = int(np.flatnonzero(np.diff(t.asi8) <= 0)[0]) + 1
        raise InputError("times not strictly increasing", file=file, field="time", value=str(t[k]))
    dims = ["time", "freq"] + ([] if dirs is None else ["dir"])
    coords = {"time": t.values.astype("datetime64[ns]"), "freq": f}
    if dirs is not None:
        coords["dir"] = np.asarray(dirs, float)
        direction_widths(coords["dir"])                               # checks the directions
    if v.shape != tuple(len(coords[d]) for d in dims):
        raise InputError(f"spectra must be {dims}", file=file, field="efth", value=list(v.shape))
    bad = ~np.isfinite(v)
    if bad.any():
        k = np.argwhere(bad)[0]
        raise InputError("spectral density not finite", file=file,
                         field=f"time {t[k[0]]}, frequency {f[k[1]]:g} Hz", value=float(v[tuple(k)]))
    out = xr.DataArray(v, dims=dims, coords=coords, name="efth")
    e1 = frequency_spectrum(out).values
    if np.any(e1 < 0):
        k = np.argwhere(e1 < 0)[0]
        raise InputError("negative spectral density", file=file,
                         field=f"time {t[k[0]]}, frequency {f[k[1]]:g} Hz", value=float(e1[tuple(k)]))
    out.attrs.update({"units": "m2 Hz-1" + ("" if dirs is None else " degree-1"),
                      "time_zone": "UTC", "direction_convention": "coming from, degrees true"})
    out.attrs.update(attrs or {})
    out["freq"].attrs["units"] = "Hz"
    if dirs is not None:
        out["dir"].attrs["units"] = "degree"
    return out


def _fill_error(table, mask, quantity):
    i, j = np.argwhere(mask)[0]
    raise InputError(f"missing-value code in the {quantity} ({int(mask.sum())} such values); "
                     "remove or repair these records", file=table.path,
                     field=f"line {table.lines[i]}, frequency {table.columns[j]} Hz",
                     value=float(table.values[i, j]))


def _direction_table(path, density, quantity):
    t = ndbc.read_table(path, quantity, spectral=True)
    if len(t.times) != len(density.times) or np.any(t.times != density.times):
        diff = np.flatnonzero(t.times[: len(density.times)] != density.times[: len(t.times)])
        where = str(density.times[diff[0]]) if diff.size else f"{len(t.times)} records"
        raise InputError(f"records differ from the density file {density.name}", file=t.path,
                         field="time", value=where)
    if not np.allclose(np.asarray(t.columns, float), np.asarray(density.columns, float)):
        raise InputError(f"frequencies differ from the density file {density.name}", file=t.path,
                         field="frequency", value=t.columns[:6])
    return t


def read_ndbc_spectra(path, *, directional=None, dirs=DEFAULT_DIRS, weighted=False) -> xr.DataArray:
    """NDBC spectral density file -> ``efth`` (1-D, or directional with the files beside it).

    directional: None (directional when all four direction files are there), True (they
    must be), False (1-D). dirs [deg]: the reconstruction grid. weighted: the
    Longuet-Higgins weights (:func:`jls.sea.directional.fourier_spreading`).
    """
    dens = ndbc.read_table(path, "NDBC spectral density file", spectral=True)
    freq = np.asarray(dens.columns, float)
    if np.any(np.diff(freq) <= 0) or freq[0] <= 0 or freq[-1] > F_MAX:
        raise InputError(f"frequencies must be > 0, strictly increasing, in Hz (<= {F_MAX:g})",
                         file=dens.path, field="frequency header", value=dens.columns[:6])
    fill = ndbc.is_fill(dens.values)
    if np.any((dens.values < 0) & ~fill):
        _fill_error(dens, (dens.values < 0) & ~fill, "spectral density (negative)")
    dropped = fill.any(axis=1)          # a record with a missing value: that hour is a gap
    kinds = {"d": "alpha1", "i": "alpha2", "j": "r1", "k": "r2"}
    paths = {k: ndbc.sibling(path, k) for k in kinds}
    found = {k: p for k, p in paths.items() if p is not None and p.is_file()}
    if directional is None:
        directional = len(found) == 4
        if 0 < len(found) < 4:
            missing = [kinds[k] for k in kinds if k not in found]
            raise InputError("some direction files are missing beside the density file: "
                             + ", ".join(f"{kinds[k]} ({paths[k].name})" for k in kinds if k not in found),
                             file=dens.path, field="directional", value=missing)
    elif directional and len(found) < 4:
        missing = {kinds[k]: str(paths[k].name) if paths[k] else None for k in kinds if k not in found}
        raise InputError("directional spectra need the four direction files beside the density "
                         "file", file=dens.path, field="directional", value=missing)
    attrs = {"source": dens.name, "sha256": dens.sha256, "path": dens.path, "format": "ndbc",
             "layout": "real-time" if dens.realtime else "historical", "directional": int(directional)}
    if not directional:
        _drop_limit(dropped, {"spectral density": (dens, fill)})
        keep = ~dropped
        attrs.update(_dropped_attrs(dens, dropped))
        return spectra_array(dens.values[keep], dens.times[keep], freq, attrs=attrs, file=dens.path)
    tabs = {k: _direction_table(found[k], dens, kinds[k]) for k in kinds}
    energy = (dens.values > 0) & ~fill
    coeff, fills = {}, {"spectral density": (dens, fill)}
    for k, name in kinds.items():
        t = tabs[k]
        v = t.values.copy()
        vfill = ndbc.is_fill(v)
        dropped |= (vfill & energy).any(axis=1)
        fills[f"{name} of a band that holds energy"] = (t, vfill & energy)
        v[vfill] = 0.0                         # bands without energy: isotropic, no weight
        if name.startswith("alpha"):
            bad = ((v < 0) | (v > 360)) & ~dropped[:, None]
        else:
            scale = 100.0 if (not t.realtime and np.any(v > 1.0)) else 1.0
            attrs[f"{name}_scale"] = scale
            v = v / scale
            bad = ((v < 0) | (v > 1.0 + 1e-9)) & ~dropped[:, None]
        if bad.any():
            i, j = np.argwhere(bad)[0]
            limit = "0-360 deg" if name.startswith("alpha") else "0-1 (historical files: 0-100)"
            raise InputError(f"{name} outside {limit} (the {name} file beside the density file "
                             f"{dens.name})", file=t.path,
                             field=f"line {t.lines[i]}, frequency {t.columns[j]} Hz",
                             value=float(t.values[i, j]))
        coeff[name] = v
        attrs[f"{name}_file"] = Path(found[k]).name
        attrs[f"{name}_sha256"] = t.sha256
    _drop_limit(dropped, fills)
    keep = ~dropped
    attrs.update(_dropped_attrs(dens, dropped))
    D = fourier_spreading(dirs, *(coeff[n][keep] for n in ("alpha1", "alpha2", "r1", "r2")),
                          weighted=weighted)
    attrs["spreading"] = "fourier, Longuet-Higgins weights" if weighted else "fourier"
    return spectra_array(dens.values[keep][..., None] * D, dens.times[keep], freq,
                         np.asarray(dirs, float), attrs=attrs, file=dens.path)


#: At most this fraction of an NDBC file's records may carry a missing-value code (each is
#: dropped as a gap, one hour); more is the wrong file or a broken one, and an error.
MAX_DROPPED_FRACTION = 0.5


def _drop_limit(dropped, fills) -> None:
    """Refuse a file whose records mostly carry a missing value, naming the first."""
    if dropped.mean() <= MAX_DROPPED_FRACTION:
        return
    for quantity, (table, mask) in fills.items():
        if mask.any():
            i, j = np.argwhere(mask)[0]
            raise InputError(f"missing-value code in the {quantity} of {int(dropped.sum())} of the "
                             f"{dropped.size} records (more than {100 * MAX_DROPPED_FRACTION:g} %, "
                             "each an hour left out); remove or repair these records",
                             file=table.path, field=f"line {table.lines[i]}, frequency "
                             f"{table.columns[j]} Hz", value=float(table.values[i, j]))


def _dropped_attrs(dens, dropped) -> dict:
    """Attributes recording the records dropped for a missing value (their lines)."""
    if not dropped.any():
        return {"n_fill_records": 0}
    lines = dens.lines[dropped]
    return {"n_fill_records": int(dropped.sum()),
            "fill_records": (f"{int(dropped.sum())} record(s) with a missing-value code (999) in "
                             f"{dens.name} or its direction files, left out as gaps (density file "
                             f"lines {', '.join(map(str, lines[:5]))}{' ...' if lines.size > 5 else ''})")}


def _open_netcdf(path, what):
    file = str(path)
    regular_file(path, what, MAX_TABLE_BYTES)        # not a device, a pipe or a folder
    try:
        return xr.open_dataset(file, engine=ENGINE)
    except FileNotFoundError:
        raise InputError(f"cannot read {what}: no such file", file=file) from None
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read {what} as NetCDF ({exc})", file=file) from None


def _require(ds, file, names, what):
    missing = [n for n in names if n not in ds.variables]
    if missing:
        raise InputError(f"not {what}: variable(s) {', '.join(missing)} not found (the file "
                         f"has {', '.join(sorted(map(str, ds.variables)))})", file=file,
                         field=missing[0])


def _units(ds, file, name, allowed):
    u = str(ds[name].attrs.get("units", "")).replace("**", "^").replace(" ", "").lower()
    if u not in allowed:
        raise InputError(f"unexpected units (expected {sorted(allowed)[0]})", file=file, field=name,
                         value=ds[name].attrs.get("units"))


def _from_wavespectra(dset, file, fmt, site_dims, site=None):
    eft = dset["efth"]
    extra = [d for d in eft.dims if d in site_dims]
    for d in extra:
        if site is not None and not 0 <= int(site) < eft.sizes[d]:
            raise InputError(f"no {d} {int(site)}: the file holds {eft.sizes[d]} {d}(s), "
                             f"indices 0 to {eft.sizes[d] - 1}", file=file, field=d, value=site)
        if eft.sizes[d] == 1:
            eft = eft.isel({d: 0})
        elif site is None:
            raise InputError(f"the file holds {eft.sizes[d]} {d}s; choose one", file=file, field=d,
                             value=eft.sizes[d])
        else:
            eft = eft.isel({d: int(site)})
    eft = eft.transpose("time", "freq", "dir").load()
    order = np.argsort(eft["dir"].values)
    eft = eft.isel(dir=order)
    raw = Path(file).read_bytes()
    attrs = {"source": Path(file).name, "sha256": hashlib.sha256(raw).hexdigest(), "path": str(file),
             "format": fmt, "directional": 1, "reader": "wavespectra"}
    return spectra_array(eft.values, pd.DatetimeIndex(eft["time"].values), eft["freq"].values.astype(float),
                         eft["dir"].values.astype(float), attrs=attrs, file=file)


def _wavespectra_reader(name: str, file: str, label: str):
    """wavespectra's reader ``name``: wavespectra is the optional extra ``[spectra]`` (with
    dask, about 90 MB); without it, an error naming the extra."""
    try:
        import wavespectra
    except ImportError:
        raise InputError(f"reading {label} spectra needs wavespectra, the optional extra [spectra], "
                         "which is not installed: pip install -e '.[spectra]' (NDBC spectral files "
                         "need nothing more)", file=file) from None
    return getattr(wavespectra, name)


def read_ww3_spectra(path, *, station=None) -> xr.DataArray:
    """WAVEWATCH III spectral point output -> directional ``efth`` (wavespectra's
    ``read_ww3``: m2 s rad-1 to m2 Hz-1 degree-1, going-to to coming-from). ``station``:
    the index of the station when the file holds several."""
    file = str(path)
    with _open_netcdf(file, "WW3 spectra") as ds:
        _require(ds, file, ("efth", "frequency", "direction", "time"), "WW3 spectral output")
        _units(ds, file, "efth", {"m2srad-1", "m^2srad^-1", "m2.s.rad-1", "m2/hz/rad"})
    read_ww3 = _wavespectra_reader("read_ww3", file, "WAVEWATCH III")
    return _from_wavespectra(read_ww3(file), file, "ww3", ("site", "station"), station)


def read_era5_spectra(path) -> xr.DataArray:
    """ECMWF ERA5 2-D wave spectra at one grid point -> directional ``efth`` (wavespectra's
    ``read_era5``: log10 of m2 s rad-1, ERA5's frequency and direction grid)."""
    file = str(path)
    with _open_netcdf(file, "ERA5 spectra") as ds:
        _require(ds, file, ("d2fd",), "ERA5 2-D wave spectra")
    read_era5 = _wavespectra_reader("read_era5", file, "ERA5")
    return _from_wavespectra(read_era5(file), file, "era5", ("latitude", "longitude", "lat", "lon"))


#: The fewest frequency bands a spectra file may hold: NDBC files hold 38-47, ERA5 30,
#: WAVEWATCH III 25-50. A file cut to a few bands integrates to a fraction of its Hs
#: (two bands of the 47 of NDBC 41010 gave a tiny Hs and a route workability 12 points high).
MIN_BANDS = 15


def read_spectra(path, format, **options) -> xr.DataArray:
    """Read a spectra file of ``format`` (one of :data:`FORMATS`); ``options`` go to the
    format's reader. A file of fewer than :data:`MIN_BANDS` frequency bands is refused."""
    readers = {"ndbc": read_ndbc_spectra, "ww3": read_ww3_spectra, "era5": read_era5_spectra}
    if format not in readers:
        raise InputError(f"unknown spectra format (known: {', '.join(FORMATS)})", file=path,
                         field="format", value=format)
    efth = readers[format](path, **options)
    n = int(efth.sizes["freq"])
    if n < MIN_BANDS:
        f = efth["freq"].values
        raise InputError(f"{n} frequency band(s) ({f[0]:g}-{f[-1]:g} Hz), fewer than the {MIN_BANDS} a "
                         "spectrum needs to stand for a sea state (NDBC files hold 38-47, ERA5 30): a "
                         "truncated or filtered file?", file=path, field="frequencies", value=n)
    return efth


def frequency_spectrum(efth: xr.DataArray) -> xr.DataArray:
    """E(f) [m2 Hz-1]: a directional spectrum summed over its direction bins."""
    if "dir" not in efth.dims:
        return efth
    w = xr.DataArray(direction_widths(efth["dir"].values), dims="dir")
    return (efth * w).sum("dir")


def band_widths(freq):
    """Width [Hz] of the band each frequency stands for: ``numpy.gradient(freq)``."""
    f = np.asarray(freq, float)
    return np.gradient(f) if f.size > 1 else np.ones(1)


def spectral_moments(efth: xr.DataArray, orders=(0, 2)) -> dict:
    """{n: m_n per record} [m2 Hz^n] = sum f^n E(f) df over the bands (module docstring)."""
    e1 = frequency_spectrum(efth)
    f = efth["freq"]
    df = xr.DataArray(band_widths(f.values), dims="freq")
    return {n: (f**n * e1 * df).sum("freq") for n in orders}


def integrated_parameters(efth: xr.DataArray) -> xr.Dataset:
    """Hs [m], Tm02, Tm01, Te and Tp [s] per record (the module's integration rule)."""
    m = spectral_moments(efth, (-1, 0, 1, 2))
    e1 = frequency_spectrum(efth)
    f = efth["freq"].values
    with np.errstate(divide="ignore", invalid="ignore"):
        ds = xr.Dataset({
            "hs": 4.0 * np.sqrt(m[0]), "tm02": np.sqrt(m[0] / m[2]), "tm01": m[0] / m[1],
            "te": m[-1] / m[0],
            "tp": ("time", np.where(e1.max("freq").values > 0, 1.0 / f[e1.values.argmax(axis=1)], np.nan)),
        })
    for k, u in (("hs", "m"), ("tm02", "s"), ("tm01", "s"), ("te", "s"), ("tp", "s")):
        ds[k].attrs["units"] = u
    ds.attrs.update({k: efth.attrs[k] for k in ("source", "sha256", "format") if k in efth.attrs})
    return ds
