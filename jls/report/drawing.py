"""Which figures the report has, and drawing them, serially or in worker processes.

    tasks = plan(cx)                      # [(name, draw)]: draw(out_dir) writes <name>.svg
    with drawn(tasks, out_dir, workers=2):
        ...                               # the figures are drawn meanwhile
    # every figure is in out_dir here (or the first failure is raised)

The list of figures and their file names are known before any is drawn, so the Typst
source can be written while the figures are being drawn. Each figure is drawn by one
process from the same code and data, so its SVG bytes do not depend on ``workers``
(matplotlib's ids are content hashes salted with ``svg.hashsalt``). With ``workers > 1``
the figures go to forked processes (the datasets are inherited, not pickled), the most
expensive first; where ``fork`` is not available they are drawn serially.
"""

from __future__ import annotations

import multiprocessing
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager
from pathlib import Path
from typing import Callable, NamedTuple

from jls.report import (
    figures,
    figures_assessment,
    figures_compare,
    figures_rigging,
    robustness,
    sections_rigging,
    sections_tuggers,
    sections_windows,
)


class Task(NamedTuple):
    name: str                              # the file is <name>.svg
    draw: Callable[[Path], Path]           # out_dir -> the saved file
    cost: float = 1.0                      # drawing time, about 0.1 s a unit: sets the order


def file_name(name: str) -> str:
    return f"{name}.svg"


def plan(cx) -> list[Task]:
    """Every figure of the report, in the report's order (module attributes are looked
    up when a figure is drawn, not when it is planned)."""
    dg = cx.dg
    n_head = cx.resp.sizes.get("heading", 1)
    live = (cx.sea["probability"] > 0).sum(("hs", "tz"))         # labelled cells per leg
    tasks = [
        Task("rigging", lambda d: figures.rigging(cx.plant, dg, d), 1.5),
        Task("hinge_raos", lambda d: figures.hinge_raos(cx.vessel, cx.plant, dg, d), 3.0),
        Task("relative_transfer", lambda d: figures.relative_transfer(cx.resp, cx.plant, dg, d),
             4.0 * n_head),
        Task("operability", lambda d: figures.operability(cx.work, cx.sea, dg, d),
             1.0 + n_head * len(dg.plot.candidates)),
        Task("workability", lambda d: figures.workability_bars(cx.work, dg, d), 1.0),
    ]
    if robustness.has_bands(cx.work):
        tasks.append(Task("workability_bands",
                          lambda d: figures_assessment.workability_bands(cx.work, dg, d), 1.0))
    if robustness.has_sensitivity(cx.work):
        tasks.append(Task("criterion_sensitivity",
                          lambda d: figures_assessment.criterion_sensitivity(cx.work, dg, d), 1.0))
    if cx.windows is not None:
        tasks.append(Task("window_months", lambda d: figures_assessment.window_months(
            cx.windows, sections_windows.window_combo(cx), d), 1.0))
    for leg in cx.legs:
        tasks.append(Task(f"scatter_{leg}",
                          lambda d, leg=leg: figures.scatter(cx.sea, cx.work, dg, leg, d),
                          1.0 + 0.03 * float(live.sel(leg=leg))))
    if sections_rigging.present(cx):
        tasks += rigging_tasks(cx)
    costs = {"td_traces": 1.0 + 1.2 * len(sections_tuggers.trace_cells(cx))}
    tasks += [Task(name, draw, costs.get(name, 0.7))
              for name, draw in sections_tuggers.figure_plan(cx)]
    return tasks


def rigging_tasks(cx) -> list[Task]:
    """The figures of the chapter "Rigging" (see :mod:`jls.report.sections_rigging`)."""
    s = cx.screening

    def screening_figure(name, draw):
        return lambda d: figures._save(draw(s), d, f"rigging_{name}")

    tasks = [Task(f"rigging_{name}", screening_figure(name, draw), cost)
             for name, draw, cost in (("sensitivity", figures_rigging.sensitivity, 2.5),
                                      ("surface", figures_rigging.screening_surface, 1.8),
                                      ("geometry", figures_rigging.geometry, 1.3))]
    tugs = [str(x) for x in cx.work["tugger"].values][:4]
    tasks.append(Task("rigging_compare", lambda d: figures_compare.baseline_vs_optimised(
        cx.resp, cx.work, tugs, d), 3.2))
    tasks.append(Task("recommended_operability", lambda d: figures_compare.recommended_operability(
        cx.work, cx.sea, cx.dg.best, float(s.attrs["design_hs_m"]), d), 0.8))
    return tasks


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
