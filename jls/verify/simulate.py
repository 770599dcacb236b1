"""Run the reference in MoorDyn under an excitation: the stepping loop.

Each step hands MoorDyn the coupled points' positions and velocities at the step's
start (it moves them linearly over the step) and integrates the body and the lines over
one step ``dt`` with RK4. The tugger lines follow the winch law of :mod:`jls.tugger.setting`
(eq. 6.2, with the limits and the optional first-order lag): at each step's start the
pay-out velocity u = b . (f' - r') of each line is taken from the body's state and the
fairlead's motion, the commanded tension T0 + c/n u is clipped to [T_min, T_max] (and
lagged), and the line's EA is set so that it carries that tension at the length it
reaches at the step's middle (its length plus half a step of its pay-out: within the
step the short line is a soft spring of about T / L, and a tension set at the step's
start would be a damper of T dt / (2 L) along the line, 5.6 % of the detuned rigging's
sway damping at a 0.1-s step; at the middle the step's mean force is the command).
Units t, kN, m, s, rad.
"""

from __future__ import annotations

import ctypes
import math
import sys
import time
from dataclasses import dataclass

import numpy as np

from jls.verify.excitation import Excitation
from jls.verify.moordyn_model import N, Session, tugger_ea
from jls.verify.statics import loads, pose_matrix

CHUNK = 20000


@dataclass(frozen=True)
class Run:
    """A reference run: time (n,) [s]; pose (n, 6) CoG position [m] and body angles
    [rad] (MoorDyn's X-Y-Z); velocity (n, 6) [m/s, rad/s]; wire tension (n, 4) [kN];
    tugger line tension (n, 2) and command (n, 2) [kN] (zeros without a tugger); the
    hinge position (n, 3) [m] and roll and yaw (n, 2) [rad]; the static pose and the
    hinge at rest; wall time [s]."""

    time: np.ndarray
    pose: np.ndarray
    velocity: np.ndarray
    tension: np.ndarray
    tugger_tension: np.ndarray
    tugger_command: np.ndarray
    hinge: np.ndarray
    hinge_angles: np.ndarray
    static_pose: np.ndarray
    hinge_rest: np.ndarray
    wall_time: float

    def relative(self) -> np.ndarray:
        """(n, 4) relative sway, heave [m], roll, yaw [rad] of the jacket to the hinge,
        the ROM's y - y_b, z - z_b, phi - phi_b, psi - psi_b, each about the static
        pose and the hinge at rest."""
        d = self.pose - self.static_pose
        dh = self.hinge - self.hinge_rest
        return np.stack([d[:, 1] - dh[:, 1], d[:, 2] - dh[:, 2], d[:, 3] - self.hinge_angles[:, 0],
                         d[:, 5] - self.hinge_angles[:, 1]], -1)


def run(ref, exc: Excitation, *, pose=None, velocity=None, dt=None) -> Run:
    """Integrate the reference over the excitation's record from ``pose`` (default: the
    static pose) with the body's ``velocity`` (6,) [m/s, rad/s] (default: at rest;
    :func:`set_body_velocity`). ``dt`` must equal the record's step (default)."""
    dt = exc.dt if dt is None else float(dt)
    if abs(dt - exc.dt) > 1e-12 * dt:
        raise ValueError("the reference steps at the excitation's sampling interval")
    pose0 = ref.pose if pose is None else np.asarray(pose, float)
    n = exc.n
    X, V = exc.coupled(ref, 0, min(CHUNK, n))
    n_tip = 12
    tips0 = X[0, :n_tip].reshape(4, 3)
    fl0 = X[0, n_tip:].reshape(2, 3) if ref.tugger is not None else None
    out_pose = np.empty((n, 6))
    out_vel = np.zeros((n, 6))
    out_ten = np.empty((n, 4))
    tug_t = np.zeros((n, 2))
    tug_c = np.zeros((n, 2))
    out_pose[0] = pose0
    if velocity is not None:
        out_vel[0] = velocity
    cog, R = pose_matrix(pose0)
    out_ten[0] = loads(ref, cog, R, tips=tips0).tension
    with Session(ref, pose0, dt, tips0=tips0, fairleads0=fl0) as s:
        import cmoordyn
        step, get_state = cmoordyn.step, cmoordyn.body_get_state
        fairten, set_ea = cmoordyn.line_get_fairlead_tension, cmoordyn.line_set_const_ea
        system, body, wires, tlines = s.system, s.body, s.wires, s.tugger_lines
        tug = ref.tugger
        if velocity is not None and np.any(np.asarray(velocity, float) != 0.0):
            set_body_velocity(s, velocity)
        if tug is not None:
            set_ea = _setter(set_ea, tlines[0], ref.tugger.pretension)
            t0 = tug.pretension
            state_t = [t0, t0]
            gain = tug.c / tug.n_lines
            decay = math.exp(-dt / tug.lag) if tug.lag > 0 else 0.0
            att = [tuple(a) for a in ref.attachments]
            lo, hi = tug.min_force, tug.max_force
            half = 0.5 * dt
        r6, v6 = list(pose0), [float(v) for v in out_vel[0]]
        w0, w1, w2, w3 = wires
        t_start = exc.t0
        wall = time.perf_counter()
        for c0 in range(0, n - 1, CHUNK):
            c1 = min(c0 + CHUNK, n - 1)
            if c0:
                X, V = exc.coupled(ref, c0, c1)
            # the outputs gathered as floats in flat lists (no objects for the garbage
            # collector to track), stored once per chunk
            poses, vels, tens, cmds, held = [], [], [], [], []
            for i in range(c0, c1):
                xi, vi = X[i - c0].tolist(), V[i - c0].tolist()
                if tug is not None:
                    for j, (a, b_) in enumerate(_attachments(r6, v6, att)):
                        k = n_tip + 3 * j
                        bx, by, bz = xi[k] - a[0], xi[k + 1] - a[1], xi[k + 2] - a[2]
                        length = math.sqrt(bx * bx + by * by + bz * bz)
                        u = (bx * (vi[k] - b_[0]) + by * (vi[k + 1] - b_[1]) + bz * (vi[k + 2] - b_[2])) / length
                        cmd = t0 + gain * u
                        sat = min(max(cmd, lo), hi)
                        state_t[j] = sat + (state_t[j] - sat) * decay if decay else sat
                        cmds.append(cmd)
                        held.append(state_t[j])
                        set_ea(tlines[j], tugger_ea(state_t[j], length + half * u))
                step(system, xi, vi, i * dt + t_start, dt)
                r6, v6 = get_state(body)
                poses += r6
                vels += v6
                tens += (fairten(w0), fairten(w1), fairten(w2), fairten(w3))
            out_pose[c0 + 1:c1 + 1] = np.reshape(poses, (-1, 6))
            out_vel[c0 + 1:c1 + 1] = np.reshape(vels, (-1, 6))
            out_ten[c0 + 1:c1 + 1] = np.reshape(tens, (-1, 4))
            if tug is not None:
                tug_c[c0:c1] = np.reshape(cmds, (-1, 2))
                tug_t[c0:c1] = np.reshape(held, (-1, 2))
        wall = time.perf_counter() - wall
    out_ten[1:] /= N
    if tug is not None:
        tug_t[-1], tug_c[-1] = tug_t[-2], tug_c[-2]
    hinge, ang = exc.hinge_pose(ref, 0, n)
    return Run(time=exc.time, pose=out_pose, velocity=out_vel, tension=out_ten, tugger_tension=tug_t,
            tugger_command=tug_c, hinge=hinge, hinge_angles=ang, static_pose=ref.pose.copy(),
               hinge_rest=ref.hinge.copy(), wall_time=wall)


def set_body_velocity(session, velocity) -> None:
    """Give the session's body the velocity (6,) [m/s, rad/s: its CoG's velocity and
    its angular velocity] at its initial pose, which MoorDyn-C's API cannot set (a free
    body starts at rest). The system's serialised state begins with the time scheme's
    state, from which each step starts: per body its count of values (13), its position
    and orientation quaternion (7) and its velocity (6). That block is found by the
    body's position followed by a unit quaternion and six zeros, the velocity written
    in, and the state restored and serialised again, which must hold the velocity
    (else RuntimeError: a MoorDyn whose layout differs). Tested by continuing a run
    from one of its states (tests/test_verify_start.py)."""
    import cmoordyn
    vel = np.asarray(velocity, float).reshape(6)
    raw = bytearray(cmoordyn.serialize(session.system))
    i = _body_block(raw, cmoordyn.body_get_state(session.body)[0][:3])
    raw[8 * (i + 7):8 * (i + 13)] = vel.tobytes()
    cmoordyn.deserialize(session.system, bytes(raw))
    back = bytes(cmoordyn.serialize(session.system))
    got = np.frombuffer(back[8 * (i + 7):8 * (i + 13)], dtype=np.float64)
    if not np.array_equal(got, vel):
        raise RuntimeError(f"MoorDyn's body took the velocity {got.tolist()}, not {vel.tolist()}")


def _body_block(raw, position) -> int:
    """Index (in doubles) of the body's 13 state values in the serialised state ``raw``:
    the first block of a count 13 followed by ``position``, a unit quaternion and six
    zero velocities."""
    a = np.frombuffer(bytes(raw[:8 * (len(raw) // 8)]), dtype=np.float64)
    counts = a.view(np.int64)
    pos = np.asarray(position, float)
    for i in np.flatnonzero(a[:-13] == pos[0]).tolist():
        if (i > 0 and counts[i - 1] == 13 and a[i + 1] == pos[1] and a[i + 2] == pos[2]
                and abs(np.linalg.norm(a[i + 3:i + 7]) - 1.0) < 1e-12 and not np.any(a[i + 7:i + 13])):
            return i
    raise RuntimeError("the body's state was not found in MoorDyn's serialised state")


def _setter(set_ea, line, tension):
    """``set_ea``, made safe: MoorDyn 2.7's Python wrapper returns None from its
    setters without taking a reference to it, so each call drops one of None's
    references and a long run ends in a crash ("deallocating None"). Measured once on
    a call; if the call leaks, every call gives the reference back."""
    before = sys.getrefcount(None)
    set_ea(line, tugger_ea(tension, 1.0))
    leak = before - sys.getrefcount(None)
    if leak <= 0:
        return set_ea
    incref = ctypes.pythonapi.Py_IncRef
    incref.argtypes = [ctypes.py_object]
    incref(None)                                   # the test call's
    none = None

    def safe(ln, ea):
        set_ea(ln, ea)
        for _ in range(leak):
            incref(none)
    return safe


def _attachments(r6, v6, points):
    """Positions and velocities of the body points (body frame) from the body's state,
    the rotation formed once."""
    rx, ry, rz = r6[3], r6[4], r6[5]
    cx, sx, cy, sy, cz, sz = math.cos(rx), math.sin(rx), math.cos(ry), math.sin(ry), math.cos(rz), math.sin(rz)
    # R = Rx Ry Rz
    r00, r01, r02 = cy * cz, -cy * sz, sy
    r10, r11, r12 = sx * sy * cz + cx * sz, -sx * sy * sz + cx * cz, -sx * cy
    r20, r21, r22 = -cx * sy * cz + sx * sz, cx * sy * sz + sx * cz, cx * cy
    wx, wy, wz = v6[3], v6[4], v6[5]
    out = []
    for b in points:
        x = r00 * b[0] + r01 * b[1] + r02 * b[2]
        y = r10 * b[0] + r11 * b[1] + r12 * b[2]
        z = r20 * b[0] + r21 * b[1] + r22 * b[2]
        out.append(((r6[0] + x, r6[1] + y, r6[2] + z),
                    (v6[0] + wy * z - wz * y, v6[1] + wz * x - wx * z, v6[2] + wx * y - wy * x)))
    return out


__all__ = ["Run", "run", "set_body_velocity"]
