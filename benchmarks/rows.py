"""A benchmark result row and how its ratio is read, shared by the benchmark scripts.

A row is (figure, target, measured, ratio): ``ratio >= 1`` meets the target (target
over measured for a time or a memory limit, measured over target for a rate).
"""

from __future__ import annotations

from typing import NamedTuple


class Row(NamedTuple):
    figure: str
    target: str
    measured: str
    ratio: float


def within(figure: str, limit: float, measured: float, unit: str = "s") -> Row:
    """A figure that must stay under ``limit`` (a time or a memory)."""
    return Row(figure, f"< {limit:g} {unit}", f"{measured:.3g} {unit}",
               limit / measured if measured > 0 else float("inf"))


def at_least(figure: str, floor: float, measured: float, unit: str) -> Row:
    """A rate that must reach ``floor``."""
    return Row(figure, f">= {floor:g} {unit}", f"{measured:.3g} {unit}", measured / floor)


# What a workflow copy leaves out: results, logs and caches of earlier runs. The
# __pycache__ folders come along: they hold the kernels numba compiled (valid for the
# copy, whose sources keep their modification times), so that "from clean" measures a
# run of the workflow, not a first compilation; ``compiled=False`` measures that.
RUN_STATE = ("results", "reports", "logs", ".snakemake", "out", ".git", ".venv")

WARM = """
import numpy as np
from jls.response.solver import relative_power, transfer_functions
from jls.config.loader import load
from jls.stages.timedomain_cell import candidate_plant
from jls.timedomain.decay import decay
from jls.tugger.setting import Tugger
a = np.eye(4)[None]; q = np.ones((1, 2, 4), complex); w = np.array([0.5, 1.0])
relative_power(a, a, a, a, w, q, q[..., 0], [0.0]); transfer_functions(a, a, a, a, w, q)
plant = candidate_plant(load("config/config.yaml"), "baseline")
decay(plant, Tugger("reference", 1000.0), release_m=1.0, duration_s=1.0)
"""


def random_plant(cfg, n, rng):
    """The plant of ``n`` riggings of the shipped configuration ``cfg`` drawn with ``rng``
    (top spread 38-55 m, drop height 55-66 m): the candidates of the benchmarks."""
    from jls.config.builders import rigging_from_config
    from jls.plant.candidates import plant_dataset
    values = {f"c{i}": {"top_spread_y": rng.uniform(38, 55), "drop_height": rng.uniform(55, 66)}
              for i in range(n)}
    return plant_dataset(rigging_from_config(cfg), values)[0]


def workflow_copy(root, dest, compiled=True):
    """Copy the repository to ``dest`` for a timed workflow run: without results, and
    with the solver's kernels compiled (``compiled=False``: as a fresh install, numba
    compiles them in the first jobs that need them)."""
    import shutil
    import subprocess
    import sys
    ignore = RUN_STATE if compiled else RUN_STATE + ("__pycache__",)
    shutil.copytree(root, dest, ignore=shutil.ignore_patterns(*ignore))
    if compiled:   # compile what the copied caches lack (a no-op when they are valid)
        subprocess.run([sys.executable, "-c", WARM], cwd=dest, check=True)
    return dest
