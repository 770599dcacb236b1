"""Nonlinear time-domain model: irregular sea, compiled plant, runs and decay tests.

The names below are imported on first use: the compiled model brings numba (0.15 s of a
job's start-up), which the jobs that only name or choose cells (:mod:`jls.timedomain.cells`)
do not need. The decay test is ``jls.timedomain.decay.decay`` (``jls.timedomain.decay`` is
its module).
"""

import importlib

_LAZY = {"Case": "run", "Settings": "run", "run_cells": "run", "Decay": "decay"}


def __getattr__(name):
    if name in _LAZY:
        return getattr(importlib.import_module(f"jls.timedomain.{_LAZY[name]}"), name)
    raise AttributeError(f"module 'jls.timedomain' has no attribute {name!r}")


__all__ = ["Case", "Settings", "run_cells", "Decay"]
