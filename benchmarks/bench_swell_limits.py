"""Benchmark: the master's table per swell system (jls.assessment.swell_limits.largest_swell),
the largest swell Hs per swell Tp of every option with the wind sea at the leg's median
partition, every criterion counted (relative motions, tip air gap, wire tensions), on one
leg and heading, one core.

The leg is the partitions example route's ``csv_partitions`` (config/examples/
partitions_route.yaml: its typical wind sea, swell direction, course and the master's swell
periods); the spectral moments of the wind sea and of the unit swells are solved once for
21 candidates of the shipped rigging (top spread and drop height drawn over their ranges)
and repeated to 441 and 2 000 candidates (the moments are the solver's, built once per leg;
what is timed is the search of the swell Hs: OP_LIM, and OP_WF with an alpha table).

Target: 441 candidates (a 21 x 21 grid) x 4 tuggers under 2 s a leg and heading, OP_LIM
and OP_WF (the per-candidate search took 27-55 s); 2 000 candidates under 10 s.

Run: python benchmarks/bench_swell_limits.py
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from rows import random_plant, within  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
#: candidates timed and the limit [s] for OP_LIM and OP_WF of one leg and heading
SIZES = ((441, 2.0), (2_000, 10.0))
SOLVED = 21
#: axis of the candidate in each moment (the rest have none)
CANDIDATE_AXIS = {"motion_m0": 1, "motion_m2": 1, "tip_m0": 1, "tip_m2": 1, "tension_m0": 1, "tension_m2": 1,
                  "tip_height": 0, "tension_static": 0}


def leg(n_solved=SOLVED, seed=0):
    """(wind moments, unit moments, criteria, tuggers, alpha table, period) of the example
    leg for ``n_solved`` candidates."""
    import yaml

    from jls.assessment.operation import AlphaTable
    from jls.assessment.swell_limits import leg_moments, mean_direction, typical_wind_sea
    from jls.commands.response import transfer_from_config
    from jls.config.loader import load
    from jls.sea.records import leg_partitions, leg_spreading
    from jls.sea.sea_state import parse_spreading
    from jls.stages.swell_limits import criteria_of, leg_geometry, swell_tp_range
    from jls.stages.voyage_plan import master_periods

    os.chdir(ROOT)
    cfg = load(ROOT / "config" / "config.yaml")
    rng = np.random.default_rng(seed)
    plant = random_plant(cfg, n_solved, rng)
    tr = transfer_from_config(cfg, ROOT, plant=plant)
    route = yaml.safe_load((ROOT / "config/examples/partitions_route.yaml").read_text())
    the_leg = route["routes"]["synthetic_partitions"]["legs"][0]
    gamma = float(cfg["sea"]["gamma"])
    frame = leg_partitions(the_leg, ROOT, gamma=gamma)
    wind = typical_wind_sea(frame)
    swells = [c[3:] for c in frame.columns if c.startswith("hs_") and c != "hs_wind"]
    course, wind_from, swell_from = leg_geometry(the_leg, wind.from_deg, mean_direction(frame, swells))[0]
    tps = master_periods({the_leg["name"]: swell_tp_range(frame)})
    spread = {k: parse_spreading(v) for k, v in leg_spreading(the_leg, cfg["sea"]).items()}
    crit = criteria_of(cfg, tr.plant)
    w, unit = leg_moments(tr, type(wind)(wind.hs, wind.tp, wind_from), tps, swell_from, course, crit,
                          gamma=gamma, spreading=spread)
    alpha = AlphaTable(source="benchmark", period_h=[12.0, 72.0], hs_m=[1.0, 6.0], alpha=[[0.7, 0.9], [0.6, 0.8]])
    return w, unit, crit, len(tr.tuggers), alpha, wind.hs


def repeated(moments: dict, n: int) -> dict:
    """The moments of ``n`` candidates, the solved ones repeated."""
    out = {}
    for k, v in moments.items():
        axis = CANDIDATE_AXIS.get(k)
        if axis is None:
            out[k] = v
        else:
            out[k] = np.take(v, np.arange(n) % v.shape[axis], axis=axis)
    return out


def bench(n, base=None):
    """(s, OP_LIM) of OP_LIM and OP_WF for ``n`` candidates."""
    from jls.assessment.swell_limits import largest_swell
    from jls.assessment.voyage_plan import alpha_periods
    w, unit, crit, n_t, alpha, wind_hs = base if base is not None else leg()
    w, unit = repeated(w, n), repeated(unit, n)
    t0 = time.perf_counter()
    oplim = largest_swell(w, unit, crit, n_t)
    total = np.sqrt(wind_hs**2 + np.where(np.isfinite(oplim), oplim, 1e3) ** 2)
    a = alpha.factor(float(alpha_periods([48.0], alpha)[0]), total)
    largest_swell(w, unit, crit, n_t, target=a)
    return time.perf_counter() - t0, oplim


def rows():
    base = leg()
    out = []
    for n, limit in SIZES:
        t, _ = bench(n, base)
        count = f"{n:,}".replace(",", " ")
        out.append(within(f"swell table (OP_LIM and OP_WF), one partitioned leg and heading, {count} candidates x "
                          f"{base[3]} tuggers x {base[1]['wave_m0'].size} swell Tp, every criterion, one core",
                          limit, t))
    return out


def main():
    base = leg()
    crit = base[2]
    print(f"criteria: {', '.join(crit.names())}; swell Tp: {base[1]['wave_m0'].size}; tuggers: {base[3]}")
    for n, limit in SIZES:
        t, oplim = bench(n, base)
        print(f"{n} candidates: {t:.2f} s (target < {limit:g} s); OP_LIM {np.nanmin(oplim):.2f}-{np.nanmax(oplim):.2f} m")


if __name__ == "__main__":
    main()
