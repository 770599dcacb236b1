"""Benchmark: hourly partitions of a leg judged on their own directional seas for every
criterion (jls.stages.hourly_seas.leg_utilisation: the relative motions, the tip clearance
and the wire tension of each hour, the functions of ``jls response`` and ``jls forecast``;
from 1000 hours of JONSWAP partitions every criterion's moments from the response table,
jls.response.response_table: the tables' candidate blocks and then the chunks of hours on
the 2 threads; the tip clearance's limiting Hs by the compiled Newton of
jls.assessment.limiting_hs_kernel at each hour's worst tip point), then the leg's hourly
workability (jls.assessment.measured_legs.leg_workability) and the departure simulation
(jls.assessment.route_simulation.route_simulation, its blocks of options on the 2 threads)
on those hours, holding what measured_response.nc holds (each hour's utilisation and own
up-crossing period, as the voyage stage does) and reading it a block of options at a time
(jls.assessment.hourly.route_own_rows), the own sigma formed from the level and period.

Target (issue 32, Speed): ten years of hourly partitions (87 600 h, a wind sea and a swell,
each spread: cos-2s s = 4 and 13) x 100 candidates x 4 tuggers through the workability and
the departure simulation in under 60 s and 4 GB. The candidates are the shipped rigging
with the top spread and drop height drawn over their ranges (as bench_sea_state.py); the
criteria the shipped configuration's. ``JLS_BENCH_HOURS`` runs fewer hours (the cost is
linear in them: the figure then says how many were run and the rate per hour). The
machine is shared: the figure states the CPU time taken and the one-minute load average
at the start and the end (a wall time above the target at a load above 2 says little).

Run: python benchmarks/bench_hourly_seas.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import resource  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from rows import within  # noqa: E402

HOURS = int(os.environ.get("JLS_BENCH_HOURS", "87600"))
CANDIDATES, THREADS = 100, 2
TARGET_S, TARGET_GB = 60.0, 4.0


def _states(n, seed=1):
    from jls.sea.partitions import sea_states
    rng = np.random.default_rng(seed)
    frame = pd.DataFrame({"hs_wind": rng.uniform(0.3, 3.0, n), "tp_wind": rng.uniform(4.0, 9.0, n),
                          "dir_wind": rng.uniform(0, 360, n), "hs_swell": rng.uniform(0.2, 2.0, n),
                          "tp_swell": rng.uniform(10.0, 18.0, n), "dir_swell": rng.uniform(0, 360, n)},
                         index=pd.date_range("2010-01-01", periods=n, freq="h", tz="UTC"))
    states, _ = sea_states(frame, gamma=3.3, spreading={"wind": "cos2s:4", "swell": "cos2s:13"})
    return states, frame.index.tz_convert(None).to_numpy()


def rows():
    import xarray as xr
    from bench_sea_state import _transfer

    from jls.assessment.hourly import route_own_rows
    from jls.assessment.measured_legs import leg_workability
    from jls.assessment.route_simulation import route_simulation
    from jls.assessment.workability import criteria_array
    from jls.config.loader import load
    from jls.stages.hourly_seas import leg_utilisation

    tr = _transfer(CANDIDATES)                      # (and into the repository's root)
    cfg = load("config/config.yaml")
    tr = type(tr)(tr.plant, tr.exc, {f"t{i}": 250.0 * i for i in range(4)}, tr.symmetric, tr.outside_policy)
    states, times = _states(HOURS)
    leg = {"name": "p", "course_deg": 200.0, "headings_deg": [90.0], "heading_probability": [1.0],
           "duration_h": 48.0}
    small = type(tr)(tr.plant.isel(candidate=slice(0, 2)), tr.exc, tr.tuggers, tr.symmetric, tr.outside_policy)
    leg_utilisation(small, cfg, leg, states[:4], np.ones((4, 1)), directional=True)     # compile
    load0 = os.getloadavg()[0]
    t0, c0 = time.perf_counter(), time.process_time()
    u = leg_utilisation(tr, cfg, leg, states, np.ones((HOURS, 1)), directional=True, threads=THREADS)
    t_u = time.perf_counter() - t0
    u = u.assign_coords(time=times)
    crit = u["criterion"].values.tolist()
    m = xr.Dataset({"hs": ("time", np.array([s.hs for s in states])), "tz": ("time", np.full(HOURS, 8.0)),
                    "heading_weight": (("time", "heading"), np.ones((HOURS, 1))),
                    "sigma_measured": (("time", "candidate", "tugger"), np.ones((HOURS, CANDIDATES, 4))),
                    "sigma_jonswap": (("time", "candidate", "tugger"), np.ones((HOURS, CANDIDATES, 4))),
                    "utilisation": u["utilisation"], "tz_response_own": u["tz_response_own"]}).expand_dims(leg=["p"])
    del u                                            # what measured_response.nc holds lives on in m
    limit = criteria_array(cfg["assessment"]["criteria"]).sel(criterion=crit)
    unit = xr.DataArray(np.full((CANDIDATES, 4, 1, 2, len(crit)), 0.1),
                        dims=("candidate", "tugger", "heading", "tz", "criterion"),
                        coords={"candidate": tr.candidates, "tugger": list(tr.tuggers), "heading": [90.0],
                                "tz": [3.0, 20.0], "criterion": crit, "strict": limit["strict"]})
    work = leg_workability(m, "p", unit)
    # the departure simulation of the leg's hours (JONSWAP statistics under them, replaced)
    stats = xr.Dataset({v: (("candidate", "tugger", "criterion", "heading", "tz"),
                            np.full((CANDIDATES, 4, len(crit), 1, 2), 1.0)) for v in ("mpm", "sigma")},
                       coords=unit.drop_vars("strict").coords)
    stats["tz_response"] = xr.full_like(stats["mpm"], 10.0)
    stats["limit"] = ("criterion", np.ones(len(crit)))
    hours = xr.Dataset({"hs": (("leg", "time"), m["hs"].values), "tz": (("leg", "time"), m["tz"].values)},
                       coords={"leg": ["p"], "time": times})
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["p"], "heading": [90.0]})
    sim = route_simulation(stats, hours, hp, xr.DataArray([48.0], dims="leg", coords={"leg": ["p"]}),
                           stats["limit"], own=route_own_rows(m, hours), threads=THREADS,
                           exposure_h=float(cfg["assessment"]["exposure_h"]), cycles=cfg["assessment"]["mpm_cycles"])
    t, cpu = time.perf_counter() - t0, time.process_time() - c0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024**2
    assert np.isfinite(work["workability"].values).all() and sim.sizes
    what = (f"{HOURS} hourly partitions (2 spread systems) x {CANDIDATES} candidates x 4 tuggers, "
            f"{len(crit)} criteria ({', '.join(crit)}): each hour's own sea, workability, departure "
            f"simulation, {THREADS} threads ({t_u:.1f} s the hours' criteria, {cpu:.1f} s of CPU, "
            f"{1e3 * t / HOURS:.2f} ms an hour; load average {load0:.1f} at the start, "
            f"{os.getloadavg()[0]:.1f} at the end)")
    return [within(what, TARGET_S, t), within(f"{what}: peak memory", TARGET_GB, peak, "GB")]


if __name__ == "__main__":
    for r in rows():
        print(f"{r.figure}: {r.measured} (target {r.target})")
