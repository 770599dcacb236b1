"""Scores of rigging candidates against one route: the screening envelope of section
5.4 and the route's workability, per tugger setting.

* ``screening_sigma``: the study's screening score (section 5.4, figure 5.4), the worst
  relative-sway standard deviation over the envelope Hs = 2.5 m, Tz 5.5-8.5 s, at the
  envelope's heading (beam seas by default). ``screening_mpm`` is the worst three-hour
  MPM of every relative motion over the same envelope (section 5.7.3: roll and yaw are
  reported beside sway and may be constrained).
* ``route_workability``: the duration-weighted workable fraction of the route
  (:func:`jls.assessment.workability.assess`), piecewise constant in the design variables.
* ``workability_surrogate``: the same sum with each cell's pass flag replaced by the
  share of its Hs bin below the limiting Hs, ``clip((Hs_lim - Hs_assessed) / dHs + 1/2,
  0, 1)``: continuous in the design variables, so an optimiser can follow it, and equal
  to the workability wherever no limiting Hs lies within half a bin of an assessed Hs.

Only candidates whose plant exists (taut, stable, finite matrices) are scored; the
others carry NaN. All frequency-domain work goes through :func:`candidate_moments`: one
solver call for all candidates of a plant dataset, cost linear in candidates. An
optimiser scoring one design at a time uses :class:`PointScorer`: the same numbers by
the same operations, without building datasets (the surrogate's sums run in one fixed
order, :func:`_surrogate`, so a candidate's surrogate does not depend on how many are
scored together).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.assessment.workability import assess, assessed_hs, criteria_array
from jls.errors import InputError
from jls.names import CRITERIA, RELATIVE_SWAY, RESPONSES, ROTATIONAL, TENSION_KEYS
from jls.response.coverage import check_coverage
from jls.response.moments import BLOCK, excitation, statistics_dataset, unit_moments
from jls.response.solver import frequency_grid, moment_weights, relative_power, spectral_moments
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, unit_spectra
from jls.vessel.headings import select
from jls.vessel.transfer import motion_on_grid

SWAY = RELATIVE_SWAY
_COVERED: set = set()          # sea-state sets whose RAO coverage was checked
ANGLES = {r for r, rotational in zip(RESPONSES, ROTATIONAL) if rotational}


@dataclass(frozen=True)
class Envelope:
    """Screening envelope: constant Hs over a Tz band at one heading (section 5.4)."""

    hs_m: float
    tz_min_s: float
    tz_max_s: float
    tz_step_s: float
    heading_deg: float

    def tz(self) -> np.ndarray:
        """Tz from the shortest in steps, the longest always included [s]."""
        n = int(np.floor((self.tz_max_s - self.tz_min_s) / self.tz_step_s + 1e-9))
        tz = np.round(self.tz_min_s + self.tz_step_s * np.arange(n + 1), 9)
        return tz if tz[-1] >= self.tz_max_s - 1e-9 else np.append(tz, self.tz_max_s)


@dataclass(frozen=True)
class MomentSettings:
    """What the screening's spectral moments depend on: the tugger slopes by name [kN s/m],
    the JONSWAP gamma, the frequency step [rad/s] and the RAO-range policy
    (``vessel.outside_rao_range``, :mod:`jls.response.coverage`). :class:`Scoring`
    carries the same attributes, so either serves :func:`candidate_moments`."""

    tuggers: dict
    gamma: float
    omega_step: float
    outside_policy: dict | None


@dataclass(frozen=True)
class Scoring:
    """Everything the scores depend on besides the candidates (built from the
    configuration by :func:`jls.config.builders.scoring_from_config`)."""

    tuggers: dict
    criteria: dict
    envelope: Envelope
    gamma: float
    exposure_h: float
    cycles: str
    omega_step: float
    outside_policy: dict | None            # vessel.outside_rao_range (jls.response.coverage)
    hs_in_bin: str
    steepness_rule: str


def screening_states(sea: xr.Dataset, sc: Scoring) -> tuple[list, list]:
    """(Tz, headings) the scores need, sorted: the route's and the envelope's."""
    env = sc.envelope
    headings = sorted({float(h) for h in sea["heading"].values} | {float(env.heading_deg)})
    tz = sorted({float(t) for t in sea["tz"].values} | {float(t) for t in env.tz()})
    return tz, headings


def _check_coverage(motion: xr.Dataset, tz, sc: MomentSettings | Scoring) -> None:
    """The RAOs' frequency range holds the sea states' energy (checked once per set)."""
    lo, hi = float(motion["omega"].min()), float(motion["omega"].max())
    key = (lo, hi, tuple(np.round(np.asarray(tz, float), 9)), float(sc.gamma), repr(sc.outside_policy))
    if key not in _COVERED:                        # refinement calls this per design
        check_coverage(lo, hi, tz, sc.gamma, sc.outside_policy, "the vessel RAOs")
        _COVERED.add(key)


def candidate_moments(plant: xr.Dataset, motion: xr.Dataset, tz, headings, sc: MomentSettings | Scoring, *,
                      candidates=slice(None), cache=None, threads=None, counter=None):
    """Unit-Hs spectral moments (m0, m2), (n_c, n_t, n_h, 4, n_tz), of the candidates
    ``candidates`` (a slice of the plant's candidate axis), from one call into the
    frequency-domain solver.

    The frequency grid is refined around the modes of *every* candidate of ``plant``,
    whichever slice is computed, and the solver works in blocks aligned to the global
    candidate index (:data:`jls.response.moments.BLOCK`): a slice's numbers are identical
    to those of the same candidates in an unsliced call, so candidates can be split over
    jobs. Candidates without a plant (NaN matrices) come out NaN. ``cache``: a sea-state
    cache directory; ``counter``: a list to which the number of (Tz, heading) sea states
    evaluated (not read from the cache) is appended.
    """
    _check_coverage(motion, tz, sc)
    exc = excitation(plant, motion, headings, sc.omega_step)
    m0, m2, evaluated = unit_moments(plant, exc, np.asarray(tz, float),
                                     [sc.tuggers[t] for t in sc.tuggers], sc.gamma,
                                     candidates=candidates, cache=cache, threads=threads)
    if counter is not None:
        counter.append(evaluated)
    return m0, m2


def unit_response(plant: xr.Dataset, motion: xr.Dataset, tz, headings, sc: Scoring, *,
                  moments=None, threads=None) -> xr.Dataset:
    """Unit-Hs statistics (sigma, mpm per candidate, tugger, heading, response, tz) of
    every candidate of ``plant`` on the sorted ``tz`` and ``headings``.

    moments: (m0, m2) of these candidates already computed (:func:`candidate_moments`,
    possibly by chunks), else computed here in one solver call.
    """
    tz = sorted(float(t) for t in tz)
    headings = sorted(float(h) for h in headings)
    if moments is None:
        moments = candidate_moments(plant, motion, tz, headings, sc, threads=threads)
    m0, m2 = moments
    return statistics_dataset(m0, m2, candidates=plant["candidate"].values.tolist(),
                              tuggers=sc.tuggers, headings=headings, tz=tz, gamma=sc.gamma,
                              exposure_h=sc.exposure_h, cycles=sc.cycles)[["sigma", "mpm"]]


def computable(plant: xr.Dataset) -> np.ndarray:
    """Candidates whose plant exists: finite matrices and positive natural periods."""
    finite = np.isfinite(plant["K"].values).all((-1, -2)) & np.isfinite(plant["C"].values).all((-1, -2))
    periods = plant["natural_period"].values
    return finite & np.all(np.isfinite(periods) & (periods > 0), -1)


def score(plant: xr.Dataset, motion: xr.Dataset, sea: xr.Dataset, sc: Scoring, *,
          moments=None, threads=None) -> xr.Dataset:
    """Scores (candidate, tugger[, response]) of the candidates of a plant dataset.

    moments: (m0, m2) of every candidate of ``plant`` on :func:`screening_states`
    (computed by chunks, :func:`candidate_moments`); else computed here in one call.
    """
    names = list(sc.tuggers)
    ok = computable(plant)
    env = sc.envelope
    tz_env = env.tz()
    tz_all, headings = screening_states(sea, sc)
    n = plant.sizes["candidate"]
    crit = criteria_array(sc.criteria)
    shape = (n, len(names))
    out = {"screening_sigma": np.full(shape, np.nan), "route_workability": np.full(shape, np.nan),
           "workability_surrogate": np.full(shape, np.nan),
           "screening_mpm": np.full(shape + (4,), np.nan)}
    responses = None
    if ok.any():
        if moments is None:
            moments = candidate_moments(plant, motion, tz_all, headings, sc, threads=threads)
        idx = np.flatnonzero(ok)
        resp = unit_response(plant.isel(candidate=idx), motion, tz_all, headings, sc,
                             moments=(moments[0][idx], moments[1][idx]))
        responses = resp["response"].values
        at_env = resp.sel(heading=float(env.heading_deg), tz=tz_env)
        out["screening_sigma"][ok] = (env.hs_m * at_env["sigma"].sel(response=SWAY)).max("tz").values
        out["screening_mpm"][ok] = (env.hs_m * at_env["mpm"]).max("tz").transpose(
            "candidate", "tugger", "response").values
        route = resp.sel(heading=sea["heading"].values, tz=sea["tz"].values)
        work = assess(route, sea, sc.criteria, hs_in_bin=sc.hs_in_bin,
                      steepness_rule=sc.steepness_rule, gamma=sc.gamma)
        out["route_workability"][ok] = work["workability_route"].transpose("candidate", "tugger").values
        hs_lim = work["hs_limit_criterion"].min("criterion")          # no steepness cap, as assess
        out["workability_surrogate"][ok] = _surrogate(
            hs_lim.transpose("candidate", "tugger", "heading", "tz").values, SeaCells(sea, sc.hs_in_bin))
    responses = list(responses) if responses is not None else list(RESPONSES)
    coords = {"candidate": plant["candidate"].values, "tugger": names,
              "c_tugger": ("tugger", [sc.tuggers[t] for t in names]), "response": responses,
              "response_units": ("response", ["degree" if r in ANGLES else "m" for r in responses])}
    ds = xr.Dataset({
        "screening_sigma": (("candidate", "tugger"), out["screening_sigma"]),
        "screening_mpm": (("candidate", "tugger", "response"), out["screening_mpm"]),
        "route_workability": (("candidate", "tugger"), out["route_workability"]),
        "workability_surrogate": (("candidate", "tugger"), out["workability_surrogate"]),
    }, coords=coords)
    what = f"Hs {env.hs_m:g} m, Tz {env.tz_min_s:g}-{env.tz_max_s:g} s, heading {env.heading_deg:g} deg"
    for name, long_name, unit in [
        ("screening_sigma", f"worst relative-sway standard deviation over the screening envelope ({what})", "m"),
        ("screening_mpm", f"worst three-hour MPM over the screening envelope ({what})", None),
        ("route_workability", "duration-weighted workable fraction of the route", "1"),
        ("workability_surrogate", "route workability with each cell's pass flag spread over its Hs bin", "1"),
        ("c_tugger", "tugger damping slope", "kN s m-1"),
    ]:
        ds[name].attrs.update(long_name=long_name, **({"units": unit} if unit else {"units_from": "response_units"}))
    ds["response_units"].attrs["long_name"] = "units of the response MPM"
    ds.attrs["criteria"] = ", ".join(f"{k} {v:g}" for k, v in zip(crit["criterion"].values, crit.values))
    return ds


class PointScorer:
    """The scores :func:`score` gives a one-candidate plant, from the candidate's
    matrices and modes, without datasets: for an optimiser that evaluates one design at
    a time. Everything that does not depend on the candidate (sea states, RAOs at the
    scored headings, criteria, the route's cells) is prepared once. The numbers are
    those of :func:`score`, by the same operations: the moments are computed in a
    solver block of :data:`jls.response.moments.BLOCK` rows as there. Route workability
    itself is not computed (the optimiser follows the surrogate); motion criteria only,
    as :func:`score`.
    """

    def __init__(self, motion: xr.Dataset, sea: xr.Dataset, sc: Scoring):
        limit = criteria_array(sc.criteria)
        self.criteria = []
        for name, lim in zip(limit["criterion"].values.tolist(), limit.values.tolist()):
            if name in TENSION_KEYS:
                raise InputError(f"the criterion {name} needs the wire-tension statistics, "
                                 "which the screening does not compute",
                                 field=f"assessment.criteria.{name}")
            self.criteria.append((RESPONSES.index(CRITERIA[name][0]), float(lim)))
        tz, headings = screening_states(sea, sc)
        _check_coverage(motion, tz, sc)
        self.sc, self.tz = sc, np.asarray(tz, float)
        self.c_tugger = [sc.tuggers[t] for t in sc.tuggers]
        self.n_cycles = "response" if sc.cycles == "response" else FIXED_CYCLES_STUDY
        self.omega_rao = motion["omega"].values
        self.motion = select(motion, headings)
        self.headings = headings
        env = sc.envelope
        self.env_heading = headings.index(float(env.heading_deg))
        self.env_tz = [tz.index(float(t)) for t in env.tz()]
        self.route_heading = [headings.index(float(h)) for h in sea["heading"].values]
        self.route_tz = [tz.index(float(t)) for t in sea["tz"].values]
        self.cells = SeaCells(sea, sc.hs_in_bin)

    def moments(self, plant) -> tuple[np.ndarray, np.ndarray]:
        """Unit-Hs (m0, m2), (1, n_t, n_h, 4, n_tz), of a one-candidate
        :class:`jls.plant.model.Plant` on the sorted screening Tz and headings."""
        lo, hi = float(self.omega_rao.min()), float(self.omega_rao.max())
        period = np.atleast_2d(plant.modes.period)
        omega = frequency_grid(lo, hi, self.sc.omega_step, 2 * np.pi / period,
                               np.atleast_2d(plant.damping_ratio))
        gm = motion_on_grid(self.motion, self.headings, omega)
        qb, yf = gm.hinge, gm.fairlead_sway
        W = moment_weights(omega, unit_spectra(omega, self.tz, self.sc.gamma))
        M, K, Kb, C = (np.asarray(a, float).reshape(1, 4, 4) for a in (plant.M, plant.K, plant.Kb, plant.C))
        P = np.zeros((BLOCK, len(self.c_tugger), qb.shape[0], 4, omega.size))
        P[:1] = relative_power(M, K, Kb, C, omega, qb, yf, self.c_tugger, threads=1)
        m0, m2 = spectral_moments(P, W)
        return m0[:1], m2[:1]

    def __call__(self, plant) -> dict[str, np.ndarray]:
        """``screening_sigma`` (n_t,), ``screening_mpm`` (n_t, 4) and
        ``workability_surrogate`` (n_t,) of a one-candidate plant; NaN where its plant
        does not exist (:func:`computable`)."""
        n_t = len(self.c_tugger)
        out = {"screening_sigma": np.full(n_t, np.nan), "screening_mpm": np.full((n_t, 4), np.nan),
               "workability_surrogate": np.full(n_t, np.nan)}
        period = np.asarray(plant.modes.period, float)
        if not (np.isfinite(plant.K).all() and np.isfinite(plant.C).all()
                and np.all(np.isfinite(period) & (period > 0))):
            return out
        m0, m2 = self.moments(plant)
        stats = from_moments(m0, m2, self.sc.exposure_h * 3600.0, self.n_cycles)
        hs_env = self.sc.envelope.hs_m
        sigma = stats["sigma"][:, :, self.env_heading][..., self.env_tz]      # (1, t, response, tz)
        mpm = stats["mpm"][:, :, self.env_heading][..., self.env_tz]
        out["screening_sigma"] = np.fmax.reduce(hs_env * sigma[:, :, 0], axis=-1)[0]
        out["screening_mpm"] = np.fmax.reduce(hs_env * mpm, axis=-1)[0]
        route = stats["mpm"][:, :, self.route_heading][..., self.route_tz]    # (1, t, h, response, tz)
        with np.errstate(divide="ignore"):
            per_criterion = [1.0 / (route[:, :, :, r] / lim) for r, lim in self.criteria]
        hs_lim = np.fmin.reduce(np.stack(per_criterion), axis=0)
        out["workability_surrogate"] = _surrogate(hs_lim, self.cells)[0]
        return out


class SeaCells:
    """The route's cells as the surrogate weighs them, in a fixed order: assessed Hs
    ``hs`` and bin ``width`` (leg, hs), cell ``weight`` (leg, heading, hs, tz) and
    ``leg_weight`` (leg)."""

    def __init__(self, sea: xr.Dataset, hs_in_bin="centre"):
        width = (sea["hs_upper"] - sea["hs_lower"]).fillna(1.0)
        weight = (sea["probability"] * sea["heading_probability"]).fillna(0.0)
        self.hs = assessed_hs(sea, hs_in_bin).transpose("leg", "hs").values
        self.width = width.transpose("leg", "hs").values
        self.weight = np.ascontiguousarray(weight.transpose("leg", "heading", "hs", "tz").values)
        self.leg_weight = sea["leg_weight"].values


def _surrogate(hs_lim: np.ndarray, cells: SeaCells) -> np.ndarray:
    """(candidate, tugger) surrogate from the limiting Hs (candidate, tugger, heading, tz)
    on the cells' headings and Tz. The sums run over contiguous rows, so each candidate's
    number is the same however many are scored together."""
    lim = hs_lim[:, :, None, :, None, :]                              # (c, t, leg, h, hs, tz)
    assessed, width = cells.hs[:, None, :, None], cells.width[:, None, :, None]
    share = ((lim - assessed) / width + 0.5).clip(0.0, 1.0)
    share[np.isnan(share)] = 0.0
    terms = np.ascontiguousarray(cells.weight * share)
    n_c, n_t, n_leg = terms.shape[:3]
    per_leg = terms.reshape(n_c * n_t * n_leg, -1).sum(-1).reshape(n_c, n_t, n_leg)
    return np.ascontiguousarray(per_leg * cells.leg_weight).reshape(n_c * n_t, n_leg).sum(-1).reshape(n_c, n_t)


def surrogate(hs_lim: xr.DataArray, sea: xr.Dataset, hs_in_bin="centre") -> xr.DataArray:
    """Route workability with each cell's pass flag replaced by the share of its Hs bin
    below ``hs_lim`` (candidate, tugger, heading, tz), centred on the assessed Hs."""
    hs_lim, sea = xr.align(hs_lim, sea, join="inner", exclude=("candidate", "tugger", "leg", "hs"))
    lim = hs_lim.transpose("candidate", "tugger", "heading", "tz")
    coords = {k: v for k, v in lim.coords.items() if set(v.dims) <= {"candidate", "tugger"}}
    return xr.DataArray(_surrogate(lim.values, SeaCells(sea, hs_in_bin)),
                        dims=("candidate", "tugger"), coords=coords)
