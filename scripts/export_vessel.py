"""Write a vessel's RAOs as an OrcaFlex vessel type or as AQWA-LINE listing RAO tables.

    python scripts/export_vessel.py --format orcaflex|aqwa_lis [--rao FILE] [--output PATH]
                                    [--vessel-type NAME] [--draught NAME]

By default the shipped vessel (``config/vessel/representative_hlv.nc``) is written to
``results/vessel/export/representative_hlv.yml`` (OrcaFlex) or ``.lis`` (AQWA), and the
vessel block that reads it back is printed: a configuration with that block assesses the
same vessel, so its ``workability.nc`` equals the clean run's (``tests/test_vessel_export.py``).
The readers (``jls.vessel.orcaflex``, ``jls.vessel.aqwa``) state the conventions; the
file is read back here and compared with the source before the command succeeds.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_RAO = ROOT / "config" / "vessel" / "representative_hlv.nc"
SUFFIX = {"orcaflex": ".yml", "aqwa_lis": ".lis"}


def main(argv=None) -> int:
    from jls.errors import InputError
    from jls.vessel import load_rao
    from jls.vessel.export import aqwa_text, orcaflex_text, write_text

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--format", required=True, choices=sorted(SUFFIX))
    ap.add_argument("--rao", type=Path, default=DEFAULT_RAO, help="RAO file to write (any format jls reads)")
    ap.add_argument("--output", type=Path, help="file to write")
    ap.add_argument("--vessel-type", default=None, help="OrcaFlex vessel type name (default: the file's stem)")
    ap.add_argument("--draught", default="operating", help="OrcaFlex draught name")
    args = ap.parse_args(argv)
    try:
        rao = load_rao(args.rao)
        name = args.vessel_type or args.rao.stem
        out = args.output or ROOT / "results" / "vessel" / "export" / (args.rao.stem + SUFFIX[args.format])
        if args.format == "orcaflex":
            write_text(orcaflex_text(rao, vessel_type=name, draught=args.draught), out)
            back = load_rao(out, "orcaflex", vessel_type=name, draught=args.draught)
            block = (f"  rao_format: orcaflex\n  orcaflex_vessel_type: {name}\n"
                     f"  orcaflex_draught: {args.draught}\n")
        else:
            write_text(aqwa_text(rao), out)
            back = load_rao(out, "aqwa_lis")
            block = "  rao_format: aqwa_lis\n"
    except InputError as exc:
        print(f"export_vessel: {exc}", file=sys.stderr)
        return 1
    diff = float(np.max(np.abs(back["rao"].values - rao["rao"].values)))
    if diff > 1e-9 * float(np.max(np.abs(rao["rao"].values))):
        print(f"export_vessel: {out} reads back {diff:.3g} away from {args.rao}", file=sys.stderr)
        return 1
    print(f"wrote {out} (reads back within {diff:.2g} of {args.rao.name}); vessel block:\n"
          f"vessel:\n  rao_file: {out}\n{block}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
