"""The report's chapter "Assessment in detail", right after the one-page summary: what
page 1 states in short, in full. The route and how workability is defined, the headline
figures, the recommendation with its selection rule and exclusions, the voyage extremes,
the uncertainty band, the operational basis, the governing criterion along the operability
curve, the notes on ties and constraints, the vessel data and hinge geometry, the inputs'
warnings in full (workability.nc, attribute ``warnings``) and table 1 of every listed
combination."""

from __future__ import annotations

from jls.io.netcdf import warnings_of
from jls.report import summary as sm
from jls.report.basis import summary_sentence
from jls.report.context import Context, combo_text, criteria_text, heading
from jls.report.contract import criterion_label, pct
from jls.report.curves import governing_runs
from jls.report.markup import bullets, num, plural, t


def chapter(cx: Context) -> str:
    """The chapter's markup (see :mod:`jls.report.chapters`)."""
    dg, sea = cx.dg, cx.sea
    base = (dg.baseline, dg.no_tugger)
    dur = float(sea["duration_h"].sum())
    out = [heading("assessment", "Assessment in detail")]
    desc = str(cx.prov.get("route_description") or "").strip()
    out.append(f"Route *{t(dg.route)}*" + (f": {t(desc.rstrip('.'))}. It is sailed in " if desc else " in ")
               + f"{plural(len(cx.legs), 'leg')} ({t(', '.join(cx.legs))}), "
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
    out.append(sm.recommendation(cx))
    out.append(sm.voyage_sentence(cx))
    out.append(sm.band_sentence(cx))
    out.append(summary_sentence(cx))
    out.append(governing_sentence(cx))
    out.extend(sm.notes(cx))
    out.append(sm.vessel_note(cx))
    lines = warnings_of(cx.work)
    if lines:
        out.append(f"*Input warnings* ({len(lines)}), from the inputs and the assessment:\n"
                   + bullets([t(w) for w in lines]) + "\n")
    out.append(sm.workability_table(cx))
    return "\n".join(out)


def governing_sentence(cx: Context) -> str:
    """The criterion that decides most of the baseline's non-workable probability, and
    the criteria that set the limiting Hs along the operability curve."""
    dg = cx.dg
    base = (dg.baseline, dg.no_tugger)
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
    return text + ".\n"


__all__ = ["chapter", "governing_sentence"]
