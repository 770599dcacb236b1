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
:func:`jls.stages.vessel_motion.select_headings` does), or multiples of the leg's
``heading_step_deg``. :func:`resolve` writes the result into each leg's
``headings_deg`` and ``heading_probability`` after validation, so the rest of jls sees
relative headings only, and records how they were obtained in ``heading_source``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jls.errors import InputError

#: how a leg's headings were obtained (leg key ``heading_source``, sea-state attribute
#: ``heading_source_<leg>``)
SOURCES = {
    "default": "not given: beam seas (90 deg) assumed",
    "given": "relative headings given in the configuration",
    "course_directions": "derived from the vessel's course and the configured wave directions",
    "direction_table": "derived from the vessel's course and the direction-resolved wave table",
}
EARTH_RADIUS_M = 6_371_008.8          # mean radius (IUGG); only ratios of distances are used


def relative_heading(course_deg, from_deg):
    """WAMIT relative heading [deg, 0-360) of waves coming from ``from_deg`` (true) met
    by a vessel heading ``course_deg`` (true); broadcast."""
    return np.mod(np.asarray(course_deg, float) - np.asarray(from_deg, float) + 180.0, 360.0)


def initial_bearing(lat1, lon1, lat2, lon2):
    """Great-circle initial bearing [deg true, 0-360) from point 1 to point 2 [deg]."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dl = np.radians(np.asarray(lon2, float) - np.asarray(lon1, float))
    y = np.sin(dl) * np.cos(p2)
    x = np.cos(p1) * np.sin(p2) - np.sin(p1) * np.cos(p2) * np.cos(dl)
    return np.mod(np.degrees(np.arctan2(y, x)), 360.0)


def great_circle_distance(lat1, lon1, lat2, lon2, radius=EARTH_RADIUS_M):
    """Great-circle (haversine) distance [m] between points given in degrees."""
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dp, dl = p2 - p1, np.radians(np.asarray(lon2, float) - np.asarray(lon1, float))
    a = np.sin(dp / 2) ** 2 + np.cos(p1) * np.cos(p2) * np.sin(dl / 2) ** 2
    return 2.0 * radius * np.arcsin(np.sqrt(np.clip(a, 0.0, 1.0)))


def leg_courses(leg: dict, field="leg"):
    """(courses [deg true], weights summing to 1) of a leg's course or waypoints."""
    if "course_deg" in leg:
        return np.array([float(leg["course_deg"]) % 360.0]), np.array([1.0])
    pts = np.array([[w["lat_deg"], w["lon_deg"]] for w in leg["waypoints"]], float)
    a, b = pts[:-1], pts[1:]
    dist = great_circle_distance(a[:, 0], a[:, 1], b[:, 0], b[:, 1])
    if not dist.sum() > 0:
        raise InputError("the waypoints do not move: the leg has no length",
                         field=f"{field}.waypoints", value=pts.tolist())
    return initial_bearing(a[:, 0], a[:, 1], b[:, 0], b[:, 1]), dist / dist.sum()


def step_grid(step_deg, field="heading_step_deg"):
    """Headings 0, step, ... below 360 [deg]; the step must divide 360."""
    n = 360.0 / float(step_deg)
    if abs(n - round(n)) > 1e-9:
        raise InputError("the heading step must divide 360 deg", field=field, value=step_deg)
    return np.arange(int(round(n))) * float(step_deg)


def rao_grid(rao_headings_deg):
    """The RAO's headings [deg] in 0-360, mirrored when they cover 0-180 only (a
    port/starboard-symmetric hull, as :func:`jls.stages.vessel_motion.select_headings` assumes)."""
    h = np.mod(np.asarray(rao_headings_deg, float), 360.0)
    if h.max() <= 180.0 + 1e-9:
        h = np.concatenate([h, np.mod(360.0 - h, 360.0)])
    return np.unique(np.round(h, 6))


def nearest(headings_deg, grid_deg):
    """Index of the nearest grid heading (circular distance; the first on a tie)."""
    d = np.abs(np.mod(np.asarray(headings_deg, float)[..., None] - np.asarray(grid_deg, float) + 180.0,
                      360.0) - 180.0)
    return np.argmin(d, axis=-1)


def direction_map(courses_deg, weights, from_deg, grid_deg):
    """Matrix (direction, grid heading): the share of each wave direction met at each
    relative heading of the grid, over the leg's course segments (rows sum to 1)."""
    beta = relative_heading(np.asarray(courses_deg, float)[None, :], np.asarray(from_deg, float)[:, None])
    idx = nearest(beta, grid_deg)                                  # (direction, segment)
    out = np.zeros((idx.shape[0], len(grid_deg)))
    rows = np.repeat(np.arange(idx.shape[0]), idx.shape[1])
    np.add.at(out, (rows, idx.ravel()), np.tile(np.asarray(weights, float), idx.shape[0]))
    return out


def heading_distribution(courses_deg, weights, from_deg, probability, grid_deg):
    """(headings [deg], probabilities) met on the leg: the grid headings that carry
    probability, ascending."""
    p = np.asarray(probability, float) @ direction_map(courses_deg, weights, from_deg, grid_deg)
    keep = p > 0
    return np.asarray(grid_deg, float)[keep], p[keep]


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
                from_deg, prob = _table_directions(leg, base_dir, field)
                leg["heading_source"] = "direction_table"
            hdg, hp = heading_distribution(courses, weights, from_deg, prob, grid)
            leg["headings_deg"] = [float(h) for h in hdg]
            leg["heading_probability"] = [float(p) for p in hp / hp.sum()]
    return cfg


def _rao_headings(vessel: dict, base_dir, source):
    if "bem" in vessel:
        return vessel["bem"]["headings_deg"]
    path = Path(base_dir) / vessel["rao_file"]
    if not path.exists():
        raise InputError("binning a leg's headings to the vessel's RAO headings needs the RAO "
                         "file: it is missing (or give the leg a heading_step_deg)", file=path,
                         field="vessel.rao_file")
    from jls.stages.vessel_motion import read_vessel_rao
    return np.degrees(read_vessel_rao(vessel, path)["wave_direction"].values)


def _table_directions(leg: dict, base_dir, field):
    """(directions [deg from, true], marginal probabilities) of a leg's table."""
    from jls.stages.sea_states import read_table
    ds = read_table(leg, base_dir)
    if "direction" not in ds.dims:
        raise InputError("a leg with the vessel's course needs wave_directions or a "
                         "direction-resolved table (a direction column)", field=f"{field}.wave_directions")
    p = ds["probability"].sum(("hs", "tz"))
    return ds["direction"].values, p.values / float(p.sum())
