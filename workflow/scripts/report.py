"""Snakemake adapter: the route's datasets -> reports/<route>.pdf.

Inputs:   the route's datasets (weather_windows.nc when a leg has an hourly record,
          measured_response.nc when a leg is given by spectra, screening.nc
          when the screening is on), leg tables and RAO file, time-domain cells (and the
          list of them), tugger studies, verification cells (and the list of them; none when
          verification.enabled is false), voyage.nc, voyage_plan.nc
Outputs:  reports/<route>.pdf
Settings: the whole configuration (provenance, per-dataset hashes), the route's description
Threads:  the figures are drawn by that many processes (the report is the same for any number)

Run by hand for debugging: python workflow/scripts/report.py [route=NAME] [--configfile FILE ...]
"""

import json
from pathlib import Path

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import read
from jls.io.provenance import provenance, workflow_step
from jls.report.document import render_report

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("report")
sm = snakemake
with workflow_step(sm.log[0], "report") as log:
    route = sm.wildcards.route
    data = {name: read(getattr(sm.input, key)) for name, key in
            [("sea_states", "sea"), ("vessel_motion", "motion"), ("plant", "plant"),
             ("response", "response"), ("workability", "workability")]}
    inputs = {f"leg {Path(p).stem}": p for p in sm.input.legs}
    inputs["vessel RAO"] = sm.input.rao
    prov = provenance(sm.config, inputs)
    prov["config_sha256_datasets"] = {name: config_hash(sm.config, name, route)
                                      for name in data}
    prov["vessel_source"] = data["vessel_motion"].attrs.get("vessel_source", "")
    prov["vessel_description"] = data["vessel_motion"].attrs.get("vessel_description", "")
    prov["document"] = sm.config["document"]
    prov["route_description"] = sm.config["routes"][route].get("description", "")
    windows = read(sm.input.windows[0]) if sm.input.windows else None
    if windows is not None:
        prov["config_sha256_datasets"]["weather_windows"] = config_hash(sm.config, "weather_windows", route)
    measured = read(sm.input.measured[0]) if sm.input.measured else None
    if measured is not None:
        prov["config_sha256_datasets"]["measured_response"] = config_hash(sm.config, "measured_response", route)
    screening = read(sm.input.screening[0]) if sm.input.screening else None
    if screening is not None:
        prov["config_sha256_datasets"]["screening"] = config_hash(sm.config, "screening", route)
    voyage = read(sm.input.voyage)
    plan = read(sm.input.plan)
    for name in ("voyage", "tugger_studies", "voyage_plan"):
        prov["config_sha256_datasets"][name] = config_hash(sm.config, name, route)
    with open(sm.input.cells) as fh:
        td_cells = json.load(fh)
    verification = [read(p) for p in sm.input.verification]
    if sm.input.verification_cells:            # why each cell was chosen, for the chapter
        with open(sm.input.verification_cells[0]) as fh:
            chosen = {c["name"]: c for c in json.load(fh)}
        for ds in verification:
            c = chosen.get(str(ds.attrs["cell"]), {})
            ds.attrs.update(roles="; ".join(c.get("roles", [])), reasons="; ".join(c.get("reasons", [])))
    log.info("%d verification cells: %s", len(verification),
             ", ".join(f"{ds.attrs['cell']} ({ds.attrs['status']})" for ds in verification) or "none")
    render_report(sm.output[0], route=route, provenance=prov, weather_windows=windows, measured=measured,
                  screening=screening, **data,
                  timedomain=[read(p) for p in sm.input.timedomain], timedomain_cells=td_cells,
                  tugger_studies=read(sm.input.studies), verification=verification,
                  verification_study=(read(sm.input.verification_study[0])
                                      if sm.input.verification_study else None),
                  verification_wires=[read(p) for p in sm.input.verification_wires],
                  voyage=voyage, voyage_plan=plan, workers=sm.threads)
    log.info("wrote %s", sm.output[0])
