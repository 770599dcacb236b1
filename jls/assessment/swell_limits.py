"""The master's table per swell system: for a leg whose sea is given by its partitions
(``spectrum: partitions``), the largest swell Hs per swell peak period that keeps every
criterion inside its limit with the wind sea at the leg's typical state.

* **The wind sea** (:func:`typical_wind_sea`): the median of the hourly wind-sea Hs over
  the leg's recorded hours (an hour without a wind partition counts as Hs 0), the median
  Tp of the hours that have one, and the energy-weighted circular mean of their
  directions. **The swell** comes from the energy-weighted circular mean direction of the
  records' swell partitions (:func:`mean_direction`); on a leg without a course both are
  met at the leg's heading of largest probability, as ``jls forecast`` assumes.
* **The criteria** are those ``jls forecast`` evaluates on a directional sea, each with
  its own function: the relative motions from their spectral moments
  (:func:`jls.response.sea_state.sea_state_moments`), the tip clearance and the wire
  tensions from :func:`jls.response.sea_state_tip_tension.tip_tension_moments` and the
  utilisations of :mod:`jls.assessment.sea_state_criteria` (Forristall's crest at the
  combined sea's Hs and steepness, the tension floor and SWL).
* **Superposition.** The two systems are independent, so every response moment of the sea
  of wind sea plus a swell of Hs h is m_wind + h^2 m_unit, with m_unit the moment of the
  same swell of Hs 1 m (the wave elevation's m0, m1, m2 alike): two solves (the wind sea
  and the unit swells at every Tp), then the utilisation of any h costs no solve.
* **OP_LIM** of the swell is the h at which the largest utilisation over the criteria
  reaches 1, found by bisection on h (:data:`BISECTIONS` halvings of [0,
  :data:`HS_SEARCH_M`]); 0 when the wind sea alone reaches a limit, infinite when no swell
  up to :data:`HS_SEARCH_M` does. **OP_WF**: alpha read as the voyage plan's master's
  table reads it (the operation's table at the planned period of the leg's stretch and
  the limiting Hs, here the total Hs sqrt(Hs_wind^2 + OP_LIM^2) of the limiting sea), and
  OP_WF the swell Hs at which the utilisation reaches alpha (with the wind sea at zero and
  a criterion linear in Hs, exactly alpha OP_LIM as in the master's table).

Linear in candidates and swell periods: the bisection runs on arrays over a block of
candidates (:data:`BLOCK_ELEMENTS`), each option with its own bracket, one evaluation of
the block's utilisation per step.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.operation import AlphaTable
from jls.assessment.sea_state_criteria import tension_utilisation, tip_utilisation
from jls.assessment.voyage_plan import alpha_periods
from jls.names import TIP_AIR_GAP_M
from jls.response.sea_state import CRITERION_OF, RESPONSES, sea_state_moments
from jls.response.sea_state_tip_tension import mean_period_t1, tip_tension_moments
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments
from jls.sea.sea_state import SeaState, WaveSystem

__all__ = ["BISECTIONS", "HS_SEARCH_M", "BLOCK_ELEMENTS", "WindSea", "Criteria", "typical_wind_sea", "mean_direction",
           "moments", "leg_moments", "block_utilisation", "utilisation", "block_size", "largest_swell", "swell_limits"]

#: halvings of the search interval of the swell Hs (2e-14 of it)
BISECTIONS = 50
#: the largest swell Hs searched [m] (beyond it: no limit)
HS_SEARCH_M = 30.0
#: numbers in a block's largest array (:func:`block_size`): 8 MB of float64
BLOCK_ELEMENTS = 2**20
#: the moments of :func:`moments` given per sea state (the rest per candidate)
PER_STATE = ("motion_m0", "motion_m2", "wave_m0", "wave_m1", "wave_m2", "sys_m0", "tip_m0", "tip_m2",
             "tension_m0", "tension_m2")
WIND_BASIS = ("the median wind-sea Hs of the leg's recorded hours (no wind partition: 0), the median Tp "
              "of the hours with one, their energy-weighted mean direction")


@dataclass(frozen=True)
class WindSea:
    """The leg's typical wind sea: Hs [m], Tp [s], direction [deg true, from]."""

    hs: float
    tp: float
    from_deg: float


@dataclass(frozen=True)
class Criteria:
    """The criteria the forecast evaluates: ``motions`` name -> limit (relative motions),
    ``tip`` (TipSettings or None) with its air gap, ``tensions`` name -> configured value,
    exposure, MPM cycles, g and the hinge's lever arm from the RAO reference point."""

    motions: dict
    tip: object
    air_gap: float
    tensions: dict
    exposure_h: float
    cycles: str
    g: float
    lever: tuple

    def names(self) -> list[str]:
        return list(self.motions) + ([TIP_AIR_GAP_M] if self.tip is not None else []) + list(self.tensions)


def mean_direction(frame: pd.DataFrame, parts) -> float:
    """Energy-weighted circular mean [deg, from] of the partitions ``parts`` of the hours."""
    vec = 0j
    for p in parts:
        hs, d = frame[f"hs_{p}"].to_numpy(float), frame[f"dir_{p}"].to_numpy(float)
        ok = np.isfinite(hs) & (hs > 0) & np.isfinite(d)
        vec += np.sum(hs[ok] ** 2 * np.exp(1j * np.radians(d[ok])))
    return float(np.mod(np.degrees(np.angle(vec)), 360.0)) if abs(vec) > 0 else float("nan")


def typical_wind_sea(frame: pd.DataFrame) -> WindSea:
    """The leg's typical wind sea (module docstring) from its partitions (hs_wind, tp_wind,
    dir_wind, ... per hour): the hours with any partition count."""
    hs_cols = [c for c in frame.columns if c.startswith("hs_")]
    recorded = frame[hs_cols].fillna(0.0).to_numpy(float).max(axis=1) > 0
    f = frame[recorded]
    hs = f["hs_wind"].fillna(0.0).to_numpy(float)
    with_wind = hs > 0
    if not with_wind.any():
        return WindSea(0.0, float("nan"), float("nan"))
    return WindSea(float(np.median(hs)), float(np.median(f["tp_wind"].to_numpy(float)[with_wind])),
                   mean_direction(f, ["wind"]))


def moments(tr, states, course, crit: Criteria) -> dict:
    """Every criterion's spectral moments of each sea state (n_s) met on ``course``: the
    relative motions' (n_s, c, t, motion), the wave's m0, m1, m2 and its systems' m0
    (n_s,), the tip's (n_s, c, t, tip) and the wires' (n_s, c, t, wire)."""
    m0, m2 = sea_state_moments(tr, states, course)
    names = [CRITERION_OF[r] for r in RESPONSES]
    k = [names.index(c) for c in crit.motions]
    out = {"motion_m0": m0[..., k], "motion_m2": m2[..., k]}
    st = tip_tension_moments(tr, states, course, tip=crit.tip, hinge_xy=crit.lever, g=crit.g,
                             tensions=bool(crit.tensions))
    sys_m0 = np.array([sum(x.m0() for x in s.systems) for s in states])
    t1 = np.asarray([mean_period_t1(s) for s in states], float)
    out.update(wave_m0=st["wave_m0"], wave_m2=st["wave_m2"], sys_m0=sys_m0,
               wave_m1=np.where(sys_m0 > 0, 2.0 * np.pi * sys_m0 / np.where(t1 > 0, t1, 1.0), 0.0))
    for key in ("tip_m0", "tip_m2", "tip_height", "tension_m0", "tension_m2", "tension_static"):
        if key in st:
            out[key] = st[key]
    return out


def _cycles(crit):
    return FIXED_CYCLES_STUDY if crit.cycles == "fixed" else "response"


def block_utilisation(wind: dict, unit: dict, h, crit: Criteria, cands=slice(None)) -> np.ndarray:
    """The largest utilisation over the criteria (n_p, b, t) of the candidates ``cands``
    (a slice or indices, b of them) in the sea of the wind sea (``wind``: :func:`moments`
    of one state) plus the unit swells (``unit``: of n_p states) scaled to swell Hs ``h``
    (n_p, b, t) [m], each option's sea its own: moments m_wind + h^2 m_unit."""
    h2 = np.asarray(h, float) ** 2                                   # (p, b, t)
    u = np.zeros(h2.shape)
    if crit.motions:
        m0 = wind["motion_m0"][0, cands] + h2[..., None] * unit["motion_m0"][:, cands]
        m2 = wind["motion_m2"][0, cands] + h2[..., None] * unit["motion_m2"][:, cands]
        mpm = from_moments(m0, m2, crit.exposure_h * 3600.0, _cycles(crit))["mpm"]
        u = np.maximum(u, (mpm / np.array(list(crit.motions.values()))).max(axis=-1))
    stats = {key: wind[key][0] + h2 * unit[key][:, None, None] for key in ("wave_m0", "wave_m1", "wave_m2", "sys_m0")}
    stats["hs"] = 4.0 * np.sqrt(stats["sys_m0"])
    with np.errstate(divide="ignore", invalid="ignore"):
        stats["wave_t1"] = 2.0 * np.pi * stats["sys_m0"] / stats["wave_m1"]
    for name in ("tip", "tension"):
        if f"{name}_m0" in unit:
            for q in ("m0", "m2"):
                stats[f"{name}_{q}"] = wind[f"{name}_{q}"][0, cands] + h2[..., None] * unit[f"{name}_{q}"][:, cands]
    if crit.tip is not None:
        stats["tip_height"] = np.asarray(wind["tip_height"], float)[cands]
        ut, _ = tip_utilisation(stats, crit.air_gap, crit.tip.crest, exposure_h=crit.exposure_h,
                                cycles=crit.cycles, g=crit.g)
        u = np.maximum(u, ut)
    if crit.tensions:
        stats["tension_static"] = np.asarray(wind["tension_static"], float)[cands]
        for name, value in crit.tensions.items():
            ut, _ = tension_utilisation(stats, name, value, exposure_h=crit.exposure_h, cycles=crit.cycles)
            u = np.maximum(u, ut)
    return u


def utilisation(wind: dict, unit: dict, h, crit: Criteria, c: int) -> np.ndarray:
    """:func:`block_utilisation` (n_p, t) of candidate ``c`` alone at swell Hs ``h`` (n_p, t)."""
    return block_utilisation(wind, unit, np.asarray(h, float)[:, None], crit, slice(c, c + 1))[:, 0]


def block_size(unit: dict, n_t: int) -> int:
    """Candidates solved together: a block's largest array (swell periods x candidates x
    tuggers x tip points, wires or motions) holds about :data:`BLOCK_ELEMENTS` numbers."""
    n_p = unit["motion_m0"].shape[0]
    parts = max([1] + [unit[k].shape[-1] for k in ("motion_m0", "tip_m0", "tension_m0") if k in unit])
    return max(1, BLOCK_ELEMENTS // (n_p * n_t * parts))


def largest_swell(wind: dict, unit: dict, crit: Criteria, n_t: int, target=1.0) -> np.ndarray:
    """The largest swell Hs (p, c, t) [m] at which the utilisation stays at most ``target``
    (scalar or (p, c, t)): 0 when the wind sea alone exceeds it, inf when no swell up to
    :data:`HS_SEARCH_M` does; bisection, the utilisation taken as rising with the swell,
    every option with its own bracket, a block of candidates (:func:`block_size`) at a
    time: the same halvings as one option alone, each within HS_SEARCH_M / 2**BISECTIONS
    (2.7e-14 m) of its limit."""
    n_p, n_c = unit["motion_m0"].shape[:2]
    tgt = np.broadcast_to(np.asarray(target, float), (n_p, n_c, n_t))
    out = np.empty((n_p, n_c, n_t))
    size = block_size(unit, n_t)
    for start in range(0, n_c, size):
        cands = slice(start, min(start + size, n_c))
        goal = tgt[:, cands]
        lo, hi = np.zeros(goal.shape), np.full(goal.shape, HS_SEARCH_M)
        at0 = block_utilisation(wind, unit, lo, crit, cands) > goal
        none = block_utilisation(wind, unit, hi, crit, cands) <= goal
        for _ in range(BISECTIONS):
            mid = 0.5 * (lo + hi)
            inside = block_utilisation(wind, unit, mid, crit, cands) <= goal
            lo, hi = np.where(inside, mid, lo), np.where(inside, hi, mid)
        out[:, cands] = np.where(at0, 0.0, np.where(none, np.inf, lo))
    return out


def leg_moments(tr, wind: WindSea, swell_tp, swell_from_deg: float, course_deg: float, crit: Criteria, *,
                gamma: float, spreading: dict) -> tuple[dict, dict]:
    """(wind, unit): the :func:`moments` of the wind sea (one state; zero without one) and
    of the swells of Hs 1 m at each of ``swell_tp`` (n_p states) met on ``course_deg``."""
    tps = np.asarray(swell_tp, float)
    states = [SeaState((WaveSystem("jonswap", 1.0, float(tp), float(swell_from_deg) % 360.0,
                                   spreading["swell"], "swell", float(gamma)),)) for tp in tps]
    if wind.hs > 0:
        states.append(SeaState((WaveSystem("jonswap", wind.hs, wind.tp, wind.from_deg % 360.0, spreading["wind"],
                                           "wind", float(gamma)),)))
    m = moments(tr, states, float(course_deg), crit)
    n = tps.size
    unit = {k: (v[:n] if k in PER_STATE else v) for k, v in m.items()}
    w = {k: (v[n:] if wind.hs > 0 else np.zeros_like(v[:1])) if k in PER_STATE else v for k, v in m.items()}
    return w, unit


def swell_limits(tr, wind: WindSea, swell_tp, swell_from_deg: float, course_deg: float, crit: Criteria, *,
                 gamma: float, spreading: dict, period_h: float, alpha: AlphaTable | None) -> xr.Dataset:
    """OP_LIM, alpha and OP_WF of the swell (candidate, tugger, swell_tp) for one leg
    (module docstring). ``spreading``: the leg's by kind (wind, swell) as Spreading;
    ``period_h``: the planned period of the leg's stretch; ``alpha``: the operation's
    table or None (alpha 1)."""
    tps = np.asarray(swell_tp, float)
    w, unit = leg_moments(tr, wind, tps, swell_from_deg, course_deg, crit, gamma=gamma, spreading=spreading)
    n_t = len(tr.tuggers)
    oplim = largest_swell(w, unit, crit, n_t)
    a = np.ones_like(oplim)
    if alpha is not None:
        period = float(alpha_periods([period_h], alpha)[0])
        total = np.sqrt(wind.hs**2 + np.where(np.isfinite(oplim), oplim, 1e3) ** 2)
        a = alpha.factor(period, total)
    opwf = largest_swell(w, unit, crit, n_t, target=a) if alpha is not None else oplim
    dims = ("swell_tp", "candidate", "tugger")
    coords = {"swell_tp": tps, "candidate": list(tr.candidates), "tugger": list(tr.tuggers)}
    return xr.Dataset({"swell_hs_oplim": (dims, oplim), "swell_alpha": (dims, a), "swell_hs_opwf": (dims, opwf)},
                      coords=coords).transpose("candidate", "tugger", "swell_tp")
