"""Every criterion of each recorded hour of a leg given by its own seas (measured spectra,
partitions, a Torsethaugen table), judged on the hour's directional sea itself.

The hour's sea is its wave systems (:mod:`jls.sea.sea_state`): a partitioned hour its
JONSWAP partitions spread by the leg's spreading (:func:`jls.sea.partitions.sea_states`),
a measured hour one long-crested measured system per direction bin of its spectrum
(:func:`jls.sea.sea_state.measured_systems`; a 1-D spectrum one long-crested system), a
Torsethaugen cell its wind sea and swell (:func:`jls.sea.sea_state.torsethaugen_systems`).
Every criterion of the configuration is evaluated on it with the functions of
``jls response`` and ``jls forecast`` (:func:`sea_state_utilisation`: the relative
motions by :func:`jls.response.sea_state.sea_state_statistics`, the tip clearance and the
wire tensions by :func:`jls.response.sea_state_tip_tension.tip_tension_moments` and
:mod:`jls.assessment.sea_state_criteria`), so an hour's utilisation here is the one those
commands print for the same systems and vessel heading.

Where the hour is met (:func:`hour_cases`):

* a leg with a course (``course_deg`` or ``waypoints``) and seas with directions: the
  hour's sea met on each of the leg's courses, the hour's utilisation the largest over
  them (one course: exactly that course), the same at every relative heading the hour is
  given in ``heading_weight`` (:func:`jls.sea.headings.hour_headings`);
* otherwise (a leg of relative headings, a table, a 1-D spectrum): at each of the leg's
  headings of the hour, the hour's largest system met at that relative heading, the
  others at their directions relative to it (``jls forecast``'s rule without a course).

The per-candidate transfer at each RAO heading is solved once and every hour shares it
(:func:`jls.response.sea_state.heading_moments`); cost and memory are linear in hours x
candidates. Many hours of parametric systems (:data:`jls.response.response_table.TABLE_HOURS`
sea states or more, every system JONSWAP or PM: a partitioned leg) take every criterion's
moments from one unit-Hs table per gamma interpolated in Tp
(:mod:`jls.response.response_table`, within 0.5 % on sigma of the exact path), in chunks
of :data:`CHUNK` sea states; measured spectra, Torsethaugen systems and fewer hours take
the exact path.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.names import CRITERIA, RESPONSES
from jls.sea.headings import leg_courses
from jls.sea.sea_state import SeaState, Spreading, measured_systems

__all__ = ["sea_state_utilisation", "hour_cases", "leg_states", "model_states", "leg_utilisation", "RULE"]

#: how the hours of such legs are met (dataset attribute ``hourly_utilisation_rule``)
#: the criteria whose voyage level is the motion itself (level units the limit's); the
#: others' level is the utilisation (limit 1), as :mod:`jls.assessment.criterion_levels`
LEVEL_IS_MOTION = tuple(k for k, (resp, _) in CRITERIA.items() if resp in RESPONSES)
#: sea states evaluated at once from the response table (bounded memory)
CHUNK = 1024

RULE = ("every criterion of each recorded hour evaluated on the hour's own directional sea "
        "(jls.stages.hourly_seas, the functions of jls response and jls forecast): on a leg with a "
        "course, the hour met on the course (the largest over the waypoints' courses); on a leg of "
        "relative headings, the hour's largest system met at each heading")


def sea_state_utilisation(tr, cfg: dict, states, course, *, threads=None, source=None, values=True,
                          period: dict | None = None):
    """(criteria, utilisation (n, c, t, criterion), value (n, c, t, criterion)) of sea
    states met on ``course`` [deg true] (one per state): every configured criterion the
    plant allows, in :data:`jls.names.CRITERIA` order, as ``jls forecast`` evaluates an hour
    (alpha 1): a relative motion's MPM over its limit, the tip clearance and wire tensions
    by :mod:`jls.assessment.sea_state_criteria`. ``cfg``: the validated configuration (its
    ``assessment``, ``vessel``, ``rigging`` and ``g_m_per_s2`` are read); ``values``
    False: the values are not kept where the table is used (None: many hours' memory).
    ``period``: a dict that receives ``tz_response`` (n, c, t, criterion), each
    criterion's up-crossing period on the sea state: a relative motion's own, the tip
    clearance's and a tension criterion's that of the governing tip point or wire
    (:func:`jls.assessment.sea_state_criteria.governing_period`)."""
    from jls.response.response_table import use_table
    from jls.response.sea_state import sea_state_statistics
    from jls.stages.forecast import _tip_tension
    a = cfg["assessment"]
    states = list(states)
    course = np.broadcast_to(np.asarray(course, float), (len(states),))
    if use_table(states):
        return _table_utilisation(tr, cfg, states, course, threads=threads, source=source, values=values,
                                  period=period)
    configured = {k for k, v in a["criteria"].items() if v is not None}
    limits = {k: float(v) for k, v in a["criteria"].items() if isinstance(v, (int, float))}
    ds = sea_state_statistics(tr, states, course, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                              threads=threads, source=source)
    periods = {} if period is not None else None        # the governing periods only when asked for
    extra = _tip_tension(tr, cfg, states, course, configured, threads, period=periods)
    motions = [c for c in ds["criterion"].values.tolist() if c in limits]
    crit = [c for c in CRITERIA if c in motions or c in extra]
    n_c, n_t = len(tr.candidates), len(tr.tuggers)
    util = np.zeros((len(states), n_c, n_t, len(crit)))
    value = np.zeros_like(util)
    tz = np.full_like(util, np.nan)
    for j, c in enumerate(crit):
        if c in extra:
            util[..., j], value[..., j] = extra[c][0], extra[c][1]
            tz[..., j] = periods.get(c, np.nan) if periods is not None else np.nan
        else:
            value[..., j] = ds["mpm"].sel(criterion=c).values
            util[..., j] = value[..., j] / limits[c]
            tz[..., j] = ds["tz_response"].sel(criterion=c).values
    if period is not None:
        period["tz_response"] = tz
    return crit, util, value


def _table_utilisation(tr, cfg: dict, states, course, *, threads=None, source=None, values=True, period=None):
    """:func:`sea_state_utilisation` of many hours of JONSWAP/PM systems from one
    :mod:`jls.response.response_table` per gamma, in chunks of :data:`CHUNK` sea states
    (memory bounded by the chunk and the table, whatever the hours), the chunks on
    ``threads`` (a chunk's numbers are its own: the same whatever the threads). The utilisation is
    float32: its 6e-8 relative precision is far inside the table's 0.5 % (and halves ten
    years of hours); the values float64."""
    from jls.names import RESPONSES
    from jls.response.response_table import response_table, table_moments, tp_grid
    from jls.response.sea_state import CRITERION_OF
    from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments
    from jls.stages.forecast import _tip_tension
    from jls.threads import thread_map
    a = cfg["assessment"]
    configured = {k for k, v in a["criteria"].items() if v is not None}
    limits = {k: float(v) for k, v in a["criteria"].items() if isinstance(v, (int, float))}
    exposure_s = float(a["exposure_h"]) * 3600.0
    cycles = "response" if a["mpm_cycles"] == "response" else FIXED_CYCLES_STUDY
    tps = {}
    for st in states:
        for x in st.systems:
            tps.setdefault(1.0 if x.shape == "pm" else float(x.gamma), []).append(x.tp)
    tables = {}

    def build(tip=None, lever=(0.0, 0.0), g=9.81, tensions=False):
        if not tables:
            for gamma, tp in tps.items():
                tables[gamma] = response_table(tr, tp_grid(tp), gamma, tip=tip, hinge_xy=lever, g=g,
                                               tensions=tensions, threads=threads)
        return tables

    motions = [CRITERION_OF[r] for r in RESPONSES]
    need = [j for j, c in enumerate(motions) if c in limits]        # the motions judged
    n_c, n_t = len(tr.candidates), len(tr.tuggers)
    out = {}

    def chunk(b):
        sl = slice(b, min(b + CHUNK, len(states)))
        held = {"m": None}

        def moments(tip, lever, g, tensions):
            held["m"] = table_moments(build(tip, lever, g, tensions), states[sl], course[sl], tr=tr, source=source)
            return held["m"]

        periods = {} if period is not None else None    # the governing periods only when asked for
        extra = _tip_tension(tr, cfg, states[sl], course[sl], configured, threads, moments=moments,
                             period=periods)
        m = held["m"] if held["m"] is not None else table_moments(build(), states[sl], course[sl], tr=tr,
                                                                   source=source)
        st = from_moments(m["m0"][..., need], m["m2"][..., need], exposure_s, cycles)
        mpm = st["mpm"]
        del m, held["m"]
        if "crit" not in out:
            out["crit"] = [c for c in CRITERIA if (c in motions and c in limits) or c in extra]
            out["util"] = np.zeros((len(states), n_c, n_t, len(out["crit"])), np.float32)
            out["value"] = np.zeros(out["util"].shape) if values else None
            out["tz"] = np.full(out["util"].shape, np.nan, np.float32) if period is not None else None
        for j, c in enumerate(out["crit"]):
            v = extra[c][1] if c in extra else mpm[..., need.index(motions.index(c))]
            out["util"][sl, ..., j] = extra[c][0] if c in extra else v / limits[c]
            if values:
                out["value"][sl, ..., j] = v
            if out["tz"] is not None:
                out["tz"][sl, ..., j] = (periods.get(c, np.nan) if c in extra
                                         else st["tz_response"][..., need.index(motions.index(c))])

    # the first chunk builds the tables (on the threads given) and the outputs; the others
    # share them, on the threads given: each chunk's numbers are its own whatever the threads
    starts = list(range(0, len(states), CHUNK))
    chunk(starts[0])
    thread_map(chunk, starts[1:], threads)
    crit, util, value = out["crit"], out["util"], out["value"]
    if period is not None:
        period["tz_response"] = out["tz"]
    return crit, util, value


def _dominant(state: SeaState) -> float:
    return float(max(state.systems, key=lambda s: s.m0()).from_deg)


def _rotated(state: SeaState, by: float) -> SeaState:
    from dataclasses import replace
    return SeaState(tuple(replace(s, from_deg=float(np.mod(s.from_deg + by, 360.0))) for s in state.systems))


def hour_cases(leg: dict, states, weights, directional: bool):
    """[(hour index, heading index or -1 for every heading, sea state, course)] of the
    hours' ``states`` (module docstring); ``weights`` (time, heading): the hour's
    ``heading_weight``; ``directional``: the states carry true directions."""
    headings = np.asarray(leg["headings_deg"], float)
    out = []
    if directional and ("course_deg" in leg or "waypoints" in leg):
        courses, _ = leg_courses(leg, f"legs[{leg['name']}]")
        for t, s in enumerate(states):
            if weights[t].sum() > 0:
                out += [(t, -1, s, float(c)) for c in courses]
        return out
    for t, s in enumerate(states):
        d = _dominant(s)
        for k in np.flatnonzero(weights[t] > 0):
            out.append((t, int(k), s, float(np.mod(headings[k] + d - 180.0, 360.0))))
    return out


def leg_states(efth: xr.DataArray):
    """(sea states, directional) of each hour of measured spectra ``efth`` (time, freq[,
    dir]): a directional hour one long-crested measured system per direction bin, a 1-D
    hour one long-crested system from 0 deg (to be met at the leg's headings)."""
    f = efth["freq"].values
    if "dir" in efth.dims:
        e = efth.transpose("time", "freq", "dir").values
        d = efth["dir"].values
        return [SeaState(tuple(measured_systems(f, e[t], d))) for t in range(e.shape[0])], True
    e = efth.transpose("time", "freq").values
    return [SeaState(tuple(measured_systems(f, e[t], from_deg=0.0, spreading=Spreading("long-crested"))))
            for t in range(e.shape[0])], False


def model_states(leg: dict, times, *, efth=None, base_dir=".", gamma: float, sea: dict | None):
    """(sea states, directional) of a leg's hours ``times`` (tz-naive UTC, as
    ``measured_response.nc`` holds them): measured spectra ``efth`` by :func:`leg_states`,
    a partitions file's hours by :func:`jls.sea.partitions.sea_states`, a Torsethaugen
    table's cells (one an hour from :data:`jls.stages.sea_model_spectra.TABLE_EPOCH`) split
    into their two systems, from 0 deg (met at the leg's headings)."""
    import pandas as pd

    from jls.sea.records import leg_partitions, leg_source, leg_spreading, sea_model
    times = pd.DatetimeIndex(times)
    model = sea_model(leg)
    if model == "measured":
        return leg_states(efth.sel(time=times.to_numpy()))
    spreading = leg_spreading(leg, sea)
    if model == "partitions":
        from jls.sea.partitions import sea_states
        frame = leg_partitions(leg, base_dir, gamma=gamma)
        states, kept = sea_states(frame, gamma=gamma, spreading=spreading)
        idx = pd.DatetimeIndex(frame.index[kept])
        idx = idx.tz_convert(None) if idx.tz is not None else idx
        at = dict(zip(idx.to_numpy(), states))
        return [at[t] for t in times.to_numpy()], True
    from jls.sea.scatter import read_scatter
    from jls.sea.sea_state import torsethaugen_systems
    ds = read_scatter(f"{base_dir}/{leg_source(leg)}",
                      **{k: leg[k] for k in ("layout", "bins", "values", "period") if k in leg})
    hs = ds["hs_upper"].values if sea["hs_in_bin"] == "upper" else ds["hs"].values
    cells = np.argwhere(ds["probability"].values > 0)
    states = [SeaState(tuple(torsethaugen_systems(float(hs[i]), "tp", float(ds["tz"].values[j]), from_deg=0.0,
                                                  spreading=spreading))) for i, j in cells]
    return states[:len(times)], False


def leg_utilisation(tr, cfg: dict, leg: dict, states, weights, *, directional: bool, threads=None,
                    source=None) -> xr.Dataset:
    """``utilisation`` (time, heading, candidate, tugger, criterion) of a leg's hours: each
    hour's criteria on its own sea (module docstring), NaN at a heading the hour is not
    met at (``weights`` 0); float32 where the hours' criteria came from the response table
    (:func:`_table_utilisation`)."""
    weights = np.asarray(weights, float)
    cases = hour_cases(leg, states, weights, directional)
    n_c, n_t = len(tr.candidates), len(tr.tuggers)
    n_k = len(leg["headings_deg"])
    held = {}
    if cases:
        crit, u, _ = sea_state_utilisation(tr, cfg, [c[2] for c in cases], [c[3] for c in cases],
                                           threads=threads, source=source, values=False, period=held)
        tz = held["tz_response"]
    else:
        crit, u, tz = [], np.zeros((0, n_c, n_t, 0)), np.zeros((0, n_c, n_t, 0))
    out = np.full((len(states), n_k, n_c, n_t, len(crit)), np.nan, u.dtype)
    per = np.full(out.shape, np.nan, u.dtype)
    seen = set()
    for (t, k, _, _), v, p in zip(cases, u, tz):
        if k >= 0:
            out[t, k], per[t, k] = v, p
            continue
        if t in seen:                          # the worst of the leg's courses (and its period)
            k0 = np.flatnonzero(weights[t] > 0)[0]
            worse = v > out[t, k0]
            v, p = np.where(worse, v, out[t, k0]), np.where(worse, p, per[t, k0])
        seen.add(t)
        out[t, weights[t] > 0] = v             # at every heading the hour is met at
        per[t, weights[t] > 0] = p
    dims = ("time", "heading", "candidate", "tugger", "criterion")
    return xr.Dataset({"utilisation": (dims, out), "tz_response_own": (dims, per)},
                      coords={"heading": np.asarray(leg["headings_deg"], float), "candidate": tr.candidates,
                              "tugger": list(tr.tuggers), "criterion": crit})
