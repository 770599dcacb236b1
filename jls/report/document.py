"""Assemble the report: check the datasets, draw the figures, write the Typst source
next to the template in a temporary directory, compile it with the ``typst`` package
and move the PDF into place atomically.

Why Typst: matplotlib draws the figures, but tables, equations, captions and page
layout typeset far better in Typst than in a figure-only PDF, and the compiler ships
inside the ``typst`` wheel (no TeX installation); the whole report compiles in a
fraction of a second. System fonts are ignored so the PDF is the same on every
machine: the text uses the fonts embedded in Typst, the figures carry their text as
paths.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from datetime import datetime
from importlib import resources
from pathlib import Path

import typst

from jls.collector import few_collections
from jls.errors import InputError
from jls.report import control, drawing
from jls.report.chapters import CHAPTERS, present_chapters
from jls.report.context import Context
from jls.report.contract import check, digest
from jls.report.markup import t

PROVENANCE_KEYS = ("jls_version", "config_sha256", "created", "inputs")


class ReportError(RuntimeError):
    """Typesetting failed (a bug in the report, not in the inputs)."""


def _check_provenance(provenance) -> dict:
    if not isinstance(provenance, dict):
        raise InputError("provenance must be a dict", field="provenance",
                         value=type(provenance).__name__)
    missing = [k for k in PROVENANCE_KEYS if k not in provenance]
    if missing:
        raise InputError(f"provenance lacks {', '.join(missing)}", field="provenance")
    return provenance


def draw_figures(cx: Context, out_dir: Path, workers: int = 1) -> dict:
    """Every figure of the report into ``out_dir``; name -> file name."""
    tasks = drawing.plan(cx)
    with drawing.drawn(tasks, out_dir, workers):
        pass
    return drawing.names(tasks)


def source(cx: Context) -> str:
    """The Typst source of the whole report: the title block, then every chapter in
    :data:`~jls.report.chapters.CHAPTERS` order."""
    p = cx.prov
    doc = control.document_info(p)
    sha = str(p.get("config_sha256", ""))
    title = doc["title"] or f"Rigging assessment, route {cx.dg.route}"
    number = doc["number"] or control.NOT_ASSIGNED
    rev = doc["revision"] or "–"
    commit = control.short_commit(str(p.get("git_commit", control.NOT_GIT)))
    subtitle = (f"Document {'number ' if not doc['number'] else ''}{number}, revision {rev} · created {p.get('created', '?')} · "
                f"configuration {sha[:12]}")
    footer = (f"{doc['number'] or 'Document number ' + number} rev. {rev} · jls {p.get('jls_version', '?')} · "
              + (commit if commit == control.NOT_GIT else f"commit {commit}"))
    head = ('#import "template.typ": *\n'
            f'#show: report.with(title: [{t(title)}], subtitle: [{t(subtitle)}], '
            f'footer-left: [{t(footer)}])\n\n')
    return head + "\n".join(chapter.chapter(cx) for chapter in CHAPTERS)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _timestamp(created):
    try:
        stamp = datetime.fromisoformat(str(created))
    except ValueError:
        return None
    return stamp if stamp.tzinfo is not None else None


def compile_pdf(typ_path: Path, pdf_path: Path, created=None) -> None:
    try:
        typst.compile(str(typ_path), output=str(pdf_path), root=str(typ_path.parent),
                      ignore_system_fonts=True, timestamp=_timestamp(created))
    except typst.TypstError as exc:
        raise ReportError(f"typesetting the report failed: {exc.message}\n{exc.diagnostic}") from exc


@few_collections()     # drawing makes many short-lived objects (jls.collector)
def render_report(out_pdf, *, route, sea_states, vessel_motion, plant, response, workability,
                  provenance, weather_windows=None, screening=None, timedomain=(),
                  timedomain_cells=(), tugger_studies=None, verification=(), voyage=None,
                  measured=None, voyage_plan=None, workers=1, verification_study=None,
                  verification_wires=()) -> Path:
    """Render the route's PDF assessment report to ``out_pdf`` and return its path.

    The five datasets are those of docs/reference/outputs.md (complex variables whole or split
    into _re/_im); ``provenance`` is the dict of :func:`jls.io.provenance.provenance` plus
    ``vessel_source`` and ``vessel_description``. Optional: ``weather_windows``, the
    route's weather-window dataset when it has hindcast legs; ``screening``, screening.nc
    when the route was screened (chapter "Rigging"); ``timedomain``, the time-domain cell
    datasets; ``timedomain_cells``, the chosen cells (name, reasons); ``tugger_studies``,
    the decay and slope-sweep dataset (chapter "Damping tuggers"); ``verification``, the
    verification cell datasets (layout ``verification_cell``, :mod:`jls.report.verification`);
    ``verification_study``, the study comparison (layout ``verification_study``);
    ``verification_wires``, the wire checks (layout ``verification_wires``).
    ``voyage``, voyage.nc
    (chapter "Voyage extremes" and the voyage line of page 1). ``measured``,
    measured_response.nc when a leg is given by spectra (chapter "Wave spectra"). ``voyage_plan``,
    voyage_plan.nc (page 1's verdict and the master's forecast table, chapter "Voyage
    plan"). ``workers``: processes
    that draw the figures (the Typst source is written meanwhile); the PDF is the same
    for any number. Everything is checked before any drawing; the PDF is compiled to a temporary file beside ``out_pdf`` and renamed
    over it only when complete, so a failure never leaves a partial report.
    """
    out_pdf = Path(out_pdf)
    data = {"sea_states": sea_states, "vessel_motion": vessel_motion, "plant": plant,
            "response": response, "workability": workability}
    check(data, optional={"voyage": voyage, "measured_response": measured, "voyage_plan": voyage_plan})
    prov = dict(_check_provenance(provenance))
    prov["created"] = control.created(prov)
    if not prov.get("git_commit"):
        prov["git_commit"] = control.source_commit()
    dg = digest(str(route), sea_states, vessel_motion, plant, response, workability, prov)
    out_pdf.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="jls-report-") as tmp:
        tmp = Path(tmp)
        cx = Context(sea=sea_states, vessel=vessel_motion, plant=plant, resp=response,
                     work=workability, prov=prov, dg=dg, figs={}, windows=weather_windows,
                     screening=screening, td=list(timedomain),
                     td_cells=list(timedomain_cells), studies=tugger_studies,
                     verification=list(verification), voyage=voyage, measured=measured, plan=voyage_plan,
                     verification_study=verification_study,
                     verification_wires=list(verification_wires))
        cx.sections = present_chapters(cx)
        tasks = drawing.plan(cx)
        cx.figs = drawing.names(tasks)
        main = tmp / "report.typ"
        with drawing.drawn(tasks, tmp, workers):
            template = resources.files("jls.report").joinpath("template.typ")
            with resources.as_file(template) as tpl:
                shutil.copyfile(tpl, tmp / "template.typ")
            main.write_text(source(cx), encoding="utf-8")
        fd, partial = tempfile.mkstemp(prefix=f".{out_pdf.stem}.", suffix=".partial.pdf",
                                       dir=out_pdf.parent)
        os.close(fd)
        try:
            compile_pdf(main, Path(partial), prov.get("created"))
            os.chmod(partial, 0o666 & ~_umask())     # mkstemp made it private
            os.replace(partial, out_pdf)
        finally:
            if os.path.exists(partial):
                os.unlink(partial)
    return out_pdf
