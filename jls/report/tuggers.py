"""The report's chapter "Damping tuggers" (chapter 6 of the study): winch settings and their
frequency-domain loads, the time-domain cells (traces, limit occupancy, power, verdicts),
decay tests and the damping-slope sweep (:mod:`jls.report.tuggers_studies`, the chapter's
second part), and the four cases of the study's section 6.8 side by side.

Reads the context's ``td`` (time-domain cell datasets), ``td_cells`` (the chosen cells
with their reasons) and ``studies`` (decay and sweep); without them the chapter says what
is missing. Its figures are listed by :func:`figure_plan`.
"""

from __future__ import annotations

import matplotlib
import numpy as np

from jls.assessment.recommendation import INFEASIBLE
from jls.names import SATURATED_FAIL, SATURATED_UNRESOLVED, SWAY_M, TIME_DOMAIN
from jls.report.context import Context, heading
from jls.report.contract import pct
from jls.report.markup import cell, figure, num, plural, ref, signed, t, table
from jls.report.style import CAND_COLOURS, STYLE, Task, new_figure, operability_top, save
from jls.report.tuggers_studies import decay, decay_section, sweep_section

MAX_TRACE_CELLS = 2
CASE_TZ = (6.0, 6.5, 7.0, 7.5, 8.0)
RIGGING_CHANGE_NAMES = ("detuned", "optimised", "optimized")
def hard_exclusion(reason) -> bool:
    """A physical reason (infeasible rigging, saturating winch), not the tugger-gain rule."""
    return any(x.startswith("winch") or x == INFEASIBLE for x in reason.short.split(", "))


def four_cases(cx: Context):
    """(label, combo) of the study's section 6.8: as rigged, tugger only, rigging changed,
    both. The rigging change is the recommended rigging when it is not the baseline, else
    the 'detuned' (or 'optimised') candidate, else the best feasible other candidate. The
    tugger is the recommended one when it is active; else the active setting page 1
    excludes least: fewest combinations of the two riggings excluded for a physical reason
    (infeasible rigging, saturating winch), then fewest excluded at all, then the highest
    route workability with the changed rigging, then the lower slope."""
    dg = cx.dg
    others = [c for c in dg.candidates if c != dg.baseline]
    named = [c for c in RIGGING_CHANGE_NAMES if c in others]
    if dg.best[0] != dg.baseline:
        rig = dg.best[0]
    elif named:
        rig = named[0]
    else:
        feas = [c for c in others if cx.feasible(c)]
        rig = max(feas, key=lambda c: cx.w_route((c, dg.no_tugger))) if feas else None
    active = [tg for tg in dg.tuggers if cx.c_tugger(tg) > 0]
    if cx.c_tugger(dg.best[1]) > 0:
        tug = dg.best[1]
    elif active:
        def key(tg):
            pair = [(dg.baseline, tg)] + ([(rig, tg)] if rig else [])
            why = [dg.excluded[ct] for ct in pair if ct in dg.excluded]
            return (sum(hard_exclusion(r) for r in why), len(why),
                    -cx.w_route(pair[-1]), cx.c_tugger(tg))
        tug = min(active, key=key)
    else:
        tug = None
    cases = [("as rigged", (dg.baseline, dg.no_tugger))]
    if tug:
        cases.append(("tugger only", (dg.baseline, tug)))
    if rig:
        cases.append(("rigging changed", (rig, dg.no_tugger)))
    if tug and rig:
        cases.append(("both", (rig, tug)))
    return cases


# -- figures ----------------------------------------------------------------------------
def _sway_limit(cx: Context) -> float:
    crit = [str(c) for c in cx.work["criterion"].values]
    return float(cx.work["limit"].sel(criterion=SWAY_M)) if SWAY_M in crit else np.nan


def figure_plan(cx: Context) -> list[Task]:
    """The chapter's figures: the traces of the time-domain cells, the decay tests, the
    four cases (each when there is data)."""
    plan = []
    if trace_cells(cx):
        plan.append(Task("td_traces", lambda d: td_traces(cx, d), 1.0 + 1.2 * len(trace_cells(cx))))
    if cx.studies is not None:
        plan.append(Task("decay", lambda d: decay(cx, d), 0.7))
    if "hs_limit_curve" in cx.work and len(four_cases(cx)) > 1:
        plan.append(Task("four_cases", lambda d: four_cases_figure(cx, d), 0.7))
    return plan


def trace_cells(cx: Context) -> list:
    """The time-domain cells whose traces are shown."""
    return [d for d in cx.td if d.sizes.get("time", 0)][:MAX_TRACE_CELLS]


def td_traces(cx: Context, out_dir):
    """Relative sway against time in the shown time-domain cells, the sway limit dashed."""
    cells = trace_cells(cx)
    lim = _sway_limit(cx)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(1.9 * len(cells))
        axes = np.atleast_1d(fig.subplots(len(cells), 1, sharex=True, squeeze=False)[:, 0])
        for ax, d in zip(axes, cells):
            for i, tg in enumerate(d["tugger"].values):
                ax.plot(d["time"].values, d["trace_relative_sway"].sel(tugger=tg).values,
                        color=CAND_COLOURS[i % len(CAND_COLOURS)], lw=0.8, label=str(tg))
            if np.isfinite(lim):
                for s in (-1, 1):
                    ax.axhline(s * lim, color="grey", ls="--", lw=0.8)
            ax.set_ylabel("relative sway [m]")
            ax.set_title(f"{d.attrs['candidate']}, heading {float(d.attrs['heading_deg']):g}°, "
                         f"Hs {float(d.attrs['hs_m']):g} m, Tz {float(d.attrs['tz_s']):g} s")
        axes[-1].set_xlabel("time in the window [s]")
        axes[0].legend(ncol=4, loc="upper right")
        return save(fig, out_dir, "td_traces")


def four_cases_figure(cx: Context, out_dir):
    """Limiting Hs of the four cases of the study's section 6.8 (lowest over the
    headings); the y-axis shows the limiting curves, the ceiling leaves it at its top."""
    cases = four_cases(cx)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        curve = cx.work["hs_limit_curve"].min("heading")
        tz = curve["tz_curve"].values
        ceiling = cx.work["steepness_limit_curve"].values
        lines = [curve.sel(candidate=c, tugger=tg).values for _, (c, tg) in cases]
        for i, ((label, (c, tg)), y) in enumerate(zip(cases, lines)):
            ax.plot(tz, y, color=CAND_COLOURS[i], label=f"{label} ({c} / {tg})")
        ax.plot(tz, ceiling, color="grey", ls="--", label="steepness ceiling")
        ax.set_xlabel("Tz [s]")
        ax.set_ylabel("limiting Hs [m]")
        ax.set_xlim(float(tz.min()), float(tz.max()))
        ax.set_ylim(0, operability_top([(y, ceiling) for y in lines]))
        ax.legend(ncol=2, loc="upper right")
        return save(fig, out_dir, "four_cases")


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
    dg = cx.dg
    out = [heading("tuggers", "Damping tuggers")]
    active = [tg for tg in dg.tuggers if cx.c_tugger(tg) > 0]
    if not active:
        out.append("No damping-tugger setting is configured (every slope is zero); nothing to "
                   "assess in this chapter.\n")
        return "\n".join(out)
    out.append(
        "A damping tugger is a pair of opposing lines from fairleads on the vessel to the jacket "
        "at CoG height. Each line follows $T = T_0 + c/n u$ between its floor and its winch "
        "capacity, so between the limits the pair is a linear damper of slope $c$ on the "
        "velocity of the jacket's sway against the fairlead. The frequency domain "
        f"({cx.secs('operability', 'workability')}) has no limits; here the loads it "
        "implies are set against the winch, cells where it saturates are flagged, and the "
        "nonlinear time domain checks the cells that matter.\n")
    out.append(_settings_table(cx, active))
    out.append(_fd_loads(cx, active))
    out.append(_timedomain(cx))
    out.append(decay_section(cx))
    out.append(sweep_section(cx))
    out.append(_cases(cx))
    return "\n".join(out)


def line_capacity(cx, tug) -> float:
    """The winch capacity per line [kN] of a tugger setting, from the time-domain cell
    datasets (coordinate ``max_force``); NaN when no cell ran it."""
    for d in cx.td:
        if "max_force" in d.coords and tug in d["tugger"].values:
            return float(d["max_force"].sel(tugger=tug))
    return float("nan")


def _settings_table(cx, active) -> str:
    work = cx.work
    rows = []
    for tg in active:
        c = cx.c_tugger(tg)
        cap = float(work["damping_capacity"].sel(tugger=tg)) if "damping_capacity" in work else np.nan
        share = (float(work["saturation_share_route"].sel(candidate=cx.dg.baseline, tugger=tg))
                 if "saturation_share_route" in work else np.nan)
        rows.append([str(tg), num(c, 0), num(line_capacity(cx, tg), 0), num(cap, 0),
                     num(cap / c if c else np.nan, 2), pct(share) if np.isfinite(share) else "–"])
    policy = work.attrs.get("winch_saturation", "not stated")
    return ("Winch settings and the frequency-domain saturation flag. A cell is flagged "
            "*frequency domain unreliable: winch saturates* when its 3-hour MPM net force exceeds "
            "what the pair has for damping, $n (T_max - T_0)$ (the study's definition: per line "
            f"the capacity above the pretension). Policy for flagged cells: *{t(policy)}* "
            + ("(they fail)" if policy == "fail" else "(the time domain decides; cells without a "
               "run keep the frequency-domain verdict)" if policy == "timedomain" else "")
            + ".\n" + table(f"Tugger settings: damping slope, winch capacity per line (the "
                            f"time-domain cells' setting; – where no cell ran), net force of the "
                            f"pair available for damping, the pay-out speed at which a line "
                            f"reaches a limit, and the probability of the route in flagged cells "
                            f"({cx.dg.baseline} rigging).",
                            ["setting", "c [kN s/m]", "capacity per line [kN]",
                             "force for damping [kN]", "saturates at [m/s]", "route flagged"], rows,
                            label="tab-tugger-settings"))


def _fd_loads(cx, active) -> str:
    resp, dg = cx.resp, cx.dg
    if "tugger_mpm_force" not in resp:
        return "#note[The response dataset has no tugger loads.]\n"
    rows = []
    r = resp.sel(candidate=dg.baseline)
    for tg in active:
        f = r["tugger_mpm_force"].sel(tugger=tg)
        i = np.unravel_index(int(np.nanargmax(f.values)), f.shape)
        at = {d: f[d].values[k] for d, k in zip(f.dims, i)}
        fmax = float(f.max())
        cap = (float(cx.work["damping_capacity"].sel(tugger=tg))
               if "damping_capacity" in cx.work else np.nan)
        rows.append([str(tg), num(at["tz"], 1), num(fmax, 0),
                     num(r["tugger_mpm_payout_velocity"].sel(tugger=tg).sel(at), 3),
                     num(r["tugger_power_mean"].sel(tugger=tg).sel(at), 0),
                     num(r["tugger_power_peak"].sel(tugger=tg).sel(at), 0),
                     num(cap / fmax if fmax > 0 else np.nan, 2)])
    return table(f"Frequency-domain tugger loads per metre of Hs ({dg.baseline} rigging), at the "
                 "Tz of the largest force: 3-hour MPM net force and pay-out velocity (scale with "
                 "Hs), mean and peak power absorbed by the pair (scale with Hs²), and the Hs above "
                 "which the winch saturates there. Every candidate, heading and Tz is in "
                 "the response dataset.",
                 ["setting", "Tz [s]", "MPM force [kN/m]", "MPM pay-out [m/s/m]",
                  "mean power [kW/m²]", "peak power [kW/m²]", "saturates above Hs [m]"], rows,
                 label="tab-tugger-loads")


def _timedomain(cx) -> str:
    work = cx.work
    out = [heading("tuggers-td", "Time-domain cells", 2)]
    if not cx.td:
        out.append("No time-domain cell ran for this route.\n")
        return "\n".join(out)
    reasons = {c["name"]: "; ".join(c.get("reasons", [])) for c in cx.td_cells}
    d0 = cx.td[0]
    out.append(
        f"{plural(len(cx.td), 'cell')} ran in the nonlinear time domain "
        f"(exact wire geometry with slack, winch limits active, RK4 at {num(d0.attrs['dt_s'], 3)} s): "
        f"records of {num(float(d0.attrs['duration_s']) / 3600, 2)} h after a "
        f"{num(d0.attrs['transient_s'], 0)} s start-up transient, every tugger setting on the "
        "same wave record. The MPM from sigma uses N from the record's own Tz, as the frequency "
        "domain does; the MPM from up-crossings counts them. A cell's time-domain verdict "
        "(relative-sway MPM from sigma within the limit, no hoist wire slack) replaces the "
        "frequency-domain one for the relative sway in every leg where the cell occurs; a cell of "
        "a leg whose sea is its own (partitions, measured spectra, a Torsethaugen table) runs on a "
        "multi-directional record of that leg's sea in the cell and decides in that leg only.\n")
    grid_best = int(work.attrs.get("timedomain_grid_best", 0))
    if grid_best:
        out.append(t(
            f"The cells of a candidate grid are chosen by a rule that does not grow with the grid: "
            f"besides the baseline, the listed candidates and the screening's optimum, only the "
            f"{plural(grid_best, 'grid candidate')} of highest frequency-domain route workability "
            "(best tugger setting, winch limits applied; timedomain.grid_boundary_candidates) "
            "sent their boundary cells. The grid's other candidates keep the frequency-domain "
            "verdicts and are excluded from the recommendation (\"no time domain\").") + "\n")
    rows = []
    for d in cx.td:
        rows.append([cell(_cell_text(d), colspan=12, fill="luma(240)")])
        for tg in d["tugger"].values:
            r = d.sel(tugger=tg)
            rows.append([str(tg),
                         num(r["sigma"], 3), num(r["sigma_fd"], 3), num(r["mpm_sigma"], 2),
                         num(r["mpm_upcrossing"], 2), num(r["max_observed"], 2),
                         num(100 * float(r["limit_fraction"]), 1), num(r["power_mean"], 0),
                         num(r["power_peak"], 0), num(r["wire_tension_min"], 0),
                         num(r["wire_tension_max"], 0), str(int(r["slack_events"]))])
    out.append(table("Time-domain statistics per cell (shaded row) and setting: sigma of the "
                     "relative sway (time domain, frequency domain), MPM from sigma and from "
                     "up-crossings, largest observed, time a line sits at a force limit, mean and "
                     "peak winch power, hoist-wire tension extremes and slack events.",
                     ["tugger", "σ TD [m]", "σ FD [m]", "MPM σ [m]", "MPM up [m]",
                      "max [m]", "at limit [%]", "P mean [kW]", "P peak [kW]", "T min [kN]",
                      "T max [kN]", "slack"], rows, size="7pt", label="tab-td"))
    if reasons:
        names = {str(d.attrs["cell"]): _cell_text(d) for d in cx.td}
        out.append("Why each cell ran: " + "; ".join(f"{t(names.get(k, k))}: {t(v)}"
                                                     for k, v in reasons.items()) + ".\n")
    if "verdict_source" in work:
        src = work["verdict_source"]
        n_td = int((src == TIME_DOMAIN).sum())
        n_fail = int((src == SATURATED_FAIL).sum())
        n_kept = int((src == SATURATED_UNRESOLVED).sum())
        out.append(f"Where the cells' verdicts come from: {n_td} from the time "
                   f"domain, {n_fail} failed because the winch saturates, {n_kept} flagged but kept "
                   "from the frequency domain (no time-domain run), the others from the frequency "
                   "domain.\n")
    if "td_traces" in cx.figs:
        out.append(figure(cx.figs["td_traces"], "Relative sway over a window from the middle of "
                          "the record (study figure 6.4), every setting on the same waves; "
                          "dashed: the relative-sway limit."))
    return "\n".join(out)


def _cell_text(d) -> str:
    """A time-domain cell in words: rigging, heading, Hs and Tz (its attributes)."""
    a = d.attrs
    text = (f"{a['candidate']} rigging, heading {float(a['heading_deg']):g}°, Hs "
            f"{float(a['hs_m']):g} m, Tz {float(a['tz_s']):g} s")
    if a.get("sea_leg"):                 # a leg's own sea, not a JONSWAP on (Hs, Tz)
        text += f", leg {a['sea_leg']}: {a['sea']}"
    return text


def _cases(cx) -> str:
    work = cx.work
    cases = four_cases(cx)
    out = [heading("tuggers-cases", "Rigging change and tugger side by side", 2)]
    if len(cases) < 4:
        out.append("The four cases of the study's section 6.8 need an active tugger setting and a "
                   "changed rigging candidate; " + ("the configuration has no changed candidate."
                                                    if len([c for c in cx.dg.candidates]) < 2 else
                                                    "only these are available.") + "\n")
    curve = work["hs_limit_curve"].min("heading") if "hs_limit_curve" in work else None
    tzc = curve["tz_curve"].values if curve is not None else np.array([])
    tz_cols = [tz for tz in CASE_TZ if np.any(np.isclose(tzc, tz))]
    rows = []
    base = cx.w_route(cases[0][1])
    dg = cx.dg
    for label, combo in cases:
        w = cx.w_route(combo)
        page1 = ("recommended" if combo == dg.best else
                 f"excluded: {dg.excluded[combo].short}" if combo in dg.excluded else "eligible")
        row = [label, f"{combo[0]} / {combo[1]}", pct(w),
               ("–" if combo == cases[0][1] else signed(100 * (w - base), 1, "pp")), page1]
        for tz in tz_cols:
            row.append(num(curve.sel(candidate=combo[0], tugger=combo[1]).sel(tz_curve=tz, method="nearest"), 2))
        rows.append(row)
    tug = next((c[1] for lab, c in cases if lab == "tugger only"), None)
    why = ""
    if tug and any(c in dg.excluded for _, c in cases):
        why = (f" The tugger setting is {t(tug)}, the one page 1 excludes least (the column "
               "'page 1' says for what); a case page 1 excludes is shown for comparison, not "
               "as an option.")
    out.append("The study's section 6.8: the rigging as rigged, with the tugger, with the rigging "
               "changed, and with both, on the same frequency-domain basis. The route workability "
               "includes the winch limits and the time-domain verdicts as above; the limiting Hs "
               f"is the linear one, without winch limits ({ref('tab-tugger-loads', 'table')} gives "
               "the Hs at which each winch saturates). The two act on the same motion, so their "
               f"effects overlap rather than add.{why}\n")
    out.append(table("Route workability and limiting Hs (lowest over the headings) at selected "
                     "Tz for the four cases, and how page 1 treats each.",
                     ["case", "rigging / tugger", "route", "gain", "page 1"]
                     + [f"Hs lim, Tz {tz:g} s [m]" for tz in tz_cols], rows, size="8pt"))
    if "four_cases" in cx.figs:
        out.append(figure(cx.figs["four_cases"], "Limiting Hs of the four cases (lowest over the "
                          "headings); dashed: the steepness ceiling (study figure 6.9)."))
    return "\n".join(out)


__all__ = ["chapter", "decay", "figure_plan", "four_cases", "four_cases_figure", "td_traces",
           "trace_cells"]
