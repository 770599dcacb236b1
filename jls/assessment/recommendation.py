"""The answer an engineer signs: which rigging and which tugger setting for the route.

* The *recommendation* is the combination (rigging candidate, tugger setting) with the
  highest route workability among those no exclusion rule removes. Combinations whose
  route workability equals it within :data:`TIE_TOLERANCE` are a tie, disclosed in the
  report and broken by :data:`TIE_RULE`: fewer active components first (the baseline
  rigging before a changed one, no tugger before a tugger), then the lower tugger slope.
* :data:`EXCLUSION_RULES` is a list of rules ``(data, combos) -> {(candidate, tugger):
  reason}``, ``data`` holding the datasets by name ("plant", "workability", ...): an
  infeasible rigging candidate, winches that saturate. :func:`exclusions` merges their
  reasons, which the report states. Adding a rule is appending a function. A reason is
  a :class:`Reason`: the sentence, a short label for a table column and what the label
  means (a plain string is taken as its own label).
"""

from __future__ import annotations

from typing import Callable

import numpy as np
import xarray as xr

INFEASIBLE = "infeasible rigging"   # the short label of an infeasible candidate's exclusion
TIE_TOLERANCE = 1e-9          # route workabilities (fractions) closer than this are equal
TIE_RULE = ("fewer active components first (the baseline rigging before a changed one, no "
            "tugger before a tugger), then the lower tugger slope")


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


def tie_key(combo, baseline, c_tugger, cands, tugs) -> tuple:
    return (active_components(combo, baseline, c_tugger), c_tugger[combo[1]],
            cands.index(combo[0]), tugs.index(combo[1]))


def best_with_ties(work: xr.Dataset, combos, baseline, c_tugger, cands, tugs):
    """(best, tied others) among ``combos`` by route workability and :data:`TIE_RULE`."""
    wr = {ct: float(work["workability_route"].sel(candidate=ct[0], tugger=ct[1])) for ct in combos}
    top = max(wr.values())
    tied = sorted((ct for ct in combos if wr[ct] >= top - TIE_TOLERANCE),
                  key=lambda ct: tie_key(ct, baseline, c_tugger, cands, tugs))
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
    excluded = exclusions(data, combos)
    best, ties = best_with_ties(data["workability"], eligible(combos, excluded), baseline,
                                c_tugger, cands, tugs)
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
        td = work["timedomain_limit_fraction"]
        for c in td["candidate"].values:
            for tg in td["tugger"].values:
                f = float(td.sel(candidate=c, tugger=tg))
                if (str(c), str(tg)) in combos and np.isfinite(f) and f > limit:
                    out[(str(c), str(tg))] = Reason(
                        f"winches at a force limit {100 * f:.1f} % of the time in a time-domain "
                        f"cell (allowed: {100 * limit:g} %)", f"winch {100 * f:.1f}\u00a0% of time",
                        f"winch x\u00a0% of time: the winches are at a force limit x\u00a0% of the "
                        f"time in a time-domain cell, more than the {100 * limit:g}\u00a0% allowed")
    if work.attrs["winch_saturation"] == "fail":
        share = work["saturation_share_route"]
        for c in share["candidate"].values:
            for tg in share["tugger"].values:
                f = float(share.sel(candidate=c, tugger=tg))
                if (str(c), str(tg)) in combos and f > limit and (str(c), str(tg)) not in out:
                    out[(str(c), str(tg))] = Reason(
                        f"winches saturate in the frequency domain in sea states carrying "
                        f"{100 * f:.1f} % of the route (allowed: {100 * limit:g} %); those "
                        "cells fail under the 'fail' policy", f"winch {100 * f:.1f}\u00a0%",
                        f"winch x\u00a0%: the winches saturate in the frequency domain in sea "
                        f"states carrying x\u00a0% of the route, more than the {100 * limit:g}\u00a0% "
                        "allowed, and those cells fail under the 'fail' policy")
    return out


EXCLUSION_RULES.append(winch_saturation)
