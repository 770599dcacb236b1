"""Snakemake adapter: hull description in the config -> the vessel's RAO file (Capytaine)."""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)
import numpy as np

from jls.io.provenance import workflow_step
from jls.vessel import bem
from jls.vessel.rao import save_rao

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("vessel_bem")
sm = snakemake
with workflow_step(sm.log[0], "vessel_bem") as log:
    b = sm.params.bem
    w = b["omega_rad_s"]
    omega = np.linspace(w["min"], w["max"], w["n"])
    headings = np.radians(np.asarray(b["headings_deg"], float))
    common = dict(radii=tuple(b["radii_of_gyration_m"]), roll_damping_ratio=b["roll_damping_ratio"],
                  omega=omega, headings=headings)
    if "box" in b:
        box = b["box"]
        log.info("box %s x %s x %s m, KG %s m: %d frequencies, %d headings", box["length_m"],
                 box["beam_m"], box["draught_m"], box["kg_m"], omega.size, headings.size)
        ds = bem.compute_box_raos(box["length_m"], box["beam_m"], box["draught_m"], box["kg_m"],
                                  panel_size=b["panel_size_m"], **common)
    else:
        m = b["mesh"]
        log.info("mesh %s, %s t: %d frequencies, %d headings", m["file"], m["mass_t"], omega.size,
                 headings.size)
        ds = bem.compute_mesh_raos(sm.input.mesh[0], m["mass_t"], tuple(m["center_of_mass_m"]),
                                   symmetry=m.get("symmetry"), **common)
    save_rao(ds, sm.output[0])
    log.info("wrote %s", sm.output[0])
