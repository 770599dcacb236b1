"""Chapter "Weather windows": how often a workable window of a leg's duration opens, per
calendar month, for the legs given by an hourly hindcast (``weather_windows.nc``,
:mod:`jls.stages.weather_windows`), with the figure of the window probability per month."""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.report.context import Context, combo_text, heading
from jls.report.contract import pct
from jls.report.markup import figure, num, t, table
from jls.report.style import STYLE, Task, legend_columns, new_figure, save

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


def window_combo(cx: Context):
    """The combination the chapter shows: the report's best when the file has it."""
    win = cx.windows
    opts = {(str(c), str(g)) for c in win["candidate"].values for g in win["tugger"].values}
    if cx.dg.best in opts:
        return cx.dg.best
    return (str(win.attrs["option_candidate"]), str(win.attrs["option_tugger"]))


def window_alpha_text(win) -> str:
    """The alpha the windows were judged with: the operation's table, hour by hour at the
    planned period of each leg's stretch (the master's OP_WF's), or a constant."""
    a = win.attrs
    if str(a.get("alpha_source", "")):
        periods = ", ".join(f"{x.split(':')[0]} {x.split(':')[1]} h" for x in str(a["alpha_periods_h"]).split())
        return (f"forecast-uncertainty factor α from {a['alpha_source']} at each hour's limiting Hs and the "
                f"planned period of the leg's stretch ({periods}), the α of the master's OP_WF")
    return f"operational factor α = {float(a['alpha']):g}, a constant"


def figure_plan(cx: Context) -> list[Task]:
    """The window probability per month, when the route has hindcast legs."""
    if cx.windows is None:
        return []
    return [Task("window_months", lambda d: window_months(cx.windows, window_combo(cx), d), 1.0)]


def chapter(cx: Context) -> str:
    out = [heading("weather_windows", "Weather windows")]
    win = cx.windows
    if win is None:
        out.append("No leg of this route is given by an hourly hindcast: its wave statistics are "
                   "scatter tables, which say how much of the time the sea is workable but not "
                   "whether the workable time comes in one piece. A weather-window (persistence) "
                   "analysis needs an hourly record of the sea states, and none was given for this "
                   f"route; the voyage extremes ({cx.sec('voyage')}) treat the sea states as "
                   "independent instead, on the conservative side.\n")
        return "\n".join(out)
    combo = window_combo(cx)
    a = win.attrs
    out.append(
        "For each leg given by an hourly hindcast, every hour is judged like a scatter cell "
        "(Hs times the unit utilisation interpolated in Tz, every criterion; no steepness cap on "
        f"recorded sea states; {t(window_alpha_text(win))}). A "
        "window of the leg's duration needs that many consecutive workable hours; the window "
        "probability is the share of start hours that open one, per calendar month of the start "
        "(DNV-ST-N001 persistence analysis). Windows containing a missing hour are "
        + ("left out" if a["gaps"] == "exclude" else "counted as not workable")
        + f"; hours with Tz outside the statistics' grid: {t(a['tz_outside'])}. "
        f"Shown: {t(combo_text(combo))}.\n")
    out.append(figure(cx.figs["window_months"],
                      f"Probability that a workable window of the leg's duration starts at a random "
                      f"hour of the month, {combo_text(combo)}; months without a judged start are "
                      "empty.", width="90%"))
    rows = []
    for leg in (str(v) for v in win["leg"].values):
        s = win.sel(leg=leg)
        p_all = float(win["window_probability_all_options"].sel(candidate=combo[0], tugger=combo[1], leg=leg))
        frac = float(win["workable_fraction_options"].sel(candidate=combo[0], tugger=combo[1], leg=leg))
        rows.append([leg, num(float(s["window_duration_h"]), 0), pct(frac), pct(p_all),
                     str(int(s["missing_hours"])), pct(float(s["record_coverage"])),
                     str(int(s["hours_outside_tz"]))])
    out.append(table(
        "Hindcast legs: window duration, share of workable hours, probability of a workable "
        "window over the record, missing hours, record coverage and hours with Tz outside the "
        "statistics' grid.", ["leg", "window [h]", "workable hours", "window probability",
                              "missing [h]", "coverage", "Tz outside [h]"], rows))
    long_legs = [str(v) for v in win["leg"].values if float(win["window_duration_h"].sel(leg=v)) > 72]
    if long_legs:
        out.append(f"#note[Legs longer than 72 h ({t(', '.join(long_legs))}) are unrestricted "
                   "operations in DNV-ST-N001, designed on the statistics of the route "
                   f"({cx.sec('operation')}); their window probability is a planning figure only.]\n")
    return "\n".join(out)


# -- figure ---------------------------------------------------------------------------
def window_months(win: xr.Dataset, combo, out_dir):
    """Probability of a workable window of each hindcast leg's duration per calendar month
    of the start, for one combination."""
    p = win["window_probability_options"].sel(candidate=combo[0], tugger=combo[1])
    legs = [str(v) for v in p["leg"].values]
    width = 0.8 / max(len(legs), 1)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        for k, leg in enumerate(legs):
            vals = 100 * p.sel(leg=leg).values
            ax.bar(np.arange(12) + (k - (len(legs) - 1) / 2) * width, np.nan_to_num(vals), width,
                   color=f"C{k}", label=f"{leg} ({float(win['window_duration_h'].sel(leg=leg)):g} h)")
        ax.set_xticks(np.arange(12), MONTHS)
        ax.set_ylim(0, 100)
        ax.set_ylabel("window probability [%]")
        ax.grid(False, axis="x")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "window_months")


__all__ = ["MONTHS", "chapter", "figure_plan", "window_combo", "window_months"]
