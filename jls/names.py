"""Names used across the package, defined once: criterion keys, response names, and the
codes of the datasets' flag variables.

A criterion key is how the configuration names a limit (``assessment.criteria``) and how
the datasets label it (dimension ``criterion``); each judges one response of the
frequency-domain solution in one unit. Flag variables carry CF ``flag_values`` and
``flag_meanings`` in the datasets; the codes here are those values.
"""

from __future__ import annotations

# -- responses of the plant relative to the hinge (dimension ``response``) --------------
RELATIVE_SWAY, RELATIVE_HEAVE, RELATIVE_ROLL, RELATIVE_YAW = (
    "relative_sway", "relative_heave", "relative_roll", "relative_yaw")
RESPONSES = (RELATIVE_SWAY, RELATIVE_HEAVE, RELATIVE_ROLL, RELATIVE_YAW)
#: whether each response is a rotation (solved in rad, stored in degree)
ROTATIONAL = (False, False, True, True)
WIRE_TENSION = "wire_tension"
#: downward motion of the jacket tip relative to the incident wave surface under it
TIP_RELATIVE_HEAVE = "tip_relative_heave"

# -- criterion keys (``assessment.criteria``; dimension ``criterion``) -----------------
SWAY_M, HEAVE_M, ROLL_DEG, YAW_DEG = ("relative_sway_m", "relative_heave_m",
                                      "relative_roll_deg", "relative_yaw_deg")
MAX_TENSION_KN, MIN_TENSION_KN = "max_wire_tension_kN", "min_wire_tension_kN"
#: the air gap the jacket tip keeps above the wave surface (dynamic tip clearance)
TIP_AIR_GAP_M = "tip_air_gap_m"
#: the hoist-wire tension criterion: no wire's lowest tension below a floor (a fraction of
#: its static tension; slack always fails), none's highest above the safe working load
#: times its factors (:mod:`jls.assessment.wire_tension`); its limit is the floor fraction
WIRE_TENSION_CRITERION = WIRE_TENSION
#: criterion key -> (response it judges, unit of its limit)
CRITERIA = {
    SWAY_M: (RELATIVE_SWAY, "m"),
    HEAVE_M: (RELATIVE_HEAVE, "m"),
    ROLL_DEG: (RELATIVE_ROLL, "degree"),
    YAW_DEG: (RELATIVE_YAW, "degree"),
    MAX_TENSION_KN: (WIRE_TENSION, "kN"),
    MIN_TENSION_KN: (WIRE_TENSION, "kN"),
    TIP_AIR_GAP_M: (TIP_RELATIVE_HEAVE, "m"),
    WIRE_TENSION_CRITERION: (WIRE_TENSION, "1"),
}
#: +1 for an upper limit on the largest tension, -1 for a floor under the smallest
TENSION_SENSE = {MAX_TENSION_KN: 1.0, MIN_TENSION_KN: -1.0}
#: every criterion judged on the hoist-wire tensions (they need the tension statistics)
TENSION_KEYS = (MAX_TENSION_KN, MIN_TENSION_KN, WIRE_TENSION_CRITERION)

# -- ``verdict_source`` of workability.nc ---------------------------------------------
FREQUENCY_DOMAIN, SATURATED_FAIL, SATURATED_UNRESOLVED, TIME_DOMAIN = 0, 1, 2, 3
VERDICT_MEANINGS = ("frequency_domain frequency_domain_unreliable_winch_saturates_failed "
                    "frequency_domain_unreliable_winch_saturates_kept time_domain")

# -- hourly flags of weather_windows.nc -----------------------------------------------
NO_RECORD, NOT_WORKABLE, WORKABLE = -1, 0, 1
FLAG_MEANINGS = "no_record not_workable workable"
