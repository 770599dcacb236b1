"""Static state and linearisation of the 6-DOF reference (pure numpy, no MoorDyn).

The reference's loads are those MoorDyn computes for the model :mod:`jls.verify.model`
writes: each hoist wire a spring of stiffness k between its lift-beam tip and its padeye
that pulls only (T = k max(L - L0, 0)), the jacket's weight M_grav g at the CoG, half of
each wire's own weight at its padeye (a one-segment line lumps its mass on its two end
nodes) and the tugger lines at their pretension. The pose is the CoG position [m] and
the MoorDyn body angles [rad] (R = Rx(rx) Ry(ry) Rz(rz), intrinsic X-Y-Z), in the
reference frame: x forward, y to port, z up, origin on the water line below the hinge.

Here the pose is solved in all six equations (Newton on the exact loads), and the
6x6 stiffness about it is taken by central differences of the exact loads with small
rotations about the global axes (the generalised forces of those rotations are the
moments about the CoG); with the 6x6 mass matrix it gives the reference's modes, surge
and pitch included. Units t, kN, m, s, rad.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

DOF6 = ("surge", "sway", "heave", "roll", "pitch", "yaw")


def rotation(rx, ry, rz) -> np.ndarray:
    """R = Rx(rx) Ry(ry) Rz(rz), MoorDyn's body orientation (Euler X-Y-Z, intrinsic)."""
    cx, sx, cy, sy, cz, sz = np.cos(rx), np.sin(rx), np.cos(ry), np.sin(ry), np.cos(rz), np.sin(rz)
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return Rx @ Ry @ Rz


def rodrigues(v) -> np.ndarray:
    """Rotation matrix of the rotation vector v [rad]."""
    v = np.asarray(v, float)
    a = np.linalg.norm(v)
    if a < 1e-300:
        return np.eye(3)
    k = v / a
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(a) * Kx + (1 - np.cos(a)) * Kx @ Kx


def euler_from_matrix(R) -> np.ndarray:
    """(rx, ry, rz) with R = Rx Ry Rz (inverse of :func:`rotation`, |ry| < pi/2)."""
    ry = np.arcsin(np.clip(R[0, 2], -1.0, 1.0))
    rx = np.arctan2(-R[1, 2], R[2, 2])
    rz = np.arctan2(-R[0, 1], R[0, 0])
    return np.array([rx, ry, rz])


@dataclass(frozen=True)
class Loads:
    """Net load on the jacket (6,) [kN, kN m about the CoG], wire tensions (4,) [kN]
    and stretched wire lengths (4,) [m] at one pose."""

    net: np.ndarray
    tension: np.ndarray
    length: np.ndarray


def loads(ref, cog, R, tips=None, fairleads=None, external=None) -> Loads:
    """Loads on the jacket at CoG position ``cog`` (3,) and orientation ``R`` (3, 3).

    tips: (4, 3) lift-beam tip positions (default: at rest); fairleads: (2, 3) tugger
    fairleads (default: at rest); external: (6,) extra load [kN, kN m].
    """
    tips = ref.tips_rest if tips is None else np.asarray(tips, float)
    arm = ref.padeyes @ R.T                                   # (4, 3) padeye - CoG
    d = tips - (cog + arm)
    length = np.linalg.norm(d, axis=1)
    tension = ref.k * np.maximum(length - ref.L0, 0.0)
    f = (tension / length)[:, None] * d
    wire_weight = 0.5 * ref.wire_mass_per_length * ref.L0 * ref.g          # per padeye, kN
    f[:, 2] -= wire_weight
    net = np.zeros(6)
    net[:3] = f.sum(0)
    net[3:] = np.cross(arm, f).sum(0)
    net[2] -= ref.m_grav * ref.g
    if ref.tugger is not None and ref.tugger.active:
        fl = ref.fairleads_rest if fairleads is None else np.asarray(fairleads, float)
        att = ref.attachments @ R.T
        b = fl - (cog + att)
        fb = ref.tugger.pretension * b / np.linalg.norm(b, axis=1)[:, None]
        net[:3] += fb.sum(0)
        net[3:] += np.cross(att, fb).sum(0)
    if external is not None:
        net += np.asarray(external, float)
    return Loads(net=net, tension=tension, length=length)


def pose_matrix(pose):
    """CoG position and rotation matrix of a pose (x, y, z, rx, ry, rz)."""
    pose = np.asarray(pose, float)
    return pose[:3], rotation(*pose[3:])


def solve_pose(ref, start=None, *, fixed=None, external=None, tips=None, tol=1e-10, max_iter=50):
    """Static pose (6,) where the net load vanishes.

    start: initial pose (default: the ROM's CoG position, unrotated); fixed: dict
    {dof index: value} of coordinates held (their equations are dropped, e.g. a sway
    release held at an offset); external: (6,) load [kN, kN m]. Newton iteration with
    a central-difference Jacobian; converges to ``tol`` of the weight.
    """
    pose = np.array(ref.cog_rest.tolist() + [0.0, 0.0, 0.0]) if start is None else np.array(start, float)
    fixed = dict(fixed or {})
    for i, v in fixed.items():
        pose[i] = v
    free = [i for i in range(6) if i not in fixed]
    weight = ref.m_grav * ref.g
    scale = np.array([1, 1, 1, ref.lever, ref.lever, ref.lever])

    def residual(p):
        return loads(ref, *pose_matrix(p), tips=tips, external=external).net / scale

    for _ in range(max_iter):
        r = residual(pose)[free]
        if np.max(np.abs(r)) <= tol * weight:
            return pose
        J = np.empty((len(free), len(free)))
        for a, i in enumerate(free):
            h = 1e-6 if i < 3 else 1e-6 / ref.lever
            e = np.zeros(6)
            e[i] = h
            J[:, a] = (residual(pose + e)[free] - residual(pose - e)[free]) / (2 * h)
        pose[free] -= np.linalg.solve(J, r)
    raise RuntimeError(f"the static pose of the reference did not converge (residual {np.max(np.abs(r)):.3e} kN)")


def stiffness(ref, pose, h_lin=1e-4) -> np.ndarray:
    """6x6 stiffness [kN/m, kN, kN m/rad] about ``pose`` by central differences of the
    exact loads (translations of the CoG, small rotations about the global axes);
    symmetrised (it is symmetric at equilibrium)."""
    cog, R = pose_matrix(pose)
    K = np.empty((6, 6))
    for j in range(6):
        h = h_lin if j < 3 else h_lin / ref.lever
        out = []
        for s in (1.0, -1.0):
            c, Rj = cog.copy(), R
            if j < 3:
                c[j] += s * h
            else:
                v = np.zeros(3)
                v[j - 3] = s * h
                Rj = rodrigues(v) @ R
            out.append(loads(ref, c, Rj).net)
        K[:, j] = -(out[0] - out[1]) / (2 * h)
    return 0.5 * (K + K.T)


def mass(ref, pose) -> np.ndarray:
    """6x6 mass matrix about the CoG [t, t m^2]: the body's inertial mass and inertia
    and half of each wire's mass at its padeye (one segment per wire)."""
    _, R = pose_matrix(pose)
    M = np.zeros((6, 6))
    M[:3, :3] = ref.m_kin * np.eye(3)
    M[3:, 3:] = R @ np.diag(ref.inertia) @ R.T
    m_end = 0.5 * ref.wire_mass_per_length * ref.L0
    for m, r in zip(m_end, ref.padeyes @ R.T):
        S = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
        M[:3, :3] += m * np.eye(3)
        M[:3, 3:] += -m * S
        M[3:, :3] += m * S
        M[3:, 3:] += -m * S @ S
    return M


@dataclass(frozen=True)
class Modes6:
    """Undamped modes of the linearised reference, longest period first: omega (6,)
    [rad/s], shapes (6 dof, 6 modes) mass-normalised, energy_fraction (6 modes, 6 dof),
    dominant (6,) DOF names (:data:`DOF6`)."""

    omega: np.ndarray
    shapes: np.ndarray
    energy_fraction: np.ndarray
    dominant: tuple

    @property
    def period(self) -> np.ndarray:
        return 2 * np.pi / self.omega

    def index(self, dof: str) -> int:
        """The mode with the largest kinetic-energy share of ``dof``."""
        return int(np.argmax(self.energy_fraction[:, DOF6.index(dof)]))


def modes(K, M) -> Modes6:
    """Solve K phi = w^2 M phi (M symmetric positive definite)."""
    L = np.linalg.cholesky(M)
    Li = np.linalg.inv(L)
    lam, v = np.linalg.eigh(Li @ K @ Li.T)
    order = np.argsort(lam)
    lam, v = lam[order], v[:, order]
    shapes = Li.T @ v
    omega = np.sqrt(np.where(lam > 0, lam, np.nan))
    ke = shapes * (M @ shapes)
    frac = (ke / ke.sum(0)).T
    frac = np.clip(frac, 0.0, None)
    return Modes6(omega=omega, shapes=shapes, energy_fraction=frac,
                  dominant=tuple(DOF6[i] for i in np.argmax(frac, axis=1)))


__all__ = ["DOF6", "rotation", "rodrigues", "euler_from_matrix", "Loads", "loads", "pose_matrix",
           "solve_pose", "stiffness", "mass", "Modes6", "modes"]
