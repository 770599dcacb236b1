"""Rigid-body RAOs from a Capytaine hydrodynamic dataset (the "bem" extra).

The hydrodynamic dataset (:func:`jls.vessel.bem.solve_hydrodynamics`: added mass,
radiation damping, excitation) is solved once with the rigid-body DOFs about a rotation
centre O; the motion then follows for any mass properties without solving again
(:func:`with_mass_properties`): mass, CoG anywhere (the rigid-body mass matrix about O
carries the offset), radii of gyration about the CoG, hydrostatic stiffness about O. A
linear viscous roll damping of ``roll_damping_ratio`` of critical at the undamped roll
natural frequency (CoG terms, including the roll added inertia there) is added:
B44v = 2 zeta sqrt(C44 (I44 + A44(omega_n))). The RAOs are returned about the CoG in the
jls conventions (Capytaine's exp(-i omega t) conjugated to exp(+i omega t)).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.vessel.rao import make_rao_dataset

CPT_DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")


def capytaine():
    """The capytaine module, imported only when a computation is asked for."""
    try:
        import capytaine as cpt
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("jls.vessel.bem needs Capytaine: pip install 'jls[bem]' "
                          "(or pip install capytaine)") from exc
    return cpt
LABELS = {"influenced_dof": list(CPT_DOFS), "radiating_dof": list(CPT_DOFS)}


def skew(r) -> np.ndarray:
    """S(r) with S(r) v = r x v."""
    x, y, z = np.asarray(r, float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def rigid_body_mass(mass, cog, radii, centre) -> np.ndarray:
    """6x6 mass matrix about ``centre`` of a body of ``mass`` with its CoG at ``cog`` and
    the principal radii of gyration ``radii`` (kxx, kyy, kzz) about the CoG."""
    r = np.asarray(cog, float) - np.asarray(centre, float)
    S = skew(r)
    M = np.zeros((6, 6))
    M[:3, :3] = mass * np.eye(3)
    M[:3, 3:], M[3:, :3] = -mass * S, mass * S
    M[3:, 3:] = np.diag(mass * np.asarray(radii, float) ** 2) + mass * (r @ r * np.eye(3) - np.outer(r, r))
    return M


def to_point(A, r) -> np.ndarray:
    """A 6x6 matrix (..., 6, 6) about a point O expressed about the point O + r (the
    motion of O is u_O = u_P + r x theta)."""
    T = np.eye(6)
    T[:3, 3:] = skew(r)
    return np.einsum("ji,...jk,kl->...il", T, A, T)


def roll_natural_frequency(omega, a44, i44, c44) -> float:
    """Undamped roll natural frequency with frequency-dependent added inertia."""
    residual = c44 - omega ** 2 * (i44 + a44)
    change = np.nonzero(np.diff(np.sign(residual)) != 0)[0]
    if change.size == 0:
        raise InputError("roll natural frequency outside the computed omega range; "
                         "widen omega", field="omega",
                         value=[float(omega[0]), float(omega[-1])])
    i = change[0]
    w = residual[i] / (residual[i] - residual[i + 1])
    return float(omega[i] + w * (omega[i + 1] - omega[i]))


def with_mass_properties(hdb: xr.Dataset, mass, cog, radii, stiffness) -> xr.Dataset:
    """``hdb`` with the ``inertia_matrix`` of the body (about the dataset's rotation
    centre, attrs ``rotation_center_m``), its ``hydrostatic_stiffness`` (6x6 about the same
    point) and the CoG in attrs ``cog_m``."""
    centre = hdb.attrs.get("rotation_center_m", hdb.attrs.get("cog_m", [0.0, 0.0, 0.0]))
    out = hdb.copy()
    out["inertia_matrix"] = xr.DataArray(rigid_body_mass(mass, cog, radii, centre),
                                         dims=list(LABELS), coords=LABELS)
    out["hydrostatic_stiffness"] = xr.DataArray(np.asarray(stiffness, float), dims=list(LABELS),
                                                coords=LABELS)
    out.attrs.update(mass_t=float(mass), cog_m=np.asarray(cog, float).tolist(),
                     radii_of_gyration_m=np.asarray(radii, float).tolist(),
                     rotation_center_m=list(map(float, centre)))
    return out


def rao_from_hydrodynamics(hdb: xr.Dataset, roll_damping_ratio: float) -> xr.Dataset:
    """jls RAO dataset about the CoG from a hydrodynamic dataset with mass properties
    (:func:`with_mass_properties`, or :func:`jls.vessel.bem.solve_hydrodynamics`'s own,
    about the CoG) plus the viscous roll damping (module docstring)."""
    capytaine()
    from capytaine.post_pro.rao import rao as capytaine_rao

    from jls.vessel.transfer import shift_reference_point

    zeta = float(roll_damping_ratio)
    if not np.isfinite(zeta) or not 0 <= zeta < 1:
        raise InputError("roll_damping_ratio must be within [0, 1)",
                         field="roll_damping_ratio", value=roll_damping_ratio)
    centre = np.asarray(hdb.attrs.get("rotation_center_m", hdb.attrs.get("cog_m", [0, 0, 0])), float)
    cog = np.asarray(hdb.attrs.get("cog_m", centre), float)
    r = cog - centre
    omega = hdb["omega"].values
    sel = dict(influenced_dof=list(CPT_DOFS), radiating_dof=list(CPT_DOFS))
    at_cog = {k: to_point(hdb[k].sel(**sel).values, r)
              for k in ("inertia_matrix", "hydrostatic_stiffness", "added_mass", "radiation_damping")}
    i44, c44 = at_cog["inertia_matrix"][3, 3], at_cog["hydrostatic_stiffness"][3, 3]
    # a free-floating body: the hydrostatic roll stiffness about any point is m g GM
    a44 = at_cog["added_mass"][:, 3, 3]
    omega_n = roll_natural_frequency(omega, a44, i44, c44)
    a44_n = float(np.interp(omega_n, omega, a44))
    critical = 2 * np.sqrt(c44 * (i44 + a44_n))
    dissipation = np.zeros((6, 6))
    dissipation[3, 3] = zeta * critical           # a pure roll moment: the same about O
    motion = capytaine_rao(hdb, dissipation=xr.DataArray(dissipation, dims=list(LABELS),
                                                         coords=LABELS))
    motion = motion.sel(radiating_dof=list(CPT_DOFS)).transpose(
        "omega", "wave_direction", "radiating_dof")
    b44_rad = float(np.interp(omega_n, omega, at_cog["radiation_damping"][:, 3, 3]))
    attrs = {}
    for k, v in hdb.attrs.items():           # plain values (a NetCDF round trip gives numpy's)
        v = v.item() if isinstance(v, np.generic) else v.tolist() if isinstance(v, np.ndarray) else v
        if isinstance(v, (str, int, float, list)) and k != "start_of_computation":
            attrs[k] = v
    attrs.update({
        "roll_natural_period_s": float(2 * np.pi / omega_n),
        "roll_added_inertia_at_resonance_t_m2": a44_n,
        "roll_viscous_damping_ratio": zeta,
        "roll_viscous_damping_knms_rad": float(zeta * critical),
        "roll_radiation_damping_ratio_at_resonance": b44_rad / critical,
        "hydrostatic_stiffness_diag": np.diag(at_cog["hydrostatic_stiffness"]).tolist(),
    })
    # Capytaine: Re{X exp(-i omega t)}; jls/WAMIT: Re{X exp(+i omega t)} -> conjugate.
    ds = make_rao_dataset(omega, hdb["wave_direction"].values, np.conj(motion.values),
                          reference_point_m=centre, source="capytaine-bem",
                          source_format="capytaine-bem", attrs=attrs)
    if np.any(r != 0):
        ds = shift_reference_point(ds, r)
        ds.attrs.pop("reference_point_shift_m", None)
    return ds
