"""Benchmark: the frequency-domain solver per core, and against numpy's batched solve.

One candidate-frequency evaluation is one 4x4 complex system (a candidate, a tugger
setting and a frequency) solved for one heading. Both solvers get the same systems:
the shipped candidates' plants around the baseline, three tugger settings, the
response grid, one heading. Run: python benchmarks/bench_solver.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("NUMBA_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from rows import at_least, random_plant  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TARGET = 5.0          # M evaluations / s / core
RATIO_AIM = 5.0       # times numpy's batched solve


def _systems(n_c=200, seed=0):
    from jls.config.loader import load
    from jls.response.solver import frequency_grid

    rng = np.random.default_rng(seed)
    cfg = load(ROOT / "config" / "config.yaml")
    plant = random_plant(cfg, n_c, rng)
    M, K, Kb, C = (plant[k].values for k in ("M", "K", "Kb", "C"))
    omega = frequency_grid(0.1, 3.0, 0.002, 2 * np.pi / plant["natural_period"].values,
                           plant["damping_ratio"].values)
    qb = rng.standard_normal((1, omega.size, 4)) + 1j * rng.standard_normal((1, omega.size, 4))
    yf = rng.standard_normal((1, omega.size)) + 0j
    return M, K, Kb, C, omega, qb, yf, np.array([0.0, 1000.0, 2000.0])


def _numpy_solve(M, K, Kb, C, omega, qb, yf, c_t):
    w = omega[None, None, :, None, None]
    A = K[:, None, None] - w**2 * M[:, None, None] + 1j * w * C[:, None, None]
    A = np.broadcast_to(A, (M.shape[0], c_t.size, omega.size, 4, 4)).copy()
    A[..., 0, 0] += 1j * c_t[None, :, None] * omega
    b = np.broadcast_to(-np.einsum("cij,hwj->chwi", Kb, qb)[:, None],
                        (M.shape[0], c_t.size, 1, omega.size, 4)).copy()
    b[..., 0] += 1j * c_t[None, :, None, None] * omega * yf
    x = np.linalg.solve(A[:, :, None], b[..., None])[..., 0]
    return np.abs(x - qb) ** 2


def _best(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def rows(repeat=3):
    from jls.response.solver import relative_power

    M, K, Kb, C, omega, qb, yf, c_t = _systems()
    n = M.shape[0] * c_t.size * omega.size
    relative_power(M[:1], K[:1], Kb[:1], C[:1], omega, qb, yf, c_t, threads=1)   # load compiled code
    t_fd = _best(lambda: relative_power(M, K, Kb, C, omega, qb, yf, c_t, threads=1), repeat)
    t_np = _best(lambda: _numpy_solve(M, K, Kb, C, omega, qb, yf, c_t), repeat)
    rate, rate_np = n / t_fd / 1e6, n / t_np / 1e6
    return [at_least("response evaluations per core (candidate x tugger x frequency)", TARGET,
                     rate, "M/s"),
            at_least(f"  ratio to numpy's batched solve ({rate_np:.2f} M/s), same systems",
                     RATIO_AIM, rate / rate_np, "x")]


if __name__ == "__main__":
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
