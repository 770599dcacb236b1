"""The one RAO dataset layout of jls: construction, validation, interpolation, NetCDF I/O.

Layout (see docs/vessel.md)::

    <xarray.Dataset>
    Dimensions:  omega (ascending, rad/s), wave_direction (rad), dof (6)
    Data:        rao (omega, wave_direction, dof) complex128
    attrs:       reference_point_m, heading_convention, phase_convention,
                 source, source_sha256, source_format, ...

Conventions (fixed for the whole project):

* vessel frame x forward, y to port, z up; the RAOs give the motion of the
  reference point (translations) and the rotations of the hull about it;
* ``wave_direction`` is the direction of propagation relative to +x (WAMIT):
  0 following seas, pi/2 beam seas travelling toward +y, pi head seas;
* motion x(t) = Re{rao * A * exp(i omega t)} for a wave elevation
  Re{A exp(i omega t)} at the reference point: the phase is a lead on the
  wave crest at the origin;
* translations m/m, rotations rad/m.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.atomic import write_atomically
from jls.io.hashing import file_sha256
from jls.io.netcdf import ENGINE

DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
DOF_UNITS = ("m/m", "m/m", "m/m", "rad/m", "rad/m", "rad/m")
HEADING_CONVENTION = (
    "wave_direction is the direction of wave propagation relative to the vessel +x axis "
    "(x forward, y to port, z up), counter-clockwise seen from above (WAMIT convention): "
    "0 = following seas, pi/2 = beam seas travelling toward +y (from starboard), "
    "pi = head seas")
PHASE_CONVENTION = (
    "motion(t) = Re{rao * A * exp(+i omega t)} for an incident wave elevation "
    "Re{A exp(+i omega t)} at the reference point (WAMIT convention); arg(rao) is the "
    "phase lead of the motion on the wave crest at the reference point")
REFERENCE_POINT_NOTE = (
    "reference_point_m is the point the RAOs refer to (translations of that point, "
    "rotations about it), in the coordinates of the source model; lever arms given to "
    "jls.vessel.transfer are measured from this point along the vessel axes")

_REQUIRED_ATTRS = ("reference_point_m", "heading_convention", "phase_convention",
                   "source", "source_sha256", "source_format")


def make_rao_dataset(omega, wave_direction, rao, *, reference_point_m=(0.0, 0.0, 0.0),
                     source: str = "", source_sha256: str = "", source_format: str = "",
                     attrs: dict | None = None, file=None) -> xr.Dataset:
    """Build and validate an RAO dataset from plain arrays.

    ``rao`` has shape (len(omega), len(wave_direction), 6) in the DOF order of
    :data:`DOFS`; ``omega`` in rad/s (sorted here), ``wave_direction`` in rad.
    """
    omega = np.asarray(omega, dtype=float)
    wave_direction = np.asarray(wave_direction, dtype=float)
    values = np.asarray(rao, dtype=complex)
    order = np.argsort(omega, kind="stable")
    ds = xr.Dataset(
        {"rao": (("omega", "wave_direction", "dof"), values[order])},
        coords={"omega": omega[order], "wave_direction": wave_direction,
                "dof": list(DOFS), "dof_units": ("dof", list(DOF_UNITS))},
    )
    ds.attrs.update({
        "title": "vessel motion RAOs",
        "reference_point_m": [float(v) for v in np.asarray(reference_point_m, float)],
        "reference_point_note": REFERENCE_POINT_NOTE,
        "frame": "vessel frame: x forward, y to port, z up",
        "heading_convention": HEADING_CONVENTION,
        "phase_convention": PHASE_CONVENTION,
        "source": str(source),
        "source_sha256": str(source_sha256),
        "source_format": str(source_format),
    })
    if attrs:
        ds.attrs.update(attrs)
    _set_var_attrs(ds)
    validate_rao(ds, file=file)
    return ds


def _set_var_attrs(ds: xr.Dataset) -> None:
    """The layout's attributes, in the file format's unit spelling (m/m, rad/s); where the
    vessel-motion dataset holds the same quantity, its registry entry has the same unit and
    long name (tests/test_registry.py checks it)."""
    ds["omega"].attrs.update(units="rad/s", long_name="wave angular frequency")
    ds["wave_direction"].attrs.update(units="rad", long_name="wave direction of propagation",
                                      convention=HEADING_CONVENTION)
    ds["dof"].attrs.update(units="1", long_name="rigid-body degree of freedom of the vessel")
    ds["dof_units"].attrs.update(units="1", long_name="units of the vessel RAO per degree of freedom")
    ds["rao"].attrs.update(units="m/m (surge, sway, heave); rad/m (roll, pitch, yaw)",
                           long_name="vessel RAO at its reference point",
                           convention=PHASE_CONVENTION)


def validate_rao(ds: xr.Dataset, *, file=None) -> xr.Dataset:
    """Check an RAO dataset against the layout; raise InputError naming the fault."""
    if not isinstance(ds, xr.Dataset) or "rao" not in ds:
        raise InputError("not an RAO dataset: no variable 'rao'", file=file, field="rao")
    da = ds["rao"]
    if tuple(da.dims) != ("omega", "wave_direction", "dof"):
        raise InputError("rao must have dims (omega, wave_direction, dof)", file=file,
                         field="rao.dims", value=tuple(da.dims))
    if tuple(str(d) for d in ds["dof"].values) != DOFS:
        raise InputError(f"dof must be {list(DOFS)}", file=file, field="dof",
                         value=[str(d) for d in ds["dof"].values])
    if not np.iscomplexobj(da.values):
        raise InputError("rao must be complex", file=file, field="rao", value=str(da.dtype))
    omega = ds["omega"].values
    if omega.size < 2 or not np.all(np.isfinite(omega)) or np.any(omega <= 0):
        raise InputError("omega must hold at least two finite positive values", file=file,
                         field="omega", value=omega.tolist()[:5])
    if np.any(np.diff(omega) <= 0):
        i = int(np.argmax(np.diff(omega) <= 0))
        raise InputError("omega must be strictly ascending (no duplicates)", file=file,
                         field="omega", value=float(omega[i + 1]))
    heading = ds["wave_direction"].values
    if heading.size < 1 or not np.all(np.isfinite(heading)):
        raise InputError("wave_direction must be finite", file=file, field="wave_direction",
                         value=heading.tolist())
    if np.unique(heading).size != heading.size:
        raise InputError("duplicate wave_direction", file=file, field="wave_direction",
                         value=np.degrees(heading).round(6).tolist())
    bad = ~np.isfinite(da.values)
    if bad.any():
        i, j, k = (int(v[0]) for v in np.nonzero(bad))
        raise InputError("non-finite RAO value", file=file,
                         field=f"rao[omega={omega[i]:.6g}, wave_direction={heading[j]:.6g}, "
                               f"dof={DOFS[k]}]", value=complex(da.values[i, j, k]))
    missing = [a for a in _REQUIRED_ATTRS if a not in ds.attrs]
    if missing:
        raise InputError("missing dataset attributes", file=file, field="attrs", value=missing)
    ref = np.asarray(ds.attrs["reference_point_m"], dtype=float)
    if ref.shape != (3,) or not np.all(np.isfinite(ref)):
        raise InputError("reference_point_m must be three finite numbers", file=file,
                         field="reference_point_m", value=ds.attrs["reference_point_m"])
    return ds


def frequency_range(ds: xr.Dataset) -> tuple[float, float]:
    """(omega_min, omega_max) in rad/s covered by the dataset."""
    omega = ds["omega"].values
    return float(omega[0]), float(omega[-1])


def interp_complex(new, old, values, method: str = "polar") -> np.ndarray:
    """Complex ``values`` (omega first) from the grid ``old`` onto ``new``, linearly in
    amplitude and unwrapped phase ("polar") or in real and imaginary parts ("cartesian");
    ``new`` must lie within ``old`` (see :func:`interp_rao`)."""
    values = np.asarray(values)
    flat = values.reshape(len(old), -1)
    if method == "polar":
        amp = np.abs(flat)
        phase = np.unwrap(np.angle(flat), axis=0)
        out = (_interp_columns(new, old, amp)
               * np.exp(1j * _interp_columns(new, old, phase)))
    elif method == "cartesian":
        out = (_interp_columns(new, old, flat.real)
               + 1j * _interp_columns(new, old, flat.imag))
    else:
        raise InputError("method must be 'polar' or 'cartesian'", field="method", value=method)
    return out.reshape((len(new),) + values.shape[1:])


def interp_rao(ds: xr.Dataset, omega, *, method: str = "polar") -> xr.Dataset:
    """Interpolate the RAOs linearly onto a new omega grid; never extrapolate.

    ``method="polar"`` (default) interpolates amplitude and phase unwrapped
    along omega; ``"cartesian"`` interpolates real and imaginary parts.
    Polar is the default because a phasor that turns between two grid points
    (a resonance, a lever-arm phase) keeps its amplitude, whereas the chord
    of re/im interpolation cuts the amplitude and under-predicts a peak; the
    price is near a zero of the amplitude, where the phase is ill-defined but
    the motion is small anyway.
    """
    new = np.atleast_1d(np.asarray(omega, dtype=float))
    if new.ndim != 1 or new.size == 0 or not np.all(np.isfinite(new)):
        raise InputError("omega must be a 1-D array of finite values", field="omega",
                         value=new.tolist()[:5])
    lo, hi = frequency_range(ds)
    tol = 1e-9 * hi
    outside = (new < lo - tol) | (new > hi + tol)
    if outside.any():
        raise InputError(f"omega outside the RAO range [{lo:.6g}, {hi:.6g}] rad/s; "
                         "refusing to extrapolate", field="omega",
                         value=float(new[outside][0]))
    new = np.clip(new, lo, hi)
    values = ds["rao"].values
    out = interp_complex(new, ds["omega"].values, values, method)
    result = ds.drop_vars("rao").drop_dims("omega").assign_coords(omega=new)
    result["rao"] = (("omega", "wave_direction", "dof"), out)
    result = result.transpose("omega", "wave_direction", "dof")
    result.attrs = dict(ds.attrs)
    result.attrs["interpolation"] = f"linear in omega, {method}"
    _set_var_attrs(result)
    return result


def _interp_columns(x_new, x_old, columns):
    idx = np.clip(np.searchsorted(x_old, x_new, side="right") - 1, 0, x_old.size - 2)
    w = ((x_new - x_old[idx]) / (x_old[idx + 1] - x_old[idx]))[:, None]
    return columns[idx] * (1.0 - w) + columns[idx + 1] * w


def mirror_headings(ds: xr.Dataset) -> xr.Dataset:
    """Extend 0..pi headings of a port/starboard-symmetric hull to 0..2pi.

    Reflection in the centreplane maps heading beta to 2pi - beta and flips
    the sign of sway, roll and yaw.
    """
    heading = ds["wave_direction"].values
    if heading.min() < -1e-9 or heading.max() > np.pi + 1e-9:
        raise InputError("mirror_headings needs headings within [0, pi]",
                         field="wave_direction", value=np.degrees(heading).round(3).tolist())
    keep = (heading > 1e-9) & (heading < np.pi - 1e-9)
    sign = xr.DataArray([1, -1, 1, -1, 1, -1], dims="dof", coords={"dof": list(DOFS)})
    mirrored = (ds["rao"].isel(wave_direction=keep) * sign)
    mirrored = mirrored.assign_coords(wave_direction=2 * np.pi - heading[keep])
    rao = xr.concat([ds["rao"], mirrored], dim="wave_direction").sortby("wave_direction")
    out = ds.drop_vars("rao").drop_dims("wave_direction")
    out = out.assign_coords(wave_direction=rao["wave_direction"].values)
    out["rao"] = rao.transpose("omega", "wave_direction", "dof")
    out.attrs = dict(ds.attrs)
    out.attrs["mirrored_headings"] = "headings beyond pi obtained by centreplane symmetry"
    _set_var_attrs(out)
    return validate_rao(out)


def save_rao(ds: xr.Dataset, path) -> Path:
    """Write an RAO dataset to NetCDF, complex values split along dim 'complex' (re, im).

    The split follows capytaine.io.xarray.separate_complex_values, so Capytaine
    and jls read each other's files.
    """
    validate_rao(ds)
    path = Path(path)
    out = ds.copy()
    rao = out["rao"]
    out["rao"] = xr.DataArray(np.stack([rao.values.real, rao.values.imag]),
                              dims=("complex",) + rao.dims, attrs=rao.attrs)
    out = out.assign_coords(complex=["re", "im"])
    out["complex"].attrs.update(long_name="real and imaginary parts of complex values",
                                units="1")
    out.attrs["reference_point_m"] = np.asarray(ds.attrs["reference_point_m"], float)
    encoding = {"rao": {"zlib": True, "complevel": 4}}
    return write_atomically(path, lambda tmp: out.to_netcdf(tmp, engine=ENGINE, encoding=encoding), suffix=".nc.tmp")


def first_line(exc) -> str:
    text = str(exc).strip()
    return text.splitlines()[0] if text else type(exc).__name__


def open_netcdf(path) -> xr.Dataset:
    """A NetCDF file loaded into memory; unreadable files are an InputError."""
    try:
        with xr.open_dataset(path, engine=ENGINE) as raw:
            return raw.load()
    except (OSError, ValueError) as exc:
        raise InputError(f"cannot read NetCDF file: {first_line(exc)}", file=path) from None


def read_rao_netcdf(path) -> xr.Dataset:
    """Read an RAO dataset written by :func:`save_rao` (re/im merged back)."""
    path = Path(path)
    ds = open_netcdf(path)
    if "rao" not in ds:
        raise InputError("no variable 'rao' in the file", file=path, field="rao")
    if "complex" in ds["rao"].dims:
        labels = [str(c) for c in ds["complex"].values]
        if labels != ["re", "im"]:
            raise InputError("complex dimension must be ['re', 'im']", file=path,
                             field="complex", value=labels)
        rao = ds["rao"]
        merged = rao.sel(complex="re") + 1j * rao.sel(complex="im")
        ds = ds.drop_vars(["rao", "complex"])
        ds["rao"] = merged.drop_vars("complex", errors="ignore").transpose(
            "omega", "wave_direction", "dof")
    ds["dof"] = [str(d) for d in ds["dof"].values]
    if "reference_point_m" in ds.attrs:
        ds.attrs["reference_point_m"] = [float(v) for v in
                                         np.atleast_1d(ds.attrs["reference_point_m"])]
    if "dof_units" not in ds.coords:
        ds = ds.assign_coords(dof_units=("dof", list(DOF_UNITS)))
    _set_var_attrs(ds)
    return validate_rao(ds, file=path)


def rao_from_records(omega, wave_direction, dof_index, values, line_numbers, *, file,
                     reference_point_m, source_format, attrs=None,
                     omega_label="omega") -> xr.Dataset:
    """Assemble a complete RAO grid from per-row records of a text file.

    Each record is one (omega, wave_direction, dof) value; duplicates,
    missing dofs and an incomplete grid raise InputError naming the line or
    the missing point.
    """
    omega = np.asarray(omega, float)
    heading = np.asarray(wave_direction, float)
    dof_index = np.asarray(dof_index, int)
    values = np.asarray(values, complex)
    lines = np.asarray(line_numbers, int)
    if omega.size == 0:
        raise InputError("no data rows", file=file)
    absent = sorted(set(range(6)) - set(dof_index.tolist()))
    if absent:
        raise InputError("missing dof(s): every file must give all six", file=file,
                         field="dof", value=[DOFS[i] for i in absent])
    omegas, io = np.unique(omega, return_inverse=True)
    headings, ih = np.unique(heading, return_inverse=True)
    grid = np.full((omegas.size, headings.size, 6), np.nan + 0j)
    seen = np.zeros(grid.shape, dtype=int)
    for n in range(values.size):
        key = (io[n], ih[n], dof_index[n])
        if seen[key]:
            raise InputError("duplicate row for the same (frequency, heading, dof)",
                             file=file, field=f"line {lines[n]}",
                             value=(float(omega[n]), float(np.degrees(heading[n])),
                                    DOFS[dof_index[n]]))
        seen[key] = lines[n]
        grid[key] = values[n]
    if not seen.all():
        missing = np.argwhere(seen == 0)

        def label(i, j, k):
            freq = (f"period {2 * np.pi / omegas[i]:.6g} s" if omega_label == "period_s"
                    else f"omega {omegas[i]:.6g} rad/s")
            return f"{freq}, heading {np.degrees(headings[j]):.6g} deg, {DOFS[k]}"

        shown = [label(*m) for m in missing[:5]]
        more = f" and {len(missing) - 5} more" if len(missing) > 5 else ""
        raise InputError(f"incomplete grid (truncated file?): {len(missing)} of {seen.size} "
                         f"(frequency, heading, dof) entries have no row: "
                         f"{'; '.join(shown)}{more}", file=file, field="grid",
                         value=int(len(missing)))
    path = Path(file)
    return make_rao_dataset(omegas, headings, grid, reference_point_m=reference_point_m,
                            source=path.name, source_sha256=file_sha256(path),
                            source_format=source_format, attrs=attrs, file=file)


OMEGA_RANGE_RAD_S = (0.01, 10.0)


ROTATION_RAO_MAX = 0.5          # rad/m: above it the file is in degrees


def check_rao(ds, file=None) -> None:
    """RAO frequencies within 0.01-10 rad/s and rotations plausible in rad/m."""
    omega = ds["omega"].values
    lo, hi = OMEGA_RANGE_RAD_S
    if omega[0] < lo or omega[-1] > hi:
        raise InputError(f"RAO frequencies {omega[0]:.4g}-{omega[-1]:.4g} rad/s lie outside "
                         f"{lo:g}-{hi:g} rad/s: periods or Hz given as rad/s?", file=file,
                         field="omega", value=float(omega[0] if omega[0] < lo else omega[-1]))
    amp = np.abs(ds["rao"].values[..., 3:])
    peak = amp.max(axis=(0, 1))
    k = int(np.argmax(peak))
    if peak[k] > ROTATION_RAO_MAX:
        name = ("roll", "pitch", "yaw")[k]
        raise InputError(f"{name} RAO peaks at {peak[k]:.3g} rad/m ({np.degrees(peak[k]):.3g} "
                         f"deg/m), more than {ROTATION_RAO_MAX} rad/m: the file looks like deg/m "
                         "(declare it: '# rotation_units: deg/m' in a CSV file, ULEN for WAMIT)",
                         file=file, field=f"rao[{name}]", value=float(peak[k]))


