"""The study's own comparison beside the project's: table 4.4 of the study (the ROM
against the full nonlinear OrcaFlex model at its five validation sea states, beam seas)
next to the project's ROM against its 6-DOF reference at the same sea states with the
study's plant (the baseline rigging, no tugger), and the linear range measured by
stepping Hs at the study's stress case S1's Tz (:func:`jls.verify.chapter4.linear_range`).

The dataset (``verification_study.nc``, layout ``verification_study`` of the registry):
dimension ``sea_state`` (V1, V2, V3, V4, S1) with ``hs`` and ``tz``; the study's
``study_sigma_rom``, ``study_sigma_full`` and ``study_error`` (its table 4.4, published
numbers: relative-sway RMS of its ROM and of OrcaFlex at equal component counts, and the
ROM's error); the project's ``sigma_rom``, ``sigma_reference``, ``sigma_ratio``,
``mpm_ratio``, ``slack_fraction`` on one record per sea state; dimension ``step`` of the
linear-range sweep (``step_hs``, ``step_mpm_ratio``, ``step_mpm_reference``) and its
attributes ``linear_range_tz_s``, ``linear_range_hs_inside_m``,
``linear_range_hs_leaves_m``, ``linear_range_mpm_inside_m``.

What the reference can and cannot see (:data:`SEES`): it shares with the ROM the mass,
stiffness, damping (as dashpots of the ROM's modal ratios) and the prescribed hinge
motion; it adds the geometric nonlinearity of the wires, surge and pitch, and (with
segments) the wires' own dynamics; it lacks the damping that grows with amplitude
(aerodynamic drag), the block connection system and any feedback of the jacket on the
vessel. The study's +16.8 % and +33.4 % at V4 and S1 come partly from what it lacks.
"""

from __future__ import annotations

import time

import numpy as np
import xarray as xr

from jls.io import registry
from jls.verify import chapter4, model
from jls.verify.names import STUDY_PARTS

LAYOUT = "verification_study"
PART_LAYOUT = "verification_study_part"
#: what each record of a part holds (the ROM's and the reference's relative-sway sigma,
#: their ratios, the reference's MPM and its slack time)
PART_VARIABLES = ("sigma_rom", "sigma_reference", "sigma_ratio", "mpm_ratio", "mpm_reference", "slack_fraction")
#: the study's table 4.4: name, Hs [m], Tz [s], ROM RMS [m], OrcaFlex RMS [m], error [%]
TABLE_4_4 = (("V1", 2.40, 4.30, 0.037, 0.039, -5.4), ("V2", 2.40, 6.60, 0.635, 0.663, -4.2),
             ("V3", 2.50, 7.50, 1.460, 1.472, -0.9), ("V4", 2.40, 8.50, 3.560, 3.047, 16.8),
             ("S1", 2.70, 9.00, 7.178, 5.383, 33.4))
HEADING_DEG = 90.0
STUDY_CANDIDATE = "baseline"
LINEAR_RANGE_SEA_STATE = "S1"
SEES = {"shares": "its mass, stiffness and damping (dashpots giving each mode the ROM's ratio) "
                  "and the prescribed hinge motion",
        "adds": "the wires' geometric nonlinearity, surge and pitch, and with segments the wires' "
                "own mass and axial dynamics",
        "lacks": "damping that grows with the amplitude (aerodynamic drag), the block connection "
                 "system and any feedback of the jacket on the vessel"}


def study_comparison(plant, motion, *, gamma=3.3, duration_s=1200.0, dt=0.1, seed=1,
                     kinematics="rigid", exposure_s=3 * 3600.0, tolerance=0.10, hs_step=0.5,
                     transient_time_constants=5.0, reference_start_time_constants=None,
                     **reference) -> xr.Dataset:
    """The study comparison dataset (module docstring) for ``plant`` (the study's: the
    baseline rigging) on ``motion`` (holding the 90-degree heading); ``reference``: the
    keywords of :func:`jls.verify.model.build_reference` (pitch inertia, wires, hinge);
    ``reference_start_time_constants``: the reference starts this many ROM sway time
    constants before the statistics, in the ROM's state (None: from rest with the ROM;
    :func:`jls.verify.chapter4.irregular_sea`).
    Its parts (:data:`jls.verify.names.STUDY_PARTS`) run here one after the other; the
    workflow runs each as a job (:func:`study_part`) and assembles them (:func:`assemble`)."""
    ref = model.build_reference(plant, vessel_lever_m=motion.attrs["hinge_m"], **reference)
    run = dict(gamma=gamma, duration_s=duration_s, dt=dt, seed=seed, kinematics=kinematics,
               exposure_s=exposure_s, tolerance=tolerance, hs_step=hs_step,
               transient_time_constants=transient_time_constants,
               reference_start_time_constants=reference_start_time_constants)
    return assemble([_part(ref, plant, motion, part, **run) for part in STUDY_PARTS], tolerance=tolerance)


def study_part(plant, motion, part, *, gamma=3.3, duration_s=1200.0, dt=0.1, seed=1,
               kinematics="rigid", exposure_s=3 * 3600.0, tolerance=0.10, hs_step=0.5,
               transient_time_constants=5.0, reference_start_time_constants=None,
               **reference) -> xr.Dataset:
    """One part of the study comparison (``part`` of :data:`jls.verify.names.STUDY_PARTS`):
    its records, each both models on one sea state (layout ``verification_study_part``);
    keywords as :func:`study_comparison`. A linear-range part steps Hs through its share of
    the steps and stops at the first outside ``tolerance``, as the whole range would."""
    if part not in STUDY_PARTS:
        raise ValueError(f"no study part {part!r} (parts: {', '.join(STUDY_PARTS)})")
    ref = model.build_reference(plant, vessel_lever_m=motion.attrs["hinge_m"], **reference)
    return _part(ref, plant, motion, part, gamma=gamma, duration_s=duration_s, dt=dt, seed=seed,
                 kinematics=kinematics, exposure_s=exposure_s, tolerance=tolerance, hs_step=hs_step,
                 transient_time_constants=transient_time_constants,
                 reference_start_time_constants=reference_start_time_constants)


def _part(ref, plant, motion, part, *, gamma, duration_s, dt, seed, kinematics, exposure_s, tolerance,
          hs_step, transient_time_constants, reference_start_time_constants) -> xr.Dataset:
    wall0 = time.perf_counter()
    from jls.verify.cell import rk4_step
    dt = rk4_step(dt, ref, plant)
    tr = chapter4.transient_s(plant, transient_time_constants)
    settle = (None if reference_start_time_constants is None
              else min(tr, chapter4.transient_s(plant, reference_start_time_constants)))
    names = [r[0] for r in TABLE_4_4]
    if part.startswith("table"):
        records = [(name, *TABLE_4_4[names.index(name)][1:3]) for name in STUDY_PARTS[part]]
        stop = False
    else:
        s1 = TABLE_4_4[names.index(LINEAR_RANGE_SEA_STATE)]
        lo, hi = STUDY_PARTS[part]
        steps = chapter4.range_steps(hs_step, hs_step, 2 * s1[1])
        records = [(f"step{lo + k + 1}", hs, s1[2]) for k, hs in enumerate(steps[lo:hi])]
        stop = True
    rows = []
    for _, hs, tz in records:
        # the ROM's frequency-domain sigma is not part of the comparison: not computed
        o = chapter4.irregular_sea(ref, plant, motion, hs, tz, HEADING_DEG, gamma=gamma, duration_s=duration_s,
                                   transient=tr, dt=dt, seed=seed, kinematics=kinematics,
                                   exposure_s=exposure_s, frequency_domain=False, settle=settle)
        rows.append((o["rom"]["sigma"], o["reference"]["sigma"], o["sigma_ratio_rom_to_reference"],
                     o["mpm_ratio_rom_to_reference"], o["reference"]["mpm"], o["slack_fraction"]))
        if stop and abs(rows[-1][3] - 1) > tolerance:
            break
    records = records[:len(rows)]
    rows = np.array(rows, float).reshape(-1, len(PART_VARIABLES))
    ds = xr.Dataset(coords={"record": [r[0] for r in records], "hs": ("record", [float(r[1]) for r in records]),
                            "tz": ("record", [float(r[2]) for r in records])})
    for k, name in enumerate(PART_VARIABLES):
        ds[name] = ("record", rows[:, k])
    ds["wall_time"] = ((), time.perf_counter() - wall0)
    registry.annotate(ds, PART_LAYOUT)
    ds.attrs.update(part=str(part), heading_deg=HEADING_DEG, gamma=float(gamma), duration_s=float(duration_s),
                    transient_s=float(tr), dt_s=float(dt), seed=int(seed), kinematics=str(kinematics),
                    tolerance=float(tolerance),
                    reference_start_s=float("nan") if settle is None else float(settle))
    return ds


def unavailable_part(reason: str, part: str) -> xr.Dataset:
    """A part that could not run (MoorDyn cannot be imported): no records, the reason in
    ``reason``."""
    ds = xr.Dataset(coords={"record": np.array([], str), "hs": ("record", np.zeros(0)),
                            "tz": ("record", np.zeros(0))})
    for name in PART_VARIABLES:
        ds[name] = ("record", np.zeros(0))
    ds["wall_time"] = ((), 0.0)
    registry.annotate(ds, PART_LAYOUT)
    ds.attrs.update(part=str(part), heading_deg=HEADING_DEG, gamma=float("nan"), duration_s=0.0,
                    transient_s=float("nan"), dt_s=0.0, seed=0, kinematics="", tolerance=float("nan"),
                    reason=str(reason))
    return ds


def assemble(parts, *, tolerance) -> xr.Dataset:
    """The study comparison dataset from its parts (:func:`study_part`, every part of
    :data:`jls.verify.names.STUDY_PARTS` once, in any order): the table's sea states in
    the study's order, the linear range's steps up to the first outside ``tolerance``
    (a later part's steps after it are dropped, so the answer is the sequential one);
    ``wall_time`` is the parts' summed. A part that could not run gives the study's
    table alone (:func:`unavailable`) with its reason."""
    by = {str(p.attrs["part"]): p for p in parts}
    if sorted(by) != sorted(STUDY_PARTS) or len(by) != len(parts):
        raise ValueError(f"the study comparison needs each of its parts once ({', '.join(STUDY_PARTS)}); "
                         f"given {', '.join(str(p.attrs['part']) for p in parts)}")
    why = next((str(p.attrs["reason"]) for p in parts if "reason" in p.attrs), None)
    if why is not None:
        return unavailable(why, tolerance=tolerance)
    names = [r[0] for r in TABLE_4_4]
    table = {}
    for k in (k for k in STUDY_PARTS if k.startswith("table")):
        for i, name in enumerate(by[k]["record"].values):
            table[str(name)] = [float(by[k][v].values[i]) for v in PART_VARIABLES]
    if sorted(table) != sorted(names):
        raise ValueError(f"the study's table parts hold {', '.join(sorted(table))}, not {', '.join(names)}")
    rows = np.array([table[n] for n in names])
    hs_list, sig, mpm, mref = [], [], [], []
    for k in (k for k in STUDY_PARTS if not k.startswith("table")):
        p = by[k]
        for i in range(p.sizes["record"]):
            if mpm and abs(mpm[-1] - 1) > tolerance:
                break
            hs_list.append(float(p["hs"].values[i]))
            sig.append(float(p["sigma_ratio"].values[i]))
            mpm.append(float(p["mpm_ratio"].values[i]))
            mref.append(float(p["mpm_reference"].values[i]))
    lr = chapter4.range_summary(hs_list, sig, mpm, mref, tolerance)
    first = by[next(iter(STUDY_PARTS))].attrs
    s1 = TABLE_4_4[names.index(LINEAR_RANGE_SEA_STATE)]
    t = np.array([r[1:] for r in TABLE_4_4], float)
    ds = xr.Dataset(coords={"sea_state": names, "hs": ("sea_state", t[:, 0]), "tz": ("sea_state", t[:, 1]),
                            "step": np.arange(1, lr["hs"].size + 1)})
    ds["study_sigma_rom"] = ("sea_state", t[:, 2])
    ds["study_sigma_full"] = ("sea_state", t[:, 3])
    ds["study_error"] = ("sea_state", t[:, 4] / 100.0)
    for k, name in enumerate(PART_VARIABLES):
        if name != "mpm_reference":
            ds[name] = ("sea_state", rows[:, k])
    ds["step_hs"] = ("step", lr["hs"])
    ds["step_mpm_ratio"] = ("step", lr["mpm_ratio"])
    ds["step_mpm_reference"] = ("step", lr["mpm_reference"])
    ds["wall_time"] = ((), float(sum(float(p["wall_time"]) for p in parts)))
    registry.annotate(ds, LAYOUT)
    ds.attrs.update(candidate=STUDY_CANDIDATE, tugger="none", heading_deg=HEADING_DEG, gamma=float(first["gamma"]),
                    duration_s=float(first["duration_s"]), transient_s=float(first["transient_s"]),
                    dt_s=float(first["dt_s"]), seed=int(first["seed"]), kinematics=str(first["kinematics"]),
                    reference_start_s=float(first.get("reference_start_s", float("nan"))),
                    tolerance=float(tolerance), linear_range_tz_s=float(s1[2]),
                    linear_range_hs_inside_m=lr["hs_inside"], linear_range_hs_leaves_m=lr["hs_leaves"],
                    linear_range_mpm_inside_m=lr["mpm_reference_inside"],
                    source="the study's table 4.4 (ROM against OrcaFlex, equal component counts)")
    return ds


def unavailable(reason: str, *, tolerance) -> xr.Dataset:
    """The study's table alone, the project's columns NaN (MoorDyn cannot be imported)."""
    t = np.array([r[1:] for r in TABLE_4_4], float)
    ds = xr.Dataset(coords={"sea_state": [r[0] for r in TABLE_4_4], "hs": ("sea_state", t[:, 0]),
                            "tz": ("sea_state", t[:, 1]), "step": np.arange(1, 1)})
    ds["study_sigma_rom"], ds["study_sigma_full"] = ("sea_state", t[:, 2]), ("sea_state", t[:, 3])
    ds["study_error"] = ("sea_state", t[:, 4] / 100.0)
    for name in ("sigma_rom", "sigma_reference", "sigma_ratio", "mpm_ratio", "slack_fraction"):
        ds[name] = ("sea_state", np.full(len(TABLE_4_4), np.nan))
    for name in ("step_hs", "step_mpm_ratio", "step_mpm_reference"):
        ds[name] = ("step", np.zeros(0))
    ds["wall_time"] = ((), 0.0)
    registry.annotate(ds, LAYOUT)
    ds.attrs.update(candidate=STUDY_CANDIDATE, tugger="none", heading_deg=HEADING_DEG, duration_s=0.0,
                    dt_s=0.0, seed=0, tolerance=float(tolerance), linear_range_tz_s=float("nan"),
                    linear_range_hs_inside_m=float("nan"), linear_range_hs_leaves_m=float("nan"),
                    linear_range_mpm_inside_m=float("nan"), reason=str(reason),
                    source="the study's table 4.4 (ROM against OrcaFlex, equal component counts)")
    return ds


__all__ = ["unavailable", "unavailable_part", "study_part", "assemble", "PART_LAYOUT", "PART_VARIABLES",
           "STUDY_PARTS", "study_comparison", "TABLE_4_4", "SEES", "LAYOUT", "STUDY_CANDIDATE"]
