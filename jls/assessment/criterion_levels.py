"""Each criterion on its own level: the unit-Hs statistics (sigma, response
zero-crossing period, MPM) the voyage extremes and the route simulation need, in the
criterion's level units, and the limit on that level (:func:`criterion_statistics`): a
relative motion as itself, a wire tension as the governing wire's dynamic utilisation, the
tip clearance as the governing tip point's utilisation.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment import wire_tension as wt
from jls.assessment.tip_clearance import criterion_statistics as tip_statistics
from jls.errors import InputError
from jls.names import TENSION_SENSE, TIP_AIR_GAP_M, WIRE_TENSION_CRITERION


def criterion_statistics(stats: xr.Dataset, limit: xr.DataArray) -> xr.Dataset:
    """Per criterion, the unit-Hs statistics the voyage extremes need, in level units.

    stats: ``response.nc`` or ``operability.nc`` (``sigma``, ``tz_response``, ``mpm`` over
    ``response``; for tension criteria ``tension_sigma``, ``tension_tz_response``,
    ``tension_mpm`` over ``wire`` and ``tension_static``); limit: the criteria with their
    coordinates ``response`` and ``criterion_units``
    (:func:`jls.assessment.workability.criteria_array`).

    Returns ``sigma`` [level units per m Hs], ``tz_response`` [s] and ``mpm`` (the
    exposure's MPM, level units per m Hs) over (candidate, tugger, criterion, heading,
    tz), and ``limit`` (criterion) on the level, with coordinate ``level_units``:

    * a relative motion: the motion itself (zero mean), its configured limit, m or degree;
    * a wire tension: the limit is on static plus dynamic tension, and the static part is
      fixed, so the extremes are those of the dynamic tension against each wire's dynamic
      allowance A = SWL - T_s (or T_s - floor). The level is the dynamic utilisation of
      the governing wire (limit 1, units "1"): in each (heading, Tz) the wire with the
      highest MPM / A, whose sigma / A and tension zero-crossing period are taken. Its
      up-crossings stand for the rig's: the other wires' are not added (the fore and aft
      wire of a side move together; counting every wire would bound the rate from above
      by at most the number of wires). A wire beyond the limit at rest has sigma = inf:
      the limit is exceeded in any sea;
    * the wire-tension criterion ``wire_tension``: the same, with each wire's allowance the
      smaller of the drop to its floor and the rise to the allowed maximum
      (:func:`jls.assessment.wire_tension.criterion_statistics`);
    * the tip clearance: the utilisation of the governing tip point, limit 1
      (:func:`jls.assessment.tip_clearance.criterion_statistics`).
    """
    parts, units, limits = [], [], []
    for name in limit["criterion"].values.tolist():
        lim = float(limit.sel(criterion=name))
        if name in TENSION_SENSE:
            missing = [v for v in ("tension_sigma", "tension_tz_response", "tension_mpm",
                                   "tension_static") if v not in stats]
            if missing:
                raise InputError(f"the voyage extreme of {name} needs the wire-tension statistics "
                                 f"({', '.join(missing)})", field=f"assessment.criteria.{name}")
            allowance = TENSION_SENSE[name] * (lim - stats["tension_static"])
            a = allowance.where(allowance > 0)
            util = (stats["tension_mpm"] / a).fillna(-np.inf)
            gov = {"wire": util.argmax("wire")}                 # the governing wire per cell
            taut = (allowance > 0).all("wire")
            part = xr.Dataset({
                "sigma": xr.where(taut, (stats["tension_sigma"] / a).isel(gov), np.inf),
                "tz_response": stats["tension_tz_response"].isel(gov),
                "mpm": xr.where(taut, (stats["tension_mpm"] / a).isel(gov), np.inf),
            }).where(allowance.notnull().all("wire"))
        elif name == WIRE_TENSION_CRITERION:
            ceiling = (float(limit["tension_ceiling_kN"].sel(criterion=name))
                       if "tension_ceiling_kN" in limit.coords else np.nan)
            part = wt.criterion_statistics(stats, lim, ceiling)
        elif name == TIP_AIR_GAP_M:
            part = tip_statistics(stats, lim)          # utilisation of the governing tip point
        if name in TENSION_SENSE or name in (TIP_AIR_GAP_M, WIRE_TENSION_CRITERION):
            units.append("1")
            limits.append(1.0)
        else:
            resp = str(limit["response"].sel(criterion=name).values)
            part = stats[["sigma", "tz_response", "mpm"]].sel(response=resp, drop=True)
            units.append(str(limit["criterion_units"].sel(criterion=name).values))
            limits.append(lim)
        part = part.drop_vars([c for c in part.coords if c not in part.dims], errors="ignore")
        parts.append(part.expand_dims(criterion=[name]))
    out = xr.concat(parts, dim="criterion", coords="minimal", compat="override", join="exact")
    out = out.transpose("candidate", "tugger", "criterion", "heading", "tz")
    out["limit"] = ("criterion", limits)
    return out.assign_coords(level_units=("criterion", units))
