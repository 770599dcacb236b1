"""Wave spectra (JONSWAP, Pierson-Moskowitz), spectral moments and period conversions.

Units: omega in rad/s, Hs in m, periods in s, S(omega) in m^2 s/rad.

The JONSWAP spectrum (study eq. 2.1, DNV-RP-C205 section 3.5.5) is written in the
nondimensional frequency x = omega / omega_p, omega_p = 2 pi / Tp::

    S(omega) = Hs^2 / (16 omega_p) * A(gamma) * g(x) * gamma**r(x)
    g(x)     = 5 x^-5 exp(-5/4 x^-4)                  (Pierson-Moskowitz shape, int g dx = 1)
    r(x)     = exp(-(x - 1)^2 / (2 sigma^2)),  sigma = sigma_a (x <= 1), sigma_b (x > 1)

A(gamma) = 1 / int g gamma**r dx is computed, not approximated, so the *continuous*
spectrum has m0 = Hs^2 / 16 exactly for every gamma.  The integral is split into the
analytic Pierson-Moskowitz part (int x^n g dx = 5/4 * 1.25^((n-4)/4) * Gamma(1 - n/4))
plus the peak correction int x^n g (gamma**r - 1) dx, which vanishes outside a window of
+-10 sigma around the peak and is integrated there with Simpson's rule on 801 points a
side (error well below 1e-10).  The same split gives the exact nondimensional moments
used for period ratios (Tz, T1, Te).  DNV's closed form A = 1 - 0.287 ln(gamma) agrees to
about 1 %.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from jls.errors import InputError

__all__ = [
    "jonswap", "pierson_moskowitz", "spectral_moment", "jonswap_normalisation",
    "jonswap_shape_moment", "tz_from_tp", "tp_from_tz", "t1_from_tp", "te_from_tp",
    "gamma_dnv", "GAMMA_DEFAULT", "SIGMA_A", "SIGMA_B",
]

GAMMA_DEFAULT = 3.3
SIGMA_A = 0.07
SIGMA_B = 0.09
_N_SIDE = 801          # Simpson points on each side of the peak (odd)
_WINDOW = 10.0         # half-width of the peak-correction window, in sigma

# DNV-RP-C205 (2010, 3.5.5.4) period ratios, valid for 1 <= gamma < 7.
_DNV_TZ = (0.6673, 0.05037, -0.006230, 0.0003341)
_DNV_T1 = (0.7303, 0.04936, -0.006556, 0.0003610)
_DNV_GAMMA_RANGE = (1.0, 7.0)


def _scalar(a):
    """Return a 0-d array as a numpy scalar, other arrays unchanged."""
    a = np.asarray(a)
    return a[()] if a.ndim == 0 else a


def _check(name, a, *, positive=False, nonneg=False):
    """Validate a numeric argument; raise InputError naming the first bad value."""
    a = np.asarray(a, dtype=float)
    bad = ~np.isfinite(a)
    if positive:
        bad |= a <= 0
    if nonneg:
        bad |= a < 0
    if bad.any():
        need = "positive" if positive else "non-negative" if nonneg else "finite"
        raise InputError(f"must be finite and {need}", field=name, value=float(a[bad].flat[0]))
    return a


def _pm_shape(x):
    """Pierson-Moskowitz shape g(x) = 5 x^-5 exp(-1.25 x^-4); zero for x <= 0."""
    x = np.asarray(x, dtype=float)
    safe = np.where(x > 0, x, 1.0)
    return np.where(x > 0, 5.0 * safe**-5 * np.exp(-1.25 * safe**-4), 0.0)


def _pm_moment(n):
    """Exact int_0^inf x^n g(x) dx for the PM shape (finite for n < 4)."""
    return 1.25 * 1.25 ** ((n - 4.0) / 4.0) * math.gamma(1.0 - n / 4.0)


def _peak_correction(n, gamma, sigma_a, sigma_b, shape=_pm_shape):
    """int x^n g(x) (gamma**r(x) - 1) dx for 1-D arrays of unique (gamma, sa, sb); g is
    the base shape (Pierson-Moskowitz by default, peak at x = 1)."""
    t = np.linspace(0.0, 1.0, _N_SIDE)
    lng = np.log(gamma)[:, None]
    lo = np.maximum(1.0 - _WINDOW * sigma_a, 0.0)[:, None]
    xl = lo + (1.0 - lo) * t
    xr = 1.0 + _WINDOW * sigma_b[:, None] * t
    total = 0.0
    for x, s in ((xl, sigma_a[:, None]), (xr, sigma_b[:, None])):
        r = np.exp(-((x - 1.0) ** 2) / (2.0 * s**2))
        f = np.where(x > 0, np.where(x > 0, x, 1.0) ** n, 0.0) * shape(x) * np.expm1(r * lng)
        total = total + _simpson_uniform(f, x[:, 1] - x[:, 0])
    return total


def _simpson_uniform(f, h):
    """Composite Simpson rule along the last axis of f (odd number of points, step h)."""
    w = np.ones(f.shape[-1])
    w[1:-1:2], w[2:-1:2] = 4.0, 2.0
    return f @ w * h / 3.0


def _unique_params(gamma, sigma_a, sigma_b):
    """Broadcast the shape parameters and return (shape, unique rows, inverse index)."""
    gamma = _check("gamma", gamma, positive=True)
    sigma_a = _check("sigma_a", sigma_a, positive=True)
    sigma_b = _check("sigma_b", sigma_b, positive=True)
    g, sa, sb = np.broadcast_arrays(gamma, sigma_a, sigma_b)
    stacked = np.stack([g.ravel(), sa.ravel(), sb.ravel()], axis=-1)
    uniq, inv = np.unique(stacked, axis=0, return_inverse=True)
    return g.shape, uniq, inv.ravel()


def jonswap_shape_moment(n, gamma=GAMMA_DEFAULT, sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Nondimensional spectral moment M_n = m_n / (m0 omega_p^n) of the JONSWAP shape.

    Exact for the continuous spectrum (no frequency truncation), n < 4 (the omega^-5
    tail makes higher moments infinite).  Broadcasts over gamma, sigma_a, sigma_b.
    Periods follow as Tz = Tp / sqrt(M_2), T1 = Tp / M_1, Te = T_-10 = Tp * M_-1.
    """
    if not n < 4:
        raise InputError("moment order must be < 4 (omega^-5 tail)", field="n", value=n)
    shape, uniq, inv = _unique_params(gamma, sigma_a, sigma_b)
    g, sa, sb = uniq.T
    num = _pm_moment(n) + _peak_correction(n, g, sa, sb)
    den = _pm_moment(0) + _peak_correction(0, g, sa, sb)
    return _scalar((num / den)[inv].reshape(shape))


def jonswap_normalisation(gamma=GAMMA_DEFAULT, sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Normalising factor A(gamma) [-] so that m0 = Hs^2/16 exactly (1 for gamma = 1).

    DNV-RP-C205's approximation is 1 - 0.287 ln(gamma).
    """
    if all(np.ndim(v) == 0 for v in (gamma, sigma_a, sigma_b)):      # the usual case: one shape
        return _normalisation(float(gamma), float(sigma_a), float(sigma_b))
    return _normalisations(gamma, sigma_a, sigma_b)


@functools.lru_cache(maxsize=256)
def _normalisation(gamma, sigma_a, sigma_b):
    return _normalisations(gamma, sigma_a, sigma_b)


def _normalisations(gamma, sigma_a, sigma_b):
    shape, uniq, inv = _unique_params(gamma, sigma_a, sigma_b)
    g, sa, sb = uniq.T
    a = 1.0 / (_pm_moment(0) + _peak_correction(0, g, sa, sb))
    return _scalar(a[inv].reshape(shape))


def jonswap(omega, hs, tp, gamma=GAMMA_DEFAULT, sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """JONSWAP wave spectrum S(omega) [m^2 s/rad].

    Parameters broadcast numpy-style: e.g. omega of shape (n,) with hs, tp, gamma of
    shape (k, 1) gives (k, n).

    omega : angular frequency [rad/s], >= 0 (S = 0 at omega = 0)
    hs : significant wave height [m], >= 0
    tp : peak period [s], > 0
    gamma : peak enhancement factor [-], > 0 (1 gives Pierson-Moskowitz)
    sigma_a, sigma_b : spectral width below / above the peak [-]
    """
    omega = _check("omega", omega, nonneg=True)
    hs = _check("hs", hs, nonneg=True)
    tp = _check("tp", tp, positive=True)
    norm = jonswap_normalisation(gamma, sigma_a, sigma_b)
    gamma, sigma_a, sigma_b = (np.asarray(v, dtype=float) for v in (gamma, sigma_a, sigma_b))
    wp = 2.0 * np.pi / tp
    x = omega / wp
    sigma = np.where(x <= 1.0, sigma_a, sigma_b)
    r = np.exp(-((x - 1.0) ** 2) / (2.0 * sigma**2))
    s = hs**2 / (16.0 * wp) * norm * _pm_shape(x) * gamma**r
    return _scalar(s)


def pierson_moskowitz(omega, hs, tp):
    """Pierson-Moskowitz spectrum S(omega) [m^2 s/rad] = JONSWAP with gamma = 1."""
    return jonswap(omega, hs, tp, gamma=1.0)


def spectral_moment(omega, S, n=0, *, tail=False):
    """Spectral moment m_n = int omega^n S(omega) domega (trapezoid along the last axis).

    omega [rad/s] (shape (..., n) broadcastable to S), S [m^2 s/rad]; m_n in m^2 (rad/s)^n.
    Points where S == 0 contribute 0 (so omega = 0 with n < 0 is safe).
    tail=True adds the analytic contribution of an omega^-5 tail beyond the last
    frequency, S_L (omega_L / omega)^5, i.e. S_L omega_L^(n+1) / (4 - n) (needs n < 4).
    """
    omega = np.asarray(omega, dtype=float)
    S = np.asarray(S, dtype=float)
    omega_b = np.broadcast_to(omega, np.broadcast_shapes(omega.shape, S.shape))
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(S == 0, 0.0, omega_b**n * S)
    m = np.trapezoid(f, omega_b, axis=-1)
    if tail:
        if not n < 4:
            raise InputError("analytic tail needs n < 4", field="n", value=n)
        m = m + S[..., -1] * omega_b[..., -1] ** (n + 1) / (4.0 - n)
    return _scalar(m)


def _dnv_poly(coeffs, gamma):
    g = np.asarray(gamma, dtype=float)
    lo, hi = _DNV_GAMMA_RANGE
    bad = ~np.isfinite(g) | (g < lo) | (g >= hi)
    if bad.any():
        raise InputError("DNV-RP-C205 period relation is valid for 1 <= gamma < 7; "
                         "use method='exact'", field="gamma", value=float(g[bad].flat[0]))
    c0, c1, c2, c3 = coeffs
    return c0 + c1 * g + c2 * g**2 + c3 * g**3


def _method(method):
    if method not in ("dnv", "exact"):
        raise InputError("method must be 'dnv' or 'exact'", field="method", value=method)
    return method


def tz_from_tp(tp, gamma=GAMMA_DEFAULT, method="dnv", sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Zero-up-crossing period Tz [s] from peak period Tp [s].

    method="dnv": Tz/Tp = 0.6673 + 0.05037 g - 0.006230 g^2 + 0.0003341 g^3
    (DNV-RP-C205, 1 <= gamma < 7); method="exact": Tp / sqrt(M_2) of this module's spectrum.
    """
    tp = _check("tp", tp, positive=True)
    if _method(method) == "dnv":
        return _scalar(tp * _dnv_poly(_DNV_TZ, gamma))
    return _scalar(tp / np.sqrt(jonswap_shape_moment(2, gamma, sigma_a, sigma_b)))


def tp_from_tz(tz, gamma=GAMMA_DEFAULT, method="dnv", sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Peak period Tp [s] from zero-up-crossing period Tz [s] (inverse of tz_from_tp).

    At gamma = 3.3 the DNV relation gives Tp = 1.286 Tz.
    """
    tz = _check("tz", tz, positive=True)
    return _scalar(tz / tz_from_tp(1.0, gamma, method, sigma_a, sigma_b))


def t1_from_tp(tp, gamma=GAMMA_DEFAULT, method="dnv", sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Mean period T1 = 2 pi m0/m1 [s] from Tp [s].

    method="dnv": T1/Tp = 0.7303 + 0.04936 g - 0.006556 g^2 + 0.0003610 g^3;
    method="exact": Tp / M_1.
    """
    tp = _check("tp", tp, positive=True)
    if _method(method) == "dnv":
        return _scalar(tp * _dnv_poly(_DNV_T1, gamma))
    return _scalar(tp / jonswap_shape_moment(1, gamma, sigma_a, sigma_b))


def te_from_tp(tp, gamma=GAMMA_DEFAULT, sigma_a=SIGMA_A, sigma_b=SIGMA_B):
    """Energy period Te = T_-10 = 2 pi m_-1/m0 [s] from Tp [s].

    DNV-RP-C205 gives no polynomial for Te, so the exact moment ratio Tp * M_-1 of the
    normalised JONSWAP shape is used (Te/Tp = 0.857 for PM, about 0.90 at gamma 3.3).
    """
    tp = _check("tp", tp, positive=True)
    return _scalar(tp * jonswap_shape_moment(-1, gamma, sigma_a, sigma_b))


def gamma_dnv(hs, tp):
    """Peak enhancement factor from Hs [m] and Tp [s] by the DNV-RP-C205 rule [-].

    phi = Tp / sqrt(Hs): gamma = 5 for phi <= 3.6, exp(5.75 - 1.15 phi) for
    3.6 < phi < 5, 1 for phi >= 5 (Hs = 0 gives 1).
    """
    hs = _check("hs", hs, nonneg=True)
    tp = _check("tp", tp, positive=True)
    with np.errstate(divide="ignore"):
        phi = tp / np.sqrt(hs)
    g = np.where(phi <= 3.6, 5.0, np.where(phi < 5.0, np.exp(5.75 - 1.15 * np.minimum(phi, 5.0)), 1.0))
    return _scalar(g)
