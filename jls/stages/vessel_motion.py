"""Vessel motion dataset: the vessel's RAOs and the motions of the hinge and fairleads."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import registry
from jls.response.coverage import describe
from jls.vessel.headings import _interpolation_text, read_vessel_rao, select_headings
from jls.vessel.transfer import carry


def vessel_data(rao: xr.Dataset, vessel: dict) -> dict:
    """Where the vessel's motions come from, for page 1 of the report: attributes
    ``vessel_data`` (``representative``: a stand-in hull whose file says so, as the
    shipped default; ``computed``: RAOs the pipeline computed from the configuration's
    hull, ``vessel.bem``; ``own``: the vessel's own RAO file), ``vessel_sway_against_study``
    (for a representative hull, how its relative sway compares with the study's) and
    ``vessel_statement``, the sentence page 1 prints."""
    if str(rao.attrs.get("vessel_data", "")) == "representative":
        against = str(rao.attrs.get("sway_against_study", ""))
        return {"vessel_data": "representative", "vessel_sway_against_study": against,
                "vessel_statement": "The vessel motions are those of a representative heavy-lift "
                                    "hull, not the vessel's own RAOs" + (f": {against}." if against else ".")}
    if "bem" in vessel:
        return {"vessel_data": "computed", "vessel_sway_against_study": "",
                "vessel_statement": "The vessel motions are computed with Capytaine from the hull "
                                    "described in the configuration, not the vessel's own RAOs."}
    return {"vessel_data": "own", "vessel_sway_against_study": "",
            "vessel_statement": "The vessel motions are the vessel's own RAOs (the file is named in "
                                "the provenance chapter)."}


def vessel_motion(vessel: dict, headings_deg, base_dir=".") -> xr.Dataset:
    """Dataset of docs/reference/outputs.md: vessel RAOs, hinge and fairlead RAOs per heading.

    ``vessel``: the validated vessel block (``rao_reference_point_height_m`` filled in by
    :func:`jls.config.loader.hinge_height`)."""
    path = Path(base_dir) / vessel["rao_file"]
    if "rao_reference_point_height_m" not in vessel:
        raise InputError("required key is missing: the RAO reference point's height above the "
                         "waterline (validate the configuration: jls.config.loader)",
                         field="vessel.rao_reference_point_height_m")
    rao = read_vessel_rao(vessel, path)
    headings = sorted(float(h) for h in headings_deg)
    rao = select_headings(rao, headings, file=path, interpolation=vessel["heading_interpolation"],
                          tolerance_deg=vessel["heading_tolerance_deg"])
    # lever arm of the hinge from the point the RAOs refer to
    lever = np.subtract(vessel["hinge_m"], vessel["rao_reference_point_m"])
    offset = [0.0, float(vessel["fairlead_half_span_m"]), -float(vessel["fairlead_drop_m"])]
    qb, fl = carry(rao, tuple(lever), offset)            # the one transfer, on the RAO's grid
    heading = np.asarray(headings, float)        # as given: no radian round trip

    def relabel(da):
        return da.rename(wave_direction="heading").assign_coords(heading=heading)

    ds = xr.Dataset({
        "rao": relabel(rao["rao"]).rename(dof="vessel_dof"),
        "hinge": relabel(qb).rename({qb.dims[-1]: "dof"}),
        "fairlead": relabel(fl),
    })
    ds = ds.drop_vars([c for c in ds.coords if c not in ("omega", "heading", "vessel_dof", "dof",
                                                          "side", "axis")])
    ds = ds.assign_coords(
        vessel_dof_units=("vessel_dof", ["m m-1"] * 3 + ["rad m-1"] * 3),
        dof_units=("dof", ["m m-1", "m m-1", "rad m-1", "rad m-1"]))
    registry.annotate(ds, "vessel_motion")
    ref_height = float(vessel["rao_reference_point_height_m"])
    ds.attrs.update(
        reference_point_m=list(rao.attrs.get("reference_point_m", [0.0, 0.0, 0.0])),
        hinge_m=[float(v) for v in lever],
        hinge_lever_arm_m=[float(v) for v in lever],
        rao_reference_point_m=[float(v) for v in vessel["rao_reference_point_m"]],
        rao_reference_point_height_m=ref_height,
        hinge_height_above_water_m=float(lever[2]) + ref_height,
        fairlead_offset_m=offset,
        heading_convention=rao.attrs.get("heading_convention", ""),
        phase_convention=rao.attrs.get("phase_convention", ""),
        vessel_source=path.name + (f" ({rao.attrs['source_format']})" if rao.attrs.get("source_format") else ""),
        vessel_description=vessel.get("description", rao.attrs.get("description", "")),
        heading_interpolation=_interpolation_text(vessel),
        extrapolation=describe(vessel.get("outside_rao_range")),
        **vessel_data(rao, vessel),
    )
    return ds
