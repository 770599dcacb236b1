"""Benchmark: the response of one sea state of two spread wave systems (36 directions each)
for 10 000 rigging candidates x 4 tugger settings (jls.response.sea_state), on 2 threads.

The candidates are the shipped rigging with the top spread and drop height drawn over
their ranges; the sea state a wind sea (Hs 1.5 m, Tp 7 s, cos-2s s = 4) and a swell
(Hs 1 m, Tp 15 s, s = 13) 50 deg apart, met by the vessel on 200 deg. The vessel motion at
the RAO's 24 headings and the frequency grid (refined around every candidate's modes) are
built first and not timed: an engineer builds them once per configuration
(:func:`jls.commands.response.transfer_from_config`). Run: python benchmarks/bench_sea_state.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from rows import random_plant, within  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 10.0
N_CANDIDATES, THREADS = 10_000, 2


def _transfer(n=N_CANDIDATES, seed=0):
    from jls.config.loader import load
    from jls.response.sea_state import sea_state_transfer
    from jls.sea.headings import rao_grid
    from jls.stages.vessel_motion import vessel_motion

    os.chdir(ROOT)
    cfg = load(ROOT / "config" / "config.yaml")
    rng = np.random.default_rng(seed)
    plant = random_plant(cfg, n, rng)
    motion = vessel_motion(cfg["vessel"], rao_grid(np.arange(0.0, 181.0, 15.0)), base_dir=ROOT)
    tuggers = {t["name"]: float(t["c_kN_s_per_m"]) for t in cfg["tuggers"]}
    return sea_state_transfer(plant, motion, tuggers, cfg["response"]["omega_step_rad_s"],
                              cfg["vessel"]["outside_rao_range"])


def _sea():
    from jls.sea.sea_state import wave_system
    return [wave_system("jonswap", 1.5, "tp", 7.0, gamma=3.3, from_deg=250.0, spreading="cos2s:4"),
            wave_system("jonswap", 1.0, "tp", 15.0, gamma=5.0, from_deg=300.0, spreading="cos2s:13",
                        kind="swell")]


def _ten_years(tr, seed=1):
    """Response moments of ten years of hourly wind sea + swell (87 600 hours) for the
    candidates of ``tr``: the table of unit-Hs moments on a 0.05 s Tp grid, then the hours."""
    from jls.response.system_table import hourly_moments, system_table
    from jls.sea.sea_state import Spreading
    rng = np.random.default_rng(seed)
    n = 87_600
    table = system_table(tr, np.arange(3.0, 22.0001, 0.05), 3.3, threads=THREADS)
    wind = (rng.uniform(0.3, 3.0, n), rng.uniform(4.0, 9.0, n), rng.uniform(0, 360, n), Spreading("cos2s", 4.0))
    swell = (rng.uniform(0.2, 2.0, n), rng.uniform(10.0, 18.0, n), rng.uniform(0, 360, n), Spreading("cos2s", 13.0))
    return hourly_moments(table, [wind, swell], rng.uniform(0, 360, n))


def rows():
    from jls.response.sea_state import sea_state_statistics

    tr = _transfer()
    small = type(tr)(tr.plant.isel(candidate=slice(0, 2)), tr.exc, tr.tuggers, tr.symmetric, tr.outside_policy)
    sea_state_statistics(small, [_sea()], 200.0)                     # load the compiled solver
    t0, c0 = time.perf_counter(), time.process_time()
    ds = sea_state_statistics(tr, [_sea()], 200.0, threads=THREADS)
    t, cpu = time.perf_counter() - t0, time.process_time() - c0
    assert np.all(np.isfinite(ds["sigma"].values))
    small100 = type(tr)(tr.plant.isel(candidate=slice(0, 100)), tr.exc, tr.tuggers, tr.symmetric, tr.outside_policy)
    t1, c1 = time.perf_counter(), time.process_time()
    m0, _ = _ten_years(small100)
    t_years, cpu_years = time.perf_counter() - t1, time.process_time() - c1
    assert np.all(np.isfinite(m0))
    return [within(f"ten years of hourly wind sea + swell (87 600 h, 2 spread systems), 100 candidates x "
                   f"{len(tr.tuggers)} tuggers: response moments of every hour ({cpu_years:.1f} s of CPU; "
                   "the workability and departure simulation of these hours not included)", 60.0, t_years),
            within(f"one sea state of 2 spread systems (36 directions each), {N_CANDIDATES} candidates "
                   f"x {len(tr.tuggers)} tuggers, {tr.exc.omega.size} frequencies, {THREADS} threads "
                   f"({cpu:.1f} s of CPU)",
                   TARGET_S, t)]


if __name__ == "__main__":
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
