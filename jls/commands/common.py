"""What every ``jls`` command shares: the configuration files it reads, argument checks,
JSON output and the one-line error of an argument parser."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from jls.config.loader import load
from jls.errors import InputError

DEFAULT_CONFIG = Path("config/config.yaml")


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


def config_option(p):
    p.add_argument("--config", action="append", metavar="FILE",
                   help="configuration file merged over config/config.yaml, as snakemake "
                        "--configfile (repeatable)")


def one_line_error(self, message):
    """argparse error as one line ``jls: error: ...`` and exit status 2."""
    print(f"jls: error: {message}", file=sys.stderr)
    raise SystemExit(2)


def fairlead_offset(cfg):
    """The port tugger fairlead from the hinge [m]."""
    v = cfg["vessel"]
    return (0.0, float(v["fairlead_half_span_m"]), -float(v["fairlead_drop_m"]))


def positive(name, value, upper):
    if not (math.isfinite(value) and 0 < value <= upper):
        raise InputError(f"must be a number in (0, {upper:g}]", field=name, value=value)


def bounded(name, value, key):
    """An option standing for the configuration key ``key``: a finite number within the
    key's bounds in the schema (:func:`jls.io.schema.bounds`)."""
    from jls.io.schema import bounds
    lo, hi, open_lo = bounds(key)
    ok = isinstance(value, (int, float)) and math.isfinite(value)
    if ok and lo is not None:
        ok = value > lo if open_lo else value >= lo
    if ok and hi is not None:
        ok = value <= hi
    if not ok:
        low = "-inf" if lo is None else f"{lo:g}"
        high = "inf" if hi is None else f"{hi:g}"
        raise InputError(f"must be a number in {'(' if open_lo else '['}{low}, {high}] (as {key} "
                         "of the configuration)", field=name, value=value)


def finite_range(name, value, lo, hi):
    """A finite number in [lo, hi]."""
    if not (isinstance(value, (int, float)) and math.isfinite(value) and lo <= value <= hi):
        raise InputError(f"must be a number in [{lo:g}, {hi:g}]", field=name, value=value)


def heading(name, value):
    if not (math.isfinite(value) and 0 <= value <= 360):
        raise InputError("must be a heading in [0, 360] degrees", field=name, value=value)


def json_value(v):
    v = float(v)
    return v if math.isfinite(v) else None


def json_default(v):
    """``json.dump`` of numpy scalars (NaN and infinity as null)."""
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.floating, float)):
        return json_value(v)
    if isinstance(v, np.bool_):
        return bool(v)
    raise TypeError(type(v).__name__)


def print_nested(d, indent=2):
    """A nested mapping as indented ``key value`` lines."""
    for k, v in d.items():
        if isinstance(v, dict):
            print(" " * indent + f"{k}:")
            print_nested(v, indent + 2)
        else:
            print(" " * indent + f"{k:<34}{v}")
