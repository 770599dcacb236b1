"""Criterion sensitivity: route workability of every option as one limit is swept.

The clearance budget behind the 3.0 m relative-sway criterion is itself an engineering
estimate. Because the model is linear, the unit-Hs statistics already hold everything
needed: for each trial limit the cells are re-judged (``Hs u <= 1`` with the swept
criterion's unit utilisation rebuilt for that limit, the other criteria unchanged)
without solving the plant again. Workability is non-decreasing in a motion limit or a
safe working load and non-increasing in a tension floor.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.workability import assessed_hs, cell_passes, criteria_array, unit_utilisation
from jls.errors import InputError
from jls.names import CRITERIA, SWAY_M

DEFAULT_SWAY_LIMITS_M = tuple(np.round(np.arange(2.0, 4.001, 0.25), 6))


def criterion_sensitivity(response: xr.Dataset, sea: xr.Dataset, criteria: dict,
                          criterion=SWAY_M, limits=DEFAULT_SWAY_LIMITS_M, *,
                          hs_in_bin="centre") -> xr.Dataset:
    """Route and leg workability of every (candidate, tugger) over trial limits of one
    criterion; the other configured criteria keep their limits.

    response: unit-Hs statistics (``response.nc`` layout, tension statistics included
    when a tension criterion is configured or swept); sea: the route's sea-state
    dataset; criteria: the configuration's criteria; limits: trial values of
    ``criterion`` in its unit (m, degree or kN).

    Variables:

    ===================== =================================== ===== ========================
    ``workability_route`` candidate, tugger, trial_limit      1     duration-weighted route
                                                                    workability
    ``workability_leg``   candidate, tugger, leg, trial_limit 1     probability-weighted leg
                                                                    workability
    ===================== =================================== ===== ========================

    Coordinate ``trial_limit`` carries the unit of the criterion; attributes name the
    swept criterion and ``hs_in_bin``.
    """
    if criterion not in CRITERIA:
        raise InputError(f"unknown criterion; one of {', '.join(CRITERIA)}", field="criterion",
                         value=criterion)
    limits = np.atleast_1d(np.asarray(limits, float))
    if limits.size == 0 or not np.all(np.isfinite(limits)) or np.any(limits < 0):
        raise InputError("trial limits must be finite and non-negative", field=criterion,
                         value=limits.tolist())
    stats = response.sel(tz=sea["tz"])
    hs = assessed_hs(sea, hs_in_bin)
    weight = sea["cell_probability"]                          # (leg, heading, hs, tz)
    # The other criteria do not depend on the trial limit: their pass flags once (the tip
    # clearance's limiting Hs is a Newton solve per cell), the swept one per trial, one
    # trial limit at a time: memory of one assessment, whatever the number of trials.
    others = {k: v for k, v in criteria.items() if k != criterion and v is not None}
    fixed = cell_passes(hs * unit_utilisation(stats, criteria_array(others))) if others else True
    legs = [(weight * (fixed & cell_passes(hs * unit_utilisation(
                stats, criteria_array({criterion: float(v)}))))).sum(("heading", "hs", "tz"))
            for v in limits]
    work_leg = xr.concat(legs, dim=xr.DataArray(limits, dims="trial_limit"), coords="minimal",
                         compat="override")
    work_route = (work_leg * sea["leg_weight"]).sum("leg")
    ds = xr.Dataset({
        "workability_leg": work_leg.transpose("candidate", "tugger", "leg", "trial_limit"),
        "workability_route": work_route.transpose("candidate", "tugger", "trial_limit"),
    })
    ds["workability_leg"].attrs.update(long_name="probability-weighted workable fraction of the leg",
                                       units="1")
    ds["workability_route"].attrs.update(long_name="duration-weighted workable fraction of the route",
                                         units="1")
    ds["trial_limit"].attrs.update(long_name=f"trial limit of {criterion}", units=CRITERIA[criterion][1])
    ds.attrs.update(criterion=criterion, hs_in_bin=hs_in_bin,
                    configured_limit=float(criteria.get(criterion, np.nan) or np.nan))
    return ds


__all__ = ["DEFAULT_SWAY_LIMITS_M", "criterion_sensitivity"]
