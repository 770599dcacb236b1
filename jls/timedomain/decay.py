"""Free decay of the sway with and without a tugger (section 6.6).

The jacket is held at a sway offset on a still vessel, its heave, roll and yaw in the
nonlinear static equilibrium of the time domain's own forces at that offset
(:func:`jls.timedomain.equilibrium.held_equilibrium`: exact wire geometry, tugger lines at
their pretension), and released from rest. Two measures, as the study reports them:

* the time to 10 %: the last instant the relative sway exceeds 10 % of the release
  amplitude (linear interpolation between steps); the study's 581 s without tugger,
  95 s with the low and 17 s with the high setting for a 3.0 m release;
* the first-cycle equivalent damping ratio from the logarithmic decrement between the
  release and the next positive peak, zeta = d / sqrt(4 pi^2 + d^2); NaN when the
  motion does not return to a positive peak (near-critical damping).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.timedomain import dynamics as dyn
from jls.timedomain.equilibrium import forces, held_equilibrium
from jls.timedomain.run import initial_state, integrate_run, parameters, sway_time_constant
from jls.tugger.setting import Tugger


@dataclass(frozen=True)
class Decay:
    """Record and measures of one release: time [s], relative sway [m], release [m],
    time to 10 % [s], first-cycle equivalent damping ratio, wall time [s], the held state
    q0 (4,) [m, m, rad, rad] and the hoist-wire tensions in it (4,) [kN]."""

    time: np.ndarray
    sway: np.ndarray
    release: float
    time_to_10pct: float
    zeta_first_cycle: float
    wall_time: float
    q0: np.ndarray
    wire_tension0: np.ndarray


def time_to_fraction(t, y, amplitude, fraction=0.1) -> float:
    """Last time |y| exceeds fraction * amplitude (interpolated); NaN if it still does at
    the end of the record."""
    level = fraction * abs(amplitude)
    above = np.abs(y) > level
    if above[-1]:
        return float("nan")
    if not above.any():
        return 0.0
    i = int(np.flatnonzero(above)[-1])
    a, b = abs(y[i]), abs(y[i + 1])
    return float(t[i] + (a - level) / (a - b) * (t[i + 1] - t[i]))


def first_cycle_damping(y, release) -> float:
    """Equivalent damping ratio from the release and the next peak of the same sign."""
    s = np.sign(release)
    z = s * np.asarray(y)
    crossed = np.flatnonzero(z < 0)
    if crossed.size == 0:
        return float("nan")
    rest = z[crossed[0]:]
    peaks = np.flatnonzero((rest[1:-1] > rest[:-2]) & (rest[1:-1] >= rest[2:]) & (rest[1:-1] > 0))
    if peaks.size == 0:
        return float("nan")
    d = np.log(abs(release) / rest[peaks[0] + 1])
    return float(d / np.sqrt(4 * np.pi**2 + d**2))


def decay(plant, tugger: Tugger | None = None, release_m=3.0, duration_s=None, dt=0.02,
          fairlead_offset_m=(0.0, 37.5, -82.5)) -> Decay:
    """Release the jacket from a sway offset on a still vessel and measure the decay.

    The default duration is three times the time the plant alone needs to decay to 10 %
    (ln 10 sway time constants), long enough for every setting.
    """
    if duration_s is None:
        duration_s = 3.0 * np.log(10.0) * sway_time_constant(plant)
    n = int(np.ceil(duration_s / dt))
    exc = np.zeros((2 * n + 1, dyn.N_CH))
    par = parameters(plant, tugger, fairlead_offset_m)
    lines = initial_state(plant, tugger)[8:10]
    q0 = held_equilibrium(par, plant.K, release_m, lines)
    x0 = initial_state(plant, tugger, q=q0)
    record, _, wall = integrate_run(par, x0, exc, dt, n, n + 1)
    t = np.arange(n + 1) * dt
    y = record[:, 0]
    return Decay(time=t, sway=y, release=float(release_m),
                 time_to_10pct=time_to_fraction(t, y, release_m),
                 zeta_first_cycle=first_cycle_damping(y, release_m), wall_time=wall, q0=q0,
                 wire_tension0=forces(par, q0, lines)[1][dyn.I_TWIRE:dyn.I_TWIRE + 4].copy())


__all__ = ["Decay", "decay", "time_to_fraction", "first_cycle_damping"]
