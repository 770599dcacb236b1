"""Snakemake adapter: vessel motion -> spectral moments of one chunk of screening candidates.

Inputs:   results/<route>/vessel_motion.nc
Outputs:  results/<route>/screening/chunk-<n>.nc (m0, m2 of the chunk's candidates; kept, so
          that re-scoring the screening, e.g. after a probability edit, reruns no chunk job)
Settings: rigging, screening (grid, envelope), tuggers, gamma, frequency step, the route's
          Tz values and headings, chunk size, the sea-state cache

Run by hand for debugging: python workflow/scripts/screening_chunk.py chunk=0 [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.builders import design_grid_points, rigging_from_config
from jls.config.dataset_hash import config_hash
from jls.design.scoring import Envelope, MomentSettings
from jls.design.screening import chunk_moments, screening_values
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.plant.candidates import plant_dataset
from jls.response.moments import moments_dataset

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("screening_chunk")
sm = snakemake
with workflow_step(sm.log[0], "screening_chunk") as log:
    p, st = sm.params.moments, sm.params.states
    t0 = time.perf_counter()
    rig = rigging_from_config(p["plant"])
    plant, _ = plant_dataset(rig, screening_values(rig, design_grid_points(p["grid_points"])))
    env = Envelope(**p["envelope"])
    scoring = MomentSettings(tuggers={k: float(v) for k, v in p["tuggers"].items()},
                             gamma=p["gamma"], omega_step=p["omega_step_rad_s"],
                             outside_policy=p["outside"])
    tz = sorted(set(map(float, st["leg_tz"])) | set(map(float, env.tz())))
    headings = sorted(set(map(float, st["headings_deg"])) | {float(env.heading_deg)})
    i, size = int(sm.wildcards.chunk), int(sm.params.chunk)
    part = slice(i * size, min((i + 1) * size, plant.sizes["candidate"]))
    motion = read(sm.input.motion)
    evaluated = []
    m0, m2 = chunk_moments(plant, motion, tz, headings, scoring, part, p["chunk_size"],
                           cache=sm.params.cache, threads=sm.threads, counter=evaluated)
    n_states = len(tz) * len(headings) * len(evaluated)
    log.info("chunk %d: screening candidates %d-%d of %d; %d of %d sea states evaluated "
             "(blocks x Tz x headings), the others read from the cache; %.2f s", i, part.start,
             part.stop - 1, plant.sizes["candidate"], sum(evaluated), n_states,
             time.perf_counter() - t0)
    ds = moments_dataset(m0, m2, candidates=plant["candidate"].values[part],
                         tuggers=scoring.tuggers, headings=headings, tz=tz)
    write(ds, sm.output[0], created_by="rule screening_chunk",
          config_sha256=config_hash(sm.config, "screening", sm.wildcards.route))
