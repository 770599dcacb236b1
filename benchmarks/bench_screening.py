"""Benchmark: the default 21 x 21 rigging screening of the shipped route, refinement
included.

Route 'default' of config/config.yaml (two legs, beam seas), its first three tugger settings,
the grid over top spread Y and drop height with the other variables at the baseline,
scored on the screening envelope and the route's workability, then refined from the
best feasible grid point. Target: under 30 s on two cores.
Run: python benchmarks/bench_screening.py [grid points per variable]
"""

import sys
import time
from dataclasses import replace
from pathlib import Path

from jls.assembly import rigging_from_config
from jls.config import load
from jls.stages.vessel_motion import vessel_motion
from jls.stages.sea_states import read_leg, sea_states
from jls.scoring import Scoring
from jls.stages.screening import Settings, screening_dataset

ROOT = Path(__file__).resolve().parents[1]


def main(n=21):
    t0 = time.perf_counter()
    cfg = load(ROOT / "config" / "config.yaml")
    rig = rigging_from_config(cfg)
    route = dict(cfg["routes"]["default"], name="default")
    rule, gamma = cfg["sea"]["steepness_rule"], cfg["sea"]["gamma"]
    legs = {leg["name"]: read_leg(leg, ROOT, rule, gamma, cfg["g_m_per_s2"]) for leg in route["legs"]}
    sea = sea_states(route, legs, rule)
    scoring = Scoring.from_config(cfg)
    scoring = replace(scoring, tuggers=dict(list(scoring.tuggers.items())[:3]))   # three settings
    headings = sorted({float(h) for leg in route["legs"] for h in leg["headings_deg"]}
                      | {scoring.envelope.heading_deg})
    motion = vessel_motion(cfg["vessel"], headings, base_dir=ROOT)
    t_inputs = time.perf_counter() - t0
    settings = Settings.from_config(cfg)
    settings = Settings(**{**settings.__dict__, "grid_points": {"top_spread_y": n, "drop_height": n}})
    t1 = time.perf_counter()
    grid_only = screening_dataset(rig, motion, sea, scoring, settings, refine_optimum=False)
    t_grid = time.perf_counter() - t1
    t2 = time.perf_counter()
    ds = screening_dataset(rig, motion, sea, scoring, settings)
    t_all = time.perf_counter() - t2
    n_cand = grid_only.sizes["candidate"]
    o = ds.attrs["optimum_candidate"]
    work = ds["route_workability"].sel(tugger=ds.attrs["objective_tugger"])
    print(f"inputs (sea states, vessel motion): {t_inputs:.2f} s")
    print(f"{n} x {n} grid + baseline ({n_cand} candidates) x {ds.sizes['tugger']} tuggers, "
          f"screening without refinement: {t_grid:.2f} s ({1e3 * t_grid / n_cand:.1f} ms per candidate)")
    print(f"screening with refinement ({ds.attrs['refinement_evaluations']} evaluations): {t_all:.2f} s; "
          f"target < 30 s on two cores")
    print(f"optimum {o}: " + ", ".join(f"{v} {ds.attrs[f'optimum_{v}_m']:.3f} m" for v in
                                       ("top_spread_y", "drop_height")) +
          f"; route workability {100 * float(work.sel(candidate=o)):.2f} % "
          f"(baseline {100 * float(work.sel(candidate='baseline')):.2f} %); "
          f"active: {ds.attrs['active_constraints']}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 21)
