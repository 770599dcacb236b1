"""Nonlinear equations of motion of the suspended jacket, compiled with numba.

State x = [y, z, phi, psi, y', z', phi', psi', T_port, T_stbd] (the last two only used
with an actuator lag). Forces on the jacket, exact in the geometry:

* hoist wires: anchor a_i = (0, y_b, z_b) + Rb A_i on the moving hinge, padeye
  p_i = (0, y, z - h) + R P_i with R = Rz(psi) Rx(phi) and Rb the same of the hinge;
  tension T_i = k_i max(L_i - L0_i, 0) along e_i = (a_i - p_i) / L_i, so a wire goes
  slack and never pushes;
* gravity M_grav g downwards;
* tugger lines (section 6.3): from the fairlead f_j (rest position plus its motion) to
  the jacket attachment r_j = (0, y, z - h) + R B_j at CoG height, direction
  b_j = (f_j - r_j) / |f_j - r_j|, pay-out velocity u_j = b_j . (f_j' - r_j') (eq. 6.3),
  tension T_j = sat[T_min, T_max](T0 + c/n u_j) (eq. 6.2), instantaneous or through a
  first-order lag T_j' = (T_cmd - T_j) / tau. Contact of a line with its fairlead is
  counted, not modelled (the straight free line no longer holds there): a line shorter
  than the configured minimum length L_min, or whose jacket end has passed the fairlead
  (the line's sway component reversed against the rest geometry; its length then counts
  as zero);
* Rayleigh damping -C q' on the absolute motion, as in the linear model.

Each force F at a point of the jacket enters as the generalised force Q_u = F . dr/dq_u.
The inertia is the linear model's M (the jacket's rotations stay small; the kinematics
of every line use the full rotation).

Integration: classical fourth-order Runge-Kutta at a fixed step dt, with the excitation
sampled at the step ends and midpoints (``exc`` rows 2n, 2n+1, 2n+2). A compiled step
costs about a microsecond, which gives thousands of times real time.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# Layout of the parameter vector built by :func:`pack`.
P_ANCHOR, P_PADEYE, P_K, P_L0 = 0, 12, 24, 28
P_DEPTH, P_WEIGHT, P_MINV, P_C = 32, 33, 34, 50
P_TUG_ON, P_TUG_C, P_TUG_T0, P_TUG_MIN, P_TUG_MAX, P_TUG_TAU = 66, 67, 68, 69, 70, 71
P_FAIRLEAD, P_ATTACH, P_TUG_LMIN = 72, 78, 84
N_PAR = 85
#: Excitation channels (columns of ``exc``).
CHANNELS = ("y_b", "z_b", "phi_b", "psi_b",
            "fairlead_port_x", "fairlead_port_y", "fairlead_port_z",
            "fairlead_stbd_x", "fairlead_stbd_y", "fairlead_stbd_z",
            "fairlead_port_vx", "fairlead_port_vy", "fairlead_port_vz",
            "fairlead_stbd_vx", "fairlead_stbd_vy", "fairlead_stbd_vz")
N_CH = len(CHANNELS)
N_STATE = 10
# Diagnostics written by the force routine.
I_TLINE, I_U, I_CMD, I_TWIRE, I_LLEN = 0, 2, 4, 6, 10
N_INFO = 12
# Statistics returned by :func:`integrate`.
STATS = ("n", "sum", "sumsq", "n_at_max", "n_at_min", "n_at_limit", "power_sum", "power_max",
         "wire_t_min", "wire_t_max", "slack_events", "line_t_min", "line_t_max", "n_slack_steps",
         "n_line_contact", "line_length_min")


def pack(anchors, padeyes, k, l0, cog_depth, weight, M, C, tugger=None, fairleads=None,
         min_line_length=0.0):
    """Parameter vector of one plant and tugger setting.

    anchors, padeyes: (4, 3) m; k, l0: (4,); weight: M_grav g [kN]; M, C: (4, 4);
    tugger: :class:`jls.tugger.setting.Tugger` or None; fairleads: (2, 3) rest positions of the
    port and starboard fairleads relative to the hinge [m]; min_line_length: a tugger line
    shorter than this [m] counts as in contact with its fairlead.
    """
    p = np.zeros(N_PAR)
    p[P_ANCHOR:P_ANCHOR + 12] = np.asarray(anchors, float).ravel()
    p[P_PADEYE:P_PADEYE + 12] = np.asarray(padeyes, float).ravel()
    p[P_K:P_K + 4] = k
    p[P_L0:P_L0 + 4] = l0
    p[P_DEPTH] = cog_depth
    p[P_WEIGHT] = weight
    p[P_MINV:P_MINV + 16] = np.linalg.inv(np.asarray(M, float)).ravel()
    p[P_C:P_C + 16] = np.asarray(C, float).ravel()
    if tugger is not None and tugger.active:
        p[P_TUG_ON] = 1.0
        p[P_TUG_C] = tugger.c / tugger.n_lines
        p[P_TUG_T0] = tugger.pretension
        p[P_TUG_MIN] = tugger.min_force
        p[P_TUG_MAX] = tugger.max_force
        p[P_TUG_TAU] = tugger.lag
        p[P_FAIRLEAD:P_FAIRLEAD + 6] = np.asarray(fairleads, float).ravel()
        hw = tugger.half_width
        p[P_ATTACH:P_ATTACH + 6] = [0.0, hw, 0.0, 0.0, -hw, 0.0]
        p[P_TUG_LMIN] = float(min_line_length)
    return p


@njit(cache=True, nogil=True)
def _point(par, off, cphi, sphi, cpsi, spsi):
    """R P, d(R P)/dphi, d(R P)/dpsi for the body point at par[off:off+3], as nine scalars
    (kept in registers, not stored to a scratch array)."""
    px, py, pz = par[off], par[off + 1], par[off + 2]
    wx = px
    wy = cphi * py - sphi * pz
    wz = sphi * py + cphi * pz
    dwy = -sphi * py - cphi * pz
    dwz = cphi * py - sphi * pz
    return (cpsi * wx - spsi * wy, spsi * wx + cpsi * wy, wz,
            -spsi * dwy, cpsi * dwy, dwz,
            -spsi * wx - cpsi * wy, cpsi * wx - spsi * wy, 0.0)


@njit(cache=True, nogil=True)
def deriv(x, e, par, dx, info):
    """dx/dt of the state x under excitation row e; diagnostics into info."""
    row = np.empty((1, e.shape[0]))
    row[0, :] = e
    _rates(x, row, 0, math.cos(e[2]), math.sin(e[2]), math.cos(e[3]), math.sin(e[3]), par, dx, info)


@njit(cache=True, nogil=True)
def _rates(x, exc, i_row, cpb, spb, cqb, sqb, par, dx, info):
    """:func:`deriv` under the excitation row exc[i_row] (read in place, no row view), the
    cosines and sines of the hinge's roll exc[i_row, 2] and yaw exc[i_row, 3] given as
    (cpb, spb, cqb, sqb): :func:`integrate` forms them once per row."""
    y, z, phi, psi = x[0], x[1], x[2], x[3]
    cphi, sphi, cpsi, spsi = math.cos(phi), math.sin(phi), math.cos(psi), math.sin(psi)
    yb, zb = exc[i_row, 0], exc[i_row, 1]
    depth = par[P_DEPTH]
    Q0 = 0.0
    Q1 = -par[P_WEIGHT]
    Q2 = 0.0
    Q3 = 0.0
    for i in range(4):
        # anchor on the hinge: (0, yb, zb) + Rb A
        ax, ay, az = par[P_ANCHOR + 3 * i], par[P_ANCHOR + 3 * i + 1], par[P_ANCHOR + 3 * i + 2]
        wy = cpb * ay - spb * az
        wz = spb * ay + cpb * az
        anx = cqb * ax - sqb * wy
        any_ = sqb * ax + cqb * wy + yb
        anz = wz + zb
        g0, g1, g2, g3, g4, g5, g6, g7, g8 = _point(par, P_PADEYE + 3 * i, cphi, sphi, cpsi, spsi)
        dx_ = anx - g0
        dy_ = any_ - (y + g1)
        dz_ = anz - (z - depth + g2)
        L = math.sqrt(dx_ * dx_ + dy_ * dy_ + dz_ * dz_)
        T = par[P_K + i] * (L - par[P_L0 + i])
        if T < 0.0:
            T = 0.0
        info[I_TWIRE + i] = T
        fx, fy, fz = T * dx_ / L, T * dy_ / L, T * dz_ / L
        Q0 += fy
        Q1 += fz
        Q2 += fx * g3 + fy * g4 + fz * g5
        Q3 += fx * g6 + fy * g7 + fz * g8
    info[I_TLINE] = 0.0
    info[I_TLINE + 1] = 0.0
    info[I_U] = 0.0
    info[I_U + 1] = 0.0
    info[I_CMD] = 0.0
    info[I_CMD + 1] = 0.0
    info[I_LLEN] = math.inf
    info[I_LLEN + 1] = math.inf
    dx[8] = 0.0
    dx[9] = 0.0
    if par[P_TUG_ON] > 0.0:
        for j in range(2):
            g0, g1, g2, g3, g4, g5, g6, g7, g8 = _point(par, P_ATTACH + 3 * j, cphi, sphi, cpsi, spsi)
            bx = par[P_FAIRLEAD + 3 * j] + exc[i_row, 4 + 3 * j] - g0
            by = par[P_FAIRLEAD + 3 * j + 1] + exc[i_row, 5 + 3 * j] - (y + g1)
            bz = par[P_FAIRLEAD + 3 * j + 2] + exc[i_row, 6 + 3 * j] - (z - depth + g2)
            L = math.sqrt(bx * bx + by * by + bz * bz)
            # the jacket end past its fairlead (the line's sway component reversed against
            # the rest geometry) counts as length zero
            if by * (par[P_FAIRLEAD + 3 * j + 1] - par[P_ATTACH + 3 * j + 1]) <= 0.0:
                info[I_LLEN + j] = 0.0
            else:
                info[I_LLEN + j] = L
            bx, by, bz = bx / L, by / L, bz / L
            # velocity of the attachment point
            vax = g3 * x[6] + g6 * x[7]
            vay = x[4] + g4 * x[6] + g7 * x[7]
            vaz = x[5] + g5 * x[6] + g8 * x[7]
            u = (bx * (exc[i_row, 10 + 3 * j] - vax) + by * (exc[i_row, 11 + 3 * j] - vay)
                 + bz * (exc[i_row, 12 + 3 * j] - vaz))
            cmd = par[P_TUG_T0] + par[P_TUG_C] * u
            info[I_CMD + j] = cmd
            sat = min(max(cmd, par[P_TUG_MIN]), par[P_TUG_MAX])
            if par[P_TUG_TAU] > 0.0:
                T = x[8 + j]
                dx[8 + j] = (sat - T) / par[P_TUG_TAU]
            else:
                T = sat
            info[I_TLINE + j] = T
            info[I_U + j] = u
            Q0 += T * by
            Q1 += T * bz
            Q2 += T * (bx * g3 + by * g4 + bz * g5)
            Q3 += T * (bx * g6 + by * g7 + bz * g8)
    F0, F1, F2, F3 = Q0, Q1, Q2, Q3
    for c in range(4):
        vc = x[4 + c]
        F0 -= par[P_C + c] * vc
        F1 -= par[P_C + 4 + c] * vc
        F2 -= par[P_C + 8 + c] * vc
        F3 -= par[P_C + 12 + c] * vc
    for r in range(4):
        dx[r] = x[4 + r]
        m = P_MINV + 4 * r
        dx[4 + r] = par[m] * F0 + par[m + 1] * F1 + par[m + 2] * F2 + par[m + 3] * F3


@njit(cache=True, nogil=True)
def integrate(x0, exc, dt, n_steps, n_skip, par, record, stats):
    """RK4 over n_steps; exc (2 n_steps + 1, N_CH) sampled every dt / 2.

    record (n_steps + 1, 2) receives the relative sway y - y_b and the absolute sway y
    at every step end; stats (len(STATS),) the statistics over steps >= n_skip (line
    contact: steps with either tugger line shorter than its minimum length or past its
    fairlead). Returns the final state.
    """
    n = x0.shape[0]
    x = x0.copy()
    k1, k2, k3, k4, xt = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    info = np.empty(N_INFO)
    slack = np.zeros(4, np.bool_)
    for s in range(stats.shape[0]):
        stats[s] = 0.0
    stats[8] = np.inf
    stats[9] = -np.inf
    stats[11] = np.inf
    stats[12] = -np.inf
    stats[7] = -np.inf
    stats[15] = np.inf
    tmax = par[P_TUG_MAX]
    tmin = par[P_TUG_MIN]
    record[0, 0] = x[0] - exc[0, 0]
    record[0, 1] = x[0]
    h = 0.5 * dt
    # the hinge angles' cosines and sines, once per excitation row: row 2n + 1 serves k2
    # and k3, row 2n + 2 k4 and the next step's k1
    c2, s2, c3, s3 = math.cos(exc[0, 2]), math.sin(exc[0, 2]), math.cos(exc[0, 3]), math.sin(exc[0, 3])
    for step in range(n_steps):
        i0 = 2 * step
        _rates(x, exc, i0, c2, s2, c3, s3, par, k1, info)
        if step >= n_skip:        # statistics at the step start, from the k1 evaluation
            yr = x[0] - exc[i0, 0]
            stats[0] += 1.0
            stats[1] += yr
            stats[2] += yr * yr
            if par[P_TUG_ON] > 0.0:
                at_max = info[I_CMD] >= tmax or info[I_CMD + 1] >= tmax
                at_min = info[I_CMD] <= tmin or info[I_CMD + 1] <= tmin
                if at_max:
                    stats[3] += 1.0
                if at_min:
                    stats[4] += 1.0
                if at_max or at_min:
                    stats[5] += 1.0
                p = info[I_TLINE] * info[I_U] + info[I_TLINE + 1] * info[I_U + 1]
                stats[6] += p
                stats[7] = max(stats[7], p)
                for j in range(2):
                    stats[11] = min(stats[11], info[I_TLINE + j])
                    stats[12] = max(stats[12], info[I_TLINE + j])
                short = min(info[I_LLEN], info[I_LLEN + 1])
                stats[15] = min(stats[15], short)
                if short <= 0.0 or short < par[P_TUG_LMIN]:
                    stats[14] += 1.0
            any_slack = False
            for i in range(4):
                t = info[I_TWIRE + i]
                stats[8] = min(stats[8], t)
                stats[9] = max(stats[9], t)
                now = t <= 0.0
                if now and not slack[i]:
                    stats[10] += 1.0
                slack[i] = now
                any_slack = any_slack or now
            if any_slack:
                stats[13] += 1.0
        c2, s2, c3, s3 = (math.cos(exc[i0 + 1, 2]), math.sin(exc[i0 + 1, 2]), math.cos(exc[i0 + 1, 3]),
                          math.sin(exc[i0 + 1, 3]))
        for m in range(n):
            xt[m] = x[m] + h * k1[m]
        _rates(xt, exc, i0 + 1, c2, s2, c3, s3, par, k2, info)
        for m in range(n):
            xt[m] = x[m] + h * k2[m]
        _rates(xt, exc, i0 + 1, c2, s2, c3, s3, par, k3, info)
        c2, s2, c3, s3 = (math.cos(exc[i0 + 2, 2]), math.sin(exc[i0 + 2, 2]), math.cos(exc[i0 + 2, 3]),
                          math.sin(exc[i0 + 2, 3]))
        for m in range(n):
            xt[m] = x[m] + dt * k3[m]
        _rates(xt, exc, i0 + 2, c2, s2, c3, s3, par, k4, info)
        for m in range(n):
            x[m] += dt / 6.0 * (k1[m] + 2.0 * k2[m] + 2.0 * k3[m] + k4[m])
        yr = x[0] - exc[i0 + 2, 0]
        record[step + 1, 0] = yr
        record[step + 1, 1] = x[0]
    return x


def generalised_force(par, q, v=None, e=None):
    """Q - C v (the right-hand side before M^-1) at state q, v and excitation row e;
    a Python-side helper for checks (uses the compiled routine)."""
    x = np.zeros(N_STATE)
    x[:4] = q
    if v is not None:
        x[4:8] = v
    e = np.zeros(N_CH) if e is None else np.asarray(e, float)
    dx = np.empty(N_STATE)
    info = np.empty(N_INFO)
    deriv(x, e, par, dx, info)
    M = np.linalg.inv(par[P_MINV:P_MINV + 16].reshape(4, 4))
    return M @ dx[4:8], info


__all__ = ["pack", "deriv", "integrate", "generalised_force", "CHANNELS", "N_CH", "N_STATE",
           "STATS"]
