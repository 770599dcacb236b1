"""What splash-clearance margin costs: route workability against the margin kept.

For each rigging *family* (an assessed candidate's design with its drop height free) the
jacket is raised from the splash-clearance limit in steps of margin, the drop height
``max_drop - margin`` and every other design variable the candidate's own; each point
is scored like a screening candidate (:func:`jls.design.screening.evaluate`: feasibility
with the tolerance budget, route workability on the motion criteria, every tugger
setting). Cost: one screening candidate per family and margin, linear in both. The report
reads the row of the recommended rigging (what each metre of margin costs, and what the
tolerance budget costs against sitting on the limit).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.design.scoring import Scoring
from jls.design.screening import Settings, evaluate
from jls.plant.candidates import Rigging
from jls.plant.rigging import DESIGN_VARIABLES


def margin_grid(margins_m, budget_m: float) -> np.ndarray:
    """The swept margins [m]: the configured ones with the splash-clearance budget added,
    sorted and unique."""
    return np.unique(np.round(np.append(np.asarray(margins_m, float), budget_m), 6))


def margin_sweep(rig: Rigging, families: dict[str, dict], margins_m, motion: xr.Dataset,
                 sea: xr.Dataset, scoring: Scoring, settings: Settings) -> xr.Dataset:
    """Variables ``margin_route_workability`` (margin_family, splash_margin, tugger),
    ``margin_feasible`` and ``margin_drop_height`` (margin_family, splash_margin) and
    ``family_splash_margin`` (margin_family), the family's own margin; ``families``:
    name -> full design values (every variable of :data:`DESIGN_VARIABLES`)."""
    top = rig.limits.max_drop()
    margins = margin_grid(margins_m, rig.limits.budget.splash)
    names = list(families)
    values = {f"{name}|{m:g}": {**{v: float(families[name][v]) for v in DESIGN_VARIABLES},
                                "drop_height": top - float(m)}
              for name in names for m in margins}
    shape = (len(names), len(margins))
    ds = evaluate(rig, values, motion, sea, scoring, settings)
    work = ds["route_workability"].values.reshape(shape + (-1,))
    out = xr.Dataset({
        "margin_route_workability": (("margin_family", "splash_margin", "tugger"), work),
        "margin_feasible": (("margin_family", "splash_margin"), ds["feasible"].values.reshape(shape)),
        "margin_drop_height": (("margin_family", "splash_margin"), ds["drop_height"].values.reshape(shape)),
        "family_splash_margin": ("margin_family", [top - float(families[n]["drop_height"]) for n in names]),
    }, coords={"margin_family": names, "splash_margin": margins, "tugger": ds["tugger"].values})
    out["margin_route_workability"].attrs["note"] = (
        "drop height = largest drop at the splash-clearance limit less the margin, the family's "
        "other design variables held; route workability on the screening's motion criteria "
        "(without the tension and dynamic tip-clearance criteria)")
    return out


__all__ = ["margin_grid", "margin_sweep"]
