"""Cross-checks between the values of a configuration: unit slips no bound sees alone.

The schema bounds each value by itself; a weight in kN given as a mass in t (75 046 for
7650) or a tugger slope in N s/m (1e6 for 1000) is inside those bounds. These checks
compare values with each other and with the plant they make:

* masses: the inertial mass against the gravitational one (0.8-1.5 x); the baseline's
  static wire tensions against the safe working load (``max_wire_tension_kN``), the
  no-slack floor (``min_wire_tension_kN``), a stated fraction of the wires' breaking load
  (``rigging.wire_capacity``) and a plausible static strain (below 3 %);
* inertia against the jacket's size: the radius of gyration sqrt(I / m) within 0.3-2 x
  the distance from the CoG to the farthest lifting point (or, in roll, the tip);
* tugger slopes against the critical damping of the sway mode, 2 m w_n (an error above
  10 x, a warning above 2 x);
* angles in degrees that look like radians (headings all within 0-2 pi with fractions, a
  single angle at a multiple of pi/12 rad, limits below their plausible span in degrees);
* leg durations against the exposure of the MPM; fractions given as percent
  (``max_saturation_fraction``);
* time-domain cells: a configured candidate and a heading of every route.

:func:`check_values` raises :class:`jls.errors.InputError` naming the key and value, and
returns the warnings (one line each) a report prints on its first page.
"""

from __future__ import annotations

import math

import numpy as np

from jls.config.builders import candidate_values, plant_from_config
from jls.config.geometry_checks import check_geometry
from jls.config.hull_checks import check_hull
from jls.errors import InputError
from jls.names import (
    MAX_TENSION_KN,
    MIN_TENSION_KN,
    ROLL_DEG,
    TENSION_KEYS,
    TENSION_SENSE,
    TIP_AIR_GAP_M,
    YAW_DEG,
)

MASS_RATIO = (0.8, 1.5)            # inertial over gravitational mass
MAX_STATIC_STRAIN = 0.03           # steel breaks near 2 %, HMPE near 3.5 %
GYRATION_RATIO = (0.3, 2.0)        # radius of gyration over the jacket's half-size
CRITICAL_ERROR, CRITICAL_WARNING = 10.0, 2.0
MIN_LIMIT_DEG = 0.2                # relative roll or yaw limits below this look like rad
MIN_LEAD_DEG = 1.0                 # lead-angle limits below this look like rad
MAX_SATURATION_FRACTION = 0.5      # at or above: a percentage given as a fraction


def check_values(cfg: dict, source="config") -> list[str]:
    """Cross-check a validated configuration (defaults filled in); returns the warnings."""
    warnings: list[str] = []
    check_geometry(cfg, source)          # geometry that cannot be, job preconditions
    warnings += check_hull(cfg, source)  # the lift system outside the hull
    _check_angles(cfg, source)
    _check_durations(cfg, source)
    _check_fractions(cfg, source)
    _check_timedomain_cells(cfg, source)
    if cfg.get("plant_matrices"):
        return warnings
    _check_mass_ratio(cfg, source)
    _check_gyration(cfg, source)
    plant = plant_from_config(cfg, source=source)
    _check_tensions(cfg, plant, source)
    warnings += _check_tuggers(cfg, plant, source)
    # the wire_tension criterion (on by default) is not screened either, like the tip
    # clearance: the warning names the explicit tension limits only
    tension = [k for k in TENSION_SENSE if cfg["assessment"]["criteria"].get(k) is not None]
    motion = [k for k, v in cfg["assessment"]["criteria"].items()
              if v is not None and k not in TENSION_KEYS and k != TIP_AIR_GAP_M]
    if cfg["screening"]["enabled"] and not motion:
        raise InputError("the rigging screening ranks the candidates on the motion criteria and "
                         "the criteria are all wire tensions: add a motion criterion (e.g. "
                         "relative_sway_m) or set screening.enabled: false", file=source,
                         field="assessment.criteria", value=sorted(cfg["assessment"]["criteria"]))
    if tension and cfg["screening"]["enabled"]:
        warnings.append(f"the rigging screening ranks the candidates on the motion criteria only; "
                        f"{', '.join(tension)} {'is' if len(tension) == 1 else 'are'} applied when the configured candidates and the "
                        "screening's optimum are assessed")
    return warnings


# --- masses and wires --------------------------------------------------------------------

def _check_mass_ratio(cfg, source):
    j = cfg["jacket"]
    if j.get("m_kin_t") is None:
        return                               # lumped: the jacket's mass plus the blocks'
    ratio = j["m_kin_t"] / j["m_grav_t"]
    lo, hi = MASS_RATIO
    if not lo <= ratio <= hi:
        raise InputError(f"the inertial mass m_kin_t {j['m_kin_t']:g} t is {ratio:.3g} x the "
                         f"gravitational mass {j['m_grav_t']:g} t; it is the jacket's own mass "
                         f"with the hoist blocks and wire moving with it ({lo:g}-{hi:g} x): a weight "
                         "in kN given as a mass in t (x g), or a mass in kg?", file=source,
                         field="jacket.m_grav_t", value=j["m_grav_t"])


def _stiffness_field(cfg):
    return ("rigging.wire_segments" if "wire_segments" in cfg["rigging"]
            else "rigging.wire_stiffness_kN_per_m")


def _check_tensions(cfg, plant, source):
    """The baseline's static tensions against the wires and the tension criteria."""
    names = [w["name"] for w in cfg["rigging"]["wires"]]
    tension = np.asarray(plant.tension, float).reshape(-1)
    length = np.asarray(plant.unstretched_length, float).reshape(-1)
    k = np.asarray(plant.wire_stiffness, float).reshape(-1)
    strain = tension / (k * length)
    i = int(np.argmax(strain))
    if strain[i] > MAX_STATIC_STRAIN:
        raise InputError(f"the static tension of wire '{names[i]}', {tension[i]:.0f} kN, stretches "
                         f"it by {100 * strain[i]:.1f} % (stiffness {k[i]:g} kN/m, length "
                         f"{length[i]:.1f} m); a hoist wire stretches well under "
                         f"{100 * MAX_STATIC_STRAIN:g} % under its static load: the stiffness or "
                         "the weight (jacket.m_grav_t) in the wrong unit?", file=source,
                         field=_stiffness_field(cfg), value=float(k[i]))
    top = int(np.argmax(tension))
    criteria = cfg["assessment"]["criteria"]
    capacity = cfg["rigging"].get("wire_capacity")
    swl = criteria.get(MAX_TENSION_KN)
    if swl is not None and tension[top] > swl:
        raise InputError(f"the static tension of wire '{names[top]}', {tension[top]:.0f} kN, is above "
                         f"the safe working load {swl:g} kN: no sea state can pass (the SWL in t, "
                         "or the weight in kN as jacket.m_grav_t?)", file=source,
                         field=f"assessment.criteria.{MAX_TENSION_KN}", value=swl)
    floor = criteria.get(MIN_TENSION_KN)
    low = int(np.argmin(tension))
    if floor is not None and tension[low] < floor:
        raise InputError(f"the static tension of wire '{names[low]}', {tension[low]:.0f} kN, is below "
                         f"the no-slack floor {floor:g} kN: no sea state can pass", file=source,
                         field=f"assessment.criteria.{MIN_TENSION_KN}", value=floor)
    if capacity is not None:
        mbl, frac = capacity["breaking_load_kN"], capacity["max_static_fraction"]
        if tension[top] > frac * mbl:
            raise InputError(f"the static tension of wire '{names[top]}', {tension[top]:.0f} kN, is "
                             f"{tension[top] / mbl:.3g} of the breaking load {mbl:g} kN, more than the "
                             f"stated {frac:g} (rigging.wire_capacity.max_static_fraction): the weight "
                             "(jacket.m_grav_t) or the breaking load in the wrong unit?", file=source,
                             field="rigging.wire_capacity.breaking_load_kN", value=mbl)


def _check_gyration(cfg, source):
    """Roll and yaw radii of gyration against the jacket's size (CoG to its farthest
    lifting point; in roll also to its tip)."""
    j = cfg["jacket"]
    pad = np.array([w["padeye_m"] for w in cfg["rigging"]["wires"]], float)
    tip = cfg["rigging"]["limits"]["padeye_to_tip_m"] - j["z_p_m"]
    size = {"ixx_t_m2": (max(float(np.hypot(pad[:, 1], pad[:, 2]).max()), abs(tip)), "roll"),
            "izz_t_m2": (float(np.hypot(pad[:, 0], pad[:, 1]).max()), "yaw")}
    lo, hi = GYRATION_RATIO
    for key, (half, what) in size.items():
        r = math.sqrt(j[key] / j["m_grav_t"])
        if half > 0 and not lo <= r / half <= hi:
            raise InputError(f"the {what} inertia gives a radius of gyration sqrt(I / m_grav) = "
                             f"{r:.3g} m, {r / half:.2g} x the jacket's half-size {half:.3g} m (CoG to "
                             f"its farthest lifting point{' or tip' if what == 'roll' else ''}); a "
                             f"jacket's lies within {lo:g}-{hi:g} x: t m2 expected (kg m2 is 1000 x; "
                             "a slipped decimal?)", file=source, field=f"jacket.{key}", value=j[key])


def _check_tuggers(cfg, plant, source) -> list[str]:
    """Tugger slopes against the critical damping of the sway mode, 2 m w_n."""
    w = float(np.asarray(plant.modes.omega).reshape(-1, 4)[0, 0])
    m = float(np.asarray(plant.M).reshape(-1, 4, 4)[0, 0, 0])
    critical = 2.0 * m * w
    out = []
    slopes = [(f"tuggers[{i}].c_kN_s_per_m", t["c_kN_s_per_m"], t["name"])
              for i, t in enumerate(cfg["tuggers"])]
    sweep = cfg["timedomain"]["slope_sweep"]["slopes_kN_s_per_m"]
    slopes += [(f"timedomain.slope_sweep.slopes_kN_s_per_m[{i}]", c, None) for i, c in enumerate(sweep)]
    for field, c, name in slopes:
        ratio = c / critical
        if ratio > CRITICAL_ERROR:
            raise InputError(f"{c:g} kN s/m is {ratio:.3g} x the critical damping of the sway mode "
                             f"(2 m w_n = {critical:.0f} kN s/m); a pair that stiff locks the jacket to "
                             "the fairleads: a slope in N s/m (1000 x kN s/m)?", file=source,
                             field=field, value=c)
        if name is not None and ratio > CRITICAL_WARNING:
            out.append(f"tugger '{name}': slope {c:g} kN s/m is {ratio:.2g} x the critical damping of "
                       f"the sway mode ({critical:.0f} kN s/m); above about {CRITICAL_WARNING:g} x the "
                       "lines carry the fairleads' motion into the jacket rather than damp it")
    return out


# --- angles, durations, fractions ----------------------------------------------------------

def _whole(x) -> bool:
    return abs(x - round(x)) < 1e-6


def _radian_multiple(x) -> bool:
    """x within 2e-3 of k pi/12 rad (k >= 1) and not a whole number: 1.5708, 3.1416 ..."""
    k = round(x / (math.pi / 12))
    return k >= 1 and abs(x - k * math.pi / 12) < 2e-3 and not _whole(x)


def _radian_course(x) -> bool:
    """A course within 2e-3 of a multiple of 5 deg in radians (k pi/36, k >= 1) and not a
    whole number of degrees: courses are steered and stated to whole degrees, mostly
    multiples of 5, so 3.49 (200 deg) is radians, where the headings' pi/12 test misses it."""
    x = float(x)
    k = round(x / (math.pi / 36))
    return 0 < x <= 2 * math.pi + 1e-9 and k >= 1 and abs(x - k * math.pi / 36) < 2e-3 and not _whole(x)


def _radians(values) -> bool:
    vals = [float(v) for v in values]
    if not vals or max(abs(v) for v in vals) > 2 * math.pi + 1e-9 or all(_whole(v) for v in vals):
        return False
    return len(vals) > 1 or _radian_multiple(vals[0])


def _angle_error(field, value, source):
    return InputError("these angles are in degrees, and the value looks like radians "
                      f"({', '.join(f'{math.degrees(float(v)):.4g}' for v in np.atleast_1d(value))} "
                      "deg if so): give degrees", file=source, field=field, value=value)


def _check_angles(cfg, source):
    for route, spec in cfg["routes"].items():
        for i, leg in enumerate(spec["legs"]):
            where = f"routes.{route}.legs[{i}]"
            if leg.get("heading_source") in ("given",) and _radians(leg["headings_deg"]):
                raise _angle_error(f"{where}.headings_deg", leg["headings_deg"], source)
            for key in ("course_deg", "heading_step_deg"):
                if key in leg and _radians([leg[key]]):
                    raise _angle_error(f"{where}.{key}", leg[key], source)
            if "course_deg" in leg and _radian_course(leg["course_deg"]):
                raise _angle_error(f"{where}.course_deg", leg["course_deg"], source)
            wd = leg.get("wave_directions")
            if wd and _radians(wd["from_deg"]):
                raise _angle_error(f"{where}.wave_directions.from_deg", wd["from_deg"], source)
    singles = [("screening.envelope.heading_deg", cfg["screening"]["envelope"]["heading_deg"]),
               ("timedomain.slope_sweep.heading_deg", cfg["timedomain"]["slope_sweep"]["heading_deg"])]
    singles += [(f"timedomain.cells[{i}].heading_deg", c["heading_deg"])
                for i, c in enumerate(cfg["timedomain"]["cells"])]
    for field, value in singles:
        if _radians([value]):
            raise _angle_error(field, value, source)
    limits = [(f"assessment.criteria.{k}", cfg["assessment"]["criteria"].get(k), MIN_LIMIT_DEG)
              for k in (ROLL_DEG, YAW_DEG)]
    limits += [(f"screening.constraints.{k}", cfg["screening"]["constraints"].get(k), MIN_LIMIT_DEG)
               for k in (ROLL_DEG, YAW_DEG)]
    limits += [(f"rigging.limits.{k}", cfg["rigging"]["limits"][k], MIN_LEAD_DEG)
               for k in ("side_lead_max_deg", "fore_aft_lead_max_deg")]
    for field, value, low in limits:
        if value is not None and value < low:
            raise InputError(f"{value:g} deg is below the plausible span of this limit (from {low:g} "
                             f"deg); in degrees, not radians ({math.degrees(value):.3g} deg if it was "
                             "radians)?", file=source, field=field, value=value)


def _check_durations(cfg, source):
    exposure = cfg["assessment"]["exposure_h"]
    for route, spec in cfg["routes"].items():
        for i, leg in enumerate(spec["legs"]):
            if leg["duration_h"] < exposure:
                raise InputError(f"the leg lasts {leg['duration_h']:g} h, less than the "
                                 f"{exposure:g} h exposure of the MPM (assessment.exposure_h): "
                                 "minutes or days given as hours? (a shorter exposure is set "
                                 "there)", file=source, field=f"routes.{route}.legs[{i}].duration_h",
                                 value=leg["duration_h"])


def _check_fractions(cfg, source):
    f = cfg["assessment"]["max_saturation_fraction"]
    if f >= MAX_SATURATION_FRACTION:
        raise InputError(f"a fraction of the time (0-1): {f:g} is {100 * f:g} % (1 % is 0.01); a "
                         f"winch at its force limit {100 * MAX_SATURATION_FRACTION:g} % of the time "
                         "or more no longer damps", file=source,
                         field="assessment.max_saturation_fraction", value=f)


def _check_timedomain_cells(cfg, source):
    """Configured cells and boundary candidates: a candidate the pipeline assesses and, for
    a cell, a heading every route has (its vessel motion holds the routes' headings)."""
    known = list(candidate_values(cfg)) + (["optimised"] if cfg["screening"]["enabled"] else [])
    td = cfg["timedomain"]
    listed = [] if td["boundary_candidates"] == "assessed" else td["boundary_candidates"]
    for i, name in enumerate(listed):
        if name not in known:
            raise InputError(f"not a rigging candidate of the assessment ({', '.join(known[:8])}"
                             f"{' ...' if len(known) > 8 else ''})", file=source,
                             field=f"timedomain.boundary_candidates[{i}]", value=name)
    for i, cell in enumerate(td["cells"]):
        if cell["candidate"] not in known:
            raise InputError(f"not a rigging candidate of the assessment ({', '.join(known[:8])}"
                             f"{' ...' if len(known) > 8 else ''})", file=source,
                             field=f"timedomain.cells[{i}].candidate", value=cell["candidate"])
        h = float(cell["heading_deg"])
        for route, spec in cfg["routes"].items():
            have = sorted({float(x) for leg in spec["legs"] for x in leg["headings_deg"]})
            if not any(abs(h - x) < 1e-6 for x in have):
                raise InputError(f"not a relative heading of route '{route}' "
                                 f"({', '.join(f'{x:g}' for x in have)} deg): the cell's vessel "
                                 "motion does not exist there", file=source,
                                 field=f"timedomain.cells[{i}].heading_deg", value=cell["heading_deg"])
