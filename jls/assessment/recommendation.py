"""The answer an engineer signs: which rigging and which tugger setting for the route.

* The *recommendation* is the combination (rigging candidate, tugger setting) with the
  highest objective (:func:`objective`: the route workability, or, ranked by the voyage
  plan, the probability that a voyage sailed by the departure rule stays inside every
  limit, its ties broken first by the shorter waits, :data:`PLAN_TIE_RULE`) among those no
  exclusion rule removes. Combinations whose
  route workability lies within the tie tolerance of it (``tie_tolerance``, a fraction
  of the route, an attribute of workability.nc from ``recommendation.tie_tolerance_pp``)
  are a tie, disclosed in the report and broken by :data:`TIE_RULE`: the larger smallest
  safety margin first (each margin relative to its limit, :func:`smallest_margin`), then
  fewer changes from the baseline (the baseline rigging before a changed one, no tugger
  before a tugger), then the lower tugger slope, then the names; no rule depends on the
  order of the configuration.
* :data:`EXCLUSION_RULES` is a list of rules ``(data, combos) -> {(candidate, tugger):
  reason}``, ``data`` holding the datasets by name ("plant", "workability", ...): an
  infeasible rigging candidate, winches that saturate, a tugger that does not earn its
  place (:func:`tugger_gain`: its gain over the best passive option is below
  ``tugger_min_gain`` or not positive in every uncertainty variant). :func:`exclusions`
  merges their reasons, which the report states. Adding a rule is appending a function.
  A reason is a :class:`Reason`: the sentence, a short label for a table column and what
  the label means (a plain string is taken as its own label).
"""

from __future__ import annotations

from typing import Callable

import numpy as np
import xarray as xr

INFEASIBLE = "infeasible rigging"   # the short label of an infeasible candidate's exclusion
TIE_RULE = ("the larger smallest safety margin first (each margin relative to its limit), "
            "then fewer changes from the baseline (the baseline rigging before a changed one, "
            "no tugger before a tugger), then the lower tugger slope, then the names")
#: plant.nc margin variable -> the plant attribute holding its limit (margins relative to it)
SAFETY_MARGINS = {"splash_clearance_margin": "splash_clearance_m",
                  "side_lead_margin": "side_lead_max_deg",
                  "fore_aft_lead_margin": "fore_aft_lead_max_deg",
                  "tension_margin": "max_tension_kN"}


#: ``recommendation.objective`` -> the workability.nc variable the options are ranked by
OBJECTIVES = {"workability": "workability_route", "voyage_exceedance": "voyage_inside_probability",
              "voyage_plan": "plan_inside_probability"}
#: the voyage plan's waits that break its ties, in order (workability.nc)
PLAN_WAITS = ("plan_wait_median_h", "plan_wait_p90_h")
PLAN_TIE_RULE = "the shorter median wait, then the shorter 90 % wait"


def effective_objective(work: xr.Dataset) -> str:
    """The objective the options are ranked by: the configuration's
    (``recommendation_objective``; none: workability), except that ``voyage_plan`` on a
    route without a departure simulation (no ``plan_inside_probability``: a leg without
    hourly records) ranks by workability, as the report states."""
    name = str(work.attrs.get("recommendation_objective", "workability"))
    return name if OBJECTIVES[name] in work else "workability"


def objective(work: xr.Dataset) -> xr.DataArray:
    """What the options are ranked by (candidate, tugger), higher is better: the route
    workability, the probability that the voyage stays inside every limit, or the
    probability that a voyage sailed by the departure rule does (one minus
    ``plan_exceedance_probability`` of voyage_plan.nc), as :func:`effective_objective`."""
    return work[OBJECTIVES[effective_objective(work)]]


def by_combination(da: xr.DataArray) -> dict:
    """{(candidate, tugger): float} of a (candidate, tugger) variable, read in one go: a
    ``.sel`` per combination cost the rules 13 s on a 10 000-candidate grid."""
    values = da.transpose("candidate", "tugger").values
    tugs = [str(t) for t in da["tugger"].values]
    return {(str(c), t): float(values[i, j]) for i, c in enumerate(da["candidate"].values)
            for j, t in enumerate(tugs)}


def tie_tolerance(work: xr.Dataset) -> float:
    """Route workabilities (fractions) closer than this are tied (workability.nc)."""
    return float(work.attrs["tie_tolerance"])


def smallest_margin(plant: xr.Dataset) -> dict:
    """Candidate -> its smallest safety margin relative to the constraint's limit
    (splash clearance over the required clearance, lead angles over their maxima, the
    static tension over its limit when one is set): 0 on a limit, 0.2 with a fifth of
    the limit to spare. Design-variable bounds are not safety margins."""
    parts = [np.asarray(plant[v].values, float) / float(plant.attrs[lim])
             for v, lim in SAFETY_MARGINS.items() if v in plant and lim in plant.attrs]
    cands = [str(c) for c in plant["candidate"].values]
    if not parts:
        return dict.fromkeys(cands, 0.0)
    return dict(zip(cands, np.min(parts, axis=0).tolist()))


class Reason(str):
    """Why a combination is excluded: the sentence (the string itself), a short label for
    a table column (``short``, e.g. "winch 1.1 %") and what such labels mean (``legend``,
    one sentence per rule that gave the reason)."""

    short: str
    legend: tuple

    def __new__(cls, text: str, short: str, legend=()):
        obj = super().__new__(cls, text)
        obj.short = short
        obj.legend = (legend,) if isinstance(legend, str) else tuple(legend)
        return obj

    def __reduce__(self):
        return (Reason, (str(self), self.short, self.legend))

    def __add__(self, other):
        """Both reasons, of two rules that exclude the same combination."""
        other = as_reason(other)
        return Reason(f"{self}; {other}", f"{self.short}, {other.short}",
                      self.legend + tuple(x for x in other.legend if x not in self.legend))


def as_reason(reason) -> Reason:
    return reason if isinstance(reason, Reason) else Reason(str(reason), str(reason))


def active_components(combo, baseline: str, c_tugger: dict) -> int:
    """Number of changes from the bare baseline: a changed rigging, a tugger."""
    return int(combo[0] != baseline) + int(c_tugger[combo[1]] > 0)


def tie_key(combo, baseline, c_tugger, margins: dict) -> tuple:
    """Sort key of :data:`TIE_RULE` (smallest first wins); ``margins``: candidate ->
    :func:`smallest_margin`."""
    return (-round(margins.get(combo[0], 0.0), 9), active_components(combo, baseline, c_tugger),
            c_tugger[combo[1]], str(combo[0]), str(combo[1]))


def best_with_ties(work: xr.Dataset, combos, baseline, c_tugger, margins: dict):
    """(best, tied others) among ``combos`` by the objective (:func:`objective`) within
    the tie tolerance and :data:`TIE_RULE`."""
    score = by_combination(objective(work))
    wr = {ct: score[ct] for ct in combos}
    top = max(wr.values())
    waits = ([by_combination(work[w]) for w in PLAN_WAITS] if effective_objective(work) == "voyage_plan"
             and all(w in work for w in PLAN_WAITS) else [])

    def key(ct):                   # the plan's waits first (unknown last), then the tie rule
        return (*(w[ct] if np.isfinite(w[ct]) else np.inf for w in waits),
                *tie_key(ct, baseline, c_tugger, margins))
    tied = sorted((ct for ct in combos if wr[ct] >= top - tie_tolerance(work)), key=key)
    return tied[0], tied[1:]


def infeasible_rigging(data: dict, combos) -> dict:
    """Exclusion rule: combinations whose rigging candidate is infeasible (``plant``'s
    ``feasible``), with the plant's ``infeasible_reason``."""
    plant = data["plant"]
    ok = dict(zip(plant["candidate"].values.tolist(), np.asarray(plant["feasible"].values).astype(bool)))
    why = dict(zip(plant["candidate"].values.tolist(), plant["infeasible_reason"].values.astype(str)))
    return {(c, tg): Reason(f"rigging {c} is not feasible: {why[c] or 'a constraint is violated'}",
                            INFEASIBLE)
            for c, tg in combos if not ok[c]}


#: Rules excluding combinations from the recommendation: (data, combos) -> {combo: reason},
#: data holding the report's datasets by name ("plant", "response", "workability", ...).
ExclusionRule = Callable[[dict, list], dict]
EXCLUSION_RULES: list[ExclusionRule] = [infeasible_rigging]


def exclusions(data: dict, combos, rules=None) -> dict:
    """{combo: :class:`Reason`} of the combinations some rule excludes (reasons of several
    rules joined with "; "); ``rules`` defaults to :data:`EXCLUSION_RULES`."""
    out: dict = {}
    for rule in (EXCLUSION_RULES if rules is None else rules):
        for combo, reason in rule(data, list(combos)).items():
            out[combo] = out[combo] + reason if combo in out else as_reason(reason)
    return out


def recommend(data: dict, cands, tugs, c_tugger: dict):
    """The recommendation among every (candidate, tugger) of ``cands`` x ``tugs``:
    (best, tied others, {excluded combination: reason}). The best is taken among the
    combinations no rule excludes, or among all of them when every one is excluded (the
    report then says so). The baseline is "baseline" when assessed, else the first
    candidate. Every stage that names "the" option (the report, the weather windows)
    takes it from here."""
    baseline = "baseline" if "baseline" in cands else cands[0]
    combos = [(c, t) for c in cands for t in tugs]
    excluded = exclusions(dict(data, c_tugger=c_tugger), combos)
    best, ties = best_with_ties(data["workability"], eligible(combos, excluded), baseline,
                                c_tugger, smallest_margin(data["plant"]))
    return best, ties, excluded


def eligible(combos, excluded: dict) -> list:
    """The combinations the recommendation is chosen among: those no rule excludes, or
    all of them when every one is excluded (the report then says so)."""
    return [ct for ct in combos if ct not in excluded] or list(combos)


# -- winch saturation -------------------------------------------------------------------
def winch_saturation(data: dict, combos) -> dict:
    """Exclusion rule: tugger settings whose winches saturate: at a force limit for more
    than ``max_saturation_fraction`` of the time in a time-domain cell, or, under the
    ``fail`` policy, flagged in the frequency domain in sea states carrying more than that
    fraction of the route (the share of the transit during which the winch cannot
    deliver). Needs workability.nc's saturation variables and attributes."""
    work = data["workability"]
    limit = float(work.attrs["max_saturation_fraction"])
    combos = set(combos)
    out = {}
    if "timedomain_limit_fraction" in work:
        for (c, tg), f in by_combination(work["timedomain_limit_fraction"]).items():
            if (c, tg) in combos and np.isfinite(f) and f > limit:
                out[(c, tg)] = Reason(
                    f"winches at a force limit {100 * f:.1f} % of the time in a time-domain "
                    f"cell (allowed: {100 * limit:g} %)", f"winch {100 * f:.1f}\u00a0% of time",
                    f"winch x\u00a0% of time: the winches are at a force limit x\u00a0% of the "
                    f"time in a time-domain cell, more than the {100 * limit:g}\u00a0% allowed")
    if work.attrs["winch_saturation"] == "fail":
        for (c, tg), f in by_combination(work["saturation_share_route"]).items():
            if (c, tg) in combos and f > limit and (c, tg) not in out:
                out[(c, tg)] = Reason(
                    f"winches saturate in the frequency domain in sea states carrying "
                    f"{100 * f:.1f} % of the route (allowed: {100 * limit:g} %); those "
                    "cells fail under the 'fail' policy", f"winch {100 * f:.1f}\u00a0%",
                    f"winch x\u00a0%: the winches saturate in the frequency domain in sea "
                    f"states carrying x\u00a0% of the route, more than the {100 * limit:g}\u00a0% "
                    "allowed, and those cells fail under the 'fail' policy")
    return out


EXCLUSION_RULES.append(winch_saturation)


def grid_without_timedomain(data: dict, combos) -> dict:
    """Exclusion rule: under the candidate-grid rule of the time-domain cells (workability
    attribute ``timedomain_grid_best`` = n > 0: only the n best of a candidate grid send
    their boundary cells, ``timedomain.grid_boundary_candidates``), the riggings whose
    boundary cells did not run, whose relative-sway verdicts are the frequency domain's
    alone (``timedomain_limit_fraction`` NaN for every tugger setting)."""
    work = data["workability"]
    n = int(work.attrs.get("timedomain_grid_best", 0))
    if not n or "timedomain_limit_fraction" not in work:
        return {}
    ran = {c for (c, _), f in by_combination(work["timedomain_limit_fraction"]).items() if np.isfinite(f)}
    if not ran:
        return {}
    return {(c, tg): Reason(
        f"rigging {c} is a grid candidate outside the {n} best by frequency-domain route "
        "workability, whose boundary cells did not run in the time domain", "no time domain",
        f"no time domain: a grid candidate outside the {n} best by frequency-domain route "
        "workability; its boundary cells did not run in the time domain "
        "(timedomain.grid_boundary_candidates)")
        for c, tg in combos if c not in ran}


EXCLUSION_RULES.append(grid_without_timedomain)


# -- a tugger earns its place ---------------------------------------------------------
def _pp(gain: float) -> str:
    """A workability gain in percentage points with its sign, '0.00' when it rounds to
    zero (a tugger that adds nothing neither adds nor takes)."""
    text = f"{100 * gain:+.2f}"
    return "0.00" if float(text) == 0 else text


def tugger_gain(data: dict, combos) -> dict:
    """Exclusion rule: a combination with an active tugger whose gain in route
    workability over the best passive option (no tugger, feasible rigging) is at most
    ``tugger_min_gain`` (workability.nc), or is not positive in every uncertainty
    variant (``workability_route_variant``: damping, sway frequency, Hs in the bin). A
    tugger needs winches, a control system and fairleads; it is recommended only where
    it clearly pays. ``data["c_tugger"]``: tugger setting -> slope (0 for none)."""
    work, c_tug = data["workability"], data["c_tugger"]
    min_gain = float(work.attrs["tugger_min_gain"])
    infeasible = infeasible_rigging(data, combos)
    passive = [ct for ct in combos if c_tug[ct[1]] <= 0 and ct not in infeasible]
    if not passive:
        return {}
    score = objective(work)
    wr = by_combination(score)
    best_p = max(passive, key=lambda ct: wr[ct])
    base = wr[best_p]
    # the uncertainty variants are of the route workability
    variant = (work.get("workability_route_variant") if score.name == "workability_route" else None)
    if variant is not None:
        dims = [d for d in variant.dims if d not in ("candidate", "tugger")]
        variant = variant.transpose("candidate", "tugger", *dims)
        variant = variant.stack(v=dims) if dims else variant.expand_dims(v=[0], axis=-1)
        row = {str(c): i for i, c in enumerate(variant["candidate"].values)}
        col = {str(t): j for j, t in enumerate(variant["tugger"].values)}
        v_all = variant.values                                   # (candidate, tugger, variant)
        theirs = v_all[row[best_p[0]], col[best_p[1]]]
        label = [", ".join(f"{d} {variant[d].values[k]}" for d in dims) for k in range(variant.sizes["v"])]
    out = {}
    for c, tg in combos:
        if c_tug[tg] <= 0:
            continue
        gain = wr[(c, tg)] - base
        where = f"{best_p[0]} rigging without tugger"
        legend = (f"tugger +x\u00a0pp: the tugger adds x percentage points of route "
                  f"workability over the best passive option, not more than the "
                  f"{100 * min_gain:g} required for the hardware it needs")
        if gain <= min_gain:
            out[(c, tg)] = Reason(
                f"tugger {tg} adds {_pp(gain)} percentage points over the best passive "
                f"option ({where}); more than {100 * min_gain:g} are required for the winches, "
                "controls and fairleads it needs", f"tugger {_pp(gain)}\u00a0pp", legend)
            continue
        if variant is not None:
            mine = v_all[row[c], col[tg]]
            worst = mine - theirs
            if np.isnan(worst).all():
                # a large grid varies only the shown candidates (bands): unjudged, not robust
                unvaried = " and ".join(dict.fromkeys(
                    f"{cand} rigging" for cand, v in ((c, mine), (best_p[0], theirs))
                    if np.isnan(v).all()))
                out[(c, tg)] = Reason(
                    f"tugger {tg}: whether its gain over the best passive option ({where}) holds in "
                    f"the uncertainty variants is not known, the {unvaried} having no variants "
                    "(a candidate grid's variants are those of the shown candidates)",
                    "tugger robustness not assessed",
                    "tugger robustness not assessed: the uncertainty variants of the option or "
                    "of the best passive option were not computed")
                continue
            k = int(np.nanargmin(worst))
            if float(worst[k]) <= 0:
                which = label[k]
                out[(c, tg)] = Reason(
                    f"tugger {tg} adds {_pp(float(worst[k]))} percentage points over the "
                    f"best passive option ({where}) in the uncertainty variant {which}: its "
                    "gain is not robust", "tugger not robust",
                    "tugger not robust: in some uncertainty variant the tugger adds nothing "
                    "over the best passive option")
    return out


EXCLUSION_RULES.append(tugger_gain)
