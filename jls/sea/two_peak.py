"""Two-peak wave spectra: Torsethaugen (DNV-RP-C205 3.5.7), Ochi-Hubble, wind sea + swell.

Units: omega in rad/s, Hs in m, periods in s, S(omega) in m^2 s/rad; directions in degrees
true, the direction the waves come FROM (as the buoys and hindcasts give them).

**Torsethaugen** (DNV-RP-C205 3.5.7; the simplified two-peak model of Torsethaugen and
Haver, 2004, table 1). A sea state (Hs, Tp) is split into two wave systems j = 1
(primary, the peak at Tp) and 2 (secondary), each of the form::

    S_j(omega) = Hs_j^2 / (16 omega_pj) * A(gamma_j) * g(x) * gamma_j**r(x),  x = omega / omega_pj
    g(x)       = G0 x^-4 exp(-x^-4),  G0 = 4 / Gamma(3/4) = 3.26   (int g dx = 1)
    r(x)       = exp(-(x - 1)^2 / (2 sigma^2)),  sigma = 0.07 (x < 1), 0.09 (x >= 1)

with Tf = 6.6 Hs^(1/3) [s] the peak period of a fully developed sea and, for a
**wind-dominated** sea (Tp <= Tf), Tl = 2 Hs^(1/2), eps_l = (Tf - Tp) / (Tf - Tl) (0-1)::

    Hs_1 = r_pw Hs,  r_pw = 0.3 exp(-(eps_l / 0.5)^2) + 0.7,  Tp_1 = Tp,
    gamma_1 = 35 (2 pi Hs_1 / (g Tp^2))^(6/7)
    Hs_2 = sqrt(1 - r_pw^2) Hs,  Tp_2 = Tf + 2.0,  gamma_2 = 1

and for a **swell-dominated** sea (Tp > Tf), eps_u = (Tp - Tf) / (25 - Tf) (0-1)::

    Hs_1 = r_ps Hs,  r_ps = 0.4 exp(-(eps_u / 0.3)^2) + 0.6,  Tp_1 = Tp,
    gamma_1 = 35 (2 pi Hs / (g Tf^2))^(6/7) (1 + 6 eps_u)
    Hs_2 = sqrt(1 - r_ps^2) Hs,  Tp_2 = 6.6 Hs_2^(1/3),  gamma_2 = 1

g = 9.81 m/s^2. gamma_1 is taken as at least 1 (the formula falls below 1 for small
steepness, e.g. Hs < 1.2 m at Tp = Tf, where the PM shape is meant). The standard's
normalising factor A = (1 + 1.1 [ln gamma]^1.19) / gamma is an approximation; here
A(gamma) = 1 / int g gamma**r dx is computed (as for :func:`jls.sea.spectra.jonswap`), so
every system carries exactly Hs_j^2/16 and the sum Hs^2/16 (``normalisation="dnv"`` uses
the standard's closed form, which is 3 % above the exact A at gamma 2 to 3.3 and 1.4 % at
5). The omega^-4 tail makes moments of order n >= 3 infinite; m_-1, m0, m1, m2 are
finite.

**Ochi-Hubble** (six parameters; Ochi and Hubble 1976, DNV-RP-C205 3.5.7)::

    S(omega) = 1/4 sum_j ((4 l_j + 1)/4 omega_pj^4)^l_j / Gamma(l_j) Hs_j^2
               / omega^(4 l_j + 1) exp(-(4 l_j + 1)/4 (omega_pj / omega)^4)

each component peaking at omega_pj = 2 pi / Tp_j with m0 = Hs_j^2/16 exactly and
m_n = Hs_j^2/16 omega_pj^n ((4 l_j + 1)/4)^(n/4) Gamma(l_j - n/4) / Gamma(l_j)
(finite for n < 4 l_j); l_j = 1 is a Pierson-Moskowitz spectrum.

**Wind sea + swell**: two :class:`Partition` JONSWAPs, each with its own Hs, Tp, gamma and
direction; the response meets each at its own relative heading
(:mod:`jls.response.directional`). Periods of all of them: :mod:`jls.sea.periods`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from jls.errors import InputError
from jls.sea.spectra import (
    GAMMA_DEFAULT,
    SIGMA_A,
    SIGMA_B,
    _check,
    _peak_correction,
    _scalar,
    jonswap,
    jonswap_shape_moment,
)

__all__ = [
    "Partition", "torsethaugen", "torsethaugen_parameters", "torsethaugen_moment",
    "torsethaugen_normalisation", "a_gamma_dnv", "ochi_hubble", "ochi_hubble_moment",
    "wind_swell", "wind_swell_moment", "TORSETHAUGEN", "G",
]

G = 9.81
#: Torsethaugen and Haver (2004) table 1, as DNV-RP-C205 3.5.7 gives them.
TORSETHAUGEN = {"af": 6.6, "ae": 2.0, "au": 25.0, "a10": 0.7, "a1": 0.5, "kg": 35.0,
                "b1": 2.0, "a20": 0.6, "a2": 0.3, "a3": 6.0}
_G0 = 4.0 / math.gamma(0.75)


def _g4(x):
    """Torsethaugen base shape G0 x^-4 exp(-x^-4), int g dx = 1; zero for x <= 0."""
    x = np.asarray(x, dtype=float)
    safe = np.where(x > 0, x, 1.0)
    return np.where(x > 0, _G0 * safe**-4 * np.exp(-(safe**-4)), 0.0)


def _g4_moment(n):
    """Exact int x^n g4(x) dx = Gamma((3 - n)/4) / Gamma(3/4) (finite for n < 3)."""
    return math.gamma((3.0 - n) / 4.0) / math.gamma(0.75)


def _g4_gamma_moments(n, gamma):
    """int x^n g4 gamma**r dx / int g4 gamma**r dx for an array of gamma (>= 1)."""
    g = np.asarray(gamma, dtype=float)
    uniq, inv = np.unique(g.ravel(), return_inverse=True)
    sa, sb = np.full_like(uniq, SIGMA_A), np.full_like(uniq, SIGMA_B)
    num = _g4_moment(n) + _peak_correction(n, uniq, sa, sb, shape=_g4)
    den = _g4_moment(0) + _peak_correction(0, uniq, sa, sb, shape=_g4)
    return (num / den)[inv.ravel()].reshape(g.shape)


def torsethaugen_normalisation(gamma):
    """Exact A(gamma) = 1 / int g4 gamma**r dx of the Torsethaugen shape (1 at gamma = 1)."""
    g = np.atleast_1d(_check("gamma", gamma, positive=True))
    uniq, inv = np.unique(g.ravel(), return_inverse=True)
    sa, sb = np.full_like(uniq, SIGMA_A), np.full_like(uniq, SIGMA_B)
    a = 1.0 / (_g4_moment(0) + _peak_correction(0, uniq, sa, sb, shape=_g4))
    return _scalar(a[inv.ravel()].reshape(np.shape(gamma)))


def a_gamma_dnv(gamma):
    """DNV-RP-C205's closed form A = (1 + 1.1 [ln gamma]^1.19) / gamma (gamma >= 1)."""
    g = np.asarray(gamma, dtype=float)
    return _scalar((1.0 + 1.1 * np.log(np.maximum(g, 1.0)) ** 1.19) / g)


def torsethaugen_parameters(hs, tp):
    """The two wave systems of a Torsethaugen sea state (arrays broadcast over hs, tp).

    Returns a dict of arrays: ``hs1, tp1, gamma1`` (primary), ``hs2, tp2, gamma2``
    (secondary), ``tf`` (Tf = 6.6 Hs^(1/3)) and ``wind_dominated`` (Tp <= Tf), with the
    formulas of the module docstring. A secondary system of zero height has tp2 = NaN.
    """
    c = TORSETHAUGEN
    hs = _check("hs", hs, nonneg=True)
    tp = _check("tp", tp, positive=True)
    hs, tp = np.broadcast_arrays(hs, tp)
    tf = c["af"] * np.cbrt(hs)
    tl = c["ae"] * np.sqrt(hs)
    wind = tp <= tf
    with np.errstate(divide="ignore", invalid="ignore"):
        eps_l = np.clip(np.where(wind, (tf - tp) / (tf - tl), 0.0), 0.0, 1.0)
        eps_u = np.clip(np.where(wind, 0.0, (tp - tf) / (c["au"] - tf)), 0.0, 1.0)
        r_pw = (1 - c["a10"]) * np.exp(-((eps_l / c["a1"]) ** 2)) + c["a10"]
        r_ps = (1 - c["a20"]) * np.exp(-((eps_u / c["a2"]) ** 2)) + c["a20"]
        r = np.where(wind, r_pw, r_ps)
        hs1 = r * hs
        hs2 = np.sqrt(np.maximum(1.0 - r**2, 0.0)) * hs
        gamma_w = c["kg"] * (2 * np.pi * hs1 / (G * tp**2)) ** (6.0 / 7.0)
        gamma_s = c["kg"] * (2 * np.pi * hs / (G * tf**2)) ** (6.0 / 7.0) * (1 + c["a3"] * eps_u)
        gamma1 = np.maximum(np.nan_to_num(np.where(wind, gamma_w, gamma_s), nan=1.0), 1.0)
        tp2 = np.where(wind, tf + c["b1"], c["af"] * np.cbrt(hs2))
    tp2 = np.where(hs2 > 0, tp2, np.nan)
    out = {"hs1": hs1, "tp1": tp * 1.0, "gamma1": gamma1, "hs2": hs2, "tp2": tp2,
           "gamma2": np.ones_like(hs1), "tf": tf, "wind_dominated": wind}
    return {k: _scalar(v) for k, v in out.items()}


def _system(omega, hs, tp, gamma, normalisation):
    """One Torsethaugen wave system S_j(omega); zero where hs = 0 or tp is NaN."""
    ok = (hs > 0) & np.isfinite(tp)
    tp = np.where(ok, tp, 1.0)
    wp = 2 * np.pi / tp
    x = omega / wp
    sigma = np.where(x < 1.0, SIGMA_A, SIGMA_B)
    r = np.exp(-((x - 1.0) ** 2) / (2 * sigma**2))
    a = torsethaugen_normalisation(gamma) if normalisation == "exact" else a_gamma_dnv(gamma)
    return np.where(ok, hs**2 / (16 * wp) * a * _g4(x) * gamma**r, 0.0)


def torsethaugen(omega, hs, tp, *, normalisation="exact", systems=False):
    """Torsethaugen spectrum S(omega) [m^2 s/rad] of a sea state (Hs [m], Tp [s]).

    Broadcasts numpy-style like :func:`jls.sea.spectra.jonswap`. ``systems=True`` returns
    the primary and secondary systems apart, (S1, S2). ``normalisation``: "exact"
    (m0 = Hs^2/16) or "dnv" (the standard's closed-form A).
    """
    if normalisation not in ("exact", "dnv"):
        raise InputError("normalisation must be 'exact' or 'dnv'", field="normalisation",
                         value=normalisation)
    omega = _check("omega", omega, nonneg=True)
    p = torsethaugen_parameters(hs, tp)
    s1 = _system(omega, *(np.asarray(p[k], float) for k in ("hs1", "tp1", "gamma1")), normalisation)
    s2 = _system(omega, *(np.asarray(p[k], float) for k in ("hs2", "tp2", "gamma2")), normalisation)
    return (_scalar(s1), _scalar(s2)) if systems else _scalar(s1 + s2)


def torsethaugen_moment(n, hs, tp):
    """Exact spectral moment m_n [m^2 (rad/s)^n] of the Torsethaugen spectrum (n < 3)."""
    if not n < 3:
        raise InputError("moment order must be < 3 (omega^-4 tail)", field="n", value=n)
    p = torsethaugen_parameters(hs, tp)
    total = 0.0
    for j in ("1", "2"):
        h, t, g = (np.asarray(p[k + j], float) for k in ("hs", "tp", "gamma"))
        ok = (h > 0) & np.isfinite(t)
        wp = 2 * np.pi / np.where(ok, t, 1.0)
        total = total + np.where(ok, h**2 / 16 * wp**n * _g4_gamma_moments(n, g), 0.0)
    return _scalar(total)


def _ochi_args(hs1, tp1, lambda1, hs2, tp2, lambda2):
    out = []
    for j, (h, t, lam) in enumerate(((hs1, tp1, lambda1), (hs2, tp2, lambda2)), 1):
        out.append((_check(f"hs{j}", h, nonneg=True), _check(f"tp{j}", t, positive=True),
                    _check(f"lambda{j}", lam, positive=True)))
    return out


def ochi_hubble(omega, hs1, tp1, lambda1, hs2, tp2, lambda2):
    """Six-parameter Ochi-Hubble spectrum S(omega) [m^2 s/rad]: component 1 (usually the
    swell, lower frequency) and 2 (wind sea), each Hs_j [m], Tp_j [s] and shape lambda_j."""
    omega = _check("omega", omega, nonneg=True)
    total = 0.0
    for h, t, lam in _ochi_args(hs1, tp1, lambda1, hs2, tp2, lambda2):
        wp = 2 * np.pi / t
        c = (4 * lam + 1) / 4
        safe = np.where(omega > 0, omega, 1.0)
        # in logs: (c wp^4)^lam / omega^(4 lam + 1) overflows for large lam
        log_s = lam * np.log(c * wp**4) - np.vectorize(math.lgamma)(lam) \
            - (4 * lam + 1) * np.log(safe) - c * (wp / safe) ** 4
        total = total + np.where(omega > 0, 0.25 * h**2 * np.exp(log_s), 0.0)
    return _scalar(total)


def ochi_hubble_moment(n, hs1, tp1, lambda1, hs2, tp2, lambda2):
    """Exact m_n [m^2 (rad/s)^n] of the Ochi-Hubble spectrum (each component n < 4 lambda_j)."""
    total = 0.0
    for j, (h, t, lam) in enumerate(_ochi_args(hs1, tp1, lambda1, hs2, tp2, lambda2), 1):
        if np.any(n >= 4 * lam):
            raise InputError(f"moment m{n:g} is infinite for lambda{j} <= {n / 4:g}",
                             field=f"lambda{j}", value=float(np.min(lam)))
        wp = 2 * np.pi / t
        lg = np.vectorize(math.lgamma)
        total = total + h**2 / 16 * wp**n * ((4 * lam + 1) / 4) ** (n / 4) * np.exp(lg(lam - n / 4) - lg(lam))
    return _scalar(total)


@dataclass(frozen=True)
class Partition:
    """One wave system (wind sea or swell): a JONSWAP of its own significant height
    ``hs`` [m], peak period ``tp`` [s], peak enhancement ``gamma`` and the direction it
    comes from, ``from_deg`` [deg true] (None: not given)."""

    hs: float
    tp: float
    gamma: float = GAMMA_DEFAULT
    from_deg: float | None = None

    def __post_init__(self):
        _check("hs", self.hs, nonneg=True)
        _check("tp", self.tp, positive=True)
        _check("gamma", self.gamma, positive=True)
        if self.from_deg is not None and not (np.isfinite(self.from_deg) and 0 <= self.from_deg <= 360):
            raise InputError("direction must be within 0-360 deg", field="from_deg", value=self.from_deg)

    def spectrum(self, omega):
        """S(omega) [m^2 s/rad] of this partition."""
        return jonswap(omega, self.hs, self.tp, self.gamma)

    def moment(self, n):
        """Exact m_n [m^2 (rad/s)^n] of this partition (n < 4)."""
        return self.hs**2 / 16 * (2 * np.pi / self.tp) ** n * jonswap_shape_moment(n, self.gamma)


def wind_swell(omega, wind: Partition, swell: Partition, *, partitions=False):
    """Wind sea + swell, the sum of two JONSWAP partitions [m^2 s/rad]; ``partitions=True``
    returns (S_wind, S_swell) apart (to meet each at its own heading)."""
    s_w, s_s = wind.spectrum(omega), swell.spectrum(omega)
    return (s_w, s_s) if partitions else s_w + s_s


def wind_swell_moment(n, wind: Partition, swell: Partition):
    """Exact m_n [m^2 (rad/s)^n] of wind sea + swell: the sum of the partitions' moments."""
    return wind.moment(n) + swell.moment(n)
