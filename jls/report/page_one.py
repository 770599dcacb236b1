"""The short parts of page 1 (:func:`jls.report.summary.summary`): the recommendation and
why in at most five short sentences, the table of each leg's governing criterion and
margin, the criteria that bind the recommendation with their figures, the caveats on the
vessel data and the sea model, and the inputs' warnings counted. Each states its figure
once, against one reference, and points to the chapter "Assessment in detail"
(:mod:`jls.report.assessment`) or the chapter that holds the rest."""

from __future__ import annotations

from jls.assessment.recommendation import effective_objective
from jls.io.netcdf import warnings_of
from jls.names import WIRE_TENSION_CRITERION
from jls.report import plan_verdict as pv
from jls.report import spectra, wire_loads
from jls.report.basis import BEYOND_MODEL, model_threshold, voyage_level
from jls.report.context import Context, combo_text, representative
from jls.report.contract import criterion_label, pct
from jls.report.markup import num, t, table

MAX_WARNING_CHARS = 160     # input warnings printed in full on page 1 up to this length; more are counted


def why(cx: Context) -> str:
    """The recommendation and why: at most five short sentences, no nested parentheses,
    every percentage-point figure against the baseline rigging without tugger."""
    dg = cx.dg
    base = (dg.baseline, dg.no_tugger)
    if not cx.feasible(dg.best[0]):
        return ("*Recommendation:* none of the assessed rigging candidates is feasible; revise the "
                f"rigging before the transit ({cx.sec('plant')}).\n")
    s = [f"*Recommendation: {t(combo_text(dg.best))}.*"]
    gain = cx.w_route(dg.best) - cx.w_route(base)
    if effective_objective(cx.work) == "voyage_plan" and cx.plan is not None \
            and "plan_inside_probability" in cx.work:
        def exc(combo):
            return 1 - float(cx.work["plan_inside_probability"].sel(candidate=combo[0], tugger=combo[1]))
        s.append(f"A voyage sailed by the departure rule exceeds a limit with probability "
                 f"{num(exc(dg.best), 3)}, against {num(exc(base), 3)} with the {t(dg.baseline)} "
                 "rigging without tugger.")
    elif dg.best == base or gain <= dg.tie_tolerance:
        s.append(f"No assessed change raises the route workability, {t(pct(cx.w_route(base)))}, "
                 f"of the {t(dg.baseline)} rigging without tugger.")
    else:
        s.append(f"Its route workability is {t(pct(cx.w_route(dg.best)))}, {num(100 * gain, 1)} "
                 f"percentage points above the {t(dg.baseline)} rigging without tugger.")
    n_ex = len(dg.excluded)
    s.append("It is the best option the selection rules allow"
             + (f"; they exclude {n_ex} combination{'s' if n_ex > 1 else ''}" if n_ex else "")
             + f" ({cx.sec('assessment')}).")
    if dg.best_any != dg.best and cx.w_route(dg.best_any) > cx.w_route(dg.best) + dg.tie_tolerance:
        s.append(f"The highest workability, {t(pct(cx.w_route(dg.best_any)))}, belongs to "
                 f"{t(combo_text(dg.best_any))}, which a rule excludes.")
    if dg.ties:
        s.append(f"{len(dg.ties)} other option{'s' if len(dg.ties) > 1 else ''} tie with it; "
                 "the tie-break rule decides.")
    return " ".join(s[:5]) + "\n"


def _leg_share(cx: Context, combo, leg: str) -> tuple[str | None, float]:
    """The criterion that fails most of the leg's probability for ``combo``, and that share."""
    g = cx.work["governing_share"].sel(candidate=combo[0], tugger=combo[1], leg=leg)
    shares = {str(c): float(g.sel(criterion=c)) for c in g["criterion"].values}
    c = max(shares, key=shares.get) if shares else None
    return (c, shares[c]) if c is not None and shares[c] > 0 else (None, 0.0)


def legs_table(cx: Context) -> str:
    """Each leg's governing criterion and margin for the recommendation: the criterion that
    fails most of its sea states, and (with ``voyage_plan.nc``) the design check's largest
    utilisation in the leg's design sea state."""
    dg, p = cx.dg, cx.plan
    best = dg.best
    design = p is not None and "design_utilisation" in p
    header = ["leg", "workability", "governing criterion", "sea states it fails"]
    if design:
        years = num(float(p.attrs.get("design_return_period_years", 10)), 0)
        header += [f"{years}-year design check", "margin"]
    rows = []
    for leg in cx.legs:
        c, share = _leg_share(cx, best, leg)
        row = [leg, pct(cx.w_leg(best, leg)), criterion_label(c) if c else "none fails",
               pct(share) if c else "–"]
        if design:
            u = pv.option_at(p["design_utilisation"], best).sel(leg=leg)
            cd = str(u["criterion"].values[int(u.argmax("criterion"))])
            x = float(u.sel(criterion=cd))
            if x <= 1:
                row += [f"{criterion_label(cd)}, {pct(x)} of its limit", pct(1 - x)]
            else:
                lvl = float(pv.option_at(p["design_level"], best).sel(criterion=cd, leg=leg))
                lim = float(p["limit"].sel(criterion=cd))
                lvl_text = pv.level_text(p, cd, lvl)
                row += [f"{criterion_label(cd)} {lvl_text.split(' (')[0]}"
                        + ("" if lvl_text.startswith(BEYOND_MODEL) else f" against {pv.level_text(p, cd, lim)}"),
                        "exceeded"]
        rows.append(row)
    cap = (f"Governing criterion and margin per leg, {combo_text(best)}"
           + (": the design check in the leg's design sea state" if design else "") + ".")
    return table(cap, header, rows, size="8pt", label="tab-legs",
                 align="(" + ", ".join(["left", "right", "left", "right"] + (["left", "right"] if design else []))
                 + ")")


def binding(cx: Context) -> str:
    """Every criterion that binds the recommendation, with its figure: the criteria that
    fail its sea states, those its design check exceeds, and those its voyage extremes
    exceed (the wire tension's own figures follow, :func:`jls.report.wire_loads.binding_figures`)."""
    dg, best = cx.dg, cx.dg.best
    share = dict(dg.governing.get(best, {}))
    if wire_loads.binding_figures(cx):        # stated there, with the DAF
        share.pop(WIRE_TENSION_CRITERION, None)
    parts = [f"{criterion_label(c)} fails {pct(x)} of the route's sea states"
             for c, x in sorted(share.items(), key=lambda kv: -kv[1]) if x > 0]
    p = cx.plan
    if p is not None and "design_utilisation" in p:
        u = pv.option_at(p["design_utilisation"], best)
        over: dict = {}
        for c in u["criterion"].values:
            legs = tuple(str(leg) for leg in u["leg"].values if float(u.sel(criterion=c, leg=leg)) > 1)
            if legs:
                over.setdefault(legs, []).append(criterion_label(str(c)))
        for legs, names in over.items():
            parts.append(f"{', '.join(names)} exceed{'s' if len(names) == 1 else ''} the limit in the "
                         f"design sea state of {'every leg' if len(legs) == u.sizes['leg'] > 1 else ', '.join(legs)}")
    v = cx.voyage
    if v is not None and best[0] in v["candidate"].values and best[1] in v["tugger"].values:
        for c in (str(x) for x in v["criterion"].values):
            lim, x = float(v["limit"].sel(criterion=c)), voyage_level(v, best, c, 0.5)
            if x <= lim:
                continue
            units = str(v["level_units"].sel(criterion=c).values) if "level_units" in v.coords else ""
            thr = model_threshold(units, lim)
            fig = BEYOND_MODEL if thr is not None and x > thr else f"{x / lim:.1f} times its limit"
            parts.append(f"the voyage's median largest {criterion_label(c)} is {fig}")
    if not parts:
        return "*Binding criteria:* none; no sea state of the route fails the recommendation.\n"
    refs = [cx.sec("workability")] + ([cx.sec("voyage")] if cx.has("voyage") and v is not None else [])
    return f"*Binding criteria:* {t('; '.join(parts))} ({', '.join(refs)}).\n"


def caveats(cx: Context) -> str:
    """The vessel data and the sea model, each in a sentence (what was verified follows,
    :mod:`jls.report.verification`)."""
    attrs = cx.vessel.attrs
    statement = str(attrs.get("vessel_statement", "")).strip()
    rep = str(attrs.get("vessel_data", "")) == "representative" or (
        not statement and representative(cx.prov.get("vessel_description", "")))
    if not statement:
        statement = ("The vessel motions come from a representative hull, not from the vessel's "
                     "own RAOs" if rep else "The vessel motions are the configured RAO file's")
    text = f"*Vessel:* {t(statement.rstrip('.'))}, {cx.sec('vessel')}."
    if rep and "representative" not in statement:
        text += " Treat the percentages as the class's."
    if spectra.page_one_warning(cx):
        sea = ""                                  # the warning that follows states it, with the ratio
    elif cx.measured is not None:
        sea = (f" *Sea model:* the legs given by measured spectra are integrated over their own seas "
               f"({cx.sec('spectra')}); the other legs are single-peaked JONSWAP seas on their Hs-Tz tables.")
    else:
        sea = (" *Sea model:* single-peaked JONSWAP seas on each leg's Hs-Tz table; a wind sea and a swell "
               f"at different periods are not represented ({cx.sec('sea_states')}).")
    return text + sea + "\n"


def input_warnings(cx: Context) -> str:
    """The inputs' warnings (workability.nc, attribute ``warnings``): in full when short,
    else counted with a reference to the full list (chapter "Assessment in detail")."""
    lines = warnings_of(cx.work)
    if not lines:
        return ""
    where = cx.sec("assessment")
    if sum(len(x) for x in lines) <= MAX_WARNING_CHARS:
        return f"#warning[*Input warnings:* {t('; '.join(x.rstrip('.') for x in lines))} ({where}).]\n"
    return f"*Input warnings:* {len(lines)}, listed in full in {where}.\n"


__all__ = ["MAX_WARNING_CHARS", "binding", "caveats", "input_warnings", "legs_table", "why"]
