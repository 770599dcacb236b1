"""Snakemake adapter: one part of the study's comparison -> results/<route>/verification_study/<part>.nc.

Inputs:   results/<route>/vessel_motion.nc
Outputs:  results/<route>/verification_study/<part>.nc (its records: the ROM against the
          6-DOF MoorDyn reference with the baseline rigging at some of the study's sea
          states, or some of the linear range's steps; where MoorDyn cannot be imported,
          no records and the reason)
Settings: verification (the run settings), jacket and rigging, vessel, sea.gamma,
          assessment.exposure_h

Run by hand for debugging: python workflow/scripts/verification_study_part.py part=NAME [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.verification_cell import study_part_dataset
from jls.verify.study import PART_LAYOUT

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("verification_study_part")
sm = snakemake
with workflow_step(sm.log[0], "verification_study_part") as log:
    ds = study_part_dataset(sm.config, read(sm.input.motion), sm.wildcards.part)
    if "reason" in ds.attrs:
        log.warning("study comparison, %s, not run: %s", sm.wildcards.part, ds.attrs["reason"])
    else:
        log.info("study comparison, %s: MPM ratios %s; %.1f s", sm.wildcards.part,
                 ", ".join(f"{r} (Hs {h:g} m, Tz {t:g} s) {m:.4f}" for r, h, t, m in
                           zip(ds["record"].values, ds["hs"].values, ds["tz"].values, ds["mpm_ratio"].values)),
                 float(ds["wall_time"]))
    write(ds, sm.output[0], dataset=PART_LAYOUT, created_by="rule verification_study_part",
          config_sha256=config_hash(sm.config, PART_LAYOUT, sm.wildcards.route))
