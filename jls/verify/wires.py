"""The wires as wires: the one-segment reference (the fast default of every cell) against a
reference whose hoist wires are lines of several segments with their own mass and axial
damping, on the same vessel record of one cell.

With one segment a wire has no node of its own: a massless spring that pulls only. With
``segments`` (at least 4) its inner nodes are free masses (``wire_mass_t_per_m``) joined
by segments with MoorDyn's axial damping (a negative BA: minus the damping ratio of a
segment's axial vibration, ``axial_damping_ratio``), so the wire's own dynamics (its
axial and transverse modes, the weight it carries) enter the jacket's motion. The check
(:func:`wire_check`) gives the static padeye tensions of the multi-segment reference held
still in MoorDyn against the ROM's, and on one record (``duration_s`` after
``transient_s``) the multi-segment reference's relative-sway sigma over the one-segment
reference's and their correlation: the one-segment reference stands as the fast default
where the two agree within the verification's tolerance. The dataset is
``verification/wires/<cell>.nc`` (layout ``verification_wires`` of the registry).
Units t, kN, m, s.
"""

from __future__ import annotations

import time

import numpy as np
import xarray as xr

from jls.io import registry
from jls.verify import excitation as exc_mod
from jls.verify import identify, model, rom, simulate

LAYOUT = "verification_wires"
#: the still-vessel time over which the multi-segment wires settle before their
#: tensions are read [s] (the static solve lumps each wire's weight half at either end,
#: MoorDyn spreads it over the nodes)
SETTLE_S = 10.0


def wire_check(plant, motion, hs, tz, heading_deg, *, segments, wire_mass_t_per_m,
               axial_damping_ratio, duration_s, transient_s, tolerance, dt=0.1, seed=1, gamma=3.3,
               kinematics="rigid", cell="", **reference) -> xr.Dataset:
    """The wire check of one cell (module docstring); ``reference``: further keywords of
    :func:`jls.verify.model.build_reference` (tugger, pitch inertia, hinge, fairleads)."""
    lever = motion.attrs["hinge_m"]
    one = model.build_reference(plant, vessel_lever_m=lever, **reference)
    many = model.build_reference(plant, vessel_lever_m=lever, segments=segments,
                                 wire_mass_t_per_m=wire_mass_t_per_m,
                                 wire_axial_damping=-float(axial_damping_ratio), **reference)
    t0 = time.perf_counter()
    still = simulate.run(many, exc_mod.still(dt, SETTLE_S))
    held = still.tension[-max(1, int(round(2.0 / dt))):].mean(0)
    exc = exc_mod.vessel_record(motion, hs, tz, heading_deg, gamma=gamma, duration_s=duration_s,
                                transient_s=transient_s, dt=dt, seed=seed, kinematics=kinematics)
    keep = exc.time >= -1e-9
    runs, walls = [], []
    for ref in (one, many):
        w0 = time.perf_counter()
        runs.append(simulate.run(ref, exc).relative()[keep, 0])
        walls.append(time.perf_counter() - w0)
    c_t = one.tugger.c if one.tugger is not None else 0.0
    qb, y_f = exc.rom_input(one.vessel_lever, one.fairleads[0])
    rel_rom = rom.relative(rom.simulate(plant, dt, qb, fairlead_sway=y_f, c_tugger=c_t), qb)[keep, 0]
    cmp_ = identify.compare(runs[1], runs[0])
    sig_one, sig_many = float(np.std(runs[0])), float(np.std(runs[1]))
    ds = xr.Dataset(coords={"wire": list(one.wire_names)})
    ds["tension_static_rom"] = ("wire", np.asarray(plant.tension, float))
    ds["tension_static_segments"] = ("wire", held)
    ds["tension_ratio_max"] = ((), float(np.max(np.abs(held / np.asarray(plant.tension) - 1))))
    ds["sigma_one_segment"] = ((), sig_one)
    ds["sigma_segments"] = ((), sig_many)
    ds["sigma_ratio_segments"] = ((), sig_many / sig_one)
    ds["r_segments"] = ((), cmp_["r"])
    ds["sigma_ratio_rom"] = ((), float(np.std(rel_rom)) / sig_many)
    ds["within_tolerance"] = ((), np.bool_(abs(sig_many / sig_one - 1) <= tolerance))
    ds["wall_time_one_segment"] = ((), walls[0])
    ds["wall_time_segments"] = ((), walls[1])
    ds["wall_time"] = ((), time.perf_counter() - t0)
    registry.annotate(ds, LAYOUT)
    ds.attrs.update(cell=str(cell), hs_m=float(hs), tz_s=float(tz), heading_deg=float(heading_deg),
                    segments=int(segments), wire_mass_t_per_m=float(wire_mass_t_per_m),
                    axial_damping_ratio=float(axial_damping_ratio), duration_s=float(duration_s),
                    transient_s=float(transient_s), dt_s=float(dt), tolerance=float(tolerance),
                    seed=int(seed) if np.isscalar(seed) else str(seed))
    return ds


def unavailable(reason: str, cell: str) -> xr.Dataset:
    """The dataset of a check that could not run (MoorDyn cannot be imported): every
    number NaN, ``within_tolerance`` false, the reason in ``reason``."""
    ds = xr.Dataset(coords={"wire": [f"wire{i + 1}" for i in range(4)]})
    for name in ("tension_static_rom", "tension_static_segments"):
        ds[name] = ("wire", np.full(4, np.nan))
    for name in ("tension_ratio_max", "sigma_one_segment", "sigma_segments", "sigma_ratio_segments",
                 "r_segments", "sigma_ratio_rom", "wall_time_one_segment", "wall_time_segments", "wall_time"):
        ds[name] = ((), np.nan)
    ds["within_tolerance"] = ((), np.bool_(False))
    registry.annotate(ds, LAYOUT)
    nan = float("nan")
    ds.attrs.update(cell=str(cell), hs_m=nan, tz_s=nan, heading_deg=nan, segments=0, wire_mass_t_per_m=nan,
                    axial_damping_ratio=nan, duration_s=nan, transient_s=nan, dt_s=nan, tolerance=nan,
                    reason=str(reason))
    return ds


__all__ = ["wire_check", "unavailable", "LAYOUT", "SETTLE_S"]
