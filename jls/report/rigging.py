"""The report's chapter "Rigging": the screening of the rigging design (the study's
chapter 5) and the optimised rigging assessed beside the baseline.

Present when the route was screened (``screening.nc``, :func:`jls.design.screening.screening_dataset`)
and the optimum assessed as the candidate "optimised"; otherwise the chapter is empty.
It shows the sensitivity of the natural periods (figure 5.3), the screening surface
(figure 5.4), the two geometries, whether the optimum lies on a constraint and which,
the rotational MPMs beside the baseline's (the study's section 5.7.3), and then the
comparison of the riggings (:mod:`jls.report.rigging_compare`): transfer functions and
operability curves, the recommended option against every leg's scatter and the workable
Tz window at the design Hs (the study's tables 6.7-6.8). The optimiser's own message is
never printed: :func:`refinement_text` says in words how the refinement ended.

The screening figures take ``screening.nc`` and return a matplotlib Figure (the plan
saves it):

* :func:`sensitivity` - natural periods against each design variable (figure 5.3);
* :func:`screening_surface` - the score over the screened grid with sway-period
  contours, the infeasible region hatched, baseline and optimum marked (figure 5.4);
* :func:`geometry` - baseline and optimised rigging in two projections with the
  waterline, the jacket tip and the splash clearance (figure 5.5).
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle

from jls.names import RELATIVE_ROLL, RELATIVE_SWAY, RELATIVE_YAW
from jls.plant import same_rigging
from jls.plant.linearise import DOF
from jls.plant.rigging import DESIGN_VARIABLES
from jls.report import rigging_compare
from jls.report.context import Context, combo_text, heading, screened
from jls.report.margins import margin_table
from jls.report.markup import figure, num, ref, signed, t, table
from jls.report.rigging_compare import OPTIMISED, window_table
from jls.report.style import STYLE, TRANSFER_DECADES, Task, log_ticks, new_figure, save

LABELS = {"top_spread_y": "top spread Y", "bottom_spread_y": "bottom spread Y",
          "bottom_spread_x": "bottom spread X", "drop_height": "drop height"}
AXIS_LABELS = {var: f"{label} [m]" for var, label in LABELS.items()}
OBJECTIVES = {"route_workability": "the route workability",
              "screening_sigma": "the worst relative-sway standard deviation over the screening envelope"}
DOF_COLOURS = {"sway": "tab:blue", "yaw": "tab:orange", "roll": "tab:green", "heave": "tab:purple"}
SCORES = {"route_workability": ("route workability [%]", 100.0, "viridis"),
          "screening_sigma": ("worst relative-sway sigma over the envelope [m]", 1.0, "viridis_r"),
          "workability_surrogate": ("route workability, bin-smoothed [%]", 100.0, "viridis")}


def present(cx: Context) -> bool:
    """Whether the chapter has something to show (:func:`jls.report.context.screened`)."""
    return screened(cx)


def _period(cx, cand, dof):
    p = cx.plant.sel(candidate=cand)
    dom = p["dominant_dof"].values
    i = np.flatnonzero(dom == DOF.index(dof))
    return float(p["natural_period"].values[i[0]]) if i.size else float("nan")


def figure_plan(cx: Context) -> list[Task]:
    """The chapter's figures (none when it is empty): the screening's three, then the
    comparison's (:func:`jls.report.rigging_compare.figure_plan`)."""
    if not present(cx):
        return []
    s = cx.screening
    return [Task("rigging_sensitivity", lambda d: save(sensitivity(s), d, "rigging_sensitivity"), 2.5),
            Task("rigging_surface", lambda d: save(screening_surface(s), d, "rigging_surface"), 1.8),
            Task("rigging_geometry", lambda d: save(geometry(s), d, "rigging_geometry"), 1.3),
            *rigging_compare.figure_plan(cx)]


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
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
    out = [heading("rigging", "Rigging")]
    out.append(
        f"The rigging design was screened on a full-factorial grid of {n_grid} points over "
        f"{t(' and '.join(LABELS[v] for v in variables))} (the other design variables at the "
        f"baseline), for {len(tugs)} tugger settings ({t(', '.join(tugs))}). Every grid point "
        "was checked against the rigging constraints (taut wires, equilibrium, stability, "
        "design bounds, lead angles, splash clearance) and scored on the screening envelope "
        f"and on this route; {n_feas} of {n_grid} are feasible. The objective is "
        f"{t(OBJECTIVES.get(a['objective'], a['objective']))} with tugger {t(a['objective_tugger'])}; "
        f"{t(refinement_text(a))}. The result, screening candidate {t(opt)}, is assessed "
        f"as the candidate *{OPTIMISED}* beside the {t(dg.baseline)} rigging (every option's "
        f"workability is in {ref('tab-summary', 'table')}){_same_as(cx)}.\n")
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
    out.append(margin_table(cx))
    out.append(_rotational_table(cx))
    out.append(figure(cx.figs["rigging_compare"], "Baseline (black) and optimised (red) rigging: "
                      "relative sway and yaw per unit wave amplitude (over "
                      f"{TRANSFER_DECADES:g} decades below the largest amplitude), and the limiting "
                      "Hs against Tz; one line style per tugger setting."))
    out.append(figure(cx.figs["recommended_operability"], f"Operability curve of the recommended "
                      f"option, {combo_text(dg.best)}, over every leg's sea states (a dot per cell, "
                      "area proportional to its probability, marker per leg; green: the cell "
                      "passes, red: it fails, orange: it passes at some headings); the steepness "
                      "ceiling, which leaves the axis where it no longer limits, and the design Hs."))
    out.append(window_table(cx))
    return "\n".join(out)


def _same_as(cx) -> str:
    """The screening's optimum landing on a configured candidate, said once."""
    name = same_rigging.alias(cx.work, OPTIMISED)
    if name in (None, OPTIMISED):
        return ""
    tol = 100 * float(cx.work.attrs.get("same_rigging_tolerance_m", 0.01))
    return (f". It is the same rigging as the configured candidate *{t(name)}* (every anchor and "
            f"padeye within {tol:g} cm): one option, named {t(name)} in the tables")


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


def refinement_text(a) -> str:
    """How the refinement ended, in words (attributes ``refinement`` and
    ``refinement_evaluations`` of screening.nc; the optimiser's message is translated,
    never printed)."""
    status = str(a.get("refinement", ""))
    n = int(a.get("refinement_evaluations", 0) or 0)
    evals = f" in {n} evaluations" if n else ""
    start = status.split(":", 1)[0].removeprefix("refined from ").removeprefix("refinement from ")
    start = start.split(" ended", 1)[0]
    if status.startswith("refined from"):
        return (f"the best feasible grid point ({start}) was refined with a constrained optimiser "
                f"(COBYQA), which {_ending(status)}{evals}")
    if status.startswith("refinement from"):
        worse = "worse" if "worse" in status else "infeasible"
        return (f"a refinement of the best feasible grid point ({start}) ended at a design that is "
                f"{worse}{evals}, so the grid point is kept")
    if status.startswith("best grid point"):
        return "the best feasible grid point is the optimum (no refinement was run)"
    return "no grid point is feasible"


def _ending(status: str) -> str:
    """The optimiser's stopping reason in words."""
    low = status.lower()
    if "trust-region radius" in low or "converged" in low or "successfully" in low:
        return "converged (its step fell to the design resolution)"
    if "maximum number" in low or "evaluations" in low or "iterations" in low:
        return "stopped at its evaluation limit without converging"
    if "infeasible" in low:
        return "stopped on an infeasible step"
    return "stopped without stating convergence"


def _constraint_text(a) -> str:
    budget = float(a.get("splash_clearance_budget_m", 0.0))
    kept = (f"the screening and the refinement tightened every safety constraint by its tolerance "
            f"budget (splash clearance {num(budget, 2)} m: {t(str(a.get('splash_clearance_budget', '')))}), "
            "so a safety margin there is its budget, no less; a design bound has none"
            if budget > 0 else "the safety constraints carry no tolerance budget, so the design has "
            "no margin there for fabrication or positioning tolerances")
    if int(a["optimum_on_constraint"]):
        return (f"*The optimum lies on a constraint:* {t(a['active_constraints'])}. The objective "
                f"would improve beyond it; {kept}.\n")
    return ("*The optimum lies on no constraint:* every margin is larger than its budget; "
            "the objective itself has its best value inside the feasible region.\n")


def _rotational_table(cx) -> str:
    a = cx.screening.attrs
    rows = []
    for resp, unit in ((RELATIVE_SWAY, "m"), (RELATIVE_ROLL, "deg"), (RELATIVE_YAW, "deg")):
        b, o = float(a[f"baseline_{resp}_mpm_{unit}"]), float(a[f"optimum_{resp}_mpm_{unit}"])
        change = "–" if b == 0 else signed(100 * (o - b) / b, 0) + " %"
        rows.append([f"{resp.replace('_', ' ')} [{unit}]", num(b, 3), num(o, 3), change])
    worse = [r[0].split(" [")[0] for r in rows[1:] if r[3] != "–" and r[3].startswith("+")]
    judged = [w for w in worse if any(c.startswith(w.replace(" ", "_")) for c in cx.dg.criteria)]
    free = [w for w in worse if w not in judged]
    note = ""
    if worse:
        note = (f" The optimisation raises the {' and '.join(worse)} MPM: an objective written on "
                "sway alone does not protect the rotational modes (the study's section 5.7.3).")
        if free:
            note += (f" No criterion of this assessment limits the {' or '.join(free)}, so the "
                     "increase is reported here and judged nowhere.")
        if judged:
            note += f" The {' and '.join(judged)} is judged by its criterion in every cell."
    return (table(f"Worst three-hour MPM over the screening envelope, tugger "
                  f"{a['objective_tugger']}: baseline beside the optimum.",
                  ["relative motion", "baseline", "optimum", "change"], rows)
            + (f"{t(note.strip())}\n" if note else ""))


# -- figures ----------------------------------------------------------------------------
def period_by_dof(periods: np.ndarray, dominant: np.ndarray, dof: str) -> np.ndarray:
    """Period of the mode dominated by ``dof`` (NaN where no mode or several are)."""
    mask = np.asarray(dominant) == DOF.index(dof)
    one = mask.sum(-1) == 1
    return np.where(one, np.where(mask, periods, 0.0).sum(-1), np.nan)


def sensitivity(screening: xr.Dataset) -> Figure:
    """Natural periods against each design variable, one at a time about the baseline
    (dashed), the feasible range about the baseline shaded (figure 5.3)."""
    with matplotlib.rc_context(STYLE):
        fig = new_figure(4.6)
        axes = fig.subplots(2, 2, sharey=True).ravel()
        for ax, var in zip(axes, DESIGN_VARIABLES):
            s = screening.sel(variable=var)
            x = s["sensitivity_value"].values
            for dof in ("sway", "yaw", "roll", "heave"):
                t = period_by_dof(s["sensitivity_period"].values, s["sensitivity_dominant_dof"].values, dof)
                ax.semilogy(x, t, color=DOF_COLOURS[dof], label=f"{dof} mode")
            lo, hi = float(s["feasible_lower"]), float(s["feasible_upper"])
            if np.isfinite(lo) and np.isfinite(hi):
                ax.axvspan(lo, hi, color="tab:green", alpha=0.10, lw=0, label="feasible range")
            bad = ~s["sensitivity_feasible"].values.astype(bool)
            if bad.any():
                ax.plot(x[bad], np.full(bad.sum(), 0.9), "x", color="tab:red", ms=3,
                        label="infeasible", transform=ax.get_xaxis_transform())
            ax.axvline(float(s["baseline_value"]), color="k", ls="--", lw=0.8, label="baseline")
            ax.set_xlabel(AXIS_LABELS[var])
            ax.set_xlim(x.min(), x.max())
        for ax in axes[::2]:
            ax.set_ylabel("natural period [s]")
        axes[0].set_ylim(0.8, 40.0)
        log_ticks(axes[0].yaxis)                     # shared by the four panels
        handles, labels = axes[0].get_legend_handles_labels()
        for ax in axes[1:]:
            for h, lab in zip(*ax.get_legend_handles_labels()):
                if lab not in labels:
                    handles.append(h)
                    labels.append(lab)
        fig.legend(handles, labels, loc="outside lower center", ncol=4)
        return fig


def _grid_slice(screening: xr.Dataset):
    """Grid candidates on the plane of the first two screened variables, through the
    optimum (or the baseline) in the others: (x var, y var, x, y, index array)."""
    variables = screening.attrs["grid_variables"].split()
    grid = screening["kind"].values == "grid"
    ref = screening.attrs["optimum_candidate"] or "baseline"
    keep = grid.copy()
    for var in variables[2:]:
        vals = screening[var].values
        target = float(screening[var].sel(candidate=ref))
        nearest = vals[grid][np.argmin(np.abs(vals[grid] - target))]
        keep &= np.isclose(vals, nearest)
    xv = variables[0]
    yv = variables[1] if len(variables) > 1 else None
    x = np.unique(screening[xv].values[keep])
    y = np.unique(screening[yv].values[keep]) if yv else np.array([0.0])
    index = np.full((y.size, x.size), -1)
    for i in np.flatnonzero(keep):
        ix = np.argmin(np.abs(x - screening[xv].values[i]))
        iy = np.argmin(np.abs(y - screening[yv].values[i])) if yv else 0
        index[iy, ix] = i
    return xv, yv, x, y, index


def _edges(centres: np.ndarray) -> np.ndarray:
    """Cell edges around grid centres (midpoints, ends mirrored)."""
    c = np.asarray(centres, float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def screening_surface(screening: xr.Dataset, score: str | None = None, tugger: str | None = None) -> Figure:
    """The score over the screened grid (figure 5.4): sway-period contours, infeasible
    region hatched, baseline (white) and optimum (red) marked."""
    score = score or screening.attrs["objective"]
    tugger = tugger or screening.attrs["objective_tugger"]
    label, scale, cmap = SCORES[score]
    xv, yv, x, y, index = _grid_slice(screening)
    values = screening[score].sel(tugger=tugger).values * scale
    sway = period_by_dof(screening["natural_period"].values, screening["dominant_dof"].values, "sway")
    feasible = screening["feasible"].values.astype(bool)
    Z = np.where(index >= 0, values[index], np.nan)
    T = np.where(index >= 0, sway[index], np.nan)
    bad = np.where(index >= 0, ~feasible[index], True)
    points = {"baseline": ("o", "white"), screening.attrs["optimum_candidate"]: ("*", "red")}
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.8)
        ax = fig.subplots()
        if yv is None:
            ax.plot(x, Z[0], color="k")
            ax.fill_between(x, 0, 1, where=bad[0], transform=ax.get_xaxis_transform(),
                            facecolor="none", hatch="///", edgecolor="grey", lw=0)
            ax.set_ylabel(label)
            for name, (marker, colour) in points.items():
                if name in screening["candidate"].values:
                    c = screening.sel(candidate=name)
                    ax.plot(float(c[xv]), float(c[score].sel(tugger=tugger)) * scale, marker,
                            mfc=colour, mec="k", ms=8, label=name)
        else:
            mesh = ax.pcolormesh(x, y, np.ma.masked_invalid(Z), cmap=cmap, shading="nearest")
            fig.colorbar(mesh, ax=ax, label=f"{label}, tugger {tugger}")
            if np.isfinite(T).sum() > 3:
                cs = ax.contour(x, y, np.ma.masked_invalid(T), colors="k", linewidths=0.6,
                                levels=np.arange(np.floor(np.nanmin(T)), np.ceil(np.nanmax(T)) + 0.5, 0.5))
                ax.clabel(cs, fmt="%.1f s", fontsize=6)
            xe, ye = _edges(x), _edges(y)
            for iy, ix in zip(*np.nonzero(bad)):
                ax.add_patch(Rectangle((xe[ix], ye[iy]), xe[ix + 1] - xe[ix], ye[iy + 1] - ye[iy],
                                       facecolor="none", edgecolor="grey", hatch="////", lw=0.0))
            for name, (marker, colour) in points.items():
                if name in screening["candidate"].values:
                    c = screening.sel(candidate=name)
                    ax.plot(float(c[xv]), float(c[yv]), marker, mfc=colour, mec="k", ms=9 if marker == "*" else 6,
                            label=f"{name}: T_sway {float(sway[list(screening['candidate'].values).index(name)]):.2f} s")
            ax.set_ylabel(AXIS_LABELS[yv])
        ax.set_xlabel(AXIS_LABELS[xv])
        handles, labels = ax.get_legend_handles_labels()
        handles.append(Patch(facecolor="none", edgecolor="grey", hatch="////"))
        labels.append("infeasible")
        ax.legend(handles, labels, loc="lower left")
        ax.set_title("screening: sway-period contours [s]" if yv else "screening")
        return fig


def geometry(screening: xr.Dataset) -> Figure:
    """Baseline and optimised rigging in the transverse (Y-Z) and longitudinal (X-Z)
    planes: hinge at the origin, wires, jacket outline to its tip, the waterline and
    the splash-clearance line, with each design's clearance."""
    hinge_h = float(screening.attrs["hinge_height_m"])
    tip_below = float(screening.attrs["padeye_to_tip_m"])
    clearance = float(screening.attrs["splash_clearance_m"])
    shown = [("baseline", "black", "-")]
    opt = screening.attrs["optimum_candidate"]
    if opt:
        shown.append((opt, "tab:red", "--"))
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.9)
        axes = fig.subplots(1, 2, sharey=True)
        for ax, (h, title) in zip(axes, ((1, "transverse view (Y-Z), looking forward"),
                                         (0, "longitudinal view (X-Z), looking to port"))):
            for name, colour, ls in shown:
                c = screening.sel(candidate=name)
                depth = float(c["cog_depth"])
                anchor = c["anchor"].values
                pad = c["padeye"].values + np.array([0.0, 0.0, -depth])
                for a, b in zip(anchor, pad):
                    ax.plot([a[h], b[h]], [a[2], b[2]], color=colour, ls=ls, lw=1.0)
                ax.plot(anchor[:, h], anchor[:, 2], "v", color=colour, ms=4)
                ax.plot(pad[:, h], pad[:, 2], "o", color=colour, ms=3, mfc="white")
                top = pad[:, 2].mean()
                tip = top - tip_below
                lo, hi = pad[:, h].min(), pad[:, h].max()
                ax.add_patch(Rectangle((lo, tip), hi - lo, top - tip, fill=False, ec=colour, ls=ls, lw=0.7))
                margin = tip - (-hinge_h + clearance)
                label = "optimised" if name == opt else name
                ax.plot([], [], color=colour, ls=ls,
                        label=f"{label}: drop {num(c['drop_height'], 2)} m, tip {num(tip + hinge_h, 2)} m "
                              f"above water (margin {num(margin, 2)} m)")
            ax.axhline(-hinge_h, color="tab:blue", lw=1.0, label="waterline")
            ax.axhline(-hinge_h + clearance, color="tab:blue", lw=0.7, ls=":",
                       label=f"splash clearance {clearance:g} m")
            ax.plot([0], [0], "s", color="red", ms=5, label="hinge (origin)")
            ax.set_title(title)
            ax.set_xlabel("y to port [m]" if h == 1 else "x forward [m]")
            ax.set_aspect("equal", adjustable="datalim")
        axes[0].set_ylabel("z up from the hinge [m]")
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=2)
        return fig


__all__ = ["AXIS_LABELS", "LABELS", "OPTIMISED", "chapter", "figure_plan", "geometry",
           "period_by_dof", "present", "screening_surface", "sensitivity"]
