"""``jls forecast``: go or no-go on an hourly wave forecast for one leg of a route.

    jls forecast FILE --format partitions-csv --route default --leg gulf_of_maine \\
        --start 2026-01-05T00:00Z --course 200 [--issued ISO] [--json] [--pdf OUT.pdf]

Every forecast hour's sea state is built from its wave systems (:mod:`jls.sea.forecast`),
met at the vessel's heading (``--course``, or ``--waypoints``, or the leg's configured
course), and every option's criteria are evaluated hour by hour: the relative motions with
the function of ``jls response`` (:mod:`jls.response.sea_state`), the tip clearance and the
wire tensions from the same directional sea (:mod:`jls.stages.forecast`); alpha per lead time and Hs
(``forecast.alpha_factors`` with its source; without one alpha 1, stated) divides each
hour's utilisation. For each option: ``go`` (the whole leg, duration plus contingency,
stays inside from ``--start``), ``first_start`` (the first hour from which it does, or
null), the ``governing`` criterion and hour of the window from ``--start``, the margin,
and ``hourly``: per forecast hour its time, utilisation and systems as used.

The options are those of the route's last run (``results/<route>/plant_assessed.nc`` or
``plant.nc``, so the report's recommendation is the one checked) when it is up to date
with the configuration, else the configured candidates, built here; ``options_from``
says which.
"""

from __future__ import annotations

import json
import sys
import types
from pathlib import Path

from jls.commands.common import (
    config_files,
    config_option,
    heading,
    json_default,
    load_config,
    one_line_error,
)
from jls.config.forecast_entries import utc_time
from jls.errors import InputError

FORMATS = ("partitions-csv", "era5", "ww3", "spectra")


def add_parser(sub, pdf_writer=None):
    """The ``forecast`` subcommand; ``pdf_writer(ds, answer, path)`` writes ``--pdf`` (the
    report layer's, given by the command line)."""
    p = sub.add_parser("forecast", help="go or no-go on an hourly wave forecast for one leg: the first "
                       "start from which the leg stays inside the forecast limits, per option")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.add_argument("file", help="the forecast file")
    p.add_argument("--format", choices=FORMATS, default="partitions-csv", help="reader (default %(default)s)")
    p.add_argument("--spectra-format", choices=("ww3", "era5", "ndbc"), default="ww3",
                   help="reader of a --format spectra forecast (default %(default)s)")
    p.add_argument("--route", default="default", help="route of the configuration (default %(default)s)")
    p.add_argument("--leg", required=True, help="leg of the route to be sailed")
    p.add_argument("--start", default=None, help="planned start, ISO 8601 with offset (default: the "
                   "forecast's first hour)")
    p.add_argument("--issued", default=None, help="the forecast's issue time, ISO 8601 with offset "
                   "(lead times count from it; default: the forecast's first hour)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--course", type=float, default=None, help="the vessel's course [deg true]")
    where.add_argument("--waypoints", default=None, metavar="LAT,LON;LAT,LON;...",
                       help="the leg's track [deg], sailed at constant speed")
    p.add_argument("--results", default="results", help="folder of the workflow's datasets (default %(default)s)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.add_argument("--pdf", default=None, help="write the pre-transit report to this PDF")
    p.set_defaults(func=lambda args: run(args, pdf_writer))


def waypoints(text):
    out = []
    for part in str(text).split(";"):
        try:
            lat, lon = (float(v) for v in part.split(","))
        except ValueError:
            raise InputError("waypoints are LAT,LON;LAT,LON;... in degrees", field="--waypoints",
                             value=text) from None
        if not (-90 <= lat <= 90 and -180 <= lon <= 360):
            raise InputError("a waypoint outside latitude -90-90 or longitude -180-360 degrees",
                             field="--waypoints", value=part)
        out.append((lat, lon))
    return out


def options_transfer(cfg, route, base_dir, results):
    """The transfer of the route's assessed options (its last run's plant when up to date),
    and where the options come from."""
    from jls.commands.response import transfer_from_config
    from jls.config.dataset_hash import config_hash
    from jls.io.netcdf import problem, read
    variant = cfg.get("variant")
    root = Path(results) / ("variants/" + variant if variant else "") / route
    for name, file in (("plant", root / "plant_assessed.nc"), ("plant", root / "plant.nc")):
        if file.is_file() and problem(file, name, config_hash(cfg, name, route)) is None:
            plant = read(file, name)
            return transfer_from_config(cfg, base_dir, plant=plant), f"the route's last run ({file})"
    return transfer_from_config(cfg, base_dir), "the configured candidates (no up-to-date run of the route)"


def alpha_table(cfg):
    from jls.assessment.go_no_go import LeadTimeAlpha
    t = cfg["forecast"].get("alpha_factors")       # optional key: no default
    if t is None:
        return None
    return LeadTimeAlpha(t["source"], t["lead_time_h"], t["hs_m"], t["alpha"])


def forecast_answer(cfg, base_dir, file, fmt, route, leg, start=None, issued=None, course=None, track=None,
                    results="results", plant=None, plant_source=None, spectra_format="ww3"):
    """(dataset, JSON object) of a forecast check (the library call behind the command and
    the workflow's rule); ``plant``: the options' plant dataset (the workflow's assessed
    plant, named by ``plant_source``), else found as :func:`options_transfer` says."""
    from jls.sea.forecast import read_forecast
    from jls.stages.forecast import answer, evaluate, leg_plan
    if course is not None:
        heading("--course", course)
    plan = leg_plan(cfg, route, leg, course, track)
    gamma = {"wind": float(cfg["sea"]["gamma"]), "swell": float(cfg["sea"]["gamma"])}
    fc = read_forecast(file, fmt, gamma=gamma, spectra_format=spectra_format)
    start = fc.times[0] if start is None else utc_time(start, "--start")
    issued = fc.times[0] if issued is None else utc_time(issued, "--issued")
    if plant is None:
        tr, source = options_transfer(cfg, route, base_dir, results)
    else:
        from jls.commands.response import transfer_from_config
        tr, source = transfer_from_config(cfg, base_dir, plant=plant), f"the route's assessed plant ({plant_source})"
    ds = evaluate(fc, plan, tr, cfg, start, issued, alpha_table(cfg))
    ds.attrs["options_from"] = source
    out = answer(ds)
    out["options_from"] = source
    return ds, out


def run(args, pdf_writer=None) -> int:
    cfg, _ = load_config(args)
    cfg_path = config_files(args.config)[-1]
    base = Path.cwd() if (Path.cwd() / cfg["vessel"]["rao_file"]).exists() else cfg_path.parent
    track = None if args.waypoints is None else waypoints(args.waypoints)
    ds, out = forecast_answer(cfg, base, args.file, args.format, args.route, args.leg, args.start, args.issued,
                              args.course, track, args.results, spectra_format=args.spectra_format)
    if args.pdf:
        if pdf_writer is None:
            raise InputError("no PDF writer given to the forecast command", field="--pdf", value=args.pdf)
        pdf_writer(ds, out, args.pdf)
    if args.json:
        sys.stdout.write(json.dumps(out, default=json_default) + "\n")     # one line: the C encoder
        return 0
    print(f"Forecast {out['forecast']['file']} issued {out['issued']}; leg {out['leg']} of route "
          f"{out['route']} from {out['start']}: {out['duration_h']:g} h + {out['contingency_h']:g} h contingency")
    print(f"Alpha: {out['alpha_source']}. Options: {out['options_from']}.")
    if out["criteria_not_evaluated"]:
        print("NOT evaluated by the forecast check: " + ", ".join(out["criteria_not_evaluated"]))
    print(f"  {'candidate':<14}{'tugger':<12}{'go':<7}{'first start':<24}{'governing':<34}{'margin':>8}")
    for c, per in out["options"].items():
        for t, o in per.items():
            g = o["governing"]
            gov = f"{g['criterion']} at {g['hour']}" if g else "-"
            m = f"{100 * o['margin']:.0f} %" if o["margin"] is not None else "-"
            print(f"  {c:<14}{t:<12}{'GO' if o['go'] else 'NO-GO':<7}{o['first_start'] or 'none':<24}"
                  f"{gov:<34}{m:>8}" + ("" if o["go"] else f"  {o['reason']}"))
    return 0
