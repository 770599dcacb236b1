"""Geometry of wave directions: relative headings from a course and the direction the
waves come from, great-circle bearings and distances of waypoints, and heading grids.

Conventions: the course is the direction the vessel heads (degrees true); a wave
direction is where waves come FROM (degrees true); a relative heading (WAMIT) is the
direction the waves travel relative to the vessel's +x axis, counter-clockwise seen from
above (0 following, 90 beam from starboard, 180 head seas):
``beta = (course - from + 180) mod 360``. See :mod:`jls.config.headings` for how a leg's
headings are resolved.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError

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
    port/starboard-symmetric hull, as :func:`jls.vessel.headings.select_headings` assumes)."""
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


def hour_headings(leg: dict, direction) -> np.ndarray:
    """Weight (n_time, n_heading) of each of the leg's relative headings (``headings_deg``)
    in each hour, the share the hour is met at it (rows sum to 1, or 0 for an hour the
    leg's direction bins leave out): the leg's heading probabilities in every hour, or,
    for a leg whose headings come from its own directions (``heading_source:
    direction_table``), the hour's mean direction binned as the leg's sea states bin it
    (the direction bin's centre on each course segment, :func:`direction_map`)."""
    from jls.sea.hindcast import direction_bins
    from jls.sea.records import leg_kind
    grid = np.asarray(leg["headings_deg"], float)
    d = np.asarray(direction, float)
    if leg.get("heading_source") != "direction_table":
        return np.broadcast_to(np.asarray(leg["heading_probability"], float), (d.size, grid.size)).copy()
    idx, centres = direction_bins(np.where(np.isfinite(d), d, 0.0), leg[leg_kind(leg)]["dir_edges_deg"])
    idx = np.where(np.isfinite(d), idx, -1)
    courses, weights = leg_courses(leg, f"legs[{leg['name']}]")
    out = np.zeros((d.size, grid.size))
    inside = idx >= 0
    out[inside] = direction_map(courses, weights, centres[idx[inside]], grid)
    return out
