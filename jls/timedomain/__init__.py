"""Nonlinear time-domain model: irregular sea, compiled plant, runs and decay tests."""

from jls.timedomain.decay import Decay, decay
from jls.timedomain.run import Case, Settings, run_cells

__all__ = ["Case", "Settings", "run_cells", "Decay", "decay"]
