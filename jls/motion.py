"""Vessel motion dataset: the vessel's RAOs and the motions of the hinge and fairleads."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.coverage import describe
from jls.errors import InputError
from jls.vessel import fairlead_motion, hinge_excitation, load_rao, mirror_headings



def select_headings(rao: xr.Dataset, headings_deg, file=None) -> xr.Dataset:
    """The RAO at the requested headings [deg] (mirrored to 0-360 for a symmetric hull).

    Every heading must exist in the RAO file: interpolating between headings is not done
    silently.
    """
    wd = rao["wave_direction"].values
    if wd.max() <= np.pi + 1e-9 and any(h % 360 > 180 for h in headings_deg):
        rao = mirror_headings(rao)
        wd = rao["wave_direction"].values
    available = np.round(np.degrees(wd), 6) % 360
    picks = []
    for h in headings_deg:
        match = np.flatnonzero(np.isclose(available, float(h) % 360, atol=1e-4))
        if match.size == 0:
            raise InputError(f"heading {h} deg is not in the RAO file (available: "
                             f"{sorted(set(available.round(3).tolist()))})", file=file,
                             field="headings_deg", value=h)
        picks.append(int(match[0]))
    out = rao.isel(wave_direction=picks)
    return out.assign_coords(wave_direction=np.radians(np.asarray(headings_deg, float)))


def vessel_motion(vessel: dict, headings_deg, base_dir=".") -> xr.Dataset:
    """Dataset of the README (section Outputs): vessel RAOs, hinge and fairlead RAOs per heading."""
    path = Path(base_dir) / vessel["rao_file"]
    rao = load_rao(path, vessel.get("rao_format"))
    rao = select_headings(rao, sorted(float(h) for h in headings_deg), file=path)
    hinge_pos = tuple(vessel.get("hinge_m", (-215.263, 1.0, 99.998)))
    qb = hinge_excitation(rao, hinge_pos)
    fl = fairlead_motion(rao, hinge_pos, drop=vessel.get("fairlead_drop_m", 82.5),
                         half_span=vessel.get("fairlead_half_span_m", 37.5))
    heading = np.degrees(rao["wave_direction"].values)

    def relabel(da):
        return da.rename(wave_direction="heading").assign_coords(heading=heading)

    ds = xr.Dataset({
        "rao": relabel(rao["rao"]).rename(dof="vessel_dof"),
        "hinge": relabel(qb).rename({qb.dims[-1]: "dof"}),
        "fairlead": relabel(fl),
    })
    ds = ds.drop_vars([c for c in ds.coords if c not in ("omega", "heading", "vessel_dof", "dof",
                                                          "side", "axis")])
    ds["rao"].attrs.update(long_name="vessel RAO at its reference point", units="m/m or rad/m")
    ds["hinge"].attrs.update(long_name="hinge excitation [y_b, z_b, phi_b, psi_b]",
                             units="m/m or rad/m")
    ds["fairlead"].attrs.update(long_name="tugger fairlead translation", units="m/m")
    ds["omega"].attrs.update(long_name="wave angular frequency", units="rad/s")
    ds["heading"].attrs.update(long_name="relative wave heading (propagation relative to +x)",
                               units="degree")
    ds.attrs.update(
        reference_point_m=list(rao.attrs.get("reference_point_m", [0.0, 0.0, 0.0])),
        hinge_m=list(hinge_pos),
        fairlead_offset_m=[0.0, float(vessel.get("fairlead_half_span_m", 37.5)),
                           -float(vessel.get("fairlead_drop_m", 82.5))],
        heading_convention=rao.attrs.get("heading_convention", ""),
        phase_convention=rao.attrs.get("phase_convention", ""),
        vessel_source=path.name + (f" ({rao.attrs['source_format']})" if rao.attrs.get("source_format") else ""),
        vessel_description=vessel.get("description", rao.attrs.get("description", "")),
        extrapolation=describe(vessel.get("outside_rao_range")),
    )
    return ds
