"""Short-term response statistics from transfer functions and wave spectra.

Because the model is linear, every response scales with Hs at fixed (Tz, gamma,
heading); statistics are therefore computed once at unit Hs and scaled (DNV-RP-H103,
study eq. 2.7):

    sigma^2 = int |H(omega)|^2 S(omega; Hs = 1, Tz, gamma) domega
    Tz_r    = 2 pi sqrt(m0 / m2)                   response zero-crossing period
    N       = exposure / Tz_r   (or a fixed number, the study's 1000)
    MPM     = sigma sqrt(2 ln N)                   Rayleigh most probable maximum
"""

from __future__ import annotations

import numpy as np

from jls.sea.spectra import jonswap, tp_from_tz

FIXED_CYCLES_STUDY = 1000


def trapezoid_weights(omega):
    """Weights w with sum(w f) = trapezoid integral of f over omega."""
    omega = np.asarray(omega, float)
    d = np.diff(omega)
    w = np.zeros_like(omega)
    w[:-1] += d / 2
    w[1:] += d / 2
    return w


def unit_spectra(omega, tz, gamma=3.3):
    """JONSWAP spectra at Hs = 1 m for each Tz: (n_tz, n_w) in m^2 s/rad."""
    tz = np.atleast_1d(np.asarray(tz, float))
    return jonswap(np.asarray(omega, float)[None, :], 1.0, tp_from_tz(tz, gamma)[:, None], gamma)


def energy_grid(tz, gamma=3.3):
    """(w, S, m0) of :func:`energy_outside`: each Tz's unit spectrum on its fine grid and
    its total energy, formed once for any number of bands."""
    tz = np.atleast_1d(np.asarray(tz, float))
    tp = tp_from_tz(tz, gamma)
    wp = 2 * np.pi / tp
    # Fine nondimensional grid up to 60 omega_p; beyond it the omega^-5 tail adds
    # S(w_end) w_end / 4, negligible at the 0.1 % level but included.
    x = np.concatenate([np.linspace(1e-3, 3.0, 6000), np.linspace(3.0, 60.0, 6000)[1:]])
    w = x[None, :] * wp[:, None]
    S = jonswap(w, 1.0, tp[:, None], gamma)
    total = np.trapezoid(S, w, axis=-1) + S[:, -1] * w[:, -1] / 4
    return w, S, total


def energy_outside(omega_lo, omega_hi, tz, gamma=3.3, grid=None):
    """Fraction of each spectrum's m0 below omega_lo or above omega_hi (n_tz,); ``grid``:
    :func:`energy_grid` of the same Tz and gamma, when several bands are wanted."""
    w, S, total = energy_grid(tz, gamma) if grid is None else grid
    inside = (w >= omega_lo) & (w <= omega_hi)
    within = np.trapezoid(np.where(inside, S, 0.0), w, axis=-1)
    return np.clip(1.0 - within / total, 0.0, 1.0)


def unit_statistics(omega, H, tz, gamma=3.3, exposure_s=3 * 3600.0, cycles="response"):
    """Unit-Hs statistics of responses with transfer functions H.

    H: (..., n_w) complex per unit wave amplitude; tz: (n_tz,).
    cycles: "response" (N = exposure / Tz_r) or a number (fixed N, the study's 1000).
    Returns dict of arrays (..., n_tz): sigma, tz_response, n_cycles, mpm.
    """
    return from_moments(*transfer_moments(omega, H, tz, gamma), exposure_s, cycles)


def transfer_moments(omega, H, tz, gamma=3.3):
    """Spectral moments m0, m2 (..., n_tz) of responses with transfer functions H
    (..., n_w) in unit-Hs JONSWAP seas of zero-crossing periods ``tz``."""
    w = trapezoid_weights(omega)
    S = unit_spectra(omega, tz, gamma)                          # (n_tz, n_w)
    H2 = np.abs(np.asarray(H)) ** 2
    m0 = np.einsum("...w,tw->...t", H2 * w, S)
    m2 = np.einsum("...w,tw->...t", H2 * (w * np.asarray(omega) ** 2), S)
    return m0, m2


def sigma_from_mpm(mpm, tz_response, exposure_s=3 * 3600.0, cycles="response"):
    """The standard deviation whose MPM over the exposure is ``mpm`` at the response
    zero-crossing period ``tz_response`` [s]: the inverse of :func:`from_moments`,
    mpm / sqrt(2 ln N) with N = exposure / Tz_r (or the fixed N). 0 where mpm is 0; NaN
    where N <= 1 or Tz_r is unknown and mpm is not 0 (no cycles to reach it)."""
    mpm, tz = np.asarray(mpm, float), np.asarray(tz_response, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        n = exposure_s / tz if cycles == "response" else np.full_like(tz, float(cycles))
        k = np.sqrt(2.0 * np.log(np.where(np.isfinite(n) & (n > 1.0), n, np.nan)))
        return np.where(mpm == 0, 0.0, mpm / k)


def from_moments(m0, m2, exposure_s=3 * 3600.0, cycles="response"):
    """sigma, tz_response, n_cycles and mpm from the spectral moments m0, m2 (any shape)."""
    m0, m2 = np.asarray(m0, float), np.asarray(m2, float)
    sigma = np.sqrt(m0)
    with np.errstate(divide="ignore", invalid="ignore"):
        tz_r = np.where(m2 > 0, 2 * np.pi * np.sqrt(m0 / m2), np.nan)
    if cycles == "response":
        n = exposure_s / tz_r
    else:
        n = np.full_like(sigma, float(cycles))
    mpm = sigma * np.sqrt(2.0 * np.log(np.maximum(np.nan_to_num(n, nan=1.0), 1.0)))
    return {"sigma": sigma, "tz_response": tz_r, "n_cycles": n, "mpm": mpm}
