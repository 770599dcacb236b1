"""Benchmark: the rigging screening through the workflow (chunk jobs on the fast solver,
the gather job with the refinement), from a cold sea-state cache.

1. The default screening of the shipped route: 21 x 21 over top spread Y and drop height,
   three tugger settings, refinement included; `snakemake --cores 2
   results/default/screening.nc` (sea states and vessel motion included). Target < 30 s.
2. A four-variable screening, 10 x 10 x 10 x 10 = 10 000 candidates (and the baseline),
   three tugger settings, refinement included, the same command. Target < 90 s.

Each runs in a temporary copy of the repository (kernels compiled, no results), so the
working tree is left alone.
Run: python benchmarks/bench_screening.py
"""

import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml
from rows import within, workflow_copy

ROOT = Path(__file__).resolve().parents[1]
TARGET = "results/default/screening.nc"
THREE = [{"name": "none", "c_kN_s_per_m": 0},
         {"name": "low", "c_kN_s_per_m": 300, "max_force_kN": 1000, "min_force_kN": 20},
         {"name": "reference", "c_kN_s_per_m": 1000, "max_force_kN": 1000, "min_force_kN": 20}]
CASES = {
    "default": {"tuggers": THREE, "screening": {"enabled": True}},
    "four_variables": {"tuggers": THREE, "screening": {
        "enabled": True, "chunk_candidates": 2560,
        "grid_points": {"top_spread_y_m": 10, "bottom_spread_y_m": 10,
                        "bottom_spread_x_m": 10, "drop_height_m": 10}}},
}


def timed_screening(overrides: dict):
    """(wall s, candidates, log line of the gather job) of one screening from scratch."""
    with tempfile.TemporaryDirectory() as tmp:
        work = workflow_copy(ROOT, Path(tmp) / "jls")
        (work / "over.yaml").write_text(yaml.safe_dump(overrides))
        t0 = time.perf_counter()
        r = subprocess.run([sys.executable, "-m", "snakemake", TARGET, "--cores", "2", "--quiet",
                            "--configfile", "over.yaml"], cwd=work, capture_output=True,
                           text=True)
        if r.returncode:
            raise RuntimeError(f"the screening run failed: {r.stderr[-2000:]}")
        wall = time.perf_counter() - t0
        line = [x for x in (work / "logs" / "default" / "screening.log").read_text().splitlines()
                if "candidates from" in x][-1]
    return wall, line


def rows():
    wall_d, log_d = timed_screening(CASES["default"])
    wall_4, log_4 = timed_screening(CASES["four_variables"])
    print(log_d.split("INFO ")[-1], file=sys.stderr)
    print(log_4.split("INFO ")[-1], file=sys.stderr)
    return [within("screening 21 x 21, 3 tuggers, refined (workflow, --cores 2)", 30.0, wall_d),
            within("screening 10^4 candidates, 4 variables, 3 tuggers, refined (workflow, --cores 2)",
                   90.0, wall_4)]


def main():
    from run import table
    print(table(rows()))


if __name__ == "__main__":
    main()
