"""Chapter "Uncertainty and sensitivity": workability bands over the plausible plant and
the Hs-in-bin choice, the route workability against the relative-sway limit, and whether
the recommendation holds (:mod:`jls.report.robustness`)."""

from __future__ import annotations

from jls.assessment import recommendation
from jls.assessment.recommendation import tie_key
from jls.report.contract import pct
from jls.report.markup import figure, num, t
from jls.report.robustness import (
    banded,
    has_bands,
    has_sensitivity,
    recommendation_holds,
    sensitivity_switches,
)
from jls.report.sections import Context, combo_text

MAX_LOSERS_NAMED = 4


def eligible(cx: Context) -> list:
    """The combinations the recommendation is chosen among: those no exclusion rule
    removes (an infeasible rigging, saturating winches; :mod:`jls.assessment.recommendation`), or
    all of them when every one is excluded, as the recommendation itself."""
    return recommendation.eligible(cx.dg.combos, cx.dg.excluded)


def band_sentence(cx: Context) -> str:
    """Page 1: the recommendation's band and whether it holds across it."""
    if not has_bands(cx.work):
        return ""
    dg, work = cx.dg, cx.work
    if not banded(work, dg.best):
        return (f"*Uncertainty:* the {t(dg.best[0])} rigging is a grid candidate that was not "
                "varied (only the baseline and named candidates are, for large grids); name it "
                "as a candidate to obtain its band.\n")
    lo = float(work["workability_route_min"].sel(candidate=dg.best[0], tugger=dg.best[1]))
    hi = float(work["workability_route_max"].sel(candidate=dg.best[0], tugger=dg.best[1]))
    v = recommendation_holds(work, dg.best, eligible(cx))
    head = (f"*Uncertainty:* over damping 0.5-2 × nominal, sway frequency ±3 % and Hs at bin "
            f"centre or upper edge, the route workability of {t(combo_text(dg.best))} lies in "
            f"{t(pct(lo))}-{t(pct(hi))}; ")
    if v.holds:
        return head + f"the recommendation *holds* across the band (best in all {v.variants} variants).\n"
    return head + (f"the recommendation *does not hold* across the band: another combination is "
                   f"best in {len(v.losers)} of {v.variants} variants (section "
                   "Uncertainty and sensitivity).\n")


def _variant_text(coords: dict) -> str:
    return (f"damping × {float(coords['damping_factor']):g}, sway frequency × "
            f"{float(coords['sway_frequency_factor']):g}, Hs at bin {coords['hs_in_bin']}")


def uncertainty(cx: Context) -> str:
    dg, work = cx.dg, cx.work
    out = ["= Uncertainty and sensitivity\n"]
    if has_bands(work):
        out.append(
            "Section 3.5 of the reference study identifies the sway damping (0.98 % of critical) "
            "from free decays and places the plausible range at about a factor of two in damping "
            "and ±3 % in the sway frequency. Every candidate is therefore also solved with the "
            "damping at 0.5, 1 and 2 times nominal and the sway frequency at 0.97, 1 and 1.03 "
            "times nominal (the sway mode's modal stiffness scaled, the other modes unchanged), "
            "and each variant is assessed with Hs at the bin centre and at its upper edge. The "
            "band of a combination runs from its lowest to its highest route workability over "
            "these variants and the nominal assessment.\n")
        out.append(figure(cx.figs["workability_bands"],
                          "Route workability per combination: nominal (diamond) and the band over "
                          "the plant variants and Hs choices (bar). Baseline without tugger and "
                          "best combination shaded. " + dg.dots.caption()))
        v = recommendation_holds(work, dg.best, eligible(cx)) if banded(work, dg.best) else None
        if v is None:
            out.append(f"The {t(dg.best[0])} rigging of the recommendation was not varied (a grid "
                       "candidate); name it as a candidate to obtain its band.\n")
        elif v.holds:
            out.append(f"The recommended {t(combo_text(dg.best))} stays the best feasible "
                       f"combination in every one of the {v.variants} variants: the "
                       "recommendation *holds* across the band.\n")
        else:
            named = "; ".join(f"{_variant_text(c)}: {w}" for c, w in v.losers[:MAX_LOSERS_NAMED])
            more = f" and {len(v.losers) - MAX_LOSERS_NAMED} more" if len(v.losers) > MAX_LOSERS_NAMED else ""
            out.append(f"#warning[The recommendation *does not hold* across the band: in "
                       f"{len(v.losers)} of {v.variants} variants another feasible combination "
                       f"has a higher route workability than {t(combo_text(dg.best))} "
                       f"({t(named)}{t(more)}).]\n")
    else:
        out.append("The workability dataset carries no uncertainty bands.\n")
    if has_sensitivity(work):
        lim = dg.limits.get("relative_sway_m")
        out.append("The clearance budget behind the relative-sway limit is itself an estimate. "
                   "Because the model is linear, every cell is re-judged for trial limits from "
                   f"{num(float(work['trial_limit'].min()), 1)} to {num(float(work['trial_limit'].max()), 1)} m "
                   "without solving the plant again (other criteria unchanged).\n")
        out.append(figure(cx.figs["criterion_sensitivity"],
                          "Route workability against the relative-sway limit" +
                          (f"; dotted: the configured {lim:g} m. " if lim is not None else ". ") +
                          dg.plot.caption()))
        runs = sensitivity_switches(work, eligible(cx),
                                    lambda ct: tie_key(ct, dg.baseline, {g: cx.c_tugger(g) for g in dg.tuggers},
                                                       dg.candidates, dg.tuggers))
        if len(runs) == 1:
            out.append(f"The best feasible combination is {t(combo_text(runs[0][1]))} at every "
                       "trial limit.\n")
        else:
            parts = [f"from {num(a, 2)} m: {combo_text(ct)}" for a, ct in runs]
            out.append("The best feasible combination changes with the limit: " + t("; ".join(parts)) + ".\n")
    return "\n".join(out)


__all__ = ["eligible", "band_sentence", "uncertainty"]
