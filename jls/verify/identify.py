"""Identification and comparison of records: log decrement, harmonic fits, series
agreement, record statistics.

* :func:`log_decrement`: period and damping ratio of a free decay from its successive
  peaks of one sign. Each peak is located by a parabola through the sample and its
  neighbours; ln(peak) against cycle number is fitted by a straight line whose slope
  is the logarithmic decrement delta, zeta = delta / sqrt(4 pi^2 + delta^2) (exact for
  a viscously damped single mode); the period is the slope of the peak times against
  cycle number (the damped period T_d; T_n = T_d sqrt(1 - zeta^2)). Fit quality: R^2
  of the log-linear fit and the scatter of the peak spacings.
* :func:`harmonic_fit`: the complex amplitude at a known frequency by least squares on a
  window of whole periods, with the free oscillation of a lightly damped mode fitted
  alongside when its frequency and damping are given (a start-up transient that has
  not died out).
* :func:`compare`: correlation coefficient r, coefficient of determination R^2 (of the
  second record as the reference), RMS error (absolute and over the reference's RMS),
  and the ratio of standard deviations.
* :func:`statistics`: sigma, zero-crossing period, most probable maximum of a record.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class DecayFit:
    """Damped period T_d and undamped T_n [s], damping ratio, log decrement per cycle,
    peaks used, R^2 of ln(peak) against cycle, relative scatter of peak spacings,
    peak times [s] and values."""

    period: float
    period_undamped: float
    zeta: float
    delta: float
    n_peaks: int
    r2: float
    period_scatter: float
    peak_time: np.ndarray
    peak_value: np.ndarray

    def as_dict(self) -> dict:
        return {"period_s": self.period, "period_undamped_s": self.period_undamped,
                "zeta": self.zeta, "log_decrement": self.delta, "n_peaks": self.n_peaks,
                "fit_r2": self.r2, "period_scatter": self.period_scatter}


def peaks(t, y):
    """Times and values of the local maxima of y > 0, refined by a parabola."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    i = np.flatnonzero((y[1:-1] > y[:-2]) & (y[1:-1] >= y[2:]) & (y[1:-1] > 0)) + 1
    a, b, c = y[i - 1], y[i], y[i + 1]
    den = a - 2 * b + c
    off = np.where(den != 0, 0.5 * (a - c) / np.where(den != 0, den, 1.0), 0.0)
    h = t[1] - t[0]
    return t[i] + off * h, b - 0.25 * (a - c) * off


def log_decrement(t, y, *, max_peaks=None, min_fraction=0.0) -> DecayFit:
    """Period and damping of a free decay y(t) about zero (see the module docstring).

    Peaks are those of y > 0 that are at least ``min_fraction`` of the first peak (to
    stay above a noise floor), at most ``max_peaks`` of them. Needs three peaks.
    """
    tp, yp = peaks(t, y)
    if yp.size:
        keep = yp >= min_fraction * yp[0]
        tp, yp = tp[keep], yp[keep]
    # successive peaks must be about one period apart: drop peaks of ripple from
    # higher modes riding on the decay (a spacing under half the median)
    if yp.size > 2:
        gap = np.diff(tp)
        med = np.median(gap)
        sel = np.concatenate([[True], gap > 0.5 * med])
        tp, yp = tp[sel], yp[sel]
    if max_peaks is not None:
        tp, yp = tp[:max_peaks], yp[:max_peaks]
    if yp.size < 3:
        raise ValueError(f"a free decay needs at least three peaks, found {yp.size}")
    k = np.arange(yp.size)
    slope, icpt = np.polyfit(k, np.log(yp), 1)
    resid = np.log(yp) - (slope * k + icpt)
    ss = np.sum((np.log(yp) - np.log(yp).mean()) ** 2)
    r2 = 1.0 - np.sum(resid ** 2) / ss if ss > 0 else 1.0
    period = float(np.polyfit(k, tp, 1)[0])
    delta = -float(slope)
    zeta = delta / np.sqrt(4 * np.pi ** 2 + delta ** 2)
    gaps = np.diff(tp)
    return DecayFit(period=period, period_undamped=period * np.sqrt(max(1 - zeta ** 2, 0.0)),
                    zeta=float(zeta), delta=delta, n_peaks=int(yp.size), r2=float(r2),
                    period_scatter=float(np.std(gaps) / np.mean(gaps)), peak_time=tp, peak_value=yp)


def harmonic_fit(t, y, omega, *, mode_omega=None, mode_zeta=0.0):
    """Complex amplitude Y of y ~ Re(Y exp(i omega t)) + mean (+ a decaying free mode).

    mode_omega, mode_zeta: the free mode fitted alongside, exp(-zeta w_n t) times a
    cosine and a sine at its damped frequency. Returns (Y, mean, rms of the residual).
    """
    t, y = np.asarray(t, float), np.asarray(y, float)
    cols = [np.cos(omega * t), -np.sin(omega * t), np.ones_like(t)]
    if mode_omega is not None and abs(mode_omega - omega) > 1e-3 * omega:
        wd = mode_omega * np.sqrt(1 - mode_zeta ** 2)
        env = np.exp(-mode_zeta * mode_omega * (t - t[0]))
        cols += [env * np.cos(wd * t), env * np.sin(wd * t)]
    A = np.stack(cols, -1)
    coef, *_ = np.linalg.lstsq(A, y, rcond=None)
    res = y - A @ coef
    return complex(coef[0], coef[1]), float(coef[2]), float(np.sqrt(np.mean(res ** 2)))


def compare(model, reference) -> dict:
    """Agreement of a model's record with a reference record of the same samples:
    r, R^2 = 1 - SS_res / SS_tot (about the reference's mean), RMS error [record
    units] and over the reference's RMS about its mean, sigma ratio model / reference."""
    a, b = np.asarray(model, float), np.asarray(reference, float)
    da, db = a - a.mean(), b - b.mean()
    r = float(np.sum(da * db) / np.sqrt(np.sum(da ** 2) * np.sum(db ** 2)))
    ss_tot = float(np.sum(db ** 2))
    rms_err = float(np.sqrt(np.mean((a - b) ** 2)))
    return {"r": r, "r2": 1.0 - float(np.sum((a - b) ** 2)) / ss_tot,
            "rms_error": rms_err, "rms_error_relative": rms_err / float(np.sqrt(ss_tot / b.size)),
            "sigma_ratio": float(np.std(a) / np.std(b))}


def statistics(y, dt, exposure_s=3 * 3600.0) -> dict:
    """sigma, mean, zero-crossing period Tz (from the record's variance and velocity
    variance), zero up-crossings counted, most probable maximum over ``exposure_s``
    from sigma (N = exposure / Tz), observed maximum of |y - mean|."""
    y = np.asarray(y, float)
    mean = float(y.mean())
    r = y - mean
    sigma = float(r.std())
    sv = float(np.gradient(r, dt).std())
    tz = 2 * np.pi * sigma / sv if sv > 0 else float("nan")
    n = exposure_s / tz if np.isfinite(tz) else 1.0
    return {"sigma": sigma, "mean": mean, "tz": tz,
            "n_upcrossings": int(np.count_nonzero((r[:-1] < 0) & (r[1:] >= 0))),
            "mpm": sigma * float(np.sqrt(2 * np.log(max(n, 1.0)))),
            "max_observed": float(np.max(np.abs(r)))}


__all__ = ["DecayFit", "peaks", "log_decrement", "harmonic_fit", "compare", "statistics"]
