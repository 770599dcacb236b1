"""Dynamic tension of the hoist wires as a linear output of the plant.

The wire length of eq. 3.6, ``L_i(q, qb) = |(r_hinge + R_b A_i) - (r_cog + R P_i)|``,
is linearised about the static equilibrium: with ``e_i`` the unit vector from padeye to
anchor at rest and ``R = Rz(psi) Rx(phi)``,

    dL_i/dq  = [-e_y, -e_z, -(P_i x e_i)_x, -(P_i x e_i)_z]      (jacket: y, z, phi, psi)
    dL_i/dqb = [+e_y, +e_z, +(A_i x e_i)_x, +(A_i x e_i)_z]      (hinge: y_b, z_b, phi_b, psi_b)

(the first derivatives of eq. 3.9's Hessian in :mod:`jls.plant.linearise`, whose elastic part
is ``sum_i k_i dL_i/dq dL_i/dq^T``). The wire is a linear spring, ``T_i = k_i (L_i -
L0_i)``, so its dynamic tension is

    T_dyn,i = k_i (dL_i/dq . q + dL_i/dqb . qb),

a linear output of the plant: its transfer function per unit wave amplitude follows
from those of q and the hinge, and its statistics at Hs = 1 m scale with Hs like the
motions'. The static tension comes from :mod:`jls.plant.equilibrium` (the plant dataset's
``tension``). A linear tension model cannot go slack: where the dynamic drop exceeds
the static tension the wire would unload and the linear result no longer holds, which
the slack margin states.

Shapes: everything is vectorised over a leading candidate axis; anchors and padeyes
(..., 4 wires, 3), gradients (..., 4 wires, 4 DOFs), wire stiffness (..., 4 wires).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.plant.linearise import wire_vectors
from jls.response.statistics import FIXED_CYCLES_STUDY, unit_statistics

TENSION_VARIABLES = {  # name -> (long name, units)
    "tension_static": ("static wire tension", "kN"),
    "tension_sigma": ("standard deviation of the dynamic wire tension at Hs = 1 m", "kN per m of Hs"),
    "tension_tz_response": ("zero-crossing period of the dynamic wire tension", "s"),
    "tension_n_cycles": ("tension cycles in the exposure", "1"),
    "tension_mpm": ("most probable maximum of the dynamic wire tension at Hs = 1 m", "kN per m of Hs"),
}


def wire_directions(anchors, padeyes, cog_depth):
    """Unit vectors e_i from padeye to anchor at rest (..., 4, 3) and lengths (..., 4) [m]."""
    d = wire_vectors(anchors, padeyes, cog_depth)
    length = np.linalg.norm(d, axis=-1)
    return d / length[..., None], length


def length_gradients(anchors, padeyes, cog_depth):
    """dL_i/dq and dL_i/dqb at rest, each (..., 4 wires, 4 DOFs) in m/m and m/rad.

    anchors (..., 4, 3) relative to the hinge, padeyes (..., 4, 3) relative to the CoG,
    cog_depth (...) [m]; see the module docstring for the formulae.
    """
    e, _ = wire_directions(anchors, padeyes, cog_depth)
    padeyes = np.broadcast_to(np.asarray(padeyes, float), e.shape)
    anchors = np.broadcast_to(np.asarray(anchors, float), e.shape)
    pe, ae = np.cross(padeyes, e), np.cross(anchors, e)
    grad_q = -np.stack([e[..., 1], e[..., 2], pe[..., 0], pe[..., 2]], axis=-1)
    grad_qb = np.stack([e[..., 1], e[..., 2], ae[..., 0], ae[..., 2]], axis=-1)
    return grad_q, grad_qb


def dynamic_tension(q, qb, grad_q, grad_qb, k):
    """T_dyn = k (dL/dq . q + dL/dqb . qb) [kN] for displacements (or complex amplitudes).

    q, qb: (..., 4) with the candidate axes leading; grad_q, grad_qb: (..., 4 wires, 4);
    k: (..., 4 wires). Returns (..., 4 wires).
    """
    elong = np.einsum("...id,...d->...i", grad_q, q) + np.einsum("...id,...d->...i", grad_qb, qb)
    return np.asarray(k) * elong


def tension_transfer(Hq, qb, grad_q, grad_qb, k):
    """Transfer functions of the dynamic wire tensions per unit wave amplitude [kN/m].

    Hq: (n_c, ..., n_h, n_w, 4) complex response of q (e.g. (candidate, tugger, heading,
    omega, dof) from :func:`jls.response.solver.transfer_functions`); qb: (n_h, n_w, 4) complex
    hinge RAO; grad_q, grad_qb: (n_c, 4 wires, 4); k: (n_c, 4 wires).
    Returns (n_c, ..., n_h, n_w, 4 wires).
    """
    Hq = np.asarray(Hq)
    qb = np.asarray(qb)
    grad_q, grad_qb, k = (np.asarray(a, float) for a in (grad_q, grad_qb, k))
    n_c = grad_q.shape[0]
    if Hq.shape[0] != n_c or Hq.shape[-3:-1] != qb.shape[:2]:
        raise ValueError(f"shapes do not match: Hq {Hq.shape}, qb {qb.shape}, "
                         f"gradients {grad_q.shape}")
    from_q = np.einsum("c...d,cid->c...i", Hq, grad_q)
    from_b = np.einsum("hwd,cid->chwi", qb, grad_qb)
    from_b = from_b.reshape((n_c,) + (1,) * (Hq.ndim - 4) + from_b.shape[1:])
    return k.reshape((n_c,) + (1,) * (Hq.ndim - 2) + (k.shape[-1],)) * (from_q + from_b)


def tension_statistics(omega, Hq, qb, grad_q, grad_qb, k, tz, gamma=3.3,
                       exposure_s=3 * 3600.0, cycles="response"):
    """Unit-Hs statistics of the dynamic wire tensions, ready for the response dataset.

    omega (n_w,) rad/s; Hq (n_c, ..., n_h, n_w, 4); qb (n_h, n_w, 4); gradients and k as
    in :func:`tension_transfer`; tz (n_tz,) s; cycles "response" or a fixed number.
    Returns a dict of arrays (n_c, ..., n_h, n_tz, 4 wires): ``tension_sigma``,
    ``tension_tz_response``, ``tension_n_cycles``, ``tension_mpm`` (kN per m of Hs, s, 1,
    kN per m of Hs), and ``tension_transfer`` (n_c, ..., n_h, n_w, 4 wires) complex.
    """
    HT = tension_transfer(Hq, qb, grad_q, grad_qb, k)
    stats = unit_statistics(omega, np.moveaxis(HT, -1, -2), tz, gamma, exposure_s, cycles)
    out = {f"tension_{name}": np.moveaxis(v, -2, -1) for name, v in stats.items()}
    out["tension_transfer"] = HT
    return out


def plant_gradients(plant: xr.Dataset):
    """grad_q, grad_qb (candidate, wire, 4) and k (candidate, wire) of a plant dataset
    (variables ``anchor``, ``padeye``, ``cog_depth``, ``wire_stiffness``)."""
    for name in ("anchor", "padeye", "cog_depth", "wire_stiffness"):
        if name not in plant:
            raise ValueError(f"the plant dataset has no '{name}': wire tensions need the "
                             "geometric plant, not one given as matrices")
    anchors = plant["anchor"].transpose("candidate", "wire", "axis").values
    padeyes = plant["padeye"].transpose("candidate", "wire", "axis").values
    grad_q, grad_qb = length_gradients(anchors, padeyes, plant["cog_depth"].values)
    return grad_q, grad_qb, plant["wire_stiffness"].transpose("candidate", "wire").values


def tension_dataset(plant: xr.Dataset, omega, Hq, qb, tz, *, tuggers, headings_deg,
                    gamma=3.3, exposure_h=3.0, cycles="response",
                    with_transfer=False) -> xr.Dataset:
    """Wire-tension statistics in the layout of ``response.nc``, to be merged into it.

    plant: the plant dataset; omega (n_w,) rad/s; Hq (candidate, tugger, heading, omega,
    4) complex response of q; qb (heading, omega, 4) complex hinge RAO; tz (n_tz,) s;
    tuggers: tugger names (the second axis of Hq); headings_deg: the third; cycles
    "response" (N = exposure / Tz of the tension), "fixed" (N = 1000) or a number.

    Variables (all per unit Hs, linear in Hs):

    ============================ ======================================== ==============
    ``tension_static``           candidate, wire                          kN
    ``tension_sigma``            candidate, tugger, heading, tz, wire     kN per m of Hs
    ``tension_tz_response``      candidate, tugger, heading, tz, wire     s
    ``tension_n_cycles``         candidate, tugger, heading, tz, wire     1
    ``tension_mpm``              candidate, tugger, heading, tz, wire     kN per m of Hs
    ``tension_transfer``         candidate, tugger, heading, omega, wire  kN per m of wave
                                                                          amplitude (complex,
                                                                          only with_transfer)
    ============================ ======================================== ==============
    """
    grad_q, grad_qb, k = plant_gradients(plant)
    n_cycles = FIXED_CYCLES_STUDY if cycles == "fixed" else cycles
    stats = tension_statistics(omega, Hq, qb, grad_q, grad_qb, k, tz, gamma,
                               exposure_h * 3600.0, n_cycles)
    dims = ("candidate", "tugger", "heading", "tz", "wire")
    coords = {"candidate": plant["candidate"].values, "tugger": list(tuggers),
              "heading": np.asarray(headings_deg, float), "tz": np.asarray(tz, float),
              "wire": plant["wire"].values}
    ds = xr.Dataset({name: (dims, stats[name]) for name in
                     ("tension_sigma", "tension_tz_response", "tension_n_cycles", "tension_mpm")},
                    coords=coords)
    ds["tension_static"] = plant["tension"].transpose("candidate", "wire")
    if with_transfer:
        ds = ds.assign_coords(omega=np.asarray(omega, float))
        ds["tension_transfer"] = (("candidate", "tugger", "heading", "omega", "wire"),
                                  stats["tension_transfer"])
        ds["tension_transfer"].attrs.update(long_name="dynamic wire tension per unit wave amplitude",
                                            units="kN/m")
    for name, (long_name, unit) in TENSION_VARIABLES.items():
        ds[name].attrs.update(long_name=long_name, units=unit)
    return ds


def dynamic_amplification(static, unit_mpm, hs):
    """DAF = (static + Hs MPM(Hs = 1)) / static of each wire [-] (broadcasting)."""
    return (static + hs * unit_mpm) / static


def slack_margin(static, unit_mpm, hs):
    """Static tension minus the MPM of the tension drop, static - Hs MPM(Hs = 1) [kN].

    Negative: the linear model predicts the wire would go slack in the exposure.
    """
    return static - hs * unit_mpm


__all__ = ["TENSION_VARIABLES", "wire_directions", "length_gradients", "dynamic_tension",
           "tension_transfer", "tension_statistics", "plant_gradients", "tension_dataset",
           "dynamic_amplification", "slack_margin"]
