"""What every chapter reads: the :class:`Context` (datasets, digest, provenance, figure
files) and the small text helpers several chapters share.

A chapter module (:mod:`jls.report.chapters`) takes a Context and returns Typst markup;
it imports what it shares with other chapters from here (and from the other shared
modules), not from another chapter, so the chapters form no cycle.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from jls.assessment import recommendation
from jls.names import TIP_AIR_GAP_M, WIRE_TENSION_CRITERION
from jls.plant import same_rigging
from jls.report.contract import Digest, criterion_label, flag, limit_text
from jls.report.markup import ref, t


@dataclass
class Context:
    sea: xr.Dataset
    vessel: xr.Dataset
    plant: xr.Dataset
    resp: xr.Dataset
    work: xr.Dataset
    prov: dict
    dg: Digest
    figs: dict
    windows: xr.Dataset | None = None      # weather_windows.nc when the route has hindcast legs
    screening: xr.Dataset | None = None     # screening.nc when the route was screened
    td: list = field(default_factory=list)          # time-domain cell datasets
    td_cells: list = field(default_factory=list)    # the chosen cells and why
    studies: xr.Dataset | None = None               # decay tests and slope sweep
    verification: list = field(default_factory=list)  # verification cell datasets
    voyage: xr.Dataset | None = None                # voyage.nc: the voyage extremes
    plan: xr.Dataset | None = None                  # voyage_plan.nc: the voyage as it will be sailed
    measured: xr.Dataset | None = None              # measured_response.nc: the spectra legs
    sections: frozenset | None = None               # chapters with a heading (None: work them out)
    verification_study: xr.Dataset | None = None    # verification_study.nc: the study's table 4.4 beside ours
    verification_wires: list = field(default_factory=list)  # verification/wires/<cell>.nc: the wire checks

    @property
    def legs(self) -> list[str]:
        return [str(v) for v in self.sea["leg"].values]

    def w_route(self, combo) -> float:
        return float(self.work["workability_route"].sel(candidate=combo[0], tugger=combo[1]))

    def w_leg(self, combo, leg) -> float:
        return float(self.work["workability_leg"].sel(candidate=combo[0], tugger=combo[1], leg=leg))

    def c_tugger(self, tug) -> float:
        return float(self.resp["c_tugger"].sel(tugger=tug))

    def has(self, key: str) -> bool:
        """Whether the chapter ``key`` (its module's name) has a heading in this report."""
        if self.sections is None:    # the document sets them; a bare Context (tests) assumes
            return key != "rigging" or screened(self)    # every chapter but an unscreened rigging
        return key in self.sections

    def sec(self, key: str, word: str | None = "section") -> str:
        """Markup of a reference to the chapter ``key`` ('section 13'; ``word`` None: '13'),
        numbered by Typst (:func:`jls.report.markup.ref`); the chapter must be present
        (:meth:`has`)."""
        if not self.has(key):
            raise KeyError(f"the report has no chapter {key!r} to refer to")
        return ref(section_label(key), word)

    def secs(self, *keys: str) -> str:
        """'sections 7 and 8' (or 'sections 7, 8 and 11') for chapters ``keys``."""
        nums = [self.sec(k, None) for k in keys]
        return "sections " + (", ".join(nums[:-1]) + " and " + nums[-1] if len(nums) > 1 else nums[0])

    def feasible(self, cand) -> bool:
        if "_feasible" not in self.__dict__:
            f = flag(self.plant["feasible"])
            self.__dict__["_feasible"] = dict(zip(map(str, f["candidate"].values), map(bool, f.values)))
        return self._feasible[str(cand)]


def governing_heading(cx: "Context") -> float:
    """The assessed heading where the baseline rigging without tugger is least workable:
    the lowest mean limiting Hs over the operability curve (the first such heading on a
    tie). The heading every drawn comparison is drawn at."""
    w, dg = cx.work, cx.dg
    curve = w["hs_limit_curve"] if "hs_limit_curve" in w else w["hs_limit"]
    c = curve.sel(candidate=dg.baseline, tugger=dg.no_tugger)
    mean = c.mean([d for d in c.dims if d != "heading"])
    return float(mean["heading"].values[int(np.nanargmin(mean.values))])


def screened(cx: "Context") -> bool:
    """Whether the route was screened and its optimum assessed as the candidate
    "optimised": the chapter "Rigging" has something to show."""
    s = cx.screening
    return (s is not None and bool(s.attrs.get("optimum_candidate"))
            and same_rigging.alias(cx.work, "optimised") is not None)


def section_label(key: str) -> str:
    """The Typst label of the chapter ``key`` (the chapter module's name)."""
    return f"sec-{key.replace('_', '-')}"


def heading(key: str, title: str, level: int = 1) -> str:
    """A chapter (or, ``level`` 2, section) heading with its label, so that other text
    refers to it by :meth:`Context.sec` / :func:`jls.report.markup.ref` and never by a
    number written by hand."""
    return f"{'=' * level} {t(title)} <{section_label(key)}>\n"


def criteria_text(dg: Digest) -> str:
    def one(c):
        if c == TIP_AIR_GAP_M:
            return f"tip clearance above the MPM wave surface ≥ {limit_text(dg, c)}"
        if c == WIRE_TENSION_CRITERION:
            return f"lowest hoist-wire tension above {limit_text(dg, c)} (no slack)"
        return f"{criterion_label(c)} MPM ≤ {limit_text(dg, c)}"
    return ", ".join(one(c) for c in dg.criteria)


def combo_text(combo) -> str:
    return f"{combo[0]} rigging, tugger {combo[1]}"


def representative(desc: str) -> bool:
    return "representative" in str(desc).lower()


def feasibility_text(dg: Digest, cand: str, short=False) -> str:
    """'yes', 'yes, at limit (...)' or 'NO (...)' for a rigging candidate; ``short``
    leaves out the details (the plant chapter has them)."""
    if dg.infeasible.get(cand):
        return "NO" if short else f"NO ({dg.infeasible[cand]})"
    if dg.at_limit.get(cand):
        return "at limit" if short else f"yes, {dg.at_limit[cand]}"
    return "yes"


def eligible(cx: Context) -> list:
    """The combinations the recommendation is chosen among: those no exclusion rule
    removes (an infeasible rigging, saturating winches; :mod:`jls.assessment.recommendation`), or
    all of them when every one is excluded, as the recommendation itself."""
    return recommendation.eligible(cx.dg.combos, cx.dg.excluded)


def at_limit_rule(plant: xr.Dataset) -> str:
    """The at-limit rule with the tolerance budgets and resolutions the plant was judged with."""
    a = plant.attrs
    return ("a candidate whose splash clearance or lead-angle margin is inside its tolerance budget "
            f"(splash clearance {float(a.get('splash_clearance_budget_m', 0.0)):.2f} m, lead angles "
            f"{float(a.get('lead_angle_budget_deg', 0.0)):.2f}°) is infeasible; at limit: feasible with a "
            "margin equal to its budget, or a design variable on its bound, within the numerical "
            f"resolution (lengths {float(a['at_limit_tolerance_m']):g} m, angles "
            f"{float(a['at_limit_tolerance_deg']):g}°, tensions {float(a['at_limit_tolerance_kN']):g} kN)")


def budget_text(plant: xr.Dataset) -> str:
    """The tolerance budgets in one sentence (plant attribute ``tolerance_budget``)."""
    text = str(plant.attrs.get("tolerance_budget", ""))
    return (f"Each safety constraint keeps a tolerance budget beyond its limit, its components "
            f"added: {text}.") if text else ""


__all__ = ["Context", "at_limit_rule", "budget_text", "combo_text", "criteria_text", "eligible",
           "feasibility_text", "heading", "representative", "screened", "section_label"]
