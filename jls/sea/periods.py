"""Wave periods of every spectrum: the project's one statement of the period conventions.

With the spectral moments m_n = int omega^n S(omega) domega (omega in rad/s; with moments
in Hz, drop the 2 pi)::

    Tp   = 2 pi / omega_p           omega_p where S is largest    NDBC DPD, ERA5 pp1d, WW3 tp (1/fp)
    Tm01 = 2 pi m0 / m1             mean period T1                WW3 t01
    Tz   = 2 pi sqrt(m0 / m2)       Tm02, zero-up-crossing period NDBC APD, WW3 t02
    Te   = 2 pi m-1 / m0            Tm-10, energy period          ERA5 mwp, mpww, mpts; WW3 t0m1

The ratios between them depend on the spectrum, so every conversion goes through
:func:`spectrum_periods` (periods of a spectrum from its parameters) or
:func:`tp_from_period` (the Tp that gives a declared Tz, Tm01 or Te):

* ``jonswap`` (hs, tp, gamma[, method="dnv"]): Tz and Tm01 from the DNV-RP-C205
  polynomials of :mod:`jls.sea.spectra` (``method="exact"``: the moment ratios), Te
  exact; Tz/Tp = 0.778 at gamma 3.3 (Tp = 1.286 Tz, the pipeline's rule).
* ``torsethaugen`` (hs, tp): exact moments of its two wave systems; the ratios depend on
  Hs and Tp (:mod:`jls.sea.two_peak`).
* ``ochi_hubble`` (hs1, tp1, lambda1, hs2, tp2, lambda2): exact moments.
* ``wind_swell`` (wind, swell: :class:`jls.sea.two_peak.Partition`): the sum of the
  partitions' exact moments.

Tp of a two-peak spectrum is its global maximum, found numerically near the
components' peaks (for Torsethaugen within a fraction of a percent of the given Tp).
A period is declared, never guessed: a table or hindcast giving Tp instead of Tz says
so, and :func:`tp_from_period` turns a declared Tz (or Te) into the Tp a spectrum needs.
"""

from __future__ import annotations

import math

import numpy as np

from jls.errors import InputError
from jls.sea import spectra, two_peak

__all__ = ["SPECTRA", "PERIODS", "from_moments", "spectrum_periods", "tp_from_period"]

SPECTRA = ("jonswap", "torsethaugen", "ochi_hubble", "wind_swell")
PERIODS = ("tp", "tm01", "tz", "te")


def from_moments(m_minus1, m0, m1, m2):
    """Tm01, Tz (= Tm02) and Te (= Tm-10) [s] from moments in rad/s (any shapes)."""
    m_1, m0, m1, m2 = (np.asarray(v, float) for v in (m_minus1, m0, m1, m2))
    with np.errstate(divide="ignore", invalid="ignore"):
        return {"tm01": 2 * np.pi * m0 / m1, "tz": 2 * np.pi * np.sqrt(m0 / m2),
                "te": 2 * np.pi * m_1 / m0}


def _need(spectrum, params, names):
    missing = [n for n in names if n not in params]
    if missing:
        raise InputError(f"spectrum '{spectrum}' needs {', '.join(names)}", field=spectrum,
                         value=sorted(params))


def _method(params):
    """The JONSWAP period relation: "dnv" (the DNV-RP-C205 polynomials, the pipeline's)
    unless ``method="exact"`` is given."""
    return params["method"] if "method" in params else "dnv"


def _partition(p, name):
    if isinstance(p, two_peak.Partition):
        return p
    if isinstance(p, dict):
        return two_peak.Partition(**p)
    raise InputError("a partition is a Partition or a mapping hs, tp[, gamma, from_deg]",
                     field=name, value=p)


def _peak(fn, omegas):
    """omega [rad/s] of the largest maximum of fn near the candidate peaks ``omegas``."""
    from scipy.optimize import minimize_scalar  # here: importing scipy.optimize costs a job 0.3 s
    best, best_w = -np.inf, np.nan
    for wp in omegas:
        if not (np.isfinite(wp) and wp > 0):
            continue
        r = minimize_scalar(lambda w: -float(fn(w)), bounds=(0.7 * wp, 1.4 * wp), method="bounded",
                            options={"xatol": 1e-9 * wp})
        if -r.fun > best:
            best, best_w = -r.fun, float(r.x)
    return best_w


def _moments(spectrum, p):
    """(m_-1, m0, m1, m2) and a callable S(omega) with its candidate peak frequencies."""
    if spectrum == "torsethaugen":
        _need(spectrum, p, ("hs", "tp"))
        m = [two_peak.torsethaugen_moment(n, p["hs"], p["tp"]) for n in (-1, 0, 1, 2)]
        par = two_peak.torsethaugen_parameters(p["hs"], p["tp"])
        cand = [2 * np.pi / float(par["tp1"]), 2 * np.pi / float(par["tp2"])]
        return m, (lambda w: two_peak.torsethaugen(w, p["hs"], p["tp"])), cand
    if spectrum == "ochi_hubble":
        names = ("hs1", "tp1", "lambda1", "hs2", "tp2", "lambda2")
        _need(spectrum, p, names)
        args = [p[k] for k in names]
        m = [two_peak.ochi_hubble_moment(n, *args) for n in (-1, 0, 1, 2)]
        return m, (lambda w: two_peak.ochi_hubble(w, *args)), [2 * np.pi / p["tp1"], 2 * np.pi / p["tp2"]]
    if spectrum == "wind_swell":
        _need(spectrum, p, ("wind", "swell"))
        wind, swell = _partition(p["wind"], "wind"), _partition(p["swell"], "swell")
        m = [two_peak.wind_swell_moment(n, wind, swell) for n in (-1, 0, 1, 2)]
        return m, (lambda w: two_peak.wind_swell(w, wind, swell)), [2 * np.pi / wind.tp, 2 * np.pi / swell.tp]
    raise InputError(f"unknown spectrum (known: {', '.join(SPECTRA)})", field="spectrum", value=spectrum)


def spectrum_periods(spectrum, **params) -> dict:
    """Hs [m] and the periods Tp, Tm01, Tz, Te [s] of a parametric spectrum (scalars).

    ``spectrum``: one of :data:`SPECTRA`; ``params`` as listed in the module docstring.
    """
    if spectrum == "jonswap":
        _need(spectrum, params, ("hs", "tp", "gamma"))
        hs, tp, g = float(params["hs"]), float(params["tp"]), float(params["gamma"])
        method = _method(params)
        return {"hs": hs, "tp": tp, "tm01": float(spectra.t1_from_tp(tp, g, method)),
                "tz": float(spectra.tz_from_tp(tp, g, method)), "te": float(spectra.te_from_tp(tp, g))}
    (m_1, m0, m1, m2), fn, cand = _moments(spectrum, params)
    out = {k: float(v) for k, v in from_moments(m_1, m0, m1, m2).items()}
    return {"hs": 4.0 * math.sqrt(float(m0)), "tp": 2 * np.pi / _peak(fn, cand), **out}


def tp_from_period(spectrum, period, value, **params) -> float:
    """The peak period Tp [s] at which ``spectrum`` has the declared ``period`` (one of
    "tz", "tm01", "te", or "tp", returned as given) equal to ``value`` [s].

    jonswap: the inverse of its ratio (gamma, method as :func:`spectrum_periods`);
    torsethaugen: solved for Tp at the given ``hs`` (the ratio depends on Hs and Tp).
    """
    if period not in PERIODS:
        raise InputError(f"period must be one of {', '.join(PERIODS)}", field="period", value=period)
    value = float(spectra._check(period, value, positive=True))
    if period == "tp":
        return value
    if spectrum == "jonswap":
        _need(spectrum, params, ("gamma",))
        g, method = float(params["gamma"]), _method(params)
        ratio = {"tz": lambda: spectra.tz_from_tp(1.0, g, method),
                 "tm01": lambda: spectra.t1_from_tp(1.0, g, method),
                 "te": lambda: spectra.te_from_tp(1.0, g)}[period]()
        return value / float(ratio)
    if spectrum == "torsethaugen":
        _need(spectrum, params, ("hs",))
        hs = float(params["hs"])

        def resid(tp):
            return spectrum_periods("torsethaugen", hs=hs, tp=tp)[period] - value
        lo, hi = 0.5 * value, 4.0 * value
        if resid(lo) * resid(hi) > 0:
            raise InputError(f"no Torsethaugen sea state with Hs {hs:g} m has {period} {value:g} s",
                             field=period, value=value)
        from scipy.optimize import brentq
        return float(brentq(resid, lo, hi, xtol=1e-10))
    raise InputError(f"a declared {period} fixes the Tp of 'jonswap' or 'torsethaugen' only; "
                     f"give '{spectrum}' its peak periods", field="spectrum", value=spectrum)
