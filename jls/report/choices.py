"""Which combinations the report draws, and the rule it states for a selection.

The recommendation, its ties and exclusions are :mod:`jls.assessment.recommendation`'s (imported
here for the report's modules). Tables show every combination. A figure with one
colour per candidate and one line style per tugger shows every combination when there
are at most :data:`MAX_PLOT_CANDIDATES` candidates and :data:`MAX_PLOT_TUGGERS` tuggers;
otherwise it shows the selection of :func:`plot_selection`, whose rule the caption
states.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.assessment.recommendation import by_combination

MAX_PLOT_CANDIDATES = 6       # colours in one plot
MAX_PLOT_TUGGERS = 4          # line styles in one plot
MAX_PANELS = 8                # candidate x heading panels in one figure
MAX_DOT_ROWS = 36             # combinations (rows) of the workability dot plot
MAX_TABLE_COMBOS = 24         # combinations in one per-combination table


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


    def table_caption(self) -> str:
        """The sentence a table caption carries about the combinations it lists."""
        if self.rule is None:
            return ""
        return (f" Listed: {len(self.combos)} of {self.total} combinations, {self.rule}; every "
                "combination's values are in the workability dataset (appendix).")

    def candidate_caption(self, n_candidates: int) -> str:
        """The same for a figure of rigging candidates alone (tuggers do not appear)."""
        if len(self.candidates) == n_candidates:
            return f"All {n_candidates} rigging candidates are drawn."
        return (f"Drawn: {len(self.candidates)} of {n_candidates} rigging candidates, "
                f"{', '.join(self.candidates)} (the baseline, the best feasible candidate, then "
                "those with the highest route workability with any tugger); every candidate is "
                "in the tables.")


def table_selection(work, combos, baseline, best, ties) -> Selection:
    """The combinations a per-combination table lists: all of them up to
    :data:`MAX_TABLE_COMBOS`; beyond, the baseline rigging with every tugger setting, the
    recommended combination and its ties, then the highest route workability."""
    combos = list(combos)
    cands = list(dict.fromkeys(c for c, _ in combos))
    tugs = list(dict.fromkeys(t for _, t in combos))
    if len(combos) <= MAX_TABLE_COMBOS:
        return Selection(combos, cands, tugs, len(combos))
    values = by_combination(work["workability_route"])
    keep = [ct for ct in combos if ct[0] == baseline] + [best] + list(ties)
    for ct in sorted(combos, key=lambda ct: -values[ct]):
        if len(dict.fromkeys(keep)) >= MAX_TABLE_COMBOS:
            break
        keep.append(ct)
    keep = set(keep)
    chosen = [ct for ct in combos if ct in keep]
    return Selection(chosen, list(dict.fromkeys(c for c, _ in chosen)),
                     list(dict.fromkeys(t for _, t in chosen)), len(combos),
                     rule=("the baseline rigging with every tugger setting, the recommended "
                           "combination and its ties, then those with the highest route "
                           "workability"))


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
    wr = by_combination(work["workability_route"])
    ranked = sorted(combos, key=lambda ct: -wr[ct])
    keep = list(dict.fromkeys([(baseline, t) for t in tugs] + [best] + ranked))[:MAX_DOT_ROWS]
    shown = [ct for ct in combos if ct in keep]
    return Selection(shown, sorted({c for c, _ in shown}, key=cands.index),
                     sorted({t for _, t in shown}, key=tugs.index), len(combos),
                     f"the {baseline} rigging with every tugger, the best feasible combination "
                     "and then those with the highest route workability")


