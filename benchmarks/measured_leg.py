"""Benchmark: the measured-spectrum response of one spectra leg of ten years of hourly
directional spectra (jls.stages.measured_response.leg_response: the relative-sway sigma
over each spectrum and over the JONSWAP on the same Hs and Tm02, per candidate x tugger).

Target (issue 22): 87 600 spectra x 40 frequencies x 24 directions against 100 candidates
x 4 tugger settings in under 60 s and under 4 GB. Synthetic inputs: random spectra and
random |H|^2 on 24 headings x 1 500 frequencies (the cost does not depend on the values).
The peak memory includes the inputs themselves (the spectra, 0.7 GB in float64).

Run: python benchmarks/measured_leg.py
"""

from __future__ import annotations

import resource
import time

import numpy as np
import pandas as pd
import xarray as xr

from jls.sea.directional import DEFAULT_DIRS
from jls.sea.measured import spectra_array
from jls.stages.measured_response import leg_response

HOURS, CANDIDATES, TUGGERS = 87_600, 100, 4


def main():
    rng = np.random.default_rng(1)
    freq = np.linspace(0.03, 0.40, 40)
    times = pd.date_range("2010-01-01", periods=HOURS, freq="h").values
    efth = spectra_array(rng.random((HOURS, freq.size, DEFAULT_DIRS.size)) * 0.01, times, freq,
                         DEFAULT_DIRS, attrs={"source": "synthetic"})
    omega, headings = np.linspace(0.1, 3.0, 1500), np.arange(0.0, 360.0, 15.0)
    power = xr.DataArray(rng.random((CANDIDATES, TUGGERS, headings.size, omega.size)),
                         dims=("candidate", "tugger", "heading", "omega"),
                         coords={"candidate": [f"c{i}" for i in range(CANDIDATES)],
                                 "tugger": [f"t{i}" for i in range(TUGGERS)],
                                 "heading": headings, "omega": omega})
    leg = {"name": "bench", "duration_h": 10, "course_deg": 200.0, "spectra": {"file": "-", "format": "ndbc"}}
    t0 = time.perf_counter()
    leg_response(leg, power, gamma=3.3, efth=efth)
    dt = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6
    print(f"{HOURS} hours x {CANDIDATES * TUGGERS} options: {dt:.1f} s (target < 60 s), "
          f"peak memory {peak:.2f} GB (target < 4 GB)")


if __name__ == "__main__":
    main()
