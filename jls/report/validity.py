"""The report's last chapter, "Assumptions and validity": the model's assumptions and the
cells outside the range of the linear model."""

from __future__ import annotations

from jls.report.context import Context
from jls.report.contract import LINEAR_ANGLE_DEG, LINEAR_SWAY_FACTOR, pct
from jls.report.markup import bullets, cell, num, t, table


def chapter(cx: Context) -> str:
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


__all__ = ["chapter"]
