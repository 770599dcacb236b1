"""Assemble the plant a validated configuration describes."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from jls import modes as modes_mod, plant as plant_mod
from jls.errors import InputError
from jls.rigging import Layout, Limits, series_stiffness


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


def rigging_from_config(cfg) -> Rigging:
    j, r = cfg["jacket"], cfg["rigging"]
    jacket = plant_mod.Jacket(m_grav=j["m_grav_t"], m_kin=j.get("m_kin_t"), ixx=j["ixx_t_m2"],
                              izz=j["izz_t_m2"], z_p=j["z_p_m"], lumping=r["mass_lumping"])
    layout = Layout(anchors=np.array([w["anchor_m"] for w in r["wires"]], float),
                    padeyes=np.array([w["padeye_m"] for w in r["wires"]], float),
                    cog_depth=np.asarray(r["h_drop_m"] + j["z_p_m"], float))
    if "wire_segments" in r:
        k = np.full(4, series_stiffness((s["length_m"], s["ea_kN"]) for s in r["wire_segments"]))
    else:
        k = np.broadcast_to(np.asarray(r["wire_stiffness_kN_per_m"], float), (4,)).copy()
    limits = Limits(**r["limits"])
    space, fixed = {}, []
    for key, spec in r["design_space"].items():
        name = key.removesuffix("_m")
        if isinstance(spec, dict):
            space[name] = tuple(float(b) for b in spec["bounds"])
            if not spec.get("free", True):
                fixed.append(name)
        else:
            space[name] = tuple(float(b) for b in spec)
    return Rigging(layout=layout, jacket=jacket, wire_names=tuple(w["name"] for w in r["wires"]),
                   wire_stiffness=k, limits=limits, design_space=space,
                   g=cfg["g_m_per_s2"], zeta=r["damping_ratio"],
                   anchor_modes=tuple(r["damping_anchor_modes"]), fixed=tuple(fixed))


def plant_from_config(cfg, source="config", base_dir=None) -> plant_mod.Plant:
    """The baseline plant: from ``plant_matrices`` if given, else from the rigging.

    A slack wire, a layout out of balance in the six rigid-body equations or a
    statically unstable layout is an InputError.
    """
    if cfg.get("plant_matrices"):
        path = Path(cfg["plant_matrices"])
        if base_dir is not None and not path.is_absolute():
            path = Path(base_dir) / path
        return plant_mod.from_matrices(path, g=cfg["g_m_per_s2"], zeta=cfg["rigging"]["damping_ratio"])
    rig = rigging_from_config(cfg)
    p = plant_mod.build(rig.layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta,
                        anchor_modes=rig.anchor_modes)
    plant_mod.require_taut(p, rig.wire_names, source)
    plant_mod.require_balanced(p, source)
    try:
        modes_mod.require_stable(p.modes)
    except ValueError as exc:
        raise InputError(str(exc), file=source, field="rigging.wires") from None
    return p
