"""Benchmark the report job of the shipped default route.

The workflow runs once with `snakemake --cores 2` in a temporary copy of the repository
to make the report's inputs; then the report job alone is re-run a few times and the
best wall-clock time of its Snakemake benchmark file (interpreter start-up, imports,
reading the datasets, drawing the figures, Typst) is the figure (target < 5 s); the
job draws its figures with as many processes as the rule gives it threads. The other
row is `render_report` alone (imports excluded) on the same datasets with two figure
workers over one (aim: at most 0.75 of the time).

Run: python benchmarks/bench_report.py
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from rows import within, workflow_copy

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = [sys.executable, "-m", "snakemake", "--cores", "2", "--quiet"]
REPEAT = 3


def _job_seconds(work: Path) -> float:
    """The report job's wall-clock time from its Snakemake benchmark file (column s)."""
    tsv = work / "benchmarks" / "out" / "default" / "report.tsv"
    return float(tsv.read_text().splitlines()[-1].split("\t")[0])


def _render_seconds(work: Path, workers: int) -> float:
    """render_report alone, in a fresh process (imports excluded), best of REPEAT."""
    code = (
        "import json, sys, time\n"
        "from pathlib import Path\n"
        "from jls.io.netcdf import read\n"
        "from jls.report import render_report\n"
        "r = Path('results/default')\n"
        "data = {n: read(r / f) for n, f in [('sea_states', 'sea_states.nc'),"
        " ('vessel_motion', 'vessel_motion.nc'), ('plant', 'plant_assessed.nc'),"
        " ('response', 'response.nc'), ('workability', 'workability.nc')]}\n"
        "cells = json.loads((r / 'timedomain' / 'cells.json').read_text())\n"
        "td = [read(p) for p in sorted((r / 'timedomain').glob('*.nc'))]\n"
        "screening = read(r / 'screening.nc') if (r / 'screening.nc').exists() else None\n"
        "opt = lambda f: read(r / f) if (r / f).exists() else None\n"
        "v = r / 'verification'\n"
        "chosen = {c['name']: c for c in json.loads((v / 'cells.json').read_text())} if (v / 'cells.json').exists() else {}\n"
        "verification = [read(p) for p in sorted(v.glob('*.nc'))]\n"
        "for ds in verification:\n"
        "    c = chosen.get(str(ds.attrs['cell']), {})\n"
        "    ds.attrs.update(roles='; '.join(c.get('roles', [])), reasons='; '.join(c.get('reasons', [])))\n"
        "extra = dict(voyage=read(r / 'voyage.nc'), voyage_plan=read(r / 'voyage_plan.nc'),"
        " weather_windows=opt('weather_windows.nc'), measured=opt('measured_response.nc'),"
        " verification=verification, verification_study=opt('verification_study.nc'),"
        " verification_wires=[read(p) for p in sorted((v / 'wires').glob('*.nc'))])\n"
        "prov = {'jls_version': '0', 'config_sha256': 'x', 'created': '2026-01-01T00:00:00+00:00',"
        " 'inputs': {}, 'document': {}}\n"
        "best = 1e9\n"
        f"for _ in range({REPEAT}):\n"
        "    t0 = time.perf_counter()\n"
        "    render_report('reports/bench.pdf', route='default', provenance=prov, screening=screening,"
        " timedomain=td, timedomain_cells=cells, tugger_studies=read(r / 'tugger_studies.nc'),"
        f" workers={workers}, **data, **extra)\n"
        "    best = min(best, time.perf_counter() - t0)\n"
        "print(best)\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=work, check=True, capture_output=True,
                         text=True, env={**os.environ, "PYTHONPATH": str(work)})
    return float(out.stdout.strip().splitlines()[-1])


def bench_report():
    """(best report job s, render_report s with 1 worker, with 2 workers)."""
    with tempfile.TemporaryDirectory() as tmp:
        work = workflow_copy(ROOT, Path(tmp) / "jls")
        subprocess.run(SNAKEMAKE + ["all"], cwd=work, check=True, capture_output=True)
        job = []
        for _ in range(REPEAT):
            subprocess.run(SNAKEMAKE + ["--forcerun", "report", "reports/default.pdf"], cwd=work,
                           check=True, capture_output=True)
            job.append(_job_seconds(work))
        return min(job), _render_seconds(work, 1), _render_seconds(work, 2)


def rows():
    job, one, two = bench_report()
    return [within(f"report job of the default route, --cores 2 (best of {REPEAT})", 5.0, job),
            within(f"  render_report, 2 figure workers over 1 ({two:.2f} s / {one:.2f} s)", 0.75,
                   two / one, "x")]


def main():
    t0 = time.perf_counter()
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
    print(f"({time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    main()
