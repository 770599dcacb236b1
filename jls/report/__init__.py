"""The per-route PDF assessment report.

    render_report(out_pdf, *, route, sea_states, vessel_motion, plant, response,
                  workability, provenance, screening=None, ..., workers=1) -> Path

reads the five datasets of the README (section Outputs) and writes an A4 engineer's report:
document control and summary (headline workability and recommendation) on page 1, inputs
and provenance, plant, vessel and hinge motion, sea states, operability, workability,
rigging (when the route was screened: ``screening``, with the optimum assessed as the
candidate "optimised"), assumptions and validity.

What the report states, and the rules it states them by:

* every candidate x tugger combination in the tables; a figure that cannot show them all
  distinctly says which it shows and why (:mod:`~jls.report.choices`);
* the best feasible combination, with any exact tie disclosed and broken by fewer active
  components (baseline rigging, no tugger), then the lower tugger slope;
* candidates feasible only at a constraint's limit, as plant.nc's ``at_limit`` and
  ``infeasible_reason`` state them (jls.plant.feasibility, tolerances in the configuration);
* amplitudes at floating-point round-off as "no motion"
  (:data:`~jls.report.contract.ROUNDOFF_RELATIVE`);
* document control from ``provenance['document']`` (the configuration's optional
  ``document`` section), the jls version and the source's git commit;
* a dataset made with another configuration: its ``config_sha256`` against
  ``provenance['config_sha256_datasets'][name]`` (the report configuration's hash of the
  sections that dataset depends on), or against the whole configuration's hash when that
  mapping is absent.

With ``SOURCE_DATE_EPOCH`` set, the creation time (text and PDF metadata) is that epoch and
two renders of the same inputs give the same bytes, whatever the number of ``workers``.

Modules: :mod:`~jls.report.contract` (what is read and checked, the derived numbers),
:mod:`~jls.report.choices` (what is shown, the best combination),
:mod:`~jls.report.control` (document control, commit, creation time),
:mod:`~jls.report.figures` (matplotlib), :mod:`~jls.report.drawing` (which figures, drawn
serially or by ``workers`` forked processes with the same bytes), :mod:`~jls.report.sections`,
:mod:`~jls.report.sections_inputs` and :mod:`~jls.report.sections_results` (Typst markup
of the sections, one function per chapter),
:mod:`~jls.report.markup` (escaping, tables), :mod:`~jls.report.document` (assembly,
compilation, atomic write) and ``template.typ`` (page layout).
"""

from jls.report.document import ReportError, render_report

__all__ = ["ReportError", "render_report"]
