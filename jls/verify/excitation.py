"""What moves the reference and the ROM: the vessel's six DOFs or a hinge record.

An :class:`Excitation` is a record sampled every ``dt`` from ``t0`` and turns it, a
chunk at a time, into the positions and velocities of the four lift-beam tips and the
two tugger fairleads (the reference's coupled points), the hinge's pose (for the
relative motions), and the ROM's input q_b = [y_b, z_b, phi_b, psi_b] with the fairlead
sway.

* ``kind="vessel"``: surge, sway, heave [m], roll, pitch, yaw [rad] at the point the
  vessel's motions refer to; every point on the hull at lever r from it moves rigidly,
  ``kinematics="rigid"`` by x = u + (R - I) r with R = Rz(yaw) Ry(pitch) Rx(roll) (the
  usual seakeeping order), ``"linear"`` by x = u + theta x r (small angles). The ROM
  gets the hinge by eq. 3.1 (linear) from the same record.
* ``kind="hinge"``: the ROM's own input q_b; tips and fairleads move with the hinge as
  the ROM has them: (0, y_b, z_b) + Rz(psi_b) Rx(phi_b) r about the hinge.

Velocities are central differences of the positions (second order; the records are
sampled at the integration step). Units m, s, rad.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.errors import InputError

KINDS = ("vessel", "hinge")
KINEMATICS = ("rigid", "linear")


def _rot_zyx(roll, pitch, yaw):
    """(n, 3, 3) R = Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    R = np.empty(np.shape(roll) + (3, 3))
    R[..., 0, 0] = cy * cp
    R[..., 0, 1] = cy * sp * sr - sy * cr
    R[..., 0, 2] = cy * sp * cr + sy * sr
    R[..., 1, 0] = sy * cp
    R[..., 1, 1] = sy * sp * sr + cy * cr
    R[..., 1, 2] = sy * sp * cr - cy * sr
    R[..., 2, 0] = -sp
    R[..., 2, 1] = cp * sr
    R[..., 2, 2] = cp * cr
    return R


def _rot_zx(phi, psi):
    """(n, 3, 3) R = Rz(psi) Rx(phi), the ROM's hinge rotation (eq. 3.6)."""
    return _rot_zyx(phi, np.zeros_like(phi), psi)


@dataclass(frozen=True)
class Excitation:
    """A motion record (see the module docstring): ``data`` (n, 6) for a vessel record
    or (n, 4) for a hinge record, sampled at t0 + i dt."""

    kind: str
    data: np.ndarray
    dt: float
    t0: float = 0.0
    kinematics: str = "rigid"

    def __post_init__(self):
        if self.kind not in KINDS:
            raise InputError(f"must be one of {', '.join(KINDS)}", field="kind", value=self.kind)
        if self.kinematics not in KINEMATICS:
            raise InputError(f"must be one of {', '.join(KINEMATICS)}", field="kinematics",
                             value=self.kinematics)
        width = 6 if self.kind == "vessel" else 4
        if np.ndim(self.data) != 2 or np.shape(self.data)[1] != width:
            raise InputError(f"a {self.kind} record needs {width} columns", field="data",
                             value=np.shape(self.data))

    @property
    def n(self) -> int:
        return int(self.data.shape[0])

    @property
    def time(self) -> np.ndarray:
        return self.t0 + self.dt * np.arange(self.n)

    # -- points on the hull --------------------------------------------------------
    def _points(self, ref, rel, i0, i1):
        """Positions (m, p, 3) of hull points given relative to the hinge (p, 3)."""
        d = self.data[i0:i1]
        rel = np.asarray(rel, float)
        if self.kind == "hinge":
            R = _rot_zx(d[:, 2], d[:, 3])
            shift = np.stack([np.zeros(len(d)), d[:, 0], d[:, 1]], -1)
            return ref.hinge + shift[:, None, :] + np.einsum("nij,pj->npi", R, rel)
        lever = ref.vessel_lever + rel                               # (p, 3) from the reference point
        if self.kinematics == "rigid":
            R = _rot_zyx(d[:, 3], d[:, 4], d[:, 5])
            move = np.einsum("nij,pj->npi", R, lever) - lever
        else:
            move = np.cross(d[:, None, 3:6], lever[None, :, :])
        return ref.hinge + rel + d[:, None, :3] + move

    def coupled(self, ref, i0, i1):
        """Coupled-point positions and velocities (m, 3 p) for samples i0..i1-1: the
        tips, then (with a tugger) the fairleads."""
        rel = ref.anchors if ref.tugger is None else np.concatenate([ref.anchors, ref.fairleads])
        lo, hi = max(i0 - 1, 0), min(i1 + 1, self.n)
        pos = self._points(ref, rel, lo, hi).reshape(hi - lo, -1)
        vel = np.gradient(pos, self.dt, axis=0) if hi - lo > 1 else np.zeros_like(pos)
        s = slice(i0 - lo, i0 - lo + (i1 - i0))
        return pos[s], vel[s]

    def hinge_pose(self, ref, i0, i1):
        """Hinge position (m, 3) and its roll and yaw (m, 2) [rad], to refer the
        jacket's motion to (relative motions)."""
        pos = self._points(ref, np.zeros((1, 3)), i0, i1)[:, 0, :]
        d = self.data[i0:i1]
        ang = d[:, 2:4] if self.kind == "hinge" else d[:, [3, 5]]
        return pos, ang

    # -- the ROM's input -----------------------------------------------------------
    def rom_input(self, vessel_lever, fairlead_offset=(0.0, 37.5, -82.5)):
        """q_b (n, 4) [m, m, rad, rad] and the fairlead sway (n,) [m] for the ROM: eq.
        3.1 from a vessel record (linear; ``vessel_lever`` the hinge from the motion
        reference point, ``fairlead_offset`` the port fairlead from the hinge), the
        record itself for a hinge record (the fairleads then sway with the hinge)."""
        d = self.data
        if self.kind == "hinge":
            return d.copy(), d[:, 0].copy()
        dx, dy, dz = np.asarray(vessel_lever, float)
        qb = np.stack([d[:, 1] + d[:, 5] * dx - d[:, 3] * dz,
                       d[:, 2] + d[:, 3] * dy - d[:, 4] * dx, d[:, 3], d[:, 5]], -1)
        off = np.asarray(fairlead_offset, float)
        # mean of the port and starboard fairleads (their y offsets cancel)
        fx, fz = dx + off[0], dz + off[2]
        y_f = d[:, 1] + d[:, 5] * fx - d[:, 3] * fz
        return qb, y_f


def harmonic_hinge(amplitude, period, dt, duration, dof=0, phase=0.0) -> Excitation:
    """Hinge record q_b[dof] = amplitude sin(w t + phase) over [0, duration]."""
    n = int(round(duration / dt)) + 1
    t = dt * np.arange(n)
    d = np.zeros((n, 4))
    d[:, dof] = amplitude * np.sin(2 * np.pi / period * t + phase)
    return Excitation("hinge", d, dt)


def still(dt, duration) -> Excitation:
    """A vessel at rest for ``duration`` [s]."""
    return Excitation("hinge", np.zeros((int(round(duration / dt)) + 1, 4)), dt)


def vessel_record(motion, hs, tz, heading_deg, *, gamma=3.3, duration_s=3 * 3600.0,
                  transient_s=0.0, dt=0.02, seed=1, kinematics="rigid") -> Excitation:
    """The vessel's six DOFs in one irregular sea state, sampled every ``dt`` from
    -transient_s to duration_s.

    motion: the vessel-motion dataset (:func:`jls.stages.vessel_motion.vessel_motion`);
    the sea is jls's realisation (:func:`jls.timedomain.sea.realise`: JONSWAP, seeded
    phases, one repeat period over the recorded duration), so the same seed gives the
    same waves as jls's own time domain.
    """
    from jls.timedomain.sea import realise
    from jls.vessel.rao import interp_rao, make_rao_dataset
    om = motion["omega"].values
    real = realise(hs, tz, gamma, (om.min(), om.max()), dt, duration_s, transient_s, seed)
    mo = motion.sel(heading=[float(heading_deg)])
    rao = make_rao_dataset(om, np.radians(mo["heading"].values),
                           mo["rao"].transpose("omega", "heading", "vessel_dof").values,
                           reference_point_m=motion.attrs.get("reference_point_m", (0, 0, 0)))
    H = interp_rao(rao, real.omega)["rao"].values[:, 0, :]            # (n_w, 6)
    n_fft = int(round(real.repeat_period / dt))
    coef = np.zeros((6, n_fft // 2 + 1), complex)
    coef[:, real.harmonic] = (H.T * real.amplitude * np.exp(1j * (real.phase - real.omega * transient_s)))
    series = np.fft.irfft(coef, n=n_fft, axis=-1) * (n_fft / 2.0)
    n = int(round((transient_s + duration_s) / dt)) + 1
    data = np.ascontiguousarray(series[:, np.arange(n) % n_fft].T)
    return Excitation("vessel", data, dt, t0=-float(transient_s), kinematics=kinematics)


__all__ = ["Excitation", "harmonic_hinge", "still", "vessel_record", "KINDS", "KINEMATICS"]
