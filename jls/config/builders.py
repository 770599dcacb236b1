"""Settings objects and plants built from a validated configuration.

The one place where the configuration's mapping becomes the library's objects: the
rigging (:class:`jls.plant.candidates.Rigging`), the candidates' design values, the
baseline and candidate plants, the tugger settings and the time-domain settings. The
configuration arrives validated with every default filled in (:func:`jls.config.loader.load`),
so nothing here supplies a default of its own.
"""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import xarray as xr

from jls.assessment.operation import AlphaTable, classify
from jls.design.scoring import Envelope, Scoring
from jls.design.screening import WORKFLOW_KEYS
from jls.design.screening import Settings as ScreeningSettings
from jls.errors import InputError
from jls.names import TENSION_KEYS, TIP_AIR_GAP_M
from jls.plant import model as plant_mod
from jls.plant import modes as modes_mod
from jls.plant.candidates import SUFFIX, Rigging
from jls.plant.rigging import (
    DESIGN_VARIABLES,
    Budget,
    Layout,
    Limits,
    apply_design,
    design_variables,
    series_stiffness,
)
from jls.response.coverage import check_coverage
from jls.response.tip import TipSettings
from jls.tugger.setting import Tugger

if TYPE_CHECKING:
    from jls.timedomain.run import Settings


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
    lim = dict(r["limits"])
    lim.pop("tolerance_budget")
    limits = Limits(**lim, budget=budget_from_config(cfg))
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


def candidate_values(cfg: dict) -> dict[str, dict]:
    """Name -> design-variable values; 'baseline' (the configured layout) first."""
    out = {"baseline": {}}
    for c in cfg.get("candidates", []):
        out[c["name"]] = {k.removesuffix(SUFFIX): v for k, v in c.items() if k != "name"}
    grid = cfg.get("candidate_grid") or {}
    if grid:
        keys = list(grid)
        for combo in itertools.product(*(grid[k] for k in keys)):
            name = "_".join(f"{k.removesuffix(SUFFIX)}={v:g}" for k, v in zip(keys, combo))
            out[name] = {k.removesuffix(SUFFIX): v for k, v in zip(keys, combo)}
    return out


def boundary_candidates(cfg) -> list[str]:
    """The candidates whose boundary cells run in the time domain whatever the results
    (``timedomain.boundary_candidates``): the list given, or with ``assessed`` every
    assessed candidate but a ``candidate_grid``'s (the baseline, the listed candidates, the
    screening's ``optimised``); of a grid, :func:`grid_boundary_count` of them join when
    the frequency-domain results rank them (:func:`jls.stages.timedomain_cell.route_cells`)."""
    given = cfg["timedomain"]["boundary_candidates"]
    if given != "assessed":
        return list(given)
    named = ["baseline"] + [c["name"] for c in cfg.get("candidates", [])]
    return named + (["optimised"] if cfg["screening"]["enabled"] else [])


def grid_boundary_count(cfg) -> int:
    """How many of a ``candidate_grid``'s candidates send their boundary cells to the time
    domain (the best by frequency-domain route workability): with ``boundary_candidates:
    assessed``, ``timedomain.grid_boundary_candidates`` or the grid's size if smaller;
    otherwise (a list given, or no grid) none."""
    grid = cfg.get("candidate_grid") or {}
    if cfg["timedomain"]["boundary_candidates"] != "assessed" or not grid:
        return 0
    size = len(candidate_values(cfg)) - 1 - len(cfg.get("candidates", []))
    return min(int(cfg["timedomain"]["grid_boundary_candidates"]), size)


def margin_families(cfg, optimised: dict | None = None) -> dict[str, dict]:
    """The rigging families of the margin trade-off (:func:`jls.design.margins.margin_sweep`):
    the baseline, the listed candidates (not a ``candidate_grid``) and the screening's
    optimum, each with every design variable's value."""
    base = {k: float(v) for k, v in design_variables(rigging_from_config(cfg).layout).items()}
    named = {"baseline": {}, **{c["name"]: {k.removesuffix(SUFFIX): v for k, v in c.items() if k != "name"}
                                for c in cfg.get("candidates", [])}}
    if optimised is not None:
        named["optimised"] = optimised
    return {n: {**base, **{k: float(x) for k, x in v.items()}} for n, v in named.items()}


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


def candidate_plant(cfg, name: str, source="config", field="timedomain.boundary_candidates"):
    """The geometric plant (:func:`jls.plant.model.build`) of one configured rigging
    candidate; ``field`` names the key an unknown name came from."""
    if cfg.get("plant_matrices"):
        raise InputError("the time-domain model needs the wire geometry; a plant given as "
                         "matrices has none", file=source, field="plant_matrices")
    values = candidate_values(cfg)
    if name not in values:
        raise InputError(f"no such rigging candidate (configured: {', '.join(values)})",
                         file=source, field=field, value=name)
    return _geometric_plant(cfg, values[name], source)


def assessed_candidate_plant(cfg, plant_ds: xr.Dataset, name: str, source="config"):
    """The geometric plant of a candidate of the assessed plant dataset
    (``plant_assessed.nc``) from its design variables stored there: how the screening's
    ``optimised``, which no configuration lists, is rebuilt."""
    if name not in [str(c) for c in plant_ds["candidate"].values]:
        raise InputError(f"no such rigging candidate in the assessed plant (assessed: "
                         f"{', '.join(map(str, plant_ds['candidate'].values))})", file=source,
                         field="candidate", value=name)
    row = plant_ds.sel(candidate=name)
    return _geometric_plant(cfg, {v: float(row[v]) for v in DESIGN_VARIABLES}, source)


def _geometric_plant(cfg, values: dict, source):
    rig = rigging_from_config(cfg)
    layout = apply_design(rig.layout, rig.jacket.z_p, **{k.removesuffix(SUFFIX): float(v)
                                                         for k, v in values.items()})
    p = plant_mod.build(layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta,
                        anchor_modes=rig.anchor_modes)
    plant_mod.require_taut(p, rig.wire_names, source)
    modes_mod.require_stable(p.modes)
    return p


def tuggers_from_config(cfg, source="config") -> dict[str, Tugger]:
    """The configured tugger settings by name (keys of the ``tuggers`` items)."""
    out = {}
    for i, item in enumerate(cfg["tuggers"]):
        t = Tugger(name=item["name"], c=float(item["c_kN_s_per_m"]),
                   max_force=float(item["max_force_kN"]), min_force=float(item["min_force_kN"]),
                   lag=float(item["lag_s"]), half_width=float(item["attachment_half_width_m"]))
        if not t.max_force > t.min_force:
            raise InputError(f"winch capacity {t.max_force:g} kN must exceed the floor "
                             f"{t.min_force:g} kN", file=source, field=f"tuggers[{i}].max_force_kN",
                             value=t.max_force)
        out[t.name] = t
    return out


def settings_from_config(cfg) -> Settings:
    # the time-domain model is imported where it is used: it brings numba (0.15 s), which
    # the jobs that only read the configuration do not need
    from jls.timedomain.run import Settings
    td = cfg["timedomain"]
    return Settings(dt=float(td["dt_s"]), transient_time_constants=float(td["transient_time_constants"]),
                    transient_s=td.get("transient_s"), repeat=td["repeat"],
                    n_components=td.get("n_components"), seed=int(td["seed"]),
                    amplitudes=td["amplitudes"], min_line_length=float(td["min_line_length_m"]))


def verification_settings_from_config(cfg):
    """One verification cell's run settings (``verification`` block,
    :class:`jls.verify.settings.Settings`; imported here only, so that the stages that do
    not verify never load the reference's package)."""
    from jls.verify.settings import Settings as VerificationSettings
    v = cfg["verification"]
    return VerificationSettings(
        duration_s=float(v["duration_s"]), transient_time_constants=float(v["transient_time_constants"]),
        tolerance=float(v["tolerance"]), seed=int(v["seed"]), dt=float(v["dt_s"]),
        kinematics=str(v["kinematics"]),
        pitch_inertia_t_m2=float(v["pitch_inertia_t_m2"]) if "pitch_inertia_t_m2" in v else None,
        wire_mass_t_per_m=float(v["wire_mass_t_per_m"]), segments=int(v["segments"]),
        release_m=float(v["release_m"]), harmonic_periods_s=tuple(map(float, v["harmonic_periods_s"])),
        harmonic_amplitude_m=float(v["harmonic_amplitude_m"]), trace_s=float(v["trace_s"]),
        reference_start_time_constants=(None if v["reference_start_time_constants"] is None
                                        else float(v["reference_start_time_constants"])))


def verification_choice_from_config(cfg):
    """Which cells a route verifies (``verification`` block, :class:`jls.verify.settings.Choice`)."""
    from jls.verify.settings import Choice
    v = cfg["verification"]
    combos = tuple(c if isinstance(c, str) else (str(c["candidate"]), str(c["tugger"]))
                   for c in v["combinations"])
    corner = v["design_corner"]
    return Choice(enabled=bool(v["enabled"]), combinations=combos,
                  boundary_cells=int(v["boundary_cells"]),
                  design_corner=((float(corner["hs_m"]), float(corner["tz_s"]), float(corner["heading_deg"]))
                                 if corner["enabled"] else None),
                  max_cells=int(v["max_cells"]), stressed_cells=bool(v["stressed_cells"]))


def dataset_from_config(cfg, motion, hs, tz, heading_deg, tuggers=None, *, source="config",
                        base_dir=None, workers=1) -> xr.Dataset:
    """The per-cell time-domain dataset of a configuration: baseline plant, the named
    tugger settings (all configured ones when None), ``timedomain`` settings, the sea's
    gamma and the assessment's exposure as the recorded duration."""
    plant = plant_from_config(cfg, source=source, base_dir=base_dir)
    configured = tuggers_from_config(cfg, source)
    names = list(configured) if tuggers is None else list(tuggers)
    for n in names:
        if n not in configured:
            raise InputError(f"no such tugger setting (configured: {', '.join(configured)})",
                             file=source, field="tuggers", value=n)
    om = motion["omega"].values
    check_coverage(om.min(), om.max(), np.atleast_1d(tz), cfg["sea"]["gamma"],
                   cfg["vessel"].get("outside_rao_range"), source=source)
    from jls.timedomain.run import run_cells
    exposure_h = cfg["assessment"]["exposure_h"]
    return run_cells(plant, motion, [configured[n] for n in names], hs, tz, heading_deg,
                     gamma=cfg["sea"]["gamma"], duration_s=exposure_h * 3600.0,
                     settings=settings_from_config(cfg), workers=workers)


def scoring_from_config(cfg) -> Scoring:
    """What the screening's scores depend on besides the candidates. The screening ranks
    the rigging on the motion criteria: it computes no wire-tension statistics, so the
    tension criteria (``max_wire_tension_kN``, ``min_wire_tension_kN``, ``wire_tension``) are left to the
    assessment of the configured candidates and the optimum (a warning says so)."""
    a, s = cfg["assessment"], cfg["sea"]
    tuggers = {t["name"]: float(t["c_kN_s_per_m"]) for t in cfg["tuggers"]}
    # The screening's candidates are scored on the motion criteria (not the tensions nor the
    # tip clearance, judged on the assessed candidates in response.nc, the optimum included).
    motion = {k: v for k, v in a["criteria"].items() if k not in TENSION_KEYS and k != TIP_AIR_GAP_M}
    return Scoring(tuggers=tuggers, criteria=motion,
                   envelope=Envelope(**cfg["screening"]["envelope"]), gamma=s["gamma"],
                   exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                   omega_step=cfg["response"]["omega_step_rad_s"],
                   outside_policy=cfg["vessel"].get("outside_rao_range"),
                   hs_in_bin=s["hs_in_bin"], steepness_rule=s["steepness_rule"])


def budget_from_config(cfg) -> Budget:
    """The safety constraints' tolerance budget (``rigging.limits.tolerance_budget``)."""
    budget = cfg["rigging"]["limits"]["tolerance_budget"]
    return Budget(**{k: tuple((str(n), float(v)) for n, v in comps.items())
                     for k, comps in budget.items()})


def tip_settings_from_config(cfg) -> TipSettings | None:
    """The tip-clearance settings the response needs (:class:`jls.response.tip.TipSettings`),
    or None when the criterion ``tip_air_gap_m`` is off (null)."""
    if cfg["assessment"]["criteria"][TIP_AIR_GAP_M] is None:
        return None
    tc, lim = cfg["assessment"]["tip_clearance"], cfg["rigging"]["limits"]
    offsets = tc["tip_offsets_m"] if "tip_offsets_m" in tc else None
    return TipSettings(crest=tc["crest"], hinge_height_m=float(lim["hinge_height_m"]),
                       padeye_to_tip_m=float(lim["padeye_to_tip_m"]),
                       tip_offsets_m=None if offsets is None else tuple(tuple(map(float, p)) for p in offsets),
                       height_allowance_m=float(budget_from_config(cfg).splash))


def screening_settings_from_config(cfg) -> ScreeningSettings:
    """The ``screening`` section's settings (grid points keyed without the ``_m`` suffix)."""
    s = {k: v for k, v in cfg["screening"].items() if k not in WORKFLOW_KEYS}
    s["grid_points"] = design_grid_points(s["grid_points"])
    s.setdefault("tugger", None)       # optional key: the first tugger setting
    return ScreeningSettings(**s)


def design_grid_points(grid_points: dict) -> dict[str, int]:
    """``screening.grid_points`` keyed by design variable (without the ``_m`` suffix)."""
    return {k.removesuffix(SUFFIX): int(v) for k, v in grid_points.items()}


def recommendation_rules(section: dict) -> dict:
    """The ``recommendation`` section as the workability dataset's attributes, in fractions
    of the route (:mod:`jls.assessment.recommendation` reads them from there)."""
    return {"recommendation_objective": str(section["objective"]),
            "tugger_min_gain": float(section["tugger_min_gain_pp"]) / 100.0,
            "tie_tolerance": float(section["tie_tolerance_pp"]) / 100.0}


def operation_basis(section: dict, route_duration_h: float):
    """The operational basis (:func:`jls.assessment.operation.classify`) and the alpha
    table (None when not configured) of ``operation``; the planned period defaults to the
    route's duration."""
    planned = float(section.get("planned_period_h", route_duration_h))
    contingency = section.get("contingency_h")
    basis = classify(planned, None if contingency is None else float(contingency))
    table = section.get("alpha_factors")
    alpha = None if table is None else AlphaTable(
        source=table["source"], period_h=table["planned_period_h"], hs_m=table["hs_m"],
        alpha=table["alpha"])
    return basis, alpha
