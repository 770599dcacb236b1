"""Sections 2-4 of the assessment report as Typst markup: inputs and provenance, plant,
vessel and hinge motion."""

from __future__ import annotations

import numpy as np

from jls.report import control
from jls.report.contract import ROUNDOFF_RELATIVE, complex_var, negligible, reference_amplitude
from jls.report.markup import Cell, cell, figure, mono, num, path, sci, t, table
from jls.report.sections import Context, at_limit_rule, feasibility_text, representative


# -- 2 -------------------------------------------------------------------------------
def provenance(cx: Context) -> str:
    p, v, dg = cx.prov, cx.vessel, cx.dg
    omega = v["omega"].values
    rows = [
        ["route", t(dg.route)], ["jls version", t(p.get("jls_version", "?"))],
        ["configuration SHA-256", mono(p.get("config_sha256", "?"))],
        ["source commit", mono(p["git_commit"]) if p.get("git_commit", control.NOT_GIT) != control.NOT_GIT
         else t(control.NOT_GIT)],
        ["created", t(p.get("created", "?"))], ["Python", t(p.get("python", "?"))],
        ["vessel data source", path(p.get("vessel_source") or v.attrs.get("vessel_source", "not stated"))],
        ["vessel description", t(p.get("vessel_description") or v.attrs.get("vessel_description", "not stated"))],
        ["RAO range", t(f"omega {omega.min():.3f}-{omega.max():.3f} rad/s (periods "
                        f"{2 * np.pi / omega.max():.1f}-{2 * np.pi / omega.min():.1f} s), "
                        f"headings {', '.join(f'{h:g}' for h in v['heading'].values)} deg")],
        ["RAO extrapolation", t(v.attrs.get("extrapolation", "not stated"))],
        ["phase convention", t(v.attrs.get("phase_convention", "not stated"))],
        ["heading convention", t(v.attrs.get("heading_convention", "not stated"))],
        ["wave spectrum", t(f"{cx.resp.attrs.get('spectrum', 'not stated')}, gamma "
                            f"{cx.resp.attrs.get('gamma', '?')}")],
        ["steepness rule", t(cx.sea.attrs.get("steepness_rule", cx.work.attrs.get("steepness_rule", "not stated")))],
    ]
    out = ["= Inputs and provenance\n",
           table("Provenance of this assessment.", ["item", "value"],
                 [[cell(a), cell(b, raw=True)] for a, b in rows],
                 columns="(auto, 1fr)", align="(left, left)")]
    desc = p.get("vessel_description") or v.attrs.get("vessel_description", "")
    if representative(desc):
        out.append("#note[*Vessel data are representative, not the vessel's own.* The RAOs belong "
                   "to a hull of the same class computed or supplied for this tool; the vessel's "
                   "own response may differ, most of all near the roll resonance, which drives "
                   "the hinge sway.]\n")
    else:
        out.append("#note[The vessel description does not say that the RAOs are representative; "
                   "they are taken to be the vessel's own data. Check the source above.]\n")
    inputs = p.get("inputs", {}) or {}
    # The checksum goes on its own line under the path: a column of its own would take
    # 64 monospace characters of the width and leave too little for the path.
    rows = [[cell(t(name, wrap=True), raw=True),
             cell(f"{path(d.get('path', ''))} \\ {mono(d.get('sha256', ''))}", raw=True)]
            for name, d in inputs.items()]
    out.append(table("Input files (path, and SHA-256 checksum below it).",
                     ["input", "path and SHA-256"], rows, columns="(22%, 1fr)", align="left",
                     size="7.5pt"))
    rows = []
    for name, ds in (("sea_states", cx.sea), ("vessel_motion", v), ("plant", cx.plant),
                     ("response", cx.resp), ("workability", cx.work)):
        sha = str(ds.attrs.get("config_sha256", ""))
        same = {None: "–", True: "yes", False: "NO"}[dg.same_config[name]]
        rows.append([cell(name), cell(t(ds.attrs.get("created_by", "–")), raw=True),
                     cell(t(ds.attrs.get("jls_version", "–")), raw=True),
                     cell(mono(sha[:12]) if sha else "–", raw=True), same])
    out.append(table("The datasets read: the rule that wrote each, its jls version and "
                     f"configuration hash, and whether that hash equals the report's hash of "
                     f"{dg.hash_basis}.",
                     ["dataset", "written by", "jls", "config SHA-256", "same config"], rows,
                     align="(left, left, left, left, center)"))
    src = [[t(leg), path(cx.sea.attrs.get(f"source_{leg}", "not stated")),
            num(cx.sea["record_total"].sel(leg=leg), 0) if "record_total" in cx.sea else "–"]
           for leg in cx.legs]
    out.append(table("Wave statistics of each leg: source file and the sum of its raw values "
                     "(records or probabilities).", ["leg", "source", "raw total"],
                     [[cell(a, raw=True), cell(b, raw=True), c] for a, b, c in src],
                     align="(left, left, right)"))
    pk = list((p.get("packages") or {}).items())
    per_row = 4
    rows = []
    for i in range(0, len(pk), per_row):
        chunk = pk[i:i + per_row] + [("", "")] * (per_row - len(pk[i:i + per_row]))
        rows.append([x for name, ver in chunk for x in (cell(name), cell(ver))])
    out.append(table("Python packages.", ["package", "version"] * per_row, rows,
                     align="(" + ", ".join(["left"] * 2 * per_row) + ")", size="7.5pt"))
    return "\n".join(out)


# -- 3 -------------------------------------------------------------------------------
def plant(cx: Context) -> str:
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


# -- 4 -------------------------------------------------------------------------------
def vessel(cx: Context) -> str:
    v, dg = cx.vessel, cx.dg
    hinge = complex_var(v, "hinge")
    rao = complex_var(v, "rao")
    period = 2 * np.pi / v["omega"].values
    out = ["= Vessel and hinge motion\n"]
    out.append(f"The hinge of the lift beams at {t(_vec(v.attrs.get('hinge_m')))} m from the RAO "
               f"reference point {t(_vec(v.attrs.get('reference_point_m')))} moves with the hull as a "
               "rigid body: $y_b = y + psi x_B - phi z_B$, $z_b = z + phi y_B - theta x_B$ "
               "(eq. 3.1); its rotations are the vessel's. The long lever arm to the hinge turns "
               "vessel roll into hinge sway, which drives the pendulum.\n")
    rows = []
    for h in v["heading"].values:
        for name, da, scale, unit in (("vessel roll", rao.sel(vessel_dof="roll"), 180 / np.pi, "deg/m"),
                                      ("hinge sway", hinge.sel(dof="sway"), 1.0, "m/m"),
                                      ("hinge heave", hinge.sel(dof="heave"), 1.0, "m/m"),
                                      ("hinge yaw", hinge.sel(dof="yaw"), 180 / np.pi, "deg/m")):
            amp = np.abs(da.sel(heading=h).values) * scale
            if negligible(amp, reference_amplitude(v, h, unit.startswith("deg")) * scale):
                rows.append([f"{h:g}°", name, f"no {name.split()[-1]} motion at this heading", "–"])
                continue
            k = int(np.nanargmax(amp))
            rows.append([f"{h:g}°", name, f"{amp[k]:.3g} {unit}", num(period[k], 2)])
    out.append(table("Peak RAO amplitudes in the RAO range; an amplitude below "
                     f"{ROUNDOFF_RELATIVE:g} of the largest of its kind (translation or rotation) "
                     "at the heading is round-off and reported as no motion.", ["heading", "motion", "peak", "at period [s]"],
                     rows, align="(left, left, right, right)"))
    out.append(figure(cx.figs["hinge_raos"], "Hinge excitation amplitudes and vessel roll and sway "
                      "RAO against wave period at the assessed headings; dotted: baseline sway period."))
    out.append(figure(cx.figs["relative_transfer"], "Relative sway and relative yaw of the jacket "
                      "against the hinge per unit wave amplitude (colour: rigging candidate, line "
                      "style: tugger setting); dotted: sway periods. " + dg.plot.caption()))
    return "\n".join(out)


def _vec(x) -> str:
    try:
        return "(" + ", ".join(f"{float(a):.3f}" for a in x) + ")"
    except TypeError:
        return "(not stated)"
