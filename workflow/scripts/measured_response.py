"""Snakemake adapter: plant + vessel motion + the spectra legs' files ->
results/<route>/measured_response.nc.

Inputs:   the assessed plant, results/<route>/vessel_motion.nc, the spectra files of the
          route's spectra legs (NDBC: with their direction files)
Outputs:  results/<route>/measured_response.nc
Settings: tuggers, sea.gamma, response.omega_step_rad_s, the route's legs, the assessment
          criteria (every criterion of each hour on its own sea)

Run by hand for debugging: python workflow/scripts/measured_response.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.measured_response import measured_response

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("measured_response")
sm = snakemake
with workflow_step(sm.log[0], "measured_response") as log:
    route = dict(sm.params.route, name=sm.wildcards.route)
    ds = measured_response(route, read(sm.input.plant), read(sm.input.motion), sm.params.tuggers,
                           gamma=sm.params.gamma, omega_step=sm.params.omega_step, threads=sm.threads,
                           sea=sm.params.sea, cfg=sm.params.cfg)
    for leg in ds["leg"].values:
        r = ds["sigma_ratio"].sel(leg=leg)
        log.info("leg %s: %d hours, sigma ratio measured/JONSWAP %.3f-%.3f over the options (%s)",
                 leg, int(ds["hours"].sel(leg=leg)), float(r.min()), float(r.max()),
                 ds.attrs[f"integration_{leg}"])
    write(ds, sm.output[0], created_by="rule measured_response", dataset="measured_response",
          config_sha256=config_hash(sm.config, "measured_response", sm.wildcards.route))
