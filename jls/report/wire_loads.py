"""Chapter "Wire loads": static and dynamic hoist-wire tensions, DAF, slack margin and the
tension criteria, from the tension statistics of ``response.nc`` (:mod:`jls.response.tension`)."""

from __future__ import annotations

import xarray as xr

from jls.assessment.workability import assessed_hs
from jls.names import MAX_TENSION_KN, MIN_TENSION_KN
from jls.report.context import Context, combo_text, heading
from jls.report.contract import flag, on_sea_grid, pct
from jls.report.markup import num, t, table
from jls.response.tension import dynamic_amplification, slack_margin

TENSION_CRITERIA = (MAX_TENSION_KN, MIN_TENSION_KN)


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


__all__ = ["TENSION_CRITERIA", "chapter", "workable_extremes"]
