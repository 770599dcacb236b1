"""The voyage as it will be sailed (``voyage_plan.nc``, :mod:`jls.stages.voyage_plan`):
page 1's verdict and the master's table, and the chapter "Voyage plan".

* :func:`verdict` -- page 1's first paragraph, beginning "Acceptable" or "Not
  acceptable": the unrestricted design check of the recommendation (its governing
  criterion and leg, by how much), then the weather-restricted verdict (every stretch
  between hold points at most 72 h and T_R at most 96 h, and voyages sail within the
  maximum wait) with the departure rule's figures, or why the route cannot be sailed
  weather-restricted, or why no departure simulation was possible;
* :func:`master_table` -- the forecast limit OP_WF per leg in Hs per peak period (the
  worst of the leg's headings, alpha applied with its source);
* the chapter: the class of every stretch, the design check per option, the plan per
  option (the exceedance probability of the sailed voyages beside that of departing at
  any hour, the departure share, the waits and the transit), the waiting-time
  distribution and the risk per option and month.

A response level beyond the linear model's range is printed as "beyond the model" in a
grey cell, never as its figure. Every number comes from the dataset.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.report.basis import BEYOND_MODEL, model_threshold
from jls.report.context import Context, combo_text, heading
from jls.report.contract import criterion_label, pct
from jls.report.markup import cell, figure, num, plural, t, table
from jls.report.style import STYLE, Task, combo_style, legend_columns, new_figure, save

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")
GREY = "luma(225)"


def present(cx: Context) -> bool:
    return cx.plan is not None


def simulated(p: xr.Dataset | None) -> bool:
    return p is not None and "plan_exceedance_probability" in p


def _sel(da: xr.DataArray, combo) -> xr.DataArray:
    return da.sel(candidate=combo[0], tugger=combo[1])


def _units(p: xr.Dataset, c: str) -> str:
    return str(p["level_units"].sel(criterion=c).values) if "level_units" in p.coords else ""


def level_text(p: xr.Dataset, c: str, x: float) -> str:
    """A design level with its unit, or :data:`BEYOND_MODEL` (with the threshold) when it
    lies beyond the linear model's range."""
    u = _units(p, c)
    lim = float(p["limit"].sel(criterion=c))
    thr = model_threshold(u, lim)
    unit = {"degree": "°", "1": ""}.get(u, f" {u}")
    if thr is not None and x > thr:
        return f"{BEYOND_MODEL} (above {num(thr, 1)}{unit})"
    return f"{num(x, 2)}{unit}"


def _level_cell(p, c, x):
    text = level_text(p, c, x)
    return cell(text, fill=GREY) if text.startswith(BEYOND_MODEL) else text


def _governing(p: xr.Dataset, combo):
    """(criterion, leg) of the largest design utilisation of the option."""
    u = _sel(p["design_utilisation"], combo).transpose("criterion", "leg")
    i, j = np.unravel_index(int(np.nanargmax(np.nan_to_num(u.values, nan=-np.inf))), u.shape)
    return str(u["criterion"].values[i]), str(u["leg"].values[j])


def _months_text(p: xr.Dataset) -> str:
    m = [int(x) for x in str(p.attrs.get("months", "")).split()]
    if m == list(range(1, 13)):
        return "January-December"
    return ", ".join(MONTHS[k - 1] for k in m)


def _holds(p: xr.Dataset) -> list[str]:
    return [str(leg) for leg, h in zip(p["leg"].values, p["leg_hold_point"].values) if int(h)][1:]


def _unrestricted(cx: Context, combo) -> tuple[bool, str]:
    p = cx.plan
    ok = bool(int(_sel(p["design_acceptable"], combo)))
    c, leg = _governing(p, combo)
    years = num(float(p.attrs.get("design_return_period_years", 10)), 0)
    lvl = float(_sel(p["design_level"], combo).sel(criterion=c, leg=leg))
    lim = float(p["limit"].sel(criterion=c))
    u = float(_sel(p["design_utilisation"], combo).sel(criterion=c, leg=leg))
    hs = float(_sel(p["design_hs"], combo).sel(criterion=c, leg=leg))
    tz = float(_sel(p["design_tz"], combo).sel(criterion=c, leg=leg))
    where = f"the {years}-year design sea state of leg {leg} (Hs {num(hs, 1)} m, Tz {num(tz, 1)} s)"
    if ok:
        return True, (f"Acceptable as an unrestricted transit with the {combo_text(combo)}: in the "
                      f"{years}-year design sea states of every leg each criterion stays inside its limit; "
                      f"the largest, the {criterion_label(c)} MPM in {where}, is {level_text(p, c, lvl)} "
                      f"against {level_text(p, c, lim)} ({pct(u)} of it).")
    n_ok = int(p["design_acceptable"].sum())
    others = (f"; {n_ok} other option{'s' if n_ok > 1 else ''} pass{'' if n_ok > 1 else 'es'} it"
              if n_ok else "; no assessed option passes it")
    return False, (f"Not acceptable as an unrestricted transit: with the {combo_text(combo)}, in {where} "
                   f"the {criterion_label(c)} MPM is {level_text(p, c, lvl)} against "
                   f"{level_text(p, c, lim)}{others}.")


def _plan_figures(cx: Context, combo) -> str:
    p = cx.plan
    frac = float(_sel(p["plan_departure_fraction"], combo))
    w50, w90 = (float(_sel(p["plan_wait_h"], combo).sel(quantile=q)) for q in (0.5, 0.9))
    exc = float(_sel(p["plan_exceedance_probability"], combo))
    ref = float(_sel(p["reference_exceedance_probability"], combo))
    ns = float(_sel(p["plan_not_sailed_fraction"], combo))
    span = str(p.attrs.get("record_span", ""))
    text = (f"departing in {_months_text(p)} (records {span}), {pct(frac)} of hours allow departure from the first hold "
            f"point, median wait {num(w50, 0)} h (90 %: {num(w90, 0)} h), probability that a sailed voyage "
            f"exceeds a limit {num(exc, 2)} (departing at any hour without the rule: {num(ref, 2)})")
    if ns > 0:
        text += (f"; {pct(ns)} of departures would wait longer than {num(float(p.attrs['max_wait_h']), 0)} h "
                 "at a hold point and are not sailed")
    judged, total = int(_sel(p["plan_judged"], combo)), int(p["departures_month"].sum())
    if judged < total:
        text += (f"; {num(judged, 0)} of the {num(total, 0)} departure hours judged (the others wait "
                 "through, or sail into, a gap in the records, or run past their end)")
    return text


def verdict(cx: Context) -> str:
    """Page 1's first paragraph (module docstring); empty without ``voyage_plan.nc``."""
    p, dg = cx.plan, cx.dg
    if p is None:
        return ""
    combo = dg.best
    ok_u, first = _unrestricted(cx, combo)
    parts = [first]
    holds = _holds(p)
    n_st = len(set(int(x) for x in p["leg_stretch"].values))
    rule = (f"departures on a forecast inside the limits below (OP_WF; forecast {p.attrs['forecast']}, "
            f"horizon {num(float(p.attrs['forecast_horizon_h']), 0)} h)")
    if str(p.attrs["route_class"]) == "weather-restricted":
        hold_text = f"hold point{'s' if len(holds) > 1 else ''}: {', '.join(holds)}" if holds else "no hold point on the way"
        if simulated(p) and float(_sel(p["plan_not_sailed_fraction"], combo)) < 1.0:
            word = "Also acceptable" if ok_u else "Acceptable"
            parts.append(f"{word} as a weather-restricted transit in {plural(n_st, 'stretch', 'stretches')} "
                         f"({hold_text}) with the {combo_text(combo)}: {rule}; {_plan_figures(cx, combo)}.")
        elif simulated(p):
            parts.append(f"Not acceptable as a weather-restricted transit either: no departure of the season "
                         f"sails within the maximum wait of {num(float(p.attrs['max_wait_h']), 0)} h.")
        else:
            parts.append(f"Weather-restricted in {plural(n_st, 'stretch', 'stretches')} ({hold_text}); "
                         f"{p.attrs['plan_reason']}.")
    else:
        parts.append(f"Not acceptable as a weather-restricted transit either: {p.attrs['class_statement']}."
                     if not ok_u else f"As a weather-restricted transit it would not qualify: "
                     f"{p.attrs['class_statement']}.")
        if simulated(p):
            parts.append(f"Sailed through the records with the departure rule ({rule}), {_plan_figures(cx, combo)}.")
        else:
            parts.append(f"{p.attrs['plan_reason'][:1].upper()}{p.attrs['plan_reason'][1:]}.")
    text = t(" ".join(parts)) + f" ({cx.sec('voyage_plan')}.)\n"
    differ = [c for c in str(p.attrs.get("consistency", "")).split("; ") if "differ" in c]
    if differ:
        text += (f"#warning[The legs' tables and their hourly records disagree: {t('; '.join(differ))}. The "
                 "assessment reads the tables, the voyage plan the records.]\n")
    return text


def master_table(cx: Context) -> str:
    """The master's table: OP_WF per leg in Hs per peak period for the recommendation."""
    p, dg = cx.plan, cx.dg
    if p is None or "master_hs_opwf" not in p:
        return ""
    combo = dg.best
    legs = [str(x) for x in p["leg"].values]
    wf = _sel(p["master_hs_opwf"], combo)
    a = _sel(p["master_alpha"], combo)
    has_alpha = bool(str(p.attrs.get("alpha_source", "")))
    header = ["Tp [s]"] + [f"{leg}: OP_WF [m]" for leg in legs] + ([f"{leg}: α" for leg in legs] if has_alpha else [])
    rows = []
    for tp in p["tp"].values:
        row = [num(float(tp), 0)]
        for leg in legs:
            x = float(wf.sel(leg=leg, tp=tp))
            row.append("no limit" if not np.isfinite(x) else num(x, 2))
        if has_alpha:
            row += [num(float(a.sel(leg=leg, tp=tp)), 2) for leg in legs]
        rows.append(row)
    heads = {str(leg): ", ".join(f"{float(h):g}°" for h, pr in zip(cx.sea["heading"].values,
                                                                  cx.sea["heading_probability"].sel(leg=leg).values)
                                 if pr > 0) for leg in legs}
    alpha = (f"α from {p.attrs['alpha_source']}" + (f" ({p.attrs['alpha_note']})" if p.attrs.get("alpha_note") else "")
             if has_alpha else "α = 1: no table of forecast-uncertainty factors is configured, so OP_WF = OP_LIM "
             "and the forecast's own uncertainty is not allowed for")
    cap = (f"Forecast limits for the master, {combo_text(combo)}: the largest forecast significant wave "
           f"height at each peak period (JONSWAP of the assessment) at which the departure rule starts a "
           f"stretch, OP_WF = α OP_LIM, per leg at the worst of its relative headings "
           f"({'; '.join(f'{k}: {v}' for k, v in heads.items())}); {alpha}.")
    return table(cap, header, rows, size="7.5pt", label="tab-master-forecast",
                 align="(" + ", ".join(["right"] * len(header)) + ")")


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
            ax.step(x, 100 * _sel(p["plan_wait_cdf"], combo).values, where="post", lw=1.0,
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
            ax.plot(np.arange(12), _sel(p["plan_exceedance_probability_month"], combo).values,
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
                 f"{num(float(p.attrs['max_wait_h']), 0)} h, departures in {_months_text(p)}; "
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
    crit = [str(c) for c in p["criterion"].values]
    legs = [str(x) for x in p["leg"].values]
    basis = "; ".join(f"{leg}: {b}" for leg, b in zip(legs, p["leg_design_basis"].values))
    text = t(f"Unrestricted design check: the response in the {num(float(p.attrs['design_return_period_years']), 0)}"
             f"-year design sea states, along the environmental contour of each leg ({p.attrs['design_method']}; "
             f"fitted to {basis}), against the limits. A level beyond the linear model's range is shown as "
             f"'{BEYOND_MODEL}' on grey: the model does not say how far beyond.") + "\n"
    header = ["candidate", "tugger"] + [f"{criterion_label(c)}, {leg}" for c in crit for leg in legs] + ["verdict"]
    rows = []
    for combo in dg.table.combos:
        bold = combo == dg.best
        row = [cell(combo[0], bold=bold), cell(combo[1], bold=bold)]
        for c in crit:
            for leg in legs:
                x = float(_sel(p["design_level"], combo).sel(criterion=c, leg=leg))
                row.append(_level_cell(p, c, x))
        row.append(cell("acceptable" if int(_sel(p["design_acceptable"], combo)) else "not acceptable", bold=bold))
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
        w, tr = _sel(p["plan_wait_h"], combo), _sel(p["plan_transit_h"], combo)
        rows.append([cell(combo[0], bold=bold), cell(combo[1], bold=bold),
                     cell(num(float(_sel(p["plan_exceedance_probability"], combo)), 3), bold=bold),
                     num(float(_sel(p["reference_exceedance_probability"], combo)), 3),
                     pct(float(_sel(p["plan_departure_fraction"], combo))),
                     pct(float(_sel(p["plan_not_sailed_fraction"], combo))),
                     num(float(w.sel(quantile=0.5)), 0), num(float(w.sel(quantile=0.9)), 0),
                     num(float(tr.sel(quantile=0.5)), 0), num(float(tr.sel(quantile=0.9)), 0)])
    cap = ("The departure rule per option: the probability that a sailed voyage exceeds a limit, beside that "
           "of the same voyages departing at every hour without the rule; the share of hours allowing "
           "departure from the first hold point; the share of departures not sailed within the maximum wait; "
           "the total wait and the transit time (first hold point to arrival) of the sailed voyages. "
           "Recommendation in bold; the recommendation is ranked by the first column, then the waits."
           + dg.table.table_caption())
    return table(cap, header, rows, size="7.5pt", align="(left, left" + ", right" * 8 + ")", label="tab-plan")


__all__ = ["BEYOND_MODEL", "chapter", "figure_plan", "level_text", "master_table", "month_figure",
           "present", "simulated", "verdict", "wait_figure"]
