"""Benchmark: the nonlinear verification against the 6-DOF MoorDyn reference.

Targets:
  1. one 3-hour verification cell (jls.verify.cell.verify_cell: the reference's static
     state and modes with six small free decays, the sway free decay of both models, and
     both models on the same 3-hour irregular record after the five-time-constant
     start-up, MoorDyn with one segment per wire, RK4 at 0.02 s) in under 30 s on one
     core, baseline rigging, Hs 2.4 m, Tz 6.6 s, beam seas;
  2. the reference's integration of that record at >= 500x real time;
  3. the study's harmonic tests (12, 13.9, 17, 19 s at 0.5 m hinge sway) in under 10 s;
  4. a pipeline cell as configured (20-min record at the 0.1-s step, the decays along the
     six modes) of the design corner in under 10 s on one core;
  5. the wire check of that cell (verification.wires: four segments of 0.1 t/m, 90 s
     after 30 s, beside the one-segment reference) in under 10 s;
  6. each part of the study comparison (verification_study.nc: five sea states and the
     linear-range steps, run by the workflow as four jobs beside each other and the
     time-domain cells, jls.verify.names.STUDY_PARTS) in under 10 s on one core.

Each job's CPU time is printed beside its wall time (on a loaded machine the CPU time is
the better guide to what an idle core would take).

Run: python benchmarks/verify.py (prints the rows and the cell's headline numbers).
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).resolve().parent))

from rows import Row, at_least, within  # noqa: E402

from jls.config.builders import plant_from_config  # noqa: E402
from jls.config.loader import load  # noqa: E402
from jls.stages.vessel_motion import vessel_motion  # noqa: E402
from jls.verify import build_reference, harmonic, reference_available  # noqa: E402
from jls.verify.cell import cell_summary, verify_cell  # noqa: E402


def measure():
    cfg = load(ROOT / "config/config.yaml")
    plant = plant_from_config(cfg)
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    verify_cell(plant, motion, 2.4, 6.6, 90.0, duration_s=60.0, transient=10.0)   # compile, load
    t = time.perf_counter()
    ds = verify_cell(plant, motion, 2.4, 6.6, 90.0, duration_s=3 * 3600.0)
    cell = time.perf_counter() - t
    sim = ds.attrs["duration_s"] + ds.attrs["transient_s"]
    ref = build_reference(plant, vessel_lever_m=motion.attrs["hinge_m"])
    t = time.perf_counter()
    harmonic(ref, plant, (12.0, 13.9, 17.0, 19.0), (0.5,))
    harm = time.perf_counter() - t
    return cell, sim / float(ds["wall_time_reference"]), harm, ds


def measure_pipeline_jobs():
    """(wall, CPU) times of a configured design-corner cell, its wire check and each part
    of the study comparison (name: (wall, CPU))."""
    from jls.stages.verification_cell import cell_dataset, study_part_dataset, wires_dataset
    from jls.verify.names import STUDY_PARTS
    cfg = load(ROOT / "config/config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    cell = {"candidate": "detuned", "tugger": "none", "heading": 90.0, "hs": 3.25, "tz": 6.5}
    jobs = {"cell": lambda: cell_dataset(cfg, motion, cell), "wires": lambda: wires_dataset(cfg, motion, cell)}
    jobs.update({f"study {p}": (lambda p=p: study_part_dataset(cfg, motion, p)) for p in STUDY_PARTS})
    out = {}
    for name, job in jobs.items():
        t, c = time.perf_counter(), time.process_time()
        job()
        out[name] = (time.perf_counter() - t, time.process_time() - c)
    return out


def rows():
    ok, why = reference_available()
    if not ok:
        return [Row(f"verification: not run ({why})", "", "", float("nan"))]
    cell, rtf, harm, _ = measure()
    jobs = measure_pipeline_jobs()
    job, wires = jobs["cell"][0], jobs["wires"][0]
    study = max(w for k, (w, _) in jobs.items() if k.startswith("study"))
    return [within("verification: one 3-h cell (reference + ROM, decays, irregular record), 1 core", 30.0, cell),
            at_least("verification: MoorDyn reference, real-time factor", 500.0, rtf, "x"),
            within("verification: study's four harmonic tests at 0.5 m", 10.0, harm),
            within("verification: a pipeline cell (design corner), 1 core", 10.0, job),
            within("verification: wire check, four segments, 1 core", 10.0, wires),
            within("verification: study comparison's longest part (table 4.4, linear range), 1 core", 10.0, study)]


if __name__ == "__main__":
    ok, why = reference_available()
    if not ok:
        print(why)
        raise SystemExit(1)
    cell, rtf, harm, ds = measure()
    jobs = measure_pipeline_jobs()
    job, wires = jobs["cell"][0], jobs["wires"][0]
    study = max(w for k, (w, _) in jobs.items() if k.startswith("study"))
    for r in [within("one 3-h cell, 1 core", 30.0, cell), at_least("reference real-time factor", 500.0, rtf, "x"),
              within("four harmonic tests at 0.5 m", 10.0, harm),
              within("a pipeline cell (design corner)", 10.0, job), within("wire check", 10.0, wires),
              within("study comparison's longest part", 10.0, study)]:
        print(f"{r.figure:<40}{r.target:>12}{r.measured:>12}{r.ratio:8.2f}")
    for name, (wall, cpu) in jobs.items():
        print(f"{name:<40}wall {wall:6.2f} s  CPU {cpu:6.2f} s")
    print(json.dumps(cell_summary(ds), indent=1))
