"""Rigid-body transfer of vessel RAOs to points on the hull (small angles, full 3-D).

For a point at lever arm r = (dx, dy, dz) from the RAO reference point the
translation RAO is u_P = u + theta x r, i.e.::

    x_P = surge + pitch*dz - yaw*dy
    y_P = sway  + yaw*dx   - roll*dz
    z_P = heave + roll*dy  - pitch*dx

which contains the study's eq. 3.1 (section 3.2.1) for the hinge:
H_sway,B = H_sway + H_yaw dx - H_roll dz and H_heave,B = H_heave + H_roll dy
- H_pitch dx. Rotations are the same at every point of a rigid hull.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.vessel.rao import DOF_UNITS, DOFS, validate_rao

#: Hinge centroid B of the lift beams relative to the vessel CoG (study, section 3.2.1), m.
HINGE_POSITION_M = (-215.263, 1.0, 99.998)
#: Tugger fairleads sit this far below the hinge (study, section 6.3.2), m.
FAIRLEAD_DROP_M = 82.5
#: ... and this far either side of the hinge, transversely (DESIGN.md), m.
FAIRLEAD_HALF_SPAN_M = 37.5

AXES = ("x", "y", "z")
DOF_B = ("sway", "heave", "roll", "yaw")


def _lever(r, field: str) -> np.ndarray:
    try:
        r = np.asarray(r, dtype=float)
    except (TypeError, ValueError):
        raise InputError("a position must be three numbers (x, y, z) in m", field=field,
                         value=r) from None
    if r.shape != (3,) or not np.all(np.isfinite(r)):
        raise InputError("a position must be three finite numbers (x, y, z) in m",
                         field=field, value=np.asarray(r).tolist())
    return r


def _translation(ds: xr.Dataset, r: np.ndarray) -> np.ndarray:
    """(omega, wave_direction, 3) complex translation RAO at lever arm r."""
    rao = ds["rao"].values
    u = rao[..., 0:3]
    theta = rao[..., 3:6]
    return u + np.cross(theta, r)


def point_motion(ds: xr.Dataset, r) -> xr.DataArray:
    """Translation RAOs (m/m) of a point at lever arm ``r`` from the reference point.

    Returns a DataArray (omega, wave_direction, axis=["x", "y", "z"]).
    """
    validate_rao(ds)
    r = _lever(r, "r")
    da = xr.DataArray(
        _translation(ds, r), dims=("omega", "wave_direction", "axis"),
        coords={"omega": ds["omega"], "wave_direction": ds["wave_direction"],
                "axis": list(AXES)},
        name="point_motion",
        attrs={"units": "m/m", "long_name": "translation RAO of a point on the hull",
               "lever_arm_m": r.tolist(),
               "method": "rigid body, small angles: u + theta x r",
               "phase_convention": ds.attrs["phase_convention"]})
    da["axis"].attrs.update(long_name="vessel axis (x forward, y port, z up)", units="1")
    return da


def hinge_excitation(ds: xr.Dataset, r_hinge=HINGE_POSITION_M) -> xr.DataArray:
    """Hinge excitation q_b = [y_B, z_B, roll, yaw] RAOs, the plant's base input.

    Returns DataArray ``qb`` (omega, wave_direction, dof_b=["sway", "heave",
    "roll", "yaw"]) in m/m and rad/m (eq. 3.1 of the study).
    """
    validate_rao(ds)
    r = _lever(r_hinge, "r_hinge")
    trans = _translation(ds, r)
    rao = ds["rao"].values
    values = np.stack([trans[..., 1], trans[..., 2],
                       rao[..., DOFS.index("roll")], rao[..., DOFS.index("yaw")]], axis=-1)
    da = xr.DataArray(
        values, dims=("omega", "wave_direction", "dof_b"),
        coords={"omega": ds["omega"], "wave_direction": ds["wave_direction"],
                "dof_b": list(DOF_B),
                "dof_b_units": ("dof_b", ["m/m", "m/m", "rad/m", "rad/m"])},
        name="qb",
        attrs={"units": "m/m (sway, heave); rad/m (roll, yaw)",
               "long_name": "hinge excitation RAO q_b = [y_b, z_b, phi_b, psi_b]",
               "hinge_position_m": r.tolist(),
               "method": "rigid body, small angles (study eq. 3.1)",
               "phase_convention": ds.attrs["phase_convention"]})
    da["dof_b"].attrs.update(long_name="hinge degree of freedom", units="1")
    return da


def fairlead_motion(ds: xr.Dataset, r_hinge=HINGE_POSITION_M, drop: float = FAIRLEAD_DROP_M,
                    half_span: float = FAIRLEAD_HALF_SPAN_M) -> xr.DataArray:
    """Translation RAOs of the two tugger fairleads at r_hinge + (0, +/-half_span, -drop).

    Returns a DataArray (omega, wave_direction, side=["port", "starboard"],
    axis) with the fairlead positions in coordinate ``position_m``.
    """
    validate_rao(ds)
    r_b = _lever(r_hinge, "r_hinge")
    for name, value in (("drop", drop), ("half_span", half_span)):
        if not np.isfinite(value) or value < 0:
            raise InputError("must be a finite non-negative length in m", field=name,
                             value=value)
    positions = np.array([r_b + (0.0, half_span, -drop), r_b + (0.0, -half_span, -drop)])
    values = np.stack([_translation(ds, p) for p in positions], axis=2)
    da = xr.DataArray(
        values, dims=("omega", "wave_direction", "side", "axis"),
        coords={"omega": ds["omega"], "wave_direction": ds["wave_direction"],
                "side": ["port", "starboard"], "axis": list(AXES),
                "position_m": (("side", "axis"), positions)},
        name="fairlead_motion",
        attrs={"units": "m/m", "long_name": "translation RAO of the tugger fairleads",
               "hinge_position_m": r_b.tolist(), "drop_m": float(drop),
               "half_span_m": float(half_span),
               "method": "rigid body, small angles: u + theta x r",
               "phase_convention": ds.attrs["phase_convention"]})
    da["position_m"].attrs.update(units="m", long_name="fairlead position from the reference point")
    return da


def shift_reference_point(ds: xr.Dataset, r) -> xr.Dataset:
    """The same RAOs referred to a new reference point at lever arm ``r``.

    Use it to move WAMIT RAOs from the body origin to the CoG (the project's
    reference point). ``reference_point_m`` becomes old + r.
    """
    validate_rao(ds)
    r = _lever(r, "r")
    out = ds.copy()
    values = ds["rao"].values.copy()
    values[..., 0:3] = _translation(ds, r)
    out["rao"] = (ds["rao"].dims, values, ds["rao"].attrs)
    old = np.asarray(ds.attrs["reference_point_m"], float)
    out.attrs["reference_point_m"] = (old + r).tolist()
    out.attrs["reference_point_shift_m"] = r.tolist()
    out = out.assign_coords(dof_units=("dof", list(DOF_UNITS)))
    return validate_rao(out)

from jls.vessel.rao import interp_rao, make_rao_dataset


def channel_transfer(motion: xr.Dataset, heading_deg, omega) -> np.ndarray:
    """(N_CH, n_w) complex RAOs of the excitation channels (see
    :data:`jls.timedomain.dynamics.CHANNELS`) at frequencies omega, from the vessel-motion
    dataset of :func:`jls.stages.vessel_motion.vessel_motion` (amplitude and phase interpolation)."""
    mo = motion.sel(heading=[float(heading_deg)])
    rao = make_rao_dataset(mo["omega"].values, np.radians(mo["heading"].values),
                           mo["rao"].transpose("omega", "heading", "vessel_dof").values,
                           reference_point_m=motion.attrs.get("reference_point_m", (0, 0, 0)))
    rao = interp_rao(rao, omega)
    hinge_m = tuple(motion.attrs["hinge_m"])
    off = motion.attrs["fairlead_offset_m"]
    qb = hinge_excitation(rao, hinge_m).isel(wave_direction=0).transpose("dof_b", "omega").values
    fl = fairlead_motion(rao, hinge_m, drop=-off[2], half_span=off[1]).isel(wave_direction=0)
    fl = fl.transpose("side", "axis", "omega").values.reshape(6, -1)
    iw = 1j * np.asarray(omega, float)
    return np.concatenate([qb, fl, iw * fl], axis=0)


