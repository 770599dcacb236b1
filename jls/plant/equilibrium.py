"""Static equilibrium of the jacket on four wires: tensions and unstretched lengths.

Six rigid-body equations hold the jacket (forces and moments about its CoG):

    sum_i T_i e_i = (0, 0, W),    sum_i P_i x T_i e_i = 0,

with e_i the unit vector from padeye i to anchor i and W = M_grav g. Four wires cannot
satisfy six equations for an arbitrary layout. The four that the model carries (sway
force, heave force, roll and yaw moments) are solved exactly; surge force and pitch
moment, which the 4-DOF model does not carry, are then made as small as the layout
allows (least squares), and what remains is reported. A layout whose surge/pitch
residual exceeds 0.1 % of the weight (the pitch moment taken over the CoG depth as
lever) is not in equilibrium: the jacket would surge or pitch away from the assumed
position when released. A wire whose tension is at or below 1e-6 of the weight
(:data:`SLACK_FRACTION`) is slack: zero in exact arithmetic comes out of the solver as
a round-off of either sign. Vectorised over leading candidate axes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.plant.linearise import wire_vectors

EQUATIONS = ("surge", "sway", "heave", "roll", "pitch", "yaw")
MODELLED = np.array([1, 2, 3, 5])
UNMODELLED = np.array([0, 4])
RESIDUAL_LIMIT = 1e-3
SLACK_FRACTION = 1e-6


@dataclass(frozen=True)
class Equilibrium:
    """Tensions [kN] (..., 4), wire lengths at rest [m] (..., 4) and residuals.

    ``residual`` (..., 6) holds the out-of-balance forces [kN] and moments over the CoG
    depth [kN] in the order of :data:`EQUATIONS`, as fractions of the weight.
    """

    tension: np.ndarray
    length: np.ndarray
    residual: np.ndarray

    @property
    def balanced(self) -> np.ndarray:
        """True where every one of the six equations holds to 0.1 % of the weight."""
        return np.all(np.abs(self.residual) <= RESIDUAL_LIMIT, axis=-1)


def slack(tension, weight):
    """True for each wire at or below :data:`SLACK_FRACTION` of the weight (slack or in
    compression), (..., 4). The one slack rule of jls."""
    return np.asarray(tension, float) <= SLACK_FRACTION * np.asarray(weight, float)[..., None]


def worst_residual(residual):
    """Index into :data:`EQUATIONS` and value of the largest out-of-balance residual."""
    residual = np.asarray(residual, float)
    i = np.argmax(np.abs(residual), axis=-1)
    return i, np.take_along_axis(residual, np.expand_dims(i, -1), -1)[..., 0]


def equilibrium_matrix(anchors, padeyes, cog_depth):
    """A (..., 6, 4) with A T = (forces, moments about the CoG) of the wires."""
    d = wire_vectors(anchors, padeyes, cog_depth)
    length = np.linalg.norm(d, axis=-1)
    e = d / length[..., None]
    moment = np.cross(np.broadcast_to(np.asarray(padeyes, float), e.shape), e)
    lever = np.asarray(cog_depth, float)[..., None, None]
    rows = np.concatenate([e, moment / lever], axis=-1)        # (..., 4 wires, 6)
    return np.swapaxes(rows, -1, -2), length


def solve(anchors, padeyes, cog_depth, weight):
    """Wire tensions holding the jacket: exact in the modelled four equations,
    least squares in surge and pitch. Returns :class:`Equilibrium`."""
    A, length = equilibrium_matrix(anchors, padeyes, cog_depth)
    weight = np.asarray(weight, float)
    b = np.zeros(A.shape[:-1])
    b[..., 2] = weight
    Am, Ao = A[..., MODELLED, :], A[..., UNMODELLED, :]
    bm, bo = b[..., MODELLED], b[..., UNMODELLED]
    # KKT system of  min |Ao T - bo|^2  s.t.  Am T = bm ; pinv copes with the
    # redundant constraints of a port/starboard symmetric layout.
    n = A.shape[:-2]
    kkt = np.zeros(n + (8, 8))
    kkt[..., :4, :4] = 2.0 * np.swapaxes(Ao, -1, -2) @ Ao
    kkt[..., :4, 4:] = np.swapaxes(Am, -1, -2)
    kkt[..., 4:, :4] = Am
    rhs = np.concatenate([2.0 * np.einsum("...ji,...j->...i", Ao, bo), bm], axis=-1)
    sol = np.einsum("...ij,...j->...i", np.linalg.pinv(kkt), rhs)
    tension = sol[..., :4]
    residual = (np.einsum("...ij,...j->...i", A, tension) - b) / weight[..., None]
    return Equilibrium(tension=tension, length=length, residual=residual)
