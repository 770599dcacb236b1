"""One verified cell: the reference of one candidate against the ROM in one sea state,
as the dataset a pipeline job writes (``verification/<cell>.nc``, layout
``verification_cell`` of the registry, which gives every variable its units and long
name).

A cell runs: the reference's static state and modes (with small free decays along its
mode shapes), the sway free decay of both models, optionally the harmonic tests, and
both models on the same irregular vessel-motion record. Dimensions: ``model`` (rom,
reference), ``wire``, ``mode`` (the reference's six), ``rom_mode`` (the ROM's four),
``response`` (relative sway, heave, roll, yaw), ``period`` and ``amplitude`` of the
harmonic tests, ``trace_time`` (a window of the relative-sway record from the middle,
every 0.1 s).

The verdict (:func:`add_verdict`): the ROM over the reference, relative-sway sigma and
MPM; *within tolerance* when both ratios are within the tolerance of 1; *conservative*
when the ROM's MPM (what the workability judges) exceeds the reference's. Where MoorDyn
cannot be imported, :func:`unavailable_cell` is the cell's dataset: ``verified`` false,
the ratios NaN, the reason in the attribute ``reason``.

A cell is named ``candidate__tugger__h<heading>__hs<Hs>__tz<Tz>``
(:func:`jls.verify.names.cell_name`).
"""

from __future__ import annotations

import time

import numpy as np
import xarray as xr

from jls.io import registry
from jls.verify import chapter4, model
from jls.verify import damping as damp
from jls.verify.moordyn_model import available
from jls.verify.names import cell_name, parse_cell

LAYOUT = "verification_cell"
TRACE_STEP_S = 0.1
#: the fewest RK4 steps per period of the shortest mode of either model (omega dt <= 0.63:
#: RK4 then damps that mode by under 0.5 % of its amplitude a period)
STEPS_PER_PERIOD = 10
MODELS = ("rom", "reference")
RESPONSES = ("relative_sway", "relative_heave", "relative_roll", "relative_yaw")
RESPONSE_UNITS = ("m", "m", "degree", "degree")
ROM_DOFS = ("sway", "heave", "roll", "yaw")
VERIFIED, UNAVAILABLE = "verified", "unavailable"
NOT_COMPARABLE, OUTSIDE_TOLERANCE = "not comparable", "outside tolerance"
#: the values of a cell's attribute ``verdict``
VERDICTS = (VERIFIED, NOT_COMPARABLE, OUTSIDE_TOLERANCE)


def rk4_step(dt, ref, plant) -> float:
    """The RK4 step both models take [s]: ``dt``, or the shortest natural period of either
    model (the reference's six modes, the ROM's four) over :data:`STEPS_PER_PERIOD` where
    that is shorter (a stiff rigging's heave or pitch)."""
    shortest = min(float(np.min(ref.modes.period)), float(np.min(plant.modes.period)))
    return min(float(dt), shortest / STEPS_PER_PERIOD)


def verify_cell(plant, motion, hs, tz, heading_deg, *, candidate="baseline", tugger=None,
                gamma=3.3, duration_s=3 * 3600.0, seed=1, dt=chapter4.DT, kinematics="rigid",
                exposure_s=3 * 3600.0, release_m=0.54, harmonic_periods_s=(),
                harmonic_amplitudes_m=(0.05,), pitch_inertia_t_m2=None, wire_mass_t_per_m=0.0,
                segments=1, fairlead_offset_m=(0.0, 37.5, -82.5),
                hinge_height_m=model.HINGE_HEIGHT_M, trace_s=600.0, transient=None,
                tolerance=0.10, tugger_name=None, damping_tolerance=damp.RATIO_TOLERANCE,
                reference_start=None) -> xr.Dataset:
    """Verify one cell (module docstring). ``motion``: the vessel-motion dataset (any
    headings holding the cell's); ``tugger``: the setting both models carry (None:
    none); ``tugger_name``: the setting's name in the dataset (default: the tugger's, or
    "none"); ``transient`` [s]: start-up time left out (default five sway time
    constants); ``reference_start`` [s]: the reference starts this long before the
    statistics in the ROM's state (None: from rest with the ROM;
    :func:`jls.verify.chapter4.irregular_sea`'s ``settle``); ``tolerance``: of the verdict (:func:`add_verdict`); ``dt``: the RK4 step,
    shortened where a mode needs it (:func:`rk4_step`; the step taken is the attribute
    ``dt_s``)."""
    wall0 = time.perf_counter()
    ref = model.build_reference(plant, pitch_inertia_t_m2=pitch_inertia_t_m2,
                                wire_mass_t_per_m=wire_mass_t_per_m, segments=segments,
                                tugger=tugger, fairlead_offset_m=fairlead_offset_m,
                                hinge_height_m=hinge_height_m,
                                vessel_lever_m=motion.attrs["hinge_m"])
    dt = rk4_step(dt, ref, plant)
    modes = chapter4.reference_modes(ref, dt=dt)
    decay = chapter4.free_decay(ref, plant, release_m=release_m, dt=dt)
    irr = chapter4.irregular_sea(ref, plant, motion, hs, tz, heading_deg, gamma=gamma,
                                 duration_s=duration_s, dt=dt, seed=seed, kinematics=kinematics,
                                 exposure_s=exposure_s, keep_records=True, transient=transient,
                                 settle=reference_start)
    harm = (chapter4.harmonic(ref, plant, harmonic_periods_s, harmonic_amplitudes_m, dt=dt)
            if len(harmonic_periods_s) else None)
    ds = xr.Dataset(coords={"model": list(MODELS), "wire": list(ref.wire_names),
                            "mode": np.arange(1, 7), "rom_mode": np.arange(1, 5),
                            "response": list(RESPONSES),
                            "response_units": ("response", list(RESPONSE_UNITS)),
                            "axis": ["x", "y", "z"]})

    def put(name, dims, values):
        ds[name] = (dims, np.asarray(values))

    st = (irr["rom"], irr["reference"])
    put("sigma", ("model", "response"),
        [[s["sigma"]] + [o["heave_m"], o["roll_deg"], o["yaw_deg"]]
         for s, o in zip(st, (irr["sigma_other_rom"], irr["sigma_other_reference"]))])
    put("mpm", "model", [s["mpm"] for s in st])
    put("tz_response", "model", [s["tz"] for s in st])
    put("max_observed", "model", [s["max_observed"] for s in st])
    put("sigma_fd", (), irr["rom_sigma_frequency_domain"])
    put("sigma_ratio", (), irr["sigma_ratio_rom_to_reference"])
    put("mpm_ratio", (), irr["mpm_ratio_rom_to_reference"])
    cmp_ = irr["comparison"]
    for k in ("r", "r2", "rms_error", "rms_error_relative"):
        put(k, (), cmp_[k])
    put("tension_static", ("model", "wire"), [plant.tension, ref.tension])
    put("pose_offset", "axis", ref.pose[:3] - ref.cog_rest)
    put("pose_angle", "axis", np.degrees(ref.pose[3:]))
    put("wire_tension_min", (), irr["wire_tension_min_kN"])
    put("wire_tension_max", (), irr["wire_tension_max_kN"])
    put("slack_fraction", (), irr["slack_fraction"])
    if "tugger_limit_fraction" in irr:
        put("tugger_limit_fraction", (), irr["tugger_limit_fraction"])
    put("natural_period_reference", "mode", modes["period_linearised"].values)
    put("period_decay_reference", "mode", modes["period_decay"].values)
    put("damping_ratio_decay_reference", "mode", modes["damping_ratio_decay"].values)
    put("damping_ratio_target", "mode", modes["damping_ratio_target"].values)
    put("damping_ratio_achieved", "mode", modes["damping_ratio_decay"].values)
    put("damping_ratio_linearised", "mode", modes["damping_ratio_linearised"].values)
    put("variance_share", "mode", chapter4.variance_share(ref, irr["records"]["pose_reference"]))
    ds = ds.assign_coords(dominant_dof=("mode", list(ref.modes.dominant)),
                          rom_dominant_dof=("rom_mode", [ROM_DOFS[i] for i in plant.modes.dominant]))
    put("natural_period_rom", "rom_mode", plant.modes.period)
    put("damping_ratio_rom", "rom_mode", plant.damping_ratio)
    fits = (decay.rom, decay.reference)
    put("decay_period", "model", [f.period_undamped for f in fits])
    put("decay_damping_ratio", "model", [f.zeta for f in fits])
    put("decay_fit_r2", "model", [f.r2 for f in fits])
    if harm is not None:
        ds = ds.assign_coords(period=harm["period"].values, amplitude=harm["amplitude"].values)
        put("harmonic_gain", ("model", "period", "amplitude"),
            [harm["gain_rom"].values, harm["gain_reference"].values])
        put("harmonic_phase", ("model", "period", "amplitude"),
            [harm["phase_rom"].values, harm["phase_reference"].values])
    rec = irr["records"]
    t = rec["time"]
    mid = 0.5 * (t[0] + t[-1])
    w = np.flatnonzero((t >= mid - trace_s / 2) & (t < mid + trace_s / 2))
    w = w[::max(1, int(round(TRACE_STEP_S / dt)))]
    ds = ds.assign_coords(trace_time=("trace_time", t[w]))
    put("trace_relative_sway", ("model", "trace_time"),
        [rec["relative_rom"][w, 0], rec["relative_reference"][w, 0]])
    put("wall_time_reference", (), irr["reference_wall_time_s"])
    put("wall_time", (), time.perf_counter() - wall0)
    add_verdict(ds, tolerance, ratio_tolerance=damping_tolerance)
    ok, version = available()
    tug_name = tugger_name or (tugger.name if tugger is not None else "none")
    registry.annotate(ds, LAYOUT)
    ds.attrs.update(
        cell=cell_name(candidate, tug_name, heading_deg, hs, tz), status=VERIFIED, reason="",
        candidate=str(candidate), hs_m=float(hs), tz_s=float(tz), heading_deg=float(heading_deg),
        gamma=float(gamma), duration_s=float(duration_s), transient_s=irr["transient_s"], dt_s=float(dt),
        reference_start_s=float("nan") if reference_start is None else float(min(reference_start, irr["transient_s"])),
        seed=int(seed) if np.isscalar(seed) else str(seed), kinematics=kinematics, exposure_h=exposure_s / 3600.0,
        tugger=tug_name,
        c_tugger_kN_s_per_m=float(tugger.c) if tugger is not None else 0.0,
        release_m=float(release_m), pitch_inertia_t_m2=float(ref.inertia[1]),
        wire_mass_t_per_m=float(wire_mass_t_per_m), segments=int(segments),
        reference=f"MoorDyn-C {version} (NREL, BSD-3): jacket a free 6-DOF body, one line of "
                  f"{int(segments)} segment(s) per hoist wire, tips moved with the vessel's six DOFs ({kinematics}), RK4, in air",
        damping="dashpots solved exactly for a damping matrix that gives each reference mode the ROM's "
                "damping ratio of its mode and couples no two modes (surge: the sway ratio; pitch: the "
                "ROM's Rayleigh law); each mode's achieved ratio measured by a free decay along it",
        dashpot_residual=float(ref.dashpots.residual))
    return ds


def add_verdict(ds: xr.Dataset, tolerance: float, reason: str = "",
                ratio_tolerance: float = damp.RATIO_TOLERANCE) -> xr.Dataset:
    """The cell's verdict (module docstring), in place: ``tolerance``, ``within_tolerance``
    and ``conservative`` from ``sigma_ratio`` and ``mpm_ratio`` (NaN: false);
    ``comparable`` (the reference damped as the ROM, :func:`jls.verify.damping.comparable`
    on ``damping_ratio_target``, ``damping_ratio_achieved`` and ``variance_share``; false
    without them) and the attributes ``verdict`` (:data:`VERDICTS`: "verified" when
    comparable and within tolerance, "outside tolerance" when comparable and not within,
    "not comparable" otherwise) and ``verdict_reason`` (``reason`` when the reference did
    not run)."""
    s, m = float(ds["sigma_ratio"]), float(ds["mpm_ratio"])
    ran = bool(np.isfinite(s) and np.isfinite(m))
    ds["verified"] = ((), np.bool_(ran))
    ds["tolerance"] = ((), float(tolerance))
    ds["within_tolerance"] = ((), np.bool_(abs(s - 1) <= tolerance and abs(m - 1) <= tolerance))
    ds["conservative"] = ((), np.bool_(m > 1))
    if not ran:
        ok, why = False, reason or "the reference did not run"
    elif not all(k in ds for k in ("damping_ratio_target", "damping_ratio_achieved", "variance_share")):
        ok, why = False, "the reference's damping was not measured against its targets"
    else:
        ok, why = damp.comparable(ds["damping_ratio_target"].values, ds["damping_ratio_achieved"].values,
                                  ds["variance_share"].values, ratio_tolerance)
    ds["comparable"] = ((), np.bool_(ok))
    within = bool(ds["within_tolerance"])
    if not ok:
        verdict = NOT_COMPARABLE
    else:
        verdict = VERIFIED if within else OUTSIDE_TOLERANCE
        why = (f"ROM over reference: sigma {s:.4f}, MPM {m:.4f}, "
               f"{'within' if within else 'outside'} the {100 * tolerance:g} % tolerance")
    ds.attrs.update(verdict=verdict, verdict_reason=why)
    return registry.annotate(ds, LAYOUT)


def unavailable_cell(reason: str, *, candidate, tugger, hs, tz, heading_deg, duration_s, dt,
                     seed, kinematics, tolerance) -> xr.Dataset:
    """The dataset of a cell that could not be verified (MoorDyn cannot be imported):
    ``verified`` false, the ratios NaN, ``reason`` saying why."""
    ds = xr.Dataset({"sigma_ratio": ((), np.nan), "mpm_ratio": ((), np.nan)})
    add_verdict(ds, tolerance, reason=f"not run: {reason}")
    ds.attrs.update(cell=cell_name(candidate, tugger, heading_deg, hs, tz), status=UNAVAILABLE,
                    reason=str(reason), candidate=str(candidate), tugger=str(tugger),
                    hs_m=float(hs), tz_s=float(tz), heading_deg=float(heading_deg),
                    duration_s=float(duration_s), dt_s=float(dt),
                    seed=int(seed) if np.isscalar(seed) else str(seed), kinematics=str(kinematics),
                    reference=f"not run: {reason}")
    return ds


def cell_summary(ds: xr.Dataset) -> dict:
    """The headline numbers of a cell dataset, JSON-ready."""
    def f(v):
        v = float(v)
        return v if np.isfinite(v) else None
    out = {k: (ds.attrs[k].item() if isinstance(ds.attrs[k], np.generic) else ds.attrs[k])
           for k in ("cell", "status", "reason", "candidate", "hs_m", "tz_s", "heading_deg",
                     "duration_s", "seed", "kinematics", "tugger")}
    out["verdict"] = {"verdict": str(ds.attrs.get("verdict", "")), "reason": str(ds.attrs.get("verdict_reason", "")),
                      "verified": bool(ds["verified"]), "tolerance": f(ds["tolerance"]),
                      "sigma_ratio": f(ds["sigma_ratio"]), "mpm_ratio": f(ds["mpm_ratio"]),
                      "within_tolerance": bool(ds["within_tolerance"]),
                      "conservative": bool(ds["conservative"])}
    if not out["verdict"]["verified"]:
        return out
    out["transient_s"] = float(ds.attrs["transient_s"])
    m = list(MODELS)
    out["sigma_relative_sway_m"] = dict(zip(m, map(f, ds["sigma"].sel(response="relative_sway").values)))
    out["mpm_relative_sway_m"] = dict(zip(m, map(f, ds["mpm"].values)))
    out["sigma_relative_sway_fd_m"] = f(ds["sigma_fd"])
    for k in ("sigma_ratio", "mpm_ratio", "r", "r2", "rms_error", "rms_error_relative",
              "wire_tension_min", "wire_tension_max", "slack_fraction", "wall_time_reference", "wall_time"):
        out[k] = f(ds[k])
    out["tension_static_kN"] = {mm: list(map(f, ds["tension_static"].sel(model=mm).values)) for mm in m}
    out["tension_static_ratio"] = list(map(f, (ds["tension_static"].sel(model="rom") / ds["tension_static"].sel(model="reference")).values))
    out["natural_period_rom_s"] = dict(zip(ds["rom_dominant_dof"].values.tolist(), map(f, ds["natural_period_rom"].values)))
    out["natural_period_reference_s"] = dict(zip(ds["dominant_dof"].values.tolist(), map(f, ds["natural_period_reference"].values)))
    out["period_decay_reference_s"] = dict(zip(ds["dominant_dof"].values.tolist(), map(f, ds["period_decay_reference"].values)))
    out["damping_ratio_decay_reference"] = dict(zip(ds["dominant_dof"].values.tolist(), map(f, ds["damping_ratio_decay_reference"].values)))
    for k in ("damping_ratio_target", "damping_ratio_achieved", "variance_share"):
        out[k] = dict(zip(ds["dominant_dof"].values.tolist(), map(f, ds[k].values)))
    out["decay_period_s"] = dict(zip(m, map(f, ds["decay_period"].values)))
    out["decay_damping_ratio"] = dict(zip(m, map(f, ds["decay_damping_ratio"].values)))
    if "harmonic_gain" in ds:
        out["harmonic"] = [{"period_s": f(p), "amplitude_m": f(a),
                            "gain": dict(zip(m, map(f, ds["harmonic_gain"].sel(period=p, amplitude=a).values))),
                            "phase_deg": dict(zip(m, map(f, ds["harmonic_phase"].sel(period=p, amplitude=a).values)))}
                           for p in ds["period"].values for a in ds["amplitude"].values]
    return out


__all__ = ["verify_cell", "cell_summary", "add_verdict", "unavailable_cell", "cell_name", "parse_cell",
           "RESPONSES", "LAYOUT", "VERIFIED", "UNAVAILABLE", "NOT_COMPARABLE", "OUTSIDE_TOLERANCE",
           "VERDICTS"]
