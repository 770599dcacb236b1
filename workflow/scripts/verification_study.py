"""Snakemake adapter: the study's comparison -> results/<route>/verification_study.nc.

Inputs:   results/<route>/verification_study/<part>.nc (its parts, each a job of its own:
          verification_study_part.py)
Outputs:  results/<route>/verification_study.nc (the study's table 4.4 beside the ROM
          against the 6-DOF MoorDyn reference at its five sea states with the baseline
          rigging, and the linear range measured by stepping Hs; where MoorDyn cannot be
          imported, the study's table alone and the reason)
Settings: verification (the run settings), jacket and rigging, vessel, sea.gamma,
          assessment.exposure_h

Run by hand for debugging: python workflow/scripts/verification_study.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.verification_cell import study_from_parts
from jls.verify.study import LAYOUT

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("verification_study")
sm = snakemake
with workflow_step(sm.log[0], "verification_study") as log:
    ds = study_from_parts(sm.config, [read(f) for f in sm.input.parts])
    if "reason" in ds.attrs:
        log.warning("study comparison not run: %s", ds.attrs["reason"])
    else:
        log.info("study comparison: MPM ratios %s; linear range at Tz %g s: inside up to Hs %g m, "
                 "leaves at Hs %g m; %.1f s in its parts", ", ".join(f"{s} {float(r):.4f}" for s, r in
                                                        zip(ds["sea_state"].values, ds["mpm_ratio"].values)),
                 ds.attrs["linear_range_tz_s"], ds.attrs["linear_range_hs_inside_m"],
                 ds.attrs["linear_range_hs_leaves_m"], float(ds["wall_time"]))
    write(ds, sm.output[0], dataset=LAYOUT, created_by="rule verification_study",
          config_sha256=config_hash(sm.config, LAYOUT, sm.wildcards.route))
