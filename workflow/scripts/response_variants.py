"""Snakemake adapter: plant + vessel motion -> results/<route>/response_variants.nc.

Inputs:   results/<route>/plant.nc, vessel_motion.nc
Outputs:  results/<route>/response_variants.nc (unit-Hs statistics of the plant variants
          of every candidate on the legs' Tz values; coordinates base_candidate,
          damping_factor, sway_frequency_factor on candidate)
Settings: the candidates to vary (all, or the shown ones for a large grid), the route's sea states, tuggers, assessment (exposure, MPM cycles), response
          (frequency step), vessel.outside_rao_range, whether a tension criterion is set, the tip
          clearance

Run by hand for debugging: python workflow/scripts/response_variants.py [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.response.tip import TipSettings
from jls.stages.response_variants import response_variants

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("response_variants")
sm = snakemake
with workflow_step(sm.log[0], "response_variants") as log:
    st, a, r = sm.params.states, sm.params.assessment, sm.params.response
    t0 = time.perf_counter()
    ds = response_variants(read(sm.input.plant), read(sm.input.motion), sm.params.candidates,
                           st["leg_tz"], st["headings_deg"], sm.params.tuggers, gamma=st["gamma"],
                           exposure_h=a["exposure_h"], cycles=a["mpm_cycles"],
                           omega_step=r["omega_step_rad_s"], outside_policy=sm.params.outside,
                           source="config vessel.rao_file", cache=sm.params.cache,
                           threads=sm.threads, tensions=sm.params.tensions,
                           tip=TipSettings(**sm.params.tip) if sm.params.tip else None, g=sm.params.g)
    evaluated = ds.attrs.pop("sea_states_evaluated")
    log.info("%d variants of %d candidates; %d sea states evaluated; %.2f s", ds.sizes["candidate"],
             ds["base_candidate"].to_index().nunique(), evaluated, time.perf_counter() - t0)
    write(ds, sm.output[0], created_by="rule response_variants",
          config_sha256=config_hash(sm.config, "response_variants", sm.wildcards.route),
          dataset="response_variants")
