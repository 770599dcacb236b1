"""The report's chapter "Damping tuggers" (chapter 6 of the study): winch settings and their
frequency-domain loads, the time-domain cells (traces, limit occupancy, power, verdicts),
decay tests, the damping-slope sweep, and the four cases of section 6.8 side by side.

Reads the context's ``td`` (time-domain cell datasets), ``td_cells`` (the chosen cells
with their reasons) and ``studies`` (decay and sweep); without them the chapter says what
is missing. Its figures are listed by :func:`figure_plan`.
"""

from __future__ import annotations

import matplotlib
import numpy as np

from jls.names import SATURATED_FAIL, SATURATED_UNRESOLVED, SWAY_M, TIME_DOMAIN
from jls.report.context import Context
from jls.report.contract import pct
from jls.report.markup import figure, num, t, table
from jls.report.style import CAND_COLOURS, STYLE, Task, new_figure, save

MAX_TRACE_CELLS = 2
#: Study section 6.6: time to 10 % of a 3.0 m release [s] (none, low 300, high 2000 kN s/m).
STUDY_DECAY_S = {0.0: 581.0, 300.0: 95.0, 2000.0: 17.0}
#: Study table 6.6 (Hs 2.4 m, capacity 1000 kN): slope -> {Tz: (MPM m, at capacity %)}.
STUDY_SWEEP = {
    150: {6.6: (2.92, 0.0), 8.0: (10.72, 0.0), 8.5: (15.08, 0.0)},
    300: {6.6: (2.89, 0.0), 8.0: (9.39, 0.0), 8.5: (12.57, 0.7)},
    600: {6.6: (2.80, 0.0), 8.0: (8.14, 2.5), 8.5: (10.80, 7.2)},
    1000: {6.6: (2.65, 0.0), 8.0: (7.47, 9.3), 8.5: (10.11, 15.7)},
    1500: {6.6: (2.47, 0.7), 8.0: (7.14, 15.7), 8.5: (9.81, 22.1)},
    2000: {6.6: (2.33, 2.5), 8.0: (6.99, 20.2), 8.5: (9.68, 26.6)},
    3000: {6.6: (2.15, 6.4), 8.0: (6.85, 25.9), 8.5: (9.56, 31.5)},
    4500: {6.6: (2.01, 11.3), 8.0: (6.76, 30.5), 8.5: (9.48, 35.3)},
    6178: {6.6: (1.94, 14.8), 8.0: (6.71, 33.2), 8.5: (9.43, 37.6)},
}
CASE_TZ = (6.0, 6.5, 7.0, 7.5, 8.0)
RIGGING_CHANGE_NAMES = ("detuned", "optimised", "optimized")


def four_cases(cx: Context):
    """(label, combo) of section 6.8: as rigged, tugger only, rigging changed, both. The
    tugger is 'reference' if configured, else the active setting with the highest route
    workability on the baseline; the rigging change is the 'detuned' (or 'optimised')
    candidate, else the best feasible candidate other than the baseline."""
    dg = cx.dg
    active = [tg for tg in dg.tuggers if cx.c_tugger(tg) > 0]
    if "reference" in active:
        tug = "reference"
    elif active:
        tug = max(active, key=lambda tg: cx.w_route((dg.baseline, tg)))
    else:
        tug = None
    others = [c for c in dg.candidates if c != dg.baseline]
    named = [c for c in RIGGING_CHANGE_NAMES if c in others]
    if named:
        rig = named[0]
    else:
        feas = [c for c in others if cx.feasible(c)]
        rig = max(feas, key=lambda c: cx.w_route((c, dg.no_tugger))) if feas else None
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


def decay(cx: Context, out_dir):
    """Free decay of the relative sway per tugger setting, 10 % of the release dotted."""
    st = cx.studies
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.3)
        ax = fig.subplots()
        for i, tg in enumerate(st["tugger"].values):
            ax.plot(st["decay_time"].values, st["decay_sway"].sel(tugger=tg).values,
                    color=CAND_COLOURS[i % len(CAND_COLOURS)], lw=0.8,
                    label=f"{tg} ({float(st['c_tugger'].sel(tugger=tg)):g} kN s/m)")
        rel = float(st.attrs["release_m"])
        for s in (-1, 1):
            ax.axhline(s * 0.1 * rel, color="grey", ls=":", lw=0.8)
        ax.set_xlabel("time after release [s]")
        ax.set_ylabel("relative sway [m]")
        ax.legend(ncol=4, loc="upper right")
        return save(fig, out_dir, "decay")


def four_cases_figure(cx: Context, out_dir):
    """Limiting Hs of the four cases of section 6.8 (lowest over the headings)."""
    cases = four_cases(cx)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        curve = cx.work["hs_limit_curve"].min("heading")
        tz = curve["tz_curve"].values
        for i, (label, (c, tg)) in enumerate(cases):
            ax.plot(tz, curve.sel(candidate=c, tugger=tg).values, color=CAND_COLOURS[i],
                    label=f"{label} ({c} / {tg})")
        ax.plot(tz, cx.work["steepness_limit_curve"].values, color="grey", ls="--",
                label="steepness ceiling")
        ax.set_xlabel("Tz [s]")
        ax.set_ylabel("limiting Hs [m]")
        ax.set_ylim(0, None)
        ax.legend(ncol=2, loc="upper right")
        return save(fig, out_dir, "four_cases")


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
    dg = cx.dg
    out = ["= Damping tuggers\n"]
    active = [tg for tg in dg.tuggers if cx.c_tugger(tg) > 0]
    if not active:
        out.append("No damping-tugger setting is configured (every slope is zero); nothing to "
                   "assess in this chapter.\n")
        return "\n".join(out)
    out.append(
        "A damping tugger is a pair of opposing lines from fairleads on the vessel to the jacket "
        "at CoG height. Each line follows $T = T_0 + c/n u$ between its floor and its winch "
        "capacity, so between the limits the pair is a linear damper of slope $c$ on the "
        "velocity of the jacket's sway against the fairlead. The frequency domain (sections 5-7) "
        "has no limits; here the loads it implies are set against the winch, cells where it "
        "saturates are flagged, and the nonlinear time domain checks the cells that matter.\n")
    out.append(_settings_table(cx, active))
    out.append(_fd_loads(cx, active))
    out.append(_timedomain(cx))
    out.append(_decay(cx))
    out.append(_sweep(cx))
    out.append(_cases(cx))
    return "\n".join(out)


def _settings_table(cx, active) -> str:
    work = cx.work
    rows = []
    for tg in active:
        c = cx.c_tugger(tg)
        cap = float(work["damping_capacity"].sel(tugger=tg)) if "damping_capacity" in work else np.nan
        share = (float(work["saturation_share_route"].sel(candidate=cx.dg.baseline, tugger=tg))
                 if "saturation_share_route" in work else np.nan)
        rows.append([str(tg), num(c, 0), num(cap, 0), num(cap / c if c else np.nan, 2),
                     pct(share) if np.isfinite(share) else "–"])
    policy = work.attrs.get("winch_saturation", "not stated")
    return ("Winch settings and the frequency-domain saturation flag. A cell is flagged "
            "*frequency domain unreliable: winch saturates* when its 3-hour MPM net force exceeds "
            "what the pair has for damping, $n (T_max - T_0)$ (the study's definition: per line "
            f"the capacity above the pretension). Policy for flagged cells: *{t(policy)}* "
            + ("(they fail)" if policy == "fail" else "(the time domain decides; cells without a "
               "run keep the frequency-domain verdict)" if policy == "timedomain" else "")
            + ".\n" + table(f"Tugger settings: damping slope, net force available for damping, the "
                            f"pay-out speed at which a line reaches a limit, and the probability "
                            f"of the route in flagged cells ({cx.dg.baseline} rigging).",
                            ["setting", "c [kN s/m]", "force for damping [kN]",
                             "saturates at [m/s]", "route flagged"], rows))


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
                 "response.nc.",
                 ["setting", "Tz [s]", "MPM force [kN/m]", "MPM pay-out [m/s/m]",
                  "mean power [kW/m²]", "peak power [kW/m²]", "saturates above Hs [m]"], rows)


def _timedomain(cx) -> str:
    work = cx.work
    out = ["== Time-domain cells\n"]
    if not cx.td:
        out.append("No time-domain cell ran for this route.\n")
        return "\n".join(out)
    reasons = {c["name"]: "; ".join(c.get("reasons", [])) for c in cx.td_cells}
    d0 = cx.td[0]
    out.append(
        f"{len(cx.td)} cell{'s' if len(cx.td) > 1 else ''} ran in the nonlinear time domain "
        f"(exact wire geometry with slack, winch limits active, RK4 at {num(d0.attrs['dt_s'], 3)} s): "
        f"records of {num(float(d0.attrs['duration_s']) / 3600, 2)} h after a "
        f"{num(d0.attrs['transient_s'], 0)} s start-up transient, every tugger setting on the "
        "same wave record. The MPM from sigma uses N from the record's own Tz, as the frequency "
        "domain does; the MPM from up-crossings counts them. A cell's time-domain verdict "
        "(relative-sway MPM from sigma within the limit, no hoist wire slack) replaces the "
        "frequency-domain one for the relative sway in every leg where the cell occurs.\n")
    rows = []
    for d in cx.td:
        name = str(d.attrs["cell"])
        for tg in d["tugger"].values:
            r = d.sel(tugger=tg)
            rows.append([name if tg == d["tugger"].values[0] else "", str(tg),
                         num(r["sigma"], 3), num(r["sigma_fd"], 3), num(r["mpm_sigma"], 2),
                         num(r["mpm_upcrossing"], 2), num(r["max_observed"], 2),
                         num(100 * float(r["limit_fraction"]), 1), num(r["power_mean"], 0),
                         num(r["power_peak"], 0), num(r["wire_tension_min"], 0),
                         num(r["wire_tension_max"], 0), str(int(r["slack_events"]))])
    out.append(table("Time-domain statistics per cell and setting: sigma of the relative sway "
                     "(time domain, frequency domain), MPM from sigma and from up-crossings, "
                     "largest observed, time a line sits at a force limit, mean and peak winch "
                     "power, hoist-wire tension extremes and slack events.",
                     ["cell", "tugger", "σ TD [m]", "σ FD [m]", "MPM σ [m]", "MPM up [m]",
                      "max [m]", "at limit [%]", "P mean [kW]", "P peak [kW]", "T min [kN]",
                      "T max [kN]", "slack"], rows, size="7pt"))
    if reasons:
        out.append("Why each cell ran: " + "; ".join(f"{t(k)}: {t(v)}" for k, v in reasons.items()) + ".\n")
    if "verdict_source" in work:
        src = work["verdict_source"]
        n_td = int((src == TIME_DOMAIN).sum())
        n_fail = int((src == SATURATED_FAIL).sum())
        n_kept = int((src == SATURATED_UNRESOLVED).sum())
        out.append(f"Verdicts in workability.nc (variable verdict_source): {n_td} from the time "
                   f"domain, {n_fail} failed because the winch saturates, {n_kept} flagged but kept "
                   "from the frequency domain (no time-domain run), the others from the frequency "
                   "domain.\n")
    if "td_traces" in cx.figs:
        out.append(figure(cx.figs["td_traces"], "Relative sway over a window from the middle of "
                          "the record (study figure 6.4), every setting on the same waves; "
                          "dashed: the relative-sway limit."))
    return "\n".join(out)


def _decay(cx) -> str:
    st = cx.studies
    out = ["== Decay tests\n"]
    if st is None:
        out.append("No decay tests were run.\n")
        return "\n".join(out)
    rows = []
    for tg in st["tugger"].values:
        c = float(st["c_tugger"].sel(tugger=tg))
        study = STUDY_DECAY_S.get(c) if abs(float(st.attrs["release_m"]) - 3.0) < 1e-9 else None
        rows.append([str(tg), num(c, 0), num(st["decay_time_to_10pct"].sel(tugger=tg), 1),
                     num(study, 0) if study else "–",
                     num(100 * float(st["decay_zeta_first_cycle"].sel(tugger=tg)), 2)])
    out.append(f"Released from {num(st.attrs['release_m'], 1)} m of sway on a still vessel "
               f"({t(cx.dg.baseline)} rigging; study section 6.6: 581 s without tugger, 95 s with "
               "300 kN s/m, 17 s with 2000 kN s/m). The decay is pure oscillation at the sway "
               "period, the resonant limit of the device: read it with the sea-state results, "
               "not in place of them.\n")
    out.append(table("Time for the sway to fall to 10 % of the release and first-cycle "
                     "equivalent damping ratio.", ["setting", "c [kN s/m]", "to 10 % [s]",
                                                   "study [s]", "ζ first cycle [%]"], rows))
    if "decay" in cx.figs:
        out.append(figure(cx.figs["decay"], "Free decay of the relative sway; dotted: 10 % of the "
                          "release."))
    return "\n".join(out)


def _sweep(cx) -> str:
    st = cx.studies
    out = ["== Damping-slope sweep\n"]
    if st is None or "sweep_mpm" not in st:
        out.append("No slope sweep was run.\n")
        return "\n".join(out)
    tzs = [float(v) for v in st["sweep_tz"].values]
    same = (abs(float(st.attrs["sweep_hs_m"]) - 2.4) < 1e-9
            and abs(float(st.attrs["sweep_capacity_kN"]) - 1000.0) < 1e-9)
    header = ["slope [kN s/m]"]
    for tz in tzs:
        header += [f"Tz {tz:g}: MPM [m]", "cap. [%]"] + (["study MPM, cap."] if same else [])
    rows = []
    for s in st["slope"].values:
        row = [num(s, 0)]
        for tz in tzs:
            r = st.sel(slope=s, sweep_tz=tz)
            row += [num(r["sweep_mpm"], 2), num(100 * float(r["sweep_at_capacity_fraction"]), 1)]
            if same:
                ref = STUDY_SWEEP.get(int(round(float(s))), {}).get(round(tz, 1))
                row.append(f"{ref[0]:.2f}, {ref[1]:.1f}" if ref else "–")
        rows.append(row)
    out.append(f"The slope of the pair swept in the time domain with the winch capacity held at "
               f"{num(st.attrs['sweep_capacity_kN'], 0)} kN, Hs {num(st.attrs['sweep_hs_m'], 1)} m, "
               f"heading {num(st.attrs['sweep_heading_deg'], 0)}°, records of "
               f"{num(float(st.attrs['sweep_duration_s']) / 3600, 2)} h (study table 6.6; critical "
               f"damping of the sway mode {num(st.attrs['critical_slope_kN_s_per_m'], 0)} kN s/m). "
               "Once a line sits at its capacity a steeper law adds no force: the gain stops "
               "where the occupancy grows.\n")
    out.append(table("Three-hour MPM relative sway (from up-crossings) and the time a line sits "
                     "at the winch capacity, against the damping slope"
                     + (", with the study's values" if same else "") + ". The vessel differs "
                     "from the study's, so the values differ; the pattern is what compares.",
                     header, rows, size="7pt"))
    return "\n".join(out)


def _cases(cx) -> str:
    work = cx.work
    cases = four_cases(cx)
    out = ["== Rigging change and tugger side by side\n"]
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
    for label, combo in cases:
        w = cx.w_route(combo)
        row = [label, f"{combo[0]} / {combo[1]}", pct(w),
               ("–" if combo == cases[0][1] else f"{100 * (w - base):+.1f} pp")]
        for tz in tz_cols:
            row.append(num(curve.sel(candidate=combo[0], tugger=combo[1]).sel(tz_curve=tz, method="nearest"), 2))
        rows.append(row)
    out.append("The study's section 6.8: the rigging as rigged, with the tugger, with the rigging "
               "changed, and with both, on the same frequency-domain basis. The route workability "
               "includes the winch limits and the time-domain verdicts as above; the limiting Hs "
               "is the linear one, without winch limits (the table of loads above gives the Hs "
               "at which each winch saturates). The two act on the same motion, so their effects "
               "overlap rather than add.\n")
    out.append(table("Route workability and limiting Hs (lowest over the headings) at selected "
                     "Tz for the four cases.",
                     ["case", "rigging / tugger", "route", "gain"] + [f"Hs lim, Tz {tz:g} s [m]" for tz in tz_cols],
                     rows))
    if "four_cases" in cx.figs:
        out.append(figure(cx.figs["four_cases"], "Limiting Hs of the four cases (lowest over the "
                          "headings); dashed: the steepness ceiling (study figure 6.9)."))
    return "\n".join(out)


__all__ = ["chapter", "decay", "figure_plan", "four_cases", "four_cases_figure", "td_traces",
           "trace_cells"]
