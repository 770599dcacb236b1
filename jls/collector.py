"""How often a short process collects reference cycles.

A workflow job, or a report being drawn, makes many objects that live until it ends
(modules, datasets) and many short-lived ones (matplotlib's artists). Python collects
its youngest generation after 700 allocations; :data:`THRESHOLD` collects it after
20 000. The default route's 19 figures drawn serially spent 0.83 s in the collector at
Python's defaults, 0.24 s with the heap frozen, 0.07 s with both; the report job's
imports ran 328 collections (0.10-0.12 s of CPU) at the defaults, 10 after. Imports only
the standard library, so a workflow script can call it before numpy or xarray.
"""

from __future__ import annotations

import gc
from contextlib import contextmanager

#: The collector's thresholds in a short process (Python's default: 700, 10, 10).
THRESHOLD = (20_000, 50, 100)


def collect_seldom() -> None:
    """Set :data:`THRESHOLD` for the rest of the process (a workflow job's first call)."""
    gc.set_threshold(*THRESHOLD)


@contextmanager
def few_collections(threshold=THRESHOLD):
    """Collect seldom while the block runs, restored on leaving: the objects alive when it
    starts are frozen, left out of every collection (in forked workers too; a workflow job
    has frozen them already, :func:`jls.io.provenance.workflow_step`, and keeps them so),
    and the thresholds are ``threshold``."""
    old, frozen = gc.get_threshold(), gc.get_freeze_count() > 0
    gc.freeze()
    gc.set_threshold(*threshold)
    try:
        yield
    finally:
        gc.set_threshold(*old)
        if not frozen:
            gc.unfreeze()


__all__ = ["THRESHOLD", "collect_seldom", "few_collections"]
