"""Static equilibrium of the jacket held at a sway offset, in the time domain's own
nonlinear forces.

A decay test (section 6.6) holds the jacket at a sway offset y0 on a still vessel and
releases it from rest. Held, the jacket is in equilibrium in every other DOF: heave, roll
and yaw solve

    Q_j(y0, z, phi, psi) = 0,   j = heave, roll, yaw,

with Q the generalised forces of :func:`jls.timedomain.dynamics.deriv` (the exact wire
geometry with slack, gravity, and the tugger lines at their pretension, the vessel and
the jacket at rest); the sway force Q_sway is what holds it. A linear condensation
(z, phi, psi from K alone) leaves the pendulum's second-order lift out: at 3 m it starts
the decay with about 18 600 kN of extra wire tension (sum of the four) and an unbalanced
heave force, at 10 m a heave bounce that slackens wires. Solved by Newton's method on
central-difference Jacobians, from that condensation.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError
from jls.timedomain import dynamics as dyn

#: Newton converges when the step is below these [m, m, rad, rad].
TOLERANCE = np.array([0.0, 1e-10, 1e-12, 1e-12])
#: Central-difference steps of the Jacobian [m, m, rad, rad].
STEP = np.array([1e-4, 1e-4, 1e-6, 1e-6])


def forces(par, q, line_tension=(0.0, 0.0)):
    """Generalised forces (4,) and diagnostics of the jacket at rest at q, still vessel;
    line_tension: the tugger lines' tension states (used with an actuator lag)."""
    x = np.zeros(dyn.N_STATE)
    x[:4] = q
    x[8:10] = line_tension
    dx = np.empty(dyn.N_STATE)
    info = np.empty(dyn.N_INFO)
    dyn.deriv(x, np.zeros(dyn.N_CH), par, dx, info)
    M = np.linalg.inv(par[dyn.P_MINV:dyn.P_MINV + 16].reshape(4, 4))
    return M @ dx[4:8], info


def held_equilibrium(par, K, sway, line_tension=(0.0, 0.0), max_iter=50) -> np.ndarray:
    """q (4,) with q[0] = sway and heave, roll, yaw in static equilibrium (module
    docstring). K: the linear stiffness (4, 4), for the starting point."""
    K = np.asarray(K, float)
    q = np.zeros(4)
    q[0] = float(sway)
    q[1:] = -np.linalg.solve(K[1:, 1:], K[1:, 0] * q[0])
    for _ in range(max_iter):
        f = forces(par, q, line_tension)[0][1:]
        J = np.empty((3, 3))
        for j in range(3):
            dq = np.zeros(4)
            dq[j + 1] = STEP[j + 1]
            J[:, j] = (forces(par, q + dq, line_tension)[0][1:]
                       - forces(par, q - dq, line_tension)[0][1:]) / (2 * STEP[j + 1])
        step = -np.linalg.solve(J, f)
        q[1:] += step
        if np.all(np.abs(step) <= TOLERANCE[1:]):
            return q
    raise InputError("no static equilibrium found at this sway offset (Newton did not converge)",
                     field="timedomain.decay_release_m", value=float(sway))


__all__ = ["held_equilibrium", "forces"]
