"""Snakemake adapter: the wire check of one cell -> results/<route>/verification/wires/<cell>.nc.

Inputs:   results/<route>/vessel_motion.nc; the assessed plant when the cell's candidate is
          not configured (the screening's optimised)
Outputs:  results/<route>/verification/wires/<cell>.nc (the one-segment reference against
          hoist wires of several segments with their mass and axial damping, same record;
          where MoorDyn cannot be imported, a dataset saying so)
Settings: the cell (from its name), verification (run settings and verification.wires),
          jacket and rigging, tuggers, vessel, sea.gamma

Run by hand for debugging: python workflow/scripts/verification_wires.py vcell=NAME [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.verification_cell import wires_dataset
from jls.verify.wires import LAYOUT

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("verification_wires")
sm = snakemake
with workflow_step(sm.log[0], "verification_wires") as log:
    plant = read(sm.input.plant[0]) if sm.input.plant else None
    ds = wires_dataset(sm.config, read(sm.input.motion), dict(sm.params.cell), plant)
    if "reason" in ds.attrs:
        log.warning("%s wire check not run: %s", sm.wildcards.vcell, ds.attrs["reason"])
    else:
        log.info("%s: %d segments, %.3f t/m: sigma over the one-segment reference's %.4f (r %.5f), "
                 "static tensions within %.3f %% of the ROM's; %.1f s (the multi-segment reference "
                 "%.1f s, the one-segment %.2f s)", sm.wildcards.vcell, ds.attrs["segments"],
                 ds.attrs["wire_mass_t_per_m"], float(ds["sigma_ratio_segments"]), float(ds["r_segments"]),
                 100 * float(ds["tension_ratio_max"]), float(ds["wall_time"]),
                 float(ds["wall_time_segments"]), float(ds["wall_time_one_segment"]))
    write(ds, sm.output[0], dataset=LAYOUT, created_by="rule verification_wires",
          config_sha256=config_hash(sm.config, LAYOUT, sm.wildcards.route))
