"""Benchmark: weather windows of a ten-year hourly hindcast for 100 options.

Target: under 2 s on one core for 87 600 hours x 50 candidates x 2 tuggers, a 75-hour
window. Run: python benchmarks/bench_windows.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import xarray as xr  # noqa: E402

from jls.assessment.windows import windows_dataset  # noqa: E402

RESPONSES = ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]


def main(n_candidates=50, n_tuggers=2, years=10, repeat=3):
    rng = np.random.default_rng(0)
    n = 24 * 365 * years
    hs = np.clip(1.5 + 0.8 * np.sin(np.arange(n) * 2 * np.pi / 8766)
                 + np.cumsum(rng.normal(0, 0.05, n)) % 1.5, 0.1, 8.0)
    tz = np.clip(4.0 + 1.5 * hs ** 0.5 + rng.normal(0, 0.4, n), 3.0, 14.0)
    idx = pd.date_range("1996-01-01", periods=n, freq="1h", tz="UTC", name="time")
    df = pd.DataFrame({"hs": hs, "tz": tz}, index=idx)
    grid = np.arange(3.0, 14.01, 0.25)
    mpm = np.zeros((n_candidates, n_tuggers, 1, 4, grid.size))
    spread = rng.uniform(0.8, 1.2, (n_candidates, n_tuggers, 1, 1))
    mpm[:, :, :, 0, :] = (0.3 + 0.1 * grid)[None, None, None, :] * spread
    stats = xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                       coords={"candidate": [f"c{i}" for i in range(n_candidates)],
                               "tugger": [f"t{i}" for i in range(n_tuggers)], "heading": [90.0],
                               "response": RESPONSES, "tz": grid})
    legs = [{"name": "leg", "duration_h": 75, "headings_deg": [90.0], "heading_probability": [1.0]}]
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        ds = windows_dataset(legs, {"leg": df}, stats, {"relative_sway_m": 3.0})
        best = min(best, time.perf_counter() - t0)
    p = ds["window_probability_all"]
    print(f"{n} hours x {n_candidates} candidates x {n_tuggers} tuggers, 75-h window: best of {repeat} "
          f"{best:.2f} s on one core (window probability {float(p.min()):.3f}-{float(p.max()):.3f}); "
          "target < 2 s")


if __name__ == "__main__":
    main()
