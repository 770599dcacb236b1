"""The report's chapter "Voyage plan" (``voyage_plan.nc``, :mod:`jls.stages.voyage_plan`):
the transit as it will be sailed -- the class of every stretch between hold points, the
unrestricted design check per option, the departure rule per option (the exceedance
probability of the sailed voyages beside that of departing at any hour, the departure
share, the waits and the transit), the waiting-time distribution and the risk per option
and month. Page 1's verdict and the master's table are :mod:`jls.report.plan_verdict`'s.

A response level beyond the linear model's range is printed as "beyond the model" in a
grey cell, never as its figure. Every number comes from the dataset.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.report import model_range
from jls.report.basis import BEYOND_MODEL
from jls.report.context import Context, heading
from jls.report.contract import criterion_label, pct
from jls.report.markup import cell, figure, num, t, table
from jls.report.plan_verdict import (
    MONTHS,
    level_cell,
    months_text,
    option_at,
    simulated,
)
from jls.report.style import STYLE, Task, combo_style, legend_columns, new_figure, save


def present(cx: Context) -> bool:
    return cx.plan is not None


# -- figures ----------------------------------------------------------------------------
def figure_plan(cx: Context) -> list[Task]:
    if not simulated(cx.plan):
        return []
    return [Task("plan_waits", lambda d: wait_figure(cx.plan, cx.dg, d), 0.8),
            Task("plan_months", lambda d: month_figure(cx.plan, cx.dg, d), 0.8)]


def wait_figure(p: xr.Dataset, dg, out_dir):
    """Share of the sailed voyages waiting at most x hours in all, per shown option."""
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        x = p["wait_step"].values
        for combo in dg.plot.combos:
            ax.step(x, 100 * option_at(p["plan_wait_cdf"], combo).values, where="post", lw=1.0,
                    **combo_style(dg, combo))
        ax.set_xscale("symlog", linthresh=6.0)
        ax.set_xticks(x, [f"{v:g}" for v in x])
        ax.set_ylim(0, 100)
        ax.set_xlabel("total wait at the hold points [h]")
        ax.set_ylabel("sailed voyages waiting at most [%]")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "plan_waits")


def month_figure(p: xr.Dataset, dg, out_dir):
    """Probability that a sailed voyage exceeds a limit, per departure month and shown
    option."""
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        for combo in dg.plot.combos:
            ax.plot(np.arange(12), option_at(p["plan_exceedance_probability_month"], combo).values,
                    marker="o", ms=3, lw=1.0, **combo_style(dg, combo))
        ax.set_xticks(np.arange(12), MONTHS)
        ax.set_ylim(bottom=0)
        ax.set_ylabel("P(sailed voyage exceeds a limit)")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "plan_months")


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
    p = cx.plan
    if p is None:
        return ""
    out = [heading("voyage_plan", "Voyage plan")]
    out.append(
        "The transit as it will be sailed. Its legs are grouped into stretches by the hold points, where "
        "the voyage can wait or make safe (the first leg's start always is one). At a hold point at hour "
        "t the stretch up to the next hold point is started when every hour of [t, t + min(D + C, H)) has "
        "a forecast utilisation at most α (D the stretch's duration, C its contingency, H the forecast "
        "horizon); else the voyage waits an hour, up to the maximum wait. The utilisation of an hour is "
        "the largest over the criteria of its 3-h MPM over the limit, from the hourly interpolation in Tz "
        "of the route simulation; a sailed voyage exceeds when any hour it actually sails has a "
        "utilisation above 1.")
    out.append(t(f" Here: forecast {p.attrs['forecast']} (the record itself), horizon "
                 f"{num(float(p.attrs['forecast_horizon_h']), 0)} h, maximum wait "
                 f"{num(float(p.attrs['max_wait_h']), 0)} h, departures in {months_text(p)}; "
                 + (f"α from {p.attrs['alpha_source']}." if p.attrs.get("alpha_source") else
                    "α = 1: no alpha table is configured, so the forecast's uncertainty is not allowed for.")) + "\n")
    out.append(_class_table(p))
    out.append(_design(cx))
    if simulated(p):
        out.append(_plan_table(cx))
        if "plan_waits" in cx.figs:
            out.append(figure(cx.figs["plan_waits"], "Waiting-time distribution: the share of the sailed "
                              "voyages whose total wait at the hold points is at most x hours, per option. "
                              + cx.dg.plot.caption()))
        if "plan_months" in cx.figs:
            out.append(figure(cx.figs["plan_months"], "Risk per option and departure month: the probability "
                              "that a voyage sailed by the departure rule exceeds a limit. " + cx.dg.plot.caption()))
    else:
        out.append(t(f"{p.attrs['plan_reason'][:1].upper()}{p.attrs['plan_reason'][1:]}.") + "\n")
    if p.attrs.get("consistency"):
        out.append(t(f"Tables and records: {p.attrs['consistency']}.") + "\n")
    return "\n".join(out)


def _class_table(p: xr.Dataset) -> str:
    rows = []
    for part in str(p.attrs["stretches"]).split("; "):
        legs, _, rest = part.partition(": ")
        cls, _, why = rest.partition(" (")
        rows.append([legs, cell(cls, bold=True), why[:-1] if why.endswith(")") else why])
    cap = ("DNV-ST-N001 class of each stretch between hold points (weather-restricted: T_POP ≤ 72 h and "
           "T_R ≤ 96 h)." + (f" {p.attrs['class_statement'][:1].upper()}{p.attrs['class_statement'][1:]}."
                              if p.attrs.get("class_statement") else ""))
    return table(cap, ["legs", "class", "why"], rows, columns="(auto, auto, 1fr)", align="(left, left, left)")


def _design(cx: Context) -> str:
    p, dg = cx.plan, cx.dg
    rng = model_range.of(cx, p)
    crit = [str(c) for c in p["criterion"].values]
    legs = [str(x) for x in p["leg"].values]
    basis = "; ".join(f"{leg}: {b}" for leg, b in zip(legs, p["leg_design_basis"].values))
    text = t(f"Unrestricted design check: the response in the {num(float(p.attrs['design_return_period_years']), 0)}"
             f"-year design sea states, along the environmental contour of each leg ({p.attrs['design_method']}; "
             f"fitted to {basis}), against the limits. A level beyond the linear model's range is shown as "
             f"'{BEYOND_MODEL}' on grey: a stated or measured linear range passed, a hoist wire slack, or the "
             f"wire's side lead at its limit at the lift beam; the model does not say how far beyond.") + "\n"
    header = ["candidate", "tugger"] + [f"{criterion_label(c)}, {leg}" for c in crit for leg in legs] + ["verdict"]
    rows = []
    for combo in dg.table.combos:
        bold = combo == dg.best
        row = [cell(combo[0], bold=bold), cell(combo[1], bold=bold)]
        for c in crit:
            for leg in legs:
                x = float(option_at(p["design_level"], combo).sel(criterion=c, leg=leg))
                row.append(level_cell(p, c, x, combo, leg, rng))
        row.append(cell("acceptable" if int(option_at(p["design_acceptable"], combo)) else "not acceptable", bold=bold))
        rows.append(row)
    cap = ("Design MPM per criterion and leg, largest along the leg's contour; verdict as an unrestricted "
           "transit. Recommendation in bold." + dg.table.table_caption())
    return text + table(cap, header, rows, size="7.5pt", align="(left, left" + ", right" * (len(header) - 3)
                        + ", left)", label="tab-plan-design")


def _plan_table(cx: Context) -> str:
    p, dg = cx.plan, cx.dg
    header = ["candidate", "tugger", "P(exceed), rule", "P(exceed), any hour", "departure share",
              "not sailed", "wait 50 % [h]", "wait 90 % [h]", "transit 50 % [h]", "transit 90 % [h]"]
    rows = []
    for combo in dg.table.combos:
        bold = combo == dg.best
        w, tr = option_at(p["plan_wait_h"], combo), option_at(p["plan_transit_h"], combo)
        rows.append([cell(combo[0], bold=bold), cell(combo[1], bold=bold),
                     cell(num(float(option_at(p["plan_exceedance_probability"], combo)), 3), bold=bold),
                     num(float(option_at(p["reference_exceedance_probability"], combo)), 3),
                     pct(float(option_at(p["plan_departure_fraction"], combo))),
                     pct(float(option_at(p["plan_not_sailed_fraction"], combo))),
                     num(float(w.sel(quantile=0.5)), 0), num(float(w.sel(quantile=0.9)), 0),
                     num(float(tr.sel(quantile=0.5)), 0), num(float(tr.sel(quantile=0.9)), 0)])
    cap = ("The departure rule per option: the probability that a sailed voyage exceeds a limit, beside that "
           "of the same voyages departing at every hour without the rule; the share of hours allowing "
           "departure from the first hold point; the share of departures not sailed within the maximum wait; "
           "the total wait and the transit time (first hold point to arrival) of the sailed voyages. "
           "Recommendation in bold; the recommendation is ranked by the first column, then the waits."
           + dg.table.table_caption())
    return table(cap, header, rows, size="7.5pt", align="(left, left" + ", right" * 8 + ")", label="tab-plan")


__all__ = ["chapter", "figure_plan", "month_figure", "present", "wait_figure"]
