"""The per-route PDF assessment report.

    render_report(out_pdf, *, route, sea_states, vessel_motion, plant, response,
                  workability, provenance, screening=None, ..., workers=1) -> Path

reads the five datasets of docs/reference/outputs.md and writes an A4 engineer's report:
document control and summary (headline workability, the recommendation, the probability
that its voyage stays inside every limit, the operational basis) on page 1, the
operational basis (DNV-ST-N001 class; the master's limiting-Hs table when the transit is
weather-restricted), inputs and provenance, plant, vessel and hinge motion, sea states,
operability, workability, rigging (when the route was screened: ``screening``, with the
optimum assessed as the candidate "optimised"), damping tuggers, wire loads, weather
windows, voyage extremes (``voyage``), uncertainty, and assumptions and validity (what
is not assessed, what to verify before sailing).

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

The tree. One module per chapter, in the report's order
(:data:`~jls.report.chapters.CHAPTERS`); each has ``chapter(cx)``, the chapter's Typst
markup, and, when it shows figures, ``figure_plan(cx)``, its figures (drawn next to the
text that shows them):

    summary          page 1: document control, summary, recommendation, table 1
    operation        "Operational basis": class, what follows, the master's table
    provenance       inputs and provenance
    plant            jacket, candidates ("detuned" defined), plant; the rigging figure
    vessel           vessel and hinge motion; hinge RAOs, relative transfer functions
    sea_states       the route, steepness rule, headings, RAO coverage; a scatter per leg
    operability      operability curves and limiting-Hs tables
    workability      workability per leg and route, failures by cause; the dot plot
    rigging          "Rigging" (when screened): the screening and its three figures,
    rigging_compare    and the optimised rigging beside the baseline (figures, tables)
    tuggers          "Damping tuggers": settings, loads, time domain, cases,
    tuggers_studies    and its second part, the decay tests and the slope sweep
    wire_loads       "Wire loads": tensions, DAF, slack margin, tension criteria
    weather_windows  "Weather windows" of hindcast legs; the window figure
    voyage           "Voyage extremes": exceedance curves, levels, months of departure
    uncertainty      "Uncertainty and sensitivity": bands, limit sweep, their figures
    validity         assumptions, not assessed, verify before sailing, validity

Chapters refer to each other, to tables and to figures by Typst labels (``sec-<chapter>``,
``tab-...``), so every number in a reference is the compiled document's.

What the chapters share, below them:

    context      :class:`~jls.report.context.Context` (datasets, digest, provenance,
                 figure files) and the small helpers several chapters use
    style        figure style and helpers (``STYLE``, ``new_figure``, ``save``,
                 ``log_ticks``, ``combo_style``, ...) and ``Task``, one planned figure
    contract     what is read and checked, the derived numbers (the digest)
    curves       the operability curves: limiting Hs, steepness ceiling, what limits
    choices      what is shown, the selection rules
    robustness   whether the recommendation holds over the band and the limit sweep
    control      document control, commit, creation time
    basis        the operational basis (workability.nc) and the voyage's probability
                 of staying inside every limit (voyage.nc), for page 1 and the chapters
    markup       escaping, numbers, tables, figures and references as Typst

and above them: :mod:`~jls.report.chapters` (the list), :mod:`~jls.report.drawing` (the
figures planned chapter by chapter, drawn serially or by ``workers`` forked processes
with the same bytes), :mod:`~jls.report.document` (the chapters assembled, compilation,
atomic write) and ``template.typ`` (page layout). A chapter imports only from the shared
modules, never from another chapter (``rigging_compare`` and ``tuggers_studies`` are the
second parts of ``rigging`` and ``tuggers``).
"""

from jls.report.document import ReportError, render_report

__all__ = ["ReportError", "render_report"]
