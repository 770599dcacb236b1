"""A multi-directional realisation of a sea state of several spread wave systems, and the
time-domain case run in it.

The components are those of :func:`jls.timedomain.sea.realise` (a uniform frequency grid,
seeded phases, deterministic or Rayleigh amplitudes) with the amplitudes of the summed
spectrum S(omega) = sum_j S_j(omega). Each component k comes from ONE direction (the
single-summation method: no two components share a frequency, so the sea stays Gaussian
and ergodic), met at one of the RAO headings h: the frequency-domain response
(:mod:`jls.response.sea_state`) meets the share

    A_h(omega) = sum_j S_j(omega) / S(omega) sum_theta D_j(theta) w_h(beta(theta))

of the energy at omega at RAO heading h (w_h: the linear interpolation of |H|^2 between RAO
headings, which is a mixture of the neighbouring headings), so the component is assigned
heading h with probability A_h(omega_k), drawn by stratified sampling (the components'
uniform variates are a seeded permutation of the strata (i + u_i) / n). Then the expected
variance of any linear response of the record is the frequency-domain variance on the
component grid, and a record's sample variance scatters about it by the direction draws:
``direction_spread`` gives the standard deviation of that scatter for independent draws (an
upper bound for the stratified ones).
"""

from __future__ import annotations

import numpy as np

from jls.response.directional import heading_weights
from jls.sea.headings import relative_heading
from jls.sea.sea_state import DIRECTIONS
from jls.timedomain.run import Case
from jls.timedomain.sea import Realisation, component_amplitudes, component_grid, synthesise
from jls.vessel.transfer import channel_transfer

__all__ = ["heading_shares", "realise_directional", "DirectionalCase", "direction_spread"]


def heading_shares(systems, course_deg, headings, omega, *, symmetric=False, n_dirs=DIRECTIONS):
    """A (n_w, n_h): the share of the sea's energy at each omega met at each RAO heading."""
    headings = np.asarray(headings, float)
    S = np.stack([np.asarray(s.spectrum(omega), float) for s in systems])        # (n_sys, n_w)
    total = S.sum(axis=0)
    A = np.zeros((np.size(omega), headings.size))
    for s, Sj in zip(systems, S):
        dirs, w = s.directions(n_dirs)
        i0, i1, w1 = heading_weights(headings, relative_heading(float(course_deg), dirs), symmetric)
        hw = np.zeros(headings.size)
        np.add.at(hw, i0, w * (1 - w1))
        np.add.at(hw, i1, w * w1)
        with np.errstate(invalid="ignore", divide="ignore"):
            A += np.where(total > 0, Sj / total, 0.0)[:, None] * hw[None, :]
    return A


def realise_directional(systems, course_deg, headings, omega_range, half_step, duration, transient,
                        seed, repeat="record", n_components=None, amplitudes="deterministic",
                        symmetric=False, n_dirs=DIRECTIONS) -> tuple[Realisation, np.ndarray]:
    """(components, the RAO-heading index of each) of the sea of ``systems`` met on
    ``course_deg`` [deg true] (module docstring). Arguments as :func:`jls.timedomain.sea.realise`."""
    m, omega, dw, period = component_grid(omega_range, half_step, duration, transient, repeat,
                                          n_components, amplitudes)
    S = sum(np.asarray(s.spectrum(omega), float) for s in systems)
    rng = np.random.default_rng(seed)
    phase, amplitude = component_amplitudes(S, dw, rng, amplitudes)
    A = heading_shares(systems, course_deg, headings, omega, symmetric=symmetric, n_dirs=n_dirs)
    u = (rng.permutation(omega.size) + rng.uniform(size=omega.size)) / omega.size
    cum = np.cumsum(A, axis=1)
    cum /= np.where(cum[:, -1:] > 0, cum[:, -1:], 1.0)
    idx = np.minimum((cum < u[:, None]).sum(axis=1), len(headings) - 1)
    real = Realisation(omega=omega, amplitude=amplitude, phase=phase, harmonic=m, d_omega=dw,
                       repeat_period=period)
    return real, idx


def direction_spread(real: Realisation, idx, power, shares) -> tuple[float, float]:
    """(the record's variance of a linear response given its direction draws, the standard
    deviation of that variance over independent draws) from ``power`` (n_w, n_h) |H|^2 at
    the components and RAO headings and the shares A (n_w, n_h)."""
    v = 0.5 * real.amplitude[:, None] ** 2 * power                    # (n_w, n_h)
    drawn = float(v[np.arange(v.shape[0]), idx].sum())
    mean = (shares * v).sum(axis=1)
    var = (shares * v**2).sum(axis=1) - mean**2
    return drawn, float(np.sqrt(np.maximum(var, 0.0).sum()))


class DirectionalCase(Case):
    """:class:`jls.timedomain.run.Case` in the multi-directional realisation of a sea of
    several spread systems met on ``course_deg`` (``motion``: the vessel motion at the RAO
    headings, over the whole circle or 0-180 deg for a symmetric hull)."""

    def __init__(self, plant, motion, systems, course_deg, *, duration_s, settings, seed=None):
        self._steps(plant, settings, duration_s)
        om = motion["omega"].values
        heads = np.mod(motion["heading"].values.astype(float), 360.0)
        self.headings = heads
        self.realisation, self.heading_index = realise_directional(
            systems, course_deg, heads, (om.min(), om.max()), self.dt / 2, self.duration, self.transient,
            settings.seed if seed is None else seed, settings.repeat, settings.n_components,
            settings.amplitudes, symmetric=bool(heads.max() <= 180.0 + 1e-9))
        w = self.realisation.omega
        per = np.stack([channel_transfer(motion, h, w) for h in heads])     # (n_h, N_CH, n_w)
        self.transfer = per[self.heading_index, :, np.arange(w.size)].T    # (N_CH, n_w)
        self.exc = synthesise(self.realisation, self.transfer, -self.n_skip * self.dt, self.dt / 2,
                              2 * self.n_steps + 1)
        self.fairlead_offset = motion.attrs["fairlead_offset_m"]
        self.systems, self.course = list(systems), float(course_deg)
        self.hs = 4.0 * float(np.sqrt(sum(s.m0() for s in systems)))
        self.tz, self.heading, self.gamma = float("nan"), float("nan"), float("nan")
