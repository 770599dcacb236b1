"""Page 1's master's table per swell system (``voyage_plan.nc``, :mod:`jls.stages.swell_limits`):
for each leg whose sea has partitions, OP_WF of the swell per swell peak period of the
recommendation, with the wind sea it holds with and the headings, under the master's
table. Every number comes from the dataset (:func:`swell_cell` is the one formatting)."""

from __future__ import annotations

import numpy as np

from jls.report.context import Context, combo_text
from jls.report.markup import cell, num, table
from jls.report.plan_verdict import GREY

__all__ = ["swell_cell", "swell_table"]


def swell_cell(x: float) -> str:
    """A swell OP_WF [m] as page 1 prints it: 2 decimals; 'none' for 0 (the wind sea alone
    reaches a limit); 'no limit' beyond the search; an en dash when missing."""
    if np.isnan(x):
        return "–"
    if not np.isfinite(x):
        return "no limit"
    return "none" if x == 0 else num(x, 2)


def swell_table(cx: Context) -> str:
    """The swell table of the recommendation (module docstring); empty without
    partitioned legs."""
    p = cx.plan
    if p is None or "swell_hs_opwf" not in p:
        return ""
    combo = cx.dg.best
    wf = p["swell_hs_opwf"].sel(candidate=combo[0], tugger=combo[1])
    a = p["swell_alpha"].sel(candidate=combo[0], tugger=combo[1])
    legs = [str(x) for x in p["leg"].values if np.isfinite(float(p["wind_sea_hs"].sel(leg=x)))
            or np.isfinite(float(p["swell_heading_deg"].sel(leg=x)))]
    tps = [float(x) for x in p["swell_tp"].values]
    has_alpha = bool(str(p.attrs.get("alpha_source", "")))
    header = ["swell Tp [s]"] + [num(x, 0) for x in tps]
    rows, seen = [], {}
    for leg in legs:
        lo, hi = float(p["swell_tp_min"].sel(leg=leg)), float(p["swell_tp_max"].sel(leg=leg))
        hw = float(p["wind_sea_hs"].sel(leg=leg))
        wind = (f"wind {num(hw, 2)} m, {num(float(p['wind_sea_tp'].sel(leg=leg)), 1)} s at "
                f"{num(float(p['wind_sea_heading_deg'].sel(leg=leg)), 0)}°" if hw > 0 else "no wind sea")
        sh = float(p["swell_heading_deg"].sel(leg=leg))
        label = (f"{wind}; swell at {num(sh, 0)}°" if np.isfinite(sh) else
                 f"wind {num(hw, 2)} m, {num(float(p['wind_sea_tp'].sel(leg=leg)), 1)} s and swell at the worst of "
                 "the leg's headings" if hw > 0 else "swell at the worst of the leg's headings")
        row = []
        for k, tp in enumerate(tps):
            text = swell_cell(float(wf.sel(leg=leg, swell_tp=tp)))
            outside = (k + 1 < len(tps) and tps[k + 1] <= lo) or (k > 0 and tps[k - 1] >= hi)
            row.append(cell(text, fill=GREY) if outside else text)
        alpha = [num(float(a.sel(leg=leg, swell_tp=tp)), 2) for tp in tps] if has_alpha else []
        key = (label, tuple(row), tuple(alpha))
        if key in seen:                           # legs of the same seas and limits: one row
            rows[seen[key]][0] = rows[seen[key]][0].replace(" (", f", {leg} (", 1)
            continue
        seen[key] = len(rows)
        rows.append([f"{leg} ({label})"] + row)
        if has_alpha:
            rows.append(["α"] + alpha)
    cap = (f"Swell OP_WF [m], {combo_text(combo)}: the largest forecast swell Hs per swell peak period with the "
           "leg's median wind sea inside every criterion (tip and wire tension included), α as above; grey: outside "
           "the leg's swell periods; none: the wind sea alone reaches a limit.")
    return table(cap, header, rows, size="7pt", label="tab-master-swell",
                 align="(" + ", ".join(["left"] + ["right"] * (len(header) - 1)) + ")")
