"""The ROM, M q'' + C q' + K q = -Kb q_b (eq. 3.10), in the frequency and time domains.

A tugger pair of slope c (section 6.3, linear, no winch limits) adds c to the sway-sway
damping and c y_f' to the sway load, y_f the fairlead sway (as
:mod:`jls.response.solver`). The time domain is the exact discretisation of the
linear state space for inputs linear between samples (first-order hold), which makes a
record of any step exact to its own sampling; the recursion is compiled (numba).
Units t, kN, m, s, rad.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy.linalg import expm


def _matrices(plant, c_tugger=0.0):
    M, K, Kb = (np.asarray(a, float) for a in (plant.M, plant.K, plant.Kb))
    C = np.array(plant.C, float)
    C[0, 0] += c_tugger
    return M, C, K, Kb


def transfer(plant, omega, c_tugger=0.0, fairlead_sway=None) -> np.ndarray:
    """q per unit hinge input, (n_w, 4 q, 4 q_b) complex; with a tugger, the fairlead
    sway per unit input (n_w, 4) (default: the fairlead moves with the hinge sway)."""
    M, C, K, Kb = _matrices(plant, c_tugger)
    omega = np.atleast_1d(np.asarray(omega, float))
    out = np.empty((omega.size, 4, 4), complex)
    for n, w in enumerate(omega):
        rhs = -Kb.astype(complex)
        if c_tugger:
            f = np.array([1.0, 0, 0, 0]) if fairlead_sway is None else np.asarray(fairlead_sway)[n]
            rhs[0] += 1j * w * c_tugger * f
        out[n] = np.linalg.solve(K - w ** 2 * M + 1j * w * C, rhs)
    return out


def relative_sway_transfer(plant, omega, c_tugger=0.0) -> np.ndarray:
    """(y - y_b) per unit hinge sway y_b, the ROM's harmonic-test quantity."""
    return transfer(plant, omega, c_tugger)[:, 0, 0] - 1.0


def discretise(plant, dt, c_tugger=0.0):
    """Ad (8, 8), B0, B1 (8, 5) with x_{n+1} = Ad x_n + B0 u_n + B1 u_{n+1}, x = [q, q'],
    u = [q_b (4), y_f'] (first-order hold)."""
    M, C, K, Kb = _matrices(plant, c_tugger)
    Mi = np.linalg.inv(M)
    A = np.zeros((8, 8))
    A[:4, 4:] = np.eye(4)
    A[4:, :4] = -Mi @ K
    A[4:, 4:] = -Mi @ C
    B = np.zeros((8, 5))
    B[4:, :4] = -Mi @ Kb
    B[4:, 4] = Mi[:, 0] * c_tugger
    n, m = 8, 5
    big = np.zeros((n + 2 * m, n + 2 * m))
    big[:n, :n] = A * dt
    big[:n, n:n + m] = B * dt
    big[n:n + m, n + m:] = np.eye(m)
    E = expm(big)
    Ad, G1, G2 = E[:n, :n], E[:n, n:n + m], E[:n, n + m:]
    return np.ascontiguousarray(Ad), np.ascontiguousarray(G1 - G2), np.ascontiguousarray(G2)


@njit(cache=True, nogil=True)
def _recur(Ad, B0, B1, x0, u, out):
    n, ns, ni = u.shape[0], Ad.shape[0], u.shape[1]
    for i in range(ns):
        out[0, i] = x0[i]
    for k in range(n - 1):
        for i in range(ns):
            acc = 0.0
            for j in range(ns):
                acc += Ad[i, j] * out[k, j]
            for j in range(ni):
                acc += B0[i, j] * u[k, j] + B1[i, j] * u[k + 1, j]
            out[k + 1, i] = acc
    return out


def simulate(plant, dt, qb, *, fairlead_sway=None, c_tugger=0.0, x0=None) -> np.ndarray:
    """State (n, 8) = [q, q'] of the ROM driven by q_b (n, 4) sampled every dt [s] from
    rest (or from ``x0``); ``fairlead_sway`` (n,) [m] feeds the tugger."""
    qb = np.ascontiguousarray(qb, float)
    n = qb.shape[0]
    u = np.zeros((n, 5))
    u[:, :4] = qb
    if c_tugger and fairlead_sway is not None:
        u[:, 4] = np.gradient(np.asarray(fairlead_sway, float), dt)
    Ad, B0, B1 = discretise(plant, dt, c_tugger)
    x0 = np.zeros(8) if x0 is None else np.asarray(x0, float)
    return _recur(Ad, B0, B1, x0, u, np.empty((n, 8)))


def relative(state, qb) -> np.ndarray:
    """(n, 4) y - y_b, z - z_b, phi - phi_b, psi - psi_b."""
    return state[:, :4] - np.asarray(qb, float)


def condensed_release(plant, sway) -> np.ndarray:
    """[q, q'] held at a sway offset with heave, roll and yaw in static equilibrium."""
    K = np.asarray(plant.K, float)
    x = np.zeros(8)
    x[0] = sway
    x[1:4] = -np.linalg.solve(K[1:, 1:], K[1:, 0] * sway)
    return x


__all__ = ["transfer", "relative_sway_transfer", "discretise", "simulate", "relative",
           "condensed_release"]
