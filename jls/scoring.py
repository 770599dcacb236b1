"""Scores of rigging candidates against one route: the screening envelope of section
5.4 and the route's workability, per tugger setting.

* ``screening_sigma``: the study's screening score (section 5.4, figure 5.4), the worst
  relative-sway standard deviation over the envelope Hs = 2.5 m, Tz 5.5-8.5 s, at the
  envelope's heading (beam seas by default). ``screening_mpm`` is the worst three-hour
  MPM of every relative motion over the same envelope (section 5.7.3: roll and yaw are
  reported beside sway and may be constrained).
* ``route_workability``: the duration-weighted workable fraction of the route
  (:func:`jls.stages.workability.assess`), piecewise constant in the design variables.
* ``workability_surrogate``: the same sum with each cell's pass flag replaced by the
  share of its Hs bin below the limiting Hs, ``clip((Hs_lim - Hs_assessed) / dHs + 1/2,
  0, 1)``: continuous in the design variables, so an optimiser can follow it, and equal
  to the workability wherever no limiting Hs lies within half a bin of an assessed Hs.

Only candidates whose plant exists (taut, stable, finite matrices) are scored; the
others carry NaN. All frequency-domain work goes through :func:`candidate_moments`: one
solver call for all candidates of a plant dataset, cost linear in candidates.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from jls.coverage import check_coverage
from jls.frequency_domain import RESPONSES, ROTATIONAL
from jls.stages.response import excitation, statistics_dataset, unit_moments
from jls.stages.workability import assess, assessed_hs, criteria_array

SWAY = "relative_sway"
_COVERED: set = set()          # sea-state sets whose RAO coverage was checked
ANGLES = {r for r, rotational in zip(RESPONSES, ROTATIONAL) if rotational}


@dataclass(frozen=True)
class Envelope:
    """Screening envelope: constant Hs over a Tz band at one heading (section 5.4)."""

    hs_m: float = 2.5
    tz_min_s: float = 5.5
    tz_max_s: float = 8.5
    tz_step_s: float = 0.25
    heading_deg: float = 90.0

    def tz(self) -> np.ndarray:
        """Tz from the shortest in steps, the longest always included [s]."""
        n = int(np.floor((self.tz_max_s - self.tz_min_s) / self.tz_step_s + 1e-9))
        tz = np.round(self.tz_min_s + self.tz_step_s * np.arange(n + 1), 9)
        return tz if tz[-1] >= self.tz_max_s - 1e-9 else np.append(tz, self.tz_max_s)


@dataclass(frozen=True)
class Scoring:
    """Everything the scores depend on besides the candidates."""

    tuggers: dict
    criteria: dict
    envelope: Envelope = field(default_factory=Envelope)
    gamma: float = 3.3
    exposure_h: float = 3.0
    cycles: str = "response"
    omega_step: float = 0.002
    outside_policy: dict | None = None     # vessel.outside_rao_range (jls.coverage)
    hs_in_bin: str = "centre"
    steepness_rule: str = "study"

    @classmethod
    def from_config(cls, cfg: dict) -> "Scoring":
        """From a validated configuration (schema defaults filled)."""
        a, s = cfg["assessment"], cfg["sea"]
        tuggers = {t["name"]: float(t["c_kN_s_per_m"]) for t in cfg["tuggers"]}
        return cls(tuggers=tuggers, criteria=a["criteria"], envelope=Envelope(**cfg["screening"]["envelope"]),
                   gamma=s["gamma"], exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                   omega_step=cfg["response"]["omega_step_rad_s"],
                   outside_policy=cfg["vessel"].get("outside_rao_range"), hs_in_bin=s["hs_in_bin"],
                   steepness_rule=s["steepness_rule"])


def screening_states(sea: xr.Dataset, sc: Scoring) -> tuple[list, list]:
    """(Tz, headings) the scores need, sorted: the route's and the envelope's."""
    env = sc.envelope
    headings = sorted({float(h) for h in sea["heading"].values} | {float(env.heading_deg)})
    tz = sorted({float(t) for t in sea["tz"].values} | {float(t) for t in env.tz()})
    return tz, headings


def candidate_moments(plant: xr.Dataset, motion: xr.Dataset, tz, headings, sc: Scoring, *,
                      candidates=slice(None), cache=None, threads=None, counter=None):
    """Unit-Hs spectral moments (m0, m2), (n_c, n_t, n_h, 4, n_tz), of the candidates
    ``candidates`` (a slice of the plant's candidate axis), from one call into the
    frequency-domain solver.

    The frequency grid is refined around the modes of *every* candidate of ``plant``,
    whichever slice is computed, and the solver works in blocks aligned to the global
    candidate index (:data:`jls.stages.response.BLOCK`): a slice's numbers are identical
    to those of the same candidates in an unsliced call, so candidates can be split over
    jobs. Candidates without a plant (NaN matrices) come out NaN. ``cache``: a sea-state
    cache directory; ``counter``: a list to which the number of (Tz, heading) sea states
    evaluated (not read from the cache) is appended.
    """
    lo, hi = float(motion["omega"].min()), float(motion["omega"].max())
    key = (lo, hi, tuple(np.round(np.asarray(tz, float), 9)), float(sc.gamma), repr(sc.outside_policy))
    if key not in _COVERED:                        # refinement calls this per design
        check_coverage(lo, hi, tz, sc.gamma, sc.outside_policy, "the vessel RAOs")
        _COVERED.add(key)
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
        out["workability_surrogate"][ok] = surrogate(hs_lim, sea, sc.hs_in_bin).transpose(
            "candidate", "tugger").values
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


def surrogate(hs_lim: xr.DataArray, sea: xr.Dataset, hs_in_bin="centre") -> xr.DataArray:
    """Route workability with each cell's pass flag replaced by the share of its Hs bin
    below ``hs_lim`` (candidate, tugger, heading, tz), centred on the assessed Hs."""
    width = (sea["hs_upper"] - sea["hs_lower"]).fillna(1.0)
    share = ((hs_lim - assessed_hs(sea, hs_in_bin)) / width + 0.5).clip(0.0, 1.0)
    weight = (sea["probability"] * sea["heading_probability"]).fillna(0.0)
    per_leg = (weight * share.fillna(0.0)).sum(("heading", "hs", "tz"))
    return (per_leg * sea["leg_weight"]).sum("leg")
