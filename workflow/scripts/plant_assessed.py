"""Snakemake adapter: configuration + screening.nc -> plant_assessed.nc.

Inputs:   results/<route>/screening.nc (its optimum)
Outputs:  results/<route>/plant_assessed.nc (the configured candidates and "optimised")
Settings: g, jacket, rigging, candidates, candidate_grid

Run by hand for debugging: python workflow/scripts/plant_assessed.py [route=NAME] [--configfile FILE ...]
"""

from jls import registry
from jls.assembly import rigging_from_config
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.stages.plant import candidate_values, plant_dataset
from jls.stages.screening import optimised_values

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("plant_assessed")
sm = snakemake
with workflow_step(sm.log[0], "plant_assessed") as log:
    cfg = sm.params.plant
    rig = rigging_from_config(cfg)
    screening = read(sm.input.screening)
    values = {**candidate_values(cfg), "optimised": optimised_values(screening, sm.input.screening)}
    ds, _ = plant_dataset(rig, values)
    ds.attrs["optimised_from"] = screening.attrs["optimum_candidate"]
    o = ds.sel(candidate="optimised")
    log.info("optimised (screening candidate %s): %s; periods %s s, feasible %s",
             screening.attrs["optimum_candidate"],
             ", ".join(f"{k} {v:.3f} m" for k, v in values["optimised"].items()),
             ", ".join(f"{t:.3f}" for t in o["natural_period"].values), bool(o["feasible"]))
    write(ds, sm.output[0], created_by="rule plant_assessed",
          config_sha256=registry.config_hash(sm.config, "plant", sm.wildcards.route))
