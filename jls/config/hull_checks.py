"""The lift system outside the hull, checked when the configuration is read.

``vessel.hull`` states the hull's extent as a box in the frame of ``vessel.hinge_m``
(x forward, y to port, z up; the frame the RAO reference point is given in): x from
``aft_end_x_m`` to ``aft_end_x_m + length_m``, y within +-``breadth_m``/2 of the
centreline y = 0, and from the keel, ``draught_m`` below the still waterline, to the main
deck, ``depth_m - draught_m`` above it. Heights above the water come from the one
geometry of the vessel block (``rigging.limits.hinge_height_m``, derived from
``vessel.rao_reference_point_height_m``).

Every point of the lift system must lie outside that box (on its surface is outside: a
fairlead on the deck edge, a lift-beam foot on the deck):

* the tugger fairleads, ``vessel.fairlead_drop_m`` below the hinge and
  ``vessel.fairlead_half_span_m`` either side of it;
* the hinge and the lift-beam anchors (``rigging.wires[i].anchor_m`` from the hinge);
* the padeyes of the baseline, of every named candidate and of the candidate grid's
  drops (the jacket's CoG under the hinge, ``jacket.z_p_m`` below the padeyes);
* the jacket's tip points (``assessment.tip_clearance.tip_offsets_m``, else the points
  below the padeyes) at the tip's height (``rigging.limits.padeye_to_tip_m`` below
  the padeyes); and, where ``jacket.envelope_half_m`` is stated, the jacket's whole
  plan envelope between the padeyes' and the tip's heights.

Each error names the key of the point, its value and the two numbers that contradict
(the point's height against the deck's, and its plan position within the hull's plan).
Without ``vessel.hull`` nothing is checked and :func:`check_hull` returns a warning
saying so (``jls check`` prints it, the report's first page lists it): the hull's
extent has no default.
"""

from __future__ import annotations

from jls.config.geometry_checks import configured_drops
from jls.errors import InputError

#: A point closer than this to the hull's surface counts as on it (outside) [m].
SURFACE_TOLERANCE_M = 1e-6

NOT_CHECKED = ("vessel.hull is not given: the lift system's points (tugger fairleads, hinge, "
               "lift-beam anchors, padeyes, jacket tip) were not checked against the hull's "
               "extent; state the hull (length_m, breadth_m, depth_m, draught_m, aft_end_x_m) "
               "beside the RAO file to have them checked")


def own_hull(cfg: dict, layers) -> None:
    """Drop a ``vessel.hull`` inherited from a configuration file before the one that
    gives the vessel's RAOs (``vessel.rao_file`` or ``vessel.bem``): the hull belongs to
    the vessel of its RAO file, and an overlay giving another vessel without its hull
    leaves the hull unstated (the check is then not made, and said so), not the first
    vessel's. ``layers``: [(file, mapping)] in merge order."""
    def last(keys):
        found = [k for k, (_, data) in enumerate(layers)
                 if isinstance(data, dict) and isinstance(data.get("vessel"), dict)
                 and any(key in data["vessel"] for key in keys)]
        return found[-1] if found else -1
    vessel = cfg.get("vessel")
    if isinstance(vessel, dict) and "hull" in vessel and last(("hull",)) < last(("rao_file", "bem")):
        del vessel["hull"]


def hull_box(vessel: dict) -> dict:
    """The hull's extent: x and y in the frame of ``hinge_m``, z as heights above the
    still waterline [m]."""
    h = vessel["hull"]
    x0 = float(h["aft_end_x_m"])
    half = float(h["breadth_m"]) / 2.0
    return {"x": (x0, x0 + float(h["length_m"])), "y": (-half, half),
            "z": (-float(h["draught_m"]), float(h["depth_m"]) - float(h["draught_m"]))}


def inside(box: dict, x: float, y: float, z: float) -> bool:
    """Strictly inside the box (more than :data:`SURFACE_TOLERANCE_M` within each face)."""
    tol = SURFACE_TOLERANCE_M
    return all(lo + tol < v < hi - tol for v, (lo, hi) in zip((x, y, z), (box["x"], box["y"], box["z"])))


def _overlaps(box: dict, lo: tuple, hi: tuple) -> bool:
    """A box [lo, hi] (x, y, height) reaching into the hull box."""
    tol = SURFACE_TOLERANCE_M
    return all(a < bhi - tol and b > blo + tol
               for a, b, (blo, bhi) in zip(lo, hi, (box["x"], box["y"], box["z"])))


def _where(box: dict, what: str, x: float, y: float, z: float) -> str:
    return (f"{what} at x = {x:.2f} m, y = {y:.2f} m, {z:.2f} m above the waterline lies inside "
            f"the hull: the hull's main deck is {box['z'][1]:.2f} m above the waterline (vessel.hull "
            f"depth_m - draught_m) and its keel {-box['z'][0]:.2f} m below it, and the point is "
            f"within its plan (x {box['x'][0]:.2f} to {box['x'][1]:.2f} m, y within "
            f"+-{box['y'][1]:.2f} m, vessel.hull); a lift-system point is on deck, on the lift "
            "beams or outboard of the hull")


def check_hull(cfg: dict, source="config") -> list[str]:
    """Every check of the module docstring on a validated configuration (defaults filled,
    ``rigging.limits.hinge_height_m`` derived); returns the warning when ``vessel.hull``
    is not given."""
    vessel = cfg["vessel"] if "vessel" in cfg else {}
    if "plant_matrices" in cfg or "jacket" not in cfg or "rigging" not in cfg:
        return []
    if "hull" not in vessel:
        return [NOT_CHECKED]
    limits = cfg["rigging"]["limits"]
    if "hinge_height_m" not in limits or "hinge_m" not in vessel:
        return [NOT_CHECKED]
    hull = vessel["hull"]
    if not float(hull["depth_m"]) > float(hull["draught_m"]):
        raise InputError(f"a moulded depth of {float(hull['depth_m']):g} m at a draught of "
                         f"{float(hull['draught_m']):g} m (vessel.hull.draught_m) puts the main deck "
                         "at or below the waterline", file=source, field="vessel.hull.depth_m",
                         value=hull["depth_m"])
    box = hull_box(vessel)
    hx, hy = float(vessel["hinge_m"][0]), float(vessel["hinge_m"][1])
    hz = float(limits["hinge_height_m"])

    def refuse(what, x, y, z, field, value):
        if inside(box, x, y, z):
            raise InputError(_where(box, what, x, y, z), file=source, field=field, value=value)

    refuse("the hinge", hx, hy, hz, "vessel.hinge_m", vessel["hinge_m"])
    drop, span = float(vessel["fairlead_drop_m"]), float(vessel["fairlead_half_span_m"])
    for side, sign in (("port", 1.0), ("starboard", -1.0)):
        refuse(f"the {side} tugger fairlead ({drop:g} m below the hinge, {span:g} m to {side})",
               hx, hy + sign * span, hz - drop, "vessel.fairlead_drop_m", vessel["fairlead_drop_m"])
    rig, jacket = cfg["rigging"], cfg["jacket"]
    for i, w in enumerate(rig["wires"]):
        a = [float(v) for v in w["anchor_m"]]
        refuse(f"the anchor of wire '{w['name']}'", hx + a[0], hy + a[1], hz + a[2],
               f"rigging.wires[{i}].anchor_m", w["anchor_m"])
    tip_depth = float(limits["padeye_to_tip_m"])
    tc = cfg["assessment"]["tip_clearance"] if "assessment" in cfg else {}
    for field, d in configured_drops(cfg):
        cog = hz - d - float(jacket["z_p_m"])
        for w in rig["wires"]:
            p = [float(v) for v in w["padeye_m"]]
            refuse(f"the padeye of wire '{w['name']}' (drop {d:g} m)", hx + p[0], hy + p[1],
                   cog + p[2], field, d)
        pad_z = cog + max(float(w["padeye_m"][2]) for w in rig["wires"])
        tip_z = pad_z - tip_depth
        if "tip_offsets_m" in tc:
            points = [(f"assessment.tip_clearance.tip_offsets_m[{k}]", p)
                      for k, p in enumerate(tc["tip_offsets_m"])]
        else:
            points = [(field, w["padeye_m"][:2]) for w in rig["wires"]]
        for key, (tx, ty) in points:
            refuse(f"the jacket tip point ({float(tx):g}, {float(ty):g}) m from the CoG "
                   f"(drop {d:g} m, {tip_depth:g} m below the padeyes)",
                   hx + float(tx), hy + float(ty), tip_z, key, [tx, ty] if key != field else d)
        if "envelope_half_m" in jacket:
            ex, ey = (abs(float(v)) for v in jacket["envelope_half_m"])
            lo, hi = (hx - ex, hy - ey, tip_z), (hx + ex, hy + ey, pad_z)
            if _overlaps(box, lo, hi):
                raise InputError(
                    f"the jacket (plan x {lo[0]:.2f} to {hi[0]:.2f} m, y {lo[1]:.2f} to {hi[1]:.2f} m, "
                    f"jacket.envelope_half_m; from {tip_z:.2f} m to {pad_z:.2f} m above the "
                    f"waterline at drop {d:g} m) reaches into the hull (x {box['x'][0]:.2f} to "
                    f"{box['x'][1]:.2f} m, y within +-{box['y'][1]:.2f} m, keel {-box['z'][0]:.2f} m "
                    f"below the waterline to the main deck {box['z'][1]:.2f} m above it, vessel.hull): "
                    "the jacket hangs outboard of the hull", file=source, field=field, value=d)
    return []


__all__ = ["check_hull", "own_hull", "hull_box", "inside", "NOT_CHECKED", "SURFACE_TOLERANCE_M"]
