"""Rigging screening and optimisation for one route (chapter 5).

Three steps, all on the reduced-order model:

1. **Sensitivity** (figure 5.3): the four natural periods against each design variable,
   one at a time about the baseline, with the feasible range of each
   (:mod:`jls.design.sensitivity`).
2. **Screening** (figure 5.4): a full-factorial grid over the screened variables
   (default 21 x 21 over top spread Y and drop height, the others at the baseline),
   every candidate checked for feasibility (:mod:`jls.plant.feasibility`) and scored
   (:mod:`jls.design.scoring`) on the study's screening envelope and on the route's
   workability, for every tugger setting. Candidates are evaluated in chunks; each
   candidate's numbers depend on it alone, so chunking changes nothing but memory.
3. **Refinement** from the best feasible grid point with a constrained optimiser
   (:mod:`jls.design.optimise`). The route workability is piecewise constant in the design,
   so the optimiser follows its continuous surrogate and the result is confirmed on
   the workability itself; a refined design that is infeasible or worse than the best
   feasible grid point is discarded for that grid point. Which constraints are active
   at the optimum is reported, with its relative roll and yaw MPM beside the baseline's
   (section 5.7.3: detuning can worsen roll unseen); configured limits on those MPMs
   are constraints. Each design the optimiser tries is built and scored once, as
   arrays (:class:`jls.design.scoring.PointScorer`), with the numbers of the datasets.

:func:`screening_dataset` returns the dataset written as ``results/<route>/screening.nc``.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, replace

import numpy as np
import xarray as xr

from jls.design.optimise import refine
from jls.design.scoring import (
    MomentSettings,
    PointScorer,
    Scoring,
    candidate_moments,
    score,
    screening_states,
)
from jls.design.sensitivity import sensitivity
from jls.errors import InputError
from jls.io import registry
from jls.names import RELATIVE_ROLL, RELATIVE_SWAY, RELATIVE_YAW, RESPONSES, ROLL_DEG, YAW_DEG
from jls.plant import equilibrium
from jls.plant.candidates import Rigging, candidate_plants, plant_dataset
from jls.plant.rigging import DESIGN_VARIABLES, design_variables

SUFFIX = "_m"
#: keys of the ``screening`` section read by the workflow or the scoring, not by Settings
WORKFLOW_KEYS = ("envelope", "enabled", "chunk_candidates", "design_hs_m", "margin_sweep_m")
ROTATIONAL = {ROLL_DEG: RELATIVE_ROLL, YAW_DEG: RELATIVE_YAW}
PLANT_VARS = ("feasible", "infeasible_reason", "at_limit", "natural_period", "dominant_dof",
              "tension", "anchor", "padeye", "cog_depth", "side_lead_margin",
              "fore_aft_lead_margin", "splash_clearance_margin", *DESIGN_VARIABLES)


@dataclass(frozen=True)
class Settings:
    """The configuration's ``screening`` section (see the schema for each key; built by
    :func:`jls.config.builders.screening_settings_from_config`)."""

    grid_points: dict
    objective: str
    tugger: str | None
    constraints: dict
    sensitivity_points: int
    chunk_size: int
    tolerance_m: float
    max_evaluations: int


def _tugger(settings: Settings, scoring: Scoring) -> str:
    return settings.tugger or next(iter(scoring.tuggers))


def screened_axes(rig: Rigging, grid_points: dict) -> dict[str, np.ndarray]:
    """The grid's values per screened design variable; a variable without bounds in
    ``rigging.design_space``, or not free, is an InputError (the one check, also run when
    the configuration is validated)."""
    axes = {}
    for var, n in grid_points.items():
        if var not in rig.design_space or var in rig.fixed:
            raise InputError("a screened variable needs bounds in rigging.design_space and must be free",
                             field=f"screening.grid_points.{var}{SUFFIX}")
        axes[var] = np.linspace(*rig.design_space[var], int(n))
    return axes


def grid_values(rig: Rigging, grid_points: dict) -> dict[str, dict]:
    """Name -> design values of the grid candidates, variables outside the grid at the
    baseline; names ``grid_0000`` ... in C order of the screened variables."""
    axes = screened_axes(rig, grid_points)
    combos = itertools.product(*axes.values())
    return {f"grid_{i:04d}": dict(zip(axes, map(float, c))) for i, c in enumerate(combos)}


def evaluate(rig: Rigging, values: dict[str, dict], motion, sea, scoring: Scoring,
             settings: Settings, chunk_size: int | None = None, *, moments=None,
             threads=None) -> xr.Dataset:
    """Feasibility, periods, geometry and scores of candidates.

    The plant of every candidate is built at once (cheap); the spectral moments are
    computed ``chunk_size`` candidates at a time on one frequency grid refined around
    every candidate's modes (:func:`jls.design.scoring.candidate_moments`), so the result does
    not depend on the chunking. ``moments``: (m0, m2) of all candidates already computed
    (the workflow's chunk jobs, :func:`chunk_moments`). Configured limits on the
    rotational MPMs make a candidate infeasible too.
    """
    plant, _ = plant_dataset(rig, values)
    if moments is None:
        tz, headings = screening_states(sea, scoring)
        moments = chunk_moments(plant, motion, tz, headings, scoring, slice(None), chunk_size,
                                threads=threads)
    scores = score(plant, motion, sea, scoring, moments=moments)
    ds = xr.merge([plant[list(PLANT_VARS)], scores], compat="override", join="exact")
    return _rotational_constraints(ds, settings, _tugger(settings, scoring), rig.limits.at_limit_tolerance_deg)


def chunk_moments(plant: xr.Dataset, motion, tz, headings, scoring: MomentSettings | Scoring,
                  candidates=slice(None), chunk_size: int | None = None, *, cache=None,
                  threads=None, counter=None):
    """Moments (m0, m2) of the candidates ``candidates`` of the full screening ``plant``
    on the sorted ``tz`` and ``headings`` (:func:`jls.design.scoring.screening_states`),
    ``chunk_size`` at a time (bounded memory); see :func:`jls.design.scoring.candidate_moments`."""
    start, stop, _ = candidates.indices(plant.sizes["candidate"])
    size = int(chunk_size or (stop - start) or 1)
    parts = [candidate_moments(plant, motion, tz, headings, scoring, candidates=slice(a, min(a + size, stop)),
                               cache=cache, threads=threads, counter=counter)
             for a in range(start, stop, size)]
    if not parts:
        shape = (0, len(scoring.tuggers), len(headings), 4, len(tz))
        return np.empty(shape), np.empty(shape)
    return tuple(np.concatenate([p[k] for p in parts], axis=0) for k in (0, 1))


def screening_values(rig: Rigging, grid_points: dict) -> dict[str, dict]:
    """Name -> design values of the screened candidates: ``baseline`` then the grid
    (``grid_points``: points per design variable, :attr:`Settings.grid_points`)."""
    return {"baseline": {}, **grid_values(rig, grid_points)}


def _rotational_constraints(ds, settings, tugger, tol):
    if not settings.constraints:
        return ds
    reason, at = ds["infeasible_reason"].values.astype(object), ds["at_limit"].values.astype(object)
    feasible = ds["feasible"].values.copy()
    for key, limit in settings.constraints.items():
        mpm = ds["screening_mpm"].sel(tugger=tugger, response=ROTATIONAL[key]).values
        label = ROTATIONAL[key].replace("_", " ")
        for i, m in enumerate(mpm):
            if not np.isfinite(m):
                continue
            if m > limit + tol:
                feasible[i] = False
                reason[i] = "; ".join(filter(None, [reason[i], f"{label} MPM {m:.2f} deg above {limit:g} deg"]))
            elif m >= limit - tol:
                phrase = f"{label} MPM {m:.2f} deg"
                at[i] = f"{at[i]}; {phrase}" if at[i] else f"at limit: {phrase}"
    out = ds.copy()
    out["feasible"] = ("candidate", feasible)
    out["infeasible_reason"] = ("candidate", reason.astype(str))
    out["at_limit"] = ("candidate", at.astype(str))
    for name in ("feasible", "infeasible_reason", "at_limit"):
        out[name].attrs = ds[name].attrs
    return out


#: objective -> (the smooth variable the refinement follows, the sign that makes higher better)
FOLLOWED = {"route_workability": ("workability_surrogate", 1.0),
            "screening_sigma": ("screening_sigma", -1.0)}


def _followed(objective: str) -> tuple[str, float]:
    if objective not in FOLLOWED:
        raise ValueError(f"unknown objective {objective!r}")
    return FOLLOWED[objective]


def objective_values(ds: xr.Dataset, objective: str, tugger: str):
    """(score, surrogate) per candidate, higher is better."""
    name, sign = _followed(objective)
    return sign * ds[objective].sel(tugger=tugger).values, sign * ds[name].sel(tugger=tugger).values


def best_feasible(ds: xr.Dataset, objective: str, tugger: str) -> int | None:
    """Index of the best feasible candidate: highest score, then highest surrogate."""
    obj, sur = objective_values(ds, objective, tugger)
    ok = ds["feasible"].values.astype(bool) & np.isfinite(obj)
    if not ok.any():
        return None
    idx = np.flatnonzero(ok)
    order = np.lexsort((-sur[idx], -obj[idx]))
    return int(idx[order[0]])


def _refine(rig, start: dict, variables, motion, sea, scoring, settings, *, counter=None):
    """Run :func:`jls.design.optimise.refine` on the surrogate from ``start``. Only the
    objective's tugger setting is solved along the way (the refined design is then
    evaluated with every setting). Each design is built and scored once, as arrays
    (:func:`jls.plant.candidates.candidate_plants`, :class:`jls.design.scoring.PointScorer`: the
    numbers of the datasets, without them); ``counter``: a list to which every design
    evaluated is appended."""
    tugger = _tugger(settings, scoring)
    scorer = PointScorer(motion, sea, replace(scoring, tuggers={tugger: scoring.tuggers[tugger]}))
    rotational = {key: RESPONSES.index(ROTATIONAL[key]) for key in settings.constraints}
    cache = {}

    def point(x):
        key = tuple(np.round(x, 10))
        if key not in cache:
            vals = dict(start, **dict(zip(variables, map(float, x))))
            p, _, fz = candidate_plants(rig, {"trial": vals})
            cache[key] = (p, fz, scorer(p))
            if counter is not None:
                counter.append(vals)
        return cache[key]

    followed, sign = _followed(settings.objective)

    def objective(x):                              # minimised
        return -sign * float(point(x)[2][followed][0])

    def margins(x):                                # each constraint tightened by its budget
        p, fz, sc = point(x)
        weight = p.m_grav * p.g
        g = [fz.spare("side_lead_margin_deg")[0], fz.spare("fore_aft_lead_margin_deg")[0],
             fz.spare("splash_clearance_margin_m")[0],
             float(np.nanmin(p.tension[0])) / weight - equilibrium.SLACK_FRACTION,
             equilibrium.RESIDUAL_LIMIT - float(np.nanmax(np.abs(p.residual[0])))]
        if "tension_margin_kN" in fz.margins:
            g.append(fz.spare("tension_margin_kN")[0])
        for key, limit in settings.constraints.items():
            g.append(limit - float(sc["screening_mpm"][0, rotational[key]]))
        return np.array([float(v) for v in g])

    lower = [rig.design_space[v][0] for v in variables]
    upper = [rig.design_space[v][1] for v in variables]
    x0 = [start[v] for v in variables]
    return refine(objective, margins, x0, lower, upper, tolerance=settings.tolerance_m,
                  max_evaluations=settings.max_evaluations)


def refined_design(x, tolerance_m: float) -> np.ndarray:
    """The refinement's end point to 1e-4 of its tolerance (1 um at 0.01 m): an optimum on
    the curved side-lead constraint is reached only to round-off, and a rerun that moves
    nothing must write the same design (and the assessed plant the same bytes)."""
    q = 1e-4 * float(tolerance_m)
    return np.round(np.asarray(x, float) / q) * q


def screening_dataset(rig: Rigging, motion: xr.Dataset, sea: xr.Dataset, scoring: Scoring,
                      settings: Settings, *, chunk_size: int | None = None,
                      refine_optimum: bool = True, moments=None, threads=None) -> xr.Dataset:
    """The screening dataset of a route (see the module docstring).

    Candidates: ``baseline``, the grid (``grid_0000`` ...) and, when the refinement
    succeeds, ``refined``; global attribute ``optimum_candidate`` names the candidate
    carried forward as "optimised". ``moments``: (m0, m2) of the baseline and the grid
    (:func:`screening_values`) computed beforehand, by the workflow's chunk jobs.
    """
    tugger = _tugger(settings, scoring)
    base = {k: float(v) for k, v in design_variables(rig.layout).items()}
    values = screening_values(rig, settings.grid_points)
    ds = evaluate(rig, values, motion, sea, scoring, settings, chunk_size or settings.chunk_size,
                  moments=moments, threads=threads)
    kind = ["baseline"] + ["grid"] * (len(values) - 1)
    grid = ds.isel(candidate=slice(1, None))
    i_best = best_feasible(grid, settings.objective, tugger)
    variables = list(settings.grid_points)
    status, optimum, evaluations = "no feasible grid point", None, 0
    if i_best is not None:
        best_name = str(grid["candidate"][i_best].values)
        optimum, status = best_name, "best grid point (refinement not run)"
        if refine_optimum:
            start = {v: float(grid[v][i_best]) for v in DESIGN_VARIABLES}
            r = _refine(rig, start, variables, motion, sea, scoring, settings)
            evaluations = r.evaluations
            x = refined_design(r.x, settings.tolerance_m)
            refined = evaluate(rig, {"refined": dict(start, **dict(zip(variables, map(float, x))))},
                               motion, sea, scoring, settings)
            ds = xr.concat([ds, refined], "candidate", data_vars="all", coords="different",
                           compat="equals")
            kind.append("refined")
            obj, sur = objective_values(ds, settings.objective, tugger)
            j, k = ds.sizes["candidate"] - 1, i_best + 1
            better = obj[j] > obj[k] or (obj[j] == obj[k] and sur[j] >= sur[k])
            if bool(ds["feasible"].values[j]) and better:
                optimum, status = "refined", f"refined from {best_name}: {r.message}"
            else:
                status = (f"refinement from {best_name} ended at a design that is "
                          f"{'worse' if ds['feasible'].values[j] else 'infeasible'}; "
                          f"the best grid point is kept ({r.message})")
    ds["kind"] = ("candidate", np.array(kind))
    ds = xr.merge([ds, sensitivity(rig, settings.sensitivity_points)])
    ds.attrs.update(_optimum_attrs(ds, optimum, tugger))
    ds.attrs.update(objective=settings.objective, objective_tugger=tugger,
                    grid_variables=" ".join(variables), refinement=status,
                    refinement_evaluations=evaluations,
                    fixed_variables=" ".join(rig.fixed),
                    hinge_height_m=rig.limits.hinge_height_m,
                    padeye_to_tip_m=rig.limits.padeye_to_tip_m,
                    splash_clearance_m=rig.limits.splash_clearance_m,
                    splash_clearance_budget_m=rig.limits.budget.splash,
                    splash_clearance_budget=rig.limits.budget.describe("splash"),
                    baseline_values_m=[base[v] for v in DESIGN_VARIABLES])
    return registry.annotate(ds, "screening")


def _optimum_attrs(ds, optimum, tugger) -> dict:
    """The optimum's design, active constraints and MPMs beside the baseline's."""
    shown = [("baseline", ds.sel(candidate="baseline"))]
    out = {"optimum_candidate": optimum or "", "active_constraints": "", "optimum_on_constraint": 0}
    if optimum is not None:
        o = ds.sel(candidate=optimum)
        shown.append(("optimum", o))
        out.update({f"optimum_{v}_m": float(o[v]) for v in DESIGN_VARIABLES})
        active = str(o["at_limit"].values).removeprefix("at limit: ")
        out["active_constraints"] = active or "none"
        out["optimum_on_constraint"] = int(bool(active))
    for who, c in shown:
        for resp, unit in ((RELATIVE_ROLL, "deg"), (RELATIVE_YAW, "deg"), (RELATIVE_SWAY, "m")):
            out[f"{who}_{resp}_mpm_{unit}"] = float(c["screening_mpm"].sel(tugger=tugger, response=resp))
    return out


def optimised_values(ds: xr.Dataset, file=None) -> dict[str, float]:
    """Design values of the candidate a screening dataset carries forward as "optimised"
    (its attribute ``optimum_candidate``); InputError when the screening found none."""
    name = str(ds.attrs.get("optimum_candidate", ""))
    if not name:
        raise InputError("the screening found no feasible candidate to carry forward as "
                         "'optimised'; widen rigging.design_space or set screening.enabled: false",
                         file=file, field="optimum_candidate", value=ds.attrs.get("refinement"))
    o = ds.sel(candidate=name)
    return {v: float(o[v]) for v in DESIGN_VARIABLES}
