"""Snakemake adapter: decay tests and damping-slope sweep -> results/<route>/tugger_studies.nc.

Inputs:   results/<route>/vessel_motion.nc
Outputs:  results/<route>/tugger_studies.nc
Settings: timedomain (integration, slope_sweep, decay_release_m), tuggers, jacket and rigging

Run by hand for debugging: python workflow/scripts/tugger_studies.py [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.tugger_studies import tugger_studies

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("tugger_studies")
sm = snakemake
with workflow_step(sm.log[0], "tugger_studies") as log:
    t0 = time.perf_counter()
    ds = tugger_studies(sm.config, read(sm.input.motion), workers=sm.threads)
    for tug in ds["tugger"].values:
        log.info("decay, tugger %s: %.1f s to 10 %%", tug, float(ds["decay_time_to_10pct"].sel(tugger=tug)))
    log.info("%d slopes x %d Tz swept; %.2f s", ds.sizes["slope"], ds.sizes["sweep_tz"],
             time.perf_counter() - t0)
    write(ds, sm.output[0], dataset="tugger_studies", created_by="rule tugger_studies",
          config_sha256=config_hash(sm.config, "tugger_studies", sm.wildcards.route))
