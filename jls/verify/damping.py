"""Damping of the reference equivalent to the ROM's, as dashpots solved exactly.

MoorDyn has no linear damping of a body, and a line's internal damping acts on its
stretch rate only: it barely damps the pendulum, and on a hoist wire it would push
when the wire is slack. The ROM's damping is therefore given to the reference as
dashpots: slack lines (no stiffness, internal damping BA) from the jacket to
earth-fixed points far away (:data:`FAR_M`), so each acts along a fixed direction n on
the absolute velocity of its body point b, with the line of action g = [n; b x n]
(a 6-vector about the CoG) and the damping matrix c g g^T.

The target is the damping matrix that gives every mode of the linearised reference
exactly its target ratio and couples no two modes: with the mass-normalised shapes
Phi (Phi^T M Phi = I), C* = Phi^-T diag(2 zeta_j w_j) Phi^-1 (so Phi^T C* Phi is
diagonal). It is built from lines exactly (:func:`design`):

1. the translational block of C* is diagonalised by a rotation: three orthogonal
   directions n_1, n_2, n_3 (on a port/starboard-symmetric jacket: sway, and two
   directions in the surge-heave plane);
2. a line along n_k through b damps translation along n_k and the two rotations about
   the other axes with the levers (b x n_k): the lines along n_k form a "family" whose
   damping on (t_k, r_i, r_j) is sum c (1, h)(1, h)^T, h the two levers. Any 3x3
   positive semi-definite block with a positive (1,1) entry a is such a sum: a
   distribution of levers of total weight a with mean p / a and covariance
   (Q - p p^T / a) / a (p the translation-rotation terms, Q the rotational block),
   realised by four points, mean +/- sqrt(2 lambda) u along the covariance's axes,
   each of weight a / 4;
3. each rotational diagonal term is shared by the two families that reach it (what
   each needs for its coupling terms, plus half the rest).

Large rotational damping needs long levers: lines of action pass up to about 200 m
from the CoG, some below the water line; the dashpot lines are of negligible diameter
and MoorDyn's seabed far below (:mod:`jls.verify.moordyn_model`), so they act in air.

What cannot be built from lines is the diagonal of the rotated translation-rotation
block (a line's n . (b x n) is zero: a dashpot cannot twist along its own axis); on a
port/starboard-symmetric jacket those terms are zero by symmetry. The design records
the part of C* it could not build (``residual``, relative to C*'s norm) and the
linearised ratios it achieves; what the reference achieves is measured by free decays
along each mode (:func:`jls.verify.chapter4.reference_modes`) and compared with the
targets there (:func:`comparable`).

The targets (:func:`targets`): sway, heave, roll and yaw the ROM's ratio of the mode
dominated by the same DOF, surge (the second pendulum mode) the ROM's sway ratio, pitch
the ROM's Rayleigh law (alpha / w + beta w) / 2 at the pitch frequency. Units t, kN, m, s.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

FAR_M = 2000.0
#: a mode misses its target when its achieved ratio is off by more than this fraction
RATIO_TOLERANCE = 0.02
#: a mode above this share of the response variance is named as such in the reason
VARIANCE_SHARE = 0.05
#: the (i, j) rotational indices each translation family reaches, and the signs that map
#: its levers h to the body point b (b x e_k = (., h1, h2) on those indices)
_FAMILY = ((1, 2), (0, 2), (0, 1))


@dataclass(frozen=True)
class Dashpots:
    """Dashpot lines: body points (n, 3) [m, body frame about the CoG], directions
    (n, 3) (unit, toward the fixed end, global), group index (n,) into ``names``, the
    coefficient of each group [kN s/m per line], the target and linearised modal
    damping ratios of the reference's modes (6,), the part of the target damping
    matrix not built (relative Frobenius norm) and the length to the fixed end [m]."""

    points: np.ndarray
    directions: np.ndarray
    group: np.ndarray
    c: np.ndarray
    target_ratio: np.ndarray
    achieved_ratio: np.ndarray
    names: tuple = field(default=())
    residual: float = 0.0
    far_m: float = FAR_M
    rotation: np.ndarray = field(default_factory=lambda: np.eye(3))

    @property
    def c_line(self) -> np.ndarray:
        """Coefficient of each line [kN s/m]."""
        return self.c[self.group]

    def matrix(self) -> np.ndarray:
        """6x6 damping matrix of the dashpots at rest [kN s/m ...] about the CoG, global axes."""
        G = action_vectors(self.points @ self.rotation.T, self.directions)
        return (G.T * self.c_line) @ G


def action_vectors(points, directions) -> np.ndarray:
    """(n, 6) lines of action [n; b x n] of dashpots at body points b along n."""
    return np.concatenate([directions, np.cross(points, directions)], axis=1)


def targets(modes6, rom_period, rom_ratio, rom_dominant, rayleigh=None) -> np.ndarray:
    """Damping-ratio target of each reference mode (see the module docstring).

    rom_period, rom_ratio: (4,) of the ROM's modes; rom_dominant: their dominant DOF
    names; rayleigh: (alpha [1/s], beta [s]) of the ROM, or None.
    """
    by_dof = {d: float(z) for d, z in zip(rom_dominant, rom_ratio)}
    out = np.empty(6)
    for j, dof in enumerate(modes6.dominant):
        if dof in by_dof:
            out[j] = by_dof[dof]
        elif dof == "surge" or rayleigh is None:
            out[j] = by_dof["sway"]
        else:
            a, b = rayleigh
            w = modes6.omega[j]
            out[j] = 0.5 * (a / w + b * w)
    return out


def target_matrix(modes6, target_ratio) -> np.ndarray:
    """C* = Phi^-T diag(2 zeta w) Phi^-1: every mode its ratio, no two modes coupled."""
    Pi = np.linalg.inv(modes6.shapes)
    C = Pi.T @ np.diag(2.0 * np.asarray(target_ratio, float) * modes6.omega) @ Pi
    return 0.5 * (C + C.T)


def _levers(a, p, Q):
    """Four levers (4, 2) and weights (4,) whose sum w (1, h)(1, h)^T has (1,1) entry a,
    first row p and rotational block Q (Q - p p^T / a is made semi-definite)."""
    mu = p / a
    S = (Q - np.outer(p, p) / a) / a
    lam, U = np.linalg.eigh(0.5 * (S + S.T))
    lam = np.clip(lam, 0.0, None)
    pts = [mu + s * np.sqrt(2.0 * lam[i]) * U[:, i] for i in range(2) for s in (1.0, -1.0)]
    return np.array(pts), np.full(4, a / 4.0)


def design(modes6, target_ratio, pose_rotation=None, far_m=FAR_M) -> Dashpots:
    """Dashpot lines giving ``target_ratio`` (6,) to the modes ``modes6`` (module
    docstring). ``pose_rotation``: the body's rotation at the static pose (body points
    are stored in the body frame)."""
    target = np.asarray(target_ratio, float)
    C = target_matrix(modes6, target)
    lam, R = np.linalg.eigh(C[:3, :3])
    if np.linalg.det(R) < 0:
        R[:, 2] = -R[:, 2]
    T = np.zeros((6, 6))
    T[:3, :3] = T[3:, 3:] = R
    Cr = T.T @ C @ T                                   # in the directions n_k
    a, B, Q = np.diag(Cr[:3, :3]), Cr[:3, 3:], Cr[3:, 3:]
    # each rotation's diagonal term: what its two families need, plus half the rest
    need = np.zeros((3, 3))                            # need[k, r]
    for k, (i, j) in enumerate(_FAMILY):
        need[k, i], need[k, j] = B[k, i] ** 2 / a[k], B[k, j] ** 2 / a[k]
    spare = np.clip(np.diag(Q) - need.sum(0), 0.0, None)
    points, directions = [], []
    weights = []
    for k, (i, j) in enumerate(_FAMILY):
        Qk = np.array([[need[k, i] + 0.5 * spare[i], Q[i, j]], [Q[i, j], need[k, j] + 0.5 * spare[j]]])
        h, w = _levers(a[k], B[k, [i, j]], Qk)
        for (h1, h2), wk in zip(h, w):
            b = np.zeros(3)                            # b x e_k = (h1, h2) on (i, j)
            if k == 0:
                b[2], b[1] = h1, -h2
            elif k == 1:
                b[2], b[0] = -h1, h2
            else:
                b[1], b[0] = h1, -h2
            points.append(R @ b)
            directions.append(R[:, k])
            weights.append(wk)
    points, directions, c = np.array(points), np.array(directions), np.array(weights)
    # a line damps alike along n or -n: each far end is put on the upper side (or, level,
    # on the side of its largest component), clear of MoorDyn's seabed
    key = np.where(np.abs(directions[:, 2]) > 1e-6, directions[:, 2],
                   directions[np.arange(len(c)), np.argmax(np.abs(directions), 1)])
    directions = directions * np.where(key < 0, -1.0, 1.0)[:, None]
    G = action_vectors(points, directions)
    built = (G.T * c) @ G
    Rp = np.eye(3) if pose_rotation is None else np.asarray(pose_rotation, float)
    residual = float(np.linalg.norm(built - C) / np.linalg.norm(C))
    return Dashpots(points=points @ Rp, directions=directions, group=np.arange(len(c)), c=c,
                    target_ratio=target, achieved_ratio=modal_ratios(built, modes6),
                    names=tuple(f"n{k + 1}_{m + 1}" for k in range(3) for m in range(4)),
                    residual=residual, far_m=far_m, rotation=Rp)


def modal_ratios(C, modes6) -> np.ndarray:
    """phi^T C phi / (2 w) per mode (mass-normalised shapes)."""
    phi = modes6.shapes
    return np.einsum("im,ij,jm->m", phi, C, phi) / (2 * modes6.omega)


def comparable(target, achieved, variance_share=None,
               tolerance=RATIO_TOLERANCE) -> tuple[bool, str]:
    """Whether the reference is damped as stated: every mode's achieved ratio within
    ``tolerance`` (relative) of its target. A mode that carries little of the response
    (``variance_share``, said in the reason) is held to it too: a verdict "verified" then
    stands on a reference damped as the ROM in every mode. Returns (comparable, the
    reason when not)."""
    target, achieved = np.asarray(target, float), np.asarray(achieved, float)
    share = (np.full(target.shape, np.nan) if variance_share is None
             else np.asarray(variance_share, float))
    miss = np.abs(achieved / target - 1.0)
    bad = [j for j in range(target.size) if not miss[j] <= tolerance]
    if not bad:
        return True, ""
    parts = [f"mode {j + 1} achieved damping ratio {100 * achieved[j]:.3f} % against its target "
             f"{100 * target[j]:.3f} % ({100 * (achieved[j] / target[j] - 1):+.1f} %"
             + ("" if not np.isfinite(share[j]) else
                f"; {100 * share[j]:.1f} % of the sway variance")
             + (", above 5 %" if share[j] > VARIANCE_SHARE else "") + ")" for j in bad]
    return False, ("the reference is not damped as the ROM: " + "; ".join(parts)
                   + f" (tolerance {100 * tolerance:g} % on every mode)")


__all__ = ["Dashpots", "design", "targets", "target_matrix", "action_vectors", "modal_ratios",
           "comparable", "FAR_M", "RATIO_TOLERANCE", "VARIANCE_SHARE"]
