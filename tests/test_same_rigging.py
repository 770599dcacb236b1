"""One option per rigging: candidates of the same geometry within 1 cm are merged."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.config.builders import rigging_from_config
from jls.config.loader import load
from jls.plant import same_rigging
from jls.plant.candidates import plant_dataset

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def plant():
    cfg = load(ROOT / "config" / "config.yaml")
    rig = rigging_from_config(cfg)
    values = {"baseline": {}, "detuned": {"top_spread_y": 27.40, "drop_height": 65.71},
              # 4 mm off detuned in the spread, 3 mm in the drop: the same rigging
              "optimised": {"top_spread_y": 27.404, "drop_height": 65.707},
              # 3 cm off: another rigging
              "wider": {"top_spread_y": 27.43, "drop_height": 65.71}}
    ds, _ = plant_dataset(rig, values)
    return ds


def work_like(plant):
    names = plant["candidate"].values
    return xr.Dataset({"workability_route": (("candidate", "tugger"),
                                             np.arange(len(names) * 2, dtype=float).reshape(-1, 2))},
                      coords={"candidate": names, "tugger": ["none", "high"]})


def test_duplicate_geometries_are_one_option_with_all_their_names(plant):
    assert same_rigging.groups(plant, plant["candidate"].values, 0.01) == [
        ["baseline"], ["detuned", "optimised"], ["wider"]]
    out = same_rigging.merge(work_like(plant), plant, 0.01)
    assert out["candidate"].values.tolist() == ["baseline", "detuned", "wider"]
    assert out["candidate_names"].values.tolist() == ["baseline", "detuned, optimised", "wider"]
    assert out.attrs["same_rigging"] == "optimised is the same rigging as detuned"
    # the kept option's numbers are its own, untouched
    np.testing.assert_array_equal(out["workability_route"].sel(candidate="wider").values, [6.0, 7.0])
    assert same_rigging.alias(out, "optimised") == "detuned"
    assert same_rigging.alias(out, "absent") is None
    # no two options left within 1 cm of each other (the contract of workability.nc)
    x = same_rigging.geometry_matrix(plant, out["candidate"].values)
    d = np.abs(x[:, None, :] - x[None, :, :]).max(axis=-1)
    assert (d[~np.eye(len(x), dtype=bool)] > 0.01).all()


def test_a_tolerance_of_zero_keeps_them_apart_and_a_wide_one_chains(plant):
    assert len(same_rigging.groups(plant, plant["candidate"].values, 0.0)) == 4
    # 5 cm: detuned, optimised and wider (3 cm off detuned) chain into one
    assert same_rigging.groups(plant, plant["candidate"].values, 0.05)[1] == ["detuned", "optimised", "wider"]
    out = same_rigging.merge(work_like(plant), plant, 0.0)
    assert out.attrs["same_rigging"] == "" and out.sizes["candidate"] == 4

