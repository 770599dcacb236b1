"""The report's chapter "Voyage extremes" (``voyage.nc``, :mod:`jls.stages.voyage`): the
distribution of the largest response over the whole voyage per option and criterion.

A transit cannot pause: workability is the share of the route's sea states inside the
limits; this chapter gives the probability that one voyage stays inside them from
departure to arrival. It shows the exceedance curve P(voyage max > x) per option with the
limit marked (``exceedance_curve``), the levels not exceeded with 50 % and 90 %
probability (``voyage_level``), the cells that contribute most at the limit
(``crossing_share``), the independence assumption and the side it errs on, whether the
levels lie inside the linear model's range and, for routes of hourly hindcasts, the
share of departures per calendar month whose voyage stays inside every limit
(``pass_probability_month``).
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr

from jls.report import model_range
from jls.report.basis import BEYOND_MODEL, voyage_inside, voyage_level
from jls.report.context import Context, combo_text, heading
from jls.report.contract import criterion_label, pct
from jls.report.markup import cell, figure, num, plural, t, table
from jls.report.model_range import ModelRange
from jls.report.style import STYLE, Task, combo_style, legend_columns, log_ticks, new_figure, save

MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")
P_FLOOR = 1e-4                # the exceedance axis ends here
TOP_CELLS = 3                 # cells named as the largest contributors at the limit


def _units(v: xr.Dataset, c: str) -> str:
    u = str(v["level_units"].sel(criterion=c).values) if "level_units" in v.coords else ""
    return {"degree": "°", "1": ""}.get(u, f" {u}" if u else "")


def _level(v, c, x) -> str:
    u = _units(v, c)
    return f"{num(x, 1)}{u}" if u == "°" else f"{num(x, 2 if u == '' else 1)}{u}"


def _levels(v, combo, q) -> dict:
    """criterion -> the option's voyage level at the non-exceedance ``q``."""
    return {str(k): voyage_level(v, combo, str(k), q) for k in v["criterion"].values}


def _beyond(rng: ModelRange, v, combo, c, q):
    """Why the option's voyage level of ``c`` at ``q`` lies beyond the linear model
    (:meth:`jls.report.model_range.ModelRange.beyond`), None inside it."""
    levels = _levels(v, combo, q)
    return rng.beyond(c, combo, levels[c], levels)


def _voyage_level(rng, v, combo, c, q) -> str:
    """A voyage level, or "beyond the model" (and why) where the linear model does not reach."""
    b = _beyond(rng, v, combo, c, q)
    return f"{BEYOND_MODEL} ({b.reason})" if b else _level(v, c, voyage_level(v, combo, c, q))


def _level_cell(rng, v, combo, c, q):
    b = _beyond(rng, v, combo, c, q)
    return cell(BEYOND_MODEL, fill="luma(225)") if b else _level(v, c, voyage_level(v, combo, c, q))


def governing(v: xr.Dataset, combo) -> str:
    """The criterion whose voyage maximum is most likely beyond its limit (then the
    largest median level over the limit)."""
    crit = [str(c) for c in v["criterion"].values]
    p = v["exceedance_probability"].sel(candidate=combo[0], tugger=combo[1])
    ratio = {c: voyage_level(v, combo, c, 0.5) / float(v["limit"].sel(criterion=c)) for c in crit}
    return max(crit, key=lambda c: (float(p.sel(criterion=c)), ratio[c]))


def hindcast(v: xr.Dataset | None) -> bool:
    return v is not None and "pass_probability_month" in v


# -- figures ----------------------------------------------------------------------------
def figure_plan(cx: Context) -> list[Task]:
    if cx.voyage is None:
        return []
    plan = []
    if "exceedance_curve" in cx.voyage:
        plan.append(Task("voyage_exceedance", lambda d: exceedance_figure(cx.voyage, cx.dg, d,
                                                                         model_range.of(cx, cx.voyage)), 1.0))
    if hindcast(cx.voyage):
        plan.append(Task("voyage_months", lambda d: month_figure(cx.voyage, cx.dg, d), 0.8))
    return plan


def curve_range(v: xr.Dataset, combos, c: str) -> float:
    """Right end of the level axis [level units] (logarithmic, from half the limit): 10 %
    beyond the largest level at which a shown option's exceedance probability is still
    above :data:`P_FLOOR`, and at least twice the limit."""
    lim = float(v["limit"].sel(criterion=c))
    cur = v["exceedance_curve"].sel(criterion=c)
    x = cur["level"].values * lim
    ends = [x[np.flatnonzero(cur.sel(candidate=a, tugger=b).values > P_FLOOR)].max(initial=0.0)
            for a, b in combos]
    return float(max(1.1 * max(ends, default=0.0), 2.0 * lim))


def _grey_from(rng: ModelRange, v, combos, c) -> float | None:
    """The level of ``c`` from which the curves are greyed: the smallest threshold of the
    shown options (None: no threshold)."""
    th = [b.threshold for a, _ in combos if (b := rng.threshold(c, a)) is not None]
    return min(th) if th else None


def exceedance_figure(v: xr.Dataset, dg, out_dir, rng: ModelRange | None = None):
    """P(voyage max > x) against x per shown option, one panel per criterion, the limit
    dotted and each option's exceedance probability at it marked; levels beyond the
    linear model's range (the smallest threshold of the shown options,
    :mod:`jls.report.model_range`) greyed and labelled "beyond the model"."""
    rng = rng or model_range.model_range(v)
    crit = [str(c) for c in v["criterion"].values]
    combos = dg.plot.combos
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.9 if len(crit) == 1 else 2.6 * int(np.ceil(len(crit) / 2)) + 0.6)
        axes = np.atleast_1d(fig.subplots(int(np.ceil(len(crit) / 2)) if len(crit) > 1 else 1,
                                          1 if len(crit) == 1 else 2, squeeze=False).ravel())
        for ax, c in zip(axes, crit):
            lim = float(v["limit"].sel(criterion=c))
            cur = v["exceedance_curve"].sel(criterion=c)
            x = cur["level"].values * lim
            for combo in combos:
                st = combo_style(dg, combo)
                y = cur.sel(candidate=combo[0], tugger=combo[1]).values
                b = rng.threshold(c, combo[0])
                edge = np.inf if b is None else b.threshold
                ax.semilogy(np.where(x <= edge, x, np.nan), y, lw=1.0, **st)
                if np.any(x > edge):                 # beyond the model: the curve greyed
                    grey = {k: val for k, val in st.items() if k != "label"} | {"color": "0.6"}
                    ax.semilogy(np.where(x >= edge, x, np.nan), y, lw=1.0, **grey)
                p = float(v["exceedance_probability"].sel(candidate=combo[0], tugger=combo[1], criterion=c))
                ax.plot([lim], [max(p, P_FLOOR)], marker="o", ms=3.5, color=st["color"], ls="")
            ax.axvline(lim, color="0.3", ls=":", lw=1.0)
            ax.annotate(f"limit {lim:g}{_units(v, c)}", (lim, P_FLOOR), xytext=(3, 3),
                        textcoords="offset points", fontsize=6, rotation=90, va="bottom")
            ax.set_xscale("log")
            right = curve_range(v, combos, c)
            ax.set_xlim(0.5 * lim, right)
            edge = _grey_from(rng, v, combos, c)
            if edge is not None and edge < right:
                ax.axvspan(max(edge, 0.5 * lim), right, color="0.92", zorder=0, lw=0)
                ax.annotate(BEYOND_MODEL, (max(edge, 0.5 * lim), 1.0), xytext=(3, -3), textcoords="offset points",
                            fontsize=6, va="top", zorder=4)
            ax.set_ylim(P_FLOOR, 1.5)
            log_ticks(ax.yaxis)
            ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
            ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _: f"{x:g}"))
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            ax.set_xlabel(f"largest {criterion_label(c)} of the voyage, x [{_units(v, c).strip() or '1'}]")
            ax.set_ylabel("P(voyage max > x)")
        for ax in axes[len(crit):]:
            ax.set_visible(False)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "voyage_exceedance")


def month_figure(v: xr.Dataset, dg, out_dir):
    """Share of the month's judged departures whose voyage stays inside every limit, per
    shown option (route simulation through the hindcast)."""
    p = v["pass_probability_month"]
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.6)
        ax = fig.subplots()
        for combo in dg.plot.combos:
            ax.plot(np.arange(12), 100 * p.sel(candidate=combo[0], tugger=combo[1]).values,
                    marker="o", ms=3, lw=1.0, **combo_style(dg, combo))
        ax.set_xticks(np.arange(12), MONTHS)
        ax.set_ylim(0, 100)
        ax.set_ylabel("departures inside every limit [%]")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "voyage_months")


# -- chapter ----------------------------------------------------------------------------
def chapter(cx: Context) -> str:
    out = [heading("voyage", "Voyage extremes")]
    v = cx.voyage
    if v is None:
        out.append("No voyage dataset was given to this report: the probability that "
                   "the voyage stays inside the limits is not assessed here.\n")
        return "\n".join(out)
    dg = cx.dg
    dur = float(cx.sea["duration_h"].sum())
    out.append(
        "A transit cannot pause: the workability is the share of the route's sea states inside "
        "the limits, but the voyage meets its sea states one after another and must stay inside "
        "the limits in every one of them. For a response with Rayleigh peaks in each sea state, "
        "the expected number of up-crossings of a level x during the voyage is "
        "$Lambda(x) = sum_\"legs\" sum_\"cells\" p D \\/ T_(z,r) exp(-x^2 \\/ (2 sigma^2))$ "
        "(cell probability p of heading, Hs and Tz, leg duration D, the response's zero-crossing "
        "period and standard deviation at the assessed Hs of the bin, its "
        f"{t(v.attrs.get('hs_in_bin', dg.hs_in_bin))}), and the voyage's largest value stays below "
        f"x with probability $exp(-Lambda(x))$; here over the {num(dur, 0)} h of "
        f"{plural(len(cx.legs), 'leg')}.\n")
    out.append(
        "*Independence, and the side it errs on.* Consecutive sea states are taken as "
        "independent: the voyage meets each cell for p D hours. Real sea states persist, so a "
        "voyage that meets a storm meets many hours of it and most voyages meet none; for the "
        "same expected number of up-crossings that lowers the probability that a voyage has any. "
        "Counting each up-crossing as an independent event errs the same way. Both "
        "*over-estimate* the exceedance probability: the assumption is *conservative*"
        + (" (the voyage dataset records it)"
           if "conservative" in str(v.attrs.get("independence", "")) else "") + ".\n")
    note = str(v.attrs.get("own_sea_not_used", ""))
    if "own_sea_level_ratio" in v:            # legs given by their own seas enter by their records
        out.append("*Sea model of the voyage extremes.* The legs given by their own seas (measured spectra, "
                   "partitions, Torsethaugen tables) enter the long-term extreme by their records (each hour, "
                   "or a table's cell, at each heading with its probability and its own sea's sigma and "
                   "up-crossing period; measured_response.nc), not by their binned JONSWAP cells "
                   "(voyage_level_jonswap: the same voyage on every leg's binned JONSWAP)"
                   + (f". Not on their own seas: {t(note)}.\n" if note else ".\n"))
    elif note:                                # legs given by their own seas: what is not on them
        out.append(f"*Sea model of the voyage extremes.* {t(note[:1].upper() + note[1:])}.\n")
    if "voyage_exceedance" in cx.figs:
        out.append(figure(cx.figs["voyage_exceedance"], "Probability that the voyage's largest "
                          "response exceeds x, per option (independent sea states; level on a "
                          "logarithmic axis); dotted: the limit, dots: each option's exceedance "
                          "probability at it. "
                          + dg.plot.caption()))
    out.append(_table(cx))
    out.append(_recommended(cx))
    out.append(_validity(cx))
    out.append(_contributors(cx))
    if hindcast(v):
        out.append(_months(cx))
    return "\n".join(out)


def _table(cx: Context) -> str:
    v, dg = cx.voyage, cx.dg
    rng = model_range.of(cx, v)
    crit = [str(c) for c in v["criterion"].values]
    sim = "pass_probability" in v
    header = ["candidate", "tugger"]
    for c in crit:
        lab = criterion_label(c)
        header += [f"{lab}: P(max > {_level(v, c, float(v['limit'].sel(criterion=c)))})",
                   "50 % level", "90 % level"]
    header += ["inside every limit"] + (["departures inside"] if sim else [])
    rows = []
    for combo in dg.table.combos:
        bold = combo == dg.best
        row = [cell(combo[0], bold=bold), cell(combo[1], bold=bold)]
        for c in crit:
            p = float(v["exceedance_probability"].sel(candidate=combo[0], tugger=combo[1], criterion=c))
            row += [pct(p), _level_cell(rng, v, combo, c, 0.5), _level_cell(rng, v, combo, c, 0.9)]
        row.append(cell(pct(voyage_inside(v, combo)), bold=bold))
        if sim:
            row.append(pct(float(v["pass_probability"].sel(candidate=combo[0], tugger=combo[1]))))
        rows.append(row)
    cap = ("Voyage extremes per option: the probability that the voyage's largest value of each "
           "criterion exceeds its limit, the levels it stays below with 50 % and 90 % "
           f"probability ('{BEYOND_MODEL}' on grey where the linear model does not reach), and the probability that it stays inside every limit (one minus the "
           "sum of the exceedance probabilities over the criteria, a lower bound)"
           + ("; departures inside: the share of the hindcast's departures whose voyage stayed "
              "inside every limit" if sim else "")
           + ". Recommendation in bold." + dg.table.table_caption())
    return table(cap, header, rows, size="8pt" if len(header) <= 9 else "7pt",
                 align="(left, left" + ", right" * (len(header) - 2) + ")", label="tab-voyage")


def _recommended(cx: Context) -> str:
    v, dg = cx.voyage, cx.dg
    rng = model_range.of(cx, v)
    c = governing(v, dg.best)
    inside = voyage_inside(v, dg.best)
    head = (f"For the recommended {t(combo_text(dg.best))} the voyage stays inside every limit "
            f"with probability *{t(pct(inside))}*; ")
    lim = t(_level(v, c, float(v['limit'].sel(criterion=c))))
    b50, b90 = (_beyond(rng, v, dg.best, c, q) for q in (0.5, 0.9))
    if b50 is not None:                     # the 90 % level lies beyond too: no figure at all
        return (head + f"the levels its largest {t(criterion_label(c))} stays below with probability "
                f"50 % and 90 % lie {BEYOND_MODEL} ({t(b50.reason)}), against a limit of {lim}.\n")
    tail = (f"below {t(_voyage_level(rng, v, dg.best, c, 0.9))} with probability 90 %" if b90 is None
            else f"its 90 % level lies {BEYOND_MODEL} ({t(b90.reason)})")
    return (head + f"its largest {t(criterion_label(c))} is below "
            f"{t(_voyage_level(rng, v, dg.best, c, 0.5))} with probability 50 % and {tail}, against a "
            f"limit of {lim}.\n")


def beyond_linear(v: xr.Dataset, combo, rng: ModelRange | None = None) -> list[tuple[str, float, float, str]]:
    """(criterion, median level, threshold, reason) of the criteria whose median voyage
    level lies beyond the linear model's range (:mod:`jls.report.model_range`; without
    ``rng``, the stated thresholds of ``v`` alone: relative motions in metres beyond
    LINEAR_SWAY_FACTOR x their limit, angles beyond LINEAR_ANGLE_DEG)."""
    rng = rng or model_range.model_range(v)
    out = []
    for c in (str(x) for x in v["criterion"].values):
        b = _beyond(rng, v, combo, c, 0.5)
        if b is not None:
            out.append((c, voyage_level(v, combo, c, 0.5), b.threshold, b.reason))
    return out


def _magnitude(x: float, units: str) -> str:
    if units != " m" or x < 10.0:
        return ""
    return " (tens of metres)" if x < 100.0 else " (hundreds of metres)"


def _validity(cx: Context) -> str:
    v, dg = cx.voyage, cx.dg
    far = beyond_linear(v, dg.best, model_range.of(cx, v))
    if not far:
        return (f"The median voyage levels of {t(combo_text(dg.best))} lie inside the range in "
                f"which the linear model holds ({cx.sec('validity')}).\n")
    parts = [f"the median largest {criterion_label(c)} lies {BEYOND_MODEL}: "
             + (f"{why}" if why == model_range.SLACK else
                f"above the {_level(v, c, thr)} of {why}")
             for c, x, thr, why in far]
    return (f"#warning[*The voyage levels lie outside the linear model's validity.* For "
            f"{t(combo_text(dg.best))} {t('; '.join(parts))} ({cx.sec('validity')}). No jacket "
            "in its rigging moves that far: at such amplitudes the wire geometry, the clearances "
            "and the damping are no longer those of the linear model. Read these levels as a "
            "statement that the voyage is expected to exceed the limit, by a margin the model "
            "cannot quantify, not as motions the jacket would reach.]\n")


def _contributors(cx: Context) -> str:
    v, dg = cx.voyage, cx.dg
    if "crossing_share" not in v:
        return ""
    c = governing(v, dg.best)
    sh = v["crossing_share"].sel(candidate=dg.best[0], tugger=dg.best[1], criterion=c)
    flat = sh.stack(cell=("leg", "heading", "hs", "tz"))
    order = np.argsort(-np.nan_to_num(flat.values))[:TOP_CELLS]
    cells = [f"leg {flat['leg'].values[i]}, {float(flat['heading'].values[i]):g}°, Hs "
             f"{float(flat['hs'].values[i]):g} m, Tz {float(flat['tz'].values[i]):g} s: "
             f"{pct(float(flat.values[i]))}" for i in order if float(flat.values[i]) > 0]
    text = (f"*Where the up-crossings of the limit come from* ({t(combo_text(dg.best))}, "
            f"{t(criterion_label(c))}): the largest contributions are {t('; '.join(cells))}")
    if "crossing_share_leg" in v:
        legs = v["crossing_share_leg"].sel(candidate=dg.best[0], tugger=dg.best[1], criterion=c)
        text += ("; by leg " + t(", ".join(f"{leg} {pct(float(legs.sel(leg=leg)))}"
                                          for leg in (str(x) for x in legs["leg"].values))))
    return text + ".\n"


def _months(cx: Context) -> str:
    v, dg = cx.voyage, cx.dg
    b = dg.best
    judged = int(v["judged_month"].sum())
    total = int(v["departures_month"].sum()) if "departures_month" in v else judged
    out = [heading("voyage-months", "Departures through the hindcast", 2)]
    best, worst = (int(v[k].sel(candidate=b[0], tugger=b[1])) for k in ("best_month", "worst_month"))
    ranked = (f"best month {MONTHS[best - 1]}, worst month {MONTHS[worst - 1]}" if best and worst
              else "no month has enough judged departures to be ranked")
    out.append(
        f"The route sailed through its hourly hindcast from every recorded departure hour, each "
        f"hour judged from its own statistics: {num(judged, 0)} of {num(total, 0)} departures could "
        f"be judged (the others meet a gap in the record). For {t(combo_text(b))}, "
        f"{t(pct(float(v['pass_probability'].sel(candidate=b[0], tugger=b[1]))))} of the judged "
        f"departures stayed inside every limit; {t(ranked)}.\n")
    if "hindcast_exceedance_probability" in v and "mean_departure_exceedance" in v:
        c = governing(v, b)
        ind = float(v["hindcast_exceedance_probability"].sel(candidate=b[0], tugger=b[1], criterion=c))
        dep = float(v["mean_departure_exceedance"].sel(candidate=b[0], tugger=b[1], criterion=c))
        out.append(f"On the same hours, the independent-sea-state formula gives an exceedance "
                   f"probability of {t(pct(ind))} for the {t(criterion_label(c))} against "
                   f"{t(pct(dep))} averaged over the departures that sail the hours in sequence: "
                   "the difference is what the persistence of real sea states is worth.\n")
    if "voyage_months" in cx.figs:
        out.append(figure(cx.figs["voyage_months"], "Share of the month's judged departures whose "
                          "voyage stays inside every limit, per option; months without a judged "
                          "departure are left out. " + dg.plot.caption()))
    return "\n".join(out)


__all__ = ["MONTHS", "beyond_linear", "chapter", "curve_range", "exceedance_figure",
           "figure_plan", "governing", "hindcast", "month_figure"]
