"""Snakemake adapter: rigging candidates -> results/<route>/plant.nc.

Inputs:   none (the configuration)
Outputs:  results/<route>/plant.nc
Settings: g, jacket, rigging, candidates, candidate_grid

Run by hand for debugging: python workflow/scripts/plant.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import write
from jls.io.provenance import workflow_step
from jls.stages.plant import plant

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("plant")
sm = snakemake
with workflow_step(sm.log[0], "plant") as log:
    ds = plant(sm.params.plant)
    for name in ds["candidate"].values:
        c = ds.sel(candidate=name)
        log.info("candidate %s: periods %s s, feasible %s", name,
                 ", ".join(f"{t:.3f}" for t in c["natural_period"].values), bool(c["feasible"]))
    write(ds, sm.output[0], config_sha256=config_hash(sm.config, "plant", sm.wildcards.route),
          created_by="rule plant", dataset="plant")
    log.info("wrote %s", sm.output[0])
