"""The operational basis of a transit (DNV-ST-N001): weather-restricted or unrestricted,
and for a weather-restricted operation the forecast limits the master sails by.

DNV-ST-N001 designs a marine operation either on a weather forecast or on statistics:

* the *reference period* is the planned operation period plus the contingency time,
  ``T_R = T_POP + T_C``;
* an operation may be **weather-restricted** when ``T_POP <= 72 h`` and ``T_R <= 96 h``
  (:data:`RESTRICTED_MAX_POP_H`, :data:`RESTRICTED_MAX_REFERENCE_H`): it starts only on a
  favourable forecast, and its operational limit OP_LIM (here: the limiting Hs per Tz and
  heading of the assessment) is reduced by the forecast-uncertainty factor alpha to the
  forecast limit OP_WF = alpha OP_LIM;
* a longer operation is **unrestricted**: it cannot rely on a forecast for its whole
  duration and is designed on the statistics of the season, here the voyage extremes of
  the route (the largest response expected over the whole voyage), not on a workability
  share.

The alpha factor depends on the planned operation period, the limiting Hs and the
forecast's quality; the standard tabulates it. No table is assumed here: it is configured
with its source (``operation.alpha_factors``), and without one the forecast limits are not
given and the report says alpha was not applied.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError

RESTRICTED_MAX_POP_H = 72.0
RESTRICTED_MAX_REFERENCE_H = 96.0
RESTRICTED, UNRESTRICTED = "weather-restricted", "unrestricted"


@dataclass(frozen=True)
class Basis:
    """Planned period, contingency and reference period [h], the class and why."""

    planned_h: float
    contingency_h: float | None
    reference_h: float
    operation_class: str
    reason: str


def classify(planned_h: float, contingency_h: float | None) -> Basis:
    """The class of an operation of ``planned_h`` hours with ``contingency_h`` hours of
    contingency (None: not stated; the reference period is then the planned period, a
    lower bound, and the reason says so)."""
    if not planned_h > 0:
        raise InputError("the planned operation period must be positive",
                         field="operation.planned_period_h", value=planned_h)
    reference = planned_h + (contingency_h or 0.0)
    stated = "" if contingency_h is not None else " (no contingency time stated: T_R is a lower bound)"
    if planned_h <= RESTRICTED_MAX_POP_H and reference <= RESTRICTED_MAX_REFERENCE_H:
        return Basis(planned_h, contingency_h, reference, RESTRICTED,
                     f"T_POP {planned_h:g} h <= {RESTRICTED_MAX_POP_H:g} h and T_R {reference:g} h "
                     f"<= {RESTRICTED_MAX_REFERENCE_H:g} h{stated}")
    which = (f"T_POP {planned_h:g} h > {RESTRICTED_MAX_POP_H:g} h" if planned_h > RESTRICTED_MAX_POP_H
             else f"T_R {reference:g} h > {RESTRICTED_MAX_REFERENCE_H:g} h")
    return Basis(planned_h, contingency_h, reference, UNRESTRICTED, which + stated)


@dataclass(frozen=True)
class AlphaTable:
    """Forecast-uncertainty factors alpha (period, Hs) with their source: ``period_h``
    (n_p,) planned operation periods, ``hs_m`` (n_h,) limiting Hs, ``alpha`` (n_p, n_h)."""

    source: str
    period_h: np.ndarray
    hs_m: np.ndarray
    alpha: np.ndarray

    def __post_init__(self):
        p, h, a = (np.asarray(x, float) for x in (self.period_h, self.hs_m, self.alpha))
        if a.shape != (p.size, h.size):
            raise InputError(f"alpha is {a.shape[0]} x {a.shape[1] if a.ndim > 1 else 0}, expected "
                             f"{p.size} periods x {h.size} Hs values", field="operation.alpha_factors.alpha",
                             value=a.tolist())
        for name, x in (("planned_period_h", p), ("hs_m", h)):
            if x.size < 1 or np.any(np.diff(x) <= 0):
                raise InputError("must increase strictly", field=f"operation.alpha_factors.{name}",
                                 value=x.tolist())
        if np.any((a <= 0) | (a > 1)):
            raise InputError("alpha factors lie in (0, 1]", field="operation.alpha_factors.alpha",
                             value=a.tolist())

    def factor(self, period_h: float, hs) -> np.ndarray:
        """alpha at one planned period and any Hs: linear between the table's values, held
        at its ends in Hs (never extrapolated); a period outside the table is an error."""
        p, h, a = (np.asarray(x, float) for x in (self.period_h, self.hs_m, self.alpha))
        if not p[0] <= period_h <= p[-1]:
            raise InputError(f"the planned operation period lies outside the alpha table "
                             f"({p[0]:g}-{p[-1]:g} h, {self.source})",
                             field="operation.alpha_factors.planned_period_h", value=period_h)
        row = np.array([np.interp(period_h, p, a[:, j]) for j in range(h.size)])
        return np.interp(np.asarray(hs, float), h, row)


def forecast_limits(hs_limit: xr.DataArray, basis: Basis, alpha: AlphaTable | None) -> xr.Dataset:
    """OP_LIM (the limiting Hs, ``hs_limit``) and, for a weather-restricted operation with
    an alpha table, alpha and OP_WF = alpha OP_LIM, on the dims of ``hs_limit``."""
    out = xr.Dataset({"hs_oplim": hs_limit})
    if basis.operation_class == RESTRICTED and alpha is not None:
        a = xr.apply_ufunc(lambda x: alpha.factor(basis.planned_h, x), hs_limit.fillna(0.0))
        out["alpha_factor"] = a.where(hs_limit.notnull())
        out["hs_opwf"] = out["alpha_factor"] * hs_limit
    return out


@dataclass(frozen=True)
class StretchClass:
    """The class of one stretch of a route (its legs from a hold point up to the next):
    the leg names, the :class:`Basis` of its planned period (the legs' durations) and
    contingency (the sum of those its legs state; None when none does), and the
    statement of what would make it weather-restricted ('' when it is)."""

    legs: tuple
    basis: Basis
    statement: str

    @property
    def restricted(self) -> bool:
        return self.basis.operation_class == RESTRICTED


def stretch_classes(names, duration_h, hold_point, contingency_h) -> list[StretchClass]:
    """The class of every stretch (DNV-ST-N001, :func:`classify`): ``hold_point`` per
    leg (the first leg's start always is one), ``contingency_h`` per leg (None: not
    stated). A leg longer than :data:`RESTRICTED_MAX_POP_H` is named: to be
    weather-restricted it must be split at a hold point; a longer stretch of shorter
    legs needs a hold point between them."""
    n = len(names)
    hold = [True] + [bool(h) for h in list(hold_point)[1:]]
    starts = [k for k in range(n) if hold[k]] + [n]
    out = []
    for a, b in zip(starts[:-1], starts[1:]):
        legs = tuple(str(x) for x in names[a:b])
        planned = float(sum(float(d) for d in duration_h[a:b]))
        stated = [float(c) for c in contingency_h[a:b] if c is not None]
        basis = classify(planned, sum(stated) if stated else None)
        words = []
        for leg, d in zip(legs, duration_h[a:b]):
            if float(d) > RESTRICTED_MAX_POP_H:
                words.append(f"leg {leg} ({float(d):g} h) is longer than {RESTRICTED_MAX_POP_H:g} h: "
                             "to be weather-restricted it must be split at a hold point")
        if basis.operation_class != RESTRICTED and len(legs) > 1:
            words.append(f"the stretch of legs {', '.join(legs)} ({planned:g} h) needs a hold point "
                         "between its legs")
        elif basis.operation_class != RESTRICTED and not words:
            words.append(f"leg {legs[0]} ({basis.reason}) needs a shorter contingency time")
        out.append(StretchClass(legs, basis, "; ".join(words)))
    return out
