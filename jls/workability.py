"""Workability of a route: which sea states keep every criterion, and how often.

Inputs are the unit-Hs most probable maxima per (candidate, tugger, heading, Tz,
response) and the route's sea states per (leg, Hs, Tz). In a cell, MPM = Hs x MPM(Hs=1);
the cell passes when every criterion's MPM is within its limit. A leg's workability is
the probability-weighted share of passing cells (over headings too); the route's is the
duration-weighted mean of its legs. The limiting Hs per Tz is eq. 2.7,
Hs_lim = X_max / X(Hs = 1), the lowest over criteria and capped by the steepness
ceiling.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.sea.steepness import steepness_limit_hs

CRITERIA = {  # config key -> (response, unit)
    "relative_sway_m": ("relative_sway", "m"),
    "relative_heave_m": ("relative_heave", "m"),
    "relative_roll_deg": ("relative_roll", "degree"),
    "relative_yaw_deg": ("relative_yaw", "degree"),
}


def criteria_array(criteria: dict) -> xr.DataArray:
    """DataArray of limits over a ``criterion`` dimension from the config mapping."""
    names = [k for k in CRITERIA if criteria.get(k) is not None]
    if not names:
        raise ValueError("at least one criterion is needed")
    return xr.DataArray([float(criteria[k]) for k in names], dims="criterion",
                        coords={"criterion": names,
                                "response": ("criterion", [CRITERIA[k][0] for k in names])},
                        attrs={"long_name": "criterion limit on the 3-hour MPM",
                               "units": "m or degree (per criterion name)"})


def assessed_hs(sea: xr.Dataset, hs_in_bin="centre") -> xr.DataArray:
    """Hs at which each (leg, hs) bin is assessed: its centre or its upper edge."""
    if hs_in_bin == "centre":
        return sea["hs"].broadcast_like(sea["hs_upper"])
    if hs_in_bin == "upper":
        return sea["hs_upper"]
    raise ValueError(f"hs_in_bin must be 'centre' or 'upper', got {hs_in_bin!r}")


def limiting_hs(unit_mpm: xr.DataArray, limit: xr.DataArray, steepness_rule="study", gamma=3.3):
    """Eq. 2.7 per criterion, the lowest over criteria capped by the steepness ceiling,
    and the ceiling, on the ``tz`` of ``unit_mpm``."""
    per_criterion = limit / unit_mpm
    ceiling = xr.DataArray(steepness_limit_hs(unit_mpm["tz"].values, steepness_rule, gamma=gamma),
                           dims="tz", coords={"tz": unit_mpm["tz"]})
    return np.minimum(per_criterion.min("criterion"), ceiling), per_criterion, ceiling


def assess(response: xr.Dataset, sea: xr.Dataset, criteria: dict, *, hs_in_bin="centre",
           steepness_rule="study", gamma=3.3, curve: xr.Dataset | None = None) -> xr.Dataset:
    """The workability dataset of the README (section Outputs).

    ``curve``: unit-Hs statistics on a fine Tz grid (``operability.nc``); when given, the
    operability curves are also evaluated there (``*_curve`` variables, dim tz_curve).
    """
    limit = criteria_array(criteria)
    unit_mpm = response["mpm"].sel(response=limit["response"]).drop_vars("response")
    unit_mpm = unit_mpm.sel(tz=sea["tz"])                      # tz of the route's cells
    hs = assessed_hs(sea, hs_in_bin)
    mpm = hs * unit_mpm                                        # (cand, tug, head, tz, crit, leg, hs)
    util = mpm / limit
    passes = (util <= 1.0).all("criterion")
    governing = util.fillna(-np.inf).argmax("criterion")
    weight = sea["probability"] * sea["heading_probability"]   # (leg, hs, tz, heading)
    work_leg = (weight * passes).sum(("heading", "hs", "tz"))
    work_route = (work_leg * sea["leg_weight"]).sum("leg")
    crit_index = xr.DataArray(np.arange(limit.sizes["criterion"]), dims="criterion",
                              coords={"criterion": limit["criterion"]})
    share = (weight * (~passes) * (governing == crit_index)).sum(("heading", "hs", "tz"))

    hs_lim, hs_lim_c, ceiling = limiting_hs(unit_mpm, limit, steepness_rule, gamma)

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
    units = {"mpm": ("most probable maximum in the cell", "m or degree (per criterion)"),
             "utilisation": ("MPM over the criterion limit", "1"),
             "passes": ("every criterion holds in the cell", "1"),
             "governing": ("criterion with the highest utilisation (index)", "1"),
             "workability_leg": ("probability-weighted workable fraction of the leg", "1"),
             "workability_route": ("duration-weighted workable fraction of the route", "1"),
             "governing_share": ("probability of failing cells governed by the criterion", "1"),
             "hs_limit": ("limiting significant wave height, capped by steepness", "m"),
             "hs_limit_criterion": ("limiting significant wave height of the criterion", "m"),
             "steepness_limit": (f"wave steepness ceiling ({steepness_rule} rule)", "m")}
    for name, (long_name, unit) in units.items():
        ds[name].attrs.update(long_name=long_name, units=unit)
    if curve is not None:
        fine = curve["mpm"].sel(response=limit["response"]).drop_vars("response")
        c_lim, c_crit, c_ceil = limiting_hs(fine, limit, steepness_rule, gamma)
        ds["hs_limit_curve"] = c_lim.transpose("candidate", "tugger", "heading", "tz").rename(tz="tz_curve")
        ds["hs_limit_curve_criterion"] = c_crit.transpose(
            "candidate", "tugger", "heading", "tz", "criterion").rename(tz="tz_curve")
        ds["steepness_limit_curve"] = c_ceil.rename(tz="tz_curve")
        for name, src in (("hs_limit_curve", "hs_limit"), ("hs_limit_curve_criterion", "hs_limit_criterion"),
                          ("steepness_limit_curve", "steepness_limit")):
            ds[name].attrs.update(ds[src].attrs, long_name=ds[src].attrs["long_name"] + ", fine Tz grid")
        ds["tz_curve"].attrs.update(long_name="zero-up-crossing period of the operability curve", units="s")
    ds["governing"].attrs["flag_meanings"] = " ".join(limit["criterion"].values)
    ds.attrs.update(hs_in_bin=hs_in_bin, steepness_rule=steepness_rule)
    return ds
