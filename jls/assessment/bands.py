"""Uncertainty bands and criterion sensitivity added to the workability dataset.

*Bands* (section 3.5 of the study): the plant is uncertain in its damping (a factor of
two either way about the identified 0.98 % of critical) and its sway frequency (+/- 3 %),
and a scatter bin's Hs may be taken at its centre or its upper edge. The response of
the plant variants of :func:`jls.assessment.uncertainty.plant_variants` (extra candidates, cost
linear in candidates) is assessed for both Hs choices
(:func:`jls.assessment.uncertainty.assess_variants`). The band of an option is the lowest and the
highest workability over the variants *and* the nominal assessment itself, so the
nominal value the report quotes always lies inside its band.

*Criterion sensitivity*: route and leg workability of every option as the relative-sway
limit is swept over 2-4 m (:func:`jls.assessment.criterion_sweep.criterion_sensitivity`).

Both are pure functions of datasets already written (``response_variants.nc``,
``response.nc``, ``sea_states.nc``); the variables they return are merged into
``workability.nc``.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.criterion_sweep import DEFAULT_SWAY_LIMITS_M, criterion_sensitivity
from jls.assessment.uncertainty import VARIANT_DIMS, assess_variants
from jls.names import SWAY_M

HS_CHOICES = ("centre", "upper")
BAND_DIMS = (*VARIANT_DIMS, "hs_in_bin")


def band_variables(variant_response: xr.Dataset, sea: xr.Dataset, criteria: dict,
                   nominal: xr.Dataset, *, steepness_rule="study", gamma=3.3,
                   tuggers=None, winch_saturation=None) -> xr.Dataset:
    """Workability over the plant variants and Hs choices, and its band per option.

    variant_response: unit-Hs statistics of the variant candidates (coordinates
    ``base_candidate``, ``damping_factor``, ``sway_frequency_factor`` on ``candidate``);
    nominal: the workability dataset of the nominal plant (its ``workability_route``,
    ``workability_leg`` and ``hs_limit`` are folded into the band).

    Variables: ``workability_route_variant`` (candidate, tugger, damping_factor,
    sway_frequency_factor, hs_in_bin), ``workability_leg_variant`` (the same with leg),
    ``workability_route_min`` / ``_max`` (candidate, tugger), ``workability_leg_min`` /
    ``_max`` (candidate, tugger, leg), ``hs_limit_min`` / ``_max`` (candidate, tugger,
    heading, tz). Candidates without variants (a large grid varies only the shown
    candidates) have NaN bands.

    tuggers ({name: Tugger}) and winch_saturation (the policy): each variant is held to
    the winch limits as the nominal plant is, on its own tugger loads (a variant with
    less damping pulls harder on the lines); under ``fail`` its saturated cells fail.
    Time-domain verdicts belong to the nominal plant and are not carried over.
    """
    def winch_limits(work, h):
        from jls.assessment.winch_limits import apply_winch_limits
        from jls.assessment.workability import assessed_hs
        return apply_winch_limits(work, variant_response, sea, tuggers, assessed_hs(sea, h),
                                  winch_saturation)

    adjust = winch_limits if winch_saturation is not None else None
    runs = assess_variants(variant_response, sea, criteria, variant_response, HS_CHOICES,
                           adjust=adjust, steepness_rule=steepness_rule, gamma=gamma)
    runs = runs.reindex(candidate=nominal["candidate"].values)    # NaN: a candidate not varied
    out = xr.Dataset()
    for name in ("workability_route", "workability_leg"):
        v = runs[name]
        out[f"{name}_variant"] = v.transpose("candidate", "tugger", ..., *BAND_DIMS)
        out[f"{name}_min"] = np.minimum(v.min(BAND_DIMS), nominal[name])
        out[f"{name}_max"] = np.maximum(v.max(BAND_DIMS), nominal[name])
    hl = runs["hs_limit"]
    out["hs_limit_min"] = np.minimum(hl.min(BAND_DIMS), nominal["hs_limit"])
    out["hs_limit_max"] = np.maximum(hl.max(BAND_DIMS), nominal["hs_limit"])
    out = out.drop_vars([c for c in out.coords if c in ("response", "unit", "strict")], errors="ignore")
    out.attrs.update(damping_factors=[float(x) for x in runs["damping_factor"].values],
                     sway_frequency_factors=[float(x) for x in runs["sway_frequency_factor"].values],
                     hs_in_bin_choices=" ".join(HS_CHOICES))
    return out


def sensitivity_variables(response: xr.Dataset, sea: xr.Dataset, criteria: dict, *,
                          hs_in_bin="centre", limits=DEFAULT_SWAY_LIMITS_M) -> xr.Dataset:
    """Route and leg workability of every option over trial relative-sway limits:
    ``workability_route_sensitivity`` (candidate, tugger, trial_limit) and
    ``workability_leg_sensitivity`` (candidate, tugger, leg, trial_limit)."""
    s = criterion_sensitivity(response, sea, criteria, SWAY_M, limits, hs_in_bin=hs_in_bin)
    out = xr.Dataset({"workability_route_sensitivity": s["workability_route"],
                      "workability_leg_sensitivity": s["workability_leg"]})
    out.attrs.update(sensitivity_criterion=s.attrs["criterion"])
    return out


def merge_into(work: xr.Dataset, *parts: xr.Dataset) -> xr.Dataset:
    """The workability dataset with the variables of ``parts`` (their attributes kept on
    the variables, theirs dataset attributes added to the dataset's)."""
    for part in parts:
        for name, da in part.data_vars.items():
            work[name] = da
        for c in part.coords:
            if c not in work.coords and c in part.dims:
                work = work.assign_coords({c: part[c]})
        work.attrs.update(part.attrs)
    return work


__all__ = ["HS_CHOICES", "BAND_DIMS", "band_variables", "sensitivity_variables", "merge_into"]
