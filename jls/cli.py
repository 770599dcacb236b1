"""Command line: ``jls modes`` prints the plant of a configuration; ``jls decay`` and
``jls simulate`` run the nonlinear time-domain model with the configured tuggers;
``jls spectrum`` prints the integrated parameters of a measured or hindcast spectra file;
``jls verify`` checks the ROM against the 6-DOF nonlinear reference (MoorDyn) in one
case, or drives the ROM with a motion record; ``jls response`` prints the frequency-domain
statistics of one sea state of one or more directional wave systems."""

from __future__ import annotations

import argparse
import json
import sys
import types
from dataclasses import replace
from pathlib import Path

import numpy as np

from jls import __version__
from jls.commands import forecast, response, verify
from jls.commands.common import (
    DEFAULT_CONFIG,
    config_files,
    config_option,
    fairlead_offset,
    finite_range,
    heading,
    json_value,
    load_config,
    one_line_error,
    positive,
)
from jls.config.builders import plant_from_config
from jls.errors import InputError
from jls.plant.linearise import DOF

__all__ = ["main", "build_parser", "format_modes", "spectrum_summary", "config_files", "load_config", "DEFAULT_CONFIG"]
#: The spectra readers of ``jls spectrum`` (jls.sea.measured.FORMATS, not imported at start-up).
SPECTRA_FORMATS = ("ndbc", "ww3", "era5")


def _matrix(name, a, unit):
    a = np.asarray(a, float)
    a = np.where(np.abs(a) < 1e-12 * np.abs(a).max(), 0.0, a)     # round-off, not coupling
    lines = [f"{name} [{unit}]"]
    lines.append("          " + "".join(f"{d:>13}" for d in DOF))
    for d, row in zip(DOF, np.asarray(a)):
        lines.append(f"  {d:<8}" + "".join(f"{v:13.5g}" for v in row))
    return "\n".join(lines)


def format_modes(s: dict) -> str:
    out = ["Modes (undamped; kinetic-energy fraction per DOF, %)",
           f"  {'mode':<5}{'period s':>10}{'damping %':>11}" + "".join(f"{d:>8}" for d in DOF)
           + "  dominant"]
    for i, (t, z, frac, dom) in enumerate(zip(s["natural_period_s"], s["damping_ratio"],
                                               s["energy_fraction"], s["dominant_dof"])):
        out.append(f"  {i + 1:<5}{t:10.4f}{100 * z:11.3f}" + "".join(f"{100 * f:8.1f}" for f in frac)
                   + f"  {dom}")
    if "rayleigh_alpha_per_s" in s:
        out.append(f"  Rayleigh damping: alpha = {s['rayleigh_alpha_per_s']:.4g} 1/s, "
                   f"beta = {s['rayleigh_beta_s']:.4g} s")
    if "tension_kN" in s:
        out += ["", "Wires (anchor relative to the hinge, padeye relative to the CoG; m)",
                f"  {'wire':<4}{'anchor x, y, z':>26}{'padeye x, y, z':>26}{'k kN/m':>10}"
                f"{'T kN':>10}{'L0 m':>9}{'side deg':>9}{'f-a deg':>9}"]
        for i in range(4):
            a = ", ".join(f"{v:.3f}" for v in s["anchors_m"][i])
            p = ", ".join(f"{v:.3f}" for v in s["padeyes_m"][i])
            out.append(f"  {i + 1:<4}{a:>26}{p:>26}{s['wire_stiffness_kN_per_m'][i]:10.0f}"
                       f"{s['tension_kN'][i]:10.0f}{s['unstretched_length_m'][i]:9.3f}"
                       f"{s['side_lead_deg'][i]:9.2f}{s['fore_aft_lead_deg'][i]:9.2f}")
        res = s["equilibrium_residual"]
        out.append(f"  CoG depth below hinge {s['cog_depth_m']:.3f} m; equilibrium residual "
                   "(fraction of weight): " + ", ".join(f"{k} {v:.1e}" for k, v in res.items())
                   + ("" if s["in_equilibrium"] else "  NOT IN EQUILIBRIUM (surge/pitch)"))
    out += ["", _matrix("M", s["M"], "t, t m^2"), _matrix("K", s["K"], "kN/m, kN, kN m/rad"),
            _matrix("Kb", s["Kb"], "kN/m, kN, kN m/rad; columns: hinge DOFs"),
            _matrix("C", s["C"], "kN s/m, kN s, kN m s/rad")]
    return "\n".join(out)


def cmd_modes(args) -> int:
    cfg, base_dir = load_config(args)
    plant = plant_from_config(cfg, source=str(base_dir), base_dir=base_dir)
    from jls.plant.model import summary
    s = summary(plant)
    if args.json:
        json.dump(s, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        print(format_modes(s))
    return 0


def _plant_and_tuggers(args):
    from jls.config.builders import settings_from_config, tuggers_from_config
    files = config_files(args.config)
    cfg, base_dir = load_config(args)
    cfg_path = files[-1]
    plant = plant_from_config(cfg, source=str(cfg_path), base_dir=base_dir)
    return cfg, cfg_path, plant, tuggers_from_config(cfg, str(cfg_path)), settings_from_config(cfg)


def cmd_decay(args) -> int:
    from jls.timedomain.decay import decay
    positive("--release-m", args.release_m, 30.0)
    cfg, _, plant, tuggers, settings = _plant_and_tuggers(args)
    names = list(tuggers)
    runs = [decay(plant, tuggers[n], args.release_m, dt=min(settings.dt, 0.02),
                  fairlead_offset_m=fairlead_offset(cfg)) for n in names]
    out = {"release_m": args.release_m, "tugger": names,
           "c_kN_s_per_m": [tuggers[n].c for n in names],
           "max_force_kN": [tuggers[n].max_force for n in names],
           "min_force_kN": [tuggers[n].min_force for n in names],
           "lag_s": [tuggers[n].lag for n in names],
           "time_to_10pct_s": [json_value(r.time_to_10pct) for r in runs],
           "zeta_first_cycle": [json_value(r.zeta_first_cycle) for r in runs]}
    if args.json:
        json.dump(out, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        print(f"Free decay from a {args.release_m:g} m sway release (still vessel)")
        print(f"  {'tugger':<12}{'c kN s/m':>10}{'T_max kN':>10}{'to 10 % s':>11}{'zeta 1st %':>12}")
        for i, n in enumerate(names):
            t10, z = out["time_to_10pct_s"][i], out["zeta_first_cycle"][i]
            cap = f"{tuggers[n].max_force:10.0f}" if tuggers[n].active else f"{'-':>10}"
            print(f"  {n:<12}{tuggers[n].c:10.0f}{cap}"
                  f"{t10 if t10 is not None else float('nan'):11.1f}"
                  f"{100 * z if z is not None else float('nan'):12.2f}")
    return 0


def cmd_simulate(args) -> int:
    from jls.stages.vessel_motion import vessel_motion
    from jls.timedomain.run import Case, frequency_domain_sigma
    positive("--hs", args.hs, 30.0)
    positive("--tz", args.tz, 30.0)
    finite_range("--tz", args.tz, 1.0, 30.0)
    positive("--duration-h", args.duration_h, 100.0)
    heading("--heading", args.heading)
    if args.seed < 0:
        raise InputError("must be a non-negative integer", field="--seed", value=args.seed)
    cfg, cfg_path, plant, tuggers, settings = _plant_and_tuggers(args)
    from jls.sea.steepness import require_not_breaking
    require_not_breaking(args.hs, args.tz, g=float(cfg["g_m_per_s2"]))
    if args.tugger not in tuggers:
        raise InputError(f"no such tugger setting (configured: {', '.join(tuggers)})",
                         file=cfg_path, field="--tugger", value=args.tugger)
    if "vessel" not in cfg:
        raise InputError("the time domain needs the vessel RAOs", file=cfg_path, field="vessel")
    base = Path.cwd() if (Path.cwd() / cfg["vessel"]["rao_file"]).exists() else cfg_path.parent
    motion = vessel_motion(cfg["vessel"], [args.heading], base_dir=base)
    gamma = cfg["sea"]["gamma"]
    from jls.response.coverage import check_coverage
    om = motion["omega"].values
    check_coverage(om.min(), om.max(), [args.tz], gamma, cfg["vessel"].get("outside_rao_range"),
                   source=cfg_path)
    tug = tuggers[args.tugger]
    if args.amplitudes:
        settings = replace(settings, amplitudes=args.amplitudes)
    from jls.timedomain.resolution import require_resolution
    from jls.timedomain.run import record_spacing
    field, value = (("timedomain.n_components", settings.n_components) if settings.n_components
                    else ("--duration-h", args.duration_h))
    n_bw = require_resolution(plant, record_spacing(plant, settings, args.duration_h * 3600.0,
                                                    (om.min(), om.max())), field=field, value=value)
    case = Case(plant, motion, args.hs, args.tz, args.heading, gamma=gamma,
                duration_s=args.duration_h * 3600.0, settings=settings, seed=args.seed)
    r = case.run(tug)
    fd = frequency_domain_sigma(plant, motion, [tug], args.hs, args.tz, args.heading, gamma)[0]
    out = {"hs_m": args.hs, "tz_s": args.tz, "heading_deg": args.heading, "tugger": tug.name,
           "c_kN_s_per_m": tug.c, "max_force_kN": tug.max_force, "min_force_kN": tug.min_force,
           "duration_h": case.duration / 3600.0, "transient_s": case.transient, "dt_s": case.dt,
           "seed": args.seed, "n_components": int(case.realisation.omega.size),
           "amplitudes": settings.amplitudes, "components_per_bandwidth": float(n_bw),
           "sigma_relative_sway_m": r["sigma"], "sigma_relative_sway_fd_m": float(fd),
           "mpm_relative_sway_m": r["mpm_upcrossing"],
           "mpm_relative_sway_from_sigma_m": r["mpm_sigma"],
           "max_relative_sway_observed_m": r["max_observed"],
           "tugger_limit_fraction": r["limit_fraction"],
           "tugger_at_max_fraction": r["at_max_fraction"],
           "tugger_at_min_fraction": r["at_min_fraction"],
           "winch_power_mean_kW": r["power_mean"], "winch_power_peak_kW": r["power_peak"],
           "wire_tension_min_kN": r["wire_tension_min"], "wire_tension_max_kN": r["wire_tension_max"],
           "slack_events": r["slack_events"],
           "line_length_min_m": r["line_length_min"], "line_contact_fraction": r["line_contact_fraction"],
           "wall_time_s": r["wall_time"],
           "real_time_factor": (case.n_steps * case.dt) / r["wall_time"]}
    out = {k: (json_value(v) if isinstance(v, float) else v) for k, v in out.items()}
    if args.json:
        json.dump(out, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        for k, v in out.items():
            print(f"  {k:<34}{v}")
    return 0


def cmd_check(args) -> int:
    from jls.config.workflow_inputs import check_run
    files = config_files(args.config)
    s = check_run(files)
    print(f"jls: {' + '.join(str(p) for p in files)}: valid; routes "
          + ", ".join(f"{r} ({n} legs)" for r, n in s["routes"].items())
          + f"; RAO file {s['rao_file']}")
    for line in s["warnings"]:                 # what the report prints on its first page
        print(f"jls: warning: {line}")
    return 0


def spectrum_summary(path, fmt, station=None) -> dict:
    """What ``jls spectrum`` prints: per record the time (ISO 8601, UTC), Hs = 4 sqrt(m0),
    Tm02 = sqrt(m0/m2) and Tp of the spectrum (:mod:`jls.sea.measured`)."""
    from jls.sea.measured import integrated_parameters, read_spectra
    options = {} if station is None else {"station": station}
    if station is not None and fmt != "ww3":
        raise InputError("--station applies to the ww3 format only", field="--station", value=station)
    if station is not None and station < 0:
        raise InputError("must be a station index >= 0 (the first station is 0)",
                         file=path, field="--station", value=station)
    efth = read_spectra(path, fmt, **options)
    p = integrated_parameters(efth)
    times = [str(t)[:19] + "Z" for t in efth["time"].values.astype("datetime64[s]")]
    return {"file": str(path), "format": fmt, "directional": "dir" in efth.dims,
            "n_records": len(times), "n_frequencies": int(efth.sizes["freq"]),
            "n_directions": int(efth.sizes.get("dir", 0)),
            "time": times, "hs_m": [json_value(v) for v in p["hs"].values],
            "tm02_s": [json_value(v) for v in p["tm02"].values],
            "tp_s": [json_value(v) for v in p["tp"].values]}


def cmd_spectrum(args) -> int:
    out = spectrum_summary(args.file, args.format, args.station)
    if args.json:
        json.dump(out, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        kind = f"directional, {out['n_directions']} directions" if out["directional"] else "1-D"
        print(f"{out['file']} ({out['format']}): {out['n_records']} records, "
              f"{out['n_frequencies']} frequencies, {kind}")
        print(f"  {'time (UTC)':<22}{'Hs m':>8}{'Tm02 s':>9}{'Tp s':>8}")
        for t, h, z, p in zip(out["time"], out["hs_m"], out["tm02_s"], out["tp_s"]):
            print(f"  {t:<22}{h:8.3f}{z:9.3f}{p:8.2f}")
    return 0


def _forecast_pdf(ds, answer, path):
    """``jls forecast --pdf``: the pre-transit report (:mod:`jls.report.forecast`)."""
    from jls.report.forecast import write_pdf
    return write_pdf(ds, answer, path)


def build_parser() -> argparse.ArgumentParser:
    """The ``jls`` command's parser (also read by the documentation's command reference)."""
    parser = argparse.ArgumentParser(prog="jls", description=__doc__)
    parser.add_argument("--version", action="version", version=f"jls {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("modes", help="natural periods, damping, tensions and matrices of the plant")
    config_option(p)
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_modes)
    p = sub.add_parser("decay", help="free decay from a sway release, per configured tugger")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.add_argument("--release-m", type=float, default=3.0, help="sway release [m] (default %(default)s)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_decay)
    p = sub.add_parser("simulate", help="nonlinear time-domain run in one sea state")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.add_argument("--hs", type=float, required=True, help="significant wave height [m]")
    p.add_argument("--tz", type=float, required=True, help="zero-up-crossing period [s]")
    p.add_argument("--heading", type=float, default=90.0, help="relative wave heading [deg] (default %(default)s)")
    p.add_argument("--tugger", default="none", help="tugger setting name (default %(default)s)")
    p.add_argument("--duration-h", type=float, default=3.0, help="recorded duration [h] (default %(default)s)")
    p.add_argument("--seed", type=int, default=1, help="seed of the wave phases (default %(default)s)")
    p.add_argument("--amplitudes", choices=("rayleigh", "deterministic"), default=None,
                   help="wave component amplitudes (default: timedomain.amplitudes of the configuration)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_simulate)
    verify.add_parser(sub)
    response.add_parser(sub)
    forecast.add_parser(sub, pdf_writer=_forecast_pdf)
    p = sub.add_parser("check", help="check the inputs of a workflow run as Snakemake does "
                       "when it reads the workflow (tables, RAO file, coverage)")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.set_defaults(func=cmd_check)
    p = sub.add_parser("spectrum", help="Hs, Tm02 and Tp per record of a measured or hindcast "
                       "spectra file (NDBC spectral files, WW3 or ERA5 spectra)")
    p.error = types.MethodType(one_line_error, p)
    p.add_argument("file", help="spectra file (NDBC: the spectral density file; the direction "
                   "files beside it are read when present)")
    p.add_argument("--format", required=True, choices=SPECTRA_FORMATS, help="reader")
    p.add_argument("--station", type=int, default=None, help="station index (ww3 files with several)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_spectrum)
    return parser


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    try:
        from jls.config.environment import check_environment
        # before numba or numpy.f2py is imported (f2py reads SOURCE_DATE_EPOCH with int())
        check_environment(cache=False)
        return args.func(args)
    except InputError as exc:
        print(f"jls: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:          # output piped into head and the like
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    sys.exit(main())
