"""The report's chapter "Operational basis" (DNV-ST-N001): whether the transit is a
weather-restricted or an unrestricted operation, as ``workability.nc`` records it
(attributes ``operation_class``, ``operation_reason``, ``planned_period_h``,
``reference_period_h``, ``contingency_h``, ``alpha_source``), and what follows:

* weather-restricted: a one-page table for the master, the limiting Hs per Tz and
  heading of the recommended option (OP_LIM, ``hs_limit``) and, where an alpha table is
  configured, OP_WF = alpha OP_LIM (``hs_opwf``); without one, the statement that alpha
  was not applied;
* unrestricted: the design basis, the voyage extremes (chapter "Voyage extremes").

Page 1's statement of the class is :func:`jls.report.basis.summary_sentence`.
"""

from __future__ import annotations

import numpy as np

from jls.report.basis import (
    RESTRICTED_MAX_POP_H,
    RESTRICTED_MAX_REFERENCE_H,
    Basis,
    operation_basis,
    voyage_inside,
)
from jls.report.context import Context, combo_text, criteria_text, heading
from jls.report.contract import pct
from jls.report.markup import cell, num, t, table

MAX_MASTER_ROWS = 45          # Tz rows of the master's table: one page


def _rule() -> str:
    return (f"T_POP ≤ {RESTRICTED_MAX_POP_H:g} h and T_R = T_POP + T_C ≤ "
            f"{RESTRICTED_MAX_REFERENCE_H:g} h")


def chapter(cx: Context) -> str:
    out = [heading("operation", "Operational basis")]
    out.append("DNV-ST-N001 designs a marine operation either on a weather forecast or on the "
               "statistics of the season. The reference period is the planned operation period "
               "plus the contingency time, $T_R = T_\"POP\" + T_C$. An operation may be "
               f"*weather-restricted* when {t(_rule())}: it starts only on a favourable forecast, "
               "and its operational limit OP_LIM (here the limiting Hs per Tz and heading) is "
               "reduced by the forecast-uncertainty factor α to the forecast limit "
               "OP_WF = α OP_LIM. A longer operation is *unrestricted*: it is designed on the "
               "statistics of the route and season.\n")
    b = operation_basis(cx.work)
    if b is None:
        out.append("#warning[The workability dataset records no operational basis (no "
                   "operation class): this report does not state whether the transit is "
                   "weather-restricted or unrestricted, and gives no forecast limits.]\n")
        return "\n".join(out)
    out.append(_basis_table(b))
    out.append(_restricted(cx, b) if b.restricted else _unrestricted(cx, b))
    return "\n".join(out)


def _basis_table(b: Basis) -> str:
    rows = [["planned operation period T_POP", num(b.planned_h, 0, "h")],
            ["contingency time T_C", "not stated" if b.contingency_h is None else num(b.contingency_h, 0, "h")],
            ["reference period T_R", num(b.reference_h, 0, "h")
             + (" (lower bound: no contingency stated)" if b.contingency_h is None else "")],
            ["class", cell(b.operation_class, bold=True)], ["why", b.reason],
            ["forecast factor α", b.alpha_source or "not applied (no alpha table)"]]
    return table("The operational basis of this transit, as the workability dataset records it.",
                 ["", ""], rows, columns="(auto, 1fr)", align="(left, left)")


def _unrestricted(cx: Context, b: Basis) -> str:
    dg = cx.dg
    inside = voyage_inside(cx.voyage, dg.best)
    basis = (f"The probability that the voyage of {t(combo_text(dg.best))} stays inside every "
             f"limit is {t(pct(inside))} ({cx.sec('voyage')})." if inside is not None
             else "No voyage dataset was given to this report, so that probability is not stated.")
    return ("*What follows.* The transit of "
            f"{num(b.planned_h, 0)} h cannot wait out a storm nor rely on one forecast from "
            "departure to arrival, so no forecast limit OP_WF and no alpha factor apply. "
            "*Design basis:* the rigging is assessed for an unrestricted transit, each "
            f"criterion ({t(criteria_text(dg))}) against the long-term statistics of the route's "
            "legs (their scatter tables, durations and headings) through the largest response "
            f"of the whole voyage. {basis} The limiting-Hs tables ({cx.sec('operability')}) "
            "stay the limits to monitor on board (OP_LIM), and the workability is the share of "
            "the route's sea states inside them, a planning figure."
            + (f" The verdict on the voyage as it will be sailed -- the design check in the design sea "
               f"states, the class of each stretch between hold points, the departure rule -- is in "
               f"{cx.sec('voyage_plan')}." if cx.plan is not None and cx.has("voyage_plan") else "") + "\n")


def _restricted(cx: Context, b: Basis) -> str:
    dg, work = cx.dg, cx.work
    combo = dg.best
    op = work["hs_limit"].sel(candidate=combo[0], tugger=combo[1])
    wf = work["hs_opwf"].sel(candidate=combo[0], tugger=combo[1]) if b.has_opwf else None
    alpha = work["alpha_factor"].sel(candidate=combo[0], tugger=combo[1]) if "alpha_factor" in work else None
    heads = [float(h) for h in work["heading"].values]
    tz = op.dropna("tz", how="all")["tz"].values
    step = max(1, int(np.ceil(tz.size / MAX_MASTER_ROWS)))
    tz = tz[::step]
    header = ["Tz [s]"]
    for h in heads:
        header += [f"{h:g}°: OP_LIM [m]"] + ([f"{h:g}°: α", f"{h:g}°: OP_WF [m]"] if wf is not None else [])
    rows = []
    for z in tz:
        row = [num(z, 2)]
        for h in heads:
            row.append(cell(num(op.sel(heading=h, tz=z), 2), bold=wf is None))
            if wf is not None:
                row += [num(alpha.sel(heading=h, tz=z), 2) if alpha is not None else "–",
                        cell(num(wf.sel(heading=h, tz=z), 2), bold=True)]
        rows.append(row)
    if wf is not None:
        alpha_text = (f"OP_WF = α OP_LIM, α from {t(b.alpha_source)} at the planned period of "
                      f"{num(b.planned_h, 0)} h and the limiting Hs.")
    else:
        alpha_text = ("*Alpha was not applied:* no table of forecast-uncertainty factors was "
                      "configured with its source, so the table gives OP_LIM only. OP_WF = α OP_LIM "
                      "follows from the forecast in hand and its α before sailing.")
    out = ["#pagebreak(weak: true)\n", heading("operation-master", "Limiting sea states for the master", 2),
           f"{t(combo_text(combo))} (the recommendation): largest significant wave height at each "
           f"zero-crossing period and relative wave heading for which every criterion holds "
           f"({t(criteria_text(dg))}, the most probable maximum over {num(dg.exposure_h, 1)} h), "
           f"capped by the wave-steepness ceiling. {alpha_text}\n",
           table(f"Limiting Hs for the master, {combo_text(combo)}: OP_LIM per Tz and heading"
                 + (", the factor α and OP_WF" if wf is not None else "")
                 + (f" (every {step}th period)" if step > 1 else "") + ".",
                 header, rows, size="8pt" if len(header) <= 8 else "7pt",
                 label="tab-master"),
           "#pagebreak(weak: true)\n"]
    return "\n".join(out)


__all__ = ["MAX_MASTER_ROWS", "chapter"]
