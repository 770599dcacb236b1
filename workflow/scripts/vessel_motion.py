"""Snakemake adapter: vessel RAO file -> results/<route>/vessel_motion.nc."""

from jls import registry
from jls.config import file_sha256
from jls.motion import vessel_motion
from jls.netcdf import write
from jls.provenance import workflow_step

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "vessel_motion") as log:
    ds = vessel_motion(sm.params.vessel, sm.params.headings)
    log.info("RAO %s: %d frequencies %.3f-%.3f rad/s, headings %s deg", sm.input.rao, ds.sizes["omega"],
             float(ds["omega"].min()), float(ds["omega"].max()), ds["heading"].values.tolist())
    write(ds, sm.output[0], config_sha256=registry.config_hash(sm.config, "vessel_motion", sm.wildcards.route), created_by="rule vessel_motion", dataset="vessel_motion",
          inputs={"rao": file_sha256(sm.input.rao)})
    log.info("wrote %s", sm.output[0])
