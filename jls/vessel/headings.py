"""The vessel's RAO headings: the headings a route needs selected from an RAO dataset
(exact, mirrored for a symmetric hull, or interpolated when configured), and the RAO
file of a vessel block read with its declared options.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.vessel.files import load_rao, rao_format
from jls.vessel.rao import mirror_headings


def select_headings(rao: xr.Dataset, headings_deg, file=None, interpolation="none",
                    tolerance_deg=0.0) -> xr.Dataset:
    """The RAO at the requested headings [deg] (mirrored to 0-360 for a symmetric hull).

    A heading not in the RAO file (within 1e-4 deg) is, by ``interpolation``:

    * ``none``: an error (interpolating between headings is not done silently);
    * ``nearest``: the nearest RAO heading, if it lies within ``tolerance_deg``;
    * ``linear``: the RAO interpolated linearly in complex value between the two
      neighbouring RAO headings (circularly, so 350 deg lies between 345 and 0), when
      they are at most 180 deg apart (a heading outside the RAO's range is an error).
    """
    if interpolation not in ("none", "nearest", "linear"):
        raise InputError("heading_interpolation must be none, nearest or linear",
                         field="vessel.heading_interpolation", value=interpolation)
    wd = rao["wave_direction"].values
    if wd.max() <= np.pi + 1e-9 and any(h % 360 > 180 for h in headings_deg):
        rao = mirror_headings(rao)
        wd = rao["wave_direction"].values
    available = np.round(np.degrees(wd), 6) % 360
    weights = np.zeros((len(headings_deg), available.size))
    for k, h in enumerate(headings_deg):
        h = float(h) % 360
        gap = np.abs((available - h + 180.0) % 360.0 - 180.0)      # circular distance
        i = int(np.argmin(gap))
        if gap[i] <= 1e-4 or (interpolation == "nearest" and gap[i] <= tolerance_deg):
            weights[k, i] = 1.0
        elif interpolation == "linear" and available.size > 1 and _span(available, h) <= 180.0:
            lo, hi = _neighbours(available, h)
            w = ((h - available[lo]) % 360.0) / _span(available, h)
            weights[k, lo], weights[k, hi] = 1.0 - w, w
        else:
            hint = ("" if interpolation != "nearest" else
                    f"; the nearest, {available[i]:g} deg, is beyond heading_tolerance_deg "
                    f"{tolerance_deg:g}")
            raise InputError(f"heading {headings_deg[k]} deg is not in the RAO file (available: "
                             f"{sorted(set(available.round(3).tolist()))}){hint}; "
                             "vessel.heading_interpolation can snap or interpolate",
                             file=file, field="headings_deg", value=headings_deg[k])
    out = rao.isel(wave_direction=np.argmax(weights, axis=1))
    values = np.einsum("owd,hw->ohd", rao["rao"].transpose("omega", "wave_direction", "dof").values,
                       weights)
    out["rao"] = out["rao"].transpose("omega", "wave_direction", "dof").copy(data=values)
    return out.assign_coords(wave_direction=np.radians(np.asarray(headings_deg, float)))


def _span(available, h):
    """Angle between the RAO headings either side of ``h`` [deg]; more than 180 means
    ``h`` lies outside the headings the RAO covers (no extrapolation)."""
    lo, hi = _neighbours(available, h)
    return (available[hi] - available[lo]) % 360.0


def _neighbours(available, h):
    """Indices of the RAO headings either side of ``h`` [deg], circularly."""
    below = (h - available) % 360.0
    above = (available - h) % 360.0
    return int(np.argmin(below)), int(np.argmin(above))


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


def _interpolation_text(vessel: dict) -> str:
    mode = vessel["heading_interpolation"]
    if mode == "nearest":
        return f"nearest: the nearest RAO heading within {vessel['heading_tolerance_deg']:g} deg"
    if mode == "linear":
        return "linear: complex RAO interpolated between the two neighbouring RAO headings"
    return "none: every heading is one of the RAO file's"


def read_vessel_rao(vessel: dict, path, config_source: str = "the configuration",
                    g: float | None = None) -> xr.Dataset:
    """The vessel's RAO file as the configuration describes it.

    A WAMIT ``.4`` file needs its length scale ULEN stated (``vessel.wamit_ulen_m``):
    WAMIT writes rotations per A/ULEN, so a wrong ULEN scales every rotation silently.
    The file's phase convention is checked by the long-wave physics, and what it states
    about its reference point (and g) against the configuration
    (:mod:`jls.vessel.phase_checks`, :mod:`jls.vessel.stated_reference`;
    ``config_source`` names the configuration file in those errors, ``g`` its g_m_per_s2).
    """
    from jls.vessel.phase_checks import check_phase_convention
    from jls.vessel.stated_reference import check_stated_reference
    fmt = vessel.get("rao_format")        # absent: inferred from the file
    kind = rao_format(path, fmt)
    for key in ("orcaflex_vessel_type", "orcaflex_draught"):
        if key in vessel and kind != "orcaflex":
            raise InputError(f"{key} applies to OrcaFlex vessel-type files only", file=path,
                             field=f"vessel.{key}", value=vessel[key])
    conventions = vessel.get("rao_conventions")
    if kind == "orcaflex":
        return load_rao(path, fmt, vessel_type=vessel.get("orcaflex_vessel_type"),
                        draught=vessel.get("orcaflex_draught"), conventions=conventions)
    if kind == "aqwa_lis":
        return load_rao(path, fmt, conventions=conventions)
    if conventions is not None:
        raise InputError("rao_conventions is read for OrcaFlex and AQWA files (the other "
                         "formats fix or declare their conventions: docs/vessel.md)", file=path,
                         field="vessel.rao_conventions", value=conventions)
    if kind == "wamit4":
        if "wamit_ulen_m" not in vessel:
            raise InputError("a WAMIT .4 file needs the length scale ULEN of its run "
                             "(rotations are written per A/ULEN): set vessel.wamit_ulen_m",
                             file=path, field="vessel.wamit_ulen_m")
        rao = load_rao(path, fmt, ulen=float(vessel["wamit_ulen_m"]))
    elif "wamit_ulen_m" in vessel:
        raise InputError("wamit_ulen_m applies to WAMIT .4 files only", file=path,
                         field="vessel.wamit_ulen_m", value=vessel["wamit_ulen_m"])
    else:
        rao = load_rao(path, fmt)
    check_phase_convention(rao, file=path)
    check_stated_reference(rao, vessel, file=path, config_source=config_source, g=g,
                           g_source=config_source)
    return rao


