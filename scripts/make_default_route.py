"""Derive the default route's per-leg Hs-Tz scatter tables from the NDBC hindcasts.

Two-leg route: leg 1 from NDBC 44007 (Gulf of Maine), leg 2 from NDBC 41009 (off Cape
Canaveral), hourly records 1996-2005 as prepared for the OMAE 2019 environmental-contour
benchmark (datasets A and B).  Both legs use the same bins so they can be combined:
Hs 0.5 m wide from 0 m, Tz 1 s wide between whole seconds, spanning the data of both
buoys; bins are [lower, upper), the last one closed.  Every valid record is counted
(nothing falls outside the bins by construction); gaps are summarised in the headers.

Usage::

    python scripts/make_default_route.py [METOCEAN_DIR] [--out config/routes/default]

METOCEAN_DIR defaults to ../shared/data/metocean relative to the repository root.
The raw files are not copied into the repository; only the derived tables are written.
"""

from __future__ import annotations

import argparse
import logging
import math
import sys
from pathlib import Path

import numpy as np

from jls.sea.hindcast import bin_hindcast, hindcast_gaps, read_hindcast
from jls.sea.scatter import write_scatter

REPO = Path(__file__).resolve().parents[1]
DEFAULT_METOCEAN = REPO.parent / "shared" / "data" / "metocean"
DEFAULT_OUT = REPO / "config" / "routes" / "default"
HS_WIDTH = 0.5  # m
TZ_WIDTH = 1.0  # s
ATTRIBUTION = ("NDBC, public domain U.S. government data, via the OMAE 2019 "
               "environmental-contour benchmark datasets A and B")
LEGS = (
    {"leg": 1, "table": "leg1_gulf_of_maine.csv", "buoy": "NDBC 44007", "location": "Gulf of Maine",
     "raw": "ndbc44007_hourly_hs_tz_1996-2005.txt"},
    {"leg": 2, "table": "leg2_cape_canaveral.csv", "buoy": "NDBC 41009", "location": "off Cape Canaveral",
     "raw": "ndbc41009_hourly_hs_tz_1996-2005.txt"},
)

log = logging.getLogger("make_default_route")


def route_edges(series_list):
    """Common bin edges for all legs: Hs from 0 in 0.5 m, Tz in whole seconds [m, s]."""
    hs_max = max(float(s["hs"].max()) for s in series_list)
    tz_min = min(float(s["tz"].min()) for s in series_list)
    tz_max = max(float(s["tz"].max()) for s in series_list)
    n_hs = max(1, math.ceil(hs_max / HS_WIDTH))
    hs_edges = HS_WIDTH * np.arange(n_hs + 1)
    tz_edges = TZ_WIDTH * np.arange(math.floor(tz_min / TZ_WIDTH), math.ceil(tz_max / TZ_WIDTH) + 1)
    return hs_edges, tz_edges


def leg_header(leg, series, ds):
    """The '# key: value' lines describing one leg's table and its provenance."""
    gaps = hindcast_gaps(series)
    steep = int(ds["count"].where(ds["steep"], 0).sum())
    return {
        "description": f"default route leg {leg['leg']}: Hs-Tz scatter, {leg['buoy']} ({leg['location']})",
        "leg": leg["leg"],
        "buoy": f"{leg['buoy']}, {leg['location']}",
        "years": f"{series.index[0].year}-{series.index[-1].year}",
        "records": len(series),
        "first_record": series.index[0].strftime("%Y-%m-%d %H:00 UTC"),
        "last_record": series.index[-1].strftime("%Y-%m-%d %H:00 UTC"),
        "missing_hours": gaps.missing_hours,
        "gaps": gaps.n_gaps,
        "longest_gap_hours": gaps.longest_gap_hours,
        "longest_gap_start": gaps.longest_gap_start.strftime("%Y-%m-%d %H:00 UTC") if gaps.n_gaps else "none",
        "coverage": f"{gaps.coverage:.4f}",
        "steep_records": f"{steep} (cell centre above the study steepness ceiling; flagged, kept)",
        "binning": "hs 0.5 m and tz 1 s bins, [lower, upper) with the last bin closed; same bins for every leg",
        "source_file": leg["raw"],
        "source_sha256": series.attrs["sha256"],
        "attribution": ATTRIBUTION,
        "generated_by": "scripts/make_default_route.py",
    }


def make_route(metocean: Path, out: Path) -> list[Path]:
    """Read both hindcasts, bin them on common edges and write one matrix CSV per leg."""
    series = [read_hindcast(Path(metocean) / leg["raw"]) for leg in LEGS]
    hs_edges, tz_edges = route_edges(series)
    written = []
    for leg, s in zip(LEGS, series):
        ds = bin_hindcast(s, hs_edges, tz_edges)
        path = write_scatter(ds, Path(out) / leg["table"], header=leg_header(leg, s, ds))
        log.info("%s: %d records -> %s", leg["raw"], ds.attrs["total"], path)
        written.append(path)
    return written


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("metocean", nargs="?", type=Path, default=DEFAULT_METOCEAN,
                   help="folder holding the NDBC hourly files (default: %(default)s)")
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, help="output folder (default: %(default)s)")
    args = p.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    make_route(args.metocean, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
