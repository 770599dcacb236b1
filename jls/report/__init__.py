"""The per-route PDF assessment report.

    render_report(out_pdf, *, route, sea_states, vessel_motion, plant, response,
                  workability, provenance) -> Path

reads the five datasets of the README (section Outputs) and writes an A4 engineer's report:
summary with the headline workability, inputs and provenance, plant, vessel and hinge
motion, sea states, operability, workability, assumptions and validity.

Modules: :mod:`~jls.report.contract` (what is read and checked, the derived numbers),
:mod:`~jls.report.figures` (matplotlib), :mod:`~jls.report.sections` and
:mod:`~jls.report.sections_results` (Typst markup of the sections),
:mod:`~jls.report.markup` (escaping, tables), :mod:`~jls.report.document` (assembly,
compilation, atomic write) and ``template.typ`` (page layout).
"""

from jls.report.document import ReportError, render_report

__all__ = ["ReportError", "render_report"]
