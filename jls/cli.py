"""Command line: ``jls modes`` prints the plant of a configuration."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from jls import __version__
from jls.assembly import plant_from_config
from jls.config import load
from jls.errors import InputError
from jls.linearise import DOF

DEFAULT_CONFIG = Path("config/config.yaml")


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
    cfg_path = Path(args.config)
    cfg = load(cfg_path)
    plant = plant_from_config(cfg, source=str(cfg_path), base_dir=cfg_path.parent)
    from jls.plant import summary
    s = summary(plant)
    if args.json:
        json.dump(s, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        print(format_modes(s))
    return 0


def cmd_check(args) -> int:
    from jls.workflow_inputs import check_run
    paths = [DEFAULT_CONFIG] if DEFAULT_CONFIG.exists() and not args.only else []
    paths += [Path(p) for p in args.configfile]
    if not paths:
        raise InputError("no configuration file to check", file=str(DEFAULT_CONFIG))
    s = check_run(paths)
    print(f"jls: {' + '.join(str(p) for p in paths)}: valid; routes "
          + ", ".join(f"{r} ({n} legs)" for r, n in s["routes"].items())
          + f"; RAO file {s['rao_file']}")
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="jls", description=__doc__)
    parser.add_argument("--version", action="version", version=f"jls {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("modes", help="natural periods, damping, tensions and matrices of the plant")
    p.add_argument("--config", default=str(DEFAULT_CONFIG), help="configuration file (default %(default)s)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_modes)
    c = sub.add_parser("check", help="check the inputs of a workflow run as Snakemake would "
                       "(config/config.yaml, then each --configfile, merged)")
    c.add_argument("configfile", nargs="*", help="configuration files merged over the default")
    c.add_argument("--only", action="store_true", help="do not start from config/config.yaml")
    c.set_defaults(func=cmd_check)
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except InputError as exc:
        print(f"jls: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:          # output piped into head and the like
        sys.stderr.close()
        return 0


if __name__ == "__main__":
    sys.exit(main())
