"""Chapter "The reference study beside this assessment": the study's published figures
(:mod:`jls.report.study_values`: the periods of tables 3.1 and 5.2, table 4.4, the tugger
results of tables 6.3 and 6.5, the windows and limits of section 6.8, tables 6.7-6.9)
next to this assessment's on the same plant and, where the vessel allows, the same sea
states, each difference with its reason.

Every number of ours is read from the datasets: periods and design values from the
plant, limiting Hs and the workable window from the workability dataset's operability
curves (fine Tz grid; a study Tz off the grid is compared at the nearest grid point, which
the tables print), the three-hour MPM relative sway at (Hs, Tz) as
``Hs x limit / Hs_lim,sway`` (eq. 2.7 read backwards: the linear MPM per metre of Hs is
the sway limit over the sway criterion's limiting Hs), the winch force from
``damping_capacity``.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.names import SWAY_M
from jls.plant import same_rigging
from jls.plant.linearise import DOF
from jls.report import study_values as sv
from jls.report.context import Context, combo_text, heading
from jls.report.markup import num, ref, signed, t, table
from jls.report.rigging_compare import tz_window

#: Candidate names that mean "the rigging change" (the study's optimised geometry).
CHANGE_NAMES = ("detuned", "optimised", "optimized")
STUDY_HEADING = 90.0
SLOPES = {"low": 300.0, "reference": 1000.0, "high": 2000.0}


def present(cx: Context) -> bool:
    """The comparison needs the relative-sway criterion and the fine operability curves."""
    return SWAY_M in cx.dg.criteria and "hs_limit_curve_criterion" in cx.work


def _heading(cx) -> float:
    heads = np.asarray(cx.work["heading"].values, float)
    return float(heads[np.argmin(np.abs(heads - STUDY_HEADING))])


def _tugger(cx, slope) -> str | None:
    """Our tugger setting of the study's slope, None when none is configured."""
    for tg in cx.dg.tuggers:
        if np.isclose(cx.c_tugger(tg), slope):
            return tg
    return None


def change_rigging(cx) -> str | None:
    """The option standing for the study's optimised rigging: the first of
    :data:`CHANGE_NAMES` the workability carries (itself, or merged into another option),
    else the recommended rigging when it is not the baseline."""
    for name in CHANGE_NAMES:
        opt = same_rigging.alias(cx.work, name)
        if opt is not None and opt != cx.dg.baseline:
            return opt
    return cx.dg.best[0] if cx.dg.best[0] != cx.dg.baseline else None


def _period(cx, cand, dof) -> float:
    p = cx.plant.sel(candidate=cand)
    i = np.flatnonzero(p["dominant_dof"].values == DOF.index(dof))
    return float(p["natural_period"].values[i[0]]) if i.size else float("nan")


def sway_mpm(cx, combo, hs, tz) -> tuple[float, float]:
    """(the grid Tz used [s], the three-hour MPM relative sway [m] at ``hs``) of a
    combination at the study's heading, from the sway criterion's limiting Hs."""
    c = cx.work["hs_limit_curve_criterion"].sel(criterion=SWAY_M, candidate=combo[0], tugger=combo[1],
                                                heading=_heading(cx))
    at = c.sel(tz_curve=tz, method="nearest")
    lim = float(cx.work["limit"].sel(criterion=SWAY_M))
    return float(at["tz_curve"]), float(hs) * lim / float(at)


def sway_curves(work: xr.Dataset) -> xr.Dataset:
    """The study's operability curve: the relative-sway criterion's limiting Hs capped by
    the steepness ceiling (the study applies no other criterion), in the layout
    :func:`jls.report.rigging_compare.tz_window` reads."""
    sway = work["hs_limit_curve_criterion"].sel(criterion=SWAY_M, drop=True)
    capped = np.minimum(sway, work["steepness_limit_curve"])
    return xr.Dataset({"hs_limit_curve": capped, "hs_limit_curve_criterion": work["hs_limit_curve_criterion"]})


def hs_limit(cx, combo, tz) -> float:
    """Limiting Hs of the relative sway, steepness-capped, at the study's heading and Tz
    [m] (NaN off the grid)."""
    c = sway_curves(cx.work)["hs_limit_curve"].sel(candidate=combo[0], tugger=combo[1], heading=_heading(cx))
    grid = c["tz_curve"].values
    return float(c.sel(tz_curve=tz)) if np.any(np.isclose(grid, tz)) else float("nan")


def window_to(cx, combo) -> float:
    """Upper end of the workable Tz window of the relative sway at the study's design Hs [s]."""
    return tz_window(sway_curves(cx.work), combo, _heading(cx), sv.DESIGN_HS_M)[1]


def cases(cx) -> dict:
    """Section 6.8's four cases on our options: label -> combination (or None)."""
    dg = cx.dg
    ref_t, rig = _tugger(cx, sv.REFERENCE_SLOPE), change_rigging(cx)
    return {"as rigged": (dg.baseline, dg.no_tugger),
            "tugger only": (dg.baseline, ref_t) if ref_t else None,
            "rigging changed": (rig, dg.no_tugger) if rig else None,
            "both": (rig, ref_t) if rig and ref_t else None}


VESSEL = "vessel: the hinge motion here is this assessment's vessel's, not the study's"


def _plant_table(cx) -> str:
    dg = cx.dg
    rows = []
    recon = "baseline reconstructed to fit study table 3.1"
    for dof in ("sway", "yaw", "roll", "heave"):
        ours = _period(cx, dg.baseline, dof)
        study = sv.TABLE_3_1_PERIOD_S[dof]
        why = recon if dof in ("sway", "yaw") else "study table 3.1 rounds to 0.1 s"
        rows.append([f"baseline {dof} period [s] (study table 3.1)", num(study, 3), num(ours, 3),
                     signed(ours - study, 2), why])
    base = cx.plant.sel(candidate=dg.baseline)
    rows.append(["baseline top spread from the centreline [m] (study table 5.2)",
                 num(sv.TABLE_5_2["baseline"]["top_spread_m"], 2), num(float(base["top_spread_y"]) / 2, 2),
                 signed(float(base["top_spread_y"]) / 2 - sv.TABLE_5_2["baseline"]["top_spread_m"], 2),
                 recon])
    rig = change_rigging(cx)
    if rig is not None:
        o = cx.plant.sel(candidate=rig)
        budget = "tolerance budgets kept (side lead, splash clearance)"
        for label, study, ours, nd in (
                ("top spread from the centreline [m]", sv.TABLE_5_2["optimised"]["top_spread_m"],
                 float(o["top_spread_y"]) / 2, 2),
                ("drop height [m]", sv.TABLE_5_2["optimised"]["drop_height_m"], float(o["drop_height"]), 2),
                ("sway period [s]", sv.TABLE_5_2["optimised"]["sway_period_s"], _period(cx, rig, "sway"), 2)):
            rows.append([f"{rig}: {label} (study table 5.2, optimised)", num(study, nd), num(ours, nd),
                         signed(ours - study, nd), budget])
        gain = _period(cx, rig, "sway") - _period(cx, dg.baseline, "sway")
        study_gain = sv.TABLE_5_2["optimised"]["sway_period_s"] - sv.TABLE_5_2["baseline"]["sway_period_s"]
        rows.append(["detuning range: sway period gained [s]", num(study_gain, 2), num(gain, 2),
                     signed(gain - study_gain, 2), budget])
    return table("The plant beside the study's (study tables 3.1 and 5.2): natural periods, the rigging "
                 "change and the detuning range it buys. The study's optimum sits on the side-lead "
                 "and splash-clearance limits; this assessment's option keeps the tolerance budget "
                 "of each inside them, so it detunes a little less.",
                 ["quantity", "study", "here", "difference", "reason"], rows,
                 columns="(auto, auto, auto, auto, 1fr)", align="(left, right, right, right, left)",
                 size="8pt")


def _validation_table(cx) -> str:
    dg = cx.dg
    rows = []
    for name, (hs, tz) in sv.VALIDATION_SEA_STATES.items():
        _, _, sigma, top = sv.TABLE_4_4[name]
        tz_used, ours = sway_mpm(cx, (dg.baseline, dg.no_tugger), hs, tz)
        rows.append([name, num(hs, 2), num(tz, 2), num(sigma, 3), num(top, 2), num(tz_used, 2),
                     num(ours, 2), num(ours / top, 2)])
    return table(f"The study's validation sea states (study table 4.4, beam seas): its converged sigma "
                 f"and three-hour maximum (3.72 sigma, N = 1000 cycles) of the relative sway "
                 f"beside this assessment's three-hour MPM, {combo_text((dg.baseline, dg.no_tugger))}, "
                 f"heading {_heading(cx):g}°, at the nearest Tz of the operability grid. The "
                 f"ratio differs from 1 by the {VESSEL} and by the cycle count ({dg.mpm_cycles}); "
                 "the study marks V4 and S1 as beyond the linear range.",
                 ["sea state", "Hs [m]", "Tz [s]", "study sigma [m]", "study 3 h max [m]",
                  "Tz here [s]", "MPM here [m]", "here / study"], rows, size="8pt")


def _tugger_tables(cx) -> list[str]:
    dg, work = cx.dg, cx.work
    names = {k: _tugger(cx, s) for k, s in SLOPES.items()}
    rows = []
    for k, (slope, tmax, pre, _, _) in sv.TABLE_6_3.items():
        tg = names[k]
        cap = float(work["damping_capacity"].sel(tugger=tg)) if tg and "damping_capacity" in work else float("nan")
        rows.append([k, num(slope, 0), num(sv.SECTION_6_4_NET_FORCE_KN[k], 0), tg or "not configured",
                     num(cap, 0), "same winch" if np.isclose(cap, sv.SECTION_6_4_NET_FORCE_KN[k])
                     else "another winch capacity or floor in the configuration"])
    out = [table("The study's tugger configurations (study table 6.3; net force of the pair at "
                 "saturation, study section 6.4) beside this assessment's settings of the same slope.",
                 ["study", "slope [kN s/m]", "net force [kN]", "setting here", "net force here [kN]",
                  "reason"], rows, columns="(auto, auto, auto, auto, auto, 1fr)",
                 align="(left, right, right, left, right, left)", size="8pt")]
    shown = [k for k in ("reference", "high") if names[k]]
    rows = []
    for (hs, tz), values in sv.TABLE_6_5.items():
        tz_used, none = sway_mpm(cx, (dg.baseline, dg.no_tugger), hs, tz)
        row = [num(hs, 1), num(tz, 1), num(tz_used, 2), num(values[0], 2), num(none, 2)]
        for k in shown:
            study = values[2] if k == "reference" else values[3]
            row += [num(study, 2), num(sway_mpm(cx, (dg.baseline, names[k]), hs, tz)[1], 2)]
        rows.append(row)
    head = ["Hs [m]", "Tz [s]", "Tz here [s]", "none, study", "none, here"]
    for k in shown:
        head += [f"{k}, study", f"{k}, here"]
    out.append(table(f"The largest relative sway expected in three hours [m] (study table 6.5), baseline "
                     f"rigging: the study's time domain with the winch limits beside this "
                     f"assessment's frequency domain without them (heading {_heading(cx):g}°, "
                     "nearest Tz of the operability grid). The winch limits only cap the damping, "
                     "so they raise the study's tugger rows; the rest of the difference is the "
                     f"{VESSEL}.", head, rows, size="8pt"))
    return out


def _window_rows(cx):
    dg = cx.dg
    as_rigged = window_to(cx, (dg.baseline, dg.no_tugger))
    rows, ours = [], {}
    for label, key, study, gain in (
            ("as rigged", None, sv.TABLE_6_8_TO_TZ_S["as rigged"], None),
            ("tugger low only", "low", sv.TABLE_6_7_TO_TZ_S["low"], sv.TABLE_6_7_GAIN_S["low"]),
            ("tugger reference only", "reference", sv.TABLE_6_8_TO_TZ_S["tugger only"],
             sv.TABLE_6_8_GAIN_S["tugger only"]),
            ("tugger high only", "high", sv.TABLE_6_7_TO_TZ_S["high"], sv.TABLE_6_7_GAIN_S["high"]),
            ("rigging changed", "rig", sv.TABLE_6_8_TO_TZ_S["rigging changed"],
             sv.TABLE_6_8_GAIN_S["rigging changed"]),
            ("both (reference tugger)", "both", sv.TABLE_6_8_TO_TZ_S["both"], sv.TABLE_6_8_GAIN_S["both"])):
        combo = cases(cx)["as rigged"] if key is None else (
            cases(cx)["rigging changed"] if key == "rig" else cases(cx)["both"] if key == "both"
            else ((dg.baseline, _tugger(cx, SLOPES[key])) if _tugger(cx, SLOPES[key]) else None))
        if combo is None:
            continue
        here = window_to(cx, combo)
        ours[label] = here - as_rigged
        rows.append([label, f"{combo[0]} / {combo[1]}", num(study, 2),
                     "–" if gain is None else signed(gain, 2),
                     num(here, 2), "–" if key is None else signed(here - as_rigged, 2)])
    return rows, ours


def _windows(cx) -> list[str]:
    rows, ours = _window_rows(cx)
    out = [table(f"Workable Tz window at the design Hs of {sv.DESIGN_HS_M:g} m, upper end and gain "
                 f"over the as-rigged case (study tables 6.7 and 6.8) beside this assessment's "
                 f"(heading {_heading(cx):g}°; the relative sway alone, as in the study; the lower "
                 f"end is the steepness ceiling's in both). The gains differ by the {VESSEL}, and "
                 "the rigging change by its tolerance budgets (the plant table above).",
                 ["case", "rigging / tugger here", "study to Tz [s]", "study gain [s]",
                  "to Tz here [s]", "gain here [s]"], rows, size="8pt")]
    cs = cases(cx)
    tz_rows = []
    for tz, (rigged, changed, tug, both, ceiling) in sv.TABLE_6_9.items():
        row = [num(tz, 2)]
        for study, key in ((rigged, "as rigged"), (changed, "rigging changed"), (tug, "tugger only"),
                           (both, "both")):
            row += [num(study, 2), num(hs_limit(cx, cs[key], tz), 2) if cs[key] else "–"]
        ceil = cx.work["steepness_limit_curve"]
        here = float(ceil.sel(tz_curve=tz)) if np.any(np.isclose(ceil["tz_curve"].values, tz)) else float("nan")
        row += [num(ceiling, 2), num(here, 2)]
        tz_rows.append(row)
    out.append(table("Largest workable Hs [m] of the relative sway across the period range (study "
                     f"table 6.9; s: the study, h: here, heading {_heading(cx):g}°); equal to the steepness "
                     "ceiling where the sea, not the jacket, sets the limit. The tip clearance and "
                     "wire tension this assessment also applies are left out, as in the study; "
                     "they are in the workability.",
                     ["Tz [s]", "rigged s", "rigged h", "rigging s", "rigging h", "tugger s", "tugger h",
                      "both s", "both h", "ceiling s", "ceiling h"], tz_rows, size="7.5pt"))
    out.append(_finding(cx, ours))
    return out


def _finding(cx, ours: dict) -> str:
    """What differs from the study's section 6.8 in the ranking of the mitigations, and
    why the recommendation's rule treats a tugger that beats the rigging change here."""
    dg = cx.dg
    rig = ours.get("rigging changed")
    study_rig = sv.TABLE_6_8_GAIN_S["rigging changed"]
    study_ref = sv.TABLE_6_8_GAIN_S["tugger only"]
    text = (f"In the study the rigging change gains {num(study_rig, 2)} s of workable period at the "
            f"design Hs against {num(study_ref, 2)} s for the reference tugger")
    if rig is None or "tugger reference only" not in ours:
        return text + "; this assessment has no such pair of options to set beside them.\n"
    text += (f"; here {num(rig, 2)} s against {num(ours['tugger reference only'], 2)} s. ")
    better = [(k, v) for k, v in ours.items() if k.startswith("tugger") and v > rig]
    if not better:
        return text + "The ranking is the study's: the rigging change gains more than any tugger alone.\n"
    label, gain = max(better, key=lambda kv: kv[1])
    tug = _tugger(cx, SLOPES[label.split()[1]])
    text += (f"Unlike the study, the {label.removesuffix(' only')} alone gains more than the rigging "
             f"change here ({num(gain, 2)} s against {num(rig, 2)} s; study {num(sv.TABLE_6_7_GAIN_S[label.split()[1]], 2)} s "
             f"against {num(study_rig, 2)} s): on this vessel the rigging change detunes less (the plant "
             "table) and the hinge motion differs, so the frequency-domain damper has more to act on. ")
    reason = dg.excluded.get((dg.baseline, tug))
    if reason is not None:
        text += (f"The recommendation's rule still excludes {t(combo_text((dg.baseline, tug)))}: "
                 f"{t(str(reason))}. The window above is the linear one, without the winch limits "
                 "that exclusion rests on.\n")
    elif dg.best == (dg.baseline, tug):
        text += "The recommendation takes it.\n"
    else:
        text += (f"The recommendation prefers {t(combo_text(dg.best))}, which ranks higher on the "
                 f"route's sea states as a whole ({ref('tab-summary', 'table')}), not only at the "
                 "design Hs.\n")
    return text


def chapter(cx: Context) -> str:
    if not present(cx):
        return ""
    out = [heading("study", "The reference study beside this assessment")]
    out.append(
        "The reference study's figures beside this assessment's on the same plant and, where the "
        "vessel allows, the same sea states and criteria: its beam seas, its 3.0 m clearance "
        "budget, its tugger slopes. Two things differ by construction and explain most of the "
        "differences below: the vessel (the study's hull and RAOs are not public; this "
        f"assessment's is described in {cx.sec('vessel')}), and the rigging change, which here "
        "keeps the tolerance budgets the study's optimum spends.\n")
    out.append(_plant_table(cx))
    out.append(_validation_table(cx))
    if "hs_limit_curve" in cx.work:
        out += _windows(cx)
    if "damping_capacity" in cx.work:
        out += _tugger_tables(cx)
    return "\n".join(out)


__all__ = ["CHANGE_NAMES", "cases", "change_rigging", "chapter", "hs_limit", "present", "sway_mpm",
           "window_to"]
