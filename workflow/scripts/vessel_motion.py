"""Snakemake adapter: vessel RAO file -> results/<route>/vessel_motion.nc.

Inputs:   the vessel RAO file (vessel.rao_file)
Outputs:  results/<route>/vessel_motion.nc
Settings: vessel block, the route's headings

Run by hand for debugging: python workflow/scripts/vessel_motion.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.hashing import file_sha256
from jls.io.netcdf import write
from jls.io.provenance import workflow_step
from jls.stages.vessel_motion import vessel_motion

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("vessel_motion")
sm = snakemake
with workflow_step(sm.log[0], "vessel_motion") as log:
    ds = vessel_motion(sm.params.vessel, sm.params.headings)
    log.info("RAO %s: %d frequencies %.3f-%.3f rad/s, headings %s deg", sm.input.rao, ds.sizes["omega"],
             float(ds["omega"].min()), float(ds["omega"].max()), ds["heading"].values.tolist())
    write(ds, sm.output[0], config_sha256=config_hash(sm.config, "vessel_motion", sm.wildcards.route), created_by="rule vessel_motion", dataset="vessel_motion",
          inputs={"rao": file_sha256(sm.input.rao)})
    log.info("wrote %s", sm.output[0])
