"""Whether the recommendation survives the uncertainty band and the criterion sweep.

Pure functions of ``workability.nc`` (variables ``workability_route_variant`` and
``workability_route_sensitivity``, :mod:`jls.assessment.bands`) and of the
recommended combination and the combinations it was chosen among. The caller passes
those (``eligible``), so whatever excludes a combination from the recommendation
(infeasible rigging, a saturated winch, ...) excludes it here too: the recommendation
*holds* in a variant when no eligible combination beats it there by more than
:func:`jls.assessment.recommendation.tie_tolerance` (workability.nc's).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from jls.assessment.recommendation import tie_tolerance

VARIANT_DIMS = ("damping_factor", "sway_frequency_factor", "hs_in_bin")


def has_bands(work: xr.Dataset) -> bool:
    return "workability_route_variant" in work


def has_sensitivity(work: xr.Dataset) -> bool:
    return "workability_route_sensitivity" in work


def _options(da: xr.DataArray, eligible) -> xr.DataArray:
    """``da`` over one ``option`` axis of the eligible (candidate, tugger) pairs."""
    parts = [da.sel(candidate=c, tugger=t, drop=True) for c, t in eligible]
    return xr.concat(parts, dim=xr.DataArray([f"{c} / {t}" for c, t in eligible], dims="option"))


@dataclass
class Verdict:
    """Where the recommendation holds: ``holds`` over every variant; ``losers`` the
    variants (a dict of the variant coordinates) where another option is best, with it."""

    holds: bool
    variants: int
    losers: list = field(default_factory=list)


def banded(work: xr.Dataset, combo) -> bool:
    """True when the combination's candidate was varied (its band is known)."""
    v = work["workability_route_variant"].sel(candidate=combo[0], tugger=combo[1])
    return bool(np.isfinite(v.values).all())


def recommendation_holds(work: xr.Dataset, best, eligible) -> Verdict:
    """Does ``best`` stay (one of) the best of ``eligible`` in every variant of the band?
    Options whose candidate was not varied are left out of the comparison."""
    eligible = [ct for ct in eligible if banded(work, ct)]
    w = _options(work["workability_route_variant"], eligible)
    mine = w.sel(option=f"{best[0]} / {best[1]}")
    top = w.max("option")
    lost = (mine < top - tie_tolerance(work))
    stacked = lost.stack(v=[d for d in VARIANT_DIMS if d in lost.dims])
    winners = w.idxmax("option").stack(v=list(stacked.indexes["v"].names))
    losers = []
    for i in np.flatnonzero(stacked.values):
        coords = {n: stacked["v"].values[i][k] for k, n in enumerate(stacked.indexes["v"].names)}
        losers.append((coords, str(winners.values[i])))
    return Verdict(bool(not stacked.any()), int(stacked.size), losers)


def sensitivity_switches(work: xr.Dataset, eligible, tie_key) -> list[tuple[float, tuple]]:
    """The best eligible option at each trial sway limit, as (limit, option) runs where
    it changes; ties broken by ``tie_key`` (the report's rule)."""
    s = work["workability_route_sensitivity"].transpose("candidate", "tugger", "trial_limit")
    ci = {str(c): i for i, c in enumerate(s["candidate"].values)}
    ti = {str(t): j for j, t in enumerate(s["tugger"].values)}
    rows = np.array([ci[c] for c, _ in eligible], int)
    cols = np.array([ti[t] for _, t in eligible], int)
    table = s.values[rows, cols, :]                      # (eligible, trial_limit)
    out = []
    for k, lim in enumerate(s["trial_limit"].values):
        vals = dict(zip(eligible, map(float, table[:, k])))
        top = max(vals.values())
        best = min((ct for ct in eligible if vals[ct] >= top - tie_tolerance(work)), key=tie_key)
        if not out or out[-1][1] != best:
            out.append((float(lim), best))
    return out


__all__ = ["VARIANT_DIMS", "banded", "has_bands", "has_sensitivity", "Verdict", "recommendation_holds",
           "sensitivity_switches"]
