"""Benchmark: voyage extremes (jls.assessment.voyage) and route simulation (jls.assessment.route_simulation).

Targets: the route simulation of ten years of hourly records, 87 600 departures, for
100 options x 3 criteria under 20 s on 2 cores (two legs of 50 h and 75 h, each with its
own record and its gaps; every hour's statistics interpolated in Tz, the departures'
voyage maxima, pass flags, months, and their exceedance probabilities under short-term
Rayleigh within each hour; 100 options = 50 candidates x 2 tuggers), also with the long-term
extreme of the same hindcast hours (175 000 cells per option) for comparison; the
long-term voyage extreme of the shipped route's two scatter tables for 10 000 candidates
under 5 s (x 3 tuggers x 3 criteria, with each cell's share of the up-crossings).

Run: python benchmarks/bench_voyage.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import xarray as xr  # noqa: E402
from rows import within  # noqa: E402

from jls.assessment.route_hours import common_hours  # noqa: E402
from jls.assessment.route_simulation import route_simulation  # noqa: E402
from jls.assessment.voyage import hindcast_long_term, long_term_extreme  # noqa: E402
from jls.sea.scatter import read_scatter  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
LEGS = {"gulf_of_maine": ("leg1_gulf_of_maine.csv", 50.0), "cape_canaveral": ("leg2_cape_canaveral.csv", 75.0)}
CRITERIA = ["relative_sway_m", "relative_roll_deg", "relative_yaw_deg"]
LIMITS = [3.0, 1.0, 2.0]
THREADS = 2


def unit_statistics(n_candidates, n_tuggers, tz, seed=0):
    """Plausible unit-Hs statistics per criterion: sigma rising to a peak near Tz 9 s."""
    rng = np.random.default_rng(seed)
    shape = (n_candidates, n_tuggers, len(CRITERIA), 1, tz.size)
    peak = np.exp(-0.5 * ((tz - 9.0) / 2.5) ** 2)
    sigma = (0.05 + 0.25 * peak) * rng.uniform(0.6, 1.4, shape[:3] + (1, 1))
    tz_r = np.broadcast_to(10.0 + 0.5 * tz, shape)
    dims = ("candidate", "tugger", "criterion", "heading", "tz")
    coords = {"candidate": [f"c{i}" for i in range(n_candidates)],
              "tugger": [f"t{i}" for i in range(n_tuggers)], "criterion": CRITERIA,
              "heading": [90.0], "tz": tz}
    n_cycles = 3 * 3600.0 / tz_r
    return xr.Dataset({"sigma": (dims, sigma), "tz_response": (dims, tz_r.copy()),
                       "mpm": (dims, sigma * np.sqrt(2 * np.log(n_cycles))),
                       "limit": ("criterion", LIMITS)}, coords=coords)


def route_tables():
    tables = [read_scatter(ROOT / "config" / "routes" / "default" / f) for f, _ in LEGS.values()]
    p = xr.concat([t["probability"] for t in tables], dim="leg").assign_coords(leg=list(LEGS))
    cp = p.expand_dims(heading=[90.0]).transpose("leg", "heading", "hs", "tz")
    hs = xr.DataArray(np.broadcast_to(p["hs"].values, (len(LEGS), p.sizes["hs"])), dims=("leg", "hs"),
                      coords={"leg": list(LEGS), "hs": p["hs"]})
    dur = xr.DataArray([d for _, d in LEGS.values()], dims="leg", coords={"leg": list(LEGS)})
    return cp, hs, dur


def records(n_hours, seed=1):
    """Two synthetic hourly records (seasonal Hs with persistence, Tz from Hs), a few gaps."""
    rng = np.random.default_rng(seed)
    out = {}
    for leg in LEGS:
        walk = np.cumsum(rng.normal(0, 0.05, n_hours)) % 1.5
        hs = np.clip(1.5 + 0.8 * np.sin(np.arange(n_hours) * 2 * np.pi / 8766) + walk - 0.5, 0.1, 9.0)
        tz = np.clip(4.0 + 1.5 * hs ** 0.5 + rng.normal(0, 0.4, n_hours), 3.0, 14.0)
        idx = pd.date_range("1996-01-01", periods=n_hours, freq="1h", tz="UTC", name="time")
        keep = np.ones(n_hours, bool)
        for start in rng.integers(0, n_hours - 100, 30):
            keep[start:start + rng.integers(1, 48)] = False
        keep[[0, -1]] = True
        df = pd.DataFrame({"hs": hs, "tz": tz}, index=idx)[keep]
        df.attrs["source"] = f"synthetic_{leg}.txt"
        out[leg] = df
    return out


def bench_route(n_candidates=50, n_tuggers=2, departures=87_600, repeat=2):
    """(best s of the route simulation, best s of the hindcast long-term, dataset)."""
    hours_needed = departures + int(sum(d for _, d in LEGS.values())) - 1
    recs = records(hours_needed)
    stats = unit_statistics(n_candidates, n_tuggers, np.arange(3.0, 14.01, 0.25))
    hp = xr.DataArray(np.ones((len(LEGS), 1)), dims=("leg", "heading"),
                      coords={"leg": list(LEGS), "heading": [90.0]})
    dur = xr.DataArray([d for _, d in LEGS.values()], dims="leg", coords={"leg": list(LEGS)})
    best_sim = best_lt = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        hours = common_hours(recs)
        ds = route_simulation(stats, hours, hp, dur, stats["limit"])
        t1 = time.perf_counter()
        lt = hindcast_long_term(stats["sigma"], stats["tz_response"], hours, dur, hp, stats["limit"],
                                threads=THREADS)
        t2 = time.perf_counter()
        best_sim, best_lt = min(best_sim, t1 - t0), min(best_lt, t2 - t1)
    return best_sim, best_lt, ds, lt


def bench_long_term(n_candidates=10_000, n_tuggers=3, repeat=3, shares=True):
    cp, hs, dur = route_tables()
    stats = unit_statistics(n_candidates, n_tuggers, cp["tz"].values)
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        ds = long_term_extreme(stats["sigma"], stats["tz_response"], cp, hs, dur, stats["limit"],
                               shares=shares, threads=THREADS)
        best = min(best, time.perf_counter() - t0)
    return best, ds


def rows():
    sim, lt, _, _ = bench_route()
    scatter, _ = bench_long_term()
    return [within("route simulation, 87 600 departures x 100 options x 3 criteria, 2 legs", 20.0, sim),
            within("the same with the hindcast hours' long-term extreme for comparison", 20.0, sim + lt),
            within("long-term voyage extreme, 10 000 candidates x 3 tuggers x 3 criteria, 2 threads",
                   5.0, scatter)]


def main():
    sim, lt, ds, lth = bench_route()
    judged = ds.attrs["departures_judged"]
    print(f"route simulation: {ds.attrs['departures']} departures ({judged} judged, the rest cross a "
          f"gap) x 100 options x 3 criteria, legs 50 h + 75 h: best {sim:.2f} s (target < 20 s); "
          f"pass probability {float(ds['pass_probability'].min()):.3f}-{float(ds['pass_probability'].max()):.3f}")
    print(f"long-term extreme of the same hours (2 threads): best {lt:.2f} s; exceedance "
          f"{float(lth['exceedance_probability'].min()):.3g}-{float(lth['exceedance_probability'].max()):.3g} "
          f"against the departures' mean {float(ds['mean_departure_exceedance'].min()):.3g}-"
          f"{float(ds['mean_departure_exceedance'].max()):.3g}")
    for shares in (True, False):
        best, _ = bench_long_term(shares=shares)
        print(f"long-term voyage extreme, shipped route's tables, 10 000 candidates x 3 tuggers x 3 "
              f"criteria ({'with' if shares else 'without'} the cells' shares, 2 threads): best {best:.2f} s "
              "(target < 5 s)")


if __name__ == "__main__":
    main()
