"""Feasibility of rigging candidates: every constraint, its margin and its reason.

A candidate is feasible when every wire is taut (:func:`jls.plant.equilibrium.slack`), the
jacket is held in all six rigid-body equations (:data:`jls.plant.equilibrium.RESIDUAL_LIMIT`),
the plant is statically stable, each design variable lies within its configured bounds,
the side and fore-aft lead angles and the splash clearance of table 5.1 hold, and, when
the configuration gives one, no static wire tension exceeds its limit.

Margins are positive when a constraint holds. Each safety constraint (lead angles,
splash clearance, static tension) must keep its tolerance budget (``Limits.budget``,
:class:`jls.plant.rigging.Budget`: wire length and creep, hinge height, draught and trim,
...): a candidate whose margin is inside its budget is infeasible, the reason naming the
constraint, the margin and the budget ("splash clearance margin 0.00 m inside its
tolerance budget 0.75 m (...)"). A margin within the numerical resolution
(``Limits.at_limit_tolerance_*``, either sign) of its budget counts as held but *at the
limit* (the budget used up exactly), and the candidate says so. The design-variable
bounds have no budget. Everything is vectorised over candidates; only the reason strings
are assembled per candidate.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.plant import equilibrium
from jls.plant.rigging import DESIGN_VARIABLES, Limits

LABELS = {"top_spread_y": "top spread Y", "bottom_spread_y": "bottom spread Y",
          "bottom_spread_x": "bottom spread X", "drop_height": "drop height"}


@dataclass(frozen=True)
class Feasibility:
    """Per candidate (n,): margins by constraint (positive = holds; units in the name),
    the budget each must keep (``budget``, same keys), ``feasible``, ``infeasible_reason``
    and ``at_limit`` ("" when none applies) and, per constraint, whether it is at its
    limit (``active``)."""

    margins: dict
    feasible: np.ndarray
    infeasible_reason: np.ndarray
    at_limit: np.ndarray
    active: dict
    budget: dict

    def spare(self, key: str) -> np.ndarray:
        """Margin beyond the budget (what an optimiser keeps >= 0)."""
        return np.asarray(self.margins[key], float) - self.budget[key]


def evaluate(plant, limits: Limits, design_space: dict, values: dict, wire_names) -> Feasibility:
    """Feasibility of the candidates of a built plant (leading axis = candidate).

    design_space: variable -> (lower, upper) [m]; values: variable -> (n,) design values.
    """
    tension = np.atleast_2d(plant.tension)
    n = tension.shape[0]
    weight = plant.m_grav * plant.g
    slack = equilibrium.slack(tension, weight)
    residual = np.atleast_2d(plant.residual)
    unbalanced = np.any(np.abs(residual) > equilibrium.RESIDUAL_LIMIT, axis=-1)
    worst_eq, worst_res = equilibrium.worst_residual(residual)
    omega = np.atleast_2d(plant.modes.omega)
    unstable = ~np.any(slack, -1) & ~np.all(np.isfinite(omega) & (omega > 0), axis=-1)
    geo = limits.check(plant.layout)
    geo = {k: np.broadcast_to(v, (n,)) for k, v in geo.items()}
    margins = dict(geo)
    tol = {"side_lead_margin_deg": limits.at_limit_tolerance_deg,
           "fore_aft_lead_margin_deg": limits.at_limit_tolerance_deg,
           "splash_clearance_margin_m": limits.at_limit_tolerance_m}
    b = limits.budget
    budget = {"side_lead_margin_deg": np.full(n, b.lead_angle), "fore_aft_lead_margin_deg": np.full(n, b.lead_angle),
              "splash_clearance_margin_m": np.full(n, b.splash)}
    if limits.max_tension_kN is not None:
        margins["tension_margin_kN"] = limits.max_tension_kN - tension.max(-1)
        tol["tension_margin_kN"] = limits.at_limit_tolerance_kN
        budget["tension_margin_kN"] = np.broadcast_to(b.tension(np.nanmax(tension, -1)), (n,))
    for var in DESIGN_VARIABLES:
        if var in design_space:
            lo, hi = design_space[var]
            v = np.broadcast_to(np.asarray(values[var], float), (n,))
            margins[f"{var}_lower_margin_m"] = v - lo
            margins[f"{var}_upper_margin_m"] = hi - v
            tol[f"{var}_lower_margin_m"] = tol[f"{var}_upper_margin_m"] = limits.at_limit_tolerance_m
            budget[f"{var}_lower_margin_m"] = budget[f"{var}_upper_margin_m"] = np.zeros(n)
    spare = {k: np.asarray(m, float) - budget[k] for k, m in margins.items()}
    violated = {k: spare[k] < -tol[k] for k in margins}
    active = {k: np.abs(spare[k]) <= tol[k] for k in margins}
    feasible = ~(np.any(slack, -1) | unbalanced | unstable
                 | np.any([violated[k] for k in margins], axis=0))
    reasons = np.empty(n, object)
    at = np.empty(n, object)
    for i in range(n):
        why, near = [], []
        for w, name in enumerate(wire_names):
            if slack[i, w]:
                state = "in compression" if tension[i, w] < 0 else "slack"
                why.append(f"wire '{name}' {state} (tension {tension[i, w]:.1f} kN)")
        if unbalanced[i]:
            why.append(f"out of balance: {equilibrium.EQUATIONS[int(worst_eq[i])]} residual "
                       f"{worst_res[i]:.1e} of the weight (limit {equilibrium.RESIDUAL_LIMIT:g})")
        if unstable[i]:
            why.append("statically unstable")
        for key, m in margins.items():
            text = _describe(key, float(m[i]), limits, design_space, tension[i], wire_names)
            held = float(m[i]) >= -tol[key]
            inside = _inside_budget(key, float(m[i]), float(budget[key][i]), limits)
            if violated[key][i]:
                why.append(inside[0] if held else text[0])
            elif active[key][i]:
                near.append(inside[1] if budget[key][i] > 0 else text[1])
        reasons[i] = "; ".join(why)
        at[i] = ("at limit: " + "; ".join(near)) if near else ""
    return Feasibility(margins=margins, feasible=feasible, infeasible_reason=reasons.astype(str),
                       at_limit=at.astype(str), active=active, budget=budget)


#: margin key -> (words, unit, which budget of :meth:`jls.plant.rigging.Budget.describe`)
BUDGETED = {"side_lead_margin_deg": ("side lead angle", "deg", "lead"),
            "fore_aft_lead_margin_deg": ("fore-aft lead angle", "deg", "lead"),
            "splash_clearance_margin_m": ("splash clearance", "m", "splash"),
            "tension_margin_kN": ("static tension", "kN", "tension")}


def _inside_budget(key, margin, budget, limits: Limits):
    """(reason when the margin is inside its budget, phrase when it uses it up exactly)."""
    if key not in BUDGETED:
        return "", ""
    words, unit, which = BUDGETED[key]
    fmt = ".0f" if unit == "kN" else ".2f"
    return (f"{words} margin {margin:{fmt}} {unit} inside its tolerance budget {budget:{fmt}} {unit} "
            f"({limits.budget.describe(which)})",
            f"{words} margin {margin:{fmt}} {unit}, its whole tolerance budget")


def _describe(key, margin, limits: Limits, space, tension, wire_names):
    """(reason when violated, phrase when at the limit) of one margin."""
    if key == "side_lead_margin_deg":
        angle = limits.side_lead_max_deg - margin
        return (f"side lead angle {angle:.2f} deg above {limits.side_lead_max_deg:g} deg",
                f"side lead angle {angle:.2f} deg")
    if key == "fore_aft_lead_margin_deg":
        angle = limits.fore_aft_lead_max_deg - margin
        return (f"fore-aft lead angle {angle:.2f} deg above {limits.fore_aft_lead_max_deg:g} deg",
                f"fore-aft lead angle {angle:.2f} deg")
    if key == "splash_clearance_margin_m":
        return (f"splash clearance short by {-margin:.2f} m (tip {limits.splash_clearance_m + margin:.2f} m "
                f"above the water, {limits.splash_clearance_m:g} m required)",
                f"splash clearance {margin:.2f} m")
    if key == "tension_margin_kN":
        w = int(np.argmax(tension))
        return (f"wire '{wire_names[w]}' tension {tension[w]:.0f} kN above the limit "
                f"{limits.max_tension_kN:g} kN", f"tension {tension[w]:.0f} kN")
    var, side = key.removesuffix("_margin_m").rsplit("_", 1)
    lo, hi = space[var]
    bound = lo if side == "lower" else hi
    value = bound + margin if side == "lower" else bound - margin
    word = "below" if side == "lower" else "above"
    return (f"{LABELS[var]} {value:.2f} m {word} its {side} bound {bound:g} m",
            f"{LABELS[var]} {side} bound {bound:g} m")
