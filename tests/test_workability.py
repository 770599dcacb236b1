"""Workability: a small scatter checked by hand."""

import numpy as np
import pytest
import xarray as xr

from jls.assessment.workability import assess
from jls.sea.scatter import scatter_dataset
from jls.stages.sea_states import sea_states


def tiny_response(mpm_sway, mpm_yaw):
    """Unit-Hs MPM over tz = [5, 7] for one candidate, tugger and heading."""
    mpm = np.zeros((1, 1, 1, 4, 2))
    mpm[..., 0, :] = mpm_sway
    mpm[..., 3, :] = mpm_yaw
    return xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                      coords={"candidate": ["baseline"], "tugger": ["none"], "heading": [90.0],
                              "response": ["relative_sway", "relative_heave", "relative_roll",
                                           "relative_yaw"], "tz": [5.0, 7.0]})


def tiny_sea(values_a, values_b):
    legs = {}
    for name, v in (("a", values_a), ("b", values_b)):
        legs[name] = scatter_dataset(np.asarray(v, float), hs_lower=[0, 1, 2], hs_upper=[1, 2, 3],
                                     tz_lower=[4, 6], tz_upper=[6, 8], values_kind="counts")
    route = {"name": "tiny", "legs": [{"name": "a", "duration_h": 30, "headings_deg": [90], "heading_probability": [1.0]},
                                      {"name": "b", "duration_h": 10, "headings_deg": [90], "heading_probability": [1.0]}]}
    return sea_states(route, legs)


def test_workability_by_hand():
    # Hs centres 0.5, 1.5, 2.5 m; unit MPM sway 1.0 m/m at Tz 5 s, 2.0 at Tz 7 s.
    # Limit 3 m: Tz 5 passes up to Hs 3 (all three bins), Tz 7 up to Hs 1.5 (two bins).
    sea = tiny_sea([[1, 2], [3, 4], [5, 6]], [[0, 0], [0, 0], [0, 10]])
    ds = assess(tiny_response([1.0, 2.0], [0.1, 0.1]), sea, {"relative_sway_m": 3.0})
    # Leg a: total 21; failing only (2.5 m, 7 s) with 6 -> 15/21.
    assert ds["workability_leg"].sel(leg="a").item() == pytest.approx(15 / 21)
    # Leg b: all its probability in the failing cell.
    assert ds["workability_leg"].sel(leg="b").item() == pytest.approx(0.0)
    # Route: weighted by duration 30 h and 10 h.
    assert ds["workability_route"].item() == pytest.approx(0.75 * 15 / 21)
    # Eq. 2.7: Hs_lim = 3 / MPM(Hs=1), capped by the steepness ceiling (2.60 m at 5 s).
    ceiling = 9.81 * 5.0**2 / (2 * np.pi * 15)
    np.testing.assert_allclose(ds["hs_limit"].values.ravel(), [ceiling, 1.5])


def test_governing_criterion_and_steepness_cap():
    sea = tiny_sea([[1, 1], [1, 1], [1, 1]], [[1, 1], [1, 1], [1, 1]])
    # Yaw 2 deg/m with a 1 deg limit governs at Tz 5; sway at Tz 7.
    ds = assess(tiny_response([0.1, 2.0], [2.0, 0.1]), sea,
                {"relative_sway_m": 3.0, "relative_yaw_deg": 1.0})
    gov = ds["governing"].sel(candidate="baseline", tugger="none", leg="a", heading=90.0)
    names = ds["governing"].attrs["flag_meanings"].split()
    assert names[int(gov.sel(hs=2.5, tz=5.0))] == "relative_yaw_deg"
    assert names[int(gov.sel(hs=2.5, tz=7.0))] == "relative_sway_m"
    hs_lim = ds["hs_limit_criterion"].sel(candidate="baseline", tugger="none", heading=90.0)
    assert hs_lim.sel(tz=5.0, criterion="relative_yaw_deg").item() == pytest.approx(0.5)
    # Small responses: the limit is the steepness ceiling g Tz^2 / (2 pi 15).
    ds2 = assess(tiny_response([0.01, 0.01], [0.01, 0.01]), sea, {"relative_sway_m": 3.0})
    np.testing.assert_allclose(ds2["hs_limit"].values.ravel(),
                               9.81 * np.array([5.0, 7.0]) ** 2 / (2 * np.pi * 15))


def test_upper_edge_assessment_is_more_conservative():
    sea = tiny_sea([[1, 2], [3, 4], [5, 6]], [[1, 2], [3, 4], [5, 6]])
    resp = tiny_response([1.0, 1.4], [0.0, 0.0])
    centre = assess(resp, sea, {"relative_sway_m": 3.0})["workability_route"].item()
    upper = assess(resp, sea, {"relative_sway_m": 3.0}, hs_in_bin="upper")["workability_route"].item()
    # Tz 7: centre 2.5 m gives 3.5 m > 3 (fails); upper edges 1, 2 m pass and 3 m fails.
    assert centre == pytest.approx(15 / 21)
    assert upper == pytest.approx(15 / 21)
    resp = tiny_response([1.1, 1.0], [0.0, 0.0])
    # Tz 5: centre 2.5 m -> 2.75 m passes; upper edge 3 m -> 3.3 m fails.
    assert assess(resp, sea, {"relative_sway_m": 3.0})["workability_route"].item() == pytest.approx(1.0)
    assert assess(resp, sea, {"relative_sway_m": 3.0},
                  hs_in_bin="upper")["workability_route"].item() == pytest.approx(16 / 21)


def test_operability_curve_on_a_fine_grid_matches_cells_where_they_meet():
    sea = tiny_sea([[1, 2], [3, 4], [5, 6]], [[1, 2], [3, 4], [5, 6]])
    fine_tz = np.arange(4.0, 8.01, 0.5)
    mpm = np.zeros((1, 1, 1, 4, fine_tz.size))
    mpm[..., 0, :] = np.interp(fine_tz, [5.0, 7.0], [1.0, 2.0])
    curve = xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                       coords={"candidate": ["baseline"], "tugger": ["none"], "heading": [90.0],
                               "response": ["relative_sway", "relative_heave", "relative_roll",
                                            "relative_yaw"], "tz": fine_tz})
    ds = assess(tiny_response([1.0, 2.0], [0.0, 0.0]), sea, {"relative_sway_m": 3.0}, curve=curve)
    fine = ds["hs_limit_curve"].sel(candidate="baseline", tugger="none", heading=90.0)
    coarse = ds["hs_limit"].sel(candidate="baseline", tugger="none", heading=90.0)
    for tz in (5.0, 7.0):
        assert fine.sel(tz_curve=tz).item() == pytest.approx(coarse.sel(tz=tz).item())
    expected = np.minimum(3.0 / mpm[0, 0, 0, 0], 9.81 * fine_tz**2 / (2 * np.pi * 15))
    np.testing.assert_allclose(fine.values, expected)
