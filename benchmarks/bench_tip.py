"""Cost of the dynamic tip clearance in the response (jls.response.tip).

  1. the default route's response job (its three assessed candidates, four tugger
     settings, beam seas, the operability grid's 45 Tz values): the response
     dataset with the tip statistics over the same without them, at most 1.25x;
  2. the tip statistics of a large grid, per 1000 candidates (four tugger settings, 13 Tz,
     the four points below the padeyes), under 2 s, with their ratio to the relative-motion
     moments they accompany (those come from the compiled |H|^2 kernel; the tip needs the
     complex transfer functions), and 128 candidates over 64 (linear: about 2).

CPU time of this process (one thread), the best of three, so that other work on a shared
machine does not count. Run: python benchmarks/bench_tip.py (or benchmarks/run.py tip).
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from rows import Row  # noqa: E402

from jls.config.builders import rigging_from_config, tip_settings_from_config  # noqa: E402
from jls.config.loader import load  # noqa: E402
from jls.plant.candidates import plant_dataset  # noqa: E402
from jls.response.moments import excitation, unit_moments  # noqa: E402
from jls.response.tip import tip_response  # noqa: E402
from jls.stages.response import response_dataset  # noqa: E402
from jls.stages.vessel_motion import vessel_motion  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
ROUTE_CANDIDATES = {"baseline": {}, "detuned": {"top_spread_y": 37.845, "drop_height": 66.46},
                    "optimised": {"top_spread_y": 35.30, "drop_height": 66.46}}


def cpu(fn, repeat=3):
    best = np.inf
    for _ in range(repeat):
        t = time.process_time()
        fn()
        best = min(best, time.process_time() - t)
    return best


def route_response(cfg, motion):
    """CPU seconds of the default route's response dataset without and with the tip."""
    rig = rigging_from_config(cfg)
    plant, _ = plant_dataset(rig, ROUTE_CANDIDATES)
    tz = np.round(np.arange(3.0, 14.001, 0.25), 6)                # the operability grid
    tuggers = {t["name"]: t["c_kN_s_per_m"] for t in cfg["tuggers"]}
    kw = dict(gamma=cfg["sea"]["gamma"], exposure_h=3.0, omega_step=cfg["response"]["omega_step_rad_s"],
              outside_policy=cfg["vessel"]["outside_rao_range"], shown=list(ROUTE_CANDIDATES),
              tensions=list(ROUTE_CANDIDATES), threads=1, g=cfg["g_m_per_s2"])
    tip = tip_settings_from_config(cfg)
    response_dataset(plant, motion, tz, [90.0], tuggers, tip=tip, **kw)          # compile / load
    without = cpu(lambda: response_dataset(plant, motion, tz, [90.0], tuggers, **kw))
    with_tip = cpu(lambda: response_dataset(plant, motion, tz, [90.0], tuggers, tip=tip, **kw))
    return without, with_tip, tz.size


def block_cost(cfg, motion, n):
    """CPU seconds of the relative-motion moments and of the tip statistics of n candidates."""
    rig = rigging_from_config(cfg)
    plant, _ = plant_dataset(rig, {f"c{i}": {"drop_height": 60.1 + 0.05 * i} for i in range(n)})
    exc = excitation(plant, motion, [90.0], cfg["response"]["omega_step_rad_s"])
    tz = np.arange(2.5, 14.6, 1.0)
    tuggers = {t["name"]: float(t["c_kN_s_per_m"]) for t in cfg["tuggers"]}
    tip = tip_settings_from_config(cfg)
    hinge = motion.attrs["hinge_m"][:2]
    tip_response(plant.isel(candidate=slice(0, 1)), exc, hinge, tz, tuggers, tip, threads=1)
    t_motion = cpu(lambda: unit_moments(plant, exc, tz, list(tuggers.values()), threads=1))
    t_tip = cpu(lambda: tip_response(plant, exc, hinge, tz, tuggers, tip, threads=1))
    return t_tip, t_motion


def rows() -> list[Row]:
    cfg = load(ROOT / "config" / "config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    without, with_tip, n_tz = route_response(cfg, motion)
    t64, m64 = block_cost(cfg, motion, 64)
    t128, _ = block_cost(cfg, motion, 128)
    r_route, per_1000, r_lin = with_tip / without, t128 / 128 * 1000, t128 / t64
    return [Row(f"tip clearance: default route's response ({len(ROUTE_CANDIDATES)} candidates, {n_tz} Tz), "
                "with over without", "<= 1.25x", f"{r_route:.2f}x ({without:.2f} -> {with_tip:.2f} s)",
                1.25 / r_route),
            Row("tip clearance: statistics per 1000 candidates, one core", "< 2 s",
                f"{per_1000:.2f} s ({t64 / m64:.1f}x the relative-motion moments)", 2.0 / per_1000),
            Row("tip clearance: 128 candidates over 64 (linear in candidates)", "<= 2.3x",
                f"{r_lin:.2f}x", 2.3 / r_lin)]


if __name__ == "__main__":
    for r in rows():
        print(f"{r.figure}: target {r.target}, measured {r.measured}, ratio {r.ratio:.2f}")
