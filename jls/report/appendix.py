"""Appendix: the long tables at every heading (the body shows the governing heading's
rows and says so, :mod:`jls.report.long_tables`), and the names behind the body's words:
which dataset file each "dataset" of the text is, and which configuration key each
criterion and rule is. Dataset file names and configuration keys appear here and in the
provenance chapter only.
"""

from __future__ import annotations

from jls.report import long_tables, rigging_compare
from jls.report.context import Context, heading, screened
from jls.report.markup import table

#: The body's word for each dataset -> (file, what the body reads from it).
DATASETS = (
    ("the plant dataset", "plant_assessed.nc", "natural periods, wire geometry and tensions, design variables, constraint margins"),
    ("the vessel-motion dataset", "vessel_motion.nc", "vessel RAOs and the hinge motion"),
    ("the sea-state dataset", "sea_states.nc", "the legs' cells, their probabilities and the steepness flags"),
    ("the response dataset", "response.nc", "unit-Hs statistics, tensions, tugger loads, transfer functions"),
    ("the workability dataset", "workability.nc", "pass flags, workability, limiting Hs, verdict sources, bands, "
                                                  "the operational basis, DAF"),
    ("the voyage dataset", "voyage.nc", "the voyage extremes and their independence assumption"),
    ("the tugger-studies dataset", "tugger_studies.nc", "decay tests and the damping-slope sweep"),
    ("the measured-response dataset", "measured_response.nc", "the spectra legs' statistics"),
    ("the screening dataset", "screening.nc", "the rigging screening and its optimum"),
    ("the weather-window dataset", "weather_windows.nc", "the hindcast legs' windows"),
)

#: The body's word for each configured rule -> its configuration key.
KEYS = (
    ("the criteria and their limits", "assessment.criteria"),
    ("the wire-tension floor, safe working load and design DAF", "assessment.criteria.wire_tension"),
    ("the exposure and the MPM's cycle count", "assessment.exposure_h, assessment.mpm_cycles"),
    ("the Hs at which a bin is assessed", "sea.hs_in_bin"),
    ("the winch-saturation policy and allowance", "assessment.winch_saturation, assessment.max_saturation_fraction"),
    ("the recommendation's tugger gain, tie tolerance and same-rigging tolerance",
     "recommendation.tugger_min_gain_pp, recommendation.tie_tolerance_pp, recommendation.same_rigging_tolerance_m"),
    ("the operational basis and alpha factors", "operation"),
    ("the title block", "document"),
)


def chapter(cx: Context) -> str:
    out = [heading("appendix", "Appendix: every heading, datasets and configuration keys")]
    rows = long_tables.peak_rows(cx, cx.vessel["heading"].values)
    if long_tables.is_long(rows):
        out.append(table("Peak RAO amplitudes at every heading of the RAO (the body shows the "
                         "governing heading's).", ["heading", "motion", "peak", "at period [s]"],
                         rows, align="(left, left, right, right)", size="7.5pt"))
    if screened(cx) and cx.work.sizes["heading"] > 1:
        out.append(rigging_compare.window_table(cx, every_heading=True))
    out.append(table("The datasets the text names in words, their files (in the route's results "
                     "folder; the provenance chapter gives each one's rule, version and configuration "
                     "hash) and what the text reads from them.", ["in the text", "file", "read for"],
                     [list(r) for r in DATASETS], columns="(auto, auto, 1fr)",
                     align="(left, left, left)", size="8pt"))
    out.append(table("The configuration keys behind the text's rules (jls/schemas/config.schema.yaml "
                     "states each key's default, unit and bounds).", ["in the text", "configuration key"],
                     [list(r) for r in KEYS], columns="(auto, 1fr)", align="(left, left)", size="8pt"))
    return "\n".join(out)


__all__ = ["DATASETS", "KEYS", "chapter"]
