"""The tip-clearance and wire-tension criteria of a sea state given as its own spectrum (a
forecast hour's wave systems met at the vessel's heading), from the statistics of
:func:`jls.response.sea_state_tip_tension.tip_tension_moments`, with the definitions of
the workability (:mod:`jls.assessment.workability`):

* ``tip_air_gap_m`` (:mod:`jls.assessment.tip_clearance`): the demand at the worst tip
  point D = MPM_r + (F - 1) MPM_eta (Forristall's crest factor F at the sea state's Hs,
  mean steepness S1 = 2 pi Hs / (g T1^2) and number of waves) against the allowance
  A = h_tip - air gap. The utilisation is the workability's, Hs / Hs_lim, with Hs_lim the
  height to which the sea state, its spectral shape and directions kept, may grow before
  D reaches A: it passes exactly when D <= A, and for a long-crested JONSWAP sea it is the
  workability's utilisation of that (Hs, Tz) and heading. With the linear crest model it
  is D / A. A tip at or below the air gap at rest: infinite (fails in any sea).
* ``wire_tension`` (:mod:`jls.assessment.wire_tension`): the largest over the wires of the
  MPM of the dynamic tension over the wire's dynamic allowance min(T_s (1 - f), C - T_s);
  strict (a wire at its floor fails); a slack wire (MPM above T_s) always fails.
* ``max_wire_tension_kN`` / ``min_wire_tension_kN``: MPM_i / (SWL - T_s,i) and
  MPM_i / (T_s,i - floor) (the floor strict).

Each also returns the criterion's extreme, as ``workability.nc``'s cell value: the lowest
tip clearance h_tip - D over the tip points [m], the highest or lowest tension over the
wires [kN], the lowest tension as a fraction of the static (``wire_tension``) [-].

The sea state's own statistics (``hs``, ``wave_t1``, ``wave_m0``, ``wave_m2``) are given
per sea state (n_s,) or per sea state, candidate and tugger (n_s, c, t): a sea of its own
for each option (the swell table's bisection, :mod:`jls.assessment.swell_limits`, grows
each option's swell to its own limit); each option's result is the same either way.
"""

from __future__ import annotations

import numpy as np

from jls.assessment import wire_tension as wt
from jls.assessment.tip_clearance import crest_factor, limiting_hs
from jls.names import TENSION_SENSE, WIRE_TENSION_CRITERION
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments

__all__ = ["STRICT", "tip_utilisation", "tension_utilisation", "governing_period"]

#: criteria whose value must stay strictly inside the limit (the tension floors)
STRICT = ("min_wire_tension_kN", WIRE_TENSION_CRITERION)


def _cycles(cycles):
    return FIXED_CYCLES_STUDY if cycles == "fixed" else "response"


def _per_state(x):
    """A statistic of the sea state (n_s,) as (n_s, 1, 1), one per option (n_s, c, t) as is."""
    x = np.asarray(x, float)
    return x[:, None, None] if x.ndim == 1 else x


def governing_period(per_part, m0, m2):
    """The up-crossing period [s] (n_s, c, t) of the governing part (tip point or wire: the
    one of highest utilisation ``per_part`` (n_s, c, t, part)), 2 pi sqrt(m0 / m2) of its
    moments; NaN where it has no m2 or no part is finite. The voyage extremes take the
    criterion's up-crossings at this period (:func:`jls.assessment.hourly.own_sigma`)."""
    u = np.nan_to_num(np.asarray(per_part, float), nan=-np.inf, posinf=np.finfo(float).max)
    g = np.argmax(u, axis=-1)[..., None]
    m0 = np.take_along_axis(np.broadcast_to(np.asarray(m0, float), u.shape), g, -1)[..., 0]
    m2 = np.take_along_axis(np.broadcast_to(np.asarray(m2, float), u.shape), g, -1)[..., 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(m2 > 0, 2.0 * np.pi * np.sqrt(m0 / m2), np.nan)


def tip_utilisation(stats: dict, air_gap: float, crest: str, *, exposure_h: float, cycles: str, g: float,
                    period: dict | None = None):
    """(utilisation, lowest clearance [m]), each (n_s, c, t): module docstring (the sea's
    statistics per sea state or per option). ``period``:
    a dict that receives the governing tip point's up-crossing period (n_s, c, t)
    (:func:`governing_period`) under the criterion's name."""
    exposure_s, n_cycles = float(exposure_h) * 3600.0, _cycles(cycles)
    # D rises with MPM_r, all else of the hour and candidate the same at every tip point:
    # the worst point is the one of the largest MPM_r, and solving for the limiting Hs
    # there alone gives the largest Hs / Hs_lim and the lowest clearance over the points
    # exactly (each a monotone function of MPM_r; NaN if any point's is)
    every = from_moments(stats["tip_m0"], stats["tip_m2"], exposure_s, n_cycles)["mpm"]   # (s, c, t, tip)
    r = every.max(axis=-1)
    wave = from_moments(stats["wave_m0"], stats["wave_m2"], exposure_s, n_cycles)
    hs = np.asarray(stats["hs"], float)
    steep = 2.0 * np.pi / (float(g) * np.asarray(stats["wave_t1"], float) ** 2)          # S1 per m of Hs
    allowance = (np.asarray(stats["tip_height"], float) - float(air_gap))[None, :, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        per_m = _per_state(hs)
        me = _per_state(wave["mpm"] / hs)
        H = limiting_hs(allowance, r / per_m, me, _per_state(steep), _per_state(wave["n_cycles"]), crest)
        u = per_m / H
    if period is not None:
        # the governing point is the one of the largest Hs / Hs_lim (the first of ties):
        # the largest MPM_r; every point ties where the allowance is not positive (each
        # fails at any Hs) and none is known where the hour's or the allowance's is not
        rank = np.where(allowance[..., None] > 0, every, np.where(np.isnan(every), np.nan, 0.0))
        unknown = np.isnan(allowance) | np.isnan(me) | ~(per_m > 0)
        rank = np.where(unknown[..., None], np.nan, rank)
        period["tip_air_gap_m"] = governing_period(rank, stats["tip_m0"], stats["tip_m2"])
    F, _ = crest_factor(hs, steep, wave["n_cycles"], crest)
    clearance = np.asarray(stats["tip_height"], float)[None, :, None] - (r + _per_state((F - 1.0) * wave["mpm"]))
    return u, clearance


def tension_utilisation(stats: dict, name: str, value, *, exposure_h: float, cycles: str,
                        period: dict | None = None):
    """(utilisation, extreme), each (n_s, c, t), of the wire-tension criterion ``name``
    (``wire_tension``, ``max_wire_tension_kN`` or ``min_wire_tension_kN``) with its
    configured ``value``: module docstring. ``period``: as :func:`tip_utilisation`'s
    (the governing wire's)."""
    mpm = from_moments(stats["tension_m0"], stats["tension_m2"], float(exposure_h) * 3600.0,
                       _cycles(cycles))["mpm"]                                           # (s, c, t, wire)
    static = np.asarray(stats["tension_static"], float)[None, :, None, :]
    if name == WIRE_TENSION_CRITERION:
        floor, ceiling = wt.settings(value)
        a = static * (1.0 - floor)
        if np.isfinite(ceiling):
            a = np.minimum(a, ceiling - static)
        extreme = ((static - mpm) / static).min(axis=-1)
    else:
        a = TENSION_SENSE[name] * (float(value) - static)
        extreme = (static + mpm).max(axis=-1) if TENSION_SENSE[name] > 0 else (static - mpm).min(axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.where(a > 0, mpm / np.where(a > 0, a, 1.0), np.where(np.isnan(a), np.nan, np.inf))
    u = np.broadcast_to(u, mpm.shape)
    if period is not None:
        period[name] = governing_period(u, stats["tension_m0"], stats["tension_m2"])
    return u.max(axis=-1), extreme
