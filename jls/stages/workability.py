"""The workability dataset (``workability.nc``): MPM and pass/fail per cell, workability
per leg and route, limiting Hs per Tz, winch-saturation flags and the time-domain verdicts
where cells ran, uncertainty bands over the plant variants and Hs choices, and the route
workability against the sway limit (layout ``workability`` of the registry).

The physics is :mod:`jls.assessment` (workability, winch limits, bands, criterion sweep);
this builder puts it together in the one order the dataset is defined by.
"""

from __future__ import annotations

import xarray as xr

from jls.assessment import wire_tension as wt
from jls.assessment.bands import band_variables, merge_into, sensitivity_variables
from jls.assessment.measured_legs import apply_measured_legs
from jls.assessment.operation import forecast_limits
from jls.assessment.winch_limits import apply_timedomain, apply_winch_limits
from jls.assessment.workability import assess, assessed_hs
from jls.config.builders import operation_basis, recommendation_rules, tuggers_from_config
from jls.io import registry
from jls.names import WIRE_TENSION_CRITERION
from jls.plant import same_rigging


def workability(sea: xr.Dataset, response: xr.Dataset, curve: xr.Dataset,
                variants: xr.Dataset, cells: list[xr.Dataset], cfg: dict, route: str,
                voyage: xr.Dataset, measured: xr.Dataset | None = None,
                plant: xr.Dataset | None = None, plan: xr.Dataset | None = None) -> xr.Dataset:
    """``cfg``: the configuration's ``assessment``, ``sea``, ``tuggers``, ``operation``,
    ``recommendation`` and ``weather_windows`` sections (a validated configuration or the
    part of it the workflow passes). ``measured``: ``measured_response.nc`` of a route
    with legs given by spectra, whose workability is then judged hour by hour
    (:mod:`jls.assessment.measured_legs`; ``weather_windows.tz_outside`` says what an
    hour beyond the Tz grid of ``curve`` does). ``plan``: ``voyage_plan.nc``, whose
    departure rule's exceedance probability and waits rank the options under the
    objective ``voyage_plan``. The recommendation's rules travel with the dataset (attributes
    ``tugger_min_gain`` and ``tie_tolerance``, fractions of the route), so every stage
    that names the recommendation applies the same ones. ``plant``: the assessed plant
    (geometric); when given, candidates of the same rigging within
    ``recommendation.same_rigging_tolerance_m`` are one option (:mod:`jls.plant.same_rigging`)."""
    a, s = cfg["assessment"], cfg["sea"]
    tuggers = tuggers_from_config({"tuggers": cfg["tuggers"]})
    own = [str(v) for v in measured["leg"].values] if measured is not None else []
    ds = nominal(sea, response, curve, cells, cfg, tuggers, own_sea_legs=own)
    amplification(ds, response, sea, a["criteria"], s["hs_in_bin"])
    bands = band_variables(variants, sea, a["criteria"], ds, steepness_rule=s["steepness_rule"],
                           gamma=s["gamma"], tuggers=tuggers, winch_saturation=a["winch_saturation"])
    sens = sensitivity_variables(response, sea, a["criteria"], hs_in_bin=s["hs_in_bin"])
    basis, alpha = operation_basis(cfg["operation"], float(sea["duration_h"].sum()))
    ds = merge_into(ds, bands, sens)
    if measured is not None:
        ds = apply_measured_legs(ds, sea, curve, measured, a["criteria"],
                                 tz_outside=cfg["weather_windows"]["tz_outside"])
    ds["voyage_inside_probability"] = (1.0 - voyage["exceedance_probability_any"]).clip(0.0, 1.0).sel(
        candidate=ds["candidate"], tugger=ds["tugger"])
    if plan is not None and "plan_exceedance_probability" in plan:
        sel = {"candidate": ds["candidate"], "tugger": ds["tugger"]}
        # an option whose voyage never sails (no sailed voyage to judge) ranks last
        ds["plan_inside_probability"] = (1.0 - plan["plan_exceedance_probability"]).fillna(0.0).sel(sel)
        ds["plan_wait_median_h"] = plan["plan_wait_h"].sel(quantile=0.5, drop=True).sel(sel)
        ds["plan_wait_p90_h"] = plan["plan_wait_h"].sel(quantile=0.9, drop=True).sel(sel)
    limits = forecast_limits(ds["hs_limit"], basis, alpha)
    for name in ("alpha_factor", "hs_opwf"):
        if name in limits:
            ds[name] = limits[name]
    if plant is not None:
        ds = same_rigging.merge(ds, plant, float(cfg["recommendation"]["same_rigging_tolerance_m"]))
    ds = registry.annotate(ds, "workability")
    return described(ds, response, cfg, route, basis, alpha)


def nominal(sea: xr.Dataset, response: xr.Dataset, curve: xr.Dataset, cells: list[xr.Dataset],
            cfg: dict, tuggers: dict, own_sea_legs=()) -> xr.Dataset:
    """The nominal plant's part of the dataset, which the rest is added to: the criteria
    per cell, leg and route, the winch limits of the tugger settings (``tuggers``: name ->
    :class:`jls.tugger.setting.Tugger`) and the time-domain verdicts of ``cells`` (a leg of
    ``own_sea_legs``, whose sea is its own, takes only the verdicts of its own cells)."""
    a, s = cfg["assessment"], cfg["sea"]
    ds = assess(response, sea, a["criteria"], hs_in_bin=s["hs_in_bin"],
                steepness_rule=s["steepness_rule"], gamma=s["gamma"], curve=curve)
    hs = assessed_hs(sea, s["hs_in_bin"])
    ds = apply_winch_limits(ds, response, sea, tuggers, hs, a["winch_saturation"])
    static = response["tension_static"] if "tension_static" in response else None
    return apply_timedomain(ds, sea, cells, hs, static, own_sea_legs)


def amplification(ds: xr.Dataset, response: xr.Dataset, sea: xr.Dataset, criteria: dict,
                  hs_in_bin: str) -> xr.Dataset:
    """With the criterion ``wire_tension``: each option's dynamic amplification factor over
    its workable sea states (``dynamic_amplification``), and the DAF limit, the floor and
    their sources as attributes (in place)."""
    conf = criteria.get(WIRE_TENSION_CRITERION)
    if conf is None:
        return ds
    ds["dynamic_amplification"] = wt.amplification(response, ds, sea, assessed_hs(sea, hs_in_bin))
    ds.attrs.update(daf_limit=float(conf["daf_limit"]), daf_source=str(conf["daf_source"]),
                    tension_floor_source=str(conf["floor_source"]))
    return ds


def described(ds: xr.Dataset, response: xr.Dataset, cfg: dict, route: str, basis, alpha) -> xr.Dataset:
    """The dataset's global attributes (in place): the route, the exposure, the
    recommendation's rules and the operational basis (``basis``, ``alpha``:
    :func:`jls.config.builders.operation_basis`)."""
    ds.attrs.update(route=route, exposure_h=response.attrs["exposure_h"], mpm_cycles=response.attrs["mpm_cycles"],
                    max_saturation_fraction=cfg["assessment"]["max_saturation_fraction"],
                    **recommendation_rules(cfg["recommendation"]),
                    operation_class=basis.operation_class, operation_reason=basis.reason,
                    planned_period_h=basis.planned_h, reference_period_h=basis.reference_h)
    if basis.contingency_h is not None:
        ds.attrs["contingency_h"] = basis.contingency_h
    if alpha is not None:
        ds.attrs["alpha_source"] = alpha.source
    return ds
