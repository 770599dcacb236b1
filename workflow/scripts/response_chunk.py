"""Snakemake adapter: plant + vessel motion -> spectral moments of one chunk of candidates.

Inputs:   results/<route>/plant.nc, vessel_motion.nc
Outputs:  results/<route>/response/chunk-<n>.nc (temporary: m0, m2 of the chunk's candidates)
Settings: the route's sea states, tuggers, response (frequency step, chunk size), the cache

Run by hand for debugging: python workflow/scripts/response_chunk.py chunk=0 [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)
import numpy as np

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.response.moments import excitation, moments_dataset, unit_moments

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("response_chunk")
sm = snakemake
with workflow_step(sm.log[0], "response_chunk") as log:
    st, tuggers = sm.params.states, sm.params.tuggers
    t0 = time.perf_counter()
    plant, motion = read(sm.input.plant), read(sm.input.motion)
    i, size = int(sm.wildcards.chunk), int(sm.params.chunk)
    part = slice(i * size, min((i + 1) * size, plant.sizes["candidate"]))
    exc = excitation(plant, motion, st["headings_deg"], sm.params.response["omega_step_rad_s"])
    tz = np.asarray(sorted(st["tz"]), float)
    m0, m2, evaluated = unit_moments(plant, exc, tz, [float(v) for v in tuggers.values()], st["gamma"],
                                     candidates=part, cache=sm.params.cache, threads=sm.threads)
    log.info("chunk %d: candidates %d-%d, %d frequencies; %d of %d sea states evaluated, the "
             "others read from the cache; %d threads; %.2f s", i, part.start, part.stop - 1,
             exc.omega.size, evaluated, tz.size * exc.headings.size, sm.threads,
             time.perf_counter() - t0)
    ds = moments_dataset(m0, m2, candidates=plant["candidate"].values[part], tuggers=tuggers,
                         headings=exc.headings, tz=tz)
    write(ds, sm.output[0], created_by="rule response_chunk",
          config_sha256=config_hash(sm.config, "response", sm.wildcards.route))
