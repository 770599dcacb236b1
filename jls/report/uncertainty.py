"""Chapter "Uncertainty and sensitivity": workability bands over the plausible plant and
the Hs-in-bin choice, the route workability against the relative-sway limit, and whether
the recommendation holds (:mod:`jls.report.robustness`); with its two figures."""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.assessment.recommendation import tie_key
from jls.names import SWAY_M
from jls.report.context import Context, combo_text, eligible, heading
from jls.report.markup import figure, num, t
from jls.report.robustness import (
    banded,
    has_bands,
    has_sensitivity,
    recommendation_holds,
    sensitivity_switches,
)
from jls.report.style import (
    STYLE,
    Task,
    combination_rows,
    combo_style,
    legend_columns,
    new_figure,
    percent_axis_start,
    save,
)

MAX_LOSERS_NAMED = 4


def _variant_text(coords: dict) -> str:
    return (f"damping × {float(coords['damping_factor']):g}, sway frequency × "
            f"{float(coords['sway_frequency_factor']):g}, Hs at bin {coords['hs_in_bin']}")


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
    dg, work = cx.dg, cx.work
    out = [heading("uncertainty", "Uncertainty and sensitivity")]
    if has_bands(work):
        out.append(
            "The study's section 3.5 identifies the sway damping (0.98 % of critical) "
            "from free decays and places the plausible range at about a factor of two in damping "
            "and ±3 % in the sway frequency. Every candidate is therefore also solved with the "
            "damping at 0.5, 1 and 2 times nominal and the sway frequency at 0.97, 1 and 1.03 "
            "times nominal (the sway mode's modal stiffness scaled, the other modes unchanged), "
            "and each variant is assessed with Hs at the bin centre and at its upper edge. The "
            "band of a combination runs from its lowest to its highest route workability over "
            "these variants and the nominal assessment.\n")
        out.append(figure(cx.figs["workability_bands"],
                          "Route workability per combination: nominal (diamond) and the band over "
                          "the plant variants and Hs choices (bar). Baseline without tugger and "
                          "best combination shaded. " + dg.dots.caption()))
        v = recommendation_holds(work, dg.best, eligible(cx)) if banded(work, dg.best) else None
        if v is None:
            out.append(f"The {t(dg.best[0])} rigging of the recommendation was not varied (a grid "
                       "candidate): its band is not known.\n")
        elif v.holds:
            out.append(f"The recommended {t(combo_text(dg.best))} stays the best feasible "
                       f"combination in every one of the {v.variants} variants: the "
                       "recommendation *holds* across the band.\n")
        else:
            named = "; ".join(f"{_variant_text(c)}: {w}" for c, w in v.losers[:MAX_LOSERS_NAMED])
            more = f" and {len(v.losers) - MAX_LOSERS_NAMED} more" if len(v.losers) > MAX_LOSERS_NAMED else ""
            out.append(f"#warning[The recommendation *does not hold* across the band: in "
                       f"{len(v.losers)} of {v.variants} variants another feasible combination "
                       f"has a higher route workability than {t(combo_text(dg.best))} "
                       f"({t(named)}{t(more)}).]\n")
    else:
        out.append("The workability dataset carries no uncertainty bands.\n")
    if has_sensitivity(work):
        lim = dg.limits.get(SWAY_M)
        out.append("The clearance budget behind the relative-sway limit is itself an estimate. "
                   "Because the model is linear, every cell is re-judged for trial limits from "
                   f"{num(float(work['trial_limit'].min()), 1)} to {num(float(work['trial_limit'].max()), 1)} m "
                   "without solving the plant again (other criteria unchanged).\n")
        out.append(figure(cx.figs["criterion_sensitivity"],
                          "Route workability against the relative-sway limit" +
                          (f"; dotted: the configured {lim:g} m. " if lim is not None else ". ") +
                          dg.plot.caption()))
        runs = sensitivity_switches(work, eligible(cx),
                                    lambda ct: tie_key(ct, dg.baseline, {g: cx.c_tugger(g) for g in dg.tuggers},
                                                       dg.margins))
        if len(runs) == 1:
            out.append(f"The best feasible combination is {t(combo_text(runs[0][1]))} at every "
                       "trial limit.\n")
        else:
            parts = [f"from {num(a, 2)} m: {combo_text(ct)}" for a, ct in runs]
            out.append("The best feasible combination changes with the limit: " + t("; ".join(parts)) + ".\n")
    return "\n".join(out)


# -- figures ----------------------------------------------------------------------------
def figure_plan(cx: Context) -> list[Task]:
    """The chapter's figures: the bands and the criterion sensitivity, each when
    workability.nc has them."""
    tasks = []
    if has_bands(cx.work):
        tasks.append(Task("workability_bands", lambda d: workability_bands(cx.work, cx.dg, d), 1.0))
    if has_sensitivity(cx.work):
        tasks.append(Task("criterion_sensitivity",
                          lambda d: criterion_sensitivity(cx.work, cx.dg, d), 1.0))
    return tasks


def workability_bands(work: xr.Dataset, dg, out_dir):
    """Route workability of each combination (diamond, nominal) with its band over the
    plant variants and Hs choices (bar from lowest to highest)."""
    combos = dg.dots.combos
    start = percent_axis_start(work, combos)
    lo = np.array([100 * float(work["workability_route_min"].sel(candidate=c, tugger=t)) for c, t in combos])
    if np.isfinite(lo).any():                 # NaN: a grid candidate that was not varied
        start = float(min(start, 5.0 * np.floor(np.nanmin(lo) / 5.0)))
    with matplotlib.rc_context(STYLE):
        fig = new_figure(1.2 + 0.22 * len(combos))
        ax = fig.subplots()
        y = np.arange(len(combos))[::-1]
        hi = [100 * float(work["workability_route_max"].sel(candidate=c, tugger=t)) for c, t in combos]
        nom = [100 * float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
        ax.hlines(y, lo, hi, color="tab:blue", lw=3.0, alpha=0.45, label="band (variants and nominal)")
        ax.plot(nom, y, ls="", marker="D", color="black", ms=4.5, label="nominal")
        combination_rows(ax, combos, dg, start, "route workability")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "workability_bands")


def criterion_sensitivity(work: xr.Dataset, dg, out_dir):
    """Route workability against the relative-sway limit, one line per combination the
    figure selection shows; the configured limit dotted."""
    s = work["workability_route_sensitivity"]
    x = s["trial_limit"].values
    with matplotlib.rc_context(STYLE):
        fig = new_figure(3.0)
        ax = fig.subplots()
        for ct in dg.plot.combos:
            ax.plot(x, 100 * s.sel(candidate=ct[0], tugger=ct[1]).values, marker=".", ms=3,
                    **combo_style(dg, ct))
        if SWAY_M in dg.limits:
            ax.axvline(dg.limits[SWAY_M], color="0.4", ls=":", lw=1.0, label="configured limit")
        ax.set_xlabel("relative-sway limit on the 3-hour MPM [m]")
        ax.set_ylabel("route workability [%]")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "criterion_sensitivity")


__all__ = ["chapter", "criterion_sensitivity", "figure_plan", "workability_bands"]
