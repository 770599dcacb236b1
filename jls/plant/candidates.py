"""Assemble the plant a validated configuration describes."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.plant import model as plant_mod
from jls.plant.rigging import Layout, Limits


@dataclass(frozen=True)
class Rigging:
    """Everything the configuration says about the suspension of one jacket."""

    layout: Layout
    jacket: plant_mod.Jacket
    wire_names: tuple
    wire_stiffness: np.ndarray
    limits: Limits
    design_space: dict
    g: float
    zeta: float
    anchor_modes: tuple
    fixed: tuple = ()


import xarray as xr

from jls.io import registry
from jls.plant import feasibility
from jls.plant.equilibrium import EQUATIONS
from jls.plant.linearise import DOF
from jls.plant.model import Plant, build
from jls.plant.rigging import DESIGN_VARIABLES, apply_design, design_variables

SUFFIX = "_m"


def candidate_layouts(rig: Rigging, values: dict[str, dict]) -> Layout:
    """Stack the candidates' layouts along a leading axis."""
    base = design_variables(rig.layout)
    arrays = {v: np.array([float(vals.get(v, base[v])) for vals in values.values()])
              for v in DESIGN_VARIABLES}
    return apply_design(rig.layout, rig.jacket.z_p, **arrays)


def candidate_plants(rig: Rigging, values: dict[str, dict]) -> tuple[Plant, dict, feasibility.Feasibility]:
    """The plant of every candidate (leading axis), its design values and its
    feasibility, as arrays: the numbers of :func:`plant_dataset` without the dataset
    (an optimiser evaluating one design at a time needs no more)."""
    layout = candidate_layouts(rig, values)
    p = build(layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta,
              anchor_modes=rig.anchor_modes)
    dv = design_variables(layout)
    return p, dv, feasibility.evaluate(p, rig.limits, rig.design_space, dv, rig.wire_names)


def plant_dataset(rig: Rigging, values: dict[str, dict]) -> tuple[xr.Dataset, Plant]:
    """The plant dataset of docs/reference/outputs.md for every candidate."""
    p, dv, fz = candidate_plants(rig, values)
    layout = p.layout
    names = list(values)
    margins = fz.margins
    dims2 = ("candidate", "dof", "dof_col")
    ds = xr.Dataset(
        {
            "M": (dims2, p.M), "K": (dims2, p.K), "C": (dims2, p.C),
            "Kb": (("candidate", "dof", "hinge_dof"), p.Kb),
            "natural_period": (("candidate", "mode"), p.modes.period),
            "damping_ratio": (("candidate", "mode"), p.damping_ratio),
            "energy_fraction": (("candidate", "mode", "dof"), p.modes.energy_fraction),
            "mode_shape": (("candidate", "dof", "mode"), p.modes.shapes),
            "dominant_dof": (("candidate", "mode"), p.modes.dominant.astype(np.int8)),
            "tension": (("candidate", "wire"), p.tension),
            "unstretched_length": (("candidate", "wire"), p.unstretched_length),
            "wire_stiffness": (("candidate", "wire"), np.broadcast_to(p.wire_stiffness, p.tension.shape)),
            "anchor": (("candidate", "wire", "axis"), layout.anchors),
            "padeye": (("candidate", "wire", "axis"), layout.padeyes),
            "cog_depth": ("candidate", np.broadcast_to(layout.cog_depth, (len(names),))),
            **{v: ("candidate", dv[v]) for v in DESIGN_VARIABLES},
            "side_lead_margin": ("candidate", margins["side_lead_margin_deg"]),
            "fore_aft_lead_margin": ("candidate", margins["fore_aft_lead_margin_deg"]),
            "splash_clearance_margin": ("candidate", margins["splash_clearance_margin_m"]),
            "equilibrium_residual": (("candidate", "equation"), p.residual),
            "feasible": ("candidate", fz.feasible),
            "infeasible_reason": ("candidate", fz.infeasible_reason),
            "at_limit": ("candidate", fz.at_limit),
            **({"tension_margin": ("candidate", margins["tension_margin_kN"])}
               if "tension_margin_kN" in margins else {}),
        },
        coords={"candidate": names, "dof": list(DOF), "dof_col": list(DOF),
                "hinge_dof": list(DOF), "mode": np.arange(1, 5), "wire": list(rig.wire_names),
                "axis": ["x", "y", "z"], "equation": list(EQUATIONS)},
    )
    registry.annotate(ds, "plant")
    ds.attrs.update(m_grav_t=rig.jacket.m_grav, g_m_per_s2=rig.g, damping_ratio=rig.zeta,
                    damping_anchor_modes=" ".join(rig.anchor_modes),
                    at_limit_tolerance_m=rig.limits.at_limit_tolerance_m,
                    at_limit_tolerance_deg=rig.limits.at_limit_tolerance_deg,
                    at_limit_tolerance_kN=rig.limits.at_limit_tolerance_kN,
                    side_lead_max_deg=rig.limits.side_lead_max_deg,
                    fore_aft_lead_max_deg=rig.limits.fore_aft_lead_max_deg,
                    splash_clearance_m=rig.limits.splash_clearance_m, **budget_attrs(rig.limits))
    if rig.limits.max_tension_kN is not None:
        ds.attrs["max_tension_kN"] = rig.limits.max_tension_kN
    return ds, p


def budget_attrs(limits: Limits) -> dict:
    """The tolerance budget as dataset attributes: totals and the components in words."""
    b = limits.budget
    return {"splash_clearance_budget_m": b.splash, "lead_angle_budget_deg": b.lead_angle,
            "tension_budget_kN": float(b.tension(0.0)),
            "tension_budget_percent": float(sum(v for _, v in b.tension_percent)),
            "tolerance_budget": (f"splash clearance {b.splash:.2f} m ({b.describe('splash')}); lead angles "
                                 f"{b.lead_angle:.2f} deg each ({b.describe('lead')}); static tension "
                                 f"({b.describe('tension')}) where a tension limit is set")}
