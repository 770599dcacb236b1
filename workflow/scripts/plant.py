"""Snakemake adapter: rigging candidates -> results/<route>/plant.nc.

Inputs:   none (the configuration)
Outputs:  results/<route>/plant.nc
Settings: g, jacket, rigging, candidates, candidate_grid

Run by hand for debugging: python workflow/scripts/plant.py [route=NAME] [--configfile FILE ...]
"""

from jls.assembly import plant_from_config, rigging_from_config
from jls.stages.plant import candidate_values, plant_dataset
from jls import registry
from jls.netcdf import write
from jls.provenance import workflow_step

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("plant")
sm = snakemake
with workflow_step(sm.log[0], "plant") as log:
    cfg = sm.params.plant
    plant_from_config(cfg)               # the baseline must be a valid plant: named errors
    rig = rigging_from_config(cfg)
    values = candidate_values(cfg)
    ds, _ = plant_dataset(rig, values)
    for name in ds["candidate"].values:
        c = ds.sel(candidate=name)
        log.info("candidate %s: periods %s s, feasible %s", name,
                 ", ".join(f"{t:.3f}" for t in c["natural_period"].values), bool(c["feasible"]))
    write(ds, sm.output[0], config_sha256=registry.config_hash(sm.config, "plant", sm.wildcards.route), created_by="rule plant", dataset="plant")
    log.info("wrote %s", sm.output[0])
