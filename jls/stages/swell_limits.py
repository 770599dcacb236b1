"""The master's table per swell system of a route's partitioned legs (``spectrum:
partitions``), for ``voyage_plan.nc`` (:mod:`jls.assessment.swell_limits`): per leg the
typical wind sea of its records, the swell's mean direction, both met on the leg's course
(a leg of relative headings: both at each of its headings, the governing one taken), and the swell's
OP_LIM, alpha and OP_WF over (candidate, tugger, leg, swell_tp), NaN for a leg whose sea
has no partitions.

The options are those of ``tr`` (:class:`jls.response.sea_state.SeaStateTransfer` of the
route's assessed plant, as ``jls forecast`` builds it); they must be the voyage plan's.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.swell_limits import (
    WIND_BASIS,
    Criteria,
    mean_direction,
    swell_limits,
    typical_wind_sea,
)
from jls.names import TENSION_KEYS, TIP_AIR_GAP_M
from jls.response.sea_state import CRITERION_OF, RESPONSES
from jls.sea.headings import initial_bearing
from jls.sea.records import leg_partitions, leg_spreading, sea_model
from jls.sea.sea_state import parse_spreading

__all__ = ["criteria_of", "partition_legs", "swell_tp_range", "leg_geometry", "swell_table"]


def partition_legs(route: dict) -> list[dict]:
    """The route's legs whose sea model is the partitions."""
    return [leg for leg in route["legs"] if sea_model(leg) == "partitions"]


def _swell_parts(frame):
    return [c[3:] for c in frame.columns if c.startswith("hs_") and c != "hs_wind"]


def swell_tp_range(frame) -> tuple[float, float]:
    """(smallest, largest) Tp [s] of the records' swell partitions (Hs > 0)."""
    tps = []
    for p in _swell_parts(frame):
        hs, tp = frame[f"hs_{p}"].to_numpy(float), frame[f"tp_{p}"].to_numpy(float)
        tps += list(tp[np.isfinite(hs) & (hs > 0) & np.isfinite(tp)])
    return (float(min(tps)), float(max(tps))) if tps else (float("nan"), float("nan"))


def leg_geometry(leg: dict, wind_from: float, swell_from: float) -> list[tuple[float, float, float]]:
    """The cases (course, wind from, swell from) [deg true] the swell table meets the seas
    in: the leg's course (its waypoints' first bearing) with the records' directions; on a
    leg of relative headings, course 0 with both systems met at each heading of the leg
    with probability (from = 180 - heading), the table taking the governing one."""
    if leg.get("course_deg") is not None:
        return [(float(leg["course_deg"]), wind_from, swell_from)]
    if leg.get("waypoints"):
        p = [(float(x["lat"]), float(x["lon"])) if isinstance(x, dict) else tuple(map(float, x))
             for x in leg["waypoints"]]
        return [(float(initial_bearing(p[0][0], p[0][1], p[1][0], p[1][1])), wind_from, swell_from)]
    heads = [float(h) for h, x in zip(leg["headings_deg"], leg["heading_probability"]) if float(x) > 0]
    return [(0.0, float(np.mod(180.0 - h, 360.0)), float(np.mod(180.0 - h, 360.0))) for h in heads]


def criteria_of(cfg: dict, plant: xr.Dataset) -> Criteria:
    """The configured criteria the forecast evaluates on the options' plant (a tip without
    its geometry, wires without theirs: not evaluated, as in ``jls forecast``)."""
    from jls.config.builders import tip_settings_from_config
    from jls.response.wire_loads import has_geometry
    a, v = cfg["assessment"], cfg["vessel"]
    crit = a["criteria"]
    motions = {c: float(crit[c]) for c in (CRITERION_OF[r] for r in RESPONSES)
               if isinstance(crit.get(c), (int, float))}
    tip = tip_settings_from_config(cfg) if crit.get(TIP_AIR_GAP_M) is not None else None
    if tip is not None and any(k not in plant for k in ["drop_height"] + (["padeye"] if tip.tip_offsets_m is None
                                                                          else [])):
        tip = None
    tensions = {k: crit[k] for k in TENSION_KEYS if crit.get(k) is not None} if has_geometry(plant) else {}
    lever = tuple(float(x) for x in np.subtract(v["hinge_m"], v["rao_reference_point_m"])[:2])
    return Criteria(motions, tip, float(crit[TIP_AIR_GAP_M]) if tip is not None else float("nan"), tensions,
                    float(a["exposure_h"]), str(a["mpm_cycles"]), float(cfg["g_m_per_s2"]), lever)


def _relative(course, from_deg):
    return float(np.mod(course - from_deg + 180.0, 360.0)) if np.isfinite(from_deg) else float("nan")


def swell_table(route: dict, names, leg_period_h, cfg: dict, tr, candidates, tuggers, *, gamma: float,
                alpha, periods, base_dir=".") -> xr.Dataset | None:
    """The swell table of the route's partitioned legs (module docstring), or None when
    it has none. ``names``, ``leg_period_h``: every leg's name and its stretch's planned
    period; ``candidates``, ``tuggers``: the voyage plan's options (``tr``'s, checked);
    ``periods``: leg -> (smallest, largest) swell Tp -> the table's swell periods (the
    master's table's rule, :func:`jls.stages.voyage_plan.master_periods`)."""
    legs = partition_legs(route)
    if not legs:
        return None
    if [str(c) for c in tr.candidates] != [str(c) for c in candidates] or \
            [str(t) for t in tr.tuggers] != [str(t) for t in tuggers]:
        raise ValueError("the swell table's options differ from the voyage plan's (the assessed plant "
                         "and operability.nc are of different runs)")
    frames = {leg["name"]: leg_partitions(leg, base_dir, gamma=gamma) for leg in legs}
    ranges = {n: swell_tp_range(f) for n, f in frames.items() if np.isfinite(swell_tp_range(f)[0])}
    tps = periods(ranges)
    crit = criteria_of(cfg, tr.plant)
    nan = float("nan")
    n_l = len(names)
    shape = (len(candidates), len(tuggers), n_l, tps.size)
    out = {v: np.full(shape, nan) for v in ("swell_hs_oplim", "swell_alpha", "swell_hs_opwf")}
    governing = np.full(shape, nan)
    per_leg = {v: np.full(n_l, nan) for v in ("wind_sea_hs", "wind_sea_tp", "wind_sea_heading_deg",
                                              "swell_heading_deg", "swell_tp_min", "swell_tp_max")}
    for leg in legs:
        k = list(names).index(leg["name"])
        frame = frames[leg["name"]]
        wind = typical_wind_sea(frame)
        swell_from = mean_direction(frame, _swell_parts(frame))
        spread = {kind: parse_spreading(v, f"legs[{leg['name']}].spreading.{kind}")
                  for kind, v in leg_spreading(leg, cfg["sea"]).items()}
        best = None
        for course, wind_from, sfrom in leg_geometry(leg, wind.from_deg, swell_from):
            w = type(wind)(wind.hs, wind.tp, wind_from)
            lim = swell_limits(tr, w, tps, sfrom, course, crit, gamma=gamma, spreading=spread,
                               period_h=float(leg_period_h[k]), alpha=alpha)
            heading = np.full(lim["swell_hs_oplim"].shape, _relative(course, sfrom))
            if best is None:
                best = {**{v: lim[v].values for v in out}, "heading": heading}
                continue
            lower = lim["swell_hs_opwf"].values < best["swell_hs_opwf"]        # the governing heading
            for v in out:
                best[v] = np.where(lower, lim[v].values, best[v])
            best["heading"] = np.where(lower, heading, best["heading"])
        for v in out:
            out[v][:, :, k] = best[v]
        governing[:, :, k] = best["heading"]
        per_leg["wind_sea_hs"][k], per_leg["wind_sea_tp"][k] = wind.hs, wind.tp
        one = len(leg_geometry(leg, wind.from_deg, swell_from)) == 1
        per_leg["wind_sea_heading_deg"][k] = (_relative(course, wind_from) if wind.hs > 0 and one else nan)
        per_leg["swell_heading_deg"][k] = _relative(course, sfrom) if one else nan
        per_leg["swell_tp_min"][k], per_leg["swell_tp_max"][k] = ranges.get(leg["name"], (nan, nan))
    dims = ("candidate", "tugger", "leg", "swell_tp")
    ds = xr.Dataset({v: (dims, x) for v, x in out.items()},
                    coords={"candidate": list(candidates), "tugger": list(tuggers), "leg": list(names),
                            "swell_tp": tps})
    ds["swell_heading_governing_deg"] = (dims, governing)
    for v, x in per_leg.items():
        ds[v] = ("leg", x)
    ds.attrs["swell_basis"] = (f"wind sea: {WIND_BASIS}; swell: the energy-weighted mean direction of the records' "
                               "swell partitions; every criterion of the forecast counted (relative motions, tip "
                               "clearance, wire tensions)")
    ds.attrs["swell_criteria"] = ", ".join(crit.names())
    return ds
