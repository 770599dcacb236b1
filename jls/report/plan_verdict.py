"""What page 1 and the chapter "Voyage plan" share (``voyage_plan.nc``): page 1's verdict
and the master's forecast table, and the helpers both read the dataset with.

* :func:`verdict` -- page 1's first paragraph, beginning "Acceptable" or "Not
  acceptable": the unrestricted design check of the recommendation (its governing
  criterion and leg, by how much), then the weather-restricted verdict (every stretch
  between hold points at most 72 h and T_R at most 96 h, and voyages sail within the
  maximum wait) with the departure rule's figures, or why the route cannot be sailed
  weather-restricted, or why no departure simulation was possible;
* :func:`master_table` -- the forecast limit OP_WF per leg in Hs per peak period (the
  worst of the leg's headings, alpha applied with its source).

A response level beyond the linear model's range is printed as "beyond the model", never
as its figure. Every number comes from the dataset.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.report import model_range
from jls.report.basis import BEYOND_MODEL
from jls.report.context import Context, combo_text
from jls.report.contract import criterion_label, pct
from jls.report.markup import cell, num, plural, t, table
from jls.report.model_range import ModelRange
from jls.report.weather_windows import window_alpha_text

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")
GREY = "luma(225)"


def simulated(p: xr.Dataset | None) -> bool:
    return p is not None and "plan_exceedance_probability" in p


def option_at(da: xr.DataArray, combo) -> xr.DataArray:
    return da.sel(candidate=combo[0], tugger=combo[1])


def _units(p: xr.Dataset, c: str) -> str:
    return str(p["level_units"].sel(criterion=c).values) if "level_units" in p.coords else ""


def level_text(p: xr.Dataset, c: str, x: float, combo=None, leg=None, rng: ModelRange | None = None) -> str:
    """A design level with its unit, or :data:`BEYOND_MODEL` (with the threshold and why)
    when it lies beyond the linear model's range (:mod:`jls.report.model_range`; for the
    option ``combo`` on ``leg``, whose other design levels there tell a slack wire; without
    ``combo`` only the stated thresholds, as for a limit)."""
    u = _units(p, c)
    unit = {"degree": "°", "1": ""}.get(u, f" {u}")
    rng = rng or model_range.model_range(p)
    levels = None
    if combo is not None and leg is not None:
        levels = {str(k): float(option_at(p["design_level"], combo).sel(criterion=k, leg=leg))
                  for k in p["criterion"].values}
    b = rng.beyond(c, combo if combo is not None else ("", ""), x, levels)
    if b is not None:
        if b.reason == model_range.SLACK:
            return f"{BEYOND_MODEL} ({b.reason})"
        return f"{BEYOND_MODEL} (above {num(b.threshold, 1)}{unit}: {b.reason})"
    return f"{num(x, 2)}{unit}"


def level_cell(p, c, x, combo=None, leg=None, rng: ModelRange | None = None):
    text = level_text(p, c, x, combo, leg, rng)
    return cell(BEYOND_MODEL, fill=GREY) if text.startswith(BEYOND_MODEL) else text


def governing(p: xr.Dataset, combo):
    """(criterion, leg) of the largest design utilisation of the option."""
    u = option_at(p["design_utilisation"], combo).transpose("criterion", "leg")
    i, j = np.unravel_index(int(np.nanargmax(np.nan_to_num(u.values, nan=-np.inf))), u.shape)
    return str(u["criterion"].values[i]), str(u["leg"].values[j])


def months_text(p: xr.Dataset) -> str:
    m = [int(x) for x in str(p.attrs.get("months", "")).split()]
    if m == list(range(1, 13)):
        return "January-December"
    return ", ".join(MONTHS[k - 1] for k in m)


def _holds(p: xr.Dataset) -> list[str]:
    return [str(leg) for leg, h in zip(p["leg"].values, p["leg_hold_point"].values) if int(h)][1:]


def _unrestricted(cx: Context, combo) -> tuple[bool, str]:
    p = cx.plan
    rng = model_range.of(cx, p)
    ok = bool(int(option_at(p["design_acceptable"], combo)))
    c, leg = governing(p, combo)
    years = num(float(p.attrs.get("design_return_period_years", 10)), 0)
    lvl = float(option_at(p["design_level"], combo).sel(criterion=c, leg=leg))
    lim = float(p["limit"].sel(criterion=c))
    u = float(option_at(p["design_utilisation"], combo).sel(criterion=c, leg=leg))
    hs = float(option_at(p["design_hs"], combo).sel(criterion=c, leg=leg))
    tz = float(option_at(p["design_tz"], combo).sel(criterion=c, leg=leg))
    where = f"the {years}-year design sea state of leg {leg} (Hs {num(hs, 1)} m, Tz {num(tz, 1)} s)"
    if ok:
        return True, (f"Acceptable as an unrestricted transit with the {combo_text(combo)}: in the "
                      f"{years}-year design sea states of every leg each criterion stays inside its limit; "
                      f"the largest, the {criterion_label(c)} MPM in {where}, is {level_text(p, c, lvl, combo, leg, rng)} "
                      f"against {level_text(p, c, lim)} ({pct(u)} of it).")
    n_ok = int(p["design_acceptable"].sum())
    others = (f"; {n_ok} other option{'s' if n_ok > 1 else ''} pass{'' if n_ok > 1 else 'es'} it"
              if n_ok else "; no assessed option passes it")
    return False, (f"Not acceptable as an unrestricted transit: with the {combo_text(combo)}, in {where} "
                   f"the {criterion_label(c)} MPM is {level_text(p, c, lvl, combo, leg, rng)} against "
                   f"{level_text(p, c, lim)}{others}.")


def _plan_figures(cx: Context, combo) -> str:
    p = cx.plan
    frac = float(option_at(p["plan_departure_fraction"], combo))
    w50, w90 = (float(option_at(p["plan_wait_h"], combo).sel(quantile=q)) for q in (0.5, 0.9))
    exc = float(option_at(p["plan_exceedance_probability"], combo))
    ref = float(option_at(p["reference_exceedance_probability"], combo))
    ns = float(option_at(p["plan_not_sailed_fraction"], combo))
    span = str(p.attrs.get("record_span", ""))
    text = (f"departing in {months_text(p)} (records {span}), {pct(frac)} of hours allow departure from the first hold "
            f"point, median wait {num(w50, 0)} h (90 %: {num(w90, 0)} h), probability that a sailed voyage "
            f"exceeds a limit {num(exc, 2)} (departing at any hour without the rule: {num(ref, 2)})")
    if ns > 0:
        text += (f"; {pct(ns)} of departures would wait longer than {num(float(p.attrs['max_wait_h']), 0)} h "
                 "at a hold point and are not sailed")
    judged, total = int(option_at(p["plan_judged"], combo)), int(p["departures_month"].sum())
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
    rule = (f"departures on a forecast inside the limits OP_WF below, forecast {p.attrs['forecast']}, "
            f"horizon {num(float(p.attrs['forecast_horizon_h']), 0)} h")      # no nested parentheses
    if str(p.attrs["route_class"]) == "weather-restricted":
        hold_text = f"hold point{'s' if len(holds) > 1 else ''}: {', '.join(holds)}" if holds else "no hold point on the way"
        if simulated(p) and float(option_at(p["plan_not_sailed_fraction"], combo)) < 1.0:
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
    wf = option_at(p["master_hs_opwf"], combo)
    a = option_at(p["master_alpha"], combo)
    has_alpha = bool(str(p.attrs.get("alpha_source", "")))
    tps = [float(tp) for tp in p["tp"].values]
    # one row per leg (and its alpha), the peak periods across: a short table on page 1
    header = ["Tp [s]"] + [num(tp, 0) for tp in tps]
    rows = []
    span = {leg: (float(p["leg_tp_min"].sel(leg=leg)), float(p["leg_tp_max"].sel(leg=leg)))
            if "leg_tp_min" in p else (-np.inf, np.inf) for leg in legs}
    for leg in legs:
        row = [f"{leg}: OP_WF [m]"]
        lo, hi = span[leg]
        for k, tp in enumerate(tps):
            x = float(wf.sel(leg=leg, tp=tp))
            text = "–" if np.isnan(x) else "no limit" if not np.isfinite(x) else num(x, 2)
            # a column outside the leg's seas (neither neighbour reaches into them) is greyed
            below = k + 1 < len(tps) and tps[k + 1] <= lo
            above = k > 0 and tps[k - 1] >= hi
            row.append(cell(text, fill=GREY) if below or above else text)
        rows.append(row)
        if has_alpha:
            rows.append([f"{leg}: α"] + [num(float(a.sel(leg=leg, tp=tp)), 2) for tp in tps])
    heads = {str(leg): ", ".join(f"{float(h):g}°" for h, pr in zip(cx.sea["heading"].values,
                                                                  cx.sea["heading_probability"].sel(leg=leg).values)
                                 if pr > 0) for leg in legs}
    alpha = (f"α from {p.attrs['alpha_source']}" + (f" ({p.attrs['alpha_note']})" if p.attrs.get("alpha_note") else "")
             if has_alpha else "α = 1: no table of forecast-uncertainty factors is configured, so OP_WF = OP_LIM "
             "and the forecast's own uncertainty is not allowed for")
    win = cx.windows
    if win is not None:
        same = str(win.attrs.get("alpha_source", "")) == str(p.attrs.get("alpha_source", "")) and \
            (has_alpha or float(win.attrs.get("alpha", 1.0)) == 1.0)
        alpha += ("; the weather windows use the same α" if same else
                  f"; the weather windows use another: {window_alpha_text(win)}")
    seas = ("; the columns span the peak periods of every leg's seas, grey outside the leg's own"
            if "leg_tp_min" in p else "")
    beyond = "; – beyond the statistics' periods" if bool(np.isnan(wf.values).any()) else ""
    cap = (f"Forecast limits for the master, {combo_text(combo)}: the largest forecast significant wave "
           f"height at each peak period (JONSWAP of the assessment) at which the departure rule starts a "
           f"stretch, OP_WF = α OP_LIM, per leg at the worst of its relative headings "
           f"({'; '.join(f'{k}: {v}' for k, v in heads.items())}){seas}{beyond}; {alpha}.")
    return table(cap, header, rows, size="7pt", label="tab-master-forecast",
                 align="(" + ", ".join(["left"] + ["right"] * (len(header) - 1)) + ")")


__all__ = ["GREY", "MONTHS", "governing", "level_cell", "level_text", "master_table", "months_text",
           "option_at", "simulated", "verdict"]
