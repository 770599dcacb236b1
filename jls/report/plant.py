"""The report's chapter "Plant": the jacket's mass and inertia, what each rigging
candidate is (the baseline, the changed riggings and what "detuned" means), the linear
4-DOF plant of each (natural periods, damping, modal energy fractions), its wires, design
variables and constraint margins, and the figure of the rigging in two projections."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.patches import Rectangle

from jls.report.context import Context, at_limit_rule, budget_text, feasibility_text, heading
from jls.report.contract import complex_var
from jls.report.markup import Cell, bullets, cell, figure, num, sci, t, table

DESIGN = (("top_spread_y", "top spread Y"), ("bottom_spread_y", "bottom spread Y"),
          ("bottom_spread_x", "bottom spread X"), ("drop_height", "drop height"))
from jls.report.style import CAND_COLOURS, STYLE, Task, new_figure, save


def figure_plan(cx: Context) -> list[Task]:
    return [Task("rigging", lambda d: rigging(cx.plant, cx.dg, d), 1.5)]


def chapter(cx: Context) -> str:
    pl, dg = cx.plant, cx.dg
    dofs = [str(d) for d in pl["dof"].values]
    out = [heading("plant", "Plant")]
    zeta = pl.attrs.get("damping_ratio")
    anchors = " and ".join(str(pl.attrs.get("damping_anchor_modes", "")).split())
    listed = dg.table.candidates
    note = ("" if len(listed) == len(dg.candidates) else
            f" Listed: {len(listed)} of {len(dg.candidates)} rigging candidates, those of the "
            "combinations the result tables list; every candidate is in the plant dataset.")
    out.append(jacket_text(cx))
    out.append(candidates_text(cx))
    out.append("The linear 4-DOF plant $M dot.double(q) + C dot(q) + K q = -K_b q_b$ (the study's eq. 3.10) of "
               f"each rigging candidate ({t(', '.join(listed))}"
               + (f" and {len(dg.candidates) - len(listed)} more" if note else "") + "): jacket CoG "
               "motions $q = [y, z, phi, psi]$ driven by the hinge $q_b$. Damping is Rayleigh"
               + (f", {num(100 * float(zeta), 2)} % on the {t(anchors)} modes" if zeta is not None else "")
               + ". Kinetic-energy fractions show which motion each mode carries.\n")
    rows = []
    for c in listed:
        p = pl.sel(candidate=c)
        for k in range(p.sizes["mode"]):
            ef = p["energy_fraction"].isel(mode=k)
            dom = dofs[int(np.argmax(ef.values))]
            rows.append([cell(c if k == 0 else ""), str(int(p["mode"].values[k])) if "mode" in p.coords else str(k + 1),
                         num(p["natural_period"].isel(mode=k), 3), num(100 * p["damping_ratio"].isel(mode=k), 2),
                         dom, *[num(100 * ef.sel(dof=d), 1) for d in dofs]])
    out.append(table("Natural periods, modal damping ratios and modal kinetic-energy fractions "
                     "(per cent of the mode's kinetic energy in each DOF)." + note,
                     ["candidate", "mode", "T [s]", "ζ [%]", "dominant", *[f"{d} [%]" for d in dofs]],
                     rows, align="(left, center, right, right, left" + ", right" * len(dofs) + ")"))
    rows = []
    for c in listed:
        p = pl.sel(candidate=c)
        for k, w in enumerate(p["wire"].values):
            a, pe = p["anchor"].sel(wire=w).values, p["padeye"].sel(wire=w).values
            rows.append([cell(c if k == 0 else ""), str(w), ", ".join(num(x, 2) for x in a),
                         ", ".join(num(x, 2) for x in pe), num(p["tension"].sel(wire=w), 0),
                         num(p["unstretched_length"].sel(wire=w), 2),
                         num(p["wire_stiffness"].sel(wire=w), 0) if "wire_stiffness" in p else "–"])
    out.append(table("Wires: anchor (relative to the hinge) and padeye (relative to the CoG) "
                     "in m, static tension, unstretched length and axial stiffness." + note,
                     ["candidate", "wire", "anchor x, y, z", "padeye x, y, z", "tension [kN]",
                      "L0 [m]", "k [kN/m]"], rows, size="7.5pt",
                     align="(left, left, right, right, right, right, right)"))
    rows = []
    for c in listed:
        p = pl.sel(candidate=c)
        res = float(np.nanmax(np.abs(p["equilibrium_residual"].values)))
        rows.append([cell(c), *[num(p[v], 2) for v in ("top_spread_y", "bottom_spread_y",
                                                       "bottom_spread_x", "drop_height", "cog_depth")],
                     num(p["side_lead_margin"], 2), num(p["fore_aft_lead_margin"], 2),
                     num(p["splash_clearance_margin"], 2), sci(res, 1),
                     cell(feasibility_text(dg, c, short=True),
                          bold=not cx.feasible(c) or bool(dg.at_limit.get(c)))])
    header = [cell("", colspan=1), cell("design variables [m]", colspan=4, align="center"),
              cell("", colspan=1), cell("constraint margins", colspan=3, align="center"),
              cell("", colspan=2)]
    header += [cell(x, align="center", bold=True) for x in (
        "candidate", "top Y", "bottom Y", "bottom X", "drop", "CoG depth [m]", "side lead [°]",
        "fore-aft lead [°]", "splash [m]", "residual", "feasible")]
    header.append(Cell("table.hline(stroke: 0.7pt)"))
    out.append(table("Design variables (the study's chapter 5: top and bottom spreads Y and X, drop height) "
                     "and constraint margins (positive: satisfied); residual: largest "
                     "out-of-balance force or moment, per unit weight; " + at_limit_rule(cx.plant) + "."
                     + note,
                     header, rows, size="7.5pt", align="(left" + ", right" * 9 + ", left)",
                     n_columns=11))
    # the details of "at limit" and "NO" below the table: a table cell stays within 3 lines
    details = [f"*{t(c)}*: {t(feasibility_text(dg, c))}" for c in listed
               if dg.infeasible.get(c) or dg.at_limit.get(c)]
    if details:
        out.append("Feasibility in full: " + "; ".join(details) + ".\n")
    if budget_text(cx.plant):
        out.append(t(budget_text(cx.plant)) + "\n")
    out.append(figure(cx.figs["rigging"], "The rigging in two projections: hinge at the origin "
                      "(square), anchors relative to it (down triangles), wires to the padeyes "
                      "(circles), jacket CoG (+) and the jacket top drawn as a box from padeye "
                      "level down to the CoG; baseline solid, other candidates dashed. "
                      + dg.plot.candidate_caption(len(dg.candidates))
                      + ("" if dg.best[0] in dg.plot.candidates else
                         f" The recommended rigging, {dg.best[0]}, is drawn too.")))
    return "\n".join(out)


def jacket_text(cx: Context) -> str:
    """The jacket's mass and inertia as the plant carries them (``m_grav_t``, the diagonal
    of ``M``), per candidate when they differ (lumped block and wire mass)."""
    pl = cx.plant
    M = pl["M"]
    dofs = [str(d) for d in pl["dof"].values]
    diag = {c: {d: float(M.sel(candidate=c, dof=d, dof_col=d)) for d in dofs}
            for c in (str(x) for x in pl["candidate"].values)}
    first = next(iter(diag.values()))
    same = all(all(abs(v[d] - first[d]) <= 1e-9 * max(abs(first[d]), 1.0) for d in dofs) for v in diag.values())
    grav = pl.attrs.get("m_grav_t")
    head = (f"*The jacket.* Gravitational (dry) mass {num(grav, 0)} t, which sets the wire "
            "tensions; " if grav is not None else "*The jacket.* ")

    def inertia(v):
        parts = []
        if "sway" in v:
            parts.append(f"inertial mass {num(v['sway'], 0)} t in sway"
                         + (" and heave" if "heave" in v and abs(v["heave"] - v["sway"]) < 1e-6 else ""))
        for d, what in (("roll", "roll"), ("yaw", "yaw")):
            if d in v:
                parts.append(f"{what} inertia {num(v[d] / 1e6, 3)} × 10⁶ t m²")
        return ", ".join(parts)
    if same:
        return head + t(inertia(first)) + " about the CoG (the diagonal of M; every candidate the same).\n"
    rows = [[c] + [num(v[d], 0) for d in dofs] for c, v in diag.items() if c in cx.dg.table.candidates]
    return (head + "the inertial mass and inertia about the CoG (the diagonal of M) differ by "
            "candidate: the hoist blocks and wires move with the jacket.\n"
            + table("Inertial mass [t] and inertia [t m²] about the CoG per candidate (the "
                    "diagonal of M).", ["candidate"] + dofs, rows))


def candidates_text(cx: Context) -> str:
    """What each rigging candidate is: the baseline, the screening's optimum, the others by
    the design variables they change; and "detuned" defined."""
    pl, dg = cx.plant, cx.dg
    base = pl.sel(candidate=dg.baseline)
    t_base = float(base["natural_period"].isel(mode=0))
    hinge = complex_var(cx.vessel, "hinge")
    amp = np.abs(hinge.sel(dof="sway").values).max(axis=tuple(i for i, d in enumerate(hinge.sel(dof="sway").dims)
                                                                 if d != "omega"))
    t_peak = float(2 * np.pi / cx.vessel["omega"].values[int(np.nanargmax(amp))])
    items = []
    for c in dg.table.candidates:
        p = pl.sel(candidate=c)
        t_c = float(p["natural_period"].isel(mode=0))
        if c == dg.baseline:
            items.append(f"*{t(c)}*: the rigging as configured; sway period {num(t_c, 2)} s")
            continue
        changed = [f"{label} {num(p[v], 2)} m (baseline {num(base[v], 2)} m)" for v, label in DESIGN
                   if abs(float(p[v]) - float(base[v])) > 5e-4]
        origin = ("the screening's optimum" + (f" ({cx.sec('rigging')})" if cx.has("rigging") else "")
                  if c == "optimised" else "a candidate of the configuration")
        items.append(f"*{t(c)}*: {origin}; " + (t(", ".join(changed)) if changed else "no design variable changed")
                     + f"; sway period {num(t_c, 2)} s")
    return ("*The rigging candidates.* A *detuned* rigging is one whose sway natural period has "
            "been moved away from the periods that excite it: the hinge sway, which drives the "
            f"pendulum, peaks at {num(t_peak, 2)} s wave period, near the baseline's sway period of "
            f"{num(t_base, 2)} s, and a narrower top spread or a longer drop lengthens the sway "
            "period past that peak (the study's chapter 5). The candidates assessed:\n"
            + bullets([it + "." for it in items]))


def drawn(dg) -> list[str]:
    """The riggings the figure draws: the figures' selection, with the recommended rigging
    always among them (a selection over many headings may hold the baseline only)."""
    return list(dict.fromkeys([*dg.plot.candidates, dg.best[0]]))


def rigging(plant: xr.Dataset, dg, out_dir) -> Path:
    """The wires of the shown candidates in the transverse (Y-Z) and longitudinal
    (X-Z) planes: hinge at the origin, anchors, padeyes, CoG and the jacket top."""
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.5)
        axes = fig.subplots(1, 2)
        for (ax, (h, name)) in zip(axes, ((1, "transverse view (Y-Z), looking forward"),
                                          (0, "longitudinal view (X-Z), looking to port"))):
            for i, cand in enumerate(drawn(dg)):
                p = plant.sel(candidate=cand)
                colour = CAND_COLOURS[i % len(CAND_COLOURS)]
                ls = "-" if i == 0 else ("--", "-.", ":", (0, (5, 1, 1, 1)), (0, (3, 1)))[(i - 1) % 5]
                anchor, pad_rel = p["anchor"].values, p["padeye"].values
                depth = float(p["cog_depth"])
                pad = pad_rel + np.array([0.0, 0.0, -depth])
                for a, b in zip(anchor, pad):
                    ax.plot([a[h], b[h]], [a[2], b[2]], color=colour, ls=ls, lw=1.0)
                ax.plot(anchor[:, h], anchor[:, 2], "v", color=colour, ms=4)
                ax.plot(pad[:, h], pad[:, 2], "o", color=colour, ms=3, mfc="white")
                ax.plot([0], [-depth], "+", color=colour, ms=9, mew=1.5)
                lo, hi = pad[:, h].min(), pad[:, h].max()
                top = pad[:, 2].mean()
                ax.add_patch(Rectangle((lo, -depth), hi - lo, top + depth, fill=False,
                                       ec=colour, ls=ls, lw=0.7, alpha=0.7))
                ax.plot([], [], color=colour, ls=ls, label=cand)
            ax.plot([0], [0], "s", color="red", ms=5, label="hinge (origin)")
            ax.axhline(0.0, color="grey", lw=0.6, ls=":")
            ax.set_title(name)
            ax.set_xlabel("y to port [m]" if h == 1 else "x forward [m]")
            ax.set_ylabel("z up from the hinge [m]")
            ax.set_aspect("equal", adjustable="datalim")
        handles, labels = axes[0].get_legend_handles_labels()
        wide = max(len(s) for s in labels) > 24
        fig.legend(handles, labels, loc="outside lower center", ncol=min(len(labels), 2 if wide else 4))
        return save(fig, out_dir, "rigging")


__all__ = ["chapter", "drawn", "figure_plan", "rigging"]
