"""The hoist-wire tension criterion ``wire_tension`` of ``assessment.criteria``.

A slack hoist wire in a suspended lift is a failure, not a statistic, and a wire loaded
beyond its safe working load is one too. A cell fails where any hoist wire's

* lowest dynamic tension falls to or below a floor, a fraction f of its static tension
  (``floor_fraction_of_static``; the slack-sling criterion of the lifting analyses,
  dynamic load at most 0.9 of the static sling load, gives f = 0.1; f = 0 still fails a
  slack wire, T <= 0), or
* highest dynamic tension exceeds the safe working load times its factors,
  ``C = SWL prod(swl_factors)`` (only where ``safe_working_load_kN`` is configured).

Frequency domain: the dynamic tension is Gaussian and symmetric about the static tension
T_s,i (:mod:`jls.response.tension`), so the lowest is ``T_s,i - Hs MPM_i(Hs = 1)`` and the
highest ``T_s,i + Hs MPM_i(Hs = 1)``, with the exposure's MPM. Each wire's dynamic
allowance is the smaller of ``T_s,i (1 - f)`` and ``C - T_s,i``; the unit utilisation is
the largest over the wires of ``MPM_i / allowance_i`` (infinite where the allowance is
not positive: the wire fails at rest), the cell passes when ``Hs u < 1`` (strict: a
wire at the floor has gone as low as allowed) and the limiting Hs is 1 / u. The
criterion's cell value (``mpm`` of ``workability.nc``) is the lowest tension over the
wires as a fraction of its static tension, ``min_i (T_s,i - Hs MPM_i) / T_s,i``; its
``limit`` the floor fraction f.

Time domain: the recorded extremes of the cell's record decide (:func:`timedomain_passes`):
the lowest hoist-wire tension above the highest floor of the wires, no slack event, the
highest at most C.

The dynamic amplification factor (DAF, the highest tension over the static tension of
the same wire) of each option is reported against ``daf_limit`` (DNV-ST-N001, lifting:
the design DAF of the rigging, 1.10 offshore for a static hook load above 2 500 t); it
informs, the criterion above decides.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import WIRE_TENSION_CRITERION

FIELD = f"assessment.criteria.{WIRE_TENSION_CRITERION}"


def settings(value) -> tuple[float, float]:
    """(floor fraction f, allowed maximum C [kN], NaN when no SWL is configured) from the
    criterion's configuration: its mapping, or a bare number (the floor fraction; a
    criterion sweep's trial limit)."""
    if isinstance(value, dict):
        f = value.get("floor_fraction_of_static")
        if f is None:
            raise InputError("the wire-tension criterion needs its floor fraction",
                             field=f"{FIELD}.floor_fraction_of_static")
        swl = value.get("safe_working_load_kN")
        factors = value.get("swl_factors") or {}
        ceiling = (float(swl) * math.prod(float(v) for v in factors.values())
                   if swl is not None else np.nan)
    else:
        f, ceiling = value, np.nan
    f = float(f)
    if not 0.0 <= f < 1.0:
        raise InputError("the floor of the wire tension is a fraction of the static tension, "
                         "in [0, 1)", field=f"{FIELD}.floor_fraction_of_static", value=f)
    return f, ceiling


def _stats(stats: xr.Dataset):
    missing = [v for v in ("tension_mpm", "tension_static") if v not in stats]
    if missing:
        raise InputError(f"the criterion {WIRE_TENSION_CRITERION} needs the wire-tension "
                         f"statistics ({', '.join(missing)}) in the response dataset", field=FIELD)
    return stats["tension_mpm"], stats["tension_static"]


def allowance(static: xr.DataArray, floor: float, ceiling: float) -> xr.DataArray:
    """Dynamic allowance of each wire [kN]: min(T_s (1 - f), C - T_s); not positive: the
    wire fails at rest (slack, or above C)."""
    low = static * (1.0 - floor)
    return low if not np.isfinite(ceiling) else np.minimum(low, ceiling - static)


def unit_utilisation(stats: xr.Dataset, floor: float, ceiling: float) -> xr.DataArray:
    """Utilisation per metre of Hs, the largest over the wires of MPM_i / allowance_i [1/m];
    infinite where a wire fails at rest, NaN where its statistics are unknown."""
    mpm, static = _stats(stats)
    a = allowance(static, floor, ceiling)
    broken = xr.where(a.isnull(), np.nan, np.inf)
    u = xr.where(a > 0, mpm / a.where(a > 0), broken)
    return u.max("wire", skipna=False)


def lowest_fraction(stats: xr.Dataset, hs) -> xr.DataArray:
    """The cell value: the lowest tension over the wires as a fraction of its static
    tension, min_i (T_s,i - Hs MPM_i) / T_s,i [-] (negative: the linear model lets the
    wire go slack)."""
    mpm, static = _stats(stats)
    return ((static - hs * mpm) / static).min("wire", skipna=False)


def criterion_statistics(stats: xr.Dataset, floor: float, ceiling: float) -> xr.Dataset:
    """The voyage level of the criterion: the dynamic utilisation of the governing wire
    (the one with the highest MPM / allowance per (heading, Tz)), its sigma / allowance,
    its tension zero-crossing period and MPM / allowance, per m of Hs; limit 1. A wire
    failing at rest has sigma = inf (exceeded in any sea)."""
    missing = [v for v in ("tension_sigma", "tension_tz_response", "tension_mpm", "tension_static")
               if v not in stats]
    if missing:
        raise InputError(f"the voyage extreme of {WIRE_TENSION_CRITERION} needs the wire-tension "
                         f"statistics ({', '.join(missing)})", field=FIELD)
    a_all = allowance(stats["tension_static"], floor, ceiling)
    a = a_all.where(a_all > 0)
    util = (stats["tension_mpm"] / a).fillna(-np.inf)
    gov = {"wire": util.argmax("wire")}
    taut = (a_all > 0).all("wire")
    return xr.Dataset({
        "sigma": xr.where(taut, (stats["tension_sigma"] / a).isel(gov), np.inf),
        "tz_response": stats["tension_tz_response"].isel(gov),
        "mpm": xr.where(taut, (stats["tension_mpm"] / a).isel(gov), np.inf),
    }).where(a_all.notnull().all("wire"))


def timedomain_passes(td: xr.Dataset, static, floor: float, ceiling: float) -> xr.DataArray:
    """Pass flag per tugger of a time-domain cell on the wire tensions: the recorded lowest
    hoist-wire tension above the highest floor of the wires (``f max_i T_s,i``: the record
    keeps the lowest over the wires, not which wire), no slack event, and the recorded
    highest at most C. static: the candidate's static tensions (wire) [kN]."""
    for v in ("wire_tension_min", "wire_tension_max", "slack_events"):
        if v not in td:
            raise InputError(f"the time-domain cell has no {v}: the wire-tension criterion cannot "
                             "judge it; rerun the cell", file=td.attrs.get("cell"), field=v)
    top_floor = floor * float(np.nanmax(np.asarray(static, float)))
    ok = (td["wire_tension_min"] > max(top_floor, 0.0)) & (td["slack_events"] == 0)
    if np.isfinite(ceiling):
        ok = ok & (td["wire_tension_max"] <= ceiling)
    return ok


def amplification(response: xr.Dataset, work: xr.Dataset, sea: xr.Dataset, hs) -> xr.DataArray:
    """Dynamic amplification factor of every (candidate, tugger): the largest over the
    route's workable cells (probability above zero) and the wires of
    (T_s,i + Hs MPM_i) / T_s,i [-]; NaN where no cell is workable."""
    mpm, static = _stats(response.sel(candidate=work["candidate"], tugger=work["tugger"],
                                      tz=work["tz"]))
    daf = ((static + hs * mpm) / static).max("wire", skipna=False)
    ok = work["passes"] & (sea["cell_probability"] > 0)
    return daf.where(ok).max(("leg", "heading", "hs", "tz")).transpose("candidate", "tugger")


__all__ = ["FIELD", "settings", "allowance", "unit_utilisation", "lowest_fraction",
           "criterion_statistics", "timedomain_passes", "amplification"]
