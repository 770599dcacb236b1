"""Verification cells of a route: which combinations and sea states the pipeline checks
against the 6-DOF nonlinear reference (``results/<route>/verification/cells.json``), and
the dataset of one cell (``results/<route>/verification/<cell>.nc``, layout
``verification_cell`` of the registry).

A cell is (rigging candidate, tugger setting, relative heading, Hs, Tz), named
``candidate__tugger__h<heading>__hs<Hs>__tz<Tz>`` (:func:`jls.verify.cell.cell_name`).
Cells are chosen (:func:`choose_cells`) per verified combination
(``verification.combinations``): ``recommendation`` is the report's recommendation
(:func:`jls.stages.weather_windows.assessed_option`), ``baseline`` the baseline
rigging without tugger (the setting of the smallest slope), or a given (candidate,
tugger). For each, the ``verification.boundary_cells`` live cells of the route
(non-zero probability on some leg) whose relative-sway utilisation with that tugger
setting is nearest 1 (smallest |ln u|), with ``verification.stressed_cells`` the cells
where the model is stressed (:func:`stressed_cells`: the design corner, the workable cell
of the highest utilisation, and the largest workable sea state of the heaviest leg), and
the configured design sea state when enabled. A job's
parameters are its cell and the run settings every cell shares, so editing one cell
reruns that cell only.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.workability import assessed_hs
from jls.config.builders import (
    assessed_candidate_plant,
    candidate_plant,
    candidate_values,
    tuggers_from_config,
    verification_choice_from_config,
    verification_settings_from_config,
)
from jls.errors import InputError
from jls.names import SWAY_M
from jls.stages.weather_windows import assessed_option
from jls.timedomain.cells import cell_seed
from jls.verify.names import DESIGN_CORNER, cell_name, wire_cells  # noqa: F401  (wire_cells: re-exported)
from jls.verify.settings import BASELINE, RECOMMENDATION

FIELD = "verification.combinations"


def combinations(work: xr.Dataset, plant: xr.Dataset, c_tugger: dict, wanted) -> list[tuple]:
    """(candidate, tugger, role) of each wanted combination, in order; ``role`` is
    "recommendation", "baseline" or "configured"."""
    cands = [str(c) for c in work["candidate"].values]
    tugs = [str(t) for t in work["tugger"].values]
    out = []
    for i, w in enumerate(wanted):
        if w == RECOMMENDATION:
            out.append((*assessed_option(work, plant, c_tugger), RECOMMENDATION))
        elif w == BASELINE:
            base = "baseline" if "baseline" in cands else cands[0]
            out.append((base, min(tugs, key=lambda t: (abs(c_tugger[t]), tugs.index(t))), BASELINE))
        else:
            cand, tug = w
            if cand not in cands or tug not in tugs:
                raise InputError(f"no such assessed combination (candidates {', '.join(cands)}; "
                                 f"tuggers {', '.join(tugs)})", field=f"{FIELD}[{i}]",
                                 value=f"{cand}, {tug}")
            out.append((cand, tug, "configured"))
    return out


def boundary_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, candidate, tugger,
                   n) -> list[dict]:
    """The ``n`` live cells of the route whose relative-sway utilisation with
    (candidate, tugger) is nearest 1, each once (the leg where it is nearest)."""
    if n <= 0 or SWAY_M not in work["criterion"].values:
        return []
    u = work["utilisation"].sel(candidate=candidate, tugger=tugger, criterion=SWAY_M, drop=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        dist = np.abs(np.log(u)).where(sea["cell_probability"] > 0)
    rows = {}
    for leg in (str(v) for v in work["leg"].values):
        d = dist.sel(leg=leg).transpose("heading", "hs", "tz")
        dv, heading, tz = d.values, d["heading"].values, d["tz"].values
        hs_leg = hs.sel(leg=leg).values
        u_leg = u.sel(leg=leg).transpose("heading", "hs", "tz").values
        for ih, ihs, itz in zip(*np.nonzero(np.isfinite(dv))):
            cell = (float(heading[ih]), float(hs_leg[ihs]), float(tz[itz]))
            value = float(dv[ih, ihs, itz])
            if cell not in rows or value < rows[cell][0]:
                rows[cell] = (value, leg, float(u_leg[ih, ihs, itz]))
    ranked = sorted(rows.items(), key=lambda kv: (kv[1][0], kv[0]))[:n]
    return [{"heading": c[0], "hs": c[1], "tz": c[2],
             "reason": f"nearest the workability boundary (relative-sway utilisation {r[2]:.3f}, leg {r[1]})"}
            for c, r in ranked]


def _live(work, sea, candidate, tugger):
    """Per cell of (candidate, tugger): the utilisation over the criteria (max), whether
    it passes, and the cell's probability, as (leg, heading, hs, tz) arrays."""
    u = work["utilisation"].sel(candidate=candidate, tugger=tugger, drop=True).max("criterion")
    ok = work["passes"].sel(candidate=candidate, tugger=tugger, drop=True) > 0
    prob = sea["cell_probability"]
    dims = ("leg", "heading", "hs", "tz")
    return (u.transpose(*dims).values, ok.transpose(*dims).values,
            prob.transpose(*dims).values)


def stressed_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, candidate, tugger) -> list[dict]:
    """The cells where the model of (candidate, tugger) is stressed: its design corner, the
    live workable cell (every criterion holds, non-zero probability) of the highest
    utilisation over the criteria; and the largest sea state inside the limits on the
    heaviest leg (the leg of the highest probability-weighted mean Hs; its live workable
    cell of the largest Hs, the highest utilisation among equal Hs). None when no live
    cell is workable or the workability has no ``passes``."""
    if "passes" not in work:
        return []
    u, ok, prob = _live(work, sea, candidate, tugger)
    legs = [str(v) for v in work["leg"].values]
    heading, tz = work["heading"].values, work["tz"].values
    hs_leg = np.stack([hs.sel(leg=leg).values for leg in legs])          # (leg, hs)
    good = ok & (prob > 0) & np.isfinite(u)
    out = []
    if good.any():
        k = np.unravel_index(np.argmax(np.where(good, u, -np.inf)), u.shape)
        out.append({"heading": float(heading[k[1]]), "hs": float(hs_leg[k[0], k[2]]),
                    "tz": float(tz[k[3]]),
                    "reason": f"{DESIGN_CORNER} ({u[k]:.3f}, leg {legs[k[0]]})"})
    w = prob.sum(axis=(1, 2, 3))
    mean_hs = np.array([(prob[i].sum(axis=(0, 2)) * hs_leg[i]).sum() / w[i] if w[i] > 0 else -np.inf
                        for i in range(len(legs))])
    i = int(np.argmax(mean_hs))
    if good[i].any():
        big = np.where(good[i], hs_leg[i][None, :, None], -np.inf)
        top = big.max()
        score = np.where(big == top, u[i], -np.inf)
        k = np.unravel_index(np.argmax(score), score.shape)
        out.append({"heading": float(heading[k[0]]), "hs": float(hs_leg[i, k[1]]), "tz": float(tz[k[2]]),
                    "reason": f"the largest sea state inside the limits on the heaviest leg ({legs[i]}, "
                              f"mean Hs {mean_hs[i]:.2f} m; utilisation {u[i][k]:.3f})"})
    return out


def refused_legs(models: dict) -> str:
    """The attribute ``verification_refused_legs`` of the workability: the legs whose sea is
    their own (``models``: leg name -> spectrum partitions, measured or torsethaugen) and
    why they have no verification cell; empty when none."""
    if not models:
        return ""
    names = ", ".join(f"{leg} ({m})" for leg, m in models.items())
    return (f"{names}: the 6-DOF reference and the ROM are compared on a long-crested JONSWAP record of "
            "a cell's (Hs, Tz), which is not the sea of these legs, so their cells are left out of the "
            "verification rather than verified on a JONSWAP")


def choose_cells(work: xr.Dataset, sea: xr.Dataset, plant: xr.Dataset, c_tugger: dict,
                 cfg, refused=()) -> list[dict]:
    """Every verification cell of the route (module docstring), named and deduplicated in
    a stable order; each carries its roles (which verified combinations it belongs to)
    and the reasons it was chosen. Nothing when ``verification.enabled`` is false.
    ``refused``: the names of the legs whose sea is their own (partitions, measured
    spectra, Torsethaugen): the reference runs a long-crested JONSWAP, so their cells are
    not chosen (:func:`refused_legs` says why); a route of such legs only has only the
    configured design corner, if any."""
    choice = verification_choice_from_config(cfg)
    if not choice.enabled:
        return []
    keep = [leg for leg in (str(v) for v in work["leg"].values) if leg not in set(map(str, refused))]
    hs = assessed_hs(sea, cfg["sea"]["hs_in_bin"])
    headings = [float(h) for h in work["heading"].values]
    out: dict = {}
    # the combinations from the whole route (its recommendation); the cells from the legs kept
    kw, ks, kh = work.sel(leg=keep), sea.sel(leg=keep), hs.sel(leg=keep)
    for cand, tug, role in combinations(work, plant, c_tugger, choice.combinations):
        chosen = boundary_cells(kw, ks, kh, cand, tug, choice.boundary_cells) if keep else []
        if choice.stressed_cells and keep:
            chosen += stressed_cells(kw, ks, kh, cand, tug)
        if choice.design_corner is not None:
            c_hs, c_tz, c_h = choice.design_corner
            if c_h not in headings:
                raise InputError(f"the design corner's heading is not a heading of the route "
                                 f"({', '.join(f'{h:g}' for h in headings)})",
                                 field="verification.design_corner.heading_deg", value=c_h)
            chosen.append({"heading": c_h, "hs": c_hs, "tz": c_tz, "reason": "design corner"})
        for c in chosen:
            name = cell_name(cand, tug, c["heading"], c["hs"], c["tz"])
            entry = out.setdefault(name, {"name": name, "candidate": cand, "tugger": tug,
                                          "heading": c["heading"], "hs": c["hs"], "tz": c["tz"],
                                          "roles": [], "reasons": []})
            if role not in entry["roles"]:
                entry["roles"].append(role)
            if c["reason"] not in entry["reasons"]:
                entry["reasons"].append(c["reason"])
    if len(out) > choice.max_cells:
        raise InputError(f"{len(out)} verification cells chosen, more than verification.max_cells "
                         f"({choice.max_cells}); raise it or verify fewer combinations or cells",
                         field="verification.max_cells", value=len(out))
    return list(out.values())


def cell_plant(cfg, name: str, plant_ds: xr.Dataset | None = None, source="config"):
    """The geometric plant of a cell's candidate: a configured candidate from the
    configuration, any other (the screening's ``optimised``) from its design variables
    in the assessed plant ``plant_ds``."""
    if name in candidate_values(cfg) or plant_ds is None:
        return candidate_plant(cfg, name, source, field="verification (cell candidate)")
    return assessed_candidate_plant(cfg, plant_ds, name, source)


def cell_dataset(cfg, motion: xr.Dataset, cell: dict, plant_ds: xr.Dataset | None = None,
                 source="config") -> xr.Dataset:
    """The verification of one cell (:func:`jls.verify.cell.verify_cell`) with the
    configured run settings, the cell's tugger setting (both models carry it) and a
    wave record seeded by the configured seed and the cell's candidate and sea state;
    where MoorDyn cannot be imported, the dataset that says so
    (:func:`jls.verify.cell.unavailable_cell`)."""
    # the models are imported here: choosing the cells (:func:`choose_cells`) does not need
    # MoorDyn, scipy or numba, which cost a job 0.3 s to import
    from jls.response.coverage import check_coverage
    from jls.verify.cell import unavailable_cell, verify_cell
    from jls.verify.chapter4 import transient_s
    from jls.verify.moordyn_model import available
    s = verification_settings_from_config(cfg)
    tuggers = tuggers_from_config(cfg, source)
    if cell["tugger"] not in tuggers:
        raise InputError(f"no such tugger setting (configured: {', '.join(tuggers)})",
                         file=source, field="verification (cell tugger)", value=cell["tugger"])
    tug = tuggers[cell["tugger"]]
    seed = cell_seed(s.seed, cell)
    ok, why = available()
    if not ok:
        return unavailable_cell(why, candidate=cell["candidate"], tugger=cell["tugger"],
                                hs=cell["hs"], tz=cell["tz"], heading_deg=cell["heading"],
                                duration_s=s.duration_s, dt=s.dt, seed=seed,
                                kinematics=s.kinematics, tolerance=s.tolerance)
    if float(cell["heading"]) not in [float(h) for h in motion["heading"].values]:
        raise InputError("the cell's heading is not in the vessel motion",
                         field="verification (cell heading)", value=cell["heading"])
    om = motion["omega"].values
    check_coverage(om.min(), om.max(), [cell["tz"]], cfg["sea"]["gamma"],
                   cfg["vessel"].get("outside_rao_range"), source=source)
    plant = cell_plant(cfg, cell["candidate"], plant_ds, source)
    v = cfg["vessel"]
    return verify_cell(
        plant, motion, cell["hs"], cell["tz"], cell["heading"], candidate=cell["candidate"],
        tugger=tug if tug.active else None, tugger_name=tug.name, gamma=cfg["sea"]["gamma"],
        duration_s=s.duration_s, seed=seed, dt=s.dt, kinematics=s.kinematics,
        exposure_s=cfg["assessment"]["exposure_h"] * 3600.0, release_m=s.release_m,
        harmonic_periods_s=s.harmonic_periods_s, harmonic_amplitudes_m=(s.harmonic_amplitude_m,),
        pitch_inertia_t_m2=s.pitch_inertia_t_m2, wire_mass_t_per_m=s.wire_mass_t_per_m,
        segments=s.segments,
        fairlead_offset_m=(0.0, float(v["fairlead_half_span_m"]), -float(v["fairlead_drop_m"])),
        hinge_height_m=float(cfg["rigging"]["limits"]["hinge_height_m"]), trace_s=s.trace_s,
        transient=transient_s(plant, s.transient_time_constants, tug.c), tolerance=s.tolerance,
        reference_start=(None if s.reference_start_time_constants is None
                         else transient_s(plant, s.reference_start_time_constants, tug.c)))


def study_dataset(cfg, motion: xr.Dataset, source="config") -> xr.Dataset:
    """The study comparison (:func:`jls.verify.study.study_comparison`) of the baseline
    rigging with the configured run settings; where MoorDyn cannot be imported, the
    study's table alone, the project's columns NaN and the reason in ``reason``."""
    from jls.verify import study
    from jls.verify.moordyn_model import available
    s = verification_settings_from_config(cfg)
    ok, why = available()
    if not ok:
        return study.unavailable(why, tolerance=s.tolerance)
    plant = candidate_plant(cfg, study.STUDY_CANDIDATE, source, field="verification.study_comparison")
    return study.study_comparison(
        plant, motion, gamma=cfg["sea"]["gamma"], duration_s=s.duration_s, dt=s.dt, seed=s.seed,
        kinematics=s.kinematics, exposure_s=cfg["assessment"]["exposure_h"] * 3600.0,
        tolerance=s.tolerance, transient_time_constants=s.transient_time_constants,
        reference_start_time_constants=s.reference_start_time_constants,
        pitch_inertia_t_m2=s.pitch_inertia_t_m2,
        hinge_height_m=float(cfg["rigging"]["limits"]["hinge_height_m"]))


def study_part_dataset(cfg, motion: xr.Dataset, part: str, source="config") -> xr.Dataset:
    """One part of the study comparison (:func:`jls.verify.study.study_part`) with the
    configured run settings, as :func:`study_dataset`; where MoorDyn cannot be imported,
    the part that says so (assembled into the study's table alone)."""
    from jls.verify import study
    from jls.verify.moordyn_model import available
    s = verification_settings_from_config(cfg)
    ok, why = available()
    if not ok:
        return study.unavailable_part(why, part)
    plant = candidate_plant(cfg, study.STUDY_CANDIDATE, source, field="verification.study_comparison")
    return study.study_part(
        plant, motion, part, gamma=cfg["sea"]["gamma"], duration_s=s.duration_s, dt=s.dt, seed=s.seed,
        kinematics=s.kinematics, exposure_s=cfg["assessment"]["exposure_h"] * 3600.0,
        tolerance=s.tolerance, transient_time_constants=s.transient_time_constants,
        reference_start_time_constants=s.reference_start_time_constants,
        pitch_inertia_t_m2=s.pitch_inertia_t_m2,
        hinge_height_m=float(cfg["rigging"]["limits"]["hinge_height_m"]))


def study_from_parts(cfg, parts) -> xr.Dataset:
    """The study comparison assembled from its parts (:func:`jls.verify.study.assemble`)."""
    from jls.verify import study
    return study.assemble(parts, tolerance=verification_settings_from_config(cfg).tolerance)


def wires_dataset(cfg, motion: xr.Dataset, cell: dict, plant_ds: xr.Dataset | None = None,
                  source="config") -> xr.Dataset:
    """The wire check of one cell (:func:`jls.verify.wires.wire_check`) with the
    configured ``verification.wires``, the cell's tugger and run settings; where MoorDyn
    cannot be imported, the dataset that says so (:func:`jls.verify.wires.unavailable`)."""
    from jls.verify.moordyn_model import available
    from jls.verify.wires import unavailable, wire_check
    ok, why = available()
    name = cell_name(cell["candidate"], cell["tugger"], cell["heading"], cell["hs"], cell["tz"])
    if not ok:
        return unavailable(why, name)
    s = verification_settings_from_config(cfg)
    w = cfg["verification"]["wires"]
    tug = tuggers_from_config(cfg, source)[cell["tugger"]]
    v = cfg["vessel"]
    return wire_check(
        cell_plant(cfg, cell["candidate"], plant_ds, source), motion, cell["hs"], cell["tz"], cell["heading"],
        segments=int(w["segments"]), wire_mass_t_per_m=float(w["wire_mass_t_per_m"]),
        axial_damping_ratio=float(w["axial_damping_ratio"]), duration_s=float(w["duration_s"]),
        transient_s=float(w["transient_s"]), tolerance=s.tolerance, dt=s.dt, seed=cell_seed(s.seed, cell),
        gamma=cfg["sea"]["gamma"], kinematics=s.kinematics,
        cell=name, tugger=tug if tug.active else None, pitch_inertia_t_m2=s.pitch_inertia_t_m2,
        fairlead_offset_m=(0.0, float(v["fairlead_half_span_m"]), -float(v["fairlead_drop_m"])),
        hinge_height_m=float(cfg["rigging"]["limits"]["hinge_height_m"]))


__all__ = ["refused_legs", "wire_cells", "wires_dataset", "study_dataset", "study_part_dataset", "study_from_parts", "combinations", "boundary_cells", "stressed_cells", "choose_cells", "cell_plant", "cell_dataset"]
