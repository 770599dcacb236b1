"""Damping of the reference equivalent to the ROM's, as dashpots.

MoorDyn has no linear damping of a body, and a line's internal damping acts on its
stretch rate only: it barely damps the pendulum, and on a hoist wire it would push
when the wire is slack. The ROM's damping (Rayleigh, on the absolute motion) is
therefore given to the reference as dashpots: slack lines (no stiffness, internal
damping BA) from the jacket to earth-fixed points far away (:data:`FAR_M`), so each
acts along a fixed direction on the absolute velocity of its body point (lever
a = :data:`LEVER_M` from the CoG):

* surge and sway: lines along x and along y at the CoG and a above and below it (three
  heights, so that the pendulum modes, in which translation and rotation combine, can
  be damped apart from the rotational modes they couple with);
* heave: one vertical line at the CoG;
* roll, pitch: a pair of vertical lines at (0, +/-a, 0) and at (+/-a, 0, 0);
* yaw: a pair of transverse lines at (+/-a, 0, 0).

A pair damps its rotation alone (a couple), a line through the CoG its translation
alone, so the damping is diagonal in the CoG's DOFs as the ROM's alpha M part is
(a single off-axis line per rotation, tried, couples sway with yaw and heave with roll
in the damping, and moved the sway phase under harmonic excitation by 0.2 degree
against 0.05 with pairs). Lines whose coefficient comes out zero are left out.

The coefficients are chosen so that every mode of the linearised reference gets the
damping ratio of the ROM's mode it corresponds to: sway, heave, roll and yaw the ROM's
ratio of the mode dominated by the same DOF, surge (the second pendulum mode) the ROM's
sway ratio, pitch the ROM's Rayleigh law (alpha / w + beta w) / 2 at the pitch
frequency. With a dashpot of coefficient c along g (the 6-vector of its line of action)
the modal ratio is zeta_j = sum c (g . phi_j)^2 / (2 w_j) for mass-normalised shapes
phi_j: six linear equations in the coefficients, solved with c >= 0 (non-negative least
squares on the relative errors). What it achieves is measured by free decays
(:func:`jls.verify.chapter4.reference_modes`). Units t, kN, m, s.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import nnls

from jls.verify.statics import Modes6

FAR_M = 2000.0
LEVER_M = 50.0
GROUPS = ("surge", "surge_high", "surge_low", "sway", "sway_high", "sway_low", "heave", "roll",
          "pitch", "yaw")


@dataclass(frozen=True)
class Dashpots:
    """Dashpot lines: body points (n, 3) [m, body frame about the CoG], directions
    (n, 3) (unit, toward the fixed end), group index (n,) into ``names``, the
    coefficient of each group [kN s/m per line], the target and linearised
    modal damping ratios of the reference's modes (6,) and the length to the fixed
    end [m]."""

    points: np.ndarray
    directions: np.ndarray
    group: np.ndarray
    c: np.ndarray
    target_ratio: np.ndarray
    achieved_ratio: np.ndarray
    names: tuple = GROUPS
    far_m: float = FAR_M

    @property
    def c_line(self) -> np.ndarray:
        """Coefficient of each line [kN s/m]."""
        return self.c[self.group]

    def matrix(self) -> np.ndarray:
        """6x6 damping matrix of the dashpots at rest [kN s/m ...]."""
        G = action_vectors(self.points, self.directions)
        return (G.T * self.c_line) @ G


def layout(lever=LEVER_M):
    """Body points, directions and group index (into :data:`GROUPS`) of each line."""
    ex, ey, ez = np.eye(3)
    pts, dirs, grp = [], [], []

    def add(p, d, g):
        pts.append(p)
        dirs.append(d)
        grp.append(GROUPS.index(g))

    for d, name in ((ex, "surge"), (ey, "sway")):
        add((0, 0, 0), d, name)
        add((0, 0, lever), d, name + "_high")
        add((0, 0, -lever), d, name + "_low")
    add((0, 0, 0), ez, "heave")
    for s in (1, -1):
        add((0, s * lever, 0), ez, "roll")
        add((s * lever, 0, 0), ez, "pitch")
        add((s * lever, 0, 0), ey, "yaw")
    return np.array(pts, float), np.array(dirs, float), np.array(grp)


def action_vectors(points, directions) -> np.ndarray:
    """(n, 6) lines of action [n; b x n] of dashpots at body points b along n."""
    return np.concatenate([directions, np.cross(points, directions)], axis=1)


def targets(modes6: Modes6, rom_period, rom_ratio, rom_dominant, rayleigh=None) -> np.ndarray:
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


def design(modes6: Modes6, target_ratio, lever=LEVER_M) -> Dashpots:
    """Dashpot coefficients giving ``target_ratio`` (6,) to the modes ``modes6``."""
    target = np.asarray(target_ratio, float)
    points, directions, group = layout(lever)
    G = action_vectors(points, directions)                  # (n, 6)
    proj = (G @ modes6.shapes) ** 2                          # (n lines, modes)
    A = np.zeros((6, len(GROUPS)))
    for k in range(len(GROUPS)):
        A[:, k] = proj[group == k].sum(0) / (2 * modes6.omega)
    # rows scaled to relative errors; nnls keeps every coefficient non-negative
    c, _ = nnls(A / target[:, None], np.ones(6))
    return Dashpots(points=points, directions=directions, group=group, c=c,
                    target_ratio=target, achieved_ratio=A @ c)


def modal_ratios(C, modes6: Modes6) -> np.ndarray:
    """phi^T C phi / (2 w) per mode (mass-normalised shapes)."""
    phi = modes6.shapes
    return np.einsum("im,ij,jm->m", phi, C, phi) / (2 * modes6.omega)


__all__ = ["Dashpots", "design", "targets", "layout", "action_vectors", "modal_ratios",
           "FAR_M", "LEVER_M", "GROUPS"]
