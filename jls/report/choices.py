"""Which combinations the report quotes and draws, and the rules it states for them.

* The *best combination* is the highest route workability among feasible rigging
  candidates. Combinations whose route workability equals it within
  :data:`TIE_TOLERANCE` are a tie, disclosed in the report and broken by
  :data:`TIE_RULE`: fewer active components first (the baseline rigging before a
  changed one, no tugger before a tugger), then the lower tugger slope.
* Combinations are *excluded* from the recommendation by :data:`EXCLUSION_RULES`, a list
  of rules each returning ``{(candidate, tugger): reason}`` (an infeasible rigging
  candidate, ...); :func:`exclusions` merges their reasons, which the report states.
  Adding a rule (a saturated winch, an uncertainty band) is appending a function.
* Tables show every combination. A figure with one colour per candidate and one line
  style per tugger shows every combination when there are at most
  :data:`MAX_PLOT_CANDIDATES` candidates and :data:`MAX_PLOT_TUGGERS` tuggers; otherwise
  it shows the selection of :func:`plot_selection`, whose rule the caption states.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
import xarray as xr

TIE_TOLERANCE = 1e-9          # route workabilities (fractions) closer than this are equal
TIE_RULE = ("fewer active components first (the baseline rigging before a changed one, no "
            "tugger before a tugger), then the lower tugger slope")
MAX_PLOT_CANDIDATES = 6       # colours in one plot
MAX_PLOT_TUGGERS = 4          # line styles in one plot
MAX_PANELS = 8                # candidate x heading panels in one figure
MAX_DOT_ROWS = 36             # combinations (rows) of the workability dot plot


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
    return {(c, tg): f"rigging {c} is not feasible: {why[c] or 'a constraint is violated'}"
            for c, tg in combos if not ok[c]}


#: Rules excluding combinations from the recommendation: (data, combos) -> {combo: reason},
#: data holding the report's datasets by name ("plant", "response", "workability", ...).
ExclusionRule = Callable[[dict, list], dict]
EXCLUSION_RULES: list[ExclusionRule] = [infeasible_rigging]


def exclusions(data: dict, combos, rules=None) -> dict:
    """{combo: reason} of the combinations some rule excludes (reasons of several rules
    joined with "; "); ``rules`` defaults to :data:`EXCLUSION_RULES`."""
    out: dict = {}
    for rule in (EXCLUSION_RULES if rules is None else rules):
        for combo, reason in rule(data, list(combos)).items():
            out[combo] = f"{out[combo]}; {reason}" if combo in out else reason
    return out


def excluded_by_candidate(excluded: dict, tuggers) -> dict:
    """{candidate: reason} of the candidates excluded with every tugger setting for one
    same reason (an infeasible rigging, the usual case); other exclusions are stated per
    combination."""
    out = {}
    for c in dict.fromkeys(c for c, _ in excluded):
        reasons = {excluded.get((c, tg)) for tg in tuggers}
        if len(reasons) == 1 and None not in reasons:
            out[c] = reasons.pop()
    return out


@dataclass
class Selection:
    """Combinations drawn in a figure; ``rule`` is None when every one is drawn."""

    combos: list
    candidates: list
    tuggers: list
    total: int
    rule: str | None = None

    def caption(self) -> str:
        """The sentence a figure caption carries about what it shows."""
        if self.rule is None:
            return f"All {self.total} combinations are shown."
        return (f"Shown: {len(self.combos)} of {self.total} combinations, {self.rule}; every "
                "combination is in the tables.")


    def candidate_caption(self, n_candidates: int) -> str:
        """The same for a figure of rigging candidates alone (tuggers do not appear)."""
        if len(self.candidates) == n_candidates:
            return f"All {n_candidates} rigging candidates are drawn."
        return (f"Drawn: {len(self.candidates)} of {n_candidates} rigging candidates, "
                f"{', '.join(self.candidates)} (the baseline, the best feasible candidate, then "
                "those with the highest route workability with any tugger); every candidate is "
                "in the tables.")


def plot_selection(work, cands, tugs, baseline, no_tug, best, n_headings=1) -> Selection:
    """The candidates and tuggers one figure can show distinctly (see module doc)."""
    total = len(cands) * len(tugs)
    max_c = max(1, min(MAX_PLOT_CANDIDATES, MAX_PANELS // max(n_headings, 1)))
    if len(cands) <= max_c and len(tugs) <= MAX_PLOT_TUGGERS:
        return Selection([(c, t) for c in cands for t in tugs], list(cands), list(tugs), total)
    wr = work["workability_route"].sel(candidate=cands, tugger=tugs)
    by_c = wr.max("tugger")
    by_t = wr.max("candidate")
    rank_c = [str(c) for c in by_c["candidate"].values[np.argsort(-by_c.values, kind="stable")]]
    rank_t = [str(t) for t in by_t["tugger"].values[np.argsort(-by_t.values, kind="stable")]]
    pick_c = list(dict.fromkeys([baseline, best[0]] + rank_c))[:max_c]
    pick_t = list(dict.fromkeys([no_tug, best[1]] + rank_t))[:MAX_PLOT_TUGGERS]
    sc = [c for c in cands if c in pick_c]
    st = [t for t in tugs if t in pick_t]
    parts = []
    if len(sc) < len(cands):
        parts.append(f"the {len(sc)} rigging candidates {', '.join(sc)} (the baseline, the best "
                     "feasible candidate, then those with the highest route workability with "
                     "any tugger)")
    else:
        parts.append("every rigging candidate")
    if len(st) < len(tugs):
        parts.append(f"the {len(st)} tugger settings {', '.join(st)} (no tugger, the best "
                     "combination's, then those with the highest route workability with any "
                     "candidate)")
    else:
        parts.append("every tugger setting")
    return Selection([(c, t) for c in sc for t in st], sc, st, total, " with ".join(parts))


def dot_selection(work, cands, tugs, baseline, no_tug, best) -> Selection:
    """Rows of the workability dot plot: every combination up to :data:`MAX_DOT_ROWS`,
    else the baseline with every tugger, the best, and the highest route workability."""
    combos = [(c, t) for c in cands for t in tugs]
    if len(combos) <= MAX_DOT_ROWS:
        return Selection(combos, list(cands), list(tugs), len(combos))
    wr = {ct: float(work["workability_route"].sel(candidate=ct[0], tugger=ct[1])) for ct in combos}
    ranked = sorted(combos, key=lambda ct: -wr[ct])
    keep = list(dict.fromkeys([(baseline, t) for t in tugs] + [best] + ranked))[:MAX_DOT_ROWS]
    shown = [ct for ct in combos if ct in keep]
    return Selection(shown, sorted({c for c, _ in shown}, key=cands.index),
                     sorted({t for _, t in shown}, key=tugs.index), len(combos),
                     f"the {baseline} rigging with every tugger, the best feasible combination "
                     "and then those with the highest route workability")


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
                    out[(str(c), str(tg))] = (f"winches at a force limit {100 * f:.1f} % of the time "
                                              f"in a time-domain cell (allowed: {100 * limit:g} %)")
    if work.attrs["winch_saturation"] == "fail":
        share = work["saturation_share_route"]
        for c in share["candidate"].values:
            for tg in share["tugger"].values:
                f = float(share.sel(candidate=c, tugger=tg))
                if (str(c), str(tg)) in combos and f > limit and (str(c), str(tg)) not in out:
                    out[(str(c), str(tg))] = (
                        f"winches saturate in the frequency domain in sea states carrying "
                        f"{100 * f:.1f} % of the route (allowed: {100 * limit:g} %); those "
                        "cells fail under the 'fail' policy")
    return out


EXCLUSION_RULES.append(winch_saturation)
