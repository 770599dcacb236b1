"""Constrained refinement of a rigging design from a starting point (section 5.3).

A derivative-free trust-region method (scipy's COBYQA) works on the free design
variables scaled to [0, 1] over their bounds, with every constraint given as a margin
that must stay non-negative. The objective is minimised; callers maximising a score
pass its negative. Objectives of the route's workability are piecewise constant, so
the caller hands in a continuous surrogate and confirms the result on the real score
(:func:`jls.design.screening.screening_dataset`). Because such an objective can be nearly flat
close to a constraint, the trust-region search is followed by a push along each
variable, as far as the bounds and constraints allow, kept only where it improves the
objective: an optimum that lies on a constraint ends on it, not a trust radius short.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Refinement:
    """Result of :func:`refine`: the design, its objective and margins, how many
    evaluations it took, and the optimiser's message."""

    x: np.ndarray
    objective: float
    margins: np.ndarray
    evaluations: int
    message: str


def refine(objective, margins, x0, lower, upper, *, tolerance=0.01, max_evaluations=200) -> Refinement:
    """Minimise ``objective(x)`` subject to ``margins(x) >= 0`` and lower <= x <= upper.

    objective: x (n,) -> float; margins: x (n,) -> (m,) array (positive = satisfied);
    both may be expensive: each design is evaluated once (cached). ``tolerance`` is the
    design-variable resolution [units of x] at which the search stops. A design that
    cannot be evaluated may return NaN; it is treated as worse than any other.
    """
    from scipy.optimize import Bounds, NonlinearConstraint, minimize  # slow import: on use only

    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    span = upper - lower
    x0 = np.clip(np.asarray(x0, float), lower, upper)
    cache: dict[tuple, tuple[float, np.ndarray]] = {}

    def evaluate(u):
        x = lower + np.clip(u, 0.0, 1.0) * span
        key = tuple(np.round(x, 10))
        if key not in cache:
            f = float(objective(x))
            g = np.atleast_1d(np.asarray(margins(x), float))
            cache[key] = (f, g)
        return cache[key]

    u0 = (x0 - lower) / span
    f0, g0 = evaluate(u0)
    penalty = (abs(f0) if np.isfinite(f0) else 1.0) * 10.0 + 1.0

    def fun(u):
        f = evaluate(u)[0]
        return f if np.isfinite(f) else penalty

    def con(u):
        g = evaluate(u)[1]
        return np.where(np.isfinite(g), g, -1.0)

    rho_end = max(float(tolerance) / (10.0 * float(span.max())), 1e-7)
    constraints = [NonlinearConstraint(con, 0.0, np.inf)] if g0.size else []
    res = minimize(fun, u0, method="COBYQA", bounds=Bounds(0.0, 1.0), constraints=constraints,
                   options={"initial_tr_radius": max(0.1, 2 * rho_end), "final_tr_radius": rho_end,
                            "maxfev": int(max_evaluations)})
    u = _push_to_limits(np.clip(res.x, 0.0, 1.0), fun, con, rho_end)
    x = lower + u * span
    f, g = evaluate(u)
    return Refinement(x=x, objective=f, margins=g, evaluations=len(cache), message=str(res.message))


def _push_to_limits(u, fun, con, resolution):
    """Move one variable at a time towards a bound, as far as the constraints allow
    (bisection to ``resolution``), keeping each move that lowers ``fun``."""
    u = np.array(u, float)
    if np.any(con(u) < 0):
        return u
    for i in range(u.size):
        for end in (0.0, 1.0):
            if abs(u[i] - end) <= resolution:
                continue
            step = u.copy()
            step[i] += np.sign(end - u[i]) * resolution
            if not (fun(step) < fun(u) and np.all(con(step) >= 0)):
                continue
            good, bad = u[i], end
            trial = u.copy()
            trial[i] = end
            if np.all(con(trial) >= 0):
                good = end
            else:
                while abs(bad - good) > resolution:
                    trial[i] = 0.5 * (good + bad)
                    if np.all(con(trial) >= 0):
                        good = trial[i]
                    else:
                        bad = trial[i]
            trial[i] = good
            if fun(trial) < fun(u):
                u = trial
    return u
