"""A route leg's wave statistics as read: its scatter table or its binned hourly record
(hindcast, metocean parameters or spectra: :mod:`jls.sea.scatter`, :mod:`jls.sea.records`), checked for plausible Hs and Tz,
direction sectors turned into relative headings when the table resolves them, and steep
cells flagged.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_TABLE_BYTES, regular_file
from jls.sea import headings as headings_mod
from jls.sea.hindcast import bin_hindcast
from jls.sea.records import leg_kind, leg_series, leg_source, sea_model
from jls.sea.scatter import read_scatter
from jls.sea.steepness import BREAKING_STEEPNESS, flag_steep


def read_table(leg: dict, base_dir, gamma: float) -> xr.Dataset:
    """The leg's table as read (dims hs, tz and, when the table resolves it, direction):
    its scatter CSV, or its hourly record (:func:`jls.sea.records.leg_series`) binned
    with the leg's edges. ``gamma``: the JONSWAP gamma a declared period other than Tz
    is converted with."""
    path = Path(base_dir) / leg_source(leg)
    kind = leg_kind(leg)
    sea_model(leg)                                   # the declared sea model fits the file
    if kind == "scatter":
        regular_file(path, "file", MAX_TABLE_BYTES, field=f"legs[{leg['name']}].scatter")
        ds = read_scatter(path, **{k: leg[k] for k in ("layout", "bins", "values", "period") if k in leg})
        if "period" in leg and leg["period"] == "tp":
            ds = tp_table_as_tz(ds, gamma)
    else:
        h = leg[kind]
        try:
            series = leg_series(leg, base_dir, gamma=gamma)
        except InputError as exc:        # the data file's line, and the key that names it
            raise InputError(_given_by(exc.message, leg, kind), file=exc.file, field=exc.field,
                             value=exc.value) from None
        if kind == "spectra":
            params = parameters_file(leg, base_dir)
            if params is not None:
                _check_companion(leg, series, path, params)
        if h.get("dir_edges_deg") is not None and "direction" not in series:
            raise InputError(_no_direction(leg, kind, path), file=path,
                             field=f"legs[{leg['name']}].{kind}.dir_edges_deg", value=h["dir_edges_deg"])
        try:
            ds = bin_hindcast(series, h["hs_edges_m"], h["tz_edges_s"],
                              h.get("dir_edges_deg"), outside=h["outside"])  # optional key: no default
        except InputError as exc:
            keys = {"hs_edges": "hs_edges_m", "tz_edges": "tz_edges_s",
                    "dir_edges": "dir_edges_deg", "bins": "bins", "direction": "dir_edges_deg"}
            sub = keys.get(exc.field, exc.field)
            raise InputError(exc.message.replace("hindcast.outside", f"{kind}.outside"),
                             file=path if exc.field in keys else exc.file,
                             field=f"legs[{leg['name']}].{kind}.{sub}" if exc.field in keys
                             else exc.field, value=exc.value) from None
        ds.attrs.update(leg_kind=kind, period_conversion=series.attrs.get("period_conversion", ""))
        if kind in ("metocean", "spectra"):
            ds.attrs["format"] = h["format"]
    check_sea_table(ds, file=path, field=f"legs[{leg['name']}]")
    return ds


def tp_table_as_tz(ds: xr.Dataset, gamma: float) -> xr.Dataset:
    """A scatter table in Hs-Tp on the pipeline's Tz axis: each Tp bin (centre and edges)
    at the Tz of the JONSWAP of ``gamma`` with that Tp (DNV-RP-C205, :func:`jls.sea.spectra.tz_from_tp`);
    the table's own Tp kept as coordinate ``tp`` (and ``tp_lower``, ``tp_upper``). A leg
    declaring ``spectrum: torsethaugen`` integrates its cells' own spectra on ``tp``
    (:mod:`jls.stages.measured_response`); this axis serves the JONSWAP comparison."""
    from jls.sea.spectra import tz_from_tp
    r = float(tz_from_tp(1.0, float(gamma)))
    tz = {k: ds[k].values * r for k in ("tz", "tz_lower", "tz_upper") if k in ds.coords}
    out = ds.assign_coords(tp=("tz", ds["tz"].values), **{f"tp{k[2:]}": ("tz", ds[k].values)
                                                          for k in ("tz_lower", "tz_upper") if k in ds.coords})
    out = out.assign_coords(tz=tz["tz"], **{k: ("tz", v) for k, v in tz.items() if k != "tz"})
    out.attrs["period_conversion"] = (f"table in Hs-Tp: Tz = {r:.4f} Tp (JONSWAP, gamma {float(gamma):g}, "
                                      "DNV-RP-C205) for the binned JONSWAP comparison")
    return out


#: The parameter-file reader of each spectra format (jls.sea.metocean).
PARAMETER_FORMATS = {"ndbc": "ndbc_stdmet", "era5": "era5", "ww3": "ww3"}


def parameters_file(leg: dict, base_dir=".") -> Path | None:
    """The parameter file a spectra leg's spectra are checked against: the leg's
    ``spectra.parameters_file``, else, for NDBC spectra, NDBC's standard meteorological
    file of the same buoy and span when it lies beside the density file
    (:func:`jls.sea.ndbc.stdmet_beside`)."""
    s = leg["spectra"]
    if "parameters_file" in s:                 # optional key: no default
        return Path(base_dir) / s["parameters_file"]
    if s["format"] == "ndbc":
        from jls.sea.ndbc import stdmet_beside
        return stdmet_beside(Path(base_dir) / s["file"])
    return None


def _check_companion(leg: dict, series, path: Path, params: Path) -> None:
    """The spectra's Hs and mean directions against the leg's parameter file
    (:func:`jls.sea.companions.check_parameters`), errors naming both files and the key."""
    from jls.sea.companions import check_parameters
    from jls.sea.metocean import read_metocean
    field = f"legs[{leg['name']}].spectra.parameters_file"
    regular_file(params, "parameter file", MAX_TABLE_BYTES, field=field)
    try:
        check_parameters(series, read_metocean(params, PARAMETER_FORMATS[leg["spectra"]["format"]]),
                         path, params, field=field)
    except InputError as exc:
        raise InputError(_given_by(exc.message, leg, "spectra"), file=exc.file,
                         field=exc.field, value=exc.value) from None


def _no_direction(leg: dict, kind: str, path: Path) -> str:
    """Why a leg binned by direction has no direction: for NDBC spectra, the direction
    files beside the density file that are not there."""
    if kind == "spectra" and leg[kind]["format"] == "ndbc":
        from jls.sea.ndbc import sibling
        names = [sibling(path, k) for k in "dijk"]
        gone = [p.name for p in names if p is not None and not p.is_file()]
        return ("the spectra are one-dimensional, so the direction bins (dir_edges_deg) have no "
                "direction to bin: the direction files beside the density file are missing"
                + (f" ({', '.join(gone)})" if gone else " (its name is not <station>w<year>...)"))
    return ("the file gives no wave direction, so the direction bins (dir_edges_deg) have none "
            "to bin: remove dir_edges_deg or give a file with directions")


def _given_by(message: str, leg: dict, kind: str) -> str:
    """``message`` naming the leg's key that gives the file the error comes from."""
    if "the file given by" in message:
        return message
    return f"{message} (the file given by legs[{leg['name']}].{kind}.file)"


def read_leg(leg: dict, base_dir, steepness_rule: str, gamma: float, g: float) -> xr.Dataset:
    """The scatter Dataset of one leg (dims hs, tz), steep cells flagged with the
    configured rule, gamma and g (the one place the flag is made).

    A direction-resolved table needs the leg's course (its headings then come from the
    table, ``heading_source: direction_table``); it is returned with the Hs-Tz marginal
    ``probability`` and the joint ``cell_probability`` (heading, hs, tz) over the leg's
    ``headings_deg``.
    """
    ds = read_table(leg, base_dir, gamma)
    if "direction" in ds.dims:
        if leg.get("heading_source") != "direction_table":
            raise InputError("a direction-resolved table needs the vessel's course on the leg "
                             "(course_deg or waypoints, without wave_directions) to turn wave "
                             "directions into relative headings", file=Path(base_dir) / leg_source(leg),
                             field=f"legs[{leg['name']}].course_deg")
        ds = _joint_headings(ds, leg)
    return flag_steep(ds, steepness_rule, gamma=gamma, g=g)


def _joint_headings(ds: xr.Dataset, leg: dict) -> xr.Dataset:
    """Direction sectors -> relative headings of the leg: (heading, hs, tz) joint
    probability, binned to the leg's (derived) headings."""
    courses, weights = headings_mod.leg_courses(leg, f"legs[{leg['name']}]")
    grid = np.asarray(leg["headings_deg"], float)
    dmap = headings_mod.direction_map(courses, weights, ds["direction"].values, grid)
    joint = np.einsum("htd,dk->kht", ds["probability"].values, dmap)
    out = ds.drop_vars([v for v in ("probability", "count") if v in ds]).drop_dims("direction")
    out["probability"] = (("hs", "tz"), joint.sum(axis=0))
    out["cell_probability"] = xr.DataArray(joint, dims=("heading", "hs", "tz"),
                                           coords={"heading": grid})
    return out



TZ_RANGE_S = (1.0, 25.0)


HS_MAX_M = 25.0


# BREAKING_STEEPNESS (Hs / L of the steepest possible sea): jls.sea.steepness


G = 9.81


def check_sea_table(ds, file=None, field="scatter") -> None:
    """Hs and Tz of a scatter dataset within the plausible ranges, and no sea state
    steeper than breaking waves (the signature of Hs and Tz swapped)."""
    p = ds["probability"].values
    if p.ndim > 2:
        p = p.sum(axis=tuple(range(2, p.ndim)))
    used_hs = p.sum(axis=1) > 0
    used_tz = p.sum(axis=0) > 0
    tz = ds["tz"].values[used_tz]
    hs = ds["hs"].values[used_hs]
    lo, hi = TZ_RANGE_S
    bad = tz[(tz < lo) | (tz > hi)]
    if bad.size:
        raise InputError(f"Tz outside {lo:g}-{hi:g} s: periods in s expected (Hz, or Hs and Tz "
                         "swapped?)", file=file, field=f"{field}: tz", value=float(bad[0]))
    bad = hs[hs > HS_MAX_M]
    if bad.size:
        raise InputError(f"Hs above {HS_MAX_M:g} m: heights in m expected (cm, or Hs and Tz "
                         "swapped?)", file=file, field=f"{field}: hs", value=float(bad[0]))
    length = G * ds["tz"].values ** 2 / (2 * np.pi)
    steep = ds["hs"].values[:, None] / length[None, :] > BREAKING_STEEPNESS
    share = float((p * steep).sum())
    if share > 0.01:
        i, j = np.argwhere(steep & (p > 0))[0]
        raise InputError(f"{100 * share:.0f} % of the probability lies in sea states steeper "
                         "than breaking waves (Hs > L/7): are Hs and Tz swapped?", file=file,
                         field=f"{field}: hs {ds['hs'].values[i]:g} m, tz {ds['tz'].values[j]:g} s",
                         value=float(p[i, j]))


