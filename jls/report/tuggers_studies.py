"""The second part of the chapter "Damping tuggers" (:mod:`jls.report.tuggers`): the
decay tests and the damping-slope sweep of ``tugger_studies.nc``, beside the study's
values (its section 6.6 and table 6.6).

The critical damping of the sway mode is the dataset's (attribute
``critical_slope_kN_s_per_m``); a sweep slope within 0.5 % of it is marked critical and
compared with the study's row at its own critical damping. What the sweep shows about
the gain of a steeper slope is read from its numbers (:func:`sweep_trend`).
"""

from __future__ import annotations

import matplotlib
import numpy as np

from jls.report.context import Context, heading
from jls.report.markup import figure, num, t, table
from jls.report.style import CAND_COLOURS, STYLE, new_figure, save

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
#: The study's critical damping of the sway mode [kN s/m] (table 6.6's last slope).
STUDY_CRITICAL_SLOPE = 6178



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


def decay_section(cx) -> str:
    st = cx.studies
    out = [heading("tuggers-decay", "Decay tests", 2)]
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


def sweep_section(cx) -> str:
    st = cx.studies
    out = [heading("tuggers-sweep", "Damping-slope sweep", 2)]
    if st is None or "sweep_mpm" not in st:
        out.append("No slope sweep was run.\n")
        return "\n".join(out)
    tzs = [float(v) for v in st["sweep_tz"].values]
    same = (abs(float(st.attrs["sweep_hs_m"]) - 2.4) < 1e-9
            and abs(float(st.attrs["sweep_capacity_kN"]) - 1000.0) < 1e-9)
    header = ["slope [kN s/m]"]
    for tz in tzs:
        header += [f"Tz {tz:g}: MPM [m]", "cap. [%]"] + (["study MPM, cap."] if same else [])
    critical = float(st.attrs["critical_slope_kN_s_per_m"])
    slopes = [float(s) for s in st["slope"].values]
    rows = []
    for s in slopes:
        is_crit = abs(s - critical) <= 0.005 * critical
        row = [num(s, 0) + (" (critical)" if is_crit else "")]
        for tz in tzs:
            r = st.sel(slope=s, sweep_tz=tz)
            row += [num(r["sweep_mpm"], 2), num(100 * float(r["sweep_at_capacity_fraction"]), 1)]
            if same:
                key = STUDY_CRITICAL_SLOPE if is_crit else int(round(s))
                study = STUDY_SWEEP.get(key, {}).get(round(tz, 1))
                row.append(f"{study[0]:.2f}, {study[1]:.1f}" if study else "–")
        rows.append(row)
    last = ""
    if abs(slopes[-1] - critical) > 0.005 * critical:
        last = (f" The sweep's last slope, {num(slopes[-1], 0)} kN s/m, is "
                + ("the study's critical damping, " if int(round(slopes[-1])) == STUDY_CRITICAL_SLOPE else "")
                + "not this plant's.")
    out.append(f"The slope of the pair swept in the time domain with the winch capacity held at "
               f"{num(st.attrs['sweep_capacity_kN'], 0)} kN, Hs {num(st.attrs['sweep_hs_m'], 1)} m, "
               f"heading {num(st.attrs['sweep_heading_deg'], 0)}°, records of "
               f"{num(float(st.attrs['sweep_duration_s']) / 3600, 2)} h (study table 6.6), each on a "
               f"long-crested JONSWAP as the study's: a study sea state, "
               f"not any leg's sea, so it compares the slopes with the study and assesses no leg. The "
               f"critical damping of this plant's sway mode is {num(critical, 0)} kN s/m "
               f"(the tugger-studies dataset).{last} Once a line sits at its capacity a steeper law adds "
               f"no force there. {t(sweep_trend(st))}\n")
    out.append(table("Three-hour MPM relative sway (from up-crossings) and the time a line sits "
                     "at the winch capacity, against the damping slope"
                     + (", with the study's values" if same else "") + ". The vessel differs "
                     "from the study's, so the values differ; the pattern is what compares.",
                     header, rows, size="7pt"))
    return "\n".join(out)


def sweep_trend(st) -> str:
    """What the sweep shows about the gain of a steeper slope, from its own numbers: per
    Tz whether the MPM still falls at the last step, and by how much against the first."""
    slopes = [float(s) for s in st["slope"].values]
    if len(slopes) < 3:
        return ""
    parts, stops = [], []
    for tz in (float(v) for v in st["sweep_tz"].values):
        m = st["sweep_mpm"].sel(sweep_tz=tz).values.astype(float)
        cap = 100 * float(st["sweep_at_capacity_fraction"].sel(sweep_tz=tz).values[-1])
        rises = np.flatnonzero(np.diff(m) >= 0)
        if rises.size:
            stops.append(f"at Tz {tz:g} s the MPM stops falling above {num(slopes[rises[0]], 0)} kN s/m")
            continue
        first, lastd = 100 * (m[0] - m[1]) / m[0], 100 * (m[-2] - m[-1]) / m[-2]
        parts.append(f"Tz {tz:g} s: {num(m[0], 2)} to {num(m[-1], 2)} m, the last step "
                     f"{num(lastd, 0)} % against {num(first, 0)} % for the first, at capacity "
                     f"{num(cap, 1)} % of the time at the end")
    text = ""
    if parts:
        text = ("Over the sweep the MPM keeps falling with the slope (" + "; ".join(parts) + "): "
                "each added slope buys less as the lines sit at their capacity longer, but the gain "
                "does not stop within the sweep.")
    if stops:
        text += (" " if text else "") + "; ".join(stops).capitalize() + "."
    return text



__all__ = ["STUDY_CRITICAL_SLOPE", "STUDY_DECAY_S", "STUDY_SWEEP", "decay", "decay_section",
           "sweep_section", "sweep_trend"]
