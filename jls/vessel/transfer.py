"""Rigid-body transfer of vessel RAOs to points on the hull (small angles, full 3-D).

For a point at lever arm r = (dx, dy, dz) from the RAO reference point the
translation RAO is u_P = u + theta x r, i.e.::

    x_P = surge + pitch*dz - yaw*dy
    y_P = sway  + yaw*dx   - roll*dz
    z_P = heave + roll*dy  - pitch*dx

which contains the study's eq. 3.1 (section 3.2.1) for the hinge:
H_sway,B = H_sway + H_yaw dx - H_roll dz and H_heave,B = H_heave + H_roll dy
- H_pitch dx. Rotations are the same at every point of a rigid hull.

**One transfer, after the interpolation.** :func:`motion_on_grid` is the one owner of
the hinge and fairlead motions on any frequency grid (the response's refined grid, the
screening's, the tugger loads', the time domain's wave components): the vessel's six
RAOs are interpolated per DOF, in amplitude and unwrapped phase, onto the grid, and
only then carried to the hinge and fairleads. The other order (interpolating the hinge
motion) is wrong between the RAO's frequencies wherever the DOFs that sum at the hinge
(sway, yaw x 215 m, roll x 100 m) have different phases: amplitude and phase
interpolation does not commute with that sum (oblique seas above all, and coarse
files). The stored ``hinge`` and ``fairlead`` of ``vessel_motion.nc`` are the same
transfer on the RAO's own frequencies, for inspection and the report.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.vessel.rao import DOF_UNITS, DOFS, interp_rao, make_rao_dataset, validate_rao

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
               "long_name": "hinge excitation [y_b, z_b, phi_b, psi_b]",
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
        attrs={"units": "m/m", "long_name": "tugger fairlead translation",
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



@dataclass(frozen=True)
class GridMotion:
    """Hinge and fairlead motions on a frequency grid, per heading.

    omega (n_w,) rad/s; headings (n_h,) deg; hinge (n_h, n_w, 4) complex q_b =
    [y_b, z_b, phi_b, psi_b] in m/m and rad/m; fairlead (n_h, n_w, 2, 3) complex
    translations of the port and starboard fairleads (x, y, z) in m/m.
    """

    omega: np.ndarray
    headings: np.ndarray
    hinge: np.ndarray
    fairlead: np.ndarray

    @property
    def fairlead_sway(self) -> np.ndarray:
        """(n_h, n_w) mean sway of the two fairleads, the tugger's ship end."""
        return self.fairlead[..., 1].mean(axis=-1)


def vessel_rao(motion: xr.Dataset, headings_deg=None) -> xr.Dataset:
    """The vessel RAO dataset (jls layout) held in a vessel-motion dataset
    (:func:`jls.stages.vessel_motion.vessel_motion`, complex merged), at ``headings_deg``
    (all when None; each must be one of its headings, within 1e-6 deg)."""
    from jls.vessel.headings import select
    mo = motion if headings_deg is None else select(motion, headings_deg)
    return make_rao_dataset(mo["omega"].values, np.radians(mo["heading"].values),
                            mo["rao"].transpose("omega", "heading", "vessel_dof").values,
                            reference_point_m=motion.attrs.get("reference_point_m", (0, 0, 0)),
                            source=str(motion.attrs.get("vessel_source", "")),
                            source_format="vessel_motion")


def carry(rao: xr.Dataset, lever_m, fairlead_offset_m, omega=None, *, method="polar"):
    """The rigid-body transfer of an RAO dataset to the hinge and the fairleads:
    (qb, fairlead) DataArrays of :func:`hinge_excitation` and :func:`fairlead_motion`,
    at the hinge's lever arm ``lever_m`` from the RAO reference point and the port
    fairlead's offset ``fairlead_offset_m`` = (0, half span, -drop) from the hinge.

    With ``omega``, the six vessel RAOs are first interpolated per DOF in amplitude and
    unwrapped phase (:func:`jls.vessel.rao.interp_rao`, never extrapolating) onto it.
    """
    if omega is not None:
        rao = interp_rao(rao, omega, method=method)
    off = np.asarray(fairlead_offset_m, float)
    if off.shape != (3,) or abs(off[0]) > 0:
        raise InputError("the fairlead offset must be (0, half span, -drop) from the hinge",
                         field="fairlead_offset_m", value=off.tolist())
    return (hinge_excitation(rao, lever_m),
            fairlead_motion(rao, lever_m, drop=-off[2], half_span=off[1]))


def motion_on_grid(motion: xr.Dataset, headings_deg, omega, *, method="polar") -> GridMotion:
    """Hinge and fairlead motions of a vessel-motion dataset on the grid ``omega`` at
    ``headings_deg``: the vessel RAOs interpolated per DOF, then carried (:func:`carry`)
    with the dataset's hinge lever arm and fairlead offset. The one transfer of every
    frequency grid of jls."""
    rao = vessel_rao(motion, headings_deg)
    qb, fl = carry(rao, tuple(motion.attrs["hinge_m"]), motion.attrs["fairlead_offset_m"],
                   np.asarray(omega, float), method=method)
    return GridMotion(qb["omega"].values, np.asarray([float(h) for h in headings_deg]),
                      np.ascontiguousarray(qb.transpose("wave_direction", "omega", "dof_b").values),
                      np.ascontiguousarray(fl.transpose("wave_direction", "omega", "side",
                                                        "axis").values))


def channel_transfer(motion: xr.Dataset, heading_deg, omega) -> np.ndarray:
    """(N_CH, n_w) complex RAOs of the excitation channels (see
    :data:`jls.timedomain.dynamics.CHANNELS`: q_b, the fairleads' translations and their
    velocities) at frequencies omega, from a vessel-motion dataset
    (:func:`motion_on_grid`: vessel RAOs interpolated per DOF, then transferred)."""
    gm = motion_on_grid(motion, [float(heading_deg)], omega)
    qb = gm.hinge[0].T                                           # (4, n_w)
    fl = np.moveaxis(gm.fairlead[0], 0, -1).reshape(6, -1)       # (side, axis) x n_w
    iw = 1j * np.asarray(omega, float)
    return np.concatenate([qb, fl, iw * fl], axis=0)
