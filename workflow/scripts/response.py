"""Snakemake adapter: plant + vessel motion (+ chunks) -> response.nc and operability.nc.

Inputs:   results/<route>/plant.nc, vessel_motion.nc (and the candidate chunks' moments)
Outputs:  results/<route>/response.nc (legs' Tz), operability.nc (the operability Tz grid)
Settings: the route's sea states (Tz, headings, gamma), tuggers, assessment (exposure, MPM
          cycles, tip clearance), response (frequency step, chunks), vessel.outside_rao_range,
          the cache

Run by hand for debugging: python workflow/scripts/response.py [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)
import numpy as np

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.response.tip import TipSettings
from jls.stages.response import response_dataset
from jls.tugger.loads import LOAD_VARIABLES

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("response")
sm = snakemake
with workflow_step(sm.log[0], "response") as log:
    st, a, r = sm.params.states, sm.params.assessment, sm.params.response
    t0 = time.perf_counter()
    plant, motion = read(sm.input.plant), read(sm.input.motion)
    moments = None
    if sm.input.chunks:
        parts = [read(p) for p in sm.input.chunks]
        moments = tuple(np.concatenate([p[k].values for p in parts], axis=0) for k in ("m0", "m2"))
        log.info("%d chunks assembled", len(parts))
    log.info("%d candidates, tuggers %s, headings %s, %d Tz values (%d on the legs)",
             plant.sizes["candidate"], list(sm.params.tuggers), st["headings_deg"], len(st["tz"]),
             len(st["leg_tz"]))
    ds = response_dataset(plant, motion, st["tz"], st["headings_deg"], sm.params.tuggers,
                          gamma=st["gamma"], exposure_h=a["exposure_h"],
                          cycles=a["mpm_cycles"], omega_step=r["omega_step_rad_s"], outside_policy=sm.params.outside,
                          source="config vessel.rao_file", shown=sm.params.shown,
                          cache=sm.params.cache, threads=sm.threads, moments=moments,
                          # every candidate's tensions when a tension criterion judges them,
                          # else those of the candidates the report shows
                          tensions=True if sm.params.tensions_all else list(sm.params.shown),
                          # the tip's motion relative to the waves, when the tip clearance is judged
                          tip=TipSettings(**sm.params.tip) if sm.params.tip else None, g=sm.params.g)
    evaluated = ds.attrs.pop("sea_states_evaluated")
    source = "the chunks" if moments is not None else "the cache"
    log.info("%d frequencies; %d of %d sea states evaluated, the others read from %s; "
             "%d threads; %.2f s", ds.sizes["omega"], evaluated, ds.sizes["tz"] * ds.sizes["heading"],
             source, sm.threads, time.perf_counter() - t0)
    route = sm.wildcards.route
    write(ds.sel(tz=st["leg_tz"]), sm.output.response, created_by="rule response", dataset="response",
          config_sha256=config_hash(sm.config, "response", route))
    curve = ds.drop_vars(["transfer", "omega", "shown_candidate", *LOAD_VARIABLES], errors="ignore").sel(tz=st["operability_tz"])
    write(curve, sm.output.operability, created_by="rule response", dataset="operability",
          config_sha256=config_hash(sm.config, "operability", route))
    log.info("wrote %s and %s", sm.output.response, sm.output.operability)
