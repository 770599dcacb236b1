"""Snakemake adapter: plant + vessel motion -> unit-Hs statistics of one leg's cells."""

import time

from jls import registry
from jls.netcdf import read, write
from jls.provenance import workflow_step
from jls.unit_response import response_dataset

sm = snakemake  # noqa: F821 - injected by Snakemake
with workflow_step(sm.log[0], "response") as log:
    cells = sm.params.cells
    a, r = sm.params.assessment, sm.params.response
    t0 = time.perf_counter()
    plant, motion = read(sm.input.plant), read(sm.input.motion)
    log.info("leg %s: %d Tz values, headings %s, %d candidates, tuggers %s", sm.wildcards.leg,
             len(cells["tz"]), cells["headings_deg"], plant.sizes["candidate"], list(sm.params.tuggers))
    ds = response_dataset(plant, motion, cells["tz"], cells["headings_deg"], sm.params.tuggers,
                          gamma=cells["gamma"], exposure_h=a["exposure_h"],
                          cycles=a["mpm_cycles"], omega_step=r["omega_step_rad_s"], outside_policy=sm.params.outside,
                          source="config vessel.rao_file")
    log.info("%d frequencies; computed in %.2f s", ds.sizes["omega"], time.perf_counter() - t0)
    write(ds, sm.output[0], config_sha256=registry.config_hash(sm.config, "response", sm.wildcards.route), created_by="rule response")
    log.info("wrote %s", sm.output[0])
