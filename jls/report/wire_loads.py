"""Chapter "Wire loads": static and dynamic hoist-wire tensions, DAF, slack margin and the
tension criteria, from the tension statistics of ``response.nc`` (:mod:`jls.response.tension`)."""

from __future__ import annotations

import xarray as xr

from jls.assessment.workability import assessed_hs
from jls.names import MAX_TENSION_KN, MIN_TENSION_KN, WIRE_TENSION_CRITERION
from jls.report.context import Context, combo_text, heading
from jls.report.contract import flag, on_sea_grid, pct
from jls.report.markup import num, t, table
from jls.response.tension import dynamic_amplification, slack_margin

TENSION_CRITERIA = (MAX_TENSION_KN, MIN_TENSION_KN, WIRE_TENSION_CRITERION)


def workable_extremes(cx: Context, combo) -> xr.Dataset:
    """Per wire, over the route's workable cells of ``combo`` (probability > 0): the
    highest unit MPM [kN per m of Hs], the highest and lowest tension [kN], DAF and slack
    margin at the cell where they occur."""
    resp, sea = cx.resp, cx.sea
    unit = on_sea_grid(resp["tension_mpm"].sel(candidate=combo[0], tugger=combo[1]), sea)
    static = resp["tension_static"].sel(candidate=combo[0])
    hs = assessed_hs(sea, cx.dg.hs_in_bin)
    live = (sea["cell_probability"]) > 0
    ok = live & flag(on_sea_grid(cx.work["passes"].sel(candidate=combo[0], tugger=combo[1]), sea))
    cells = ("leg", "heading", "hs", "tz")
    dyn = (hs * unit).where(ok)
    top = dyn.max(cells)                               # the largest dynamic MPM of a workable cell
    return xr.Dataset({"static": static, "unit_mpm": unit.where(live).max(cells),
                       "t_max": static + top, "t_min": static - top,
                       "daf": dynamic_amplification(static, top, 1.0),
                       "slack_margin": slack_margin(static, top, 1.0), "any": ok.any()})


def chapter(cx: Context) -> str:
    dg, resp = cx.dg, cx.resp
    out = [heading("wire_loads", "Wire loads")]
    if "tension_mpm" not in resp or "tension_static" not in resp:
        out.append("The response dataset carries no wire-tension statistics (the plant was "
                   "given as matrices, without the wire geometry the tensions need); this "
                   "chapter is empty.\n")
        return "\n".join(out)
    out.append(
        "Each hoist wire is a linear spring, so its dynamic tension is a linear output of the "
        "plant: $T_(d,i) = k_i (partial L_i \\/ partial q dot q + partial L_i \\/ partial q_b "
        "dot q_b)$, with the length gradients of eq. 3.6 at rest. Its statistics at Hs = 1 m "
        "scale with Hs like the motions'. The dynamic tension is Gaussian and symmetric about "
        f"the static tension (the equilibrium of {cx.sec('plant')}), so the most probable maximum rise "
        "and drop over the exposure are equal. The table gives, per wire, over the route's "
        "*workable* sea states (probability above zero): the largest tension, the dynamic "
        "amplification factor DAF = max tension / static tension and the slack margin "
        "(static tension minus the largest MPM drop; negative: the linear model would let the "
        "wire go slack and no longer holds).\n")
    wires = [str(w) for w in resp["wire"].values]
    combos = list(dict.fromkeys([(dg.baseline, dg.no_tugger), dg.best]))
    rows = []
    for ct in combos:
        x = workable_extremes(cx, ct)
        for w in wires:
            s = x.sel(wire=w)
            rows.append([f"{ct[0]} / {ct[1]}", w, num(float(s["static"]), 0),
                         num(float(s["unit_mpm"]), 0), num(float(s["t_max"]), 0),
                         num(float(s["daf"]), 3), num(float(s["slack_margin"]), 0)])
    out.append(table(
        "Hoist-wire tensions of the baseline rigging without tugger and of the best combination "
        f"({combo_text(dg.best)}): static tension, the largest MPM of the dynamic tension per "
        f"metre of Hs over the route's sea states, and over its workable sea states the largest "
        f"tension, DAF and slack margin ({dg.exposure_h:g}-hour MPM, Hs at the bin "
        f"{dg.hs_in_bin}).",
        ["combination", "wire", "static [kN]", "MPM/Hs [kN/m]", "max [kN]", "DAF", "slack margin [kN]"],
        rows, size="8pt"))
    set_ = [c for c in TENSION_CRITERIA if c in dg.criteria]
    if not set_:
        out.append("No tension criterion is applied in this assessment: the tensions are reported, "
                   "not judged against a safe working load of the wires or a no-slack floor; the "
                   f"wires' capacity is among what was not assessed ({cx.sec('validity')}).\n")
        return "\n".join(out)
    share = (cx.work["governing_share"] * cx.sea["leg_weight"]).sum("leg")
    if WIRE_TENSION_CRITERION in set_:
        out.append(criterion_paragraph(cx, combos, share))
        set_ = [c for c in set_ if c != WIRE_TENSION_CRITERION]
        if not set_:
            return "\n".join(out)
    items = []
    for c in set_:
        what = "safe working load" if c == MAX_TENSION_KN else "minimum tension (no slack)"
        gov = [pct(float(share.sel(candidate=ct[0], tugger=ct[1], criterion=c))) for ct in combos]
        items.append(f"{what} {num(dg.limits[c], 0)} kN: probability of the route's failing sea "
                     f"states it governs {' and '.join(gov)} ({'; '.join(combo_text(ct) for ct in combos)})")
    out.append("*Tension criteria:* " + t("; ".join(items)) + ". A cell passes when every wire "
               "keeps $T_(s,i) + H_s "
               "\"MPM\"_i (H_s = 1) <= \"SWL\"$ (and stays above the floor); its limiting Hs is "
               "$(\"SWL\" - T_(s,i)) \\/ \"MPM\"_i (H_s = 1)$, the lowest over the wires.\n")
    return "\n".join(out)


def ceiling_kN(work: xr.Dataset) -> float:
    """The allowed highest tension of the wire-tension criterion [kN] (NaN: not judged)."""
    lim = work["limit"]
    if "tension_ceiling_kN" not in lim.coords:
        return float("nan")
    return float(lim["tension_ceiling_kN"].sel(criterion=WIRE_TENSION_CRITERION))


def criterion_paragraph(cx: Context, combos, share) -> str:
    """The wire-tension criterion: its floor and maximum with their sources, the share of the
    failing sea states it governs, and each option's DAF against the configured limit."""
    dg, work = cx.dg, cx.work
    floor = dg.limits[WIRE_TENSION_CRITERION]
    cap = ceiling_kN(work)
    src = work.attrs.get("tension_floor_source", "not stated")
    top = (f"at most {num(cap, 0)} kN, the safe working load times its factors"
           if cap == cap else "not judged: no safe working load is configured, so the highest "
           "tension is reported in the table above, not judged")
    gov = "; ".join(f"{t(combo_text(ct))} {pct(float(share.sel(candidate=ct[0], tugger=ct[1], criterion=WIRE_TENSION_CRITERION)))}"
                    for ct in combos)
    text = [f"*Wire-tension criterion:* a sea state fails where any hoist wire's lowest tension "
            f"falls to or below {num(100 * floor, 0)} % of its static tension ({t(src)}); a slack "
            f"wire always fails. In the frequency domain the lowest tension is the static tension "
            f"minus the {dg.exposure_h:g}-hour MPM of the dynamic tension; where a sea state ran in "
            f"the time domain, the recorded lowest tension decides. The highest tension: {top}. "
            f"Share of the route's failing sea states the criterion governs: {gov}.\n"]
    if "dynamic_amplification" in work:
        lim = float(work.attrs.get("daf_limit", float("nan")))
        rows = []
        for ct in dict.fromkeys([*combos, dg.best]):
            daf = float(work["dynamic_amplification"].sel(candidate=ct[0], tugger=ct[1]))
            rows.append([str(ct[0]), str(ct[1]), num(daf, 3), "above" if daf > lim else "within"])
        text.append(table(
            f"Dynamic amplification factor (DAF, the highest tension over the static tension of the "
            f"same wire, over each option's workable sea states) against the design value "
            f"{num(lim, 2)} ({work.attrs.get('daf_source', 'not stated')}). A DAF above it does not "
            f"fail a sea state; it means the rigging and the lift points must be checked for the "
            f"higher dynamic load.",
            ["rigging", "tugger", "DAF", f"against {num(lim, 2)}"], rows, size="8pt"))
    return "\n".join(text)


def binding_figures(cx: Context, combo=None) -> str:
    """Page 1 (for the lead to place): the wire-tension figures of the recommended option
    (``combo``, default the recommendation) when the wire tension binds it: the share of
    its failing sea states the criterion governs and its DAF against the design value; an
    empty string when the criterion is off or binds nothing."""
    work, dg = cx.work, cx.dg
    if WIRE_TENSION_CRITERION not in dg.criteria:
        return ""
    combo = combo or dg.best
    share = float(((work["governing_share"] * cx.sea["leg_weight"]).sum("leg")).sel(
        candidate=combo[0], tugger=combo[1], criterion=WIRE_TENSION_CRITERION))
    parts = []
    if share > 0:
        parts.append(f"the hoist-wire tension governs {pct(share)} of the route's sea states "
                     f"(a wire falling to {num(100 * dg.limits[WIRE_TENSION_CRITERION], 0)} % of its "
                     "static tension or going slack)")
    if "dynamic_amplification" in work:
        daf = float(work["dynamic_amplification"].sel(candidate=combo[0], tugger=combo[1]))
        lim = float(work.attrs["daf_limit"])
        if daf > lim:
            parts.append(f"its dynamic amplification of the wire tension is {num(daf, 2)}, above "
                         f"the design value {num(lim, 2)}: the rigging and lift points must be "
                         "checked for it")
    if not parts:
        return ""
    return f"*Wire tension:* {t('; '.join(parts))} ({cx.sec('wire_loads')}).\n"


__all__ = ["TENSION_CRITERIA", "binding_figures", "ceiling_kN", "chapter", "criterion_paragraph",
           "workable_extremes"]
