"""Vessel motion dataset: the vessel's RAOs and the motions of the hinge and fairleads."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls import registry
from jls.coverage import describe
from jls.errors import InputError
from jls.vessel import fairlead_motion, hinge_excitation, load_rao, mirror_headings
from jls.vessel.rao import rao_format


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


def select(ds: xr.Dataset, headings_deg, dim: str = "heading") -> xr.Dataset:
    """``ds`` at the given headings [deg], matched within 1e-6 deg (headings are kept in
    degrees as the configuration gives them; the tolerance absorbs a float round trip)."""
    want = np.asarray([float(h) for h in headings_deg])
    have = ds[dim].values
    idx = [int(np.argmin(np.abs(have - h))) for h in want]
    bad = [float(h) for h, i in zip(want, idx) if abs(have[i] - h) > 1e-6]
    if bad:
        raise InputError(f"heading(s) {bad} deg are not in the vessel motion (available: "
                         f"{have.tolist()})", field=dim, value=bad)
    return ds.isel({dim: idx}).assign_coords({dim: want})


def read_vessel_rao(vessel: dict, path) -> xr.Dataset:
    """The vessel's RAO file as the configuration describes it.

    A WAMIT ``.4`` file needs its length scale ULEN stated (``vessel.wamit_ulen_m``):
    WAMIT writes rotations per A/ULEN, so a wrong ULEN scales every rotation silently.
    """
    fmt = vessel.get("rao_format")        # absent: inferred from the file
    if rao_format(path, fmt) == "wamit4":
        if "wamit_ulen_m" not in vessel:
            raise InputError("a WAMIT .4 file needs the length scale ULEN of its run "
                             "(rotations are written per A/ULEN): set vessel.wamit_ulen_m",
                             file=path, field="vessel.wamit_ulen_m")
        return load_rao(path, fmt, ulen=float(vessel["wamit_ulen_m"]))
    if "wamit_ulen_m" in vessel:
        raise InputError("wamit_ulen_m applies to WAMIT .4 files only", file=path,
                         field="vessel.wamit_ulen_m", value=vessel["wamit_ulen_m"])
    return load_rao(path, fmt)


def vessel_motion(vessel: dict, headings_deg, base_dir=".") -> xr.Dataset:
    """Dataset of the README (section Outputs): vessel RAOs, hinge and fairlead RAOs per heading."""
    path = Path(base_dir) / vessel["rao_file"]
    rao = read_vessel_rao(vessel, path)
    headings = sorted(float(h) for h in headings_deg)
    rao = select_headings(rao, headings, file=path)
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
        extrapolation=describe(vessel.get("outside_rao_range")),
    )
    return ds
