"""The second part of the chapter "Rigging" (:mod:`jls.report.rigging`): the optimised
rigging assessed beside the baseline, and the recommended option against the route's
sea states.

* :func:`baseline_vs_optimised` - relative sway and yaw transfer functions and the
  operability curves of the two riggings, per tugger setting shown;
* :func:`recommended_operability` - the limiting Hs of the recommended combination with
  every leg's scatter behind it (cells as dots sized by probability), the steepness
  ceiling and the design Hs;
* :func:`workability_table` and :func:`window_table` - workability of both riggings, and
  the workable Tz window at the design Hs (:func:`tz_window`; the study's tables 6.7-6.8).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.names import RELATIVE_SWAY, RELATIVE_YAW
from jls.report.context import Context
from jls.report.contract import ceiling_curve, complex_var, limit_curves, pct
from jls.report.markup import cell, num, table
from jls.report.style import STYLE, TUG_STYLES, Task, legend_columns, log_ticks, new_figure, save

OPTIMISED = "optimised"
RIG_COLOURS = {"baseline": "black", OPTIMISED: "tab:red"}
LEG_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink"]


def figure_plan(cx: Context) -> list[Task]:
    """The comparison of baseline and optimised (the first four tugger settings) and the
    recommended option's operability."""
    tugs = [str(x) for x in cx.work["tugger"].values][:4]
    design_hs = float(cx.screening.attrs["design_hs_m"])
    return [Task("rigging_compare", lambda d: baseline_vs_optimised(cx.resp, cx.work, tugs, d), 3.2),
            Task("recommended_operability",
                 lambda d: recommended_operability(cx.work, cx.sea, cx.dg.best, design_hs, d), 0.8)]


# -- tables -----------------------------------------------------------------------------
def workability_table(cx: Context) -> str:
    legs = cx.legs
    rows = []
    for cand in ("baseline", OPTIMISED):
        for tg in [str(x) for x in cx.work["tugger"].values]:
            rows.append([f"{cand} / {tg}", *[pct(cx.w_leg((cand, tg), leg)) for leg in legs],
                         cell(pct(cx.w_route((cand, tg))), bold=True)])
    return table("Workability per leg and for the route, baseline and optimised rigging.",
                 ["rigging / tugger", *legs, "route"], rows)


def window_table(cx: Context) -> str:
    dg, work = cx.dg, cx.work
    hs = float(cx.screening.attrs["design_hs_m"])
    heads = [float(h) for h in work["heading"].values]
    combos = [(c, str(tg)) for c in ("baseline", OPTIMISED) for tg in work["tugger"].values]
    if dg.best not in combos:
        combos.append(dg.best)
    ref = {h: tz_window(work, (dg.baseline, dg.no_tugger), h, hs)[1] for h in heads}
    rows = []
    for combo in combos:
        for h in heads:
            lo, hi = tz_window(work, combo, h, hs)
            gain = hi - ref[h]
            rows.append([f"{combo[0]} / {combo[1]}" + (f", {h:g}°" if len(heads) > 1 else ""),
                         num(lo, 2), num(hi, 2),
                         "–" if combo == (dg.baseline, dg.no_tugger) or not np.isfinite(gain)
                         else f"{gain:+.2f}"])
    return table(f"Workable Tz window at the design Hs of {hs:g} m (screening.design_hs_m): the "
                 "Tz range in which the limiting Hs, capped by the steepness ceiling, reaches it, "
                 f"and the upper end gained over the {dg.baseline} rigging without tugger (the "
                 "study's tables 6.7-6.8). A lower end set by the ceiling is the same for every "
                 "combination.", ["rigging / tugger", "from Tz [s]", "to Tz [s]", "gained [s]"], rows)


# -- figures ----------------------------------------------------------------------------
def baseline_vs_optimised(resp: xr.Dataset, work: xr.Dataset, tuggers, out_dir,
                          heading=None) -> Path:
    """Three panels at one heading: |relative sway| and |relative yaw| per unit wave
    amplitude against wave period, and the limiting Hs against Tz, baseline (black)
    and optimised (red), one line style per tugger setting."""
    H = complex_var(resp, "transfer").rename(shown_candidate="candidate")
    h = float(resp["heading"].values[0] if heading is None else heading)
    period = 2 * np.pi / resp["omega"].values
    curve, _ = limit_curves(work)
    tz = curve["tz"].values
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.0)
        axes = fig.subplots(1, 3)
        for cand, colour in RIG_COLOURS.items():
            for k, tg in enumerate(tuggers):
                style = {"color": colour, "ls": TUG_STYLES[k % len(TUG_STYLES)], "lw": 0.9,
                         "label": f"{cand} / {tg}"}
                for ax, r in ((axes[0], RELATIVE_SWAY), (axes[1], RELATIVE_YAW)):
                    ax.semilogy(period, np.abs(H.sel(candidate=cand, tugger=tg, heading=h, response=r).values),
                                **style)
                axes[2].plot(tz, curve.sel(candidate=cand, tugger=tg, heading=h).values, **style)
        axes[0].set_title(f"relative sway [m/m], {h:g}°")
        axes[1].set_title(f"relative yaw [deg/m], {h:g}°")
        axes[2].set_title("limiting Hs [m]")
        for ax in axes[:2]:
            log_ticks(ax.yaxis)
            ax.set_xlim(3.0, min(float(period.max()), 25.0))
            ax.set_xlabel("wave period [s]")
        axes[2].set_xlabel("Tz [s]")
        axes[2].set_xlim(float(np.nanmin(tz)), float(np.nanmax(tz)))
        axes[2].set_ylim(0, None)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "rigging_compare")


def recommended_operability(work: xr.Dataset, sea: xr.Dataset, combo, design_hs, out_dir) -> Path:
    """The recommended combination's limiting Hs (per heading) over every leg's
    scatter: one dot per cell of non-zero probability, area proportional to it."""
    curve, _ = limit_curves(work)
    tz_c = curve["tz"].values
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.4)
        ax = fig.subplots()
        for k, leg in enumerate(sea["leg"].values):
            p = sea["probability"].sel(leg=leg)
            p = p.transpose("hs", "tz").values
            hs, tz = np.meshgrid(sea["hs"].values, sea["tz"].values, indexing="ij")
            live = np.isfinite(p) & (p > 0)
            ax.scatter(tz[live], hs[live], s=600 * p[live], color=LEG_COLOURS[k % len(LEG_COLOURS)],
                       alpha=0.45, lw=0, label=f"leg {leg} (dot area = probability)")
        t_f, ceil = ceiling_curve(work, float(np.nanmin(tz_c)), float(np.nanmax(tz_c)))
        lines = [curve.sel(candidate=combo[0], tugger=combo[1], heading=hd).values
                 for hd in work["heading"].values]
        top = float(np.nanmax([np.nanmax(x) for x in lines])) * 1.15 if lines else 5.0
        top = max(top, 1.2 * float(design_hs), float(np.nanmax(sea["hs"].values)))
        ax.plot(t_f, np.minimum(ceil, top), color="0.5", ls="--", lw=1.0, label="steepness ceiling")
        for k, (hd, y) in enumerate(zip(work["heading"].values, lines)):
            ax.plot(tz_c, y, color="k", ls=TUG_STYLES[k % len(TUG_STYLES)], lw=1.3,
                    label=f"limiting Hs, {combo[0]} / {combo[1]}, {hd:g}°")
        ax.axhline(float(design_hs), color="tab:red", lw=0.8, label=f"design Hs {float(design_hs):g} m")
        ax.set_xlim(float(np.nanmin(tz_c)), float(np.nanmax(tz_c)))
        ax.set_ylim(0, top)
        ax.set_xlabel("zero-crossing period Tz [s]")
        ax.set_ylabel("significant wave height Hs [m]")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "recommended_operability")


def tz_window(work: xr.Dataset, combo, heading, design_hs) -> tuple[float, float]:
    """(from, to) Tz [s] of the contiguous window in which the combination's limiting Hs
    (steepness-capped) reaches ``design_hs``, the ends interpolated linearly on the
    operability grid; (nan, nan) when it never does. The widest such window is returned."""
    curve, _ = limit_curves(work)
    tz = curve["tz"].values
    y = curve.sel(candidate=combo[0], tugger=combo[1], heading=heading).values - float(design_hs)
    ok = np.isfinite(y) & (y >= 0)
    if not ok.any():
        return np.nan, np.nan
    runs, start = [], None
    for i, flag in enumerate(ok):
        if flag and start is None:
            start = i
        if start is not None and (not flag or i == ok.size - 1):
            runs.append((start, i if flag else i - 1))
            start = None
    a, b = max(runs, key=lambda r: tz[r[1]] - tz[r[0]])

    def cross(i, j):                     # zero of y between grid points i (>= 0) and j (< 0)
        if j < 0 or j >= tz.size or not np.isfinite(y[j]):
            return float(tz[i])
        return float(tz[i] + (tz[j] - tz[i]) * y[i] / (y[i] - y[j]))

    return cross(a, a - 1), cross(b, b + 1)


__all__ = ["LEG_COLOURS", "OPTIMISED", "RIG_COLOURS", "baseline_vs_optimised", "figure_plan",
           "recommended_operability", "tz_window", "window_table", "workability_table"]
