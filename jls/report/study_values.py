"""The reference study's published numbers the report prints beside this assessment's
(chapter "The reference study beside this assessment", :mod:`jls.report.study`), each
with the table or section it comes from. Copied by hand from the study's text; a test
reads them back from it (``tests/test_study_comparison.py``).
"""

from __future__ import annotations

#: Table 3.1, modal analysis of the linear ROM: natural period [s] per dominant DOF.
TABLE_3_1_PERIOD_S = {"sway": 15.7, "yaw": 3.543, "roll": 1.2, "heave": 1.1}

#: Table 5.2, baseline and optimised hoist configuration: top spread from the centreline
#: [m], drop height [m], sway period [s].
TABLE_5_2 = {"baseline": {"top_spread_m": 22.48, "drop_height_m": 60.09, "sway_period_s": 15.70},
             "optimised": {"top_spread_m": 13.05, "drop_height_m": 66.46, "sway_period_s": 18.39}}

#: Section 4.3.2, the validation sea states: name -> (Hs [m], Tz [s]), beam seas (90 deg).
VALIDATION_SEA_STATES = {"V1": (2.40, 4.30), "V2": (2.40, 6.60), "V3": (2.40, 7.50),
                         "V4": (2.40, 8.50), "S1": (2.70, 9.00)}

#: Table 4.4, relative sway: ROM RMS [m], ORCAFLEX RMS [m], converged sigma [m] and the
#: three-hour maximum 3.72 sigma [m] (N = 1000 cycles) per validation sea state.
TABLE_4_4 = {"V1": (0.037, 0.039, 0.060, 0.22), "V2": (0.635, 0.663, 0.791, 2.94),
             "V3": (1.460, 1.472, 2.209, 8.22), "V4": (3.560, 3.047, 6.144, 22.86),
             "S1": (7.178, 5.383, 10.042, 37.36)}

#: Table 6.3, the tugger configurations: slope [kN s/m], capacity T_max [kN], pretension
#: [kN], pay-out speed of saturation [m/s], capacity [% of the payload weight].
TABLE_6_3 = {"low": (300, 1000, 510, 3.27, 2.7), "reference": (1000, 1000, 510, 0.98, 2.7),
             "high": (2000, 2000, 1010, 0.99, 5.3)}
#: Section 6.4: net force of the opposing pair at saturation [kN] (low, reference, high).
SECTION_6_4_NET_FORCE_KN = {"low": 980.0, "reference": 980.0, "high": 1980.0}

#: Table 6.5, the largest sway expected in three hours [m] (time domain, winch limits on):
#: (Hs [m], Tz [s]) -> (none, low, reference, high, high at a tension limit [%]).
TABLE_6_5 = {(2.4, 6.6): (2.93, 2.89, 2.65, 2.29, 0), (3.0, 6.6): (3.67, 3.61, 3.32, 2.86, 0),
             (2.4, 7.0): (4.23, 4.09, 3.59, 2.98, 0), (2.4, 7.5): (10.10, 6.42, 5.27, 4.08, 1),
             (3.0, 7.5): (13.29, 8.11, 6.84, 5.25, 3), (3.6, 7.5): (15.55, 9.86, 8.55, 6.61, 6),
             (2.4, 8.0): (15.57, 9.39, 7.47, 5.44, 3), (2.4, 8.5): (22.56, 12.57, 10.11, 7.02, 7)}

#: Table 6.7, the workable wave-period window at the design Hs 2.4 m per tugger
#: configuration (baseline rigging): upper end [s].
TABLE_6_7_TO_TZ_S = {"none": 6.63, "low": 6.66, "reference": 6.78, "high": 7.03}

#: Table 6.7, the gain over no tugger [s] as published.
TABLE_6_7_GAIN_S = {"low": 0.03, "reference": 0.15, "high": 0.40}

#: Table 6.8 (section 6.8), the same window for the four cases (reference tugger): upper
#: end [s], and the gain over the as-rigged case [s] as published (the table rounds each).
TABLE_6_8_TO_TZ_S = {"as rigged": 6.63, "tugger only": 6.78, "rigging changed": 7.15, "both": 7.23}
TABLE_6_8_GAIN_S = {"tugger only": 0.15, "rigging changed": 0.53, "both": 0.60}
#: The design wave height of tables 6.7 and 6.8 [m].
DESIGN_HS_M = 2.4

#: Table 6.9, the largest workable Hs [m] across the period range: Tz [s] -> (as rigged,
#: rigging changed, tugger only, both, steepness ceiling).
TABLE_6_9 = {6.00: (3.75, 3.75, 3.75, 3.75, 3.75), 6.25: (3.35, 4.07, 3.60, 4.07, 4.07),
             6.50: (2.68, 3.77, 2.95, 3.91, 4.40), 6.75: (2.13, 3.16, 2.44, 3.29, 4.74),
             7.00: (1.65, 2.65, 2.03, 2.78, 5.10), 7.25: (1.25, 2.24, 1.69, 2.36, 5.47),
             7.50: (0.93, 1.90, 1.43, 2.03, 5.85), 8.00: (0.52, 1.40, 1.05, 1.53, 6.66)}

#: The study's relative-sway clearance budget [m] (sections 6.5-6.8).
CLEARANCE_BUDGET_M = 3.0
#: The study's reference tugger slope [kN s/m] (section 6.4, table 6.3).
REFERENCE_SLOPE = 1000.0

__all__ = ["CLEARANCE_BUDGET_M", "DESIGN_HS_M", "REFERENCE_SLOPE", "SECTION_6_4_NET_FORCE_KN",
           "TABLE_3_1_PERIOD_S", "TABLE_4_4", "TABLE_5_2", "TABLE_6_3", "TABLE_6_5",
           "TABLE_6_7_GAIN_S", "TABLE_6_7_TO_TZ_S", "TABLE_6_8_GAIN_S", "TABLE_6_8_TO_TZ_S", "TABLE_6_9", "VALIDATION_SEA_STATES"]
