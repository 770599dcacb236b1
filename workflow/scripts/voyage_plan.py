"""Snakemake adapter: sea states + unit statistics (+ the legs' hourly records) ->
results/<route>/voyage_plan.nc.

Inputs:   results/<route>/sea_states.nc, operability.nc; the hourly records of the route's
          legs (record legs' files, table legs' records); measured_response.nc when a leg
          is given by spectra; the assessed plant and the RAO file when a leg's sea has
          partitions (the swell table)
Outputs:  results/<route>/voyage_plan.nc
Settings: assessment.criteria, assessment.exposure_h, operation, sea.gamma, the route's legs

Run by hand for debugging: python workflow/scripts/voyage_plan.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.voyage_plan import voyage_plan

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("voyage_plan")
sm = snakemake
with workflow_step(sm.log[0], "voyage_plan") as log:
    measured = read(sm.input.measured[0]) if sm.input.measured else None
    transfer = None
    if sm.input.swell:                     # partitioned legs: the options' transfer, as jls forecast builds it
        from jls.commands.response import transfer_from_config
        transfer = transfer_from_config(sm.config, ".", plant=read(sm.input.swell[0]))
    ds = voyage_plan(read(sm.input.sea), read(sm.input.operability), sm.params.route, sm.params.criteria,
                     sm.params.operation, gamma=sm.params.gamma, exposure_h=sm.params.exposure_h,
                     measured=measured, transfer=transfer, config=sm.config)
    ds.attrs["route"] = sm.wildcards.route
    log.info("route %s: %s; %s", ds.attrs["route_class"], ds.attrs["stretches"],
             ds.attrs["class_statement"] or "every stretch weather-restricted")
    log.info("unrestricted design check: %d of %d options acceptable", int(ds["design_acceptable"].sum()),
             ds["design_acceptable"].size)
    if "plan_exceedance_probability" in ds:
        log.info("departure rule: P(sailed voyage exceeds) %.3g-%.3g over the options",
                 float(ds["plan_exceedance_probability"].min()), float(ds["plan_exceedance_probability"].max()))
    else:
        log.info("%s", ds.attrs["plan_reason"])
    write(ds, sm.output[0], created_by="rule voyage_plan", dataset="voyage_plan",
          config_sha256=config_hash(sm.config, "voyage_plan", sm.wildcards.route))
