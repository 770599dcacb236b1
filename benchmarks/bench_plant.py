"""Benchmark: K, Kb and modes for 10 000 candidate rigging geometries on one core.

Target (issue: plant): under 2 s. Run: python benchmarks/bench_plant.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from rows import within  # noqa: E402

from jls.config.builders import rigging_from_config  # noqa: E402
from jls.config.loader import load  # noqa: E402
from jls.plant.model import build  # noqa: E402
from jls.plant.rigging import apply_design  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def bench(n=10_000, repeat=5):
    """(best seconds, geometries with finite periods) for n random geometries."""
    rig = rigging_from_config(load(ROOT / "config" / "config.yaml"))
    rng = np.random.default_rng(0)
    space = rig.design_space
    values = {name: rng.uniform(*space[name], n) for name in space}
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        layout = apply_design(rig.layout, rig.jacket.z_p, **values)
        plant = build(layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta)
        best = min(best, time.perf_counter() - t0)
    return best, int(np.isfinite(plant.modes.period).all(-1).sum())


def rows(n=10_000):
    best, _ = bench(n)
    return [within(f"K, Kb and modes for {n} geometries, one core", 2.0, best)]


def main(n=10_000, repeat=5):
    best, ok = bench(n, repeat)
    print(f"{n} geometries (equilibrium, K, Kb, modes, Rayleigh C): best of {repeat} "
          f"{best:.3f} s on one core; {ok} with finite periods; target < 2 s")


if __name__ == "__main__":
    main()
