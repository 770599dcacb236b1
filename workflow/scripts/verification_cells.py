"""Snakemake adapter: workability and the assessed plant -> the route's verification cells.

Inputs:   results/<route>/sea_states.nc, workability.nc and the assessed plant
Outputs:  results/<route>/verification/cells.json (name, candidate, tugger, heading, hs, tz,
          roles, reasons)
Settings: verification (enabled, combinations, boundary_cells, design_corner, max_cells),
          tuggers, sea.hs_in_bin

Run by hand for debugging: python workflow/scripts/verification_cells.py [route=NAME] [--configfile FILE ...]
"""

import json

from jls.io.netcdf import read
from jls.io.provenance import workflow_step
from jls.stages.verification_cell import choose_cells

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("verification_cells")
sm = snakemake
with workflow_step(sm.log[0], "verification_cells") as log:
    p = sm.params
    cfg = {"verification": p.choice, "sea": {"hs_in_bin": p.hs_in_bin}}
    cells = choose_cells(read(sm.input.workability), read(sm.input.sea), read(sm.input.plant),
                         {k: float(v) for k, v in p.tuggers.items()}, cfg)
    for c in cells:
        log.info("cell %s (%s): %s", c["name"], ", ".join(c["roles"]), "; ".join(c["reasons"]))
    with open(sm.output[0], "w") as fh:
        json.dump(cells, fh, indent=1)
    log.info("%d verification cells", len(cells))
