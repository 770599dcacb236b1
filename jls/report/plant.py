"""Chapter 3 of the report, "Plant": the linear 4-DOF plant of each rigging candidate
(natural periods, damping, modal energy fractions), its wires, design variables and
constraint margins, and the figure of the rigging in two projections."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.patches import Rectangle

from jls.report.context import Context, at_limit_rule, feasibility_text
from jls.report.markup import Cell, cell, figure, num, sci, t, table
from jls.report.style import CAND_COLOURS, STYLE, Task, new_figure, save


def figure_plan(cx: Context) -> list[Task]:
    return [Task("rigging", lambda d: rigging(cx.plant, cx.dg, d), 1.5)]


def chapter(cx: Context) -> str:
    pl, dg = cx.plant, cx.dg
    dofs = [str(d) for d in pl["dof"].values]
    out = ["= Plant\n"]
    zeta = pl.attrs.get("damping_ratio")
    anchors = " and ".join(str(pl.attrs.get("damping_anchor_modes", "")).split())
    listed = dg.table.candidates
    note = ("" if len(listed) == len(dg.candidates) else
            f" Listed: {len(listed)} of {len(dg.candidates)} rigging candidates, those of the "
            "combinations the result tables list; every candidate is in plant.nc.")
    out.append("The linear 4-DOF plant $M dot.double(q) + C dot(q) + K q = -K_b q_b$ (eq. 3.10) of "
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
            rows.append([cell(c if k == 0 else ""), str(w), ", ".join(f"{x:.2f}" for x in a),
                         ", ".join(f"{x:.2f}" for x in pe), num(p["tension"].sel(wire=w), 0),
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
                     cell(feasibility_text(dg, c), bold=not cx.feasible(c) or bool(dg.at_limit.get(c)))])
    header = [cell("", colspan=1), cell("design variables [m]", colspan=4, align="center"),
              cell("", colspan=1), cell("constraint margins", colspan=3, align="center"),
              cell("", colspan=2)]
    header += [cell(x, align="center", bold=True) for x in (
        "candidate", "top Y", "bottom Y", "bottom X", "drop", "CoG depth [m]", "side lead [°]",
        "fore-aft lead [°]", "splash [m]", "residual", "feasible")]
    header.append(Cell("table.hline(stroke: 0.7pt)"))
    out.append(table("Design variables (chapter 5: top and bottom spreads Y and X, drop height) "
                     "and constraint margins (positive: satisfied); residual: largest "
                     "out-of-balance force or moment, per unit weight; " + at_limit_rule(cx.plant) + "."
                     + note,
                     header, rows, size="7.5pt", align="(left" + ", right" * 9 + ", left)",
                     n_columns=11))
    out.append(figure(cx.figs["rigging"], "The rigging in two projections: hinge at the origin "
                      "(square), anchors relative to it (down triangles), wires to the padeyes "
                      "(circles), jacket CoG (+) and the jacket top drawn as a box from padeye "
                      "level down to the CoG; baseline solid, other candidates dashed. "
                      + dg.plot.candidate_caption(len(dg.candidates))))
    return "\n".join(out)


def rigging(plant: xr.Dataset, dg, out_dir) -> Path:
    """The wires of the shown candidates in the transverse (Y-Z) and longitudinal
    (X-Z) planes: hinge at the origin, anchors, padeyes, CoG and the jacket top."""
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.5)
        axes = fig.subplots(1, 2)
        for (ax, (h, name)) in zip(axes, ((1, "transverse view (Y-Z), looking forward"),
                                          (0, "longitudinal view (X-Z), looking to port"))):
            for i, cand in enumerate(dg.plot.candidates):
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


__all__ = ["chapter", "figure_plan", "rigging"]
