"""Linearisation of the four-wire suspension: K and Kb as exact Hessians of V.

Reference study, section 3.3.2, eqs. 3.6-3.9, in the project's frame (origin at the
hinge, x forward, y to port, z up):

    d_i(q, qb) = (r_hinge + R(phi_b, psi_b) A_i) - (r_cog + R(phi, psi) P_i)
    L_i = |d_i|,     R = Rz(psi) Rx(phi)
    V  = M_grav g z + 1/2 sum_i k_i (L_i - L0_i)^2

with q = [y, z, phi, psi] of the jacket CoG (at rest h_drop + z_p below the hinge) and
qb = [y_b, z_b, phi_b, psi_b] of the hinge. Gravity is linear in z and adds nothing to
the Hessian; with T_i = k_i (L_i - L0_i) the wire tension,

    d2V/du dv = sum_i k_i (e.d_u)(e.d_v) + T_i [ (d_u.d_v - (e.d_u)(e.d_v)) / L_i + e.d_uv ]

where e = d/L and d_u, d_uv are the first and second derivatives of d at q = qb = 0.
Everything here is vectorised over any leading "candidate" axes: anchors and padeyes
have shape (..., 4, 3), stiffness and tension (..., 4).
"""

from __future__ import annotations

import numpy as np

DOF = ("sway", "heave", "roll", "yaw")
ROLL, YAW = 2, 3


def _first_derivatives(r):
    """d(R r)/d[y, z, phi, psi] at zero for a point r (..., 3): shape (..., 4, 3)."""
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    zero, one = np.zeros_like(x), np.ones_like(x)
    d_y = np.stack([zero, one, zero], -1)
    d_z = np.stack([zero, zero, one], -1)
    d_phi = np.stack([zero, -z, y], -1)        # e_x cross r
    d_psi = np.stack([-y, x, zero], -1)        # e_z cross r
    return np.stack([d_y, d_z, d_phi, d_psi], -2)


def _second_derivatives(r):
    """d2(R r)/du dv at zero for R = Rz(psi) Rx(phi): shape (..., 4, 4, 3)."""
    x, y, z = r[..., 0], r[..., 1], r[..., 2]
    zero = np.zeros_like(x)
    out = np.zeros(r.shape[:-1] + (4, 4, 3))
    out[..., ROLL, ROLL, :] = np.stack([zero, -y, -z], -1)
    out[..., YAW, YAW, :] = np.stack([-x, -y, zero], -1)
    mixed = np.stack([z, zero, zero], -1)      # Gz Gx r
    out[..., ROLL, YAW, :] = mixed
    out[..., YAW, ROLL, :] = mixed
    return out


def wire_vectors(anchors, padeyes, cog_depth):
    """Wire vectors d_i = A_i - (r_cog + P_i) at rest, pointing from padeye to anchor.

    anchors: (..., 4, 3) relative to the hinge; padeyes: (..., 4, 3) relative to the
    CoG; cog_depth: (...) depth of the CoG below the hinge [m].
    """
    anchors = np.asarray(anchors, float)
    padeyes = np.asarray(padeyes, float)
    cog = np.zeros(np.broadcast_shapes(anchors.shape, padeyes.shape))
    cog[..., 2] = -np.asarray(cog_depth, float)[..., None]
    return anchors - (cog + padeyes)


def stiffness_matrices(anchors, padeyes, cog_depth, k, tension):
    """K (4x4) and Kb (4x4) of eq. 3.9 for one or many geometries.

    Parameters
    ----------
    anchors : (..., 4, 3) top anchors relative to the hinge [m]
    padeyes : (..., 4, 3) padeyes relative to the jacket CoG [m]
    cog_depth : (...) CoG depth below the hinge, h_drop + z_p [m]
    k : (..., 4) axial wire stiffness [kN/m]
    tension : (..., 4) wire tension at rest [kN]

    Returns
    -------
    K, Kb : (..., 4, 4) in kN/m, kN, kN m/rad (rows: q, columns: q or qb).
    """
    d = wire_vectors(anchors, padeyes, cog_depth)
    length = np.linalg.norm(d, axis=-1)
    e = d / length[..., None]
    # d = r_hinge + R_b A - r_cog - R P: jacket terms enter with a minus sign.
    dq = -_first_derivatives(np.broadcast_to(np.asarray(padeyes, float), d.shape))
    dqb = _first_derivatives(np.broadcast_to(np.asarray(anchors, float), d.shape))
    dqq = -_second_derivatives(np.broadcast_to(np.asarray(padeyes, float), d.shape))

    k = np.asarray(k, float)
    t = np.asarray(tension, float)
    gq = np.einsum("...wuc,...wc->...wu", dq, e)        # dL/dq per wire
    gb = np.einsum("...wuc,...wc->...wu", dqb, e)       # dL/dqb per wire
    t_over_l = t / length

    def hessian(da, db, ga, gb_, dab=None):
        geo = np.einsum("...wuc,...wvc->...wuv", da, db) - ga[..., :, None] * gb_[..., None, :]
        h = k[..., None, None] * ga[..., :, None] * gb_[..., None, :] + t_over_l[..., None, None] * geo
        if dab is not None:
            h = h + t[..., None, None] * np.einsum("...wuvc,...wc->...wuv", dab, e)
        return h.sum(axis=-3)

    K = hessian(dq, dq, gq, gq, dqq)
    Kb = hessian(dq, dqb, gq, gb)
    return K, Kb


def potential(q, qb, anchors, padeyes, cog_depth, k, unstretched, m_grav, g):
    """V(q, qb) of eq. 3.8 evaluated exactly (for checks and nonlinear use).

    q, qb: (4,) displacements; other arguments as in :func:`stiffness_matrices` for
    one geometry, ``unstretched`` the unstretched wire lengths L0 [m].
    Returns V in kJ (kN m) relative to the CoG at rest.
    """
    y, z, phi, psi = q
    yb, zb, phib, psib = qb
    r_cog = np.array([0.0, y, z - cog_depth])
    r_hinge = np.array([0.0, yb, zb])
    d = (r_hinge + np.asarray(anchors) @ rotation(phib, psib).T) - (
        r_cog + np.asarray(padeyes) @ rotation(phi, psi).T)
    length = np.linalg.norm(d, axis=-1)
    return m_grav * g * z + 0.5 * np.sum(np.asarray(k) * (length - unstretched) ** 2)


def rotation(phi, psi):
    """R = Rz(psi) Rx(phi) (section 3.3.2)."""
    c, s = np.cos(phi), np.sin(phi)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    c, s = np.cos(psi), np.sin(psi)
    rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return rz @ rx
