"""Resolution of a wave record against the sway resonance, and the scatter it carries.

A record's wave components sit on a grid of spacing dw = 2 pi / T_rep (T_rep the repeat
period: the recorded duration by default, :mod:`jls.timedomain.sea`). A linear response
then has the variance of the Riemann sum sum_k |H(w_k)|^2 S(w_k) dw instead of the
integral. Near the lightly damped sway mode |H|^2 is a Lorentzian of half-power bandwidth
B = 2 zeta w_n, and with n = B / dw components per bandwidth its Riemann sum is (Poisson
summation) the integral times

    sinh(pi n) / (cosh(pi n) - cos(2 pi delta)),   delta = w_n / dw mod 1,

which lies between tanh(pi n / 2) and coth(pi n / 2): the resonant share of the variance is
off by -67 % .. +200 % at n = 0.22 (0.05 h on the shipped plant), -8 % .. +9 % at n = 1 and
-0.4 % .. +0.4 % at n = 2, depending on where the grid falls against w_n. Convergence of
sigma on the shipped plant (:func:`linear_grid` over 600 record lengths of 0.03-3 h, Tz
8.5 s, no tugger, where the resonance carries most of the variance): -41 .. +63 % at
n = 0.2-0.3, -16 .. +16 % at 0.5-0.75, -3.4 .. +3.3 % at 1-1.25, -0.5 .. +0.7 % at
1.5-1.75, within 0.13 % from n = 2 on; the nonlinear runs agree (-18 % at 0.05 h, +7.5 %
at 0.167 h). jls refuses a record of fewer than :data:`MIN_COMPONENTS_PER_BANDWIDTH`
components per bandwidth of the bare plant's sway mode (the narrowest: a tugger only
widens it) and reports, per record, n and the bias of sigma (the linear model's sigma on
the record's own grid over the converged one).

The same grid sets the scatter of random-amplitude records (:func:`jls.timedomain.sea.independent_components`).
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError
from jls.sea.spectra import jonswap, tp_from_tz

#: Fewest components per sway half-power bandwidth of a record the pipeline accepts: the
#: resonant share's worst-case bias coth(pi) - 1 = 0.37 %.
MIN_COMPONENTS_PER_BANDWIDTH = 2.0


def half_power_bandwidth(plant) -> float:
    """B = 2 zeta w_n of the sway mode of the plant without tugger [rad/s]."""
    i = int(plant.modes.mode_of("sway"))
    return float(2.0 * plant.damping_ratio[i] * plant.modes.omega[i])


def components_per_bandwidth(plant, d_omega) -> float:
    """n = B / dw: wave components per sway half-power bandwidth."""
    return half_power_bandwidth(plant) / float(d_omega)


def resonant_bias_bounds(n) -> tuple[float, float]:
    """Range of the relative error of a Lorentzian's variance on a grid of n components per
    half-power bandwidth over every grid offset: (tanh(pi n / 2) - 1, coth(pi n / 2) - 1)."""
    x = 0.5 * np.pi * float(n)
    return float(np.tanh(x) - 1.0), float(1.0 / np.tanh(x) - 1.0)


def shortest_record_s(plant, n=MIN_COMPONENTS_PER_BANDWIDTH) -> float:
    """Repeat period that gives n components per bandwidth, 2 pi n / B [s]."""
    return 2.0 * np.pi * float(n) / half_power_bandwidth(plant)


def require_resolution(plant, d_omega, *, field, value, source=None,
                       minimum=MIN_COMPONENTS_PER_BANDWIDTH) -> float:
    """n of a record, or an InputError naming ``field`` and ``value`` (the key that set the
    spacing, e.g. ``timedomain.duration_h``) when n < minimum."""
    n = components_per_bandwidth(plant, d_omega)
    if n < minimum:
        lo, hi = resonant_bias_bounds(n)
        need = shortest_record_s(plant, minimum)
        raise InputError(
            f"the wave record is too short for the sway resonance: component spacing "
            f"2 pi / T = {float(d_omega):.3g} rad/s gives {n:.2f} components per half-power "
            f"bandwidth 2 zeta w_n = {half_power_bandwidth(plant):.3g} rad/s, fewer than "
            f"{minimum:g}; the resonant share of the variance would be off by "
            f"{100 * lo:+.0f} % to {100 * hi:+.0f} %; records of at least {need:.0f} s "
            f"({need / 3600:.2f} h) are needed", file=source, field=field, value=value)
    return n


def linear_grid(plant, motion, tuggers, omega, d_omega, hs, tz, heading_deg, gamma) -> dict:
    """The linear model on a record's component grid, per tugger: ``sigma`` (its expected
    value, sqrt(sum v_k), v_k = |H_rel(w_k)|^2 S(w_k) dw) and ``n_eff`` ((sum v)^2 / sum v^2,
    the independent components of the relative sway)."""
    from jls.response.solver import transfer_functions
    from jls.timedomain.sea import independent_components
    from jls.vessel.transfer import channel_transfer
    omega = np.asarray(omega, float)
    tuggers = list(tuggers)
    tr = channel_transfer(motion, heading_deg, omega)
    fl = 0.5 * (tr[5] + tr[8])
    _, Hrel = transfer_functions(plant.M, plant.K, plant.Kb, plant.C, omega,
                                 tr[None, :4].transpose(0, 2, 1), fl[None], [t.c for t in tuggers])
    S = jonswap(omega, float(hs), float(tp_from_tz(tz, gamma)), gamma)
    v = np.abs(Hrel[:, 0, :, 0]) ** 2 * S * float(d_omega)           # (tugger, w)
    return {"sigma": np.sqrt(v.sum(axis=1)),
            "n_eff": np.array([independent_components(r) for r in v])}


__all__ = ["MIN_COMPONENTS_PER_BANDWIDTH", "half_power_bandwidth", "components_per_bandwidth",
           "resonant_bias_bounds", "shortest_record_s", "require_resolution", "linear_grid"]
