"""Relative wave headings of a leg from the vessel's course and the wave directions.

A leg gives its relative wave headings directly (``headings_deg`` with
``heading_probability``; beam seas, 90 deg, by default), or the vessel's course and the
directions the waves come from, and jls derives the relative headings.

Conventions (converted once, here):

* course: the direction the vessel heads, degrees true (clockwise from north);
  ``course_deg``, or ``waypoints`` (lat/lon in degrees) whose segments each sail on the
  great-circle initial bearing from one waypoint to the next, weighted by their share of
  the leg's great-circle distance;
* wave direction: the direction the waves come FROM, degrees true (the meteorological
  and buoy convention, e.g. NDBC MWD); ``wave_directions`` in the configuration and the
  ``direction`` column of a direction-resolved scatter table or hindcast;
* relative heading (WAMIT): the direction the waves travel, relative to the vessel's +x
  axis, counter-clockwise seen from above: 0 following seas, 90 beam seas from
  starboard (travelling toward port), 180 head seas, 270 beam seas from port.

The waves travel toward ``from + 180`` true; seen from the vessel, counter-clockwise,
that is ``beta = (course - from + 180) mod 360``.

Relative headings are binned to the nearest heading of a grid: the headings of the
vessel's RAOs (mirrored to 0-360 for a port/starboard-symmetric hull, as
:func:`jls.vessel.headings.select_headings` does), or multiples of the leg's
``heading_step_deg``. :func:`resolve` writes the result into each leg's
``headings_deg`` and ``heading_probability`` after validation, so the rest of jls sees
relative headings only, and records how they were obtained in ``heading_source``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jls.errors import InputError
from jls.sea.headings import heading_distribution, leg_courses, rao_grid, step_grid

#: how a leg's headings were obtained (leg key ``heading_source``, sea-state attribute
#: ``heading_source_<leg>``)
SOURCES = {
    "default": "not given: beam seas (90 deg) assumed",
    "given": "relative headings given in the configuration",
    "course_directions": "derived from the vessel's course and the configured wave directions",
    "direction_table": "derived from the vessel's course and the direction-resolved wave table",
}


def check_leg(leg: dict, field: str) -> None:
    """Input checks of a leg's heading keys before schema defaults are filled in: a
    course or waypoints excludes given relative headings, and directions need a course."""
    has_course = "course_deg" in leg or "waypoints" in leg
    if "course_deg" in leg and "waypoints" in leg:
        raise InputError("give the course either as course_deg or as waypoints, not both",
                         field=f"{field}.waypoints")
    for key in ("wave_directions", "heading_step_deg"):
        if key in leg and not has_course:
            raise InputError(f"{key} needs the vessel's course (course_deg or waypoints)",
                             field=f"{field}.{key}", value=leg[key])
    derived = leg.get("heading_source") in ("course_directions", "direction_table")
    if has_course and not derived:
        for key in ("headings_deg", "heading_probability"):
            if key in leg:
                raise InputError("a leg with the vessel's course takes its relative headings "
                                 f"from the wave directions: remove {key}", field=f"{field}.{key}",
                                 value=leg[key])
    if "wave_directions" in leg:
        wd = leg["wave_directions"]
        d, p = wd["from_deg"], wd["probability"]
        if len(d) != len(p) or abs(sum(p) - 1.0) > 1e-6:
            raise InputError("wave_directions needs one probability per direction, summing to 1",
                             field=f"{field}.wave_directions.probability", value=p)


def resolve(cfg: dict, base_dir=".", source="config") -> dict:
    """Write every leg's relative headings and ``heading_source`` (in place; returns cfg).

    Legs giving a course take their headings from ``wave_directions`` or, without them,
    from the direction marginal of their direction-resolved table (read here). The grid
    is the leg's ``heading_step_deg`` or the vessel's RAO headings (``vessel.bem``'s
    headings, or the RAO file's, read from ``base_dir``).
    """
    rao_headings = None
    for route, spec in cfg["routes"].items():
        for i, leg in enumerate(spec["legs"]):
            field = f"routes.{route}.legs[{i}]"
            if "course_deg" not in leg and "waypoints" not in leg:
                leg.setdefault("heading_source", "given")
                continue
            courses, weights = leg_courses(leg, field)
            if "heading_step_deg" in leg:
                grid = step_grid(leg["heading_step_deg"], f"{field}.heading_step_deg")
            else:
                if rao_headings is None:
                    rao_headings = _rao_headings(cfg["vessel"], base_dir, source)
                grid = rao_grid(rao_headings)
            if "wave_directions" in leg:
                from_deg = leg["wave_directions"]["from_deg"]
                prob = leg["wave_directions"]["probability"]
                leg["heading_source"] = "course_directions"
            else:
                from_deg, prob = _table_directions(leg, base_dir, field, cfg["sea"]["gamma"])
                leg["heading_source"] = "direction_table"
            hdg, hp = heading_distribution(courses, weights, from_deg, prob, grid)
            leg["headings_deg"] = [float(h) for h in hdg]
            leg["heading_probability"] = [float(p) for p in hp / hp.sum()]
    return cfg


def rao_headings(cfg: dict, base_dir=".") -> list[float]:
    """The vessel's RAO headings on 0-360 [deg] (mirrored for a symmetric hull, as the
    legs' derived headings are binned to): what a response over directional spectra,
    whose direction bins meet the vessel at every relative heading, needs."""
    return [float(h) for h in rao_grid(_rao_headings(cfg["vessel"], base_dir, "config"))]


def _rao_headings(vessel: dict, base_dir, source):
    if "bem" in vessel:
        return vessel["bem"]["headings_deg"]
    path = Path(base_dir) / vessel["rao_file"]
    if not path.exists():
        raise InputError("binning a leg's headings to the vessel's RAO headings needs the RAO "
                         "file: it is missing (or give the leg a heading_step_deg)", file=path,
                         field="vessel.rao_file")
    from jls.vessel.headings import read_vessel_rao
    return np.degrees(read_vessel_rao(vessel, path)["wave_direction"].values)


def _with_key(message: str, key: str, name: str) -> str:
    """A data file's error message naming the configuration key that gives the file in
    full (``routes.<route>.legs[<i>]...`` for ``legs[<name>]...``)."""
    short = f"the file given by legs[{name}]."
    if short in message:
        return message.replace(short, f"the file given by {key.split('.legs[')[0]}.legs["
                               f"{key.split('.legs[')[1].split(']')[0]}].", 1)
    if "the file given by" in message:
        return message
    return f"{message} (the file given by {key})"


def _table_directions(leg: dict, base_dir, field, gamma):
    """(directions [deg from, true], marginal probabilities) of a leg's table."""
    from jls.sea.legs import read_table
    from jls.sea.records import leg_kind
    kind = leg_kind(leg)
    key = f"{field}.{'scatter' if kind == 'scatter' else kind + '.file'}"
    try:
        ds = read_table(leg, base_dir, gamma)
    except InputError as exc:           # a data file's error: its file and line, and the key
        raise InputError(_with_key(exc.message, key, leg["name"]), file=exc.file, field=exc.field,
                         value=exc.value) from None
    if "direction" not in ds.dims:
        raise InputError("a leg with the vessel's course needs wave_directions or a "
                         "direction-resolved table (a direction column)", field=f"{field}.wave_directions")
    p = ds["probability"].sum(("hs", "tz"))
    return ds["direction"].values, p.values / float(p.sum())
