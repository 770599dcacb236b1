"""NetCDF conventions for every dataset jls writes.

Complex variables are split into ``<name>_re`` and ``<name>_im``; booleans become int8
flags; global attributes carry the jls version, the configuration hash and the
checksums of the input files; files are written atomically (temporary file, then
rename) so that a failed job never leaves a partial result behind.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls import __version__
from jls.io.atomic import write_atomically


def split_complex(ds: xr.Dataset) -> xr.Dataset:
    out = ds.copy()
    for name in list(ds.data_vars):
        da = ds[name]
        if np.iscomplexobj(da.values):
            for part, fn in (("re", np.real), ("im", np.imag)):
                out[f"{name}_{part}"] = da.copy(data=fn(da.values))
                out[f"{name}_{part}"].attrs["long_name"] = (
                    f"{da.attrs.get('long_name', name)} ({'real' if part == 're' else 'imaginary'} part)")
            out = out.drop_vars(name)
        elif da.dtype == bool:
            out[name] = da.astype(np.int8)
            out[name].attrs.update(da.attrs, flag_values=np.array([0, 1], np.int8),
                                   flag_meanings="false true")
    return out


def merge_complex(ds: xr.Dataset) -> xr.Dataset:
    out = ds.copy()
    for name in list(ds.data_vars):
        if name.endswith("_re") and name[:-3] + "_im" in ds:
            base = name[:-3]
            out[base] = ds[name] + 1j * ds[base + "_im"]
            out[base].attrs = {k: v for k, v in ds[name].attrs.items() if k != "long_name"}
            out = out.drop_vars([name, base + "_im"])
    return out


def provenance_attrs(config_sha256: str, created_by: str, inputs: dict | None = None) -> dict:
    attrs = {"jls_version": __version__, "config_sha256": config_sha256,
             "created_by": created_by, "Conventions": "CF-1.10"}
    for name, sha in (inputs or {}).items():
        attrs[f"input_sha256_{name}"] = sha
    return attrs


def write(ds: xr.Dataset, path, *, config_sha256: str, created_by: str, inputs=None,
          dataset: str | None = None) -> Path:
    """Write ``ds`` to ``path`` atomically with the project's conventions.

    ``dataset`` names its layout in the registry (``jls/schemas/datasets.yaml``); the
    dataset is checked against it before anything is written.
    """
    path = Path(path)
    if dataset is not None:
        from jls.io import registry
        registry.check(ds, dataset, file=path)
    path.parent.mkdir(parents=True, exist_ok=True)
    out = split_complex(ds)
    out.attrs.update(provenance_attrs(config_sha256, created_by, inputs))
    for name in out.variables:
        for key, value in list(out[name].attrs.items()):
            if isinstance(value, (bool, np.bool_)):
                out[name].attrs[key] = int(value)
    encoding = {name: {"zlib": True, "complevel": 1} for name in out.data_vars
                if out[name].dtype.kind in "fiu"}
    return write_atomically(path, lambda tmp: out.to_netcdf(tmp, engine="netcdf4", encoding=encoding),
                            suffix=".nc.tmp")


def read(path) -> xr.Dataset:
    """Open a jls dataset fully into memory with complex values merged back."""
    with xr.open_dataset(path, engine="netcdf4") as ds:
        return merge_complex(ds.load())
