"""Benchmark: the measured-spectrum response of one spectra leg of ten years of hourly
directional spectra (jls.stages.measured_response.leg_response: the relative-sway sigma
over each spectrum and over the JONSWAP on the same Hs and Tm02, per candidate x tugger),
and the leg's hourly workability from it (jls.assessment.measured_legs.leg_workability:
every hour at its heading, three criteria, the nine-limit criterion sweep).

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

from jls.assessment.measured_legs import leg_workability
from jls.assessment.workability import criteria_array, unit_utilisation
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
    leg = {"name": "bench", "duration_h": 10, "course_deg": 200.0, "heading_source": "direction_table",
           "headings_deg": list(headings), "heading_probability": [1 / headings.size] * headings.size,
           "spectra": {"file": "-", "format": "ndbc", "dir_edges_deg": list(np.arange(-7.5, 353.0, 15.0))}}
    t0 = time.perf_counter()
    m = leg_response(leg, power, gamma=3.3, efth=efth)
    dt = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6
    print(f"{HOURS} hours x {CANDIDATES * TUGGERS} options: {dt:.1f} s (target < 60 s), "
          f"peak memory {peak:.2f} GB (target < 4 GB)")
    del efth
    tz = np.arange(2.0, 25.01, 0.5)
    mpm = rng.uniform(0.2, 1.5, (CANDIDATES, TUGGERS, headings.size, 4, tz.size))
    stats = xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                       coords={"candidate": power["candidate"].values, "tugger": power["tugger"].values,
                               "heading": headings, "tz": tz,
                               "response": ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]})
    crit = {"relative_sway_m": 3.0, "relative_heave_m": 2.0, "relative_roll_deg": 2.0}
    unit = unit_utilisation(stats, criteria_array(crit))
    limits = np.arange(2.0, 4.001, 0.25)
    trial = xr.concat([unit_utilisation(stats, criteria_array({"relative_sway_m": float(v)})) for v in limits],
                      dim=xr.DataArray(limits, dims="trial_limit"))
    t0 = time.perf_counter()
    r = leg_workability(m.expand_dims(leg=["bench"]), "bench", unit, tz_outside="nearest",
                        sensitivity=("relative_sway_m", trial))
    dt = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6
    print(f"hourly workability of the leg, {int(r['hours'])} hours x {CANDIDATES * TUGGERS} options x "
          f"3 criteria, {limits.size} sweep limits: {dt:.1f} s, peak memory so far {peak:.2f} GB")


if __name__ == "__main__":
    main()
