"""``jls response``: the frequency-domain statistics of one sea state for the configured
candidates and tugger settings: sigma, Tz of the response and the MPM over the exposure
(``assessment.exposure_h``) per criterion (:mod:`jls.response.sea_state`).

The sea state is one or more wave systems:

* ``--hs HS --tp TP`` (or ``--tz TZ``) ``--spectrum jonswap|pm|torsethaugen`` with
  ``--gamma`` (JONSWAP; default ``sea.gamma``), met at the relative heading ``--heading``
  (WAMIT: 90 is a beam sea), spread by ``--spreading`` (cos2s:S, cosn:N, long-crested;
  default ``sea.spreading`` of its kind: a JONSWAP or PM is a wind sea, a Torsethaugen sea
  state is split into its wind sea and swell, each with its own default);
* and any number of ``--system HS,TP,DIR_FROM,GAMMA,SPREADING``: a JONSWAP system from
  DIR_FROM [deg true]. Its kind (for the report) is swell when TP exceeds 6.6 HS^(1/3), the
  Torsethaugen Tf of a fully developed sea, else wind sea.

``--vessel-heading DEG`` is the vessel's heading [deg true]; without it the directions of
``--system`` are taken relative to the bow (the vessel heading 0, stated in the output).

    jls response --hs 2 --tp 12 --spectrum torsethaugen --heading 90 --json
    jls response --system 1.5,7,250,3.3,cos2s:4 --system 1,16,300,5,cos2s:13 --vessel-heading 200
"""

from __future__ import annotations

import json
import math
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
from jls.errors import InputError

SPECTRA = ("jonswap", "pm", "torsethaugen")


def add_parser(sub):
    p = sub.add_parser("response", help="sigma, Tz and MPM of the relative motions in one sea state "
                       "(one or more directional wave systems), per candidate and tugger")
    p.error = types.MethodType(one_line_error, p)
    config_option(p)
    p.add_argument("--hs", type=float, help="significant wave height [m] of the sea state (or first system)")
    per = p.add_mutually_exclusive_group()
    per.add_argument("--tp", type=float, help="peak period [s]")
    per.add_argument("--tz", type=float, help="zero-up-crossing period [s] (turned into Tp by the shape's relation)")
    p.add_argument("--spectrum", choices=SPECTRA, default="jonswap", help="spectrum shape (default %(default)s)")
    p.add_argument("--gamma", type=float, default=None, help="JONSWAP peak enhancement (default: sea.gamma)")
    p.add_argument("--heading", type=float, default=None,
                   help="relative heading of the waves [deg] (WAMIT, 90 beam; default 90)")
    p.add_argument("--spreading", default=None,
                   help="cos2s:S, cosn:N or long-crested (default: sea.spreading of the system's kind)")
    p.add_argument("--system", action="append", default=[], metavar="HS,TP,DIR_FROM,GAMMA,SPREADING",
                   help="a JONSWAP wave system from DIR_FROM [deg true] (repeatable)")
    p.add_argument("--spectra", metavar="FILE", help="a measured or hindcast spectra file (jls spectrum) "
                   "instead of --hs: its record at --time")
    p.add_argument("--format", choices=("ndbc", "ww3", "era5"), help="reader of --spectra")
    p.add_argument("--time", help="the record of --spectra (ISO 8601, UTC; the nearest within 30 min)")
    p.add_argument("--vessel-heading", type=float, default=None,
                   help="the vessel's heading [deg true] (directions of --system are true)")
    p.add_argument("--json", action="store_true", help="print JSON for scripts")
    p.set_defaults(func=run)


def _number(text, field):
    try:
        v = float(text)
    except ValueError:
        raise InputError("not a number", field=field, value=text) from None
    if not math.isfinite(v):
        raise InputError("not a finite number", field=field, value=text)
    return v


def _spectra_systems(args, default, course):
    """The systems of the --spectra record at --time: one long-crested system per direction
    bin of a directional spectrum (directions true), or the 1-D spectrum at --heading
    spread by --spreading (default sea.spreading.wind)."""
    import numpy as np
    import pandas as pd

    from jls.sea.measured import read_spectra
    from jls.sea.sea_state import measured_systems
    if args.hs is not None:
        raise InputError("give --hs or --spectra, not both", field="--spectra", value=args.spectra)
    if args.format is None or args.time is None:
        raise InputError("--spectra needs --format and --time", field="--format" if args.format is None else "--time")
    try:
        when = pd.Timestamp(args.time)
    except ValueError:
        raise InputError("not an ISO 8601 time", field="--time", value=args.time) from None
    when = (when.tz_convert("UTC").tz_localize(None) if when.tzinfo else when).to_datetime64()
    efth = read_spectra(args.spectra, args.format)
    times = efth["time"].values
    k = int(np.argmin(np.abs(times - when)))
    if abs(times[k] - when) > np.timedelta64(30, "m"):
        raise InputError(f"no record within 30 min (the file covers {str(times[0])[:16]} to "
                         f"{str(times[-1])[:16]})", file=args.spectra, field="--time", value=args.time)
    rec = efth.isel(time=k)
    if "dir" in rec.dims:
        if args.heading is not None or args.spreading is not None:
            raise InputError("a directional spectrum carries its own directions and spreading",
                             field="--heading" if args.heading is not None else "--spreading")
        return measured_systems(rec["freq"].values, rec.transpose("freq", "dir").values, rec["dir"].values)
    beta = 90.0 if args.heading is None else args.heading
    heading("--heading", beta)
    return measured_systems(rec["freq"].values, rec.values, from_deg=(course + 180.0 - beta) % 360.0,
                            spreading=args.spreading or default["wind"])


def _kind(hs, tp):
    return "swell" if tp > 6.6 * hs ** (1.0 / 3.0) else "wind"


def sea_state_from_args(args, cfg) -> tuple[list, float, str]:
    """(systems, vessel heading [deg true], how directions are taken) of the options."""
    from jls.sea.sea_state import parse_spreading, torsethaugen_systems, wave_system
    default = cfg["sea"]["spreading"]
    course = 0.0 if args.vessel_heading is None else args.vessel_heading
    heading("--vessel-heading", course)
    systems = []
    if args.hs is not None:
        if args.tp is None and args.tz is None:
            raise InputError("give the period of --hs: --tp or --tz", field="--tp")
        if not (math.isfinite(args.hs) and 0 < args.hs <= 30):
            raise InputError("must be a number in (0, 30]", field="--hs", value=args.hs)
        period, value = ("tp", args.tp) if args.tp is not None else ("tz", args.tz)
        if not (math.isfinite(value) and 0 < value <= 40):
            raise InputError("must be a number in (0, 40] s", field=f"--{period}", value=value)
        beta = 90.0 if args.heading is None else args.heading
        heading("--heading", beta)
        from_deg = (course + 180.0 - beta) % 360.0          # met at beta on the vessel's heading
        if args.spectrum == "torsethaugen":
            if args.gamma is not None:
                raise InputError("a Torsethaugen sea state sets its own gammas", field="--gamma", value=args.gamma)
            spread = ({"wind": args.spreading, "swell": args.spreading} if args.spreading else default)
            systems += torsethaugen_systems(args.hs, period, value, from_deg=from_deg, spreading=spread)
        else:
            gamma = cfg["sea"]["gamma"] if args.gamma is None else args.gamma
            spread = parse_spreading(args.spreading or default["wind"], "--spreading")
            systems.append(wave_system(args.spectrum, args.hs, period, value, gamma=gamma,
                                       from_deg=from_deg, spreading=spread))
    elif args.spectra is not None:
        systems += _spectra_systems(args, default, course)
    elif args.tp is not None or args.tz is not None or args.heading is not None:
        raise InputError("--tp, --tz and --heading describe the sea state of --hs: give --hs", field="--hs")
    for i, text in enumerate(args.system):
        field = f"--system {text}"
        parts = [s.strip() for s in text.split(",")]
        if len(parts) != 5:
            raise InputError("expected HS,TP,DIR_FROM,GAMMA,SPREADING (five fields)", field=field, value=text)
        hs, tp, d, g = (_number(v, f"{field}: {n}") for v, n in zip(parts[:4], ("HS", "TP", "DIR_FROM", "GAMMA")))
        if not 0 < hs <= 30:
            raise InputError("HS must be in (0, 30] m", field=field, value=hs)
        if not 0 < tp <= 40:
            raise InputError("TP must be in (0, 40] s", field=field, value=tp)
        if not 0 <= d <= 360:
            raise InputError("DIR_FROM must be in [0, 360] degrees (from, true)", field=field, value=d)
        if not 1 <= g <= 20:
            raise InputError("GAMMA must be in [1, 20]", field=field, value=g)
        systems.append(wave_system("jonswap", hs, "tp", tp, gamma=g, from_deg=d % 360.0,
                                   spreading=parse_spreading(parts[4], field), kind=_kind(hs, tp)))
    if not systems:
        raise InputError("no sea state: give --hs with --tp or --tz, --spectra, or --system", field="--hs")
    how = ("true; the vessel heads " + f"{course:g} deg" if args.vessel_heading is not None else
           "relative to the bow (no --vessel-heading: the vessel's heading is taken as 0 deg)")
    return systems, course, how


def response_summary(ds, systems, course, how) -> dict:
    """The JSON object of ``jls response`` from :func:`jls.response.sea_state.sea_state_statistics`."""
    from jls.names import CRITERIA
    from jls.sea.headings import relative_heading
    from jls.sea.sea_state import SeaState
    sea = SeaState(tuple(systems))
    out = {"sea_state": {"hs_m": sea.hs, "vessel_heading_deg": course, "directions": how,
                         "energy_outside_rao_range": float(ds["energy_outside"].values[0]),
                         "systems": [{"kind": s.kind, "spectrum": s.shape, "hs_m": s.hs, "tp_s": s.tp,
                                      "gamma": s.gamma, "from_deg": s.from_deg,
                                      "relative_heading_deg": float(relative_heading(course, s.from_deg)),
                                      "spreading": str(s.spreading), "spread_deg": s.spreading.spread_deg()}
                                     for s in systems]},
           "exposure_h": ds.attrs["exposure_h"], "mpm_cycles": ds.attrs["mpm_cycles"],
           "units": {c: CRITERIA[c][1] for c in ds["criterion"].values.tolist()},
           "candidates": {}}
    for c in ds["candidate"].values.tolist():
        per = out["candidates"].setdefault(str(c), {})
        for t in ds["tugger"].values.tolist():
            row = ds.sel(sea_state=0, candidate=c, tugger=t)
            per[str(t)] = {str(k): {"sigma": float(row["sigma"].sel(criterion=k)),
                                    "tz_response": float(row["tz_response"].sel(criterion=k)),
                                    "mpm": float(row["mpm"].sel(criterion=k))}
                           for k in ds["criterion"].values.tolist()}
    return out


def transfer_from_config(cfg: dict, base_dir=".", plant=None):
    """The :class:`jls.response.sea_state.SeaStateTransfer` of a validated configuration: its candidates (the
    baseline and ``candidates``), its tugger settings, the vessel motion at every heading of
    the RAO file over the whole circle (mirrored for a symmetric hull), the response's
    frequency step and the stated zero-motion bands (``plant``: another plant dataset, e.g.
    a run's assessed candidates, instead of the configured ones). Built once; every sea state (an hour of
    a forecast, a cell, a record) then costs one call of :func:`sea_state_statistics`."""
    import numpy as np

    from jls.config.builders import tuggers_from_config
    from jls.response.sea_state import sea_state_transfer
    from jls.sea.headings import rao_grid
    from jls.stages.plant import plant as plant_of
    from jls.stages.vessel_motion import vessel_motion
    from jls.vessel.headings import read_vessel_rao

    vessel = cfg["vessel"]
    rao = read_vessel_rao(vessel, Path(base_dir) / vessel["rao_file"])
    heads = rao_grid(np.degrees(rao["wave_direction"].values))
    motion = vessel_motion(vessel, heads, base_dir=base_dir)
    tuggers = {n: float(t.c) for n, t in tuggers_from_config(cfg).items()}
    return sea_state_transfer(plant_of(cfg) if plant is None else plant, motion, tuggers, float(cfg["response"]["omega_step_rad_s"]),
                              vessel.get("outside_rao_range"))


def run(args) -> int:
    from jls.response.sea_state import sea_state_statistics
    cfg, _ = load_config(args)
    cfg_path = config_files(args.config)[-1]
    systems, course, how = sea_state_from_args(args, cfg)
    base = Path.cwd() if (Path.cwd() / cfg["vessel"]["rao_file"]).exists() else cfg_path.parent
    tr = transfer_from_config(cfg, base)
    a = cfg["assessment"]
    ds = sea_state_statistics(tr, [systems], course, exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                              source=str(cfg_path))
    out = response_summary(ds, systems, course, how)
    if args.json:
        json.dump(out, sys.stdout, indent=1, default=json_default)
        sys.stdout.write("\n")
        return 0
    s = out["sea_state"]
    print(f"Sea state Hs {s['hs_m']:.3g} m, vessel heading {course:g} deg ({how}); "
          f"{100 * s['energy_outside_rao_range']:.2f} % of the energy outside the RAO range")
    for x in s["systems"]:
        print(f"  {x['kind']:<6}{x['spectrum']:<13}Hs {x['hs_m']:6.3f} m  Tp {x['tp_s']:6.2f} s  gamma "
              f"{x['gamma']:5.2f}  from {x['from_deg']:6.1f} deg (relative {x['relative_heading_deg']:5.1f})  "
              f"{x['spreading']}")
    print(f"Statistics over {out['exposure_h']:g} h (MPM cycles: {out['mpm_cycles']})")
    print(f"  {'candidate':<14}{'tugger':<12}{'criterion':<20}{'sigma':>10}{'Tz s':>8}{'MPM':>10}")
    for c, per in out["candidates"].items():
        for t, crit in per.items():
            for k, v in crit.items():
                print(f"  {c:<14}{t:<12}{k:<20}{v['sigma']:10.4g}{v['tz_response']:8.2f}{v['mpm']:10.4g}")
    return 0
