"""Snakemake adapter: one verification cell -> results/<route>/verification/<cell>.nc.

Inputs:   results/<route>/vessel_motion.nc; the assessed plant when the cell's candidate is
          not configured (the screening's optimised)
Outputs:  results/<route>/verification/<cell>.nc (the ROM against the 6-DOF MoorDyn
          reference; where MoorDyn cannot be imported, a dataset saying so)
Settings: the cell (from its name: candidate, tugger, heading, Hs, Tz), verification (the
          run settings), jacket and rigging, tuggers, vessel, sea.gamma, assessment.exposure_h

Run by hand for debugging: python workflow/scripts/verification_cell.py vcell=NAME [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.verification_cell import cell_dataset
from jls.verify.cell import LAYOUT

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("verification_cell")
sm = snakemake
with workflow_step(sm.log[0], "verification_cell") as log:
    plant = read(sm.input.plant[0]) if sm.input.plant else None
    ds = cell_dataset(sm.config, read(sm.input.motion), dict(sm.params.cell), plant)
    if ds.attrs["status"] != "verified":
        log.warning("%s not verified: %s", sm.wildcards.vcell, ds.attrs["reason"])
    else:
        log.info("%s: ROM over reference, sigma %.4f, MPM %.4f (tolerance %g: %s; %s); "
                 "%.0f s of record, %.1f s", sm.wildcards.vcell, float(ds["sigma_ratio"]),
                 float(ds["mpm_ratio"]), float(ds["tolerance"]),
                 "within" if bool(ds["within_tolerance"]) else "outside",
                 "conservative" if bool(ds["conservative"]) else "not conservative",
                 ds.attrs["duration_s"], float(ds["wall_time"]))
    write(ds, sm.output[0], dataset=LAYOUT, created_by="rule verification_cell",
          config_sha256=config_hash(sm.config, LAYOUT, sm.wildcards.route))
