"""Go or no-go on a forecast for one leg of a route: every forecast hour's sea state (its
wave systems, :mod:`jls.sea.forecast`) met at the vessel's heading, the criteria of every
option evaluated hour by hour (the relative motions by
:func:`jls.response.sea_state.sea_state_statistics`, the function of ``jls response``; the
tip clearance and the wire tensions by
:func:`jls.response.sea_state_tip_tension.tip_tension_moments` from the same directional
sea, their utilisations as the workability's, :mod:`jls.assessment.sea_state_criteria`),
alpha applied per lead time and Hs
(:mod:`jls.assessment.go_no_go`), and the first start from which the whole leg, its
contingency included, stays inside the forecast limits.

The answer is a dataset (dims ``time``, ``candidate``, ``tugger``, ``criterion``,
``system``) and :func:`answer` turns it into the JSON object of ``jls forecast``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.go_no_go import LeadTimeAlpha, alpha_factors, decide, window_hours
from jls.assessment.sea_state_criteria import STRICT
from jls.errors import InputError
from jls.names import CRITERIA, TENSION_KEYS, TIP_AIR_GAP_M, WIRE_TENSION_CRITERION
from jls.response.tip import still_water_height
from jls.sea.forecast import Forecast, forecast_systems
from jls.sea.headings import initial_bearing
from jls.sea.sea_state import SeaState
from jls.threads import single_threaded_blas, thread_map

#: the relative motions and the tip clearance and wire tensions are evaluated side by side
#: on this many threads (the bridge's machine: 2 cores)
PARALLEL = 2

__all__ = ["LegPlan", "leg_plan", "hourly_course", "evaluate", "answer"]


@dataclass(frozen=True)
class LegPlan:
    """The leg as planned: ``route``, ``leg``, ``duration_h``, ``contingency_h`` and where
    that contingency comes from, the course [deg true] or the waypoints (lat, lon)."""

    route: str
    leg: str
    duration_h: float
    contingency_h: float
    contingency_source: str
    course_deg: float | None
    waypoints: tuple | None
    assumed_heading_deg: float | None = None


def leg_plan(cfg: dict, route: str, leg: str, course_deg=None, waypoints=None) -> LegPlan:
    """The :class:`LegPlan` of ``route``/``leg`` of a validated configuration: the leg's
    ``contingency_h`` where it gives one, else ``operation.contingency_h``, else none
    (stated). The course: ``course_deg`` given, else the leg's ``course_deg`` or
    ``waypoints``; a leg without any (a leg of relative headings, as the shipped route's
    beam seas) is sailed as the route assumes it: each hour's largest wave system met at
    the leg's heading of largest probability (``assumed_heading_deg``; the answer says so)."""
    routes = cfg["routes"]
    if route not in routes:
        raise InputError(f"no such route (routes: {', '.join(routes)})", field="--route", value=route)
    legs = {str(x["name"]): x for x in routes[route]["legs"]}
    if leg not in legs:
        raise InputError(f"no such leg of route {route} (legs: {', '.join(legs)})", field="--leg", value=leg)
    x = legs[leg]
    if x.get("contingency_h") is not None:
        cont, src = float(x["contingency_h"]), f"routes.{route}.legs[{leg}].contingency_h"
    elif cfg["operation"].get("contingency_h") is not None:
        cont, src = float(cfg["operation"]["contingency_h"]), "operation.contingency_h"
    else:
        cont, src = 0.0, "none stated (operation.contingency_h absent): the leg's planned duration alone"
    if course_deg is None and waypoints is None:
        course_deg, waypoints = x.get("course_deg"), x.get("waypoints")
        if waypoints is not None:
            waypoints = [(float(p["lat"]), float(p["lon"])) if isinstance(p, dict) else tuple(map(float, p))
                         for p in waypoints]
    assumed = None
    if course_deg is None and not waypoints:
        heads = [float(h) for h in x["headings_deg"]]
        prob = [float(p) for p in x["heading_probability"]]
        assumed = heads[int(np.argmax(prob))]
    return LegPlan(route, leg, float(x["duration_h"]), cont, src,
                   None if course_deg is None else float(course_deg),
                   None if not waypoints else tuple(tuple(p) for p in waypoints), assumed)


def hourly_course(plan: LegPlan, hours: int) -> np.ndarray:
    """The vessel's heading [deg true] in each of the leg's ``hours`` hours: the course, or
    along the waypoints at a constant speed, each segment on its great-circle initial
    bearing for its share of the track's length."""
    if plan.waypoints is None:
        return np.full(hours, np.nan if plan.course_deg is None else plan.course_deg)
    from jls.sea.headings import great_circle_distance
    p = np.asarray(plan.waypoints, float)
    if p.shape[0] < 2:
        raise InputError("waypoints need at least two points", field="--waypoints", value=p.tolist())
    d = great_circle_distance(p[:-1, 0], p[:-1, 1], p[1:, 0], p[1:, 1])
    if not np.all(d > 0):
        raise InputError("two consecutive waypoints coincide", field="--waypoints", value=p.tolist())
    bearing = initial_bearing(p[:-1, 0], p[:-1, 1], p[1:, 0], p[1:, 1])
    along = (np.arange(hours) + 0.5) / max(hours, 1) * d.sum()
    seg = np.minimum(np.searchsorted(np.cumsum(d), along, side="right"), d.size - 1)
    return bearing[seg]


def evaluate(fc: Forecast, plan: LegPlan, tr, cfg: dict, start: pd.Timestamp, issued: pd.Timestamp,
             alpha: LeadTimeAlpha | None, *, threads=None) -> xr.Dataset:
    """Utilisation per forecast hour from ``start`` on, option and criterion, and each
    option's decision. ``tr``: the :class:`jls.response.sea_state.SeaStateTransfer` of the
    options; ``cfg``: the validated configuration (its ``assessment`` and ``sea``)."""
    from jls.response.sea_state import CRITERION_OF, HEADING_STATES, heading_products, sea_state_statistics

    times = fc.times
    if start < times[0] or start > times[-1]:
        raise InputError(f"the start lies outside the forecast ({times[0].isoformat()} to "
                         f"{times[-1].isoformat()})", file=fc.file, field="--start", value=start.isoformat())
    if issued > start:
        raise InputError("the forecast was issued after the start asked for", file=fc.file, field="--issued",
                         value=issued.isoformat())
    i0 = int(times.get_loc(start))
    need = window_hours(plan.duration_h, plan.contingency_h)
    sel = np.arange(len(times))
    leg_course = hourly_course(plan, need)
    # the course of each hour as a start at ``start`` sails it (constant on a course; along
    # waypoints, later starts are judged with the same hourly courses)
    course = leg_course[np.clip(sel - i0, 0, need - 1)]
    if plan.assumed_heading_deg is not None:
        # no course: each hour's largest system met at the leg's assumed relative heading,
        # beta = (course - from + 180) mod 360
        dominant = np.argmax(np.where(fc.hs > 0, fc.hs, -1.0), axis=1)
        from_deg = fc.dir_from[np.arange(len(times)), dominant]
        course = np.mod(plan.assumed_heading_deg + np.nan_to_num(from_deg) - 180.0, 360.0)
    a = cfg["assessment"]
    gamma = {"wind": float(cfg["sea"]["gamma"]), "swell": float(cfg["sea"]["gamma"])}
    spread = cfg["sea"]["spreading"]
    states = [SeaState(tuple(forecast_systems(fc, int(i), gamma=gamma, spreading=spread)))
              if fc.hs[i].max() > 0 else None for i in sel]
    calm = [s is None for s in states]
    live = [k for k, s in enumerate(states) if s is not None]
    configured = {k for k, v in a["criteria"].items() if v is not None}
    limits = {k: float(v) for k, v in a["criteria"].items() if isinstance(v, (int, float))}
    live_states = [states[k] for k in live]
    # the spectra met at the RAO headings, formed once for the motions and the tip and wires
    products = (heading_products(tr, live_states, course[live])
                if len(live) * HEADING_STATES >= tr.exc.headings.size else None)

    def motions_of():
        return sea_state_statistics(tr, live_states, course[live], exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                                    threads=threads, source=fc.file, products=products) if live else None

    def others():
        return _tip_tension(tr, cfg, live_states, course[live], configured, threads, products)

    # the relative motions and the tip and tensions side by side (independent; the same
    # numbers on one thread or two: BLAS on one thread throughout, each solve on its own)
    with single_threaded_blas():
        ds, extra = thread_map(lambda f: f(), [motions_of, others], PARALLEL)
    motions = [c for c in (ds["criterion"].values.tolist() if ds is not None else
                           list(CRITERION_OF.values())) if c in limits]
    crit = [c for c in CRITERIA if c in motions or c in extra]
    not_evaluated = sorted(configured - set(crit))
    n_c, n_t = len(tr.candidates), len(tr.tuggers)
    mpm = np.zeros((sel.size, n_c, n_t, len(crit)))
    u_crit = np.zeros((sel.size, n_c, n_t, len(crit)))
    for j, c in enumerate(crit):
        if c in extra:
            if live:
                u_crit[live, ..., j], mpm[live, ..., j] = extra[c][0], extra[c][1]
        elif ds is not None:
            mpm[live, ..., j] = ds["mpm"].sel(criterion=c).values
            u_crit[..., j] = mpm[..., j] / limits[c]
    if any(calm) and extra:                                 # a calm hour: the criteria's values at rest
        _at_rest(mpm, u_crit, crit, extra, np.asarray(calm))
    lim = np.array([extra[c][2] if c in extra else limits[c] for c in crit])
    hs_total = 4.0 * np.sqrt(np.nansum(np.where(fc.hs[sel] > 0, fc.hs[sel], 0.0) ** 2, axis=1) / 16.0)
    lead_h = (times[sel] - issued).total_seconds().to_numpy() / 3600.0
    af = alpha_factors(alpha, lead_h, hs_total)
    per_crit = u_crit / af[:, None, None, None]                       # NaN beyond the alpha table
    util = per_crit.max(axis=-1) if crit else np.zeros((sel.size, n_c, n_t))
    u2 = np.moveaxis(util, 0, -1).reshape(n_c * n_t, sel.size)
    pc2 = np.moveaxis(per_crit, 0, 2).reshape(n_c * n_t, sel.size, len(crit))
    reason = (f"the forecast ends at {times[-1].isoformat()}, before the leg's {plan.duration_h:g} h and "
              f"{plan.contingency_h:g} h of contingency are over")
    if alpha is not None and np.isnan(af[i0:i0 + need]).any():
        reason = (f"the alpha table ({alpha.source}) ends at a lead time of {alpha.lead_time_h[-1]:g} h, "
                  "before the leg and its contingency are over")
    dec = decide(u2, pc2, crit, i0, need, uncovered_reason=reason, strict=[c in STRICT for c in crit])
    hour = pd.DatetimeIndex(times[sel]).tz_convert(None)
    out = xr.Dataset(
        {"utilisation": (("time", "candidate", "tugger"), util),
         "criterion_utilisation": (("time", "candidate", "tugger", "criterion"), per_crit),
         "mpm": (("time", "candidate", "tugger", "criterion"), mpm),
         "alpha": ("time", af), "lead_time_h": ("time", lead_h), "course_deg": ("time", course),
         "hs_total": ("time", hs_total), "calm": ("time", np.asarray(calm)),
         "hs": (("time", "system"), fc.hs[sel]), "tp": (("time", "system"), fc.tp[sel]),
         "dir_from": (("time", "system"), fc.dir_from[sel]),
         "go": (("candidate", "tugger"), np.array([d.go for d in dec]).reshape(n_c, n_t)),
         "first_start": (("candidate", "tugger"),
                         np.array([-1 if d.first_start is None else d.first_start for d in dec]).reshape(n_c, n_t)),
         "governing_hour": (("candidate", "tugger"),
                            np.array([-1 if d.governing is None else d.governing[1] for d in dec]).reshape(n_c, n_t)),
         "governing_criterion": (("candidate", "tugger"),
                                 np.array(["" if d.governing is None else d.governing[0] for d in dec],
                                          dtype=object).reshape(n_c, n_t)),
         "margin": (("candidate", "tugger"),
                    np.array([np.nan if d.margin is None else d.margin for d in dec]).reshape(n_c, n_t)),
         "reason": (("candidate", "tugger"), np.array([d.reason for d in dec], dtype=object).reshape(n_c, n_t))},
        coords={"time": hour, "candidate": tr.candidates, "tugger": list(tr.tuggers), "criterion": crit,
                "system": list(fc.kinds), "limit": ("criterion", lim)})
    out["mpm"].attrs["long_name"] = ("the hour's value of each criterion: a relative motion's 3-h MPM [m, degree], "
                                     "the lowest tip clearance over the tip points [m], the lowest wire tension "
                                     "as a fraction of the static (wire_tension) [1], the highest or lowest wire "
                                     "tension [kN]; its limit the coordinate limit")
    out.attrs.update(
        route=plan.route, leg=plan.leg, duration_h=plan.duration_h, contingency_h=plan.contingency_h,
        contingency_source=plan.contingency_source, window_h=need, start=start.isoformat(), start_index=i0,
        issued=issued.isoformat(), forecast_file=fc.file, forecast_format=fc.format, forecast_sha256=fc.sha256,
        gamma_wind=gamma["wind"], gamma_swell=gamma["swell"],
        spreading_wind=str(spread["wind"]), spreading_swell=str(spread["swell"]),
        alpha_source=("alpha 1: no forecast alpha table configured (forecast.alpha_factors); the "
                      "forecast limits equal the operational limits" if alpha is None else alpha.source),
        criteria_not_evaluated=", ".join(not_evaluated),
        exposure_h=float(a["exposure_h"]), mpm_cycles=a["mpm_cycles"],
        heading_basis=("the course given" if plan.assumed_heading_deg is None and plan.waypoints is None
                       else "along the waypoints" if plan.assumed_heading_deg is None else
                       f"no course given or configured: each hour's largest wave system met at the leg's "
                       f"relative heading {plan.assumed_heading_deg:g} deg, as the route assumes"))
    return out


def _tip_tension(tr, cfg: dict, states, course, configured, threads, products=None, moments=None,
                 period: dict | None = None) -> dict:
    """The configured tip-clearance and wire-tension criteria the options' plant allows
    (its rigging geometry), per criterion (utilisation, extreme) of each live hour
    (n_live, candidate, tugger), the limit, and (utilisation, extreme) at rest
    (candidate, tugger) for the calm hours (:mod:`jls.assessment.sea_state_criteria`).
    ``moments(tip, hinge_xy, g, tensions)``: the hours' moments in the layout of
    :func:`jls.response.sea_state_tip_tension.tip_tension_moments` from elsewhere (a table).
    ``period``: a dict that receives each criterion's governing up-crossing period of the
    live hours (:func:`jls.assessment.sea_state_criteria.governing_period`)."""
    from jls.assessment.sea_state_criteria import tension_utilisation, tip_utilisation
    from jls.assessment.wire_tension import settings
    from jls.config.builders import tip_settings_from_config
    from jls.response.sea_state_tip_tension import tip_tension_moments
    from jls.response.wire_loads import has_geometry

    a, plant = cfg["assessment"], tr.plant
    tip = tip_settings_from_config(cfg) if TIP_AIR_GAP_M in configured else None
    if tip is not None and any(v not in plant for v in ["drop_height"] + (["padeye"] if tip.tip_offsets_m is None
                                                                          else [])):
        tip = None                                     # a plant given as matrices: not evaluated, stated
    tension = [k for k in TENSION_KEYS if k in configured] if has_geometry(plant) else []
    if tip is None and not tension:
        return {}
    v = cfg["vessel"]
    lever = np.subtract(v["hinge_m"], v["rao_reference_point_m"])[:2]
    g = float(cfg["g_m_per_s2"])
    if not len(states):
        stats = None
    elif moments is not None:
        stats = moments(tip, lever, g, bool(tension))
    else:
        stats = tip_tension_moments(tr, states, course, tip=tip, hinge_xy=lever, g=g, tensions=bool(tension),
                                    threads=threads, products=products)
    n_c, n_t = len(tr.candidates), len(tr.tuggers)
    out = {}
    if tip is not None:
        gap = float(a["criteria"][TIP_AIR_GAP_M])
        h = np.asarray(still_water_height(tip, plant["drop_height"].values), float)
        rest = (np.broadcast_to(np.where(h > gap, 0.0, np.inf)[:, None], (n_c, n_t)),
                np.broadcast_to(h[:, None], (n_c, n_t)))
        live = (tip_utilisation(stats, gap, tip.crest, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"], g=g,
                                period=period) if stats is not None else (None, None))
        out[TIP_AIR_GAP_M] = (*live, gap, *rest)
    for name in tension:
        value = a["criteria"][name]
        static = plant["tension"].transpose("candidate", "wire").values
        zero = {"tension_m0": np.zeros((1, n_c, n_t, static.shape[-1])), "tension_static": static}
        zero["tension_m2"] = zero["tension_m0"]
        rest = tension_utilisation(zero, name, value, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"])
        live = (tension_utilisation(stats, name, value, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                                    period=period) if stats is not None else (None, None))
        limit = settings(value)[0] if name == WIRE_TENSION_CRITERION else float(value)
        out[name] = (*live, limit, rest[0][0], rest[1][0])
    return out


def _at_rest(value, util, crit, extra, calm):
    """Calm hours (no wave system): the tip-clearance and tension criteria at rest."""
    for j, c in enumerate(crit):
        if c in extra:
            util[calm, ..., j] = extra[c][3]
            value[calm, ..., j] = extra[c][4]


def _iso(t) -> str:
    return pd.Timestamp(t).tz_localize("UTC").isoformat().replace("+00:00", "Z")


def answer(ds: xr.Dataset) -> dict:
    """The JSON object of ``jls forecast`` (module docstring of :mod:`jls.commands.forecast`)."""
    times = [_iso(t) for t in ds["time"].values]
    systems = []
    measured = ds.attrs["forecast_format"] == "spectra"
    for k in range(ds.sizes["time"]):
        if measured:                           # the spectrum's bins, summed: one entry an hour
            hs = ds["hs"].values[k]
            j = int(np.argmax(hs))
            systems.append([{"kind": "spectrum", "hs": float(ds["hs_total"].values[k]),
                             "tp": float(ds["tp"].values[k, j]), "dir_from": float(ds["dir_from"].values[k, j]),
                             "gamma": None, "spreading": f"measured, {int((hs > 0).sum())} direction bins"}])
            continue
        row = []
        for j, kind in enumerate(ds["system"].values.tolist()):
            hs = float(ds["hs"].values[k, j])
            if hs > 0:
                row.append({"kind": kind, "hs": hs, "tp": float(ds["tp"].values[k, j]),
                            "dir_from": float(ds["dir_from"].values[k, j]) % 360.0,
                            "gamma": float(ds.attrs[f"gamma_{kind}"]),
                            "spreading": ds.attrs[f"spreading_{kind}"]})
        systems.append(row)
    options = {}
    util = ds["utilisation"].values                       # (time, candidate, tugger)
    alpha = [_num(v) for v in ds["alpha"].values]
    course = [float(v) for v in ds["course_deg"].values]
    first, gh = ds["first_start"].values, ds["governing_hour"].values
    gc, margin, reason, go = (ds[k].values for k in ("governing_criterion", "margin", "reason", "go"))
    for ci, c in enumerate(ds["candidate"].values.tolist()):
        for ti, t in enumerate(ds["tugger"].values.tolist()):
            f, h = int(first[ci, ti]), int(gh[ci, ti])
            u = util[:, ci, ti]
            options.setdefault(str(c), {})[str(t)] = {
                "go": bool(go[ci, ti]),
                "first_start": None if f < 0 else times[f],
                "governing": None if h < 0 else {"criterion": str(gc[ci, ti]), "hour": times[h], "hour_index": h},
                "margin": _num(margin[ci, ti]),
                "reason": str(reason[ci, ti]),
                "hourly": [{"time": times[k], "utilisation": _num(u[k]), "alpha": alpha[k],
                            "course_deg": course[k], "systems": systems[k]}
                           for k in range(len(times))]}
    a = ds.attrs
    return {"route": a["route"], "leg": a["leg"], "start": _iso(pd.Timestamp(a["start"]).tz_convert(None)),
            "issued": _iso(pd.Timestamp(a["issued"]).tz_convert(None)),
            "duration_h": a["duration_h"], "contingency_h": a["contingency_h"],
            "contingency_source": a["contingency_source"], "window_h": int(a["window_h"]),
            "forecast": {"file": a["forecast_file"], "format": a["forecast_format"], "sha256": a["forecast_sha256"]},
            "alpha_source": a["alpha_source"], "heading_basis": a["heading_basis"],
            "exposure_h": a["exposure_h"], "mpm_cycles": a["mpm_cycles"],
            "criteria": {c: float(v) for c, v in zip(ds["criterion"].values.tolist(), ds["limit"].values)},
            "criteria_not_evaluated": [s for s in a["criteria_not_evaluated"].split(", ") if s],
            "options": options}


def _num(v):
    v = float(v)
    return v if np.isfinite(v) else None
