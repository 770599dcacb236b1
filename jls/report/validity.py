"""The report's last chapter, "Assumptions and validity": the model's assumptions, what
this assessment does not cover, what to verify on board before sailing, and the cells
outside the range of the linear model.

Every number in the lists comes from a dataset: the uncertainty band's factors
(``workability.nc`` attributes ``sway_frequency_factors``, ``damping_factors``), the
recommended rigging's sway period, damping ratio and splash-clearance margin
(``plant.nc``), the relative-sway limit and the response cycles behind its MPM
(``response.nc``), the tugger demand (``response.nc``) and the fairlead offsets
(``vessel_motion.nc``).
"""

from __future__ import annotations

import numpy as np

from jls.names import MAX_TENSION_KN, MIN_TENSION_KN, RELATIVE_SWAY, SWAY_M, WIRE_TENSION_CRITERION
from jls.report import model_range
from jls.report.context import Context, heading
from jls.report.contract import LINEAR_ANGLE_DEG, LINEAR_SWAY_FACTOR, on_sea_grid, pct
from jls.report.markup import bullets, cell, num, t, table


def linear_range_measured(cx) -> str:
    """The linear range the verification measured (``verification_study.nc``), beside the
    study's flag above; empty without it or when the reference did not run."""
    st = getattr(cx, "verification_study", None)
    if st is None or "reason" in st.attrs:
        return ""
    a = st.attrs
    hs_out = float(a["linear_range_hs_leaves_m"])
    if not np.isfinite(hs_out):
        return ""
    return (f"Measured against the 6-DOF nonlinear reference (chapter \"Verification against a "
            f"nonlinear reference\"): the wires' geometry alone takes the ROM outside the "
            f"{num(100 * float(a['tolerance']), 0)} % tolerance from a relative-sway MPM of about "
            f"{num(float(a['linear_range_mpm_inside_m']), 0)} m (Hs {num(hs_out, 2)} m at Tz "
            f"{num(float(a['linear_range_tz_s']), 1)} s, beam seas, the study's plant); the flag above is "
            "stricter because the study's comparison also carries drag that grows with the swing "
            "and the block connection system, which the reference lacks.\n")


def chapter(cx: Context) -> str:
    dg = cx.dg
    cycles = dg.mpm_cycles
    items = [
        "*Linear frequency-domain model* (the study's section 3.3, eq. 3.10): $M dot.double(q) + "
        "C dot(q) + K q = -K_b q_b$, linearised about the static equilibrium; responses scale "
        "with Hs at fixed Tz, which is what makes eq. 2.7 and the unit-Hs statistics exact within "
        "the model.",
        "*Damping*: Rayleigh, $C = alpha M + beta K$, anchored on the configured modes (the "
        "study's section 3.5); no aerodynamic drag and no amplitude dependence.",
        f"*Most probable maximum*: $\"MPM\" = sigma sqrt(2 ln N)$ over an exposure of "
        f"{num(dg.exposure_h, 1)} h with N from {t(cycles)} (as the response dataset records "
        "them); a Rayleigh distribution of the peaks of a narrow-banded response.",
        f"*Hs in a bin*: each cell is assessed at the {t(dg.hs_in_bin)} of its Hs bin"
        + (" (non-conservative by up to half a bin width)." if dg.hs_in_bin == "centre"
           else " (conservative)."),
        f"*Wave spectrum*: {t(cx.resp.attrs.get('spectrum', 'JONSWAP'))}, gamma "
        f"{t(cx.resp.attrs.get('gamma', '?'))}, long-crested, one heading per state with the "
        "leg's heading probabilities.",
        "*Light lift*: the vessel's motion is unaffected by the jacket (RAOs of the vessel alone), "
        "and the jacket hangs *in air* during transit: no hydrodynamic loads on it.",
        "*Tugger* modelled in the frequency domain as a linear damper between fairlead and jacket "
        "(the study's section 6.7 form) *without winch limits*, line compliance or slack; the "
        "cells where its winch would saturate are flagged and judged by the saturation policy, "
        f"and the time domain checks cells near the boundary ({cx.sec('tuggers')}).",
        _wires(cx),
    ]
    out = [heading("validity", "Assumptions and validity"), bullets(items)]
    out.append("*Not assessed.* This report does not cover:\n" + bullets(not_assessed(cx)))
    out.append("*Verify before sailing.* The assessment holds for the rig as modelled; confirm "
               "on board, before departure:\n" + bullets(verify_before_sailing(cx)))
    out.append("*Validity of the linear model.* The study found the linear model to over-predict "
               "the nonlinear reference at large motions, by 16.8 % and 33.4 % at and beyond the "
               "longest periods of its design envelope (the study's chapter 4; geometric "
               "stiffening, amplitude-dependent damping), and to agree within 5.4 % inside it. "
               f"Cells are therefore flagged as outside the linear range when their MPM relative "
               f"sway exceeds {num(LINEAR_SWAY_FACTOR, 0)} × the relative-sway limit or their MPM "
               f"relative roll or yaw exceeds {num(LINEAR_ANGLE_DEG, 0)}°. A flagged cell that fails "
               "on sway fails by at least a factor of two, more than the largest over-prediction, "
               "so its verdict stands; a flagged cell that passes rests on the model outside its "
               "range.\n")
    measured = linear_range_measured(cx)
    if measured:
        out.append(measured)
    levels = cx.voyage if getattr(cx, "voyage", None) is not None else getattr(cx, "plan", None)
    if levels is not None:
        said = model_range.statement(model_range.of(cx, levels), cx.plant["candidate"].values)
        if said:
            out.append("*The model's range for the reported levels.* The voyage levels, the design "
                       "check and page 1 print 'beyond the model' (on grey, the curves greyed), never the "
                       "figure, where a level passes the smallest of: the linear range stated above, the "
                       "one the time domain measured, the relative sway at which the most inclined hoist "
                       "wire's side lead angle reaches its limit (drop height × (tan of the limit - tan "
                       "of its static lead)), and, for every criterion, a hoist wire going slack at the "
                       "same point. Per rigging: " + t(said) + ".\n")
    base = dg.linear[(dg.baseline, dg.no_tugger)]
    if not base["sway_limit_found"]:
        out.append("#note[No relative-sway criterion is applied; the sway flag uses 3.0 m as "
                   "its reference limit.]\n")
    out.append(f"For the {t(dg.baseline)} rigging without tugger, {base['cells']} cells carrying "
               f"{t(pct(base['route_probability']))} of the route's probability lie outside the "
               f"linear range, {base['passing_cells']} of them passing.\n")
    rows = []
    shown = dg.table
    for combo in shown.combos:                 # a large grid: the tables' selection
        lin = dg.linear[combo]
        legs = "; ".join(f"{leg} {pct(p)}" for leg, p in lin["leg_probability"].items())
        rows.append([combo[0], combo[1], f"{lin['cells']} of {lin['live_cells']}",
                     pct(lin["route_probability"]), cell(t(legs), raw=True),
                     f"{lin['passing_cells']} ({pct(lin['passing_probability'])})"])
    out.append(table(f"Cells with data outside the linear range (relative sway MPM > "
                     f"{LINEAR_SWAY_FACTOR:g} × limit, or relative roll or yaw MPM > "
                     f"{LINEAR_ANGLE_DEG:g}°): number, route probability, per leg, and how many of "
                     f"them pass."
                     + (f" Listed: {len(shown.combos)} of {shown.total} combinations, {shown.rule}."
                        if shown.rule else ""), ["candidate", "tugger", "cells", "route", "per leg", "passing"],
                     rows, columns="(auto, auto, auto, auto, 1fr, auto)",
                     align="(left, left, right, right, left, right)"))
    return "\n".join(out)


def _wires(cx: Context) -> str:
    judged = [c for c in (MAX_TENSION_KN, MIN_TENSION_KN, WIRE_TENSION_CRITERION) if c in cx.dg.criteria]
    has_dynamic = "tension_mpm" in cx.resp
    text = (f"*Wires*: the static tensions ({cx.sec('plant')})"
            + (f" and the dynamic tensions, DAF and slack margin ({cx.sec('wire_loads')}) are "
               "assessed" if has_dynamic else " are reported; the dynamic tensions are not "
               "available (no wire geometry)"))
    if judged:
        text += ", and judged against the tension criteria in every cell"
    elif has_dynamic:
        text += ", reported but judged against no tension criterion"
    return text + "; the strength of wires, slings and lift points is not checked."


def not_assessed(cx: Context) -> list[str]:
    """What the assessment leaves out (markup items)."""
    items = ["*Wind*: no wind load on the jacket (a large area in air) or on the vessel, neither "
             "its mean offset nor its gusts.",
             "*The block connection system*: the hoist blocks' connection to the lift beams and "
             "to the jacket, its strength and fatigue over the voyage.",
             "*Lift-point capacity*: the jacket's lift points (padeyes) and slings under the "
             "tensions of " + cx.sec("wire_loads") + "; no structural check of the jacket."]
    active = [tg for tg in cx.dg.tuggers if cx.c_tugger(tg) > 0]
    if active and "tugger_mpm_payout_velocity" in cx.resp:
        r = cx.resp.sel(candidate=cx.dg.baseline)
        v = max(float(r["tugger_mpm_payout_velocity"].sel(tugger=tg).max()) for tg in active)
        pw = max(float(r["tugger_power_peak"].sel(tugger=tg).max()) for tg in active)
        items.append("*Winch speed and power against a rating*: the demand is given (up to "
                     f"{num(v, 2)} m/s of MPM pay-out per metre of Hs and {num(pw, 0)} kW per m² of "
                     f"Hs² of peak power, {cx.sec('tuggers')}), but no winch rating was assessed "
                     "against it.")
    fl = cx.vessel.attrs.get("fairlead_offset_m")
    where = ""
    if fl is not None and len(fl) == 3:
        where = (f" ({num(abs(float(fl[2])), 1)} m below the hinge and {num(abs(float(fl[1])), 1)} m "
                 "either side of it)")
    items.append(f"*Fairlead feasibility*: the tugger fairleads' positions{where} are assumed; "
                 "whether the vessel can carry them (deck space, structure, a clear line lead to "
                 "the jacket) is not assessed.")
    return items


def verify_before_sailing(cx: Context) -> list[str]:
    """What to confirm on board before departure (markup items), with the values the
    assessment rests on."""
    dg, pl, work = cx.dg, cx.plant, cx.work
    rig = dg.best[0]
    p = pl.sel(candidate=rig)
    period = float(p["natural_period"].isel(mode=0))
    zeta = float(p["damping_ratio"].isel(mode=0))
    f = np.asarray(work.attrs.get("sway_frequency_factors", [1.0]), float)
    d = np.asarray(work.attrs.get("damping_factors", [1.0]), float)
    band = 100 * float(np.max(np.abs(f - 1.0)))
    if band > 0 and d.max() > d.min():
        decay = (f"the sway period within ±{num(band, 0)} % of the assessed {num(period, 2)} s "
                 f"({num(period / f.max(), 2)}-{num(period / f.min(), 2)} s) and the damping ratio within "
                 f"{num(100 * zeta * d.min(), 2)}-{num(100 * zeta * d.max(), 2)} % ({num(d.min(), 1)}-"
                 f"{num(d.max(), 1)} × the assessed {num(100 * zeta, 2)} %), the range the uncertainty "
                 f"band covers ({cx.sec('uncertainty')}); outside it the assessment does not describe "
                 "the rig")
    else:
        decay = (f"the sway period of {num(period, 2)} s and the damping ratio of "
                 f"{num(100 * zeta, 2)} % as assessed; no uncertainty band was assessed, so the "
                 "assessment covers the nominal plant only")
    items = [f"*Decay test* of the jacket in the {t(rig)} rigging: {decay}."]
    clear = pl.attrs.get("splash_clearance_m")
    if clear is not None:
        tip = float(clear) + float(p["splash_clearance_margin"])
        items.append(f"*Tip height after pay-out*: the jacket's lowest point measured at least "
                     f"{num(tip, 2)} m above the still waterline, as assessed (splash clearance "
                     f"{num(clear, 2)} m plus the margin of {num(p['splash_clearance_margin'], 2)} m).")
    hinge = cx.screening.attrs.get("hinge_height_m") if cx.screening is not None else None
    items.append("*Draught and trim* of the vessel at departure as those its RAOs were computed "
                 "for" + (f", and the hinge {num(hinge, 2)} m above the waterline" if hinge else "")
                 + ": the hinge motion, the tip height and the wire geometry depend on them.")
    items.append(_monitoring(cx))
    return items


def _monitoring(cx: Context) -> str:
    """Sway monitoring: the action levels on the measured relative sway, from the limit and
    the response cycles of the recommended option over the route's sea states."""
    dg = cx.dg
    if SWAY_M not in dg.limits:
        return ("*Motion monitoring* of the jacket against the hinge during the transit, with "
                "action levels agreed before sailing against the criteria of this report.")
    lim = dg.limits[SWAY_M]
    n = on_sea_grid(cx.resp["n_cycles"].sel(candidate=dg.best[0], tugger=dg.best[1],
                                            response=RELATIVE_SWAY), cx.sea)
    live = (cx.sea["cell_probability"] > 0).any("leg")
    vals = n.where(live).values
    vals = vals[np.isfinite(vals) & (vals > 1)]
    if vals.size:
        lo, hi = (lim / np.sqrt(2 * np.log(x)) for x in (vals.max(), vals.min()))
        sigma = (f": the limit is a standard deviation of {num(lo, 2)}-{num(hi, 2)} m over "
                 f"{num(dg.exposure_h, 0)} h (N = {num(vals.min(), 0)}-{num(vals.max(), 0)} cycles "
                 "in the route's sea states)")
    else:
        sigma = ""
    return ("*Sway monitoring*: the relative sway of the jacket against the hinge measured during "
            f"the transit, with action levels agreed before sailing on the {num(lim, 1)} m limit of "
            f"the {num(dg.exposure_h, 0)}-hour MPM{sigma}; an alert level below it for the master "
            "to change heading or speed, and a stop level at it.")


__all__ = ["chapter", "not_assessed", "verify_before_sailing"]
