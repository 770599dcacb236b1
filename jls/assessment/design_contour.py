"""The unrestricted design check: the response in the design sea states of the return
period, along an environmental contour of each leg's sea states (IFORM).

**The joint model** (fitted per leg, on the hourly records of the season or on the
scatter table's cells weighted by their probability): the Hs-Tz model of Haselsteiner
et al. (2019, the OMAE 2019 contour benchmark; the model virocon ships as "OMAE2020"),
in a closed-form simplification for the period:

* Hs follows an exponentiated Weibull distribution, F(h) = (1 - exp(-(h / lambda)^k))^a,
  fitted by weighted maximum likelihood (its upper tail follows the records' largest
  values far better than a two- or three-parameter Weibull fitted to all sea states);
* ln Tz given Hs is normal with mean ln(c + d sqrt(Hs)) (c, d by weighted least
  squares of Tz on sqrt(Hs): the period grows as the root of the height, a steepness
  that tends to a constant in storms) and standard deviation s, the residuals' of the
  sea states in the top 10 % of Hs (the spread narrows as Hs grows; the contour's
  design points lie far above that quantile) -- the conditional modelling approach of
  DNV-RP-C205 3.6.4.

The model is implemented here rather than taken from virocon: it takes a scatter table's
weighted cells as well as records, and it degenerates gracefully: a leg whose every sea
state is one (Hs, Tz) has that sea state as its contour. Contour points are not capped
by the steepness rule.

**The contour** (IFORM, inverse first-order reliability method): the sea states
``(F_Hs^-1(Phi(beta cos theta)), exp(a + b ln Hs + s beta sin theta))`` for theta round
the circle, beta = Phi^-1(1 - p), p = T_s / (R T_season) the probability that a sea
state of duration T_s (the assessment exposure, 3 h) is the return period's R-year one
within the season (its months' share of the year).

**The design check** (:func:`design_check`): each contour point is a sea state, assessed
as a recorded hour is (unit statistics interpolated in Tz, the worst of the leg's
headings, :func:`jls.assessment.route_simulation.hourly_statistics`); the design level
of a criterion on a leg is the largest over the contour of its MPM, its design
utilisation that over the limit. The transit is acceptable as an unrestricted transit
when every design utilisation stays at most 1 (below 1 for a strict criterion).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr
from scipy.optimize import minimize
from scipy.special import ndtr, ndtri
from scipy.stats import exponweib

from jls.assessment.route_simulation import hourly_statistics
from jls.errors import InputError

HOURS_PER_YEAR = 8766.0
N_ANGLES = 72
METHOD = ("IFORM contour of a fitted joint model: Hs exponentiated Weibull (weighted maximum "
          "likelihood, after Haselsteiner et al. 2019), ln Tz normal given Hs with mean "
          "ln(c + d sqrt(Hs)) and the spread of the top 10 % of Hs")
UPPER = 0.9                    # the sea states above this Hs quantile give the Tz spread


@dataclass(frozen=True)
class JointModel:
    """Hs exponentiated Weibull (scale ``lam`` [m], shapes ``k`` and ``a``; k = inf: one
    Hs), ln Tz | Hs normal with mean ``ln(c + d sqrt(Hs))`` and standard deviation ``s``."""

    lam: float
    k: float
    a: float
    c: float
    d: float
    s: float

    def hs(self, p):
        """Hs at non-exceedance probability p."""
        p = np.asarray(p, float)
        if not np.isfinite(self.k):
            return np.full(p.shape, self.lam)
        return self.lam * (-np.log1p(-p ** (1.0 / self.a))) ** (1.0 / self.k)

    def contour(self, beta: float, n: int = N_ANGLES):
        """(hs, tz) of the IFORM contour of reliability index ``beta`` at n angles."""
        th = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
        u1, u2 = beta * np.cos(th), beta * np.sin(th)
        hs = self.hs(ndtr(u1))
        tz = (self.c + self.d * np.sqrt(hs)) * np.exp(self.s * u2)
        return hs, tz


def _exponweib(h, w):
    """(lam, k, a) of the exponentiated Weibull by weighted maximum likelihood; the
    sea states are pooled by Hs to the centimetre first (the likelihood of 87 600
    records in a few hundred terms)."""
    key, inv = np.unique(np.round(h, 2), return_inverse=True)
    key = np.maximum(key, 0.005)
    ww = np.bincount(inv, weights=w)
    x = np.log(key)

    def nll(p):
        k, a, lam = np.exp(p)
        with np.errstate(all="ignore"):
            v = -float(ww @ exponweib.logpdf(key, a, k, scale=lam))
        return v if np.isfinite(v) else 1e300
    mx = float(ww @ x)
    sx = float(np.sqrt(ww @ (x - mx) ** 2))
    k0 = np.pi / (np.sqrt(6.0) * max(sx, 1e-6))
    start = np.log([k0, 1.0, np.exp(mx + 0.5772 / k0)])
    res = minimize(nll, start, method="Nelder-Mead", options={"xatol": 1e-7, "fatol": 1e-10, "maxiter": 6000})
    k, a, lam = np.exp(res.x)
    return float(lam), float(k), float(a)


def fit(hs, tz, weight=None, source=None) -> JointModel:
    """The joint model of sea states (hs [m], tz [s]) with weights (counts or
    probabilities; None: equal). Sea states without a positive Hs, Tz and weight are
    left out; none left is an InputError naming ``source``."""
    hs, tz = np.asarray(hs, float).ravel(), np.asarray(tz, float).ravel()
    w = np.ones(hs.size) if weight is None else np.asarray(weight, float).ravel()
    ok = np.isfinite(hs) & np.isfinite(tz) & np.isfinite(w) & (hs > 0) & (tz > 0) & (w > 0)
    if not ok.any():
        raise InputError("no sea state with a positive Hs and Tz to fit the design contour to",
                         file=source)
    h, t, w = hs[ok], tz[ok], w[ok] / w[ok].sum()
    x = np.log(h)
    mx = float(w @ x)
    if float(np.sqrt(max(w @ (x - mx) ** 2, 0.0))) <= 1e-12:      # one Hs: a point
        return JointModel(float(h[0]), np.inf, 1.0, float(w @ t), 0.0, 0.0)
    lam, k, a = _exponweib(h, w)
    r = np.sqrt(h)
    mr, mt = float(w @ r), float(w @ t)
    d = float(w @ ((r - mr) * (t - mt)) / (w @ (r - mr) ** 2))
    c = mt - d * mr
    mean = c + d * r
    if np.any(mean <= 0):
        raise InputError("the fitted mean period is not positive at every Hs", file=source)
    res = np.log(t) - np.log(mean)
    order = np.argsort(h)
    upper = np.zeros(h.size, bool)
    upper[order[np.cumsum(w[order]) > UPPER - 1e-12]] = True
    wu = w[upper] / w[upper].sum()
    s = float(np.sqrt(max(wu @ (res[upper] - wu @ res[upper]) ** 2, 0.0)))
    return JointModel(lam, k, a, c, d, s)


def reliability_index(return_period_years: float, state_h: float, season_share: float = 1.0) -> float:
    """beta of the IFORM contour: Phi^-1(1 - T_s / (R x 8766 h x season share))."""
    p = state_h / (return_period_years * HOURS_PER_YEAR * season_share)
    if not 0 < p < 1:
        raise InputError("the design return period must be longer than a sea state",
                         field="operation.design_return_period_years", value=return_period_years)
    return float(ndtri(1.0 - p))


def contours(models: dict, beta: float, n: int = N_ANGLES) -> xr.Dataset:
    """``contour_hs``, ``contour_tz`` (leg, angle) of leg name -> :class:`JointModel`."""
    legs = list(models)
    pts = [models[leg].contour(beta, n) for leg in legs]
    angle = np.linspace(0.0, 360.0, n, endpoint=False)
    return xr.Dataset({"contour_hs": (("leg", "angle"), np.array([p[0] for p in pts])),
                       "contour_tz": (("leg", "angle"), np.array([p[1] for p in pts]))},
                      coords={"leg": legs, "angle": angle})


def design_check(stats: xr.Dataset, contour: xr.Dataset, heading_probability: xr.DataArray,
                 limit: xr.DataArray) -> xr.Dataset:
    """The design levels along the contours (module docstring).

    stats: :func:`jls.assessment.criterion_levels.criterion_statistics` of
    ``operability.nc``; contour: :func:`contours`. Returns over (..., criterion, leg):
    ``design_level`` (the largest MPM over the contour, level units), ``design_utilisation``
    (over the limit), ``design_hs``, ``design_tz`` (the contour point that gives it)."""
    hours = xr.Dataset({"hs": contour["contour_hs"].rename(angle="time"),
                        "tz": contour["contour_tz"].rename(angle="time")})
    hs_stats, _ = hourly_statistics(stats, hours, heading_probability)
    level = hs_stats["level"]
    at = level.fillna(-np.inf).argmax("time")
    out = xr.Dataset({"design_level": level.max("time"),
                      "design_hs": hours["hs"].isel(time=at).drop_vars("time", errors="ignore"),
                      "design_tz": hours["tz"].isel(time=at).drop_vars("time", errors="ignore")})
    out["design_utilisation"] = out["design_level"] / limit
    return out


def verdict(design: xr.Dataset, strict=None) -> xr.DataArray:
    """(..., ) True where every criterion on every leg stays inside its limit (a strict
    criterion below it)."""
    u = design["design_utilisation"]
    bad = u > 1.0
    if strict is not None:
        bad = bad | ((u >= 1.0) & xr.DataArray(strict).broadcast_like(u))
    return ~(bad | u.isnull()).any(("criterion", "leg"))
