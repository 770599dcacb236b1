"""The report's chapter "Workability": per leg and for the route, the workable and
non-workable probability split by what makes a cell fail (the governing criterion, a
saturating winch, a time-domain verdict), the steep cells kept, and the cross-check
against the pass flags; with the dot plot of every combination."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.names import SATURATED_FAIL, TIME_DOMAIN
from jls.report.context import Context, heading
from jls.report.contract import criterion_label, flag, on_sea_grid, pct
from jls.report.markup import cell, figure, t, table
from jls.report.style import (
    STYLE,
    Task,
    combination_rows,
    legend_columns,
    new_figure,
    percent_axis_start,
    save,
)


def figure_plan(cx: Context) -> list[Task]:
    return [Task("workability", lambda d: workability_bars(cx.work, cx.dg, d), 1.0)]


def chapter(cx: Context) -> str:
    dg, work, sea = cx.dg, cx.work, cx.sea
    out = [heading("workability", "Workability")]
    out.append("A leg's workability is the sum of the probabilities of its workable cells over "
               "Hs, Tz and heading; the route's weights the legs by duration. A failing cell is "
               "governed by the criterion with the highest utilisation (MPM over limit); the "
               "shares below split each leg's non-workable probability by that criterion.\n")
    out.append(figure(cx.figs["workability"], "Workability per leg and for the route, one row "
                      "per combination (route: filled diamond). The axis starts at "
                      f"{percent_axis_start(cx.work, dg.dots.combos):g} % to show the differences; "
                      "the values are in the table below. " + dg.dots.caption()))
    crit = dg.criteria
    causes = failure_causes(work)
    header = ["candidate", "tugger", "leg", "workable", "fails", *[f"{criterion_label(c)}" for c in crit],
              *[CAUSE_LABELS[k] for k in causes], "in steep cells"]
    rows = []
    failing = failing_cells(cx)
    for combo in dg.table.combos:
        split = failure_split(cx, combo, failing)
        for k, leg in enumerate(cx.legs + ["route"]):
            if leg == "route":
                w = cx.w_route(combo)
                sh = {c: float((split[c] * sea["leg_weight"]).sum()) for c in split}
                steep = float((sea["steep_probability"] * sea["leg_weight"]).sum())
            else:
                w = cx.w_leg(combo, leg)
                sh = {c: float(split[c].sel(leg=leg)) for c in split}
                steep = float(sea["steep_probability"].sel(leg=leg))
            bold = leg == "route"
            rows.append([cell(combo[0] if k == 0 else ""), cell(combo[1] if k == 0 else ""),
                         cell(leg, bold=bold), cell(pct(w), bold=bold), pct(1 - w),
                         *[pct(sh[c]) for c in crit], *[pct(sh[c]) for c in causes], pct(steep)])
    explain = "".join(f"; {CAUSE_LABELS[k]}: {CAUSE_TEXT[k]}" for k in causes)
    out.append(table("Workable and non-workable probability per leg and for the route, the "
                     "non-workable part split by what fails the cell (a criterion: the one with the "
                     f"highest utilisation{explain}; the parts add up to the non-workable "
                     "probability), and the probability in cells above the steepness ceiling."
                     + dg.table.table_caption(), header, rows,
                     size="8pt" if len(header) <= 9 else "7pt",
                     align="(left, left, left" + ", right" * (len(header) - 3) + ")",
                     label="tab-workability"))
    weight = sea["cell_probability"]
    base = (dg.baseline, dg.no_tugger)
    steep_pass = weight * flag(sea["steep"]) * flag(
        on_sea_grid(work["passes"].sel(candidate=base[0], tugger=base[1]), sea))
    sp = float((steep_pass.sum(("heading", "hs", "tz")) * sea["leg_weight"]).sum())
    out.append(f"Steep cells are kept: {t(pct(sp))} of the route's probability lies in steep cells "
               f"that the {t(dg.baseline)} rigging without tugger passes; excluding them would lower "
               f"its route workability by that much. Cross-check: the route workability recomputed "
               f"from the pass flags and the cell and heading probabilities agrees with "
               f"the workability dataset's to {dg.recheck:.1e}.\n")
    if dg.recheck > 1e-6:
        out.append("#warning[The workability in the workability dataset does not follow from its own pass "
                   "flags and the sea-state probabilities; the datasets are inconsistent.]\n")
    return "\n".join(out)


CAUSE_LABELS = {"winch": "winch saturates", "timedomain": "time domain"}
CAUSE_TEXT = {"winch": "cells every criterion passes in the frequency domain but failed because "
                       "the tugger winch saturates there",
              "timedomain": "cells every criterion passes in the frequency domain but the "
                            "time-domain run fails"}


def failure_causes(work: xr.Dataset) -> list[str]:
    """The causes besides the criteria that can fail a cell in ``work``: a saturating
    winch under the 'fail' policy, a time-domain verdict."""
    if "verdict_source" not in work:
        return []
    src = work["verdict_source"]
    return [k for k, code in (("winch", SATURATED_FAIL), ("timedomain", TIME_DOMAIN))
            if bool((src == code).any())]


def failing_cells(cx: Context) -> dict:
    """Every combination's failing cells on the sea grid, by cause (the keys of
    :func:`failure_split`), as flags over candidate, tugger, leg, heading, Hs and Tz; worked
    out once for the whole table rather than once a combination."""
    work, sea = cx.work, cx.sea
    fails = ~flag(on_sea_grid(work["passes"], sea)) & (sea["cell_probability"] > 0)
    util = on_sea_grid(work["utilisation"], sea)
    crit_fails = (util > 1.0).any("criterion")
    top = util.fillna(-np.inf).argmax("criterion")
    order = list(util["criterion"].values)
    out = {c: fails & crit_fails & (top == order.index(c)) for c in cx.dg.criteria}
    if "verdict_source" in work:
        src = on_sea_grid(work["verdict_source"], sea)
        for key, code in (("winch", SATURATED_FAIL), ("timedomain", TIME_DOMAIN)):
            out[key] = fails & ~crit_fails & (src == code)
    return out


def failure_split(cx: Context, combo, failing: dict | None = None) -> dict:
    """Per leg, the probability of the combination's failing cells by cause: each criterion
    (cells a criterion fails in the frequency domain, by the criterion of highest
    utilisation), then ``winch`` and ``timedomain`` (:func:`failure_causes`) for failing
    cells no criterion fails; a leg judged hour by hour, by its hours. The parts add up to
    1 - workability_leg. ``failing``: :func:`failing_cells` of ``cx`` when already known."""
    work, sea = cx.work, cx.sea
    sel = dict(candidate=combo[0], tugger=combo[1])
    weight = sea["cell_probability"]
    failing = failing_cells(cx) if failing is None else failing
    cells = ("heading", "hs", "tz")
    out = {key: (weight * mine.sel(sel)).sum(cells) for key, mine in failing.items()}
    if "leg_hourly" in work and bool(work["leg_hourly"].any()):
        out = _hourly_split(work, sel, out)
    return out


def _hourly_split(work: xr.Dataset, sel: dict, out: dict) -> dict:
    """The split of the legs judged hour by hour (:mod:`jls.assessment.measured_legs`):
    the criteria's shares of their failing hours (``governing_share``), a saturating winch
    the rest; no time-domain verdict is carried to their hours."""
    hourly = work["leg_hourly"].astype(bool)
    share = work["governing_share"].sel(sel)
    for c in share["criterion"].values:
        out[str(c)] = xr.where(hourly, share.sel(criterion=c, drop=True), out[str(c)])
    rest = (1.0 - work["workability_leg"].sel(sel) - share.sum("criterion")).clip(0.0, 1.0)
    if "winch" in out:
        out["winch"] = xr.where(hourly, rest, out["winch"])
    if "timedomain" in out:
        out["timedomain"] = xr.where(hourly, 0.0, out["timedomain"])
    return out


# -- figure ---------------------------------------------------------------------------
def workability_bars(work: xr.Dataset, dg, out_dir) -> Path:
    """Workability per leg and for the route as a dot plot: one row per combination, a
    marker per leg and a filled diamond for the route, on an axis that starts where the
    values do (the start is stated in the caption; a dot plot does not imply a zero)."""
    legs = [str(v) for v in work["leg"].values]
    combos = dg.dots.combos
    start = percent_axis_start(work, combos)
    markers = ["o", "s", "^", "v", "<", ">", "p", "h"]
    with matplotlib.rc_context(STYLE):
        fig = new_figure(1.2 + 0.22 * len(combos))
        ax = fig.subplots()
        y = np.arange(len(combos))[::-1]
        for k, leg in enumerate(legs):
            vals = [100 * float(work["workability_leg"].sel(candidate=c, tugger=t, leg=leg)) for c, t in combos]
            ax.plot(vals, y, ls="", marker=markers[k % len(markers)], mfc="white", mec=f"C{k}",
                    ms=4.5, mew=1.0, label=f"leg {leg}")
        route = [100 * float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
        ax.plot(route, y, ls="", marker="D", color="black", ms=4.5, label="route")
        combination_rows(ax, combos, dg, start, "workable fraction")
        ax.grid(True, axis="x")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "workability")


__all__ = ["chapter", "figure_plan", "workability_bars"]
