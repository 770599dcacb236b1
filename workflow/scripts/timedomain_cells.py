"""Snakemake adapter: frequency-domain workability -> the route's time-domain cells.

Inputs:   results/<route>/sea_states.nc, response.nc
Outputs:  results/<route>/timedomain/cells.json (name, candidate, heading, hs, tz, reasons)
Settings: assessment.criteria, assessment.winch_saturation, sea, tuggers, timedomain
          (cells, candidates, boundary_cells_per_leg)

Run by hand for debugging: python workflow/scripts/timedomain_cells.py [route=NAME] [--configfile FILE ...]
"""

import json

from jls.assessment.winch_limits import apply_winch_limits
from jls.assessment.workability import assess, assessed_hs
from jls.config.builders import tuggers_from_config
from jls.io.netcdf import read
from jls.io.provenance import workflow_step
from jls.stages.timedomain_cell import choose_cells

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("timedomain_cells")
sm = snakemake
with workflow_step(sm.log[0], "timedomain_cells") as log:
    sea, response = read(sm.input.sea), read(sm.input.response)
    p = sm.params
    if p.winch_saturation != "timedomain":
        # the boundary cells are chosen per candidate from that candidate's own
        # utilisation: only the boundary candidates need assessing (a large grid's other
        # candidates cost the assessment of all of them, for no cell), unless every
        # candidate's saturating cells run in the time domain
        wanted = set(p.choice["boundary_candidates"])
        response = response.sel(candidate=[c for c in response["candidate"].values if c in wanted])
    work = assess(response, sea, p.criteria, hs_in_bin=p.sea["hs_in_bin"],
                  steepness_rule=p.sea["steepness_rule"], gamma=p.sea["gamma"])
    hs = assessed_hs(sea, p.sea["hs_in_bin"])
    work = apply_winch_limits(work, response, sea, tuggers_from_config({"tuggers": p.tuggers}), hs,
                              p.winch_saturation)
    cfg = {"timedomain": p.choice, "assessment": {"winch_saturation": p.winch_saturation}}
    cells = choose_cells(work, sea, hs, cfg)
    for c in cells:
        log.info("cell %s: %s", c["name"], "; ".join(c["reasons"]))
    with open(sm.output[0], "w") as fh:
        json.dump(cells, fh, indent=1)
    log.info("%d time-domain cells", len(cells))
