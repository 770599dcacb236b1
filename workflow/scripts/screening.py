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

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.plant.rigging import DESIGN_VARIABLES
from jls.stages.plant import assessed_plant
from jls.stages.screening import screening

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("screening")
sm = snakemake
with workflow_step(sm.log[0], "screening") as log:
    t0 = time.perf_counter()
    sea, motion = read(sm.input.sea), read(sm.input.motion)
    chunks = {path: read(path) for path in sm.input.chunks}
    ds = screening(sm.params.config, motion, sea, chunks, threads=sm.threads)
    a = ds.attrs
    log.info("%d candidates from %d chunks, %d feasible; optimum %s (%s); %.2f s",
             ds.sizes["candidate"], len(chunks), int(ds["feasible"].sum()),
             a["optimum_candidate"] or "none", a["refinement"], time.perf_counter() - t0)
    plant = assessed_plant(sm.params.plant, ds, sm.output.screening)
    o = plant.sel(candidate="optimised")
    log.info("optimised (screening candidate %s): %s; periods %s s, feasible %s",
             a["optimum_candidate"],
             ", ".join(f"{k} {float(o[k]):.3f} m" for k in DESIGN_VARIABLES),
             ", ".join(f"{t:.3f}" for t in o["natural_period"].values), bool(o["feasible"]))
    write(ds, sm.output.screening, dataset="screening", created_by="rule screening",
          config_sha256=config_hash(sm.config, "screening", sm.wildcards.route))
    write(plant, sm.output.plant, created_by="rule screening",
          config_sha256=config_hash(sm.config, "plant", sm.wildcards.route))
    log.info("wrote %s and %s", sm.output.screening, sm.output.plant)
