"""The margin trade-off of the chapter "Rigging": route workability of the recommended
rigging family against the splash-clearance margin it keeps (``screening.nc``'s
``margin_route_workability``, :func:`jls.design.margins.margin_sweep`), i.e. what the
tolerance budget and each further metre of margin cost. Every number is read from the
dataset."""

from __future__ import annotations

import numpy as np

from jls.report.context import Context
from jls.report.markup import num, signed, t, table


def margin_rows(cx: Context):
    """(rows, summary sentence) for the recommended combination, or None when the
    screening dataset has no sweep of its rigging."""
    s = cx.screening
    cand, tug = cx.dg.best
    if s is None or "margin_route_workability" not in s or cand not in s["margin_family"].values:
        return None
    f = s.sel(margin_family=cand)
    margins = f["splash_margin"].values
    w = 100.0 * f["margin_route_workability"].sel(tugger=tug).values
    ok = f["margin_feasible"].values.astype(bool)
    budget = float(s.attrs.get("splash_clearance_budget_m", 0.0))
    own = float(f["family_splash_margin"])
    rows = []
    for i, m in enumerate(margins):
        per_m = (w[i] - w[i - 1]) / (m - margins[i - 1]) if i else np.nan
        note = ("the tolerance budget" if np.isclose(m, budget) else "inside the budget" if m < budget - 1e-9
                else "" if ok[i] else "infeasible")
        if np.isclose(m, own, atol=0.01):
            note = ", ".join(filter(None, [note, f"the {cand} design"]))
        rows.append([num(m, 2), num(f["margin_drop_height"].values[i], 2), num(w[i], 2),
                     signed(w[i] - w[0], 2), signed(per_m, 2), note])
    top = len(margins) - 1
    j = int(np.argmin(np.abs(margins - budget)))
    parts = [f"For the {t(cand)} rigging with tugger {t(tug)}, keeping the {num(budget, 2)} m tolerance "
             f"budget costs {num(w[0] - w[j], 2)} percentage points of route workability against "
             "sitting on the limit"]
    if top > j:
        parts.append(f"beyond the budget each further metre of margin costs on average "
                     f"{num((w[j] - w[top]) / (margins[top] - margins[j]), 2)} percentage points "
                     f"(to {num(margins[top], 2)} m)")
    sentence = "; ".join(parts) + "."
    if own > margins[top] + 0.01:
        sentence += f" The {t(cand)} design itself keeps {num(own, 2)} m, beyond the swept margins."
    return rows, sentence


def margin_table(cx: Context) -> str:
    """The table and its sentence (empty when the screening has no sweep of the
    recommended rigging)."""
    got = margin_rows(cx)
    if got is None:
        return ""
    rows, sentence = got
    cand, tug = cx.dg.best
    note = str(cx.screening["margin_route_workability"].attrs.get("note", ""))
    return (f"*What margin costs.* {sentence}\n"
            + table(f"Route workability of the recommended rigging family ({cand}, tugger {tug}) against "
                    f"its splash-clearance margin: {note}. Change: against the margin 0 (the limit); "
                    "per metre: against the row above.",
                    ["margin [m]", "drop height [m]", "route workability [%]", "change [pp]",
                     "per metre [pp/m]", ""], rows, align="(right, right, right, right, right, left)"))


__all__ = ["margin_rows", "margin_table"]
