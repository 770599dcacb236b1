"""Snakemake adapter: sea states + unit-Hs statistics -> results/<route>/workability.nc."""

from jls.config import config_hash
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.workability import assess

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "workability") as log:
    sea, response = read(sm.input.sea), read(sm.input.response)
    ds = assess(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea.get("hs_in_bin", "centre"),
                steepness_rule=sm.params.sea.get("steepness_rule", "study"),
                gamma=float(sm.params.sea.get("gamma", 3.3)), curve=read(sm.input.curve))
    ds.attrs.update(route=sm.wildcards.route, exposure_h=response.attrs["exposure_h"],
                    mpm_cycles=response.attrs["mpm_cycles"])
    route_share = ds["workability_route"].transpose("candidate", "tugger").values
    for cand, shares in zip(ds["candidate"].values, route_share):
        for tug, share in zip(ds["tugger"].values, shares):
            log.info("candidate %s, tugger %s: route workability %.1f %%", cand, tug, 100 * share)
    write(ds, sm.output[0], config_sha256=config_hash(sm.config), created_by="rule workability")
