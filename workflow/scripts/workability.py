"""Snakemake adapter: sea states + unit-Hs statistics -> results/<route>/workability.nc."""

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.workability import assess

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "workability") as log:
    sea, response = read(sm.input.sea), read(sm.input.response)
    ds = assess(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea["hs_in_bin"],
                steepness_rule=sm.params.sea["steepness_rule"], gamma=sm.params.sea["gamma"],
                curve=read(sm.input.curve))
    ds.attrs.update(route=sm.wildcards.route, exposure_h=response.attrs["exposure_h"],
                    mpm_cycles=response.attrs["mpm_cycles"])
    for cand in ds["candidate"].values:
        for tug in ds["tugger"].values:
            log.info("candidate %s, tugger %s: route workability %.1f %%", cand, tug,
                     100 * float(ds["workability_route"].sel(candidate=cand, tugger=tug)))
    write(ds, sm.output[0], config_sha256=registry.config_hash(sm.config, "workability", sm.wildcards.route), created_by="rule workability")
