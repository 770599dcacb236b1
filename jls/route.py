"""A route: its legs, their wave statistics and headings, as one sea-state dataset.

Each leg gives a scatter table (matrix or long CSV, :mod:`jls.sea.scatter`) or an
hourly hindcast binned with configured edges (:mod:`jls.sea.hindcast`), a duration and
the relative wave headings it meets with their probabilities (WAMIT convention:
propagation direction relative to +x, 90 deg beam seas from starboard, 180 head seas).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import xarray as xr

from jls import registry
from jls.errors import InputError
from jls.plausible import check_sea_table
from jls.sea.hindcast import bin_hindcast, read_hindcast
from jls.sea.scatter import read_scatter
from jls.sea.steepness import flag_steep


def leg_source(leg: dict) -> Path:
    return Path(leg["scatter"] if "scatter" in leg else leg["hindcast"]["file"])


def read_leg(leg: dict, base_dir, steepness_rule: str, gamma: float, g: float) -> xr.Dataset:
    """The scatter Dataset of one leg (dims hs, tz), steep cells flagged with the
    configured rule, gamma and g (the one place the flag is made)."""
    path = Path(base_dir) / leg_source(leg)
    if not path.exists():
        field = "scatter" if "scatter" in leg else "hindcast.file"
        raise InputError("file not found", file=path, field=f"legs[{leg['name']}].{field}")
    if "scatter" in leg:
        ds = read_scatter(path, **{k: leg[k] for k in ("layout", "bins", "values") if k in leg})
    else:
        h = leg["hindcast"]
        try:
            ds = bin_hindcast(read_hindcast(path), h["hs_edges_m"], h["tz_edges_s"],
                              outside=h["outside"])
        except InputError as exc:
            keys = {"hs_edges": "hs_edges_m", "tz_edges": "tz_edges_s", "bins": "bins"}
            sub = keys.get(exc.field, exc.field)
            raise InputError(exc.message, file=path if exc.field in keys else exc.file,
                             field=f"legs[{leg['name']}].hindcast.{sub}" if exc.field in keys
                             else exc.field, value=exc.value) from None
    check_sea_table(ds, file=path, field=f"legs[{leg['name']}]")
    if "direction" in ds.dims:
        raise InputError("direction-resolved tables are not assessed per leg yet: give the "
                         "leg's relative headings (headings_deg) and a table without direction",
                         file=path, field="direction")
    return flag_steep(ds, steepness_rule, gamma=gamma, g=g)


def leg_key(leg_ds: xr.Dataset, leg: dict, gamma: float) -> dict:
    """What a leg's response work depends on: its Tz values, headings and gamma.

    Editing only the probabilities of a table leaves the key unchanged, so no response
    job has to rerun.
    """
    tz = sorted(float(t) for t in leg_ds["tz"].values)
    headings = sorted(float(h) for h in leg["headings_deg"])
    body = {"tz": tz, "headings_deg": headings, "gamma": float(gamma)}
    digest = hashlib.sha256(json.dumps(body, sort_keys=True).encode()).hexdigest()[:12]
    return {**body, "key": digest}


def sea_states(route: dict, leg_datasets: dict, steepness_rule="study") -> xr.Dataset:
    """Combine the legs of a route into the sea-state dataset (the README (section Outputs))."""
    legs = route["legs"]
    names = [leg["name"] for leg in legs]
    headings = sorted({float(h) for leg in legs for h in leg["headings_deg"]})
    parts = []
    for leg in legs:
        ds = leg_datasets[leg["name"]]
        hdg = [float(h) for h in leg["headings_deg"]]
        hp = np.asarray(leg["heading_probability"], float)
        if len(hp) != len(hdg) or not np.isclose(hp.sum(), 1.0, atol=1e-6) or np.any(hp < 0):
            raise InputError("heading probabilities must be one per heading, non-negative and "
                             "sum to 1", field=f"legs[{leg['name']}].heading_probability",
                             value=hp.tolist())
        hprob = xr.DataArray(np.zeros(len(headings)), dims="heading", coords={"heading": headings})
        for h, p in zip(hdg, hp):
            hprob.loc[h] += p
        part = xr.Dataset(
            {"probability": (("hs", "tz"), ds["probability"].values),
             "steep": (("hs", "tz"), ds["steep"].values.astype(float)),
             "hs_lower": ("hs", ds["hs_lower"].values), "hs_upper": ("hs", ds["hs_upper"].values),
             "tz_lower": ("tz", ds["tz_lower"].values), "tz_upper": ("tz", ds["tz_upper"].values),
             "heading_probability": hprob, "duration_h": float(leg["duration_h"]),
             "record_total": float(ds.attrs.get("total", np.nan))},
            coords={"hs": ds["hs"].values, "tz": ds["tz"].values})
        parts.append(part.expand_dims(leg=[leg["name"]]))
    out = xr.concat(parts, dim="leg", join="outer", data_vars="all", coords="minimal",
                    compat="override", fill_value={"probability": 0.0, "heading_probability": 0.0})
    out["steep"] = out["steep"].fillna(0.0) > 0.5
    out["steep_probability"] = (out["probability"] * out["steep"]).sum(("hs", "tz"))
    out["leg_weight"] = out["duration_h"] / out["duration_h"].sum()
    out = out.sel(leg=names)
    registry.annotate(out, "sea_states")
    out.attrs.update(route=route.get("name", ""), steepness_rule=steepness_rule)
    for leg in legs:
        ds = leg_datasets[leg["name"]]
        out.attrs[f"source_{leg['name']}"] = ds.attrs.get("source") or str(leg.get("scatter", ""))
    return out
