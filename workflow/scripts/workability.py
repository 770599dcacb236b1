"""Snakemake adapter: sea states + unit-Hs statistics (+ time-domain cells) ->
results/<route>/workability.nc.

Inputs:   results/<route>/sea_states.nc, response.nc, operability.nc, response_variants.nc,
          and the route's time-domain cells results/<route>/timedomain/<cell>.nc (none when
          no cell runs), measured_response.nc when a leg is given by spectra
          and the assessed plant (the verification cells' candidates)
Outputs:  results/<route>/workability.nc; results/<route>/verification/cells.json, the route's
          verification cells (name, candidate, tugger, heading, hs, tz, roles, reasons)
Settings: assessment (criteria, winch_saturation, max_saturation_fraction), sea (hs_in_bin, steepness rule,
          gamma), tuggers (winch capacities), weather_windows.tz_outside (hours of spectra legs);
          the inputs' warnings (attribute warnings, for page 1); verification (enabled,
          combinations, boundary_cells, design_corner, max_cells); grid_best (how many of a
          candidate grid's candidates sent their boundary cells: the others are excluded
          from the recommendation, jls.assessment.recommendation.grid_without_timedomain)

Run by hand for debugging: python workflow/scripts/workability.py [route=NAME] [--configfile FILE ...]
"""

import json
from pathlib import Path

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.atomic import write_atomically
from jls.io.netcdf import add_warnings, read, warnings_of, write
from jls.io.provenance import workflow_step
from jls.names import TIME_DOMAIN
from jls.stages.verification_cell import choose_cells, refused_legs
from jls.stages.workability import workability

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("workability")
sm = snakemake
LOGGED = 48                    # combinations logged one by one
with workflow_step(sm.log[0], "workability") as log:
    p = sm.params
    cfg = {"assessment": {"criteria": p.criteria, "winch_saturation": p.winch_saturation,
                          "max_saturation_fraction": p.max_saturation_fraction},
           "sea": p.sea, "tuggers": p.tuggers, "recommendation": p.recommendation,
           "operation": p.operation, "weather_windows": {"tz_outside": p.tz_outside}}
    cells = [read(path) for path in sm.input.timedomain]
    measured = read(sm.input.measured[0]) if sm.input.measured else None
    sea = read(sm.input.sea)
    plant = read(sm.input.plant)
    ds = workability(sea, read(sm.input.response), read(sm.input.curve),
                     read(sm.input.variants), cells, cfg, sm.wildcards.route, read(sm.input.voyage),
                     measured, plant, plan=read(sm.input.plan))
    # the inputs' warnings (configuration, RAO file, tables) before the assessment's own
    own = warnings_of(ds)
    # the candidate-grid rule of the time-domain cells, for the recommendation's exclusions
    ds.attrs["timedomain_grid_best"] = int(p.grid_best)
    ds.attrs["warnings"] = ""
    add_warnings(ds, list(p.input_warnings) + own)
    log.info("winch saturation (%s): %d cells flagged; %d time-domain cells replace %d verdicts",
             p.winch_saturation, int(ds["winch_saturates"].sum()), len(cells),
             int((ds["verdict_source"] == TIME_DOMAIN).sum()))
    share, lo, hi = (ds[f"workability_route{e}"].transpose("candidate", "tugger").values
                     for e in ("", "_min", "_max"))
    combos = [(i, j) for i in range(share.shape[0]) for j in range(share.shape[1])]
    for i, j in combos[:LOGGED]:         # a large grid's every line would cost more than the stage
        log.info("candidate %s, tugger %s: route workability %.1f %% (band %.1f-%.1f %%)",
                 ds["candidate"].values[i], ds["tugger"].values[j], 100 * share[i, j],
                 100 * lo[i, j], 100 * hi[i, j])
    if len(combos) > LOGGED:
        log.info("... and %d more combinations (workability.nc)", len(combos) - LOGGED)
    # the verification cells, from this workability (jls.stages.verification_cell)
    chosen = choose_cells(ds, sea, plant, {k: float(v) for k, v in p.verification_tuggers.items()},
                          {"verification": p.verification, "sea": {"hs_in_bin": p.sea["hs_in_bin"]}},
                          refused=list(p.sea_models))
    ds.attrs["verification_refused_legs"] = refused_legs(dict(p.sea_models))
    if ds.attrs["verification_refused_legs"]:
        log.info("verification: %s", ds.attrs["verification_refused_legs"])
    for c in chosen:
        log.info("verification cell %s (%s): %s", c["name"], ", ".join(c["roles"]), "; ".join(c["reasons"]))
    log.info("%d verification cells", len(chosen))
    write(ds, sm.output.workability, created_by="rule workability", dataset="workability",
          config_sha256=config_hash(sm.config, "workability", sm.wildcards.route))
    write_atomically(sm.output.verification_cells,
                     lambda tmp: Path(tmp).write_text(json.dumps(chosen, indent=1)), suffix=".json.tmp")
