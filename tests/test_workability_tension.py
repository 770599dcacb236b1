"""Wire-tension criteria in the workability assessment, checked by hand."""

import copy
from pathlib import Path

import numpy as np
import pytest
from test_workability import tiny_response, tiny_sea

from jls.assessment.workability import assess
from jls.config.loader import load, validate
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
STATIC = np.array([20000.0, 17000.0, 20000.0, 17000.0])      # kN, mirror pairs


def with_tension(resp, mpm_tz5, mpm_tz7):
    """Add unit-Hs tension MPM per wire (kN per m Hs) at tz 5 and 7 s and static tensions."""
    mpm = np.stack([mpm_tz5, mpm_tz7], axis=0)                 # (tz, wire)
    out = resp.copy()
    out["tension_mpm"] = (("candidate", "tugger", "heading", "tz", "wire"), mpm[None, None, None])
    out["tension_static"] = (("candidate", "wire"), STATIC[None].copy())
    return out.assign_coords(wire=["pf", "pa", "sf", "sa"])


def sea():
    return tiny_sea([[1, 2], [3, 4], [5, 6]], [[0, 0], [0, 0], [0, 10]])


def test_safe_working_load_by_hand():
    # SWL 21.5 MN. Tz 5: allowances 1500 / 500 and 4500 / 800 -> Hs_lim 3 m (capped by
    # the steepness ceiling 2.60 m). Tz 7: 1500 / 1000 = 1.5 m and 4500 / 2000 = 2.25 m.
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [500, 800, 500, 800],
                        [1000, 2000, 1000, 2000])
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, "max_wire_tension_kN": 21500.0})
    hs_c = ds["hs_limit_criterion"].sel(criterion="max_wire_tension_kN").values.ravel()
    np.testing.assert_allclose(hs_c, [3.0, 1.5])
    np.testing.assert_allclose(ds["hs_limit"].values.ravel(), [9.81 * 25 / (2 * np.pi * 15), 1.5])
    # Cells (Hs 0.5, 1.5, 2.5) at Tz 7: the first two pass (1.5 m at the limit exactly).
    assert ds["workability_leg"].sel(leg="a").item() == pytest.approx(15 / 21)
    assert ds["workability_leg"].sel(leg="b").item() == pytest.approx(0.0)
    # The cell's figure is the highest maximum tension over the wires.
    cell = ds["mpm"].sel(criterion="max_wire_tension_kN", leg="a", hs=2.5, tz=7.0).item()
    assert cell == pytest.approx(max(20000 + 2.5 * 1000, 17000 + 2.5 * 2000))
    util = ds["utilisation"].sel(criterion="max_wire_tension_kN", leg="a", hs=2.5, tz=7.0).item()
    assert util == pytest.approx(2.5 / 1.5)
    gov = ds["governing"].sel(leg="a", hs=2.5, tz=7.0).item()
    assert ds["governing"].attrs["flag_meanings"].split()[gov] == "max_wire_tension_kN"
    assert ds["limit"].sel(criterion="max_wire_tension_kN")["criterion_units"].item() == "kN"


def test_tension_floor_is_strict_and_lowest_wire_counts():
    # Floor 16 MN: the 17 MN wires have 1 MN to lose; at Tz 7 their unit MPM is 2 MN/m,
    # so Hs_lim = 0.5 m and the 0.5 m cell sits exactly on the floor: it fails.
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [500, 800, 500, 800],
                        [1000, 2000, 1000, 2000])
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, "min_wire_tension_kN": 16000.0})
    hs_c = ds["hs_limit_criterion"].sel(criterion="min_wire_tension_kN").values.ravel()
    np.testing.assert_allclose(hs_c, [1000 / 800, 0.5])
    cell = ds["mpm"].sel(criterion="min_wire_tension_kN", leg="a", hs=0.5, tz=7.0).item()
    assert cell == pytest.approx(16000.0)
    assert not ds["passes"].sel(leg="a", hs=0.5, tz=7.0).item()
    # Tz 5 passes up to 1.25 m (the 0.5 m cell only): leg a keeps 1 of 21.
    assert ds["workability_leg"].sel(leg="a").item() == pytest.approx(1 / 21)
    # A safe working load met exactly (20 MN + 0.5 m x 2 MN/m = 21 MN) passes: the
    # maximum is inclusive, the floor strict.
    resp_max = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [500, 800, 500, 800],
                            [2000, 100, 2000, 100])
    ds_max = assess(resp_max, sea(), {"relative_sway_m": 3.0, "max_wire_tension_kN": 21000.0})
    assert ds_max["passes"].sel(leg="a", hs=0.5, tz=7.0).item()


def test_static_tension_beyond_the_limit_fails_everywhere():
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [500] * 4, [500] * 4)
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, "max_wire_tension_kN": 19000.0})
    assert ds["workability_route"].item() == 0.0
    np.testing.assert_allclose(ds["hs_limit"].values, 0.0)


def test_governing_moves_between_sway_and_tension():
    # Sway limits Tz 7 (3 / 2 = 1.5 m); tension limits Tz 5 (1500 / 1000 = 1.5 m < 3 / 0.5).
    resp = with_tension(tiny_response([0.5, 2.0], [0.0, 0.0]), [1000, 100, 1000, 100],
                        [100, 100, 100, 100])
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, "max_wire_tension_kN": 21500.0})
    names = ds["governing"].attrs["flag_meanings"].split()
    gov = ds["governing"].sel(leg="a", hs=2.5).squeeze()
    assert names[int(gov.sel(tz=5.0))] == "max_wire_tension_kN"
    assert names[int(gov.sel(tz=7.0))] == "relative_sway_m"
    share = ds["governing_share"].sel(leg="a")
    assert share.sel(criterion="max_wire_tension_kN").item() == pytest.approx(5 / 21)
    assert share.sel(criterion="relative_sway_m").item() == pytest.approx(6 / 21)


def test_tension_criteria_need_tension_statistics_and_an_ordered_band():
    resp = tiny_response([1.0, 1.0], [0.0, 0.0])
    with pytest.raises(InputError, match="tension_mpm"):
        assess(resp, sea(), {"max_wire_tension_kN": 21500.0})
    full = with_tension(resp, [500] * 4, [500] * 4)
    with pytest.raises(InputError, match="below the maximum"):
        assess(full, sea(), {"max_wire_tension_kN": 15000.0, "min_wire_tension_kN": 16000.0})


def test_schema_takes_the_tension_criteria():
    cfg = load(ROOT / "config" / "config.yaml")
    cfg = copy.deepcopy(cfg)
    cfg["assessment"]["criteria"].update(max_wire_tension_kN=30000.0, min_wire_tension_kN=2000.0)
    validate(cfg)
    cfg["assessment"]["criteria"]["min_wire_tension_kN"] = -1.0
    with pytest.raises(InputError, match="min_wire_tension_kN"):
        validate(cfg)


def test_a_candidate_without_tensions_gets_no_limiting_hs():
    # A slack layout carries NaN tensions: its limit is unknown, never unlimited.
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [500] * 4, [500] * 4)
    resp["tension_static"][:] = np.nan
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, "max_wire_tension_kN": 21500.0})
    assert np.isnan(ds["hs_limit_criterion"].sel(criterion="max_wire_tension_kN")).all()
    assert ds["workability_route"].item() == 0.0
