"""Reader for Capytaine RAO results saved to NetCDF.

Accepts the DataArray returned by ``capytaine.post_pro.rao.rao`` saved as a
Dataset variable (default name ``rao``, or the only variable with dims
omega/wave_direction/radiating_dof), in any of the layouts NetCDF forces on
complex numbers:

* split along a ``complex`` dimension labelled ["re", "im"]
  (``capytaine.io.xarray.separate_complex_values``, Capytaine's own export);
* two variables ``<name>_re`` and ``<name>_im``;
* a native complex variable (netCDF4 with auto_complex).

Capytaine's time convention is Re{X exp(-i omega t)}; jls (like WAMIT) uses
exp(+i omega t), so the values are conjugated. Its headings are the direction
of propagation in rad (the jls convention) and its ``radiating_dof`` names
Surge..Yaw are matched case-insensitively. The RAOs refer to the rotation
centre of the Capytaine body (``rotation_center`` if saved, else pass
``reference_point``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.hashing import file_sha256
from jls.vessel.rao import DOFS, make_rao_dataset, open_netcdf

_DOF_DIMS = ("radiating_dof", "dof")


def read_capytaine_nc(path, *, variable: str | None = None,
                      reference_point=None) -> xr.Dataset:
    """Read a Capytaine RAO NetCDF file into the jls RAO dataset."""
    path = Path(path)
    ds = open_netcdf(path)

    da = _complex_rao(ds, variable, path)
    dof_dim = next((d for d in _DOF_DIMS if d in da.dims), None)
    if dof_dim is None:
        raise InputError("no radiating_dof dimension", file=path, field="dims",
                         value=list(da.dims))
    if "omega" not in da.dims:
        if "omega" in da.coords and da["omega"].ndim == 1:
            da = da.swap_dims({da["omega"].dims[0]: "omega"})
        else:
            raise InputError("no omega coordinate (rad/s)", file=path, field="omega",
                             value=list(da.dims))
    if "wave_direction" not in da.dims:
        if "wave_direction" in da.coords and da["wave_direction"].ndim == 0:
            da = da.expand_dims("wave_direction")
        else:
            raise InputError("no wave_direction coordinate", file=path,
                             field="wave_direction", value=list(da.dims))
    extra = [d for d in da.dims if d not in ("omega", "wave_direction", dof_dim)]
    for dim in extra:
        if da.sizes[dim] != 1:
            raise InputError("unexpected extra dimension (select one value first)",
                             file=path, field=dim, value=int(da.sizes[dim]))
        da = da.isel({dim: 0}, drop=True)

    names = [str(n).strip().lower() for n in da[dof_dim].values]
    unknown = [n for n in names if n not in DOFS]
    if unknown:
        raise InputError("unknown radiating_dof name(s)", file=path, field=dof_dim,
                         value=unknown)
    if len(set(names)) != len(names):
        raise InputError("duplicate radiating_dof", file=path, field=dof_dim, value=names)
    missing = [d for d in DOFS if d not in names]
    if missing:
        raise InputError("missing dof(s): all six rigid-body dofs are needed", file=path,
                         field=dof_dim, value=missing)
    da = da.assign_coords({dof_dim: names}).sel({dof_dim: list(DOFS)})
    da = da.transpose("omega", "wave_direction", dof_dim)

    omega = np.asarray(da["omega"].values, float)
    heading = np.asarray(da["wave_direction"].values, float)
    coords = _check_coordinates(ds, da, omega, heading, path)
    values = np.conj(np.asarray(da.values, complex))
    if reference_point is None:
        reference_point, ref_source = _rotation_center(ds, path)
    else:
        ref_source = "given by the caller"
    attrs = {"capytaine_time_convention": "exp(-i omega t) in the file; conjugated on reading",
             "reference_point_source": ref_source, **coords}
    if np.unique(omega).size != omega.size:
        raise InputError("duplicate omega", file=path, field="omega", value=omega.tolist())
    return make_rao_dataset(omega, heading, values, reference_point_m=reference_point,
                            source=path.name, source_sha256=file_sha256(path),
                            source_format="capytaine", attrs=attrs, file=path)


def _complex_rao(ds: xr.Dataset, variable, path) -> xr.DataArray:
    name = variable if variable is not None else _find_variable(ds, path)
    if name in ds:
        da = ds[name]
        if "complex" in da.dims:
            labels = [str(c) for c in da["complex"].values]
            if sorted(labels) != ["im", "re"]:
                raise InputError("complex dimension must be labelled re, im", file=path,
                                 field="complex", value=labels)
            return (da.sel(complex="re") + 1j * da.sel(complex="im")).drop_vars(
                "complex", errors="ignore")
        if np.iscomplexobj(da.values):
            return da
        raise InputError("RAO variable is real: expected a 'complex' dimension, "
                         "<name>_re/<name>_im variables or complex values", file=path,
                         field=name, value=str(da.dtype))
    if f"{name}_re" in ds and f"{name}_im" in ds:
        return ds[f"{name}_re"] + 1j * ds[f"{name}_im"]
    raise InputError("RAO variable not found", file=path, field="variable", value=name)


def _find_variable(ds: xr.Dataset, path) -> str:
    for candidate in ("rao", "RAO"):
        if candidate in ds or f"{candidate}_re" in ds:
            return candidate
    hits = [v for v in ds.data_vars
            if any(d in ds[v].dims for d in _DOF_DIMS) and "influenced_dof" not in ds[v].dims
            and ("omega" in ds[v].dims or "omega" in ds[v].coords)]
    stems = sorted({v[:-3] if v.endswith(("_re", "_im")) else v for v in hits})
    if len(stems) != 1:
        raise InputError("cannot tell which variable holds the RAO; pass variable=",
                         file=path, field="variable", value=list(ds.data_vars))
    return stems[0]


def _rotation_center(ds: xr.Dataset, path):
    if "rotation_center" in ds.variables:
        rc = np.asarray(ds["rotation_center"].values, float).ravel()
        if rc.shape == (3,) and np.all(np.isfinite(rc)):
            return rc.tolist(), "rotation_center in the file"
        raise InputError("rotation_center must be three finite numbers", file=path,
                         field="rotation_center", value=rc.tolist())
    return [0.0, 0.0, 0.0], ("not in the file: assumed at the origin of the Capytaine "
                             "mesh; pass reference_point= to state it")


_UNITS = {"omega": {"rad/s", "rad s-1", "rad.s-1", "radian/s", "rad/sec"},
          "wave_direction": {"rad", "radian", "radians"}}


def _scalar(da, name):
    if name not in da.coords:
        return None
    values = np.atleast_1d(np.asarray(da[name].values, float))
    return values


def _check_coordinates(ds, da, omega, heading, path) -> dict:
    """Honour or refuse what a Capytaine dataset states besides the RAO: the units of omega
    and wave_direction (rad/s and rad), the headings within 0-2 pi (degrees refused), the
    period and freq coordinates against omega, a forward speed (refused: the RAOs would be
    at the encounter frequency of a moving hull, which jls does not model), and the water
    depth and g (kept as attributes; the long-wave check uses the depth)."""
    for name in ("omega", "wave_direction"):
        unit = str(da[name].attrs.get("units", "")).strip().lower()
        if unit and unit not in _UNITS[name]:
            raise InputError(f"{name} is in {unit!r}; Capytaine writes rad/s and rad, and jls "
                             "reads those only", file=path, field=f"{name}.units", value=unit)
    if heading.size and np.abs(heading).max() > 2 * np.pi + 1e-6:
        raise InputError("wave_direction beyond 2 pi: degrees, where Capytaine writes radians",
                         file=path, field="wave_direction",
                         value=np.round(heading, 6).tolist()[:6])
    for name, expect in (("period", 2 * np.pi / omega), ("freq", omega / (2 * np.pi))):
        if name in da.coords and da[name].dims == ("omega",):
            got = np.asarray(da[name].values, float)
            if not np.allclose(got, expect, rtol=1e-6, atol=0.0):
                i = int(np.argmax(np.abs(got - expect) / expect))
                raise InputError(f"the {name} coordinate disagrees with omega (omega "
                                 f"{omega[i]:.6g} rad/s, {name} {got[i]:.6g}): an edited file?",
                                 file=path, field=name, value=float(got[i]))
    speed = _scalar(da, "forward_speed")
    if speed is not None and np.any(np.abs(speed) > 1e-9):
        raise InputError("the RAOs are for a hull moving at a forward speed; jls takes them at "
                         "the wave frequency of a hull at rest (no encounter-frequency shift): "
                         "give zero-speed RAOs", file=path, field="forward_speed",
                         value=float(np.abs(speed).max()))
    out = {}
    depth = _scalar(da, "water_depth")
    if depth is not None:
        d = float(depth[0])
        if not (d > 0):
            raise InputError("water_depth must be positive (inf for deep water)", file=path,
                             field="water_depth", value=d)
        out["water_depth_m"] = d
    g = _scalar(da, "g")
    if g is not None:
        out["capytaine_g"] = float(g[0])
    return out
