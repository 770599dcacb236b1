"""Every number is independent of the threads a job runs with and of the sea-state
cache's history.

Snakemake sets a job's BLAS threads (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS) to the job's
threads, and a multi-threaded BLAS rounds a matrix product differently from a
single-threaded one; the solver's own threads solve each candidate alone. So the moments'
product runs on one BLAS thread (jls.threads.single_threaded_blas), and a 1-thread and a
2-thread run give the same bits, in the datasets and in the cache. The 1-thread run's jobs
run in their own processes, the 2-thread run's in children of the job server
(workflow/scripts/_server.py): the bits do not depend on that either.
"""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from test_pipeline import make_workdir

from jls.io.netcdf import read

PRODUCT = """
import sys
import numpy as np
from jls.response.solver import spectral_moments
rng = np.random.default_rng(7)
P = rng.random((3, 64, 4, 1625))
W = rng.random((1625, 90))
m0, m2 = spectral_moments(P, W)
np.save(sys.argv[1], np.stack([m0, m2]))
"""


def test_spectral_moments_do_not_depend_on_the_blas_threads(tmp_path):
    out = {}
    for n in (1, 2):
        path = tmp_path / f"m{n}.npy"
        env = {**os.environ, "OPENBLAS_NUM_THREADS": str(n), "OMP_NUM_THREADS": str(n)}
        r = subprocess.run([sys.executable, "-c", PRODUCT, str(path)], env=env,
                           capture_output=True, text=True, timeout=120)
        assert r.returncode == 0, r.stderr
        out[n] = np.load(path)
    assert np.array_equal(out[1], out[2])


def _cache(work: Path) -> dict:
    root = work / "results" / "cache" / "sea_states"
    return {p.relative_to(root): p.read_bytes() for p in sorted(root.rglob("*.npy"))}


@pytest.mark.slow
def test_one_and_two_threads_with_and_without_the_job_server_give_the_same_bits(tmp_path):
    runs = {}
    trace = tmp_path / "served.txt"
    for threads in (1, 2):
        work = tmp_path / f"threads{threads}"
        work.mkdir()
        make_workdir(work)
        env = {**os.environ, "JLS_JOB_SERVER": "off"} if threads == 1 else \
            {**os.environ, "JLS_JOB_SERVER_TRACE": str(trace)}
        r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2",
                            "results/tiny/workability.nc", "--set-threads",
                            *(f"{rule}={threads}" for rule in
                              ("response", "response_variants", "timedomain_cell"))],
                           cwd=work, capture_output=True, text=True, timeout=900, env=env)
        assert r.returncode == 0, r.stderr[-3000:]
        runs[threads] = work
    served = trace.read_text().splitlines()        # the 2-thread run's jobs, all served
    assert any(".response.py" in line for line in served), served
    assert len(served) >= 5, served
    log = (runs[2] / "logs" / "tiny" / "response.log").read_text()
    assert "; 2 threads;" in log, log
    for name in ("response", "operability", "response_variants", "workability"):
        a, b = (read(runs[t] / "results" / "tiny" / f"{name}.nc") for t in (1, 2))
        assert sorted(a.data_vars) == sorted(b.data_vars)
        for v in a.data_vars:
            if a[v].dtype.kind in "fc":
                assert np.array_equal(a[v].values, b[v].values, equal_nan=True), (name, v)
    # The cache's entries are the same bytes whichever run wrote them: a cache filled by
    # jobs of one thread count serves jobs of any other with the same numbers.
    one, two = _cache(runs[1]), _cache(runs[2])
    assert one and one == two
