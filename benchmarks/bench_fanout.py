"""Benchmark: the assessment of many rigging candidates.

1. 441 candidates (21 x 21 top spread x drop height) on the shipped route with its 3
   tugger settings: the library's work from configuration to workability in one
   process, interpreter start-up and imports excluded (target < 5 s), and the workflow
   with `snakemake --cores 2`, report included (target < 30 s wall clock).
2. 10 000 candidates (a 10 x 10 x 10 x 10 grid of the four design variables) through
   the workflow to workability.nc with `snakemake --cores 2` (target < 60 s wall clock,
   < 4 GB peak memory of any job).

The workflow runs in a temporary copy of the repository. Run:
python benchmarks/bench_fanout.py
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml
from rows import WARM, within, workflow_copy

ROOT = Path(__file__).resolve().parents[1]
# Runs a command and prints the peak resident memory of its largest descendant (kB).
MAXRSS = ("import resource, subprocess, sys; r = subprocess.run(sys.argv[1:]); "
          "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr); "
          "sys.exit(r.returncode)")


def _lin(lo, hi, n):
    return [round(float(x), 3) for x in np.linspace(lo, hi, n)]


def grid_441():
    return {"top_spread_y_m": _lin(36.0, 60.0, 21), "drop_height_m": _lin(51.0, 66.4, 21)}


def grid_10k():
    return {"top_spread_y_m": _lin(36.0, 60.0, 10), "bottom_spread_y_m": _lin(31.0, 46.5, 10),
            "bottom_spread_x_m": _lin(10.5, 34.0, 10), "drop_height_m": _lin(51.0, 66.4, 10)}


def compute_441() -> float:
    """Seconds of library work for 441 candidates, after the imports."""
    from jls.assessment.workability import assess
    from jls.config.builders import candidate_values, rigging_from_config
    from jls.config.loader import load
    from jls.plant.candidates import plant_dataset
    from jls.sea.legs import read_leg
    from jls.stages.response import response_dataset
    from jls.stages.sea_states import sea_states
    from jls.stages.vessel_motion import vessel_motion

    cfg = load(ROOT / "config" / "config.yaml")
    cfg["candidate_grid"] = grid_441()
    route = cfg["routes"]["default"]
    t0 = time.perf_counter()
    plant, _ = plant_dataset(rigging_from_config(cfg), candidate_values(cfg))
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    legs = {leg["name"]: read_leg(leg, ROOT, cfg["sea"]["steepness_rule"], cfg["sea"]["gamma"],
                                  cfg["g_m_per_s2"]) for leg in route["legs"]}
    sea = sea_states(route, legs)
    tuggers = {t["name"]: t["c_kN_s_per_m"] for t in cfg["tuggers"]}
    tz = sea["tz"].values.tolist() + np.arange(3.0, 14.001, 0.25).tolist()
    resp = response_dataset(plant, motion, tz, [90.0], tuggers, outside_policy={"zero_above_rad_s": 3.0, "reason": "the hull no longer responds above 3 rad/s"},
                            shown=["baseline", "detuned"])
    assess(resp.sel(tz=sea["tz"].values), sea, {"relative_sway_m": 3.0})
    return time.perf_counter() - t0


def workflow(grid: dict, target: str) -> tuple[float, float]:
    """(wall clock s, peak job memory GB) of `snakemake --cores 2 target` from clean."""
    with tempfile.TemporaryDirectory() as tmp:
        work = workflow_copy(ROOT, Path(tmp) / "jls")
        # the time domain runs the baseline's boundary cells only, as when these figures
        # were first measured (the default now adds the named candidates' and the grid's
        # timedomain.grid_boundary_candidates best: docs/theory/tuggers.md)
        (work / "grid.yaml").write_text(yaml.safe_dump({"candidate_grid": grid,
                                                        "timedomain": {"boundary_candidates": ["baseline"]}}))
        cmd = [sys.executable, "-c", MAXRSS, sys.executable, "-m", "snakemake", target,
               "--cores", "2", "--quiet", "--configfile", "grid.yaml"]
        t0 = time.perf_counter()
        r = subprocess.run(cmd, cwd=work, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        if r.returncode != 0:
            raise RuntimeError(r.stderr[-2000:])
        return wall, int(r.stderr.strip().splitlines()[-1]) / 1024**2


def warm_up():
    """Load (or, on a fresh install, compile once and cache) the solver's kernels, for the
    library figure measured in this process."""
    subprocess.run([sys.executable, "-c", WARM], check=True, cwd=ROOT)


def rows():
    warm_up()
    compute = compute_441()
    wall_441, _ = workflow(grid_441(), "all")
    wall_10k, mem_10k = workflow(grid_10k(), "results/default/workability.nc")
    return [within("441 candidates x route x 3 tuggers: library compute (no start-up)", 5.0, compute),
            within("441 candidates x route x 3 tuggers: workflow with report, --cores 2", 30.0, wall_441),
            within("10 000 candidates (4-variable grid) to workability.nc, --cores 2", 60.0, wall_10k),
            within("  peak memory of any job, 10 000 candidates", 4.0, mem_10k, "GB")]


if __name__ == "__main__":
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
