"""Which figures the report has, and drawing them, serially or in worker processes.

    tasks = plan(cx)                      # [Task(name, draw, cost)]: draw(out_dir) writes <name>.svg
    with drawn(tasks, out_dir, workers=2):
        ...                               # the figures are drawn meanwhile
    # every figure is in out_dir here (or the first failure is raised)

The figures are planned by chapter (each chapter module's ``figure_plan``, in the order
of :data:`jls.report.chapters.CHAPTERS`). The list of figures and their file names are
known before any is drawn, so the Typst source can be written while the figures are being
drawn. Each figure is drawn by one process from the same code and data, so its SVG bytes
do not depend on ``workers``
(matplotlib's ids are content hashes salted with ``svg.hashsalt``). With ``workers > 1``
the figures go to forked processes (the datasets are inherited, not pickled), the most
expensive first; where ``fork`` is not available they are drawn serially.
"""

from __future__ import annotations

import multiprocessing
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager
from pathlib import Path

from jls.report.chapters import CHAPTERS
from jls.report.style import Task, file_name


def plan(cx) -> list[Task]:
    """Every figure of the report, chapter by chapter in the report's order (each
    chapter's ``figure_plan``; a figure's function is looked up when it is drawn, not when
    it is planned)."""
    return [task for chapter in CHAPTERS if hasattr(chapter, "figure_plan")
            for task in chapter.figure_plan(cx)]


def names(tasks) -> dict:
    """name -> file name of every planned figure (what the Typst source refers to)."""
    return {task.name: file_name(task.name) for task in tasks}


# -- drawing ----------------------------------------------------------------------------
_FORKED: list = []            # the tasks and folder, inherited by the forked workers


def _draw_one(i: int) -> str:
    tasks, out_dir = _FORKED
    return str(tasks[i].draw(out_dir))


def can_fork() -> bool:
    return "fork" in multiprocessing.get_all_start_methods()


@contextmanager
def drawn(tasks, out_dir, workers: int = 1):
    """Draw ``tasks`` into ``out_dir``: with ``workers`` <= 1 (or without ``fork``)
    before the body runs, else in ``workers`` forked processes while it runs. On leaving,
    every figure has been written; a figure's exception is raised in the caller."""
    out_dir = Path(out_dir)
    if workers <= 1 or len(tasks) <= 1 or not can_fork():
        for task in tasks:
            task.draw(out_dir)
        yield
        return
    order = sorted(range(len(tasks)), key=lambda i: -tasks[i].cost)   # stable: ties keep order
    _FORKED[:] = [list(tasks), out_dir]
    pool = ProcessPoolExecutor(min(workers, len(tasks)),
                               mp_context=multiprocessing.get_context("fork"))
    try:
        futures = [pool.submit(_draw_one, i) for i in order]
        yield
        for future in futures:
            future.result()
    finally:
        _FORKED.clear()
        pool.shutdown(wait=True, cancel_futures=True)
