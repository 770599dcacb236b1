"""The second part of the chapter "Rigging" (:mod:`jls.report.rigging`): the optimised
rigging assessed beside the baseline, and the recommended option against the route's
sea states.

* :func:`baseline_vs_optimised` - relative sway and yaw transfer functions and the
  operability curves of the two riggings, per tugger setting shown;
* :func:`recommended_operability` - the limiting Hs of the recommended combination with
  every leg's scatter behind it (cells as dots sized by probability and coloured by
  whether the combination passes them), the steepness ceiling and the design Hs;
* :func:`window_table` - the workable Tz window at the design Hs of every option
  (:func:`tz_window`; the study's tables 6.7-6.8).

The workability of the options is table 1's (page 1); it is not repeated here.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.names import RELATIVE_SWAY, RELATIVE_YAW
from jls.plant import same_rigging
from jls.report.context import Context, governing_heading
from jls.report.contract import complex_var, flag, on_sea_grid
from jls.report.curves import ceiling_curve, limit_curves
from jls.report.long_tables import MAX_BODY_ROWS
from jls.report.markup import num, signed, table
from jls.report.style import (
    STYLE,
    TUG_STYLES,
    Task,
    legend_columns,
    log_ticks,
    new_figure,
    operability_top,
    save,
    transfer_range,
)

OPTIMISED = "optimised"
RIG_COLOURS = {"baseline": "black", OPTIMISED: "tab:red"}


def figure_plan(cx: Context) -> list[Task]:
    """The comparison of baseline and optimised (the first four tugger settings) and the
    recommended option's operability."""
    tugs = [str(x) for x in cx.work["tugger"].values][:4]
    design_hs = float(cx.screening.attrs["design_hs_m"])
    head = governing_heading(cx)
    return [Task("rigging_compare", lambda d: baseline_vs_optimised(cx.resp, cx.work, tugs, d, head), 3.2),
            Task("recommended_operability",
                 lambda d: recommended_operability(cx.work, cx.sea, cx.dg.best, design_hs, d), 0.8)]


# -- tables -----------------------------------------------------------------------------
def window_table(cx: Context, every_heading=False) -> str:
    """The workable Tz window at the design Hs of every option table 1 lists: at every
    heading when that is at most :data:`jls.report.long_tables.MAX_BODY_ROWS` rows or
    ``every_heading`` (the appendix), else at the governing heading only (the body)."""
    dg, work = cx.dg, cx.work
    hs = float(cx.screening.attrs["design_hs_m"])
    heads = [float(h) for h in work["heading"].values]
    n_combos = len(set(dg.table.combos) | {dg.best})
    shown = ""
    if not every_heading and len(heads) * n_combos > MAX_BODY_ROWS:
        heads = [governing_heading(cx)]
        shown = (f" Shown: the governing heading, {heads[0]:g}° (where the baseline rigging "
                 "without tugger has the lowest limiting Hs); every heading is in the appendix.")
    combos = list(dg.table.combos)
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
                         else signed(gain, 2)])
    return table(f"Workable Tz window at the design Hs of {hs:g} m (the screening's): the "
                 "Tz range in which the limiting Hs, capped by the steepness ceiling, reaches it, "
                 f"and the upper end gained over the {dg.baseline} rigging without tugger (the "
                 "study's tables 6.7-6.8). A lower end set by the ceiling is the same for every "
                 "combination." + shown + dg.table.table_caption(),
                 ["rigging / tugger", "from Tz [s]", "to Tz [s]", "gained [s]"], rows)


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
                opt = same_rigging.alias(work, cand)        # the option carrying the name
                axes[2].plot(tz, curve.sel(candidate=opt, tugger=tg, heading=h).values, **style)
        for ax, r in ((axes[0], RELATIVE_SWAY), (axes[1], RELATIVE_YAW)):
            ax.set_ylim(*transfer_range([np.abs(H.sel(candidate=c, tugger=tg, heading=h, response=r).values)
                                         for c in RIG_COLOURS for tg in tuggers]))
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


PASS, FAIL, PARTIAL = "#2e7d32", "#c62828", "#ef6c00"
MIN_DOT = 4.0                 # marker area of a cell of negligible probability [pt²]: still seen
LEG_MARKERS = ["o", "s", "^", "D", "v", "P"]


def recommended_operability(work: xr.Dataset, sea: xr.Dataset, combo, design_hs, out_dir) -> Path:
    """The recommended combination's limiting Hs (per heading) over every leg's
    scatter: one dot per cell of non-zero probability, area proportional to it, marker
    per leg, colour by whether the combination passes the cell (at every heading, at
    none, or at some); the steepness ceiling drawn whole (it leaves the axis at its top)."""
    curve, _ = limit_curves(work)
    tz_c = curve["tz"].values
    passes = flag(on_sea_grid(work["passes"].sel(candidate=combo[0], tugger=combo[1]), sea))
    hp = sea["heading_probability"]
    share = (passes * hp).sum("heading") / hp.sum("heading").where(hp.sum("heading") > 0)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.4)
        ax = fig.subplots()
        hs_live, used = [], set()
        for k, leg in enumerate(sea["leg"].values):
            p = sea["probability"].sel(leg=leg).transpose("hs", "tz").values
            f = share.sel(leg=leg).transpose("hs", "tz").values
            hs, tz = np.meshgrid(sea["hs"].values, sea["tz"].values, indexing="ij")
            live = np.isfinite(p) & (p > 0)
            colour = np.where(f >= 1 - 1e-9, PASS, np.where(f <= 1e-9, FAIL, PARTIAL))[live]
            ax.scatter(tz[live], hs[live], s=MIN_DOT + 600 * p[live], c=list(colour), alpha=0.55, lw=0,
                       marker=LEG_MARKERS[k % len(LEG_MARKERS)])
            ax.scatter([], [], s=20, color="0.5", marker=LEG_MARKERS[k % len(LEG_MARKERS)],
                       label=f"leg {leg} (marker area = probability)")
            hs_live.extend(hs[live].tolist())
            used.update(colour.tolist())
        for colour, what in ((PASS, "cell passes"), (FAIL, "cell fails"), (PARTIAL, "passes at some headings")):
            if colour in used:
                ax.scatter([], [], s=20, color=colour, label=what)
        t_f, ceil = ceiling_curve(work, float(np.nanmin(tz_c)), float(np.nanmax(tz_c)))
        lines = [curve.sel(candidate=combo[0], tugger=combo[1], heading=hd).values
                 for hd in work["heading"].values]
        cl = np.interp(tz_c, t_f, ceil)
        top = max(operability_top([(y, cl) for y in lines]), 1.2 * float(design_hs),
                  1.05 * max(hs_live, default=0.0))
        ax.plot(t_f, ceil, color="0.5", ls="--", lw=1.0, label="steepness ceiling")
        for k, (hd, y) in enumerate(zip(work["heading"].values, lines)):
            ax.plot(tz_c, y, color="k", ls=TUG_STYLES[k % len(TUG_STYLES)], lw=1.3,
                    label=f"limiting Hs, {combo[0]} / {combo[1]}, {hd:g}°")
        ax.axhline(float(design_hs), color="tab:blue", lw=0.8, label=f"design Hs {float(design_hs):g} m")
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
    for i, inside in enumerate(ok):
        if inside and start is None:
            start = i
        if start is not None and (not inside or i == ok.size - 1):
            runs.append((start, i if inside else i - 1))
            start = None
    a, b = max(runs, key=lambda r: tz[r[1]] - tz[r[0]])

    def cross(i, j):                     # zero of y between grid points i (>= 0) and j (< 0)
        if j < 0 or j >= tz.size or not np.isfinite(y[j]):
            return float(tz[i])
        return float(tz[i] + (tz[j] - tz[i]) * y[i] / (y[i] - y[j]))

    return cross(a, a - 1), cross(b, b + 1)


__all__ = ["LEG_MARKERS", "OPTIMISED", "RIG_COLOURS", "baseline_vs_optimised", "figure_plan",
           "recommended_operability", "tz_window", "window_table"]
