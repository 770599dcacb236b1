"""Snakemake adapter: plant + vessel motion -> unit-Hs statistics on the fine Tz grid."""

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.unit_response import response_dataset

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "operability") as log:
    a, r = sm.params.assessment, sm.params.response
    plant, motion = read(sm.input.plant), read(sm.input.motion)
    log.info("%d Tz values %.2f-%.2f s, headings %s", len(sm.params.tz), min(sm.params.tz),
             max(sm.params.tz), sm.params.headings)
    ds = response_dataset(plant, motion, sm.params.tz, sm.params.headings, sm.params.tuggers,
                          gamma=sm.params.gamma, exposure_h=a["exposure_h"],
                          cycles=a["mpm_cycles"], omega_step=r["omega_step_rad_s"],
                          outside_policy=sm.params.outside, source="config vessel.rao_file")
    write(ds.drop_vars("transfer"), sm.output[0], config_sha256=registry.config_hash(sm.config, "operability", sm.wildcards.route),
          created_by="rule operability")
    log.info("wrote %s", sm.output[0])
