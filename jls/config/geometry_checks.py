"""Geometry that cannot be, and job preconditions, checked when the configuration is read.

Each value here passes the schema alone; together they place a point where no point of a
heavy lift can be. Every error names the key and the two numbers that contradict:

* the tugger fairleads below the waterline (``vessel.fairlead_drop_m`` against the hinge's
  height above the water, ``rigging.limits.hinge_height_m``);
* any point of the lift system below the waterline: the lift-beam anchors and the padeyes
  of the baseline and of every named candidate (its ``drop_height_m``);
* a splash clearance the baseline's jacket tip cannot keep (the tip's height above the
  still water: hinge height - drop - ``padeye_to_tip_m``);
* tip points (``assessment.tip_clearance.tip_offsets_m``) outside the jacket's plan
  envelope: ``jacket.envelope_half_m`` when given, else :data:`ENVELOPE_FACTOR` times the
  padeyes' largest plan offsets from the CoG (a jacket's legs batter outward below its
  lifting points, so its bottom is wider, but not by more than that);
* job preconditions: a winch capacity equal to (or below) its floor, for the tugger
  settings and the slope sweep (the jobs refused it after datasets were written);
* an empty file name for a file key (``""`` names no file; it read as the folder);
* the verification's design corner at a heading a route does not have;
* a sea state named for a study (time-domain cells, the slope sweep, the verification's
  design corner, the screening envelope) steeper than breaking waves.

:func:`check_geometry` raises :class:`jls.errors.InputError`; it is called by
:func:`jls.config.cross_checks.check_values`, so ``jls check``, the workflow's parse and
every command see it.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError

#: Tip points may lie this many times the padeyes' largest plan offset from the CoG
#: when the configuration states no envelope (jacket.envelope_half_m).
ENVELOPE_FACTOR = 2.0
#: The smallest height above the still water of any point of the lift system [m].
MIN_HEIGHT_M = 0.0


def configured_drops(cfg) -> list[tuple[str, float]]:
    """(key, drop height [m]) of the baseline, the named candidates and the grid."""
    rig = cfg["rigging"]
    drops = [("rigging.h_drop_m", float(rig["h_drop_m"]))]
    drops += [(f"candidates[{k}].drop_height_m", float(c["drop_height_m"]))
              for k, c in enumerate(cfg["candidates"] if "candidates" in cfg else [])
              if "drop_height_m" in c]
    grid = cfg["candidate_grid"] if "candidate_grid" in cfg else {}
    drops += [(f"candidate_grid.drop_height_m[{k}]", float(d))
              for k, d in enumerate(grid["drop_height_m"] if "drop_height_m" in grid else [])]
    return drops


def check_geometry(cfg: dict, source="config") -> None:
    """Every check of the module docstring (a validated configuration, defaults filled)."""
    _check_file_keys(cfg, source)
    _check_winch_floors(cfg, source)
    _check_sea_states(cfg, source)
    _check_corner_heading(cfg, source)
    if "plant_matrices" in cfg or "jacket" not in cfg or "rigging" not in cfg:
        return
    limits = cfg["rigging"]["limits"]
    if "hinge_height_m" not in limits:
        return
    hinge = float(limits["hinge_height_m"])
    _check_fairleads(cfg, hinge, source)
    _check_lift_points(cfg, hinge, source)
    _check_splash(cfg, hinge, source)
    _check_tip_points(cfg, source)


def _check_file_keys(cfg, source):
    vessel = cfg["vessel"] if "vessel" in cfg else {}
    keys = [("vessel.rao_file", vessel["rao_file"])] if "rao_file" in vessel else []
    for route, spec in (cfg["routes"] if "routes" in cfg else {}).items():
        for i, leg in enumerate(spec["legs"]):
            where = f"routes.{route}.legs[{i}]"
            if "scatter" in leg:
                keys.append((f"{where}.scatter", leg["scatter"]))
            for kind in ("hindcast", "metocean", "spectra"):
                if kind in leg:
                    keys.append((f"{where}.{kind}.file", leg[kind]["file"]))
    for field, value in keys:
        if isinstance(value, str) and not value.strip():
            raise InputError("an empty file name names no file: give the file's path",
                             file=source, field=field, value=value)


def _check_winch_floors(cfg, source):
    for i, t in enumerate(cfg["tuggers"]):
        cap, floor = t["max_force_kN"], t["min_force_kN"]
        if not float(cap) > float(floor):
            raise InputError(f"winch capacity {float(cap):g} kN must exceed the no-slack floor "
                             f"{float(floor):g} kN (tuggers[{i}].min_force_kN): the pretension lies "
                             "midway and a line with no range between the two cannot damp",
                             file=source, field=f"tuggers[{i}].max_force_kN", value=cap)
    sweep = cfg["timedomain"]["slope_sweep"]
    cap, floor = sweep["capacity_kN"], sweep["floor_kN"]
    if not float(cap) > float(floor):
        raise InputError(f"winch capacity {float(cap):g} kN must exceed the no-slack floor "
                         f"{float(floor):g} kN (timedomain.slope_sweep.floor_kN)", file=source,
                         field="timedomain.slope_sweep.capacity_kN", value=cap)


def _check_sea_states(cfg, source):
    """The sea states the configuration names for a study (time-domain cells, the slope
    sweep, the verification's design corner, the screening envelope) no steeper than
    breaking waves (:func:`jls.sea.steepness.require_not_breaking`): the jobs would run
    them and print results for a sea that cannot exist."""
    from jls.sea.steepness import require_not_breaking
    td = cfg["timedomain"]
    states = [(f"timedomain.cells[{i}].hs_m", f"timedomain.cells[{i}].tz_s", c["hs_m"], c["tz_s"])
              for i, c in enumerate(td["cells"])]
    sw = td["slope_sweep"]
    states += [("timedomain.slope_sweep.hs_m", f"timedomain.slope_sweep.tz_s[{j}]", sw["hs_m"], tz)
               for j, tz in enumerate(sw["tz_s"])]
    corner = cfg["verification"]["design_corner"]
    if corner["enabled"]:
        states.append(("verification.design_corner.hs_m", "verification.design_corner.tz_s",
                       corner["hs_m"], corner["tz_s"]))
    if cfg["screening"]["enabled"]:
        env = cfg["screening"]["envelope"]
        states.append(("screening.envelope.hs_m", "screening.envelope.tz_min_s", env["hs_m"],
                       env["tz_min_s"]))
    for hs_key, tz_key, hs, tz in states:
        try:
            require_not_breaking(hs, tz, g=float(cfg["g_m_per_s2"]), fields=(hs_key, tz_key))
        except InputError as exc:
            raise InputError(exc.message, file=source, field=hs_key, value=hs) from None


def _check_corner_heading(cfg, source):
    """The verification's design corner at a relative heading of every route: its cell
    takes the route's response there (the workability job refused it, after the
    response datasets were written)."""
    corner = cfg["verification"]["design_corner"]
    if not (cfg["verification"]["enabled"] and corner["enabled"]):
        return
    h = float(corner["heading_deg"])
    for route, spec in cfg["routes"].items():
        have = sorted({float(x) for leg in spec["legs"] for x in leg["headings_deg"]})
        if not any(abs(h - x) < 1e-6 for x in have):
            raise InputError(f"not a relative heading of route '{route}' ({', '.join(f'{x:g}' for x in have)} "
                             "deg): the design corner's cell takes the route's response at its heading",
                             file=source, field="verification.design_corner.heading_deg",
                             value=corner["heading_deg"])


def _check_fairleads(cfg, hinge, source):
    drop = float(cfg["vessel"]["fairlead_drop_m"])
    if hinge - drop < MIN_HEIGHT_M:
        raise InputError(f"the tugger fairleads {drop:g} m below the hinge would sit "
                         f"{drop - hinge:.2f} m below the waterline (the hinge is {hinge:.2f} m "
                         "above it, rigging.limits.hinge_height_m): fairleads are on deck or "
                         "on the lift beams, above the water", file=source,
                         field="vessel.fairlead_drop_m", value=cfg["vessel"]["fairlead_drop_m"])


def _padeye_heights(cfg, hinge, drop):
    """Heights above the still water of the padeyes for a drop height [m]."""
    rig, jacket = cfg["rigging"], cfg["jacket"]
    cog = hinge - drop - float(jacket["z_p_m"])
    return [cog + float(w["padeye_m"][2]) for w in rig["wires"]]


def _check_lift_points(cfg, hinge, source):
    rig = cfg["rigging"]
    for i, w in enumerate(rig["wires"]):
        z = hinge + float(w["anchor_m"][2])
        if z < MIN_HEIGHT_M:
            raise InputError(f"the anchor of wire '{w['name']}' would sit {-z:.2f} m below the "
                             f"waterline (hinge {hinge:.2f} m above it, anchor z "
                             f"{float(w['anchor_m'][2]):g} m from the hinge)", file=source,
                             field=f"rigging.wires[{i}].anchor_m", value=w["anchor_m"])
    for field, drop in configured_drops(cfg):
        heights = _padeye_heights(cfg, hinge, drop)
        low = int(np.argmin(heights))
        if heights[low] < MIN_HEIGHT_M:
            raise InputError(f"the padeye of wire '{rig['wires'][low]['name']}' would sit "
                             f"{-heights[low]:.2f} m below the waterline: the hinge is {hinge:.2f} m "
                             f"above it and the drop {drop:g} m (a jacket is lifted clear of the "
                             "water in transit)", file=source, field=field, value=drop)


def _check_splash(cfg, hinge, source):
    lim = cfg["rigging"]["limits"]
    drop = float(cfg["rigging"]["h_drop_m"])
    tip = hinge - drop - float(lim["padeye_to_tip_m"])
    clearance = float(lim["splash_clearance_m"])
    if clearance > tip:
        space = cfg["rigging"]["design_space"]
        space = space["drop_height_m"] if "drop_height_m" in space else None
        lowest = None
        if space is not None:
            lo = space["bounds"][0] if isinstance(space, dict) else space[0]
            lowest = hinge - float(lo) - float(lim["padeye_to_tip_m"])
        more = ("" if lowest is None else
                f"; at the design space's shortest drop, {lowest:.2f} m")
        raise InputError(f"a splash clearance of {clearance:g} m is more than the baseline's jacket "
                         f"tip height above the still water, {tip:.2f} m (hinge {hinge:.2f} m - drop "
                         f"{drop:g} m - padeye to tip {float(lim['padeye_to_tip_m']):g} m){more}: the "
                         "baseline the report compares with would be excluded; check the clearance "
                         "and the tip's depth below the padeyes", file=source,
                         field="rigging.limits.splash_clearance_m", value=lim["splash_clearance_m"])


def jacket_envelope(cfg) -> tuple[np.ndarray, str]:
    """(half-extents [x, y] from the CoG [m], where they come from) of the jacket's plan."""
    if "envelope_half_m" in cfg["jacket"]:            # optional key: no default
        return np.abs(np.asarray(cfg["jacket"]["envelope_half_m"], float)), "jacket.envelope_half_m"
    pad = np.abs(np.array([w["padeye_m"][:2] for w in cfg["rigging"]["wires"]], float)).max(axis=0)
    return ENVELOPE_FACTOR * pad, (f"{ENVELOPE_FACTOR:g} x the padeyes' largest offsets "
                                   f"{pad[0]:.1f}, {pad[1]:.1f} m; jacket.envelope_half_m states it")


def _check_tip_points(cfg, source):
    tc = cfg["assessment"]["tip_clearance"]
    if "tip_offsets_m" not in tc:
        return
    half, why = jacket_envelope(cfg)
    for i, (x, y) in enumerate(tc["tip_offsets_m"]):
        if abs(float(x)) > half[0] + 1e-9 or abs(float(y)) > half[1] + 1e-9:
            raise InputError(f"the tip point ({float(x):g}, {float(y):g}) m lies "
                             f"{float(np.hypot(x, y)):.1f} m from the CoG, outside the jacket's "
                             f"plan: x within +-{half[0]:.1f} m and y within +-{half[1]:.1f} m "
                             f"({why})", file=source,
                             field=f"assessment.tip_clearance.tip_offsets_m[{i}]", value=[x, y])


__all__ = ["check_geometry", "configured_drops", "jacket_envelope", "ENVELOPE_FACTOR"]
