"""Benchmark: the departure rule at hold points (jls.assessment.voyage_plan,
jls.assessment.departure_rule).

Target: ten years of hourly records (87 600 departure hours) x 2 legs (50 h and 75 h,
a hold point between them, 12 h contingency each, a 72-h forecast horizon, waits up to
30 days) x 100 options (50 candidates x 2 tuggers) x 3 criteria, the rule simulated for
every departure hour, every hour's statistics interpolated in Tz: under 20 s on 2 cores.
At scale: the same at 2 000 options (500 candidates x 4 tuggers, the size of a 21 x 21
candidate grid's plan): under 0.02 s an option (under 40 s), the compiled kernels
already compiled (a small plan first).

Run: python benchmarks/bench_voyage_plan.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402

import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402
from bench_voyage import LEGS, records, unit_statistics  # noqa: E402
from rows import within  # noqa: E402

from jls.assessment.route_hours import common_hours  # noqa: E402
from jls.assessment.voyage_plan import voyage_plan  # noqa: E402

TARGET_S = 20.0
#: the plan at scale: options (candidates x tuggers) and the limit per option [s]
SCALE = (500, 4)
PER_OPTION_S = 0.02


def bench_plan(n_candidates=50, n_tuggers=2, departures=87_600, repeat=2):
    """(best s, dataset)."""
    recs = records(departures + 125 + 30 * 24)
    stats = unit_statistics(n_candidates, n_tuggers, np.arange(3.0, 14.01, 0.25))
    hp = xr.DataArray(np.ones((len(LEGS), 1)), dims=("leg", "heading"),
                      coords={"leg": list(LEGS), "heading": [90.0]})
    dur = [d for _, d in LEGS.values()]
    best, ds = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        hours = common_hours(recs)
        ds = voyage_plan(stats, hours, hp, dur, stats["limit"], strict=False, hold_point=[True, True],
                         contingency_h=[12.0, 12.0], horizon_h=72, max_wait_h=720, months=range(1, 13))
        best = min(best, time.perf_counter() - t0)
    return best, ds


def bench_scale():
    """(wall s per option, options, CPU s per option) of the plan at :data:`SCALE`, after a
    small warm-up plan."""
    bench_plan(2, 1, departures=2_000, repeat=1)
    cpu = time.process_time()
    t, ds = bench_plan(*SCALE, repeat=1)
    cpu = time.process_time() - cpu
    n = ds["plan_exceedance_probability"].size
    return t / n, n, cpu / n


def rows():
    t, _ = bench_plan()
    per, n, _ = bench_scale()
    return [within("departure rule at 2 hold points, 87 600 departures x 100 options x 3 criteria", TARGET_S, t),
            within(f"the same at {n:_} options (500 candidates x 4 tuggers), per option".replace("_", " "),
                   PER_OPTION_S, per)]


def main():
    t, ds = bench_plan()
    p = ds["plan_exceedance_probability"]
    print(f"departure rule: {int(ds['departures_month'].sum())} departure hours x 100 options x 3 criteria, "
          f"legs 50 h + 75 h with a hold point between: best {t:.2f} s (target < {TARGET_S:g} s); "
          f"P(sailed voyage exceeds) {float(p.min()):.3f}-{float(p.max()):.3f}, departure share "
          f"{float(ds['plan_departure_fraction'].min()):.2f}-{float(ds['plan_departure_fraction'].max()):.2f}")
    per, n, cpu = bench_scale()
    print(f"departure rule at {n} options: {per * n:.1f} s, {per * 1e3:.1f} ms an option "
          f"(target < {PER_OPTION_S * 1e3:g} ms), {cpu * 1e3:.1f} ms of CPU an option; "
          f"load average {os.getloadavg()[0]:.1f}, {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
