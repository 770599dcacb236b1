"""Snakemake adapter: frequency-domain workability -> the route's time-domain cells.

Inputs:   results/<route>/sea_states.nc, response.nc
Outputs:  results/<route>/timedomain/cells.json (name, candidate, heading, hs, tz, reasons)
Settings: assessment.criteria, assessment.winch_saturation, sea, tuggers, timedomain
          (cells, candidates, boundary_cells_per_leg, max_cells; grid_best: how many of a
          candidate grid's candidates, the best, send their boundary cells)

Run by hand for debugging: python workflow/scripts/timedomain_cells.py [route=NAME] [--configfile FILE ...]
"""

import json

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.io.netcdf import read
from jls.io.provenance import workflow_step
from jls.stages.timedomain_cell import route_cells

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("timedomain_cells")
sm = snakemake
with workflow_step(sm.log[0], "timedomain_cells") as log:
    p = sm.params
    cfg = {"assessment": {"criteria": p.criteria, "winch_saturation": p.winch_saturation},
           "sea": p.sea, "tuggers": p.tuggers, "timedomain": p.choice}
    cells = route_cells(read(sm.input.sea), read(sm.input.response), cfg, model_legs=p.model_legs)
    for c in cells:
        log.info("cell %s: %s", c["name"], "; ".join(c["reasons"]))
    with open(sm.output[0], "w") as fh:
        json.dump(cells, fh, indent=1)
    log.info("%d time-domain cells", len(cells))
