"""The report's chapter "Rigging": the screening of the rigging design (the study's
chapter 5) and the optimised rigging assessed beside the baseline.

Present when the route was screened (``screening.nc``, :func:`jls.design.screening.screening_dataset`)
and the optimum assessed as the candidate "optimised"; otherwise the chapter is empty.
It shows the sensitivity of the natural periods (figure 5.3), the screening surface
(figure 5.4), the two geometries, whether the optimum lies on a constraint and which,
the rotational MPMs beside the baseline's (section 5.7.3), the transfer functions,
operability curves and workability of both riggings, the recommended option against
every leg's scatter and the workable Tz window at the design Hs (tables 6.7-6.8).
"""

from __future__ import annotations

import numpy as np

from jls.plant.rigging import DESIGN_VARIABLES
from jls.report.contract import pct
from jls.report.figures_compare import tz_window
from jls.report.markup import cell, figure, num, t, table
from jls.report.sections import Context, combo_text

OPTIMISED = "optimised"
LABELS = {"top_spread_y": "top spread Y", "bottom_spread_y": "bottom spread Y",
          "bottom_spread_x": "bottom spread X", "drop_height": "drop height"}
OBJECTIVES = {"route_workability": "the route workability",
              "screening_sigma": "the worst relative-sway standard deviation over the screening envelope"}


def present(cx: Context) -> bool:
    """Whether the chapter has something to show."""
    s = cx.screening
    return (s is not None and bool(s.attrs.get("optimum_candidate"))
            and OPTIMISED in cx.work["candidate"].values)


def _period(cx, cand, dof):
    p = cx.plant.sel(candidate=cand)
    dom = p["dominant_dof"].values
    i = np.flatnonzero(dom == ["sway", "heave", "roll", "yaw"].index(dof))
    return float(p["natural_period"].values[i[0]]) if i.size else float("nan")


def rigging(cx: Context) -> str:
    """Chapter "Rigging" (empty when the route was not screened)."""
    if not present(cx):
        return ""
    s, dg = cx.screening, cx.dg
    a = s.attrs
    opt = str(a["optimum_candidate"])
    kinds = s["kind"].values
    n_grid = int((kinds == "grid").sum())
    n_feas = int(s["feasible"].values[kinds == "grid"].astype(bool).sum())
    variables = str(a["grid_variables"]).split()
    tugs = [str(x) for x in s["tugger"].values]
    out = ["= Rigging\n"]
    out.append(
        f"The rigging design was screened on a full-factorial grid of {n_grid} points over "
        f"{t(' and '.join(LABELS[v] for v in variables))} (the other design variables at the "
        f"baseline), for {len(tugs)} tugger settings ({t(', '.join(tugs))}). Every grid point "
        "was checked against the rigging constraints (taut wires, equilibrium, stability, "
        "design bounds, lead angles, splash clearance) and scored on the screening envelope "
        f"and on this route; {n_feas} of {n_grid} are feasible. The objective is "
        f"{t(OBJECTIVES.get(a['objective'], a['objective']))} with tugger {t(a['objective_tugger'])}; "
        f"the best feasible grid point was refined with a constrained optimiser "
        f"({t(a['refinement'])}). The result, screening candidate {t(opt)}, is assessed below "
        f"as the candidate *{OPTIMISED}* beside the {t(dg.baseline)} rigging.\n")
    out.append(figure(cx.figs["rigging_sensitivity"], "Natural periods against each design "
                      "variable, one at a time about the baseline (dashed); shaded: the feasible "
                      "range about the baseline (the study's figure 5.3)."))
    out.append(figure(cx.figs["rigging_surface"], f"Screening surface: {a['objective'].replace('_', ' ')} "
                      f"with tugger {a['objective_tugger']} over the screened grid, contours of the "
                      "sway natural period [s], infeasible candidates hatched, the baseline (circle) "
                      "and the optimum (star) marked (the study's figure 5.4)."))
    out.append(_design_table(cx, opt))
    out.append(_constraint_text(a))
    out.append(figure(cx.figs["rigging_geometry"], "Baseline and optimised rigging in the "
                      "transverse and longitudinal planes: wires from the anchors to the padeyes, "
                      "the jacket to its tip, the waterline and the splash-clearance line."))
    out.append(_rotational_table(cx))
    out.append(figure(cx.figs["rigging_compare"], "Baseline (black) and optimised (red) rigging: "
                      "relative sway and yaw per unit wave amplitude, and the limiting Hs against "
                      "Tz; one line style per tugger setting."))
    out.append(_workability_table(cx))
    out.append(figure(cx.figs["recommended_operability"], f"Operability curve of the recommended "
                      f"option, {combo_text(dg.best)}, over every leg's sea states (dots, area "
                      "proportional to the cell's probability); the steepness ceiling and the "
                      "design Hs."))
    out.append(_window_table(cx))
    return "\n".join(out)


def _design_table(cx, opt) -> str:
    s = cx.screening
    base, o = s.sel(candidate="baseline"), s.sel(candidate=opt)
    rows = [[LABELS[v] + " [m]", num(base[v], 3), num(o[v], 3), num(float(o[v]) - float(base[v]), 3)]
            for v in DESIGN_VARIABLES]
    for dof in ("sway", "yaw", "roll", "heave"):
        tb, to = _period(cx, "baseline", dof), _period(cx, OPTIMISED, dof)
        rows.append([f"{dof} natural period [s]", num(tb, 2), num(to, 2), num(to - tb, 2)])
    for name, label in (("splash_clearance_margin", "splash clearance margin [m]"),
                        ("side_lead_margin", "side lead margin [deg]"),
                        ("fore_aft_lead_margin", "fore-aft lead margin [deg]")):
        rows.append([label, num(base[name], 2), num(o[name], 2), num(float(o[name]) - float(base[name]), 2)])
    return table("Baseline and optimised rigging: design variables, natural periods and "
                 "constraint margins (positive: the constraint holds).",
                 ["", "baseline", OPTIMISED, "change"], rows)


def _constraint_text(a) -> str:
    if int(a["optimum_on_constraint"]):
        return (f"*The optimum lies on a constraint:* {t(a['active_constraints'])}. The objective "
                "would improve beyond it, so the design has no margin there for fabrication or "
                "positioning tolerances.\n")
    return ("*The optimum lies on no constraint:* every margin is larger than its tolerance; "
            "the objective itself has its best value inside the feasible region.\n")


def _rotational_table(cx) -> str:
    a = cx.screening.attrs
    rows = []
    for resp, unit in (("relative_sway", "m"), ("relative_roll", "deg"), ("relative_yaw", "deg")):
        b, o = float(a[f"baseline_{resp}_mpm_{unit}"]), float(a[f"optimum_{resp}_mpm_{unit}"])
        change = "–" if b == 0 else f"{100 * (o - b) / b:+.0f} %"
        rows.append([f"{resp.replace('_', ' ')} [{unit}]", num(b, 3), num(o, 3), change])
    worse = [r[0].split(" [")[0] for r in rows[1:] if r[3] != "–" and r[3].startswith("+")]
    note = (f" The optimisation raises the {' and '.join(worse)} MPM: an objective written on "
            "sway alone does not protect the rotational modes (the study's section 5.7.3); "
            "configure screening.constraints to bound them." if worse else "")
    return (table(f"Worst three-hour MPM over the screening envelope, tugger "
                  f"{a['objective_tugger']}: baseline beside the optimum.",
                  ["relative motion", "baseline", "optimum", "change"], rows)
            + (f"{t(note.strip())}\n" if note else ""))


def _workability_table(cx) -> str:
    legs = cx.legs
    rows = []
    for cand in ("baseline", OPTIMISED):
        for tg in [str(x) for x in cx.work["tugger"].values]:
            rows.append([f"{cand} / {tg}", *[pct(cx.w_leg((cand, tg), leg)) for leg in legs],
                         cell(pct(cx.w_route((cand, tg))), bold=True)])
    return table("Workability per leg and for the route, baseline and optimised rigging.",
                 ["rigging / tugger", *legs, "route"], rows)


def _window_table(cx) -> str:
    dg, work = cx.dg, cx.work
    hs = float(cx.screening.attrs["design_hs_m"])
    heads = [float(h) for h in work["heading"].values]
    combos = [(c, str(tg)) for c in ("baseline", OPTIMISED) for tg in work["tugger"].values]
    if dg.best not in combos:
        combos.append(dg.best)
    ref = {h: tz_window(work, (dg.baseline, dg.no_tugger), h, hs)[1] for h in heads}
    rows = []
    for combo in combos:
        for h in heads:
            lo, hi = tz_window(work, combo, h, hs)
            gain = hi - ref[h]
            rows.append([f"{combo[0]} / {combo[1]}" + (f", {h:g}°" if len(heads) > 1 else ""),
                         num(lo, 2), num(hi, 2),
                         "–" if combo == (dg.baseline, dg.no_tugger) or not np.isfinite(gain)
                         else f"{gain:+.2f}"])
    return table(f"Workable Tz window at the design Hs of {hs:g} m (screening.design_hs_m): the "
                 "Tz range in which the limiting Hs, capped by the steepness ceiling, reaches it, "
                 f"and the upper end gained over the {dg.baseline} rigging without tugger (the "
                 "study's tables 6.7-6.8). A lower end set by the ceiling is the same for every "
                 "combination.", ["rigging / tugger", "from Tz [s]", "to Tz [s]", "gained [s]"], rows)
