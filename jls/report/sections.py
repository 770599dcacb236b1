"""Sections 1-4 of the assessment report as Typst markup (5-8: sections_results).

Each function takes the :class:`Context` (datasets, digest, provenance, figure files)
and returns the markup of one section, heading included. Numbers are formatted here
and only here; the headline percentages come straight from ``workability_route``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.report import control
from jls.report.choices import TIE_RULE, TIE_TOLERANCE
from jls.report.contract import (AT_LIMIT_TOLERANCE, Digest, complex_var, criterion_label, flag,
                                 governing_runs, limit_text, negligible, pct,
                                 reference_amplitude, ROUNDOFF_RELATIVE)
from jls.report.markup import Cell, cell, checksum, figure, mono, num, path, sci, t, table

MAX_SUMMARY_ROWS = 24


@dataclass
class Context:
    sea: xr.Dataset
    vessel: xr.Dataset
    plant: xr.Dataset
    resp: xr.Dataset
    work: xr.Dataset
    prov: dict
    dg: Digest
    figs: dict

    @property
    def legs(self) -> list[str]:
        return [str(v) for v in self.sea["leg"].values]

    def w_route(self, combo) -> float:
        return float(self.work["workability_route"].sel(candidate=combo[0], tugger=combo[1]))

    def w_leg(self, combo, leg) -> float:
        return float(self.work["workability_leg"].sel(candidate=combo[0], tugger=combo[1], leg=leg))

    def c_tugger(self, tug) -> float:
        return float(self.resp["c_tugger"].sel(tugger=tug))

    def feasible(self, cand) -> bool:
        return bool(flag(self.plant["feasible"].sel(candidate=cand)))


def criteria_text(dg: Digest) -> str:
    return ", ".join(f"{criterion_label(c)} MPM ≤ {limit_text(dg, c)}" for c in dg.criteria)


def combo_text(combo) -> str:
    return f"{combo[0]} rigging, tugger {combo[1]}"


def representative(desc: str) -> bool:
    return "representative" in str(desc).lower()


def feasibility_text(dg: Digest, cand: str, short=False) -> str:
    """'yes', 'yes, at limit (...)' or 'NO (...)' for a rigging candidate; ``short``
    leaves out the details (section 3 has them)."""
    if dg.infeasible.get(cand):
        return "NO" if short else f"NO ({dg.infeasible[cand]})"
    if dg.at_limit.get(cand):
        return "at limit" if short else f"yes, at limit ({dg.at_limit[cand]})"
    return "yes"


def at_limit_rule() -> str:
    return ("at limit: feasible, but a constraint margin is below its tolerance ("
            + ", ".join(f"{name} {tol:g}{'' if unit == '°' else ' '}{unit}"
                        for tol, unit, name in AT_LIMIT_TOLERANCE.values()) + ")")


# -- document control (page 1, before section 1) ---------------------------------------
def document_control(cx: Context) -> str:
    """The document-control block: number, revision, client, project, sign-off, the
    creation time, the jls version and the source commit."""
    doc, p = control.document_info(cx.prov), cx.prov
    blank = "–"
    commit = str(p.get("git_commit", control.NOT_GIT))
    pairs = [("document number", t(doc["number"] or control.NOT_ASSIGNED)),
             ("revision", t(doc["revision"] or blank)),
             ("client", t(doc["client"] or blank)), ("project", t(doc["project"] or blank)),
             ("prepared", t(doc["prepared"] or blank)), ("created", t(p.get("created", "?"))),
             ("checked", t(doc["checked"] or blank)), ("jls version", t(p.get("jls_version", "?"))),
             ("approved", t(doc["approved"] or blank)),
             ("source commit", mono(commit) if commit != control.NOT_GIT else t(commit))]
    cells = ", ".join(f"[{t(k)}], [{v}]" for k, v in pairs)
    return ("#doccontrol(" + cells + ")\n")


# -- 1 -------------------------------------------------------------------------------
def summary(cx: Context) -> str:
    dg, sea = cx.dg, cx.sea
    base = (dg.baseline, dg.no_tugger)
    dur = float(sea["duration_h"].sum())
    out = ["= Summary\n"]
    out.append(f"Route *{t(dg.route)}*: {len(cx.legs)} legs ({t(', '.join(cx.legs))}), "
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
    out.append(recommendation(cx))
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
    out.append(text + ".\n")
    if not cx.feasible(dg.best[0]):
        out.append("#warning[No rigging candidate is feasible (section 3); the best combination "
                   "quoted above does not meet every rigging constraint.]\n")
    elif dg.best_any[0] != dg.best[0] and cx.w_route(dg.best_any) > cx.w_route(dg.best) + TIE_TOLERANCE:
        out.append(f"#warning[The highest route workability, {t(pct(cx.w_route(dg.best_any)))}, "
                   f"belongs to {t(combo_text(dg.best_any))}, but that rigging candidate is not "
                   "feasible (section 3); the best feasible combination is quoted above.]\n")
    if dg.ties:
        others = "; ".join(combo_text(ct) for ct in dg.ties)
        out.append(f"#note[*Tie.* {t(others)} reach{'es' if len(dg.ties) == 1 else ''} the same route "
                   f"workability as {t(combo_text(dg.best))} ({t(pct(cx.w_route(dg.best)))}, equal "
                   f"within {TIE_TOLERANCE:g}). The combination quoted is chosen by the tie-break "
                   f"rule: {t(TIE_RULE)}.]\n")
    if dg.at_limit.get(dg.best[0]):
        out.append(f"#warning[The {t(dg.best[0])} rigging of the best combination is feasible only "
                   f"*at the limit* of a constraint: {t(dg.at_limit[dg.best[0]])} (section 3). "
                   "It leaves no room for fabrication or positioning tolerances.]\n")
    if dg.hash_mismatch:
        out.append(f"#warning[Configuration mismatch: {t(', '.join(dg.hash_mismatch))} "
                   f"{'was' if len(dg.hash_mismatch) == 1 else 'were'} made with a configuration "
                   f"other than this report's ({t(dg.hash_basis)} differ; section 2).]\n")
    if representative(cx.prov.get("vessel_description", "")):
        out.append("#note[The vessel motions come from a *representative hull*, not from the "
                   "vessel's own RAOs (section 2). Treat the percentages as the class's, to be "
                   "confirmed with the vessel's data.]\n")
    out.append(workability_table(cx, summary=True))
    return "\n".join(out)


def recommendation(cx: Context) -> str:
    """The headline answer in one sentence: what to rig and what it gains."""
    dg = cx.dg
    base = (dg.baseline, dg.no_tugger)
    gain = cx.w_route(dg.best) - cx.w_route(base)
    if not cx.feasible(dg.best[0]):
        return ("*Recommendation:* none of the assessed rigging candidates is feasible; revise "
                "the rigging before the transit.\n")
    if dg.best == base or gain <= TIE_TOLERANCE:
        return (f"*Recommendation:* sail with the {t(dg.baseline)} rigging without tugger; no "
                "assessed change raises the route workability.\n")
    extra = f" ({t(dg.at_limit[dg.best[0]])})" if dg.at_limit.get(dg.best[0]) else ""
    return (f"*Recommendation:* {t(combo_text(dg.best))}{extra}: route workability "
            f"{t(pct(cx.w_route(dg.best)))}, {num(100 * gain, 1)} percentage points above the "
            f"{t(dg.baseline)} rigging without tugger.\n")


def workability_table(cx: Context, summary: bool) -> str:
    dg, work = cx.dg, cx.work
    all_combos = [(str(c), str(tg)) for c in work["candidate"].values for tg in work["tugger"].values]
    combos = all_combos
    note = ""
    if len(all_combos) > MAX_SUMMARY_ROWS:
        ranked = sorted(all_combos, key=lambda ct: -cx.w_route(ct))
        keep = set(ranked[:MAX_SUMMARY_ROWS - len(dg.tuggers)]) | {(dg.baseline, tg) for tg in dg.tuggers}
        combos = [ct for ct in all_combos if ct in keep]
        note = f" The {len(combos)} best of {len(all_combos)} combinations and the baseline are shown."
    header = ["candidate", "tugger", "c [kN s/m]", "feasible", *cx.legs, "route", "governing"]
    rows = []
    for ct in combos:
        share = (work["governing_share"].sel(candidate=ct[0], tugger=ct[1]) * cx.sea["leg_weight"]).sum("leg")
        gov = str(share["criterion"].values[int(np.argmax(share.values))]) if float(share.max()) > 0 else "none fails"
        bold = ct in (dg.best, (dg.baseline, dg.no_tugger))
        rows.append([cell(ct[0], bold=bold), cell(ct[1], bold=bold), num(cx.c_tugger(ct[1]), 0),
                     feasibility_text(dg, ct[0], short=True),
                     *[pct(cx.w_leg(ct, leg)) for leg in cx.legs],
                     cell(pct(cx.w_route(ct)), bold=bold),
                     criterion_label(gov) if gov != "none fails" else gov])
    cap = ("Workability per leg and for the route (duration-weighted) of every rigging candidate "
           "and tugger setting; baseline without tugger and best feasible combination in bold; "
           "governing: the criterion that decides most of the non-workable probability; "
           + at_limit_rule() + "; section 3 names the constraint." + note)
    size = "8.5pt" if len(header) <= 9 else "7.5pt" if len(header) <= 12 else "6.5pt"
    return table(cap, header, rows, size=size,
                 align="(left, left, right, center" + ", right" * (len(cx.legs) + 1) + ", left)")


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
        ["vessel data source", t(p.get("vessel_source") or v.attrs.get("vessel_source", "not stated"))],
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
    rows = [[cell(t(name, wrap=True), raw=True), cell(path(d.get("path", "")), raw=True),
             cell(checksum(d.get("sha256", "")), raw=True)] for name, d in inputs.items()]
    out.append(table("Input files and their SHA-256 checksums.", ["input", "path", "SHA-256"],
                     rows, columns="(auto, 1fr, auto)", align="left", size="7.5pt"))
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
    src = [[t(leg), t(cx.sea.attrs.get(f"source_{leg}", "not stated")),
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
    anchors = pl.attrs.get("damping_anchor_modes", "")
    out.append("The linear 4-DOF plant $M dot.double(q) + C dot(q) + K q = -K_b q_b$ (eq. 3.10) of "
               f"each rigging candidate ({t(', '.join(dg.candidates))}): jacket CoG "
               "motions $q = [y, z, phi, psi]$ driven by the hinge $q_b$. Damping is Rayleigh"
               + (f", {num(100 * float(zeta), 2)} % on the {t(anchors)} modes" if zeta is not None else "")
               + ". Kinetic-energy fractions show which motion each mode carries.\n")
    rows = []
    for c in dg.candidates:
        p = pl.sel(candidate=c)
        for k in range(p.sizes["mode"]):
            ef = p["energy_fraction"].isel(mode=k)
            dom = dofs[int(np.argmax(ef.values))]
            rows.append([cell(c if k == 0 else ""), str(int(p["mode"].values[k])) if "mode" in p.coords else str(k + 1),
                         num(p["natural_period"].isel(mode=k), 3), num(100 * p["damping_ratio"].isel(mode=k), 2),
                         dom, *[num(100 * ef.sel(dof=d), 1) for d in dofs]])
    out.append(table("Natural periods, modal damping ratios and modal kinetic-energy fractions "
                     "(per cent of the mode's kinetic energy in each DOF).",
                     ["candidate", "mode", "T [s]", "ζ [%]", "dominant", *[f"{d} [%]" for d in dofs]],
                     rows, align="(left, center, right, right, left" + ", right" * len(dofs) + ")"))
    rows = []
    for c in dg.candidates:
        p = pl.sel(candidate=c)
        for k, w in enumerate(p["wire"].values):
            a, pe = p["anchor"].sel(wire=w).values, p["padeye"].sel(wire=w).values
            rows.append([cell(c if k == 0 else ""), str(w), ", ".join(f"{x:.2f}" for x in a),
                         ", ".join(f"{x:.2f}" for x in pe), num(p["tension"].sel(wire=w), 0),
                         num(p["unstretched_length"].sel(wire=w), 2),
                         num(p["wire_stiffness"].sel(wire=w), 0) if "wire_stiffness" in p else "–"])
    out.append(table("Wires: anchor (relative to the hinge) and padeye (relative to the CoG) "
                     "in m, static tension, unstretched length and axial stiffness.",
                     ["candidate", "wire", "anchor x, y, z", "padeye x, y, z", "tension [kN]",
                      "L0 [m]", "k [kN/m]"], rows, size="7.5pt",
                     align="(left, left, right, right, right, right, right)"))
    rows = []
    for c in dg.candidates:
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
                     "out-of-balance force or moment, per unit weight; " + at_limit_rule() + ".",
                     header, rows, size="7.5pt", align="(left" + ", right" * 9 + ", left)",
                     n_columns=11))
    out.append(figure(cx.figs["rigging"], "The rigging in two projections: hinge at the origin "
                      "(square), anchors relative to it (down triangles), wires to the padeyes "
                      "(circles), jacket CoG (+) and the jacket top drawn as a box from padeye "
                      "level down to the CoG; baseline solid, other candidates dashed. "
                      + dg.plot.caption().replace("combinations", "candidate x tugger combinations")))
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
