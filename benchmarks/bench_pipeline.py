"""Benchmark the pipeline and the statistics kernel.

1. The shipped default route from a clean results/ with `snakemake --cores 2`,
   verification against the nonlinear reference included (target < 20 s).
2. A rerun after editing one leg's probabilities (target < 8 s).
   And, for the record, the first run of a fresh install (numba compiles the kernels).
3. Unit-Hs statistics for 1 000 scatter cells of one plant (target < 0.1 s).

The workflow runs in a temporary copy of the repository, so the working tree is left
alone; "from clean" starts without results/ but with the solver's kernels compiled (as
after any earlier run); the first run of a fresh install compiles them too. Run: python benchmarks/bench_pipeline.py
"""

import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from rows import within, workflow_copy

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = [sys.executable, "-m", "snakemake", "--cores", "2", "--quiet", "all"]


def timed_run(cwd):
    t0 = time.perf_counter()
    subprocess.run(SNAKEMAKE, cwd=cwd, check=True, capture_output=True)
    return time.perf_counter() - t0


def edit_probabilities(table: Path):
    """Move 5 records between two non-zero counts of a row of a matrix table: the
    probabilities change, the record count its header states does not (a changed total
    is refused as a table that disagrees with its own metadata)."""
    lines = table.read_text().splitlines()
    for i, line in enumerate(lines):
        if line and not line.startswith("#") and line[0].isdigit():
            cells = line.split(",")
            counts = [j for j in range(1, len(cells)) if cells[j].strip() not in ("0", "")]
            big = [j for j in counts if int(cells[j]) > 5]
            if big and len(counts) > 1:
                give = big[0]
                take = next(j for j in counts if j != give)
                cells[give] = str(int(cells[give]) - 5)
                cells[take] = str(int(cells[take]) + 5)
                lines[i] = ",".join(cells)
                table.write_text("\n".join(lines) + "\n")
                return
    raise RuntimeError(f"no counts to move in {table}")


def bench_statistics(n_hs=40, n_tz=25, repeat=20):
    from jls.plant.model import from_matrices
    from jls.response.solver import frequency_grid, transfer_functions
    from jls.response.statistics import unit_statistics

    p = from_matrices(ROOT / "tests" / "data" / "appendix_a1_plant.yaml", g=9.81, zeta=0.0098)
    omega = frequency_grid(0.15, 2.5, 0.002, 2 * np.pi / p.modes.period, p.damping_ratio)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0
    _, H = transfer_functions(p.M, p.K, p.Kb, p.C, omega, qb)
    H = np.moveaxis(H[0, 0], -1, -2)                        # (response, omega)
    hs = np.linspace(0.25, 9.75, n_hs)
    tz = np.linspace(3.0, 15.0, n_tz)
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        s = unit_statistics(omega, H, tz)
        mpm = hs[:, None, None] * s["mpm"][None]            # every cell, every response
        best = min(best, time.perf_counter() - t0)
    return best, mpm.shape[0] * mpm.shape[2], omega.size


def bench_workflow():
    """(clean run s, rerun after a probability edit s, first run of a fresh install s) of
    the shipped default route."""
    with tempfile.TemporaryDirectory() as tmp:
        work = workflow_copy(ROOT, Path(tmp) / "jls")
        clean = timed_run(work)
        edit_probabilities(work / "config" / "routes" / "default" / "leg2_cape_canaveral.csv")
        rerun = timed_run(work)
    with tempfile.TemporaryDirectory() as tmp:
        first = timed_run(workflow_copy(ROOT, Path(tmp) / "jls", compiled=False))
    return clean, rerun, first


def rows():
    clean, rerun, first = bench_workflow()
    stats, cells, n_omega = bench_statistics()
    return [within("default route from clean results/ (verification included), --cores 2", 20.0, clean),
            within("rerun after editing one leg's probabilities", 8.0, rerun),
            within("  first run of a fresh install (numba compiles the kernels once)", 15.0, first),
            within(f"statistics for {cells} scatter cells of one plant ({n_omega} frequencies)",
                   0.1, stats)]


def main():
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")


if __name__ == "__main__":
    main()
