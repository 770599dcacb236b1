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


def config_files(given) -> list[Path]:
    """The files a command reads: the project's default configuration, then each
    ``--config`` file merged over it (as ``snakemake --configfile``)."""
    files = [Path(p) for p in (given or [])]
    if DEFAULT_CONFIG.is_file() and DEFAULT_CONFIG.resolve() not in [f.resolve() for f in files if f.exists()]:
        files.insert(0, DEFAULT_CONFIG)
    if not files:
        raise InputError("no configuration: run in the project folder (config/config.yaml) "
                         "or give --config FILE")
    return files


def load_config(args) -> tuple[dict, Path]:
    """The validated configuration of a command and the folder its relative paths are
    taken from (the last file given)."""
    files = config_files(args.config)
    return load(*files), files[-1].parent


def cmd_modes(args) -> int:
    cfg, base_dir = load_config(args)
    plant = plant_from_config(cfg, source=str(base_dir), base_dir=base_dir)
    from jls.plant import summary
    s = summary(plant)
    if args.json:
        json.dump(s, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        print(format_modes(s))
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="jls", description=__doc__)
    parser.add_argument("--version", action="version", version=f"jls {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("modes", help="natural periods, damping, tensions and matrices of the plant")
    p.add_argument("--config", action="append", metavar="FILE",
                   help="configuration file merged over config/config.yaml (repeatable)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=cmd_modes)
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
