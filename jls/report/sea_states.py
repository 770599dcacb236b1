"""The report's chapter "Sea states": the route as described in the configuration, its
legs, the wave-steepness rule and what it does, how each leg's wave headings were
obtained and how much sea-state energy lies outside the RAO frequency range, and one
Hs-Tz scatter figure per leg with the pass/fail overlay of the bare baseline."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.collections import PatchCollection
from matplotlib.patches import Patch, Rectangle

from jls.report.context import Context, criteria_text, heading
from jls.report.contract import flag, on_sea_grid, pct
from jls.report.curves import ceiling_curve, limit_curves
from jls.report.markup import cell, figure, num, plural, sci, t, table
from jls.report.style import STYLE, TUG_STYLES, Task, new_figure, save

PASS, FAIL, PARTIAL = "#7cc47f", "#e57373", "#ffcc80"


def figure_plan(cx: Context) -> list[Task]:
    """One scatter figure per leg, in the legs' order (cost: the cells it labels)."""
    live = (cx.sea["probability"] > 0).sum(("hs", "tz"))         # labelled cells per leg
    return [Task(f"scatter_{leg}", lambda d, leg=leg: scatter(cx.sea, cx.work, cx.dg, leg, d),
                 1.0 + 0.03 * float(live.sel(leg=leg)))
            for leg in cx.legs]


def chapter(cx: Context) -> str:
    sea, dg = cx.sea, cx.dg
    base = (dg.baseline, dg.no_tugger)
    out = [heading("sea_states", "Sea states")]
    desc = str(cx.prov.get("route_description") or "").strip()
    total = float(sea["duration_h"].sum())
    out.append((f"*The route.* {t(desc.rstrip('.'))}. " if desc else "")
               + f"The voyage of {num(total, 0)} h is sailed in {plural(len(cx.legs), 'leg')} "
               f"({t(', '.join(f'{leg} {float(sea.duration_h.sel(leg=leg)):g} h' for leg in cx.legs))}), "
               "each described by its own table of Hs-Tz cells (its source in the table of "
               f"{cx.sec('provenance')}); a leg's weight in the route is its share of the duration.\n")
    out.append(f"*The wave-steepness rule.* {steepness_text(cx)} A cell whose centre lies above "
               "the ceiling is *flagged, not dropped*: it is assessed like any other and its "
               f"probability is reported. Cells are assessed at the Hs of their *{t(dg.hs_in_bin)}*.\n")
    rows = []
    for leg in cx.legs:
        s = sea.sel(leg=leg)
        hp = s["heading_probability"]
        heads = ", ".join(f"{float(h):g}° ({100 * float(p):.0f} %)" for h, p in zip(hp["heading"].values, hp.values)
                          if float(p) > 0)
        live = int((s["probability"] > 0).sum())
        rows.append([t(leg), num(s["duration_h"], 1), pct(float(s["leg_weight"])), str(live),
                     t(heads), pct(float(s["steep_probability"])), pct(cx.w_leg(base, leg))])
    out.append(table(f"Route legs: duration, weight in the route, cells with data, wave headings, "
                     f"probability in steep cells and workability of the {dg.baseline} rigging "
                     f"without tugger.", ["leg", "duration [h]", "weight", "cells", "headings",
                                          "steep", "workable"],
                     [[cell(r[0], raw=True), r[1], r[2], r[3], cell(r[4], raw=True), r[5], r[6]]
                      for r in rows], align="(left, right, right, right, left, right, right)"))
    out.append(headings_and_coverage(cx))
    for leg in cx.legs:
        s = sea.sel(leg=leg)
        cap = (t(f"Leg {leg}: {float(s['duration_h']):g} h, weight {pct(float(s['leg_weight']))}. "
                 f"Numbers: probability of each cell in per cent. Colour: pass or fail of the "
                 f"{dg.baseline} rigging without tugger ({criteria_text(dg)}); hatched: above the "
                 f"steepness ceiling ({pct(float(s['steep_probability']))} of the leg); triangle "
                 "and bold: outside the linear range (") + cx.sec("validity")
               + t("). Solid line: limiting Hs of the same combination; dashed: steepness ceiling."))
        out.append(figure(cx.figs[f"scatter_{leg}"], cap, width="88%", caption_raw=True))
    return "\n".join(out)


STEEPNESS_RULES = {
    "study": ("the study's rule, $H_s <= g T_z^2 \\/ (2 pi dot 15)$: a sea-state steepness of at most "
              "1/15 on the wavelength of the zero-crossing period"),
    "dnv": ("DNV-RP-C205's rule, $H_s <= S_p g T_p^2 \\/ (2 pi)$ with the steepness $S_p$ from 1/15 "
            "at $T_p <= 8$ s to 1/25 at $T_p >= 15$ s (linear between), Tp from Tz by the "
            "JONSWAP relation"),
}


def steepness_text(cx: Context) -> str:
    """What the configured steepness rule says, and its ceiling at two Tz of the tables
    (``steepness_limit`` of workability.nc) - markup."""
    rule = str(cx.sea.attrs.get("steepness_rule", cx.work.attrs.get("steepness_rule", "")))
    what = STEEPNESS_RULES.get(rule, t(f"rule '{rule}'" if rule else "a rule not recorded"))
    lim = cx.work["steepness_limit"].dropna("tz")
    at = lim.isel(tz=[lim.sizes["tz"] // 3, 2 * lim.sizes["tz"] // 3]) if lim.sizes["tz"] > 2 else lim
    examples = "; ".join(f"{num(float(a), 2)} m at Tz {float(z):g} s" for z, a in zip(at["tz"].values, at.values))
    return (f"Waves break beyond a certain steepness, so no sea state is steeper than a ceiling on Hs "
            f"that rises with the period: {what} (ceiling {t(examples)}).")


# -- headings and RAO coverage --------------------------------------------------------
HEADING_SOURCES = {
    "default": "not given: beam seas (90°) assumed",
    "given": "given as relative headings in the configuration",
    "course_directions": "derived from the course and the wave directions",
    "direction_table": "derived from the course and the leg's direction-resolved table",
}


def energy_outside_leg(cx: Context, leg: str) -> float | None:
    """Share of the wave energy outside the RAO range, weighted by the leg's Hs-Tz
    probabilities (``energy_outside`` per Tz of response.nc); None when absent."""
    if "energy_outside" not in cx.resp:
        return None
    e = on_sea_grid(cx.resp["energy_outside"], cx.sea)
    p = cx.sea["probability"].sel(leg=leg)
    total = float(p.sum())
    return float((p * e).sum() / total) if total > 0 else None


def headings_and_coverage(cx: Context) -> str:
    rows = []
    for leg in cx.legs:
        src = str(cx.sea.attrs.get(f"heading_source_{leg}", "not recorded"))
        e = energy_outside_leg(cx, leg)
        rows.append([leg, HEADING_SOURCES.get(src, src), "n/a" if e is None else sci(e, 2)])
    policy = str(cx.resp.attrs.get("outside_rao_range", ""))
    return table("How each leg's wave headings were obtained, and the share of the sea states' "
                 "wave energy outside the RAO frequency range, weighted by the leg's Hs-Tz "
                 "probabilities" + (f" ({policy})" if policy else "") + ".",
                 ["leg", "headings", "energy outside the RAO range"], rows,
                 align="(left, left, right)")


# -- figure ---------------------------------------------------------------------------
def scatter(sea: xr.Dataset, work: xr.Dataset, dg, leg: str, out_dir) -> Path:
    """One leg's Hs-Tz table: probability per cell, pass/fail of the baseline without
    tugger, steep cells hatched, cells outside the linear range marked, the baseline's
    limiting Hs and the steepness ceiling."""
    s = sea.sel(leg=leg)
    combo = (dg.baseline, dg.no_tugger)
    passes = flag(on_sea_grid(work["passes"].sel(candidate=combo[0], tugger=combo[1], leg=leg), sea))
    hp = s["heading_probability"]
    pass_frac = ((passes * hp).sum("heading") / max(float(hp.sum()), 1e-12)).transpose("hs", "tz")
    outside = dg.linear[combo]["mask"].sel(leg=leg).any("heading").transpose("hs", "tz").values
    prob = s["probability"].transpose("hs", "tz").values
    steep = flag(s["steep"]).transpose("hs", "tz").values
    live = prob > 0
    rows_live = np.flatnonzero(live.any(axis=1))
    cols_live = np.flatnonzero(live.any(axis=0))
    n_rows = rows_live[-1] + 1 if rows_live.size else s.sizes["hs"]
    small = n_rows > 10 or (cols_live.size and cols_live[-1] - cols_live[0] > 10)
    with matplotlib.rc_context({**STYLE, "hatch.color": "0.4", "hatch.linewidth": 0.5}):
        fig = new_figure(float(np.clip(1.4 + 0.3 * n_rows, 3.0, 6.2)))
        ax = fig.subplots()
        hs_lo, hs_up = s["hs_lower"].values, s["hs_upper"].values
        tz_lo, tz_up = s["tz_lower"].values, s["tz_upper"].values
        frac = pass_frac.values
        cells = {False: [], True: []}                  # hatched (steep) or not -> cell rectangles
        for i in range(s.sizes["hs"]):
            for j in range(s.sizes["tz"]):
                h0, h1 = float(hs_lo[i]), float(hs_up[i])
                t0, t1 = float(tz_lo[j]), float(tz_up[j])
                if not np.all(np.isfinite([h0, h1, t0, t1])):
                    continue
                p = prob[i, j]
                f = float(frac[i, j])
                colour = "white" if p <= 0 else PASS if f >= 1 - 1e-9 else FAIL if f <= 1e-9 else PARTIAL
                cells[bool(steep[i, j] and p > 0)].append(
                    Rectangle((t0, h0), t1 - t0, h1 - h0, fc=colour, ec="0.6", lw=0.4))
                if p > 0:
                    txt = f"{100 * p:.1f}" if p >= 0.0005 else "<0.1"
                    ax.text((t0 + t1) / 2, (h0 + h1) / 2, txt, ha="center", va="center",
                            fontsize=5 if small else 6,
                            weight="bold" if bool(outside[i, j]) else "normal",
                            bbox={"fc": "white", "ec": "none", "alpha": 0.7, "pad": 0.4},
                            in_layout=False)      # inside its cell, inside the axes
                    if bool(outside[i, j]):
                        ax.plot(t1 - 0.08 * (t1 - t0), h1 - 0.14 * (h1 - h0), marker="^",
                                color="k", ms=2 if small else 3)
        for hatched, rects in cells.items():          # one artist per kind: same look, drawn faster
            if rects:
                ax.add_collection(PatchCollection(rects, match_original=True, zorder=1,
                                                  hatch="///" if hatched else None),
                                  autolim=False)
        if cols_live.size:
            t_lo, t_hi = float(tz_lo[cols_live[0]]), float(tz_up[cols_live[-1]])
            h_hi = float(s["hs_upper"].values[rows_live[-1]])
        else:
            t_lo, t_hi = float(np.nanmin(tz_lo)), float(np.nanmax(tz_up))
            h_hi = float(np.nanmax(s["hs_upper"]))
        tz, ceil = ceiling_curve(work, t_lo, t_hi)
        ax.plot(tz, ceil, color="0.35", ls="--", lw=1.0, label="steepness ceiling")
        curve, _ = limit_curves(work)
        for k, h in enumerate(work["heading"].values):
            hl = curve.sel(candidate=combo[0], tugger=combo[1], heading=h).dropna("tz")
            ax.plot(hl["tz"], hl, color="navy", lw=1.2, ls=TUG_STYLES[k % 4],
                    label=f"limiting Hs, {h:g}°")
        ax.set_xlim(t_lo, t_hi)
        ax.set_ylim(0, h_hi)
        ax.set_xlabel("zero-crossing period Tz [s]")
        ax.set_ylabel("significant wave height Hs [m]")
        ax.set_title(f"leg {leg}: probability per cell [%]; {combo[0]} rigging, tugger {combo[1]}")
        handles = ax.get_legend_handles_labels()[0] + [
            Patch(fc=PASS, ec="0.6", label="passes"), Patch(fc=FAIL, ec="0.6", label="fails"),
            Patch(fc=PARTIAL, ec="0.6", label="passes at some headings"),
            Patch(fc="white", ec="0.6", hatch="///", label="above steepness ceiling"),
            matplotlib.lines.Line2D([], [], marker="^", color="k", ls="", ms=3,
                                    label="outside linear range")]
        fig.legend(handles=handles, loc="outside right upper", fontsize=6)
        ax.grid(False)
        return save(fig, out_dir, f"scatter_{leg}")


__all__ = ["HEADING_SOURCES", "chapter", "energy_outside_leg", "figure_plan",
           "headings_and_coverage", "scatter"]
