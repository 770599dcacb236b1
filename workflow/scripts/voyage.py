"""Snakemake adapter: sea states + unit-Hs statistics (+ the legs' hourly hindcasts) ->
results/<route>/voyage.nc.

Inputs:   results/<route>/sea_states.nc, response.nc, operability.nc; the hindcast files of
          the route's legs (route simulation when every leg is a hindcast); measured_response.nc
          when a leg is given by spectra (its hours' sway ratio in the route simulation)
Outputs:  results/<route>/voyage.nc
Settings: assessment.criteria, sea.hs_in_bin, sea.gamma, the route's legs

Run by hand for debugging: python workflow/scripts/voyage.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.voyage import voyage

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("voyage")
sm = snakemake
LOGGED = 48                    # combinations logged one by one
with workflow_step(sm.log[0], "voyage") as log:
    measured = read(sm.input.measured[0]) if sm.input.measured else None
    ds = voyage(read(sm.input.sea), read(sm.input.response), read(sm.input.operability),
                sm.params.criteria, sm.params.hs_in_bin, sm.params.route, threads=sm.threads,
                gamma=sm.params.gamma, measured=measured)
    ds.attrs["route"] = sm.wildcards.route
    combos = [(c, t) for c in ds["candidate"].values for t in ds["tugger"].values]
    for c, t in combos[:LOGGED]:         # a large grid's every line would cost more than the stage
        p = ds["exceedance_probability"].sel(candidate=c, tugger=t)
        log.info("candidate %s, tugger %s: P(voyage max > limit) %s", c, t,
                 ", ".join(f"{k} {float(v):.3g}" for k, v in zip(p["criterion"].values, p.values)))
    if len(combos) > LOGGED:
        log.info("... and %d more combinations (voyage.nc)", len(combos) - LOGGED)
    if "pass_probability" in ds:
        log.info("route simulation: %d departures judged", int(ds["judged_month"].sum()))
    write(ds, sm.output[0], created_by="rule voyage", dataset="voyage",
          config_sha256=config_hash(sm.config, "voyage", sm.wildcards.route))
