"""What every chapter reads: the :class:`Context` (datasets, digest, provenance, figure
files) and the small text helpers several chapters share.

A chapter module (:mod:`jls.report.chapters`) takes a Context and returns Typst markup;
it imports what it shares with other chapters from here (and from the other shared
modules), not from another chapter, so the chapters form no cycle.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import xarray as xr

from jls.assessment import recommendation
from jls.names import TIP_AIR_GAP_M
from jls.report.contract import Digest, criterion_label, flag, limit_text


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

    @property
    def legs(self) -> list[str]:
        return [str(v) for v in self.sea["leg"].values]

    def w_route(self, combo) -> float:
        return float(self.work["workability_route"].sel(candidate=combo[0], tugger=combo[1]))

    def w_leg(self, combo, leg) -> float:
        return float(self.work["workability_leg"].sel(candidate=combo[0], tugger=combo[1], leg=leg))

    def c_tugger(self, tug) -> float:
        return float(self.resp["c_tugger"].sel(tugger=tug))

    def feasible(self, cand) -> bool:
        if "_feasible" not in self.__dict__:
            f = flag(self.plant["feasible"])
            self.__dict__["_feasible"] = dict(zip(map(str, f["candidate"].values), map(bool, f.values)))
        return self._feasible[str(cand)]


def criteria_text(dg: Digest) -> str:
    return ", ".join(f"tip clearance above the MPM wave surface ≥ {limit_text(dg, c)}" if c == TIP_AIR_GAP_M
                     else f"{criterion_label(c)} MPM ≤ {limit_text(dg, c)}" for c in dg.criteria)


def combo_text(combo) -> str:
    return f"{combo[0]} rigging, tugger {combo[1]}"


def representative(desc: str) -> bool:
    return "representative" in str(desc).lower()


def feasibility_text(dg: Digest, cand: str, short=False) -> str:
    """'yes', 'yes, at limit (...)' or 'NO (...)' for a rigging candidate; ``short``
    leaves out the details (section 3 has them)."""
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
    """The at-limit rule with the tolerances the plant was judged with."""
    a = plant.attrs
    return ("at limit: feasible, but a constraint margin is within its tolerance of zero "
            f"(lengths {float(a['at_limit_tolerance_m']):g} m, angles "
            f"{float(a['at_limit_tolerance_deg']):g}°, tensions {float(a['at_limit_tolerance_kN']):g} kN)")


__all__ = ["Context", "at_limit_rule", "combo_text", "criteria_text", "eligible",
           "feasibility_text", "representative"]
