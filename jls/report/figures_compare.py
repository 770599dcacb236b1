"""Figures comparing the baseline and the optimised rigging (chapter 5 beside chapter 6),
and the recommended option against the route's sea states.

* :func:`baseline_vs_optimised` - relative sway and yaw transfer functions and the
  operability curves of the two riggings, per tugger setting shown;
* :func:`recommended_operability` - the limiting Hs of the recommended combination with
  every leg's scatter behind it (cells as dots sized by probability), the steepness
  ceiling and the design Hs.

Each returns the saved SVG path (the style of :mod:`jls.report.figures`).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.report.contract import complex_var
from jls.report.figures import (
    STYLE,
    TUG_STYLES,
    _ceiling_curve,
    _figure,
    _limit_curves,
    _ncol,
    _save,
    log_ticks,
)

RIG_COLOURS = {"baseline": "black", "optimised": "tab:red"}
LEG_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown", "tab:pink"]


def baseline_vs_optimised(resp: xr.Dataset, work: xr.Dataset, tuggers, out_dir,
                          heading=None) -> Path:
    """Three panels at one heading: |relative sway| and |relative yaw| per unit wave
    amplitude against wave period, and the limiting Hs against Tz, baseline (black)
    and optimised (red), one line style per tugger setting."""
    H = complex_var(resp, "transfer").rename(shown_candidate="candidate")
    h = float(resp["heading"].values[0] if heading is None else heading)
    period = 2 * np.pi / resp["omega"].values
    curve, _ = _limit_curves(work)
    tz = curve["tz"].values
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.0)
        axes = fig.subplots(1, 3)
        for cand, colour in RIG_COLOURS.items():
            for k, tg in enumerate(tuggers):
                style = {"color": colour, "ls": TUG_STYLES[k % len(TUG_STYLES)], "lw": 0.9,
                         "label": f"{cand} / {tg}"}
                for ax, r in ((axes[0], "relative_sway"), (axes[1], "relative_yaw")):
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
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "rigging_compare")


def recommended_operability(work: xr.Dataset, sea: xr.Dataset, combo, design_hs, out_dir) -> Path:
    """The recommended combination's limiting Hs (per heading) over every leg's
    scatter: one dot per cell of non-zero probability, area proportional to it."""
    curve, _ = _limit_curves(work)
    tz_c = curve["tz"].values
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.4)
        ax = fig.subplots()
        for k, leg in enumerate(sea["leg"].values):
            p = sea["probability"].sel(leg=leg)
            p = p.transpose("hs", "tz").values
            hs, tz = np.meshgrid(sea["hs"].values, sea["tz"].values, indexing="ij")
            live = np.isfinite(p) & (p > 0)
            ax.scatter(tz[live], hs[live], s=600 * p[live], color=LEG_COLOURS[k % len(LEG_COLOURS)],
                       alpha=0.45, lw=0, label=f"leg {leg} (dot area = probability)")
        t_f, ceil = _ceiling_curve(work, float(np.nanmin(tz_c)), float(np.nanmax(tz_c)))
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
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "recommended_operability")


def tz_window(work: xr.Dataset, combo, heading, design_hs) -> tuple[float, float]:
    """(from, to) Tz [s] of the contiguous window in which the combination's limiting Hs
    (steepness-capped) reaches ``design_hs``, the ends interpolated linearly on the
    operability grid; (nan, nan) when it never does. The widest such window is returned."""
    curve, _ = _limit_curves(work)
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
