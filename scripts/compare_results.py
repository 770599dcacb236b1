"""Build the default route at two commits and compare every dataset.

    python scripts/compare_results.py REF [--route default] [--keep DIR]

Runs ``snakemake --cores 2`` in a clean worktree of REF and in a clean copy of the working
tree (each importing its own ``jls``), then compares every NetCDF file of ``results/``:
identical bytes, or identical data and attributes but for what records a run rather than
a result (``wall_time``, a verification cell's ``wall_time_reference``; with
``--ignore-config-hash`` also the ``config_sha256`` attribute, which changes with any
schema default). Exits 1 on any other difference.
Used to check that a restructuring changes no number.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

ROOT = Path(__file__).resolve().parents[1]
RUN_RECORDS = ("wall_time", "wall_time_reference")     # what records a run, not a result


def build(tree: Path) -> Path:
    env = dict(os.environ, PYTHONPATH=str(tree))
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", "-q"], cwd=tree, env=env,
                       capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"the workflow failed in {tree}:\n{r.stderr[-3000:]}")
    return tree / "results"


def differences(a: Path, b: Path, ignore_hash: bool) -> list[str]:
    out = []
    files_a = sorted(p.relative_to(a) for p in a.rglob("*.nc"))
    files_b = sorted(p.relative_to(b) for p in b.rglob("*.nc"))
    if files_a != files_b:
        out.append(f"different files: {sorted(set(files_a) ^ set(files_b))}")
    for rel in sorted(set(files_a) & set(files_b)):
        if (a / rel).read_bytes() == (b / rel).read_bytes():
            continue
        da, db = (xr.load_dataset(p / rel).drop_vars(list(RUN_RECORDS), errors="ignore") for p in (a, b))
        if ignore_hash:
            for d in (da, db):
                d.attrs.pop("config_sha256", None)
        if not da.identical(db):
            vars_ = [v for v in set(da.variables) | set(db.variables)
                     if v not in da.variables or v not in db.variables or not da[v].identical(db[v])]
            attrs = [k for k in set(da.attrs) | set(db.attrs)
                     if not np.array_equal(np.asarray(da.attrs.get(k), object), np.asarray(db.attrs.get(k), object))]
            out.append(f"{rel}: variables {sorted(vars_)}, attributes {sorted(attrs)}")
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ref", help="the commit to compare the working tree against")
    ap.add_argument("--ignore-config-hash", action="store_true")
    ap.add_argument("--keep", type=Path, help="keep both builds in this folder")
    args = ap.parse_args(argv)
    tmp = Path(args.keep or tempfile.mkdtemp(prefix="jls-compare-"))
    old, new = tmp / "ref", tmp / "work"
    subprocess.run(["git", "worktree", "add", "--detach", str(old), args.ref], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)
    try:
        shutil.copytree(ROOT, new, ignore=shutil.ignore_patterns(
            ".git", ".venv", "results", "reports", "logs", ".snakemake", "__pycache__", "benchmarks/out"))
        diff = differences(build(old), build(new), args.ignore_config_hash)
    finally:
        subprocess.run(["git", "worktree", "remove", "--force", str(old)], cwd=ROOT, check=False)
        if not args.keep:
            shutil.rmtree(tmp, ignore_errors=True)
    for line in diff:
        print(line)
    print("identical" if not diff else f"{len(diff)} difference(s)")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main())
