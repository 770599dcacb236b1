"""Irregular-sea realisation and the vessel-borne excitation of the time-domain model.

The sea is a sum of regular components with seeded random phases on a uniform frequency
grid,

    eta(t) = sum_k a_k cos(w_k t + eps_k),   w_k = k dw,

over the RAO's frequency range (JONSWAP, Tp from Tz as in :mod:`jls.sea.spectra`), with
amplitudes either

* ``"deterministic"``: a_k = sqrt(2 S(w_k) dw), so every seed has the same discretised
  variance and seeds sample the phases only, or
* ``"rayleigh"``: a_k = sqrt(2 S(w_k) dw E_k), E_k independent standard exponential
  (a_k Rayleigh distributed with E[a_k^2] = 2 S dw; equivalently Gaussian Fourier
  coefficients), so a record's variance scatters from seed to seed as a real record's
  does: a linear response of variance contributions v_k = |H_k|^2 S_k dw has
  sigma^2 = sum_k v_k E_k, mean sum v_k and variance sum v_k^2, i.e. a relative variance
  1 / N_eff with N_eff = (sum v)^2 / sum v^2 the number of independent components in the
  response band (:func:`independent_components`).

The phases are drawn first, so one seed gives the same phases in either mode. Every
excitation channel (the hinge's sway, heave, roll and yaw, the fairleads' translations
and velocities) is the same sum weighted by its RAO, synthesised by inverse FFTs over the
repeat period at half the time step (:func:`synthesise`), so the cost does not depend on
the component count.

The spacing sets the repeat period 2 pi / dw. ``repeat="record"`` (default) makes it
the recorded duration: the record holds exactly one period and never repeats, and after
the start-up transient a linear plant is in its periodic steady state, so its sample
variance equals the discretised spectral sum exactly. ``repeat="never"`` makes it the
whole simulated time (transient included). A component count, when given, sets
dw = (w_hi - w_lo) / n instead (the record may then repeat; the dataset says so).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.errors import InputError
from jls.sea.spectra import jonswap, tp_from_tz
from jls.timedomain.dynamics import N_CH

#: Component amplitude models (module docstring).
AMPLITUDES = ("rayleigh", "deterministic")


@dataclass(frozen=True)
class Realisation:
    """Wave components: frequencies [rad/s], amplitudes [m], phases [rad], the grid
    spacing dw [rad/s] (w_k = m_k dw, m_k integers) and the repeat period [s]."""

    omega: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    harmonic: np.ndarray
    d_omega: float
    repeat_period: float


def repeat_period(omega_range, half_step, duration, transient, repeat="record",
                  n_components=None) -> float:
    """Repeat period 2 pi / dw of a realisation [s] (module docstring), a whole number of
    half steps."""
    lo, hi = float(omega_range[0]), float(omega_range[1])
    if n_components is not None:
        if int(n_components) < 10:
            raise InputError("at least 10 wave components are needed", field="timedomain.n_components",
                             value=n_components)
        period = 2 * np.pi * int(n_components) / (hi - lo)
    elif repeat == "record":
        period = duration
    elif repeat == "never":
        period = duration + transient
    else:
        raise InputError("must be 'record' or 'never'", field="timedomain.repeat", value=repeat)
    return int(np.ceil(period / half_step)) * half_step


def realise(hs, tz, gamma, omega_range, half_step, duration, transient, seed, repeat="record",
            n_components=None, amplitudes="deterministic") -> Realisation:
    """Components of one sea state on a grid commensurate with the half step.

    omega_range: (lo, hi) rad/s; half_step: sampling interval of the excitation [s];
    duration, transient: recorded and discarded time [s]; amplitudes: "deterministic" or
    "rayleigh" (module docstring).
    """
    m, omega, dw, period = component_grid(omega_range, half_step, duration, transient, repeat,
                                          n_components, amplitudes)
    S = jonswap(omega, float(hs), float(tp_from_tz(tz, gamma)), gamma)
    rng = np.random.default_rng(seed)
    phase, amplitude = component_amplitudes(S, dw, rng, amplitudes)
    return Realisation(omega=omega, amplitude=amplitude, phase=phase, harmonic=m,
                       d_omega=dw, repeat_period=period)


def component_grid(omega_range, half_step, duration, transient, repeat, n_components, amplitudes):
    """(harmonic numbers m, omega = m d_omega [rad/s], d_omega, repeat period [s]) of the
    components inside ``omega_range`` on a grid commensurate with the half step (the
    arguments as :func:`realise`, ``amplitudes`` checked here)."""
    if amplitudes not in AMPLITUDES:
        raise InputError(f"must be one of {', '.join(AMPLITUDES)}", field="timedomain.amplitudes",
                         value=amplitudes)
    lo, hi = float(omega_range[0]), float(omega_range[1])
    period = repeat_period(omega_range, half_step, duration, transient, repeat, n_components)
    n_fft = int(round(period / half_step))
    dw = 2 * np.pi / period
    m = np.arange(max(1, int(np.ceil(lo / dw))), int(np.floor(hi / dw)) + 1)
    m = m[m < n_fft // 2]
    return m, m * dw, dw, period


def component_amplitudes(S, dw, rng, amplitudes):
    """(phases, amplitudes) of components of spectral density ``S`` [m^2 s/rad] a ``dw``
    apart: phases uniform, then (``rayleigh``) squared amplitudes exponential about 2 S dw,
    drawn from ``rng`` in that order."""
    phase = rng.uniform(0.0, 2 * np.pi, S.size)
    a2 = 2 * S * dw
    if amplitudes == "rayleigh":
        a2 = a2 * rng.standard_exponential(S.size)
    return phase, np.sqrt(a2)


def independent_components(v) -> float:
    """N_eff = (sum v)^2 / sum v^2 of variance contributions v (module docstring): with
    Rayleigh amplitudes the relative variance of a record's sigma^2 is 1 / N_eff, and
    sigma^2 / E[sigma^2] is close to chi-square with 2 N_eff degrees of freedom over 2 N_eff
    (exact when the N_eff contributions are equal)."""
    v = np.asarray(v, float)
    return float(v.sum() ** 2 / np.sum(v * v)) if np.any(v > 0) else float("nan")


def _decimation(n_fft, m_max) -> int:
    """The largest factor D of n_fft whose coarse grid of n_fft / D samples still holds the
    highest harmonic m_max below its Nyquist bin (1 if none does)."""
    best = 1
    for d in range(2, n_fft // (2 * m_max + 2) + 1):
        if n_fft % d == 0 and m_max < (n_fft // d) // 2:
            best = d
    return best


def synthesise(real: Realisation, transfer, t0, half_step, n_samples) -> np.ndarray:
    """Excitation samples (n_samples, N_CH) at t0 + j half_step.

    transfer: (N_CH, n_w) channel RAOs at ``real.omega``. The sea is periodic over the
    repeat period of n_fft half steps; samples beyond it wrap. The components lie far
    below the half step's Nyquist frequency, so the period is synthesised on D interleaved
    coarse grids of n_fft / D samples, offset by r half steps (r < D, D the largest
    factor of n_fft whose grid still resolves the highest harmonic): one short inverse
    real FFT per channel and offset, written straight into the rows j = n D + r of the
    output. The same sums as one inverse FFT over the period, equal to round-off.
    """
    n_fft = int(round(real.repeat_period / half_step))
    m = np.asarray(real.harmonic)
    n_ch = np.shape(transfer)[0]
    d = _decimation(n_fft, int(m.max())) if m.size else 1
    n_coarse = n_fft // d
    # the scale of the inverse FFT (1 / n) undone, the factor 2 of the real part
    base = (np.asarray(transfer) * (real.amplitude * (n_coarse / 2.0))
            * np.exp(1j * (real.phase + real.omega * t0)))
    coef = np.zeros((n_ch, n_coarse // 2 + 1), complex)
    out = np.empty((max(n_samples, n_fft), n_ch))
    grid = out[:n_fft].reshape(n_coarse, d, n_ch)        # grid[n, r] = row n d + r
    for r in range(d):
        coef[:, m] = base * np.exp(1j * real.omega * (r * half_step)) if r else base
        grid[:, r, :] = np.fft.irfft(coef, n=n_coarse, axis=-1).T
    for start in range(n_fft, n_samples, n_fft):          # rows beyond the period wrap
        stop = min(start + n_fft, n_samples)
        out[start:stop] = out[:stop - start]
    assert out.shape[1] == N_CH
    return out[:n_samples]


def wave_elevation(real: Realisation, t) -> np.ndarray:
    """eta(t) by direct summation (for checks and short plots)."""
    t = np.asarray(t, float)
    return np.sum(real.amplitude * np.cos(real.omega * t[..., None] + real.phase), axis=-1)


__all__ = ["Realisation", "realise", "repeat_period", "synthesise", "wave_elevation", "independent_components",
           "AMPLITUDES"]
