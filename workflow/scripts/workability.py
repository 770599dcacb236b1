"""Snakemake adapter: sea states + unit-Hs statistics -> results/<route>/workability.nc.

Inputs:   results/<route>/sea_states.nc, response.nc, operability.nc, response_variants.nc
Outputs:  results/<route>/workability.nc
Settings: assessment.criteria, sea (hs_in_bin, steepness rule, gamma)

Run by hand for debugging: python workflow/scripts/workability.py [route=NAME] [--configfile FILE ...]
"""

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.stages.workability import assess
from jls.stages.workability_bands import band_variables, merge_into, sensitivity_variables

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("workability")
sm = snakemake
with workflow_step(sm.log[0], "workability") as log:
    sea, response = read(sm.input.sea), read(sm.input.response)
    ds = assess(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea["hs_in_bin"],
                steepness_rule=sm.params.sea["steepness_rule"], gamma=sm.params.sea["gamma"],
                curve=read(sm.input.curve))
    bands = band_variables(read(sm.input.variants), sea, sm.params.criteria, ds,
                           steepness_rule=sm.params.sea["steepness_rule"], gamma=sm.params.sea["gamma"])
    sens = sensitivity_variables(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea["hs_in_bin"])
    ds = registry.annotate(merge_into(ds, bands, sens), "workability")
    ds.attrs.update(route=sm.wildcards.route, exposure_h=response.attrs["exposure_h"],
                    mpm_cycles=response.attrs["mpm_cycles"])
    route_share = ds["workability_route"].transpose("candidate", "tugger").values
    for cand, shares in zip(ds["candidate"].values, route_share):
        for tug, share in zip(ds["tugger"].values, shares):
            band = [float(ds[f"workability_route_{e}"].sel(candidate=cand, tugger=tug)) for e in ("min", "max")]
            log.info("candidate %s, tugger %s: route workability %.1f %% (band %.1f-%.1f %%)", cand, tug,
                     100 * share, 100 * band[0], 100 * band[1])
    write(ds, sm.output[0], created_by="rule workability",
          config_sha256=registry.config_hash(sm.config, "workability", sm.wildcards.route))
