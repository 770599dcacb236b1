"""Page 1 of the assessment report as Typst markup: the document control block and
section 1, the summary (2-4: sections_inputs, 5-8: sections_results).

Each function takes the :class:`Context` (datasets, digest, provenance, figure files)
and returns the markup of one section, heading included; a chapter is one such function,
listed in :data:`jls.report.document.SECTIONS`. Numbers are formatted here
and only here; the headline percentages come straight from ``workability_route``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import xarray as xr

from jls.assessment.recommendation import INFEASIBLE, TIE_RULE, TIE_TOLERANCE, Reason
from jls.report import control
from jls.report.contract import Digest, criterion_label, flag, governing_runs, limit_text, pct
from jls.report.markup import cell, mono, num, t, table

MAX_TIES_NAMED = 6            # tied combinations named on page 1; the table has them all
MAX_EXCLUSIONS_NAMED = 3      # riggings whose exclusions page 1 names; more are counted


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
    return ", ".join(f"{criterion_label(c)} MPM ≤ {limit_text(dg, c)}" for c in dg.criteria)


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


def at_limit_rule(plant: xr.Dataset) -> str:
    """The at-limit rule with the tolerances the plant was judged with."""
    a = plant.attrs
    return ("at limit: feasible, but a constraint margin is within its tolerance of zero "
            f"(lengths {float(a['at_limit_tolerance_m']):g} m, angles "
            f"{float(a['at_limit_tolerance_deg']):g}°, tensions {float(a['at_limit_tolerance_kN']):g} kN)")


# -- document control (page 1, before section 1) ---------------------------------------
def document_control(cx: Context) -> str:
    """The document-control block: number, revision, client, project, sign-off, the
    creation time, the jls version and the source commit."""
    doc, p = control.document_info(cx.prov), cx.prov
    blank = "–"
    commit = str(p.get("git_commit", control.NOT_GIT))
    pairs = [("document number", t(doc["number"] or control.NOT_ASSIGNED)),
             ("revision", t(doc["revision"] or blank)),
             ("client", t(doc["client"] or blank)), ("project", t(doc["project"] or blank)),
             ("prepared", t(doc["prepared"] or blank)), ("created", t(p.get("created", "?"))),
             ("checked", t(doc["checked"] or blank)), ("jls version", t(p.get("jls_version", "?"))),
             ("approved", t(doc["approved"] or blank)),
             ("source commit", mono(commit) if commit != control.NOT_GIT else t(commit))]
    cells = ", ".join(f"[{t(k)}], [{v}]" for k, v in pairs)
    return ("#doccontrol(" + cells + ")\n")


# -- 1 -------------------------------------------------------------------------------
def summary(cx: Context) -> str:
    dg, sea = cx.dg, cx.sea
    base = (dg.baseline, dg.no_tugger)
    dur = float(sea["duration_h"].sum())
    out = ["= Summary\n"]
    out.append(f"Route *{t(dg.route)}*: {len(cx.legs)} legs ({t(', '.join(cx.legs))}), "
               f"{num(dur, 0)} h in all, relative wave headings "
               f"{t(', '.join(f'{h:g}°' for h in cx.work['heading'].values))}. A sea state is "
               f"workable when every criterion holds: {t(criteria_text(dg))}, the most probable "
               f"maximum over {num(dg.exposure_h, 1)} h. Workability is the probability of the "
               "workable sea states, per leg and weighted by leg duration for the route.\n")
    c_best = cx.c_tugger(dg.best[1])
    c_base = cx.c_tugger(dg.no_tugger)
    base_label = "no tugger" if c_base == 0 else f"lowest tugger setting ({dg.no_tugger})"
    out.append(
        f"#headline([Route workability, {t(dg.baseline)} rigging, {t(base_label)}], "
        f"[{t(pct(cx.w_route(base)))}], [{t(combo_text(base))}])\n#h(1fr)\n"
        f"#headline([Route workability, best combination], [{t(pct(cx.w_route(dg.best)))}], "
        f"[{t(combo_text(dg.best))} ({num(c_best, 0)} kN s/m)"
        + (f", tied with {len(dg.ties)} other{'s' if len(dg.ties) > 1 else ''}" if dg.ties else "")
        + "])\n")
    out.append(recommendation(cx))
    from jls.report.sections_uncertainty import band_sentence
    out.append(band_sentence(cx))
    gov = dg.governing_name(base)
    runs = [r for h in cx.work["heading"].values for r in governing_runs(cx.work, base, h)]
    crit_runs = sorted({r[0] for r in runs if r[0] != "steepness"})
    text = (f"*Governing criterion:* {t(criterion_label(gov))} decides "
            f"{t(pct(dg.governing[base][gov] / max(1 - cx.w_route(base), 1e-12)))} of the "
            f"non-workable probability of the {t(dg.baseline)} rigging without tugger"
            if gov else "*Governing criterion:* no sea state of the route fails any criterion")
    if crit_runs:
        text += (f"; along the operability curve the limiting Hs is set by "
                 f"{t(', '.join(criterion_label(c) for c in crit_runs))}")
        if any(r[0] == "steepness" for r in runs):
            text += " and, at short periods, by the wave steepness ceiling"
    out.append(text + ".\n")
    if not cx.feasible(dg.best[0]):
        out.append("#warning[No rigging candidate is feasible (section 3); the best combination "
                   "quoted above does not meet every rigging constraint.]\n")
    elif dg.best_any[0] != dg.best[0] and cx.w_route(dg.best_any) > cx.w_route(dg.best) + TIE_TOLERANCE:
        out.append(f"#warning[The highest route workability, {t(pct(cx.w_route(dg.best_any)))}, "
                   f"belongs to {t(combo_text(dg.best_any))}, but that rigging candidate is not "
                   "feasible (section 3); the best feasible combination is quoted above.]\n")
    if dg.ties:
        others = "; ".join(combo_text(ct) for ct in dg.ties[:MAX_TIES_NAMED])
        if len(dg.ties) > MAX_TIES_NAMED:
            others += f" and {len(dg.ties) - MAX_TIES_NAMED} more (table 1)"
        out.append(f"#note[*Tie.* {t(others)} reach{'es' if len(dg.ties) == 1 else ''} the same route "
                   f"workability as {t(combo_text(dg.best))} ({t(pct(cx.w_route(dg.best)))}, equal "
                   f"within {TIE_TOLERANCE:g}). The combination quoted is chosen by the tie-break "
                   f"rule: {t(TIE_RULE)}.]\n")
    if dg.at_limit.get(dg.best[0]):
        out.append(f"#warning[The {t(dg.best[0])} rigging of the best combination is feasible only "
                   f"*at the limit* of a constraint: {t(dg.at_limit[dg.best[0]])} (section 3). "
                   "It leaves no room for fabrication or positioning tolerances.]\n")
    if dg.hash_mismatch:
        out.append(f"#warning[Configuration mismatch: {t(', '.join(dg.hash_mismatch))} "
                   f"{'was' if len(dg.hash_mismatch) == 1 else 'were'} made with a configuration "
                   f"other than this report's (compared on {t(dg.hash_basis)}; section 2).]\n")
    if representative(cx.prov.get("vessel_description", "")):
        out.append("#note[The vessel motions come from a *representative hull*, not from the "
                   "vessel's own RAOs (section 2). Treat the percentages as the class's, to be "
                   "confirmed with the vessel's data.]\n")
    out.append(workability_table(cx))
    return "\n".join(out)


def recommendation(cx: Context) -> str:
    """The headline answer in one sentence: what to rig and what it gains."""
    dg = cx.dg
    base = (dg.baseline, dg.no_tugger)
    gain = cx.w_route(dg.best) - cx.w_route(base)
    if not cx.feasible(dg.best[0]):
        return ("*Recommendation:* none of the assessed rigging candidates is feasible; revise "
                "the rigging before the transit.\n")
    if dg.best == base or gain <= TIE_TOLERANCE:
        return (f"*Recommendation:* sail with the {t(dg.baseline)} rigging without tugger; no "
                "assessed change raises the route workability" + _selection_rule(dg) + ".\n")
    extra = f" ({t(dg.at_limit[dg.best[0]])})" if dg.at_limit.get(dg.best[0]) else ""
    return (f"*Recommendation:* {t(combo_text(dg.best))}{extra}: route workability "
            f"{t(pct(cx.w_route(dg.best)))}, {num(100 * gain, 1)} percentage points above the "
            f"{t(dg.baseline)} rigging without tugger" + _selection_rule(dg) + ".\n")


def _selection_rule(dg: Digest) -> str:
    """How the recommended combination was chosen: the tie-break rule and what was
    excluded, and why. Infeasible rigging candidates are named with their reason (counted
    when there are more than :data:`MAX_EXCLUSIONS_NAMED`); the other exclusions are
    named by rigging with their short labels (the column "excluded" of table 1), or
    counted when they concern more riggings, and what the labels mean follows."""
    text = (f" (the highest route workability among the combinations not excluded; ties "
            f"broken by {TIE_RULE})")
    if not dg.excluded:
        return text
    infeasible = [c for c in dict.fromkeys(c for c, _ in dg.excluded)
                  if all(INFEASIBLE in dg.excluded.get((c, tg), Reason("", "")).short.split(", ")
                         for tg in dg.tuggers)]
    if len(infeasible) > MAX_EXCLUSIONS_NAMED:
        parts = [f"{len(infeasible)} rigging candidates that are not feasible (section 3)"]
    else:
        parts = [f"{c}: {dg.infeasible.get(c) or 'a constraint is violated'}" for c in infeasible]
    rest = {ct: why for ct, why in dg.excluded.items() if ct[0] not in infeasible}
    per_rigging: dict = {}
    for (c, tg), why in rest.items():
        per_rigging.setdefault(c, []).append(f"{tg} ({why.short})")
    if len(per_rigging) > MAX_EXCLUSIONS_NAMED:
        parts.append(f"{len(rest)} combinations of {len(per_rigging)} feasible rigging candidates "
                     "(the column 'excluded' of table 1 for those it lists, workability.nc for all)")
    else:
        parts += [f"{c} rigging with tugger {_and(items)}" for c, items in per_rigging.items()]
    legend = list(dict.fromkeys(x for why in rest.values() for x in why.legend))
    text += f". Excluded: {t('; '.join(parts))}"
    if legend:
        text += f" ({t('; '.join(legend))})"
    return text


def _and(items: list) -> str:
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} and {items[-1]}"


def workability_table(cx: Context) -> str:
    """Table 1: the combinations of the digest's table selection (all of them, or the
    baseline, the recommendation and its ties, then the highest route workability)."""
    dg = cx.dg
    combos = dg.table.combos
    header = ["candidate", "tugger", "c [kN s/m]", "feasible", *cx.legs, "route", "governing",
              "excluded"]
    rows = []
    for ct in combos:
        gov = dg.governing_name(ct)                  # the digest's leg-weighted shares
        bold = ct in (dg.best, (dg.baseline, dg.no_tugger))
        rows.append([cell(ct[0], bold=bold), cell(ct[1], bold=bold), num(cx.c_tugger(ct[1]), 0),
                     feasibility_text(dg, ct[0], short=True),
                     *[pct(cx.w_leg(ct, leg)) for leg in cx.legs],
                     cell(pct(cx.w_route(ct)), bold=bold),
                     criterion_label(gov) if gov else "none fails",
                     dg.excluded[ct].short if ct in dg.excluded else "–"])
    cap = ("Workability per leg and for the route (duration-weighted) of every rigging candidate "
           "and tugger setting; baseline without tugger and best feasible combination in bold; "
           "governing: the criterion that decides most of the non-workable probability; "
           + at_limit_rule(cx.plant) + "; section 3 names the constraint; excluded: why the "
           "recommendation passes the combination over (the labels are explained with it)."
           + dg.table.table_caption())
    size = "8.5pt" if len(header) <= 9 else "7.5pt" if len(header) <= 12 else "6.5pt"
    return table(cap, header, rows, size=size,
                 align="(left, left, right, center" + ", right" * (len(cx.legs) + 1) + ", left, left)")
