"""Vessel motion dataset: the vessel's RAOs and the motions of the hinge and fairleads."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.io import registry
from jls.response.coverage import describe
from jls.vessel.headings import _interpolation_text, read_vessel_rao, select_headings
from jls.vessel.transfer import fairlead_motion, hinge_excitation


def vessel_motion(vessel: dict, headings_deg, base_dir=".") -> xr.Dataset:
    """Dataset of the README (section Outputs): vessel RAOs, hinge and fairlead RAOs per heading."""
    path = Path(base_dir) / vessel["rao_file"]
    rao = read_vessel_rao(vessel, path)
    headings = sorted(float(h) for h in headings_deg)
    rao = select_headings(rao, headings, file=path, interpolation=vessel["heading_interpolation"],
                          tolerance_deg=vessel["heading_tolerance_deg"])
    # lever arm of the hinge from the point the RAOs refer to
    hinge_pos = tuple(np.subtract(vessel["hinge_m"], vessel["rao_reference_point_m"]))
    qb = hinge_excitation(rao, hinge_pos)
    fl = fairlead_motion(rao, hinge_pos, drop=vessel["fairlead_drop_m"],
                         half_span=vessel["fairlead_half_span_m"])
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
    ds.attrs.update(
        reference_point_m=list(rao.attrs.get("reference_point_m", [0.0, 0.0, 0.0])),
        hinge_m=list(hinge_pos),
        rao_reference_point_m=[float(v) for v in vessel["rao_reference_point_m"]],
        fairlead_offset_m=[0.0, float(vessel["fairlead_half_span_m"]),
                           -float(vessel["fairlead_drop_m"])],
        heading_convention=rao.attrs.get("heading_convention", ""),
        phase_convention=rao.attrs.get("phase_convention", ""),
        vessel_source=path.name + (f" ({rao.attrs['source_format']})" if rao.attrs.get("source_format") else ""),
        vessel_description=vessel.get("description", rao.attrs.get("description", "")),
        heading_interpolation=_interpolation_text(vessel),
        extrapolation=describe(vessel.get("outside_rao_range")),
    )
    return ds
