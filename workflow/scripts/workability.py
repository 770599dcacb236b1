"""Snakemake adapter: sea states + unit-Hs statistics (+ time-domain cells) ->
results/<route>/workability.nc.

Inputs:   results/<route>/sea_states.nc, response.nc, operability.nc, response_variants.nc,
          and the route's time-domain cells results/<route>/timedomain/<cell>.nc (none when
          no cell runs)
Outputs:  results/<route>/workability.nc
Settings: assessment (criteria, winch_saturation, max_saturation_fraction), sea (hs_in_bin, steepness rule,
          gamma), tuggers (winch capacities)

Run by hand for debugging: python workflow/scripts/workability.py [route=NAME] [--configfile FILE ...]
"""

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.stages.workability import assess, assessed_hs
from jls.stages.workability_bands import band_variables, merge_into, sensitivity_variables
from jls.stages.winch_limits import apply_timedomain, apply_winch_limits
from jls.tugger import tuggers_from_config

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("workability")
sm = snakemake
with workflow_step(sm.log[0], "workability") as log:
    sea, response = read(sm.input.sea), read(sm.input.response)
    ds = assess(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea["hs_in_bin"],
                steepness_rule=sm.params.sea["steepness_rule"], gamma=sm.params.sea["gamma"],
                curve=read(sm.input.curve))
    hs = assessed_hs(sea, sm.params.sea["hs_in_bin"])
    tuggers = tuggers_from_config({"tuggers": sm.params.tuggers})
    ds = apply_winch_limits(ds, response, sea, tuggers, hs, sm.params.winch_saturation)
    cells = [read(p) for p in sm.input.timedomain]
    ds = apply_timedomain(ds, sea, cells, hs)
    n_sat = int(ds["winch_saturates"].sum())
    log.info("winch saturation (%s): %d cells flagged; %d time-domain cells replace %d verdicts",
             sm.params.winch_saturation, n_sat, len(cells), int((ds["verdict_source"] == 3).sum()))
    bands = band_variables(read(sm.input.variants), sea, sm.params.criteria, ds,
                           steepness_rule=sm.params.sea["steepness_rule"], gamma=sm.params.sea["gamma"],
                           tuggers=tuggers, winch_saturation=sm.params.winch_saturation)
    sens = sensitivity_variables(response, sea, sm.params.criteria, hs_in_bin=sm.params.sea["hs_in_bin"])
    ds = registry.annotate(merge_into(ds, bands, sens), "workability")
    ds.attrs.update(route=sm.wildcards.route, exposure_h=response.attrs["exposure_h"],
                    mpm_cycles=response.attrs["mpm_cycles"],
                    max_saturation_fraction=sm.params.max_saturation_fraction)
    share, lo, hi = (ds[f"workability_route{e}"].transpose("candidate", "tugger").values
                     for e in ("", "_min", "_max"))
    for i, cand in enumerate(ds["candidate"].values):
        for j, tug in enumerate(ds["tugger"].values):
            log.info("candidate %s, tugger %s: route workability %.1f %% (band %.1f-%.1f %%)", cand,
                     tug, 100 * share[i, j], 100 * lo[i, j], 100 * hi[i, j])
    write(ds, sm.output[0], created_by="rule workability", dataset="workability",
          config_sha256=registry.config_hash(sm.config, "workability", sm.wildcards.route))
