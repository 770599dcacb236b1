"""The weather-window dataset a route writes (``results/<route>/weather_windows.nc``).

:func:`jls.assessment.windows.windows_dataset` evaluates every option (candidate,
tugger) and heading. The route's file carries those under names ending in ``_options``
and, for the *assessed option* (the report's recommendation: the best combination by
route workability that no exclusion rule removes, ties broken by the report's rule,
:mod:`jls.assessment.recommendation`), the layout docs/reference/outputs.md states:

========================== ========== ===== ==========================================
``window_probability``     leg, month 1     a workable window of the leg's duration
                                            starts at a random hour of the month
``window_probability_all`` leg        1     the same over the whole record
``workable_fraction``      leg        1     share of recorded hours that are workable
``workable_hourly``        leg, time  flag  1 workable, 0 not, -1 no record, at the
                                            leg's most probable heading
                                            (``workable_hourly_heading``)
========================== ========== ===== ==========================================
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.recommendation import recommend
from jls.assessment.windows import PER_OPTION, windows_dataset
from jls.names import FLAG_MEANINGS


def assessed_option(work: xr.Dataset, plant: xr.Dataset, c_tugger: dict) -> tuple[str, str]:
    """The report's recommendation (:func:`jls.assessment.recommendation.recommend`): the best
    combination by route workability that no exclusion rule removes (an infeasible
    rigging, saturating winches), ties broken by the report's rule."""
    cands = [str(c) for c in work["candidate"].values]
    tugs = [str(t) for t in work["tugger"].values]
    best, _, _ = recommend({"plant": plant, "workability": work}, cands, tugs, c_tugger)
    return best


def operational_alpha(route_legs: list[dict], operation: dict):
    """(the operation's alpha table or None, leg name -> the planned period of its
    stretch [h]) of a route's legs (configuration mappings, in sailing order): the alpha
    the voyage plan's OP_WF is read with (:mod:`jls.stages.voyage_plan`), for the windows."""
    from jls.stages.voyage_plan import alpha_table, leg_periods, route_stretches
    _, _, classes = route_stretches(route_legs, [float(leg["duration_h"]) for leg in route_legs], operation)
    return alpha_table(operation), leg_periods(classes)


def route_windows(legs: list[dict], hindcasts: dict, stats: xr.Dataset, criteria: dict,
                  option: tuple[str, str], **kwargs) -> xr.Dataset:
    """The route's weather windows: every option (``*_options``) and the assessed option
    ``option`` in the layout of the module docstring. ``kwargs``: alpha, gaps, tz_outside,
    alpha_factors, leg_period_h of :func:`jls.assessment.windows.windows_dataset`. Only the legs given by an
    hourly hindcast are evaluated."""
    legs = [leg for leg in legs if leg["name"] in hindcasts]
    full = windows_dataset(legs, hindcasts, stats, criteria, **kwargs)
    ds = full.rename({v: f"{v}_options" for v in PER_OPTION})
    pick = {"candidate": option[0], "tugger": option[1]}
    for v in ("window_probability", "window_probability_all", "workable_fraction"):
        ds[v] = full[v].sel(pick, drop=True)
    top = {leg["name"]: float(np.asarray(leg["headings_deg"], float)[
        int(np.argmax(leg["heading_probability"]))]) for leg in legs}
    heading = xr.DataArray([top[str(n)] for n in full["leg"].values], dims="leg",
                           coords={"leg": full["leg"]})
    ds["workable_hourly"] = full["workable_hourly"].sel(pick, drop=True).sel(
        heading=heading, drop=True).transpose("leg", "time").astype(np.int8)
    ds["workable_hourly_heading"] = heading
    ds["workable_hourly"].attrs.update(flag_values=np.array([-1, 0, 1], np.int8),
                                       flag_meanings=FLAG_MEANINGS)
    ds["workable_hourly_options"].attrs.update(flag_values=np.array([-1, 0, 1], np.int8),
                                               flag_meanings=FLAG_MEANINGS)
    ds.attrs.update(option_candidate=str(option[0]), option_tugger=str(option[1]))
    return ds


__all__ = ["assessed_option", "operational_alpha", "route_windows"]
