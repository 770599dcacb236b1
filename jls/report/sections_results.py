"""Sections 5-8 of the assessment report as Typst markup: sea states, operability,
workability, assumptions and validity."""

from __future__ import annotations

import numpy as np

from jls.report.contract import (
    LINEAR_ANGLE_DEG,
    LINEAR_SWAY_FACTOR,
    criterion_label,
    flag,
    governing_runs,
    on_sea_grid,
    pct,
)
from jls.report.figures import percent_axis_start
from jls.report.markup import bullets, cell, figure, num, t, table
from jls.report.sections import Context, criteria_text
from jls.report.sections_headings import headings_and_coverage

MAX_TZ_ROWS = 40
MAX_LIMIT_COLUMNS = 8


# -- 5 -------------------------------------------------------------------------------
def sea_states(cx: Context) -> str:
    sea, dg = cx.sea, cx.dg
    base = (dg.baseline, dg.no_tugger)
    out = ["= Sea states\n"]
    out.append("Each leg's wave statistics as a table of Hs-Tz cells. A cell whose centre lies "
               "above the wave-steepness ceiling is *flagged, not dropped*: it is assessed like "
               f"any other and its probability is reported. Cells are assessed at the Hs of their "
               f"*{t(dg.hs_in_bin)}* (attribute hs_in_bin).\n")
    rows = []
    for leg in cx.legs:
        s = sea.sel(leg=leg)
        hp = s["heading_probability"]
        heads = ", ".join(f"{float(h):g}° ({100 * float(p):.0f} %)" for h, p in zip(hp["heading"].values, hp.values)
                          if float(p) > 0)
        live = int((s["probability"] > 0).sum())
        rows.append([t(leg), num(s["duration_h"], 1), pct(float(s["leg_weight"])), str(live),
                     t(heads), pct(float(s["steep_probability"])), pct(cx.w_leg(base, leg))])
    out.append(table(f"Route legs: duration, weight in the route, cells with data, wave headings, "
                     f"probability in steep cells and workability of the {dg.baseline} rigging "
                     f"without tugger.", ["leg", "duration [h]", "weight", "cells", "headings",
                                          "steep", "workable"],
                     [[cell(r[0], raw=True), r[1], r[2], r[3], cell(r[4], raw=True), r[5], r[6]]
                      for r in rows], align="(left, right, right, right, left, right, right)"))
    out.append(headings_and_coverage(cx))
    for leg in cx.legs:
        s = sea.sel(leg=leg)
        out.append(figure(cx.figs[f"scatter_{leg}"],
                          f"Leg {leg}: {float(s['duration_h']):g} h, weight {pct(float(s['leg_weight']))}. "
                          f"Numbers: probability of each cell in per cent. Colour: pass or fail of the "
                          f"{dg.baseline} rigging without tugger ({criteria_text(dg)}); hatched: above the "
                          f"steepness ceiling ({pct(float(s['steep_probability']))} of the leg); triangle "
                          f"and bold: outside the linear range (section 8). Solid line: limiting Hs of "
                          f"the same combination; dashed: steepness ceiling.", width="88%"))
    return "\n".join(out)


# -- 6 -------------------------------------------------------------------------------
def operability(cx: Context) -> str:
    dg, work = cx.dg, cx.work
    out = ["= Operability\n"]
    out.append("The largest workable significant wave height at each zero-crossing period follows "
               "from the unit-Hs response because the model is linear (eq. 2.7):\n"
               "$ H_(s,lim)(T_z) = min(min_k X_(max,k) / X_k (H_s = 1 \"m\", T_z), "
               "H_(s,\"steep\")(T_z)) $\n"
               "with $X_k$ the most probable maximum of criterion $k$ and the wave-steepness "
               "ceiling as the upper bound, as in the study's figure 6.7.\n")
    out.append(figure(cx.figs["operability"], "Limiting Hs against Tz, one panel per rigging "
                      "candidate (and heading), one line per tugger setting; thin grey: the "
                      f"{dg.baseline} rigging without tugger for comparison; dashed grey: the "
                      "steepness ceiling, clipped at the top of each panel (the y-range shows the "
                      "limiting curves; above it the ceiling continues to rise). "
                      + dg.plot.caption()))
    groups: dict[str, list[str]] = {}
    heads = work["heading"].values
    for combo in dg.table.combos:
        for h in heads:
            runs = governing_runs(work, combo, h)
            txt = "; ".join(f"{'steepness ceiling' if lab == 'steepness' else criterion_label(lab)} "
                            f"{a:g}-{b:g} s" for lab, a, b in runs)
            groups.setdefault(txt, []).append(f"{combo[0]} / {combo[1]}"
                                              + (f" at {h:g}°" if len(heads) > 1 else ""))
    n_all = len(dg.table.combos) * len(heads)
    rows = [["all" if len(who) == n_all else "; ".join(who), txt] for txt, who in groups.items()]
    out.append(table("What limits Hs along the operability curve, by Tz range (candidate / tugger)."
                     + dg.table.table_caption(),
                     ["combinations", "governing (Tz range)"], rows,
                     columns="(1fr, 1fr)", align="(left, left)"))
    hl = work["hs_limit"]
    tz = hl.dropna("tz", how="all")["tz"].values
    step = max(1, int(np.ceil(tz.size / MAX_TZ_ROWS)))
    tz = tz[::step]
    shown = dg.table.combos
    chunks = [shown[i:i + MAX_LIMIT_COLUMNS] for i in range(0, len(shown), MAX_LIMIT_COLUMNS)]
    for h in heads:
        for k, cols in enumerate(chunks):
            header = ["Tz [s]", "ceiling [m]"] + [cell(f"{t(c[0], wrap=True)} \\ {t(c[1])}", raw=True)
                                                  for c in cols]
            rows = [[num(z, 2), num(work["steepness_limit"].sel(tz=z), 2),
                     *[num(hl.sel(candidate=c[0], tugger=c[1], heading=h, tz=z), 2) for c in cols]]
                    for z in tz]
            part = f", part {k + 1} of {len(chunks)}" if len(chunks) > 1 else ""
            out.append(table(f"Limiting Hs [m] per Tz at heading {h:g}°{part}"
                             + (f" (every {step}th period)" if step > 1 else "") + "."
                             + dg.table.table_caption(),
                             header, rows, size="8pt" if len(header) <= 7 else "7pt",
                             columns="(auto, auto" + ", 1fr" * len(cols) + ")"))
    return "\n".join(out)


# -- 7 -------------------------------------------------------------------------------
def workability(cx: Context) -> str:
    dg, work, sea = cx.dg, cx.work, cx.sea
    out = ["= Workability\n"]
    out.append("A leg's workability is the sum of the probabilities of its workable cells over "
               "Hs, Tz and heading; the route's weights the legs by duration. A failing cell is "
               "governed by the criterion with the highest utilisation (MPM over limit); the "
               "shares below split each leg's non-workable probability by that criterion.\n")
    out.append(figure(cx.figs["workability"], "Workability per leg and for the route, one row "
                      "per combination (route: filled diamond). The axis starts at "
                      f"{percent_axis_start(cx.work, dg.dots.combos):g} % to show the differences; "
                      "the values are in the table below. " + dg.dots.caption()))
    crit = dg.criteria
    header = ["candidate", "tugger", "leg", "workable", "fails", *[f"{criterion_label(c)}" for c in crit],
              "in steep cells"]
    rows = []
    for combo in dg.table.combos:
        share = work["governing_share"].sel(candidate=combo[0], tugger=combo[1])
        for k, leg in enumerate(cx.legs + ["route"]):
            if leg == "route":
                w = cx.w_route(combo)
                sh = {c: float((share.sel(criterion=c) * sea["leg_weight"]).sum()) for c in crit}
                steep = float((sea["steep_probability"] * sea["leg_weight"]).sum())
            else:
                w = cx.w_leg(combo, leg)
                sh = {c: float(share.sel(leg=leg, criterion=c)) for c in crit}
                steep = float(sea["steep_probability"].sel(leg=leg))
            bold = leg == "route"
            rows.append([cell(combo[0] if k == 0 else ""), cell(combo[1] if k == 0 else ""),
                         cell(leg, bold=bold), cell(pct(w), bold=bold), pct(1 - w),
                         *[pct(sh[c]) for c in crit], pct(steep)])
    out.append(table("Workable and non-workable probability per leg and for the route, the "
                     "non-workable part split by governing criterion, and the probability "
                     "in cells above the steepness ceiling." + dg.table.table_caption(), header, rows,
                     size="8pt" if len(header) <= 9 else "7pt",
                     align="(left, left, left" + ", right" * (len(header) - 3) + ")"))
    weight = sea["cell_probability"]
    base = (dg.baseline, dg.no_tugger)
    steep_pass = weight * flag(sea["steep"]) * flag(
        on_sea_grid(work["passes"].sel(candidate=base[0], tugger=base[1]), sea))
    sp = float((steep_pass.sum(("heading", "hs", "tz")) * sea["leg_weight"]).sum())
    out.append(f"Steep cells are kept: {t(pct(sp))} of the route's probability lies in steep cells "
               f"that the {t(dg.baseline)} rigging without tugger passes; excluding them would lower "
               f"its route workability by that much. Cross-check: the route workability recomputed "
               f"from the pass flags and the cell and heading probabilities agrees with "
               f"workability.nc to {dg.recheck:.1e}.\n")
    if dg.recheck > 1e-6:
        out.append("#warning[The workability in workability.nc does not follow from its own pass "
                   "flags and the sea-state probabilities; the datasets are inconsistent.]\n")
    return "\n".join(out)


# -- 8 -------------------------------------------------------------------------------
def validity(cx: Context) -> str:
    dg = cx.dg
    cycles = dg.mpm_cycles
    items = [
        "*Linear frequency-domain model* (section 3.3, eq. 3.10): $M dot.double(q) + C dot(q) + K q "
        "= -K_b q_b$, linearised about the static equilibrium; responses scale with Hs at fixed Tz, "
        "which is what makes eq. 2.7 and the unit-Hs statistics exact within the model.",
        "*Damping*: Rayleigh, $C = alpha M + beta K$, anchored on the configured modes (section 3.5); "
        "no aerodynamic drag and no amplitude dependence.",
        f"*Most probable maximum*: $\"MPM\" = sigma sqrt(2 ln N)$ over an exposure of "
        f"{num(dg.exposure_h, 1)} h with N from {t(cycles)} (attributes exposure_h and mpm_cycles "
        "of response.nc); a Rayleigh distribution of the peaks of a narrow-banded response.",
        f"*Hs in a bin*: each cell is assessed at the {t(dg.hs_in_bin)} of its Hs bin"
        + (" (non-conservative by up to half a bin width)." if dg.hs_in_bin == "centre"
           else " (conservative)."),
        f"*Wave spectrum*: {t(cx.resp.attrs.get('spectrum', 'JONSWAP'))}, gamma "
        f"{t(cx.resp.attrs.get('gamma', '?'))}, long-crested, one heading per state with the "
        "leg's heading probabilities.",
        "*Light lift*: the vessel's motion is unaffected by the jacket (RAOs of the vessel alone), "
        "and the jacket hangs *in air* during transit: no hydrodynamic loads on it.",
        "*Tugger* modelled as a linear damper between fairlead and jacket (section 6.7 form) "
        "*without winch limits*, line compliance or slack; in long waves a real winch saturates "
        "(study section 6.5) and the benefit shown here is an upper bound.",
        "*No structural check* of slings, wires or lift points: the static tensions of section 3 "
        "are reported, dynamic tensions and lift-point capacities are not assessed.",
    ]
    out = ["= Assumptions and validity\n", bullets(items)]
    out.append("*Validity of the linear model.* The study found the linear model to over-predict "
               "the nonlinear reference at large motions, by 16.8 % and 33.4 % at and beyond the "
               "longest periods of its design envelope (chapter 4; geometric stiffening, "
               "amplitude-dependent damping), and to agree within 5.4 % inside it. Cells are "
               f"therefore flagged as outside the linear range when their MPM relative sway exceeds "
               f"{num(LINEAR_SWAY_FACTOR, 0)} × the relative-sway limit or their MPM relative roll or "
               f"yaw exceeds {num(LINEAR_ANGLE_DEG, 0)}°. A flagged cell that fails on sway fails by "
               "at least a factor of two, more than the largest over-prediction, so its verdict "
               "stands; a flagged cell that passes rests on the model outside its range.\n")
    rows = []
    for combo, lin in dg.linear.items():
        legs = "; ".join(f"{leg} {pct(p)}" for leg, p in lin["leg_probability"].items())
        rows.append([combo[0], combo[1], f"{lin['cells']} of {lin['live_cells']}",
                     pct(lin["route_probability"]), cell(t(legs), raw=True),
                     f"{lin['passing_cells']} ({pct(lin['passing_probability'])})"])
    out.append(table(f"Cells with data outside the linear range (relative sway MPM > "
                     f"{LINEAR_SWAY_FACTOR:g} × limit, or relative roll or yaw MPM > "
                     f"{LINEAR_ANGLE_DEG:g}°): number, route probability, per leg, and how many of "
                     f"them pass.", ["candidate", "tugger", "cells", "route", "per leg", "passing"],
                     rows, columns="(auto, auto, auto, auto, 1fr, auto)",
                     align="(left, left, right, right, left, right)"))
    base = dg.linear[(dg.baseline, dg.no_tugger)]
    if not base["sway_limit_found"]:
        out.append("#note[No relative-sway criterion is configured; the sway flag uses 3.0 m as "
                   "its reference limit.]\n")
    out.append(f"For the {t(dg.baseline)} rigging without tugger, {base['cells']} cells carrying "
               f"{t(pct(base['route_probability']))} of the route's probability lie outside the "
               f"linear range, {base['passing_cells']} of them passing.\n")
    return "\n".join(out)
