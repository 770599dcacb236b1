"""Snakemake adapter: one time-domain cell -> results/<route>/timedomain/<cell>.nc.

Inputs:   results/<route>/vessel_motion.nc; plant_assessed.nc for a candidate no
          configuration lists (the screening's optimised)
Outputs:  results/<route>/timedomain/<cell>.nc (statistics per tugger, trace window)
Settings: the cell (from its name: candidate, heading, Hs, Tz[, the leg whose own sea it
          runs in, with that leg's files and sea.spreading]), timedomain (integration,
          record, trace), jacket and rigging, tuggers, sea.gamma, assessment.exposure_h

Run by hand for debugging: python workflow/scripts/timedomain_cell.py cell=NAME [route=NAME] [--configfile FILE ...]
"""

import time

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.timedomain_cell import cell_dataset

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("timedomain_cell")
sm = snakemake
with workflow_step(sm.log[0], "timedomain_cell") as log:
    t0 = time.perf_counter()
    cell = dict(sm.params.cell)
    plant = read(sm.input.plant[0]) if sm.input.plant else None
    ds = cell_dataset(sm.config, read(sm.input.motion), cell, source="config", workers=sm.threads,
                      plant_ds=plant, leg=sm.params.sea_leg)
    log.info("%s: the sea is %s", sm.wildcards.cell, ds.attrs["sea"])
    for tug in ds["tugger"].values:
        r = ds.sel(tugger=tug)
        log.info("%s, tugger %s: sigma %.3f m (FD %.3f; std over records %.3f, expected %.3f), "
                 "MPM %.2f m, at a limit %.1f %%, line contact %.2f %%",
                 sm.wildcards.cell, tug, float(r["sigma"]), float(r["sigma_fd"]),
                 float(r["sigma_seed_std"]), float(r["sigma_seed_std_expected"]),
                 float(r["mpm_sigma"]), 100 * float(r["limit_fraction"]),
                 100 * float(r["line_contact_fraction"]))
    if ds.attrs["record_warning"]:
        log.warning("%s: %s", sm.wildcards.cell, ds.attrs["record_warning"])
    log.info("%d records of %.1f s per setting (%s amplitudes, %.1f components per sway "
             "half-power bandwidth); %.2f s", ds.attrs["seeds_per_cell"], ds.attrs["duration_s"],
             ds.attrs["amplitudes"], ds.attrs["components_per_bandwidth"], time.perf_counter() - t0)
    write(ds, sm.output[0], dataset="timedomain_cell", created_by="rule timedomain_cell",
          config_sha256=config_hash(sm.config, "timedomain_cell", sm.wildcards.route))
