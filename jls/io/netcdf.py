"""NetCDF conventions for every dataset jls writes.

Complex variables are split into ``<name>_re`` and ``<name>_im``; booleans become int8
flags; global attributes carry the jls version, the configuration hash and the
checksums of the input files; files are written atomically (temporary file, then
rename) so that a failed job never leaves a partial result behind.

Reading checks what is read (:func:`read`, :func:`problem`): the file opens as NetCDF, it
follows its layout in the registry (the dataset is known from the file's name: see
:func:`dataset_of`), it carries the provenance attributes and, when the caller knows it,
the configuration hash it should have been made with. A file that fails is an
:class:`jls.errors.InputError` naming it, never a traceback; the workflow checks every
existing dataset when it is parsed and rebuilds a bad one (:mod:`jls.config.intermediates`).

Warnings for a report's first page are kept in a dataset's ``warnings`` attribute, one
a line (:func:`warnings_of`, :func:`add_warnings`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls import __version__
from jls.errors import InputError
from jls.io import xarray_start  # noqa: F401  (before any dataset: see there)
from jls.io.atomic import write_atomically

#: global attributes every dataset jls writes carries (:func:`provenance_attrs`)
PROVENANCE = ("jls_version", "config_sha256", "created_by")
#: the engine every NetCDF file is opened and written with (netCDF4 reads NetCDF-3 and
#: NetCDF-4 alike). Naming it skips xarray's guess of the engine, which imports every
#: installed backend first (wavespectra's among them: about 0.4 s in each process).
ENGINE = "netcdf4"


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


#: Compressed variables of at least this size [bytes] are stored in chunks of whole rows
#: of their first dimension, about this size each (:func:`_chunking`).
CHUNK_BYTES = 1 << 20


def _chunking(var) -> dict:
    """HDF5 chunks of ``var`` for compression: whole rows of its first dimension
    (candidate, for the large datasets), about CHUNK_BYTES each, so that a chunk is one
    contiguous block of the array in memory. The library's default chunks cut every
    dimension and gather each chunk strided from the whole array: a 10 000-candidate
    workability.nc took 30 s to write and 10 s to read that way, 12 s and 7 s in rows,
    and is smaller (400 MB instead of 720 MB). The values are the same either way. Small
    variables, and those whose one row exceeds 4 CHUNK_BYTES, keep the default."""
    if var.ndim < 2 or var.nbytes < CHUNK_BYTES or 0 in var.shape:
        return {}
    row = var.nbytes // var.shape[0]
    if row > 4 * CHUNK_BYTES:
        return {}
    return {"chunksizes": (max(1, min(var.shape[0], CHUNK_BYTES // row)), *var.shape[1:])}


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
    encoding = {name: {"zlib": True, "complevel": 1, **_chunking(out[name])} for name in out.data_vars
                if out[name].dtype.kind in "fiu"}
    return write_atomically(path, lambda tmp: out.to_netcdf(tmp, engine=ENGINE, encoding=encoding),
                            suffix=".nc.tmp")


def dataset_of(path) -> str | None:
    """The registry layout a file of the workflow follows, from its name: ``<name>.nc`` for
    a registry name, ``timedomain/<cell>.nc`` a time-domain cell, ``plant_assessed.nc``
    the plant; None for files without a layout of their own (the chunk files)."""
    from jls.io import registry
    path = Path(path)
    if path.parent.name == "timedomain" and path.suffix == ".nc":
        return "timedomain_cell"
    stem = {"plant_assessed": "plant"}.get(path.stem, path.stem)
    return stem if stem in registry.names() else None


def _first_line(exc) -> str:
    text = str(exc).strip()
    return text.splitlines()[0] if text else type(exc).__name__


def header(path) -> dict:
    """Variables (name -> dims), global attributes and the size of a NetCDF file, read
    from its header only (netCDF4); InputError when it does not open as NetCDF."""
    import netCDF4
    path = Path(path)
    try:
        with netCDF4.Dataset(path, "r") as nc:
            variables = {name: tuple(v.dimensions) for name, v in nc.variables.items()}
            attrs = {k: nc.getncattr(k) for k in nc.ncattrs()}
            dims = set(nc.dimensions)
            coords = set(str(attrs.get("coordinates", "")).split())
            for v in nc.variables.values():
                if "coordinates" in v.ncattrs():
                    coords |= set(str(v.getncattr("coordinates")).split())
    except (OSError, ValueError, RuntimeError) as exc:
        raise InputError(f"cannot read the dataset ({_first_line(exc)}): a truncated or corrupt "
                         "file, or not NetCDF", file=path) from None
    data = {n: d for n, d in variables.items() if n not in dims and n not in coords}
    return {"variables": variables, "data": data, "attrs": attrs, "dims": dims}


def layout_problems(head: dict, dataset: str) -> list[str]:
    """How a file's header departs from the registry layout of ``dataset``: missing or
    undeclared variables, other dimensions, missing global attributes."""
    from jls.io import registry
    entry = registry.layout(dataset)
    declared = entry["variables"]
    data = dict(head["data"])
    for name in list(data):                         # complex values, split on writing
        base = name[:-3]
        if name.endswith("_re") and f"{base}_im" in data and base in declared:
            data[base] = data.pop(name)
            data.pop(f"{base}_im")
    problems = []
    missing = [n for n, spec in declared.items() if n not in data and not spec.get("optional")]
    if missing:
        problems.append(f"missing variable(s) {_some(missing)}")
    for name, spec in declared.items():
        if name in data and set(data[name]) != set(spec["dims"]):
            problems.append(f"{name} has dims {data[name]}, expected {tuple(spec['dims'])}")
    undeclared = sorted(set(data) - set(declared))
    if undeclared:
        problems.append(f"undeclared variable(s) {_some(undeclared)}")
    missing = [k for k in list(PROVENANCE) + list(entry.get("attrs", [])) if k not in head["attrs"]]
    if missing:
        problems.append(f"missing global attribute(s) {', '.join(missing)}")
    return problems


def _some(names, n=4) -> str:
    return ", ".join(names[:n]) + (f" and {len(names) - n} more" if len(names) > n else "")


def problem(path, dataset: str | None = None, config_sha256: str | None = None) -> str | None:
    """Why the workflow may not use a dataset file (None when it may): it does not open as
    NetCDF, departs from its registry layout (``dataset``, default from the file name),
    lacks the provenance attributes, or was made with another configuration (its
    ``config_sha256`` differs from the given one)."""
    try:
        head = header(path)
    except InputError as exc:
        return exc.message
    name = dataset if dataset is not None else dataset_of(path)
    missing = [k for k in PROVENANCE if k not in head["attrs"]]
    if missing:
        return f"not a jls dataset (no {', '.join(missing)})"
    if name is not None:
        problems = layout_problems(head, name)
        if problems:
            return (f"does not follow the layout '{name}' of jls/schemas/datasets.yaml: "
                    + "; ".join(problems[:3]) + ("; ..." if len(problems) > 3 else ""))
    if config_sha256 is not None and str(head["attrs"]["config_sha256"]) != config_sha256:
        return (f"made with another configuration (config_sha256 "
                f"{str(head['attrs']['config_sha256'])[:12]}..., this one's {config_sha256[:12]}...)")
    return None


def read(path, dataset: str | None = None, config_sha256: str | None = None) -> xr.Dataset:
    """Open a jls dataset fully into memory with complex values merged back, after the
    checks of :func:`problem` (layout from the file name unless ``dataset`` is given; the
    configuration hash only when ``config_sha256`` is given). A bad file is an
    InputError naming it."""
    why = problem(path, dataset, config_sha256)
    if why is not None:
        raise InputError(f"{why}; the workflow rebuilds it on its next run", file=path)
    try:
        with xr.open_dataset(path, engine=ENGINE) as ds:
            return merge_complex(ds.load())
    except (OSError, ValueError, RuntimeError, KeyError) as exc:
        raise InputError(f"cannot read the dataset ({_first_line(exc)}): a truncated or corrupt "
                         "file; the workflow rebuilds it on its next run", file=path) from None


def warnings_of(ds: xr.Dataset) -> list[str]:
    """The warnings a dataset carries for a report's first page (attribute ``warnings``,
    one a line; absent or empty: none)."""
    text = ds.attrs.get("warnings", "")
    if isinstance(text, (list, tuple, np.ndarray)):
        return [str(t) for t in text if str(t).strip()]
    return [line for line in str(text).splitlines() if line.strip()]


def add_warnings(ds: xr.Dataset, lines) -> xr.Dataset:
    """Append warnings (one line each) to ``ds.attrs["warnings"]``, keeping their order
    and dropping repeats; sets the attribute (possibly empty) in any case."""
    have = warnings_of(ds)
    for line in lines:
        line = " ".join(str(line).split())
        if line and line not in have:
            have.append(line)
    ds.attrs["warnings"] = "\n".join(have)
    return ds
