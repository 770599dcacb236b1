"""``jls verify``: the ROM against the 6-DOF nonlinear reference (MoorDyn) in one case,
with the configuration's ``verification`` settings unless an option overrides them, or
the ROM driven by a motion record (``--record``, optionally against a response record).

    jls verify --candidate detuned --tugger low --hs 0.75 --tz 9.5 --duration-h 0.33 --json
"""

from __future__ import annotations

import json
import sys
import types
from pathlib import Path

import numpy as np

from jls.commands.common import (
    bounded,
    config_files,
    config_option,
    fairlead_offset,
    finite_range,
    heading,
    json_default,
    load_config,
    one_line_error,
    positive,
    print_nested,
)
from jls.errors import InputError


def add_parser(sub):
    p = sub.add_parser("verify", help="the ROM against the 6-DOF nonlinear reference (MoorDyn) in "
                       "one case, or the ROM driven by a motion record (--record)")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.add_argument("--candidate", default="baseline", help="rigging candidate (default %(default)s)")
    p.add_argument("--tugger", default="none", help="tugger setting name (default %(default)s)")
    p.add_argument("--hs", type=float, default=2.4, help="significant wave height [m] (default %(default)s)")
    p.add_argument("--tz", type=float, default=6.6, help="zero-up-crossing period [s] (default %(default)s)")
    p.add_argument("--heading", type=float, default=90.0, help="relative wave heading [deg] (default %(default)s)")
    p.add_argument("--duration-h", type=float, default=3.0, help="recorded duration [h] (default %(default)s)")
    p.add_argument("--seed", type=int, default=1, help="seed of the wave phases (default %(default)s)")
    p.add_argument("--kinematics", choices=("rigid", "linear"), default=None,
                   help="how the tips follow the vessel's rotations (default: verification.kinematics)")
    p.add_argument("--release-m", type=float, default=None,
                   help="sway release of the free decay [m] (default: verification.release_m)")
    p.add_argument("--harmonic-period-s", type=float, nargs="*", default=None,
                   help="hinge-sway periods of the harmonic tests [s] (default: verification."
                        "harmonic_periods_s; none given: no harmonic test)")
    p.add_argument("--harmonic-amplitude-m", type=float, default=None,
                   help="hinge-sway amplitude of the harmonic tests [m] (default: verification.harmonic_amplitude_m)")
    p.add_argument("--pitch-inertia-t-m2", type=float, default=None,
                   help="the jacket's pitch inertia [t m^2] (default: verification.pitch_inertia_t_m2, "
                        "else its roll inertia)")
    p.add_argument("--wire-mass-t-per-m", type=float, default=None,
                   help="hoist-wire mass per length [t/m] (default: verification.wire_mass_t_per_m)")
    p.add_argument("--dt-s", type=float, default=None, help="RK4 step [s] (default: verification.dt_s)")
    p.add_argument("--tolerance", type=float, default=None,
                   help="tolerance of the verdict on the ROM over the reference (default: verification.tolerance)")
    p.add_argument("--record", metavar="CSV", help="drive the ROM with this vessel or hinge motion record instead")
    p.add_argument("--response", metavar="CSV", help="response record to compare the ROM with (with --record)")
    p.add_argument("--highpass-hz", type=float, default=0.02,
                   help="high-pass cut-off applied to the records [Hz] (default %(default)s, section 4.6)")
    p.add_argument("--transient-s", type=float, default=None,
                   help="start-up transient left out of the statistics [s] (default: "
                        "verification.transient_time_constants sway time constants)")
    p.add_argument("--assessed-plant", metavar="NC", default=None,
                   help="a pipeline run's plant_assessed.nc: a candidate the configuration does not "
                        "list (the screening's optimised) is rebuilt from its design variables there")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=run)
    return p


def candidate_plant(cfg, name, source, assessed=None):
    """The plant of one rigging candidate and the wire names: a configured candidate
    (``baseline`` or a named one) from the configuration, any other (the screening's
    ``optimised``) from its design variables in ``assessed``, a pipeline run's
    ``plant_assessed.nc`` (``--assessed-plant``), as the pipeline's verification cells do."""
    from jls.config.builders import (
        assessed_candidate_plant,
        candidate_values,
        rigging_from_config,
    )
    from jls.config.builders import candidate_plant as configured_plant
    from jls.plant.model import require_balanced
    values = candidate_values(cfg)
    if name in values:
        plant = configured_plant(cfg, name, source, field="--candidate")
    elif assessed is not None:
        from jls.io.netcdf import read
        plant = assessed_candidate_plant(cfg, read(assessed), name, str(assessed))
    else:
        raise InputError(f"no such rigging candidate (configured: {', '.join(values)}; a "
                         "candidate of a pipeline run, such as the screening's optimised, needs "
                         "--assessed-plant results/<route>/plant_assessed.nc)",
                         file=source, field="--candidate", value=name)
    require_balanced(plant, source)
    return plant, rigging_from_config(cfg).wire_names


def check_options(args) -> None:
    """Every number option of ``jls verify`` within the bounds of the configuration key it
    stands for (:func:`jls.commands.common.bounded`), before any model is built: a
    harmonic period of 0 s, a negative seed or inertia, a NaN are named here."""
    finite_range("--tz", args.tz, 1.0, 30.0)
    for name in ("--record", "--response", "--assessed-plant"):
        value = getattr(args, name[2:].replace("-", "_"))
        if value is not None and not str(value).strip():
            raise InputError("an empty path names no file: give the file's path", field=name,
                             value=value)
    for period in args.harmonic_period_s or ():
        bounded("--harmonic-period-s", period, "verification.harmonic_periods_s.items")
    if args.harmonic_period_s and len(args.harmonic_period_s) > 10:
        raise InputError("at most 10 periods (as verification.harmonic_periods_s)",
                         field="--harmonic-period-s", value=len(args.harmonic_period_s))
    for name, key in (("--pitch-inertia-t-m2", "verification.pitch_inertia_t_m2"),
                      ("--wire-mass-t-per-m", "verification.wire_mass_t_per_m"),
                      ("--seed", "verification.seed")):
        value = getattr(args, name[2:].replace("-", "_"))
        if value is not None:
            bounded(name, value, key)
    if args.transient_s is not None:
        finite_range("--transient-s", args.transient_s, 0.0, 360000.0)
    finite_range("--highpass-hz", args.highpass_hz, 0.0, 1.0)


def _record(args, cfg, plant, tug) -> dict:
    from jls.verify.records import read_motion_record, read_response_record, rom_from_record
    record = read_motion_record(args.record)
    response = read_response_record(args.response) if args.response else None
    v = cfg["vessel"]
    lever = np.subtract(v["hinge_m"], v["rao_reference_point_m"]).tolist()
    return rom_from_record(plant, record, response, highpass_hz=args.highpass_hz,
                           transient=args.transient_s, vessel_lever_m=lever,
                           fairlead_offset_m=fairlead_offset(cfg), c_tugger=tug.c,
                           exposure_s=cfg["assessment"]["exposure_h"] * 3600.0)


def _given(value, configured):
    return configured if value is None else value


def _one_case(args, cfg, cfg_path, plant, tug) -> dict:
    from jls.config.builders import verification_settings_from_config
    from jls.verify import reference_available
    s = verification_settings_from_config(cfg)
    for name, value, upper in (("--hs", args.hs, 30.0), ("--tz", args.tz, 30.0),
                               ("--duration-h", args.duration_h, 100.0)):
        positive(name, value, upper)
    heading("--heading", args.heading)
    for name, value, upper in (("--dt-s", args.dt_s, 0.1), ("--tolerance", args.tolerance, 1.0),
                               ("--release-m", args.release_m, 20.0),
                               ("--harmonic-amplitude-m", args.harmonic_amplitude_m, 5.0)):
        if value is not None:
            positive(name, value, upper)
    from jls.sea.steepness import require_not_breaking
    require_not_breaking(args.hs, args.tz, g=float(cfg["g_m_per_s2"]))
    ok, why = reference_available()
    if not ok:
        raise InputError(why, field="jls verify")
    from jls.response.coverage import check_coverage
    from jls.stages.vessel_motion import vessel_motion
    from jls.verify.cell import verify_cell
    from jls.verify.chapter4 import transient_s
    base = Path.cwd() if (Path.cwd() / cfg["vessel"]["rao_file"]).exists() else cfg_path.parent
    motion = vessel_motion(cfg["vessel"], [args.heading], base_dir=base)
    om = motion["omega"].values
    check_coverage(om.min(), om.max(), [args.tz], cfg["sea"]["gamma"],
                   cfg["vessel"].get("outside_rao_range"), source=cfg_path)
    transient = _given(args.transient_s, transient_s(plant, s.transient_time_constants, tug.c))
    return verify_cell(
        plant, motion, args.hs, args.tz, args.heading, candidate=args.candidate,
        tugger=tug if tug.active else None, tugger_name=tug.name, gamma=cfg["sea"]["gamma"],
        duration_s=args.duration_h * 3600.0, seed=args.seed,
        kinematics=_given(args.kinematics, s.kinematics),
        exposure_s=cfg["assessment"]["exposure_h"] * 3600.0, dt=_given(args.dt_s, s.dt),
        release_m=_given(args.release_m, s.release_m),
        harmonic_periods_s=tuple(_given(args.harmonic_period_s, s.harmonic_periods_s)),
        harmonic_amplitudes_m=(_given(args.harmonic_amplitude_m, s.harmonic_amplitude_m),),
        pitch_inertia_t_m2=_given(args.pitch_inertia_t_m2, s.pitch_inertia_t_m2),
        wire_mass_t_per_m=_given(args.wire_mass_t_per_m, s.wire_mass_t_per_m),
        segments=s.segments, fairlead_offset_m=fairlead_offset(cfg),
        hinge_height_m=cfg["rigging"]["limits"]["hinge_height_m"], trace_s=s.trace_s,
        transient=transient, tolerance=_given(args.tolerance, s.tolerance),
        reference_start=(None if s.reference_start_time_constants is None
                         else transient_s(plant, s.reference_start_time_constants, tug.c)))


def run(args) -> int:
    if args.response and not args.record:
        raise InputError("a response record is compared with the ROM driven by a motion "
                         "record: give --record too", field="--response", value=args.response)
    if not args.highpass_hz >= 0:
        raise InputError("must be >= 0 (0: no filter)", field="--highpass-hz", value=args.highpass_hz)
    check_options(args)
    files = config_files(args.config)
    cfg, _ = load_config(args)
    cfg_path = files[-1]
    from jls.config.builders import tuggers_from_config
    tuggers = tuggers_from_config(cfg, str(cfg_path))
    if args.tugger not in tuggers:
        raise InputError(f"no such tugger setting (configured: {', '.join(tuggers)})",
                         file=cfg_path, field="--tugger", value=args.tugger)
    tug = tuggers[args.tugger]
    plant, wire_names = candidate_plant(cfg, args.candidate, str(cfg_path), args.assessed_plant)
    if args.record:
        out = _record(args, cfg, plant, tug)
    else:
        from jls.verify.cell import cell_summary
        out = cell_summary(_one_case(args, cfg, cfg_path, plant, tug))
        out["wire"] = list(wire_names)
    if args.json:
        json.dump(out, sys.stdout, indent=1, default=json_default)
        sys.stdout.write("\n")
    else:
        print_nested(out)
    return 0


__all__ = ["add_parser", "run", "candidate_plant"]
