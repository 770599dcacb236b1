"""Benchmark: ``jls forecast`` from the command line, start-up included, on a 10-day hourly
forecast (240 hours of wind sea and swell) for 100 options (25 candidates x 4 tuggers) and
4 criteria (relative sway, heave and roll, and the hoist-wire tension, on by default; the
tip clearance off).

Target: under 5 s on 2 cores (it runs on the bridge). The candidates are the shipped
rigging with its top spread and drop height varied; the forecast a wind sea turning and
a swell rising and falling, met on a course of 200 deg. Run: python benchmarks/bench_forecast.py
"""

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from rows import within

ROOT = Path(__file__).resolve().parents[1]
TARGET_S = 5.0
HOURS = 240


def write_inputs(folder: Path) -> tuple[Path, Path]:
    import pandas as pd
    t = pd.date_range("2026-01-05T00:00Z", periods=HOURS, freq="h")
    k = np.arange(HOURS)
    rows = ["time,hs_wind,tp_wind,dir_wind,hs_swell,tp_swell,dir_swell"]
    for i, ti in enumerate(t):
        rows.append(f"{ti.strftime('%Y-%m-%dT%H:%MZ')},{0.6 + 0.4 * np.sin(k[i] / 20):.3f},"
                    f"{5.5 + np.sin(k[i] / 30):.2f},{(180 + k[i]) % 360},"
                    f"{0.3 + 0.25 * np.sin(k[i] / 50) ** 2:.3f},{13 + 2 * np.cos(k[i] / 40):.2f},260")
    fc = folder / "forecast.csv"
    fc.write_text("\n".join(rows) + "\n")
    spreads = np.linspace(40.0, 60.0, 6)
    drops = np.linspace(56.0, 66.0, 4)
    cands = [f"  - {{name: c{i}, top_spread_y_m: {s:.2f}, drop_height_m: {d:.2f}}}"
             for i, (s, d) in enumerate((s, d) for s in spreads for d in drops)]
    cfg = folder / "options.yaml"
    cfg.write_text("candidates:\n" + "\n".join(cands) + "\nscreening: {enabled: false}\n"
                   "assessment:\n  criteria: {relative_sway_m: 3.0, relative_heave_m: 1.0, relative_roll_deg: 2.0,"
                   " tip_air_gap_m: null}\n")
    return fc, cfg


def rows():
    with tempfile.TemporaryDirectory() as tmp:
        fc, cfg = write_inputs(Path(tmp))
        cmd = [sys.executable, "-m", "jls.cli", "forecast", str(fc), "--leg", "gulf_of_maine", "--course", "200",
               "--config", str(cfg), "--results", str(Path(tmp) / "none"), "--json"]
        subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True)        # compiled kernels cached
        best = np.inf
        for _ in range(3):
            t0 = time.perf_counter()
            r = subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True)
            best = min(best, time.perf_counter() - t0)
        assert '"go"' in r.stdout
    return [within(f"jls forecast from the command line: {HOURS} hourly sea states of 2 spread systems x "
                   "25 candidates x 4 tuggers x 4 criteria (3 motions, wire tension), start-up included, best of 3", TARGET_S, best)]


if __name__ == "__main__":
    os.chdir(ROOT)
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
