"""A route: its legs, their wave statistics and headings, as one sea-state dataset.

Each leg gives a scatter table (matrix or long CSV, :mod:`jls.sea.scatter`) or an
hourly record (a hindcast, a metocean parameter file or spectra, :mod:`jls.sea.records`)
binned with configured edges (:mod:`jls.sea.hindcast`), a duration and
the relative wave headings it meets with their probabilities (WAMIT convention:
propagation direction relative to +x, 90 deg beam seas from starboard, 180 head seas),
given or derived from the vessel's course (:mod:`jls.config.headings`).

A leg's cells carry the joint probability of (heading, Hs, Tz), ``cell_probability``:
the product of the Hs-Tz and heading probabilities when the two are independent (a
table without direction), or taken from the table when it resolves the wave direction
(each direction sector goes to the relative heading it is met at on the leg's course).
"""

from __future__ import annotations

import hashlib
import json

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import registry


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
    """Combine the legs of a route into the sea-state dataset (docs/reference/outputs.md)."""
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
        cell = _cell_probability(ds, hdg, hp, headings)
        hprob = cell.sum(("hs", "tz"))
        part = xr.Dataset(
            {"probability": (("hs", "tz"), ds["probability"].values),
             "cell_probability": cell,
             "steep": (("hs", "tz"), ds["steep"].values.astype(float)),
             "hs_lower": ("hs", ds["hs_lower"].values), "hs_upper": ("hs", ds["hs_upper"].values),
             "tz_lower": ("tz", ds["tz_lower"].values), "tz_upper": ("tz", ds["tz_upper"].values),
             "heading_probability": hprob, "duration_h": float(leg["duration_h"]),
             "record_total": float(ds.attrs.get("total", np.nan))},
            coords={"hs": ds["hs"].values, "tz": ds["tz"].values})
        parts.append(part.expand_dims(leg=[leg["name"]]))
    out = xr.concat(parts, dim="leg", join="outer", data_vars="all", coords="minimal",
                    compat="override", fill_value={"probability": 0.0, "heading_probability": 0.0,
                                                         "cell_probability": 0.0})
    out["steep"] = out["steep"].fillna(0.0) > 0.5
    out["steep_probability"] = (out["probability"] * out["steep"]).sum(("hs", "tz"))
    out["leg_weight"] = out["duration_h"] / out["duration_h"].sum()
    out = out.sel(leg=names)
    registry.annotate(out, "sea_states")
    out.attrs.update(route=route.get("name", ""), steepness_rule=steepness_rule)
    for leg in legs:
        ds = leg_datasets[leg["name"]]
        out.attrs[f"source_{leg['name']}"] = ds.attrs.get("source") or str(leg.get("scatter", ""))
        out.attrs[f"heading_source_{leg['name']}"] = leg.get("heading_source", "given")
        if ds.attrs.get("leg_kind"):              # an hourly record (absent: a scatter table)
            out.attrs[f"leg_kind_{leg['name']}"] = ds.attrs["leg_kind"]
        if ds.attrs.get("period_conversion"):
            out.attrs[f"period_conversion_{leg['name']}"] = ds.attrs["period_conversion"]
        if "record_start" in ds.attrs:            # a hindcast: what its record covers
            a = ds.attrs
            out.attrs[f"record_{leg['name']}"] = (
                f"{a['record_start']} to {a['record_end']}, step {a['record_step_h']:g} h, "
                f"{a['record_count']} records ({100 * a['record_coverage']:.1f} % of the span), "
                f"months {a['record_months']}")
    out.attrs["warnings"] = "\n".join(line for leg in legs for line in str(
        leg_datasets[leg["name"]].attrs.get("warnings", "")).splitlines() if line)
    return out


def _cell_probability(ds: xr.Dataset, hdg, hp, headings) -> xr.DataArray:
    """Joint probability (heading, hs, tz) of a leg on the route's ``headings``: from a
    direction-resolved table, or the product of the Hs-Tz and heading probabilities."""
    coords = {"heading": headings, "hs": ds["hs"].values, "tz": ds["tz"].values}
    cell = xr.DataArray(np.zeros((len(headings), ds.sizes["hs"], ds.sizes["tz"])),
                        dims=("heading", "hs", "tz"), coords=coords)
    if "cell_probability" in ds:
        table = ds["cell_probability"]
        for h in table["heading"].values:
            cell.loc[float(h)] += table.sel(heading=h).values
        return cell
    for h, p in zip(hdg, hp):
        cell.loc[h] += p * ds["probability"].values
    return cell
