"""Figures of the wire-load, weather-window and uncertainty chapters."""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.report.figures import STYLE, _figure, _ncol, _save, combination_rows, combo_style, percent_axis_start

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


def workability_bands(work: xr.Dataset, dg, out_dir):
    """Route workability of each combination (diamond, nominal) with its band over the
    plant variants and Hs choices (bar from lowest to highest)."""
    combos = dg.dots.combos
    start = percent_axis_start(work, combos)
    lo = np.array([100 * float(work["workability_route_min"].sel(candidate=c, tugger=t)) for c, t in combos])
    if np.isfinite(lo).any():                 # NaN: a grid candidate that was not varied
        start = float(min(start, 5.0 * np.floor(np.nanmin(lo) / 5.0)))
    with matplotlib.rc_context(STYLE):
        fig = _figure(1.2 + 0.22 * len(combos))
        ax = fig.subplots()
        y = np.arange(len(combos))[::-1]
        hi = [100 * float(work["workability_route_max"].sel(candidate=c, tugger=t)) for c, t in combos]
        nom = [100 * float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
        ax.hlines(y, lo, hi, color="tab:blue", lw=3.0, alpha=0.45, label="band (variants and nominal)")
        ax.plot(nom, y, ls="", marker="D", color="black", ms=4.5, label="nominal")
        combination_rows(ax, combos, dg, start, "route workability")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "workability_bands")


def criterion_sensitivity(work: xr.Dataset, dg, out_dir):
    """Route workability against the relative-sway limit, one line per combination the
    figure selection shows; the configured limit dotted."""
    s = work["workability_route_sensitivity"]
    x = s["trial_limit"].values
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.0)
        ax = fig.subplots()
        for ct in dg.plot.combos:
            ax.plot(x, 100 * s.sel(candidate=ct[0], tugger=ct[1]).values, marker=".", ms=3,
                    **combo_style(dg, ct))
        if "relative_sway_m" in dg.limits:
            ax.axvline(dg.limits["relative_sway_m"], color="0.4", ls=":", lw=1.0, label="configured limit")
        ax.set_xlabel("relative-sway limit on the 3-hour MPM [m]")
        ax.set_ylabel("route workability [%]")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "criterion_sensitivity")


def window_months(win: xr.Dataset, combo, out_dir):
    """Probability of a workable window of each hindcast leg's duration per calendar month
    of the start, for one combination."""
    p = win["window_probability_options"].sel(candidate=combo[0], tugger=combo[1])
    legs = [str(v) for v in p["leg"].values]
    width = 0.8 / max(len(legs), 1)
    with matplotlib.rc_context(STYLE):
        fig = _figure(2.6)
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
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "window_months")


__all__ = ["workability_bands", "criterion_sensitivity", "window_months"]
