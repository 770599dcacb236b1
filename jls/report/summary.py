"""Page 1 of the assessment report: the document-control block and chapter 1, the
summary, one page that decides (the verdict, the master's table, the recommendation and
why, each leg's governing criterion and margin, the binding criteria, the caveats and
the warnings; :mod:`jls.report.page_one`). The parts that state it in full (the headline
boxes, the recommendation with its selection rule, the voyage and uncertainty sentences,
the notes and table 1 of every combination) are made here for the chapter "Assessment in
detail" (:mod:`jls.report.assessment`).

Numbers are formatted here and only here; the headline percentages come straight from
``workability_route``.
"""

from __future__ import annotations

import numpy as np

from jls.assessment.recommendation import INFEASIBLE, PLAN_TIE_RULE, TIE_RULE, Reason, effective_objective
from jls.report import control, model_range, page_one, spectra, swell_table, verification, wire_loads
from jls.report import plan_verdict as plan_page
from jls.report.basis import BEYOND_MODEL, voyage_inside, voyage_level
from jls.report.context import (
    Context,
    at_limit_rule,
    combo_text,
    eligible,
    feasibility_text,
    heading,
    representative,
)
from jls.report.contract import criterion_label, pct
from jls.report.markup import cell, mono, num, ref, t, table
from jls.report.robustness import banded, has_bands, recommendation_holds

MAX_TIES_NAMED = 6            # tied combinations named on page 1; the table has them all
MAX_EXCLUSIONS_NAMED = 3      # riggings whose exclusions page 1 names; more are counted


def chapter(cx: Context) -> str:
    """Page 1: the document-control block, then the summary."""
    return document_control(cx) + "\n" + summary(cx)


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


# -- 1 summary ------------------------------------------------------------------------
def summary(cx: Context) -> str:
    """Page 1, one page that decides: the verdict, the master's table, the recommendation
    and why, the governing criterion and margin of each leg, the criteria that bind the
    recommendation with their figures, the caveats that change the answer (vessel data,
    sea model, what was verified) and the warnings. The rest is in the chapter
    "Assessment in detail" (:mod:`jls.report.assessment`)."""
    out = [heading("summary", "Summary")]
    out.append(plan_page.verdict(cx))           # the verdict first (voyage_plan.nc)
    out.append(plan_page.master_table(cx))
    out.append(swell_table.swell_table(cx))      # partitioned legs only
    out.append(page_one.why(cx))
    out.append(page_one.legs_table(cx))
    out.append((page_one.binding(cx).rstrip() + " " + wire_loads.binding_figures(cx)).rstrip() + "\n")
    out.append(page_one.caveats(cx))
    checked = verification.page_one_what_was_verified(cx)     # one paragraph: what was verified
    out.append(verification.page_one_sentence(cx) + (" " + checked if checked else "") + "\n")
    out.append(spectra.page_one_warning(cx))
    out.extend(page_one_warnings(cx))
    out.append(page_one.input_warnings(cx))
    return "\n".join(x for x in out if x)


def page_one_warnings(cx: Context) -> list[str]:
    """The warnings that change the answer: no feasible rigging, the best rigging at a
    safety limit without tolerance budget, a recommendation that does not hold across the
    uncertainty band, datasets made with another configuration."""
    dg, out = cx.dg, []
    if not cx.feasible(dg.best[0]):
        out.append(f"#warning[No rigging candidate is feasible ({cx.sec('plant')}); the best "
                   "combination quoted above does not meet every rigging constraint.]\n")
    if dg.at_limit.get(dg.best[0]) and _at_limit_note(cx).startswith("#warning"):
        out.append(_at_limit_note(cx))
    if has_bands(cx.work) and cx.feasible(dg.best[0]) and banded(cx.work, dg.best):
        v = recommendation_holds(cx.work, dg.best, eligible(cx))
        if not v.holds:
            out.append(f"#warning[*Uncertainty:* the recommendation *does not hold* across the band of "
                       f"damping, sway frequency and Hs in the bin: another combination is best in "
                       f"{len(v.losers)} of {v.variants} variants ({cx.sec('uncertainty')}).]\n")
    if dg.hash_mismatch:
        out.append(f"#warning[Configuration mismatch: {t(', '.join(dg.hash_mismatch))} "
                   f"{'was' if len(dg.hash_mismatch) == 1 else 'were'} made with a configuration "
                   f"other than this report's (compared on {t(dg.hash_basis)}; {cx.sec('provenance')}).]\n")
    return out


def notes(cx: Context) -> list[str]:
    """The notes of the chapter "Assessment in detail": the option of the highest
    workability passed over, ties, and the best rigging on a constraint."""
    dg, out = cx.dg, []
    if cx.feasible(dg.best[0]) and dg.best_any != dg.best \
            and cx.w_route(dg.best_any) > cx.w_route(dg.best) + dg.tie_tolerance:
        out.append(f"#warning[The highest route workability, {t(pct(cx.w_route(dg.best_any)))}, "
                   f"belongs to {t(combo_text(dg.best_any))}, {best_any_reason(cx)}; the "
                   "recommendation above is the best of the combinations it may choose.]\n")
    if dg.ties:
        others = "; ".join(combo_text(ct) for ct in dg.ties[:MAX_TIES_NAMED])
        if len(dg.ties) > MAX_TIES_NAMED:
            others += f" and {len(dg.ties) - MAX_TIES_NAMED} more"
        others = t(others) + (f" ({ref('tab-summary', 'table')})" if len(dg.ties) > MAX_TIES_NAMED else "")
        if effective_objective(cx.work) == "voyage_plan":
            out.append(f"#note[*Tie.* {others} reach{'es' if len(dg.ties) == 1 else ''} the same probability "
                       f"that a voyage sailed by the departure rule exceeds a limit as {t(combo_text(dg.best))} "
                       f"(equal within {num(100 * dg.tie_tolerance, 2)} percentage points). The combination "
                       f"quoted is chosen by {t(PLAN_TIE_RULE)}, then the tie-break rule: {t(TIE_RULE)}.]\n")
        else:
            out.append(f"#note[*Tie.* {others} reach{'es' if len(dg.ties) == 1 else ''} the same route "
                       f"workability as {t(combo_text(dg.best))} ({t(pct(cx.w_route(dg.best)))}, equal "
                       f"within {num(100 * dg.tie_tolerance, 2)} percentage points). The combination quoted is chosen by the tie-break "
                       f"rule: {t(TIE_RULE)}.]\n")
    if dg.at_limit.get(dg.best[0]):
        out.append(_at_limit_note(cx))
    return out


def best_any_reason(cx: Context) -> str:
    """Why the combination of the highest route workability is not the recommendation:
    its rigging is infeasible, or a rule excludes it (the rule's own words)."""
    dg = cx.dg
    if not cx.feasible(dg.best_any[0]):
        return f"but that rigging candidate is not feasible ({cx.sec('plant')})"
    reason = dg.excluded.get(dg.best_any)
    if reason is not None:
        return f"which the recommendation passes over: {t(str(reason))}"
    return "which the tie-break rule places after the recommendation"


def vessel_note(cx: Context) -> str:
    """Page 1's sentence on the vessel data (``vessel_motion.nc``'s ``vessel_statement``:
    the vessel's own RAOs, computed ones or a representative hull and how its sway
    compares with the study's) and the hinge geometry the lever arm and the splash
    clearance rest on."""
    attrs = cx.vessel.attrs
    statement = str(attrs.get("vessel_statement", ""))
    rep = str(attrs.get("vessel_data", "")) == "representative" or (
        not statement and representative(cx.prov.get("vessel_description", "")))
    if not statement:
        statement = ("The vessel motions come from a representative hull, not from the vessel's "
                     "own RAOs." if rep else "The vessel motions are the configured RAO file's.")
    text = t(statement.rstrip().rstrip(".")) + f" ({cx.sec('vessel')}, {cx.sec('provenance')})."
    lever, height = attrs.get("hinge_lever_arm_m"), attrs.get("hinge_height_above_water_m")
    if lever is not None and height is not None:
        lever = [float(x) for x in np.atleast_1d(lever)]
        text += (f" The hinge stands {t(num(float(height), 2))} m above the waterline, at "
                 f"{t(', '.join(num(x, 1) for x in lever))} m (forward, port, up) from the RAO "
                 "reference point: the lever arm that turns vessel roll into hinge sway.")
    if rep:
        text += " Treat the percentages as the class's, to be confirmed with the vessel's data."
    return "#note[" + text + "]\n"


def _at_limit_note(cx: Context) -> str:
    """The best rigging on a constraint: a note when it keeps the constraint's tolerance
    budget, a warning when a safety constraint has no budget (nothing to spare)."""
    dg = cx.dg
    phrases = dg.at_limit[dg.best[0]].removeprefix("at limit: ").split("; ")
    bare = [p for p in phrases if "tolerance budget" not in p and " bound " not in p]
    if bare:
        return (f"#warning[The {t(dg.best[0])} rigging of the best combination is feasible only "
                f"*at the limit* of a constraint: {t('; '.join(bare))} ({cx.sec('plant')}). "
                "Its tolerance budget is zero: it leaves no room for fabrication or positioning "
                "tolerances.]\n")
    return (f"#note[The {t(dg.best[0])} rigging of the best combination sits on a constraint with "
            f"its tolerance budget to spare and no more: {t('; '.join(phrases))} ({cx.sec('plant')}"
            + (f"; what more margin would cost: {cx.sec('rigging')}" if cx.has("rigging") else "") + ").]\n")


def recommendation(cx: Context) -> str:
    """The headline answer in one sentence: what to rig and what it gains."""
    dg = cx.dg
    base = (dg.baseline, dg.no_tugger)
    gain = cx.w_route(dg.best) - cx.w_route(base)
    if not cx.feasible(dg.best[0]):
        return ("*Recommendation:* none of the assessed rigging candidates is feasible; revise "
                "the rigging before the transit.\n")
    if effective_objective(cx.work) == "voyage_plan":
        return _plan_recommendation(cx)
    if dg.best == base or gain <= dg.tie_tolerance:
        return (f"*Recommendation:* sail with the {t(dg.baseline)} rigging without tugger; no "
                "assessed change raises the route workability" + _selection_rule(dg) + "."
                + _no_plan_ranking(cx) + "\n")
    extra = f" ({t(dg.at_limit[dg.best[0]])})" if dg.at_limit.get(dg.best[0]) else ""
    text = (f"*Recommendation:* {t(combo_text(dg.best))}{extra}: route workability "
            f"{t(pct(cx.w_route(dg.best)))}, {num(100 * gain, 1)} percentage points above the "
            f"{t(dg.baseline)} rigging without tugger" + _selection_rule(dg) + ".")
    return _no_plan_ranking(cx, text)


def _no_plan_ranking(cx: Context, sentence: str = "") -> str:
    """``sentence`` and, where the voyage plan was asked to rank the options but the route
    has no departure simulation (a leg without hourly records), the statement that they
    are ranked by workability instead; ends the paragraph when ``sentence`` is given."""
    note = ""
    if str(cx.work.attrs.get("recommendation_objective", "")) == "voyage_plan":
        where = f" ({cx.sec('voyage_plan')})" if cx.has("voyage_plan") and cx.plan is not None else ""
        note = (" The voyage plan has no departure simulation on this route" + where
                + ", so the options are ranked by route workability.")
    return sentence + note + ("\n" if sentence else "")


def _plan_recommendation(cx: Context) -> str:
    """The recommendation ranked by the voyage plan (workability.nc's
    ``plan_inside_probability`` and waits, from voyage_plan.nc)."""
    dg, w = cx.dg, cx.work
    base = (dg.baseline, dg.no_tugger)

    def at(name, combo):
        return float(w[name].sel(candidate=combo[0], tugger=combo[1]))
    p_best, p_base = 1 - at("plan_inside_probability", dg.best), 1 - at("plan_inside_probability", base)
    rule = (f" (ranked by the probability that a voyage sailed by the departure rule exceeds a limit, "
            f"then {PLAN_TIE_RULE}, then {TIE_RULE}; {cx.sec('voyage_plan')}). The route workability, "
            f"{t(pct(cx.w_route(dg.best)))}, stays a planning figure")
    extra = f" ({t(dg.at_limit[dg.best[0]])})" if dg.at_limit.get(dg.best[0]) else ""
    if dg.best == base:
        return (f"*Recommendation:* sail with the {t(dg.baseline)} rigging without tugger: probability "
                f"that a sailed voyage exceeds a limit {num(p_best, 3)}, median wait "
                f"{num(at('plan_wait_median_h', dg.best), 0)} h" + rule + ".\n")
    return (f"*Recommendation:* {t(combo_text(dg.best))}{extra}: probability that a sailed voyage exceeds "
            f"a limit {num(p_best, 3)} against {num(p_base, 3)} for the {t(dg.baseline)} rigging without "
            f"tugger, median wait {num(at('plan_wait_median_h', dg.best), 0)} h (90 %: "
            f"{num(at('plan_wait_p90_h', dg.best), 0)} h)" + rule + ".\n")


def band_sentence(cx: Context) -> str:
    """Page 1: the recommendation's band and whether it holds across it."""
    if not has_bands(cx.work):
        return ""
    dg, work = cx.dg, cx.work
    if not banded(work, dg.best):
        return (f"*Uncertainty:* the {t(dg.best[0])} rigging is a grid candidate that was not "
                "varied (only the baseline and named candidates are, for large grids): its band "
                "is not known.\n")
    lo = float(work["workability_route_min"].sel(candidate=dg.best[0], tugger=dg.best[1]))
    hi = float(work["workability_route_max"].sel(candidate=dg.best[0], tugger=dg.best[1]))
    v = recommendation_holds(work, dg.best, eligible(cx))
    head = (f"*Uncertainty:* over damping 0.5-2 × nominal, sway frequency ±3 % and Hs at bin "
            f"centre or upper edge, the route workability of {t(combo_text(dg.best))} lies in "
            f"{t(pct(lo))}-{t(pct(hi))}; ")
    if v.holds:
        return head + f"the recommendation *holds* across the band (best in all {v.variants} variants).\n"
    return head + (f"the recommendation *does not hold* across the band: another combination is "
                   f"best in {len(v.losers)} of {v.variants} variants ({cx.sec('uncertainty')}).\n")


def voyage_sentence(cx: Context) -> str:
    """Page 1: the probability that the recommended option's voyage stays inside every
    limit (``voyage.nc``) and, when its median largest value exceeds a limit, by how much."""
    dg, v = cx.dg, cx.voyage
    inside = voyage_inside(v, dg.best)
    if inside is None:
        return ""
    text = (f"*Voyage:* the probability that the voyage of {t(combo_text(dg.best))} stays inside "
            f"every limit from departure to arrival is *{t(pct(inside))}* (independent sea "
            f"states, conservative; {cx.sec('voyage')})")
    crit = [str(c) for c in v["criterion"].values]
    lim = {c: float(v["limit"].sel(criterion=c)) for c in crit}
    c = max(crit, key=lambda c: voyage_level(v, dg.best, c, 0.5) / lim[c])
    x = voyage_level(v, dg.best, c, 0.5)
    if x > lim[c]:
        units = str(v["level_units"].sel(criterion=c).values) if "level_units" in v.coords else ""
        unit = {"1": "", "degree": "°"}.get(units, f" {units}")
        levels = {k: voyage_level(v, dg.best, k, 0.5) for k in crit}
        b = model_range.of(cx, v).beyond(c, dg.best, x, levels)
        if b is not None:                          # no figure the linear model cannot give
            text += (f"; its median largest {t(criterion_label(c))} lies {BEYOND_MODEL} ("
                     + (t(b.reason) if b.reason == model_range.SLACK else
                        f"above the {num(b.threshold, 1)}{t(unit)} of {t(b.reason)}") + ")")
        else:
            text += (f"; its median largest {t(criterion_label(c))} is {num(x, 1)}{t(unit)}, "
                     f"{x / lim[c]:.1f} times the limit")
    return text + ".\n"


def _selection_rule(dg) -> str:
    """How the recommended combination was chosen: the tie-break rule and what was
    excluded, and why. Infeasible rigging candidates are named with their reason (counted
    when there are more than :data:`MAX_EXCLUSIONS_NAMED`); the other exclusions are
    named by rigging with their short labels (the column "excluded" of table 1), or
    counted when they concern more riggings, and what the labels mean follows."""
    text = (f" (the highest route workability among the combinations not excluded; a tugger "
            f"only where it adds more than {num(100 * dg.tugger_min_gain, 1)} percentage points "
            f"over the best passive option and adds to it in every uncertainty variant; options "
            f"within {num(100 * dg.tie_tolerance, 2)} percentage points are tied and decided by "
            f"{TIE_RULE})")
    if not dg.excluded:
        return text
    infeasible = [c for c in dict.fromkeys(c for c, _ in dg.excluded)
                  if all(INFEASIBLE in dg.excluded.get((c, tg), Reason("", "")).short.split(", ")
                         for tg in dg.tuggers)]
    if len(infeasible) > MAX_EXCLUSIONS_NAMED:
        parts = [f"{len(infeasible)} rigging candidates that are not feasible"]
    else:
        parts = [f"{c}: {dg.infeasible.get(c) or 'a constraint is violated'}" for c in infeasible]
    rest = {ct: why for ct, why in dg.excluded.items() if ct[0] not in infeasible}
    per_rigging: dict = {}
    for (c, tg), why in rest.items():
        per_rigging.setdefault(c, []).append(f"{tg} ({why.short})")
    if len(per_rigging) > MAX_EXCLUSIONS_NAMED:
        parts.append(f"{len(rest)} combinations of {len(per_rigging)} feasible rigging candidates "
                     "(the column 'excluded' of the table below for those it lists, workability.nc "
                     "for all)")
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
    cap = (t("Workability per leg and for the route (duration-weighted) of every rigging candidate "
             "and tugger setting; baseline without tugger and best feasible combination in bold; "
             "governing: the criterion that decides most of the non-workable probability; "
             + at_limit_rule(cx.plant) + "; ") + cx.sec("plant") + t(
             " names the constraint; excluded: why the recommendation passes the combination "
             "over (the labels are explained with it)." + dg.table.table_caption()))
    size = "8.5pt" if len(header) <= 9 else "7.5pt" if len(header) <= 12 else "6.5pt"
    return table(cap, header, rows, size=size, label="tab-summary", caption_raw=True,
                 align="(left, left, right, center" + ", right" * (len(cx.legs) + 1) + ", left, left)")


__all__ = ["MAX_EXCLUSIONS_NAMED", "MAX_TIES_NAMED", "band_sentence", "chapter", "document_control", "notes",
           "page_one_warnings", "recommendation", "summary", "vessel_note", "voyage_sentence", "workability_table"]
