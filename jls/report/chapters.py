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
                        operability,
                        plant,
                        provenance,
                        rigging,
                        sea_states,
                        summary,
                        tuggers,
                        uncertainty,
                        validity,
                        verification,
                        vessel,
                        weather_windows,
                        wire_loads,
                        workability,
)

CHAPTERS = (summary, provenance, plant, vessel, sea_states, operability, workability, rigging,
            tuggers, wire_loads, weather_windows, uncertainty, verification, validity)

__all__ = ["CHAPTERS"]
