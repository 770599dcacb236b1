"""The report's chapters in their order, one module each.

Every chapter module has ``chapter(cx) -> str``, the Typst markup of the chapter
(heading included; the rigging chapter is empty when the route was not screened), and,
when the chapter has figures, ``figure_plan(cx) -> [Task]``
(:class:`jls.report.style.Task`), the figures it shows, drawn next to its text. The
document joins the chapters (:mod:`jls.report.document`); the drawing plans their
figures in the same order (:mod:`jls.report.drawing`).
"""

from __future__ import annotations

from jls.report import (
    appendix,
    assessment,
    operability,
    operation,
    plant,
    provenance,
    rigging,
    sea_states,
    spectra,
    study,
    summary,
    tuggers,
    uncertainty,
    validity,
    verification,
    vessel,
    voyage,
    voyage_plan,
    weather_windows,
    wire_loads,
    workability,
)

CHAPTERS = (summary, assessment, operation, provenance, plant, vessel, sea_states, spectra, operability, workability,
            rigging, tuggers, study, wire_loads, weather_windows, voyage, voyage_plan, uncertainty,
            verification, validity, appendix)


def key(chapter) -> str:
    """The name other chapters refer to the chapter by: its module's name."""
    return chapter.__name__.rsplit(".", 1)[-1]


def present_chapters(cx) -> frozenset:
    """The chapters that have a heading in this report."""
    return frozenset(key(c) for c in CHAPTERS if getattr(c, "present", lambda cx: True)(cx))


__all__ = ["CHAPTERS", "key", "present_chapters"]
