"""One-at-a-time sensitivity of the natural periods to the design variables (figure 5.3;
variables of layout ``screening`` of the registry): :func:`sensitivity` sweeps each
variable over its design bounds about the baseline, the others held, and finds the
contiguous feasible range around the baseline by bisection.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.io import registry
from jls.plant.candidates import Rigging, plant_dataset
from jls.plant.rigging import DESIGN_VARIABLES, design_variables


def _bisect_ends(rig: Rigging, ends: dict, tolerance: float) -> None:
    """Narrow each [feasible, infeasible] pair to ``tolerance`` by bisection, all at once."""
    open_ = [k for k, (a, b) in ends.items() if abs(b - a) > tolerance]
    while open_:
        trial = {f"{var}_{side}": {var: 0.5 * (ends[var, side][0] + ends[var, side][1])}
                 for var, side in open_}
        plant, _ = plant_dataset(rig, trial)
        for (var, side), ok in zip(open_, plant["feasible"].values):
            mid = 0.5 * (ends[var, side][0] + ends[var, side][1])
            ends[var, side][0 if ok else 1] = mid
        open_ = [k for k in open_ if abs(ends[k][1] - ends[k][0]) > tolerance]


def sensitivity(rig: Rigging, points: int = 41, tolerance: float = 1e-3) -> xr.Dataset:
    """Natural periods against each design variable, one at a time about the baseline
    (figure 5.3), over its design bounds (or +/- 25 % where it has none), with the
    contiguous feasible range around the baseline, its ends found to ``tolerance`` [m]."""
    base = {k: float(v) for k, v in design_variables(rig.layout).items()}
    sweep = {}
    for var in DESIGN_VARIABLES:
        lo, hi = rig.design_space.get(var, (0.75 * base[var], 1.25 * base[var]))
        sweep[var] = np.linspace(lo, hi, points)
    values = {f"{v}_{i}": {v: float(x)} for v in DESIGN_VARIABLES for i, x in enumerate(sweep[v])}
    plant, _ = plant_dataset(rig, values)
    shape = (len(DESIGN_VARIABLES), points)
    feasible = plant["feasible"].values.reshape(shape)
    ends = {}                                    # (var, side) -> [feasible x, infeasible x]
    for j, var in enumerate(DESIGN_VARIABLES):
        x, ok = sweep[var], feasible[j]
        i0 = int(np.argmin(np.abs(x - base[var])))
        if not ok[i0]:
            continue
        lo_i, hi_i = i0, i0
        while lo_i > 0 and ok[lo_i - 1]:
            lo_i -= 1
        while hi_i < points - 1 and ok[hi_i + 1]:
            hi_i += 1
        ends[var, 0] = [x[lo_i], x[lo_i - 1] if lo_i > 0 else x[lo_i]]
        ends[var, 1] = [x[hi_i], x[hi_i + 1] if hi_i < points - 1 else x[hi_i]]
    _bisect_ends(rig, ends, tolerance)
    lower = np.array([ends[v, 0][0] if (v, 0) in ends else np.nan for v in DESIGN_VARIABLES])
    upper = np.array([ends[v, 1][0] if (v, 1) in ends else np.nan for v in DESIGN_VARIABLES])
    ds = xr.Dataset({
        "sensitivity_value": (("variable", "point"), np.stack([sweep[v] for v in DESIGN_VARIABLES])),
        "sensitivity_period": (("variable", "point", "mode"),
                               plant["natural_period"].values.reshape(shape + (-1,))),
        "sensitivity_dominant_dof": (("variable", "point", "mode"),
                                     plant["dominant_dof"].values.reshape(shape + (-1,))),
        "sensitivity_feasible": (("variable", "point"), feasible),
        "feasible_lower": ("variable", lower), "feasible_upper": ("variable", upper),
        "baseline_value": ("variable", [base[v] for v in DESIGN_VARIABLES]),
    }, coords={"variable": list(DESIGN_VARIABLES), "point": np.arange(points),
               "mode": plant["mode"].values})
    return registry.annotate(ds, "screening")
