"""Workability of a route: which sea states keep every criterion, and how often.

Inputs are the unit-Hs most probable maxima per (candidate, tugger, heading, Tz,
response) and the route's sea states per (leg, Hs, Tz). In a cell, MPM = Hs x MPM(Hs=1);
the cell passes when every criterion's MPM is within its limit. A leg's workability is
the share of passing cells weighted by the joint probability of (heading, Hs, Tz),
``cell_probability`` of the sea states (the product of the Hs-Tz and heading
probabilities for independent legs, from the table for direction-resolved ones); the
route's is the duration-weighted mean of its legs. The limiting Hs per Tz is eq. 2.7,
Hs_lim = X_max / X(Hs = 1), the lowest over criteria and capped by the steepness
ceiling.

Wire-tension criteria (optional; they need the tension statistics of
:mod:`jls.response.tension` in the response dataset: ``tension_mpm`` and ``tension_static``):

* ``max_wire_tension_kN``: every wire's tension stays at or below the safe working load,
  ``T_s,i + Hs MPM_i(Hs = 1) <= SWL``;
* ``min_wire_tension_kN``: every wire's tension stays above a floor (no slack),
  ``T_s,i - Hs MPM_i(Hs = 1) > floor``.

The dynamic tension is Gaussian and symmetric about the static tension, so the MPM of
its rise and of its drop are the same. A tension criterion's cell MPM is the extreme
tension of the worst wire (the highest maximum, or the lowest minimum). Eq. 2.7
generalises to ``Hs_lim = (SWL - T_s) / MPM(Hs = 1)`` and ``(T_s - floor) / MPM(Hs = 1)``,
the lowest over the wires.

Every criterion is reduced to a *unit utilisation* u (per unit Hs): the dynamic demand
over the dynamic allowance, ``MPM / X_max`` for a motion and ``MPM_i / (SWL - T_s,i)``
or ``MPM_i / (T_s,i - floor)`` (the highest over the wires) for a tension. A cell's
utilisation is ``Hs u``, it passes when that is at most 1 (below 1 for the strict
minimum-tension floor), and ``Hs_lim = 1 / u``; so the governing criterion of a cell is
always the one with the lowest limiting Hs at its Tz. A wire whose static tension is
already beyond a limit has u = infinity: it fails at any Hs.

The dynamic tip clearance ``tip_air_gap_m`` (:mod:`jls.assessment.tip_clearance`; it needs
the tip statistics of :mod:`jls.response.tip`): the clearance of the jacket tip above the
wave surface, still-water height minus the MPM of its downward relative motion (with the
crest-height correction the response dataset states), at least the air gap. Its unit
utilisation is 1 / Hs_lim, its cell extreme the lowest clearance over the tip points [m].

The hoist-wire tension criterion ``wire_tension`` (:mod:`jls.assessment.wire_tension`):
no wire's lowest tension at or below a fraction of its static tension (slack always
fails), none's highest above the safe working load times its factors; its limit is the
floor fraction, its cell extreme the lowest tension over the wires as a fraction of the
static tension, and the allowed maximum travels as the coordinate ``tension_ceiling_kN``
of the limits (NaN: no safe working load configured).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment import tip_clearance
from jls.assessment import wire_tension as wt
from jls.errors import InputError
from jls.io import registry
from jls.names import (
    CRITERIA,
    MAX_TENSION_KN,
    MIN_TENSION_KN,
    TENSION_SENSE,
    TIP_AIR_GAP_M,
    WIRE_TENSION_CRITERION,
)
from jls.sea.steepness import steepness_limit_hs


def criteria_array(criteria: dict) -> xr.DataArray:
    """DataArray of limits over a ``criterion`` dimension from the config mapping.

    Coordinates: ``response`` (the response or "wire_tension"), ``unit`` and
    ``strict`` (the cell must stay strictly inside the limit: the tension floors); with
    the criterion ``wire_tension``, ``tension_ceiling_kN`` (its allowed maximum tension,
    NaN for the others and where no safe working load is configured).
    """
    names = [k for k in CRITERIA if criteria.get(k) is not None]
    if not names:
        raise ValueError("at least one criterion is needed")
    hi, lo = criteria.get(MAX_TENSION_KN), criteria.get(MIN_TENSION_KN)
    if hi is not None and lo is not None and not float(lo) < float(hi):
        raise InputError("the minimum wire tension must lie below the maximum (safe working "
                         f"load {float(hi):g} kN)", field="assessment.criteria.min_wire_tension_kN",
                         value=lo)
    values, ceiling = [], []
    for k in names:
        floor, top = (wt.settings(criteria[k]) if k == WIRE_TENSION_CRITERION
                      else (float(criteria[k]), np.nan))
        values.append(floor)
        ceiling.append(top)
    coords = {"criterion": names,
              "response": ("criterion", [CRITERIA[k][0] for k in names]),
              "criterion_units": ("criterion", [CRITERIA[k][1] for k in names]),
              "strict": ("criterion", [k in (MIN_TENSION_KN, WIRE_TENSION_CRITERION) for k in names])}
    if WIRE_TENSION_CRITERION in names:
        coords["tension_ceiling_kN"] = ("criterion", ceiling)
    return xr.DataArray(values, dims="criterion", coords=coords,
                        attrs={"long_name": "criterion limit on the 3-hour MPM",
                               "units_from": "criterion_units"})


def _ceiling(limit: xr.DataArray, name) -> float:
    return float(limit["tension_ceiling_kN"].sel(criterion=name))


def _tension_stats(stats: xr.Dataset, name: str):
    missing = [v for v in ("tension_mpm", "tension_static") if v not in stats]
    if missing:
        raise InputError(f"the criterion {name} needs the wire-tension statistics "
                         f"({', '.join(missing)}) in the response dataset",
                         field=f"assessment.criteria.{name}")
    return stats["tension_mpm"], stats["tension_static"]


def unit_utilisation(stats: xr.Dataset, limit: xr.DataArray) -> xr.DataArray:
    """Utilisation per metre of Hs of every criterion (see module docstring).

    stats: unit-Hs statistics (``mpm`` over ``response``; ``tension_mpm`` over ``wire``
    and ``tension_static`` for tension criteria); limit: :func:`criteria_array`.
    Returns (candidate, tugger, heading, tz, criterion) in 1/m.
    """
    parts = []
    for name in limit["criterion"].values:
        lim = float(limit.sel(criterion=name))
        if name in TENSION_SENSE:
            mpm, static = _tension_stats(stats, name)
            allowance = TENSION_SENSE[name] * (lim - static)
            broken = xr.where(allowance.isnull(), np.nan, np.inf)     # unknown, or beyond at rest
            u = xr.where(allowance > 0, mpm / allowance.where(allowance > 0), broken)
            u = u.max("wire", skipna=False)
        elif name == WIRE_TENSION_CRITERION:
            u = wt.unit_utilisation(stats, lim, _ceiling(limit, name))
        elif name == TIP_AIR_GAP_M:
            u = tip_clearance.unit_utilisation(stats, lim)
        else:
            u = stats["mpm"].sel(response=CRITERIA[name][0], drop=True) / lim
        parts.append(u.expand_dims(criterion=[name]))
    out = xr.concat(parts, dim="criterion", coords="minimal", compat="override")
    out = out.assign_coords({c: limit[c] for c in ("response", "criterion_units", "strict",
                                                   "tension_ceiling_kN") if c in limit.coords})
    return out.transpose("candidate", "tugger", "heading", "tz", "criterion")


def cell_extreme(stats: xr.Dataset, limit: xr.DataArray, hs) -> xr.DataArray:
    """The quantity each criterion limits at wave height ``hs``: the MPM of a motion, the
    highest maximum or the lowest minimum wire tension over the wires [m, degree, kN], the
    lowest tip clearance over the tip points [m], the lowest wire tension as a fraction of
    its static tension (``wire_tension``) [-]."""
    parts = []
    for name in limit["criterion"].values:
        if name in TENSION_SENSE:
            mpm, static = _tension_stats(stats, name)
            if TENSION_SENSE[name] > 0:
                x = (static + hs * mpm).max("wire", skipna=False)
            else:
                x = (static - hs * mpm).min("wire", skipna=False)
        elif name == WIRE_TENSION_CRITERION:
            x = wt.lowest_fraction(stats, hs)
        elif name == TIP_AIR_GAP_M:
            x = tip_clearance.lowest_clearance(stats, hs)
        else:
            x = hs * stats["mpm"].sel(response=CRITERIA[name][0], drop=True)
        parts.append(x.expand_dims(criterion=[name]))
    return xr.concat(parts, dim="criterion", coords="minimal", compat="override")


def cell_passes(utilisation: xr.DataArray) -> xr.DataArray:
    """Every criterion holds: utilisation <= 1 (< 1 where the criterion is strict)."""
    ok = xr.where(utilisation["strict"], utilisation < 1.0, utilisation <= 1.0)
    return ok.all("criterion")


def assessed_hs(sea: xr.Dataset, hs_in_bin="centre") -> xr.DataArray:
    """Hs at which each (leg, hs) bin is assessed: its centre or its upper edge."""
    if hs_in_bin == "centre":
        return sea["hs"].broadcast_like(sea["hs_upper"])
    if hs_in_bin == "upper":
        return sea["hs_upper"]
    raise ValueError(f"hs_in_bin must be 'centre' or 'upper', got {hs_in_bin!r}")


def limiting_hs(unit_util: xr.DataArray, steepness_rule="study", gamma=3.3):
    """Eq. 2.7 per criterion (1 / unit utilisation), the lowest over criteria capped by
    the steepness ceiling, and the ceiling, on the ``tz`` of ``unit_util``."""
    with np.errstate(divide="ignore"):
        per_criterion = 1.0 / unit_util          # u = 0: unlimited; u = inf: 0; NaN stays NaN
    ceiling = xr.DataArray(steepness_limit_hs(unit_util["tz"].values, steepness_rule, gamma=gamma),
                           dims="tz", coords={"tz": unit_util["tz"]})
    return np.minimum(per_criterion.min("criterion"), ceiling), per_criterion, ceiling


def assess(response: xr.Dataset, sea: xr.Dataset, criteria: dict, *, hs_in_bin="centre",
           steepness_rule="study", gamma=3.3, curve: xr.Dataset | None = None) -> xr.Dataset:
    """The workability dataset of docs/reference/outputs.md.

    ``curve``: unit-Hs statistics on a fine Tz grid (``operability.nc``); when given, the
    operability curves are also evaluated there (``*_curve`` variables, dim tz_curve).
    """
    limit = criteria_array(criteria)
    stats = response.sel(tz=sea["tz"])                         # tz of the route's cells
    unit_util = unit_utilisation(stats, limit)
    hs = assessed_hs(sea, hs_in_bin)
    mpm = cell_extreme(stats, limit, hs)                       # (cand, tug, head, tz, crit, leg, hs)
    util = hs * unit_util
    passes = cell_passes(util)
    # the criterion index as int8 (a handful of criteria): an int64 was the third-largest
    # variable of a 10 000-candidate workability.nc, 166 MB before compression
    governing = util.fillna(-np.inf).argmax("criterion").astype(np.int8)
    weight = sea["cell_probability"]                           # (leg, heading, hs, tz)
    work_leg = (weight * passes).sum(("heading", "hs", "tz"))
    work_route = (work_leg * sea["leg_weight"]).sum("leg")
    crit_index = xr.DataArray(np.arange(limit.sizes["criterion"]), dims="criterion",
                              coords={"criterion": limit["criterion"]})
    share = (weight * (~passes) * (governing == crit_index)).sum(("heading", "hs", "tz"))

    hs_lim, hs_lim_c, ceiling = limiting_hs(unit_util, steepness_rule, gamma)

    order = ("candidate", "tugger", "leg", "heading", "hs", "tz")
    ds = xr.Dataset({
        "mpm": mpm.transpose(*order, "criterion"),
        "utilisation": util.transpose(*order, "criterion"),
        "passes": passes.transpose(*order),
        "governing": governing.transpose(*order),
        "workability_leg": work_leg.transpose("candidate", "tugger", "leg"),
        "workability_route": work_route.transpose("candidate", "tugger"),
        "governing_share": share.transpose("candidate", "tugger", "leg", "criterion"),
        "hs_limit": hs_lim.transpose("candidate", "tugger", "heading", "tz"),
        "hs_limit_criterion": hs_lim_c.transpose("candidate", "tugger", "heading", "tz", "criterion"),
        "steepness_limit": ceiling,
        "limit": limit,
    })
    if curve is not None:
        c_lim, c_crit, c_ceil = limiting_hs(unit_utilisation(curve, limit), steepness_rule, gamma)
        ds["hs_limit_curve"] = c_lim.transpose("candidate", "tugger", "heading", "tz").rename(tz="tz_curve")
        ds["hs_limit_curve_criterion"] = c_crit.transpose(
            "candidate", "tugger", "heading", "tz", "criterion").rename(tz="tz_curve")
        ds["steepness_limit_curve"] = c_ceil.rename(tz="tz_curve")
    registry.annotate(ds, "workability")
    ds["governing"].attrs["flag_meanings"] = " ".join(limit["criterion"].values)
    tip = TIP_AIR_GAP_M in limit["criterion"].values.tolist()
    ds.attrs.update(hs_in_bin=hs_in_bin, steepness_rule=steepness_rule,
                    tip_crest=response.attrs.get("tip_crest", "not stated") if tip else
                    "not assessed (no tip-clearance criterion)")
    return ds
