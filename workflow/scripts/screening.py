"""Snakemake adapter: sea states + vessel motion + chunk moments -> screening.nc and
plant_assessed.nc.

Inputs:   results/<route>/sea_states.nc, vessel_motion.nc, screening/chunk-<n>.nc
Outputs:  results/<route>/screening.nc (candidates baseline, grid_NNNN, refined; attribute
          optimum_candidate names the design assessed as "optimised"),
          results/<route>/plant_assessed.nc (the configured candidates and "optimised")
Settings: rigging, tuggers, sea, assessment, response, screening, vessel; g, jacket,
          candidates, candidate_grid (the assessed plant)

Run by hand for debugging: python workflow/scripts/screening.py [route=NAME] [--configfile FILE ...]
"""

import time

import numpy as np

from jls import registry
from jls.assembly import rigging_from_config
from jls.errors import InputError
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.scoring import Scoring, screening_states
from jls.stages.plant import candidate_values, plant_dataset
from jls.stages.screening import Settings, optimised_values, screening_dataset

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("screening")
sm = snakemake
with workflow_step(sm.log[0], "screening") as log:
    cfg = sm.params.config
    t0 = time.perf_counter()
    rig = rigging_from_config(cfg)
    scoring, settings = Scoring.from_config(cfg), Settings.from_config(cfg)
    sea, motion = read(sm.input.sea), read(sm.input.motion)
    parts = [read(p) for p in sm.input.chunks]
    tz, headings = screening_states(sea, scoring)
    for path, part in zip(sm.input.chunks, parts):
        if not (np.allclose(part["tz"].values, tz) and np.allclose(part["heading"].values, headings)):
            raise InputError("the chunk's sea states differ from the route's; rerun its chunk job",
                             file=path, field="tz", value=part["tz"].values.tolist())
    moments = tuple(np.concatenate([p[k].values for p in parts], axis=0) for k in ("m0", "m2"))
    ds = screening_dataset(rig, motion, sea, scoring, settings, moments=moments, threads=sm.threads)
    ds.attrs["design_hs_m"] = float(cfg["screening"]["design_hs_m"])   # the report's Tz window
    a = ds.attrs
    n_feasible = int(ds["feasible"].sum())
    log.info("%d candidates from %d chunks, %d feasible; optimum %s (%s); %.2f s",
             ds.sizes["candidate"], len(parts), n_feasible, a["optimum_candidate"] or "none",
             a["refinement"], time.perf_counter() - t0)
    # The assessed plant: the configured candidates and the optimum, named "optimised".
    pcfg = sm.params.plant
    values = {**candidate_values(pcfg), "optimised": optimised_values(ds, sm.output.screening)}
    plant, _ = plant_dataset(rigging_from_config(pcfg), values)
    plant.attrs["optimised_from"] = a["optimum_candidate"]
    o = plant.sel(candidate="optimised")
    log.info("optimised (screening candidate %s): %s; periods %s s, feasible %s",
             a["optimum_candidate"], ", ".join(f"{k} {v:.3f} m" for k, v in values["optimised"].items()),
             ", ".join(f"{t:.3f}" for t in o["natural_period"].values), bool(o["feasible"]))
    write(ds, sm.output.screening, dataset="screening", created_by="rule screening",
          config_sha256=registry.config_hash(sm.config, "screening", sm.wildcards.route))
    write(plant, sm.output.plant, created_by="rule screening",
          config_sha256=registry.config_hash(sm.config, "plant", sm.wildcards.route))
    log.info("wrote %s and %s", sm.output.screening, sm.output.plant)
