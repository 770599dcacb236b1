"""Relative wave headings from the vessel's course, direction-resolved tables and the
joint (heading, Hs, Tz) probability of the sea states."""

import copy
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.assessment.workability import assess
from jls.config.loader import load_yaml, validate
from jls.errors import InputError
from jls.sea import headings
from jls.sea.legs import read_leg
from jls.sea.scatter import scatter_dataset
from jls.stages.sea_states import sea_states

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
TABLE = "config/routes/default/leg1_gulf_of_maine.csv"


@pytest.fixture
def cfg():
    return copy.deepcopy(load_yaml(CONFIG))


def course_leg(cfg, **keys):
    """The default route reduced to one leg on the first table, with heading keys."""
    leg = {"name": "a", "scatter": TABLE, "duration_h": 10.0, **keys}
    cfg["routes"]["default"]["legs"] = [leg]
    return cfg


def resolved_leg(cfg, **keys):
    return validate(course_leg(cfg, **keys), base_dir=ROOT)["routes"]["default"]["legs"][0]


# --- conventions -------------------------------------------------------------------

@pytest.mark.parametrize("course", [0.0, 37.0, 180.0, 300.0])
def test_waves_from_dead_ahead_are_head_seas(course):
    assert headings.relative_heading(course, course) == pytest.approx(180.0)
    assert headings.relative_heading(course, course + 180.0) == pytest.approx(0.0)


@pytest.mark.parametrize("course", [0.0, 45.0, 200.0, 350.0])
def test_waves_from_the_right_side_are_beam_seas_from_starboard(course):
    # Coming from 90 deg clockwise of the bow (starboard): travelling toward port, +y:
    # WAMIT 90 deg. From the port side: 270 deg.
    assert headings.relative_heading(course, (course + 90.0) % 360) == pytest.approx(90.0)
    assert headings.relative_heading(course, (course - 90.0) % 360) == pytest.approx(270.0)


def test_great_circle_initial_bearing_against_hand_values():
    # Along the equator eastward, along a meridian northward.
    assert headings.initial_bearing(0.0, 0.0, 0.0, 10.0) == pytest.approx(90.0)
    assert headings.initial_bearing(0.0, 0.0, 10.0, 0.0) == pytest.approx(0.0)
    # From (0 N, 0 E) to (45 N, 90 E): y = sin 90 cos 45, x = sin 45 - 0 -> atan2 = 45 deg,
    # although the target lies due east in longitude.
    assert headings.initial_bearing(0.0, 0.0, 45.0, 90.0) == pytest.approx(45.0)
    # Land's End (50.0664 N, 5.7147 W) to John o'Groats (58.6439 N, 3.0700 W): initial
    # bearing 009 deg 07' 11" and 968.9 km (the classic worked example of the haversine
    # and bearing formulae).
    assert headings.initial_bearing(50.0664, -5.7147, 58.6439, -3.0700) == pytest.approx(
        9 + 7 / 60 + 11 / 3600, abs=2e-3)
    assert headings.great_circle_distance(50.0664, -5.7147, 58.6439, -3.0700) == pytest.approx(
        968.9e3, rel=1e-3)


def test_waypoint_segments_are_weighted_by_distance():
    # 2 deg east along the equator, then 1 deg north: courses 90 and 0, lengths 2 : 1.
    leg = {"waypoints": [{"lat_deg": 0, "lon_deg": 0}, {"lat_deg": 0, "lon_deg": 2},
                         {"lat_deg": 1, "lon_deg": 2}]}
    courses, weights = headings.leg_courses(leg)
    np.testing.assert_allclose(courses, [90.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(weights, [2 / 3, 1 / 3], rtol=1e-9)
    # Waves from the north: heading east they come from port (270), heading north from
    # ahead (180).
    h, p = headings.heading_distribution(courses, weights, [0.0], [1.0], headings.step_grid(15))
    np.testing.assert_allclose(h, [180.0, 270.0])
    np.testing.assert_allclose(p, [1 / 3, 2 / 3])


def test_binning_to_the_nearest_grid_heading_is_circular():
    grid = headings.step_grid(30)
    np.testing.assert_array_equal(grid[headings.nearest([350.0, 14.0, 16.0, 181.0], grid)],
                                  [0.0, 0.0, 30.0, 180.0])
    with pytest.raises(InputError, match="divide 360"):
        headings.step_grid(25)
    # RAO headings 0-180 of a symmetric hull are mirrored to 0-360.
    np.testing.assert_allclose(headings.rao_grid([0, 90, 180]), [0, 90, 180, 270])


# --- configuration ------------------------------------------------------------------

def test_course_and_wave_directions_give_the_legs_headings(cfg):
    leg = resolved_leg(cfg, course_deg=10.0, heading_step_deg=15,
                       wave_directions={"from_deg": [10.0, 100.0, 280.0], "probability": [0.5, 0.3, 0.2]})
    # from dead ahead: 180; from 90 deg to starboard: 90; from 90 deg to port: 270.
    assert leg["headings_deg"] == [90.0, 180.0, 270.0]
    np.testing.assert_allclose(leg["heading_probability"], [0.3, 0.5, 0.2])
    assert leg["heading_source"] == "course_directions"


def test_derived_headings_are_binned_to_the_rao_headings(cfg):
    # Course 0, waves from 100: beta = 80 deg; the default vessel's RAOs are every 15 deg
    # (0-180, mirrored), so 75 deg; from 190: beta = 350 -> 345 (a mirrored heading).
    leg = resolved_leg(cfg, course_deg=0.0, wave_directions={"from_deg": [100.0, 190.0],
                                                             "probability": [0.6, 0.4]})
    assert leg["headings_deg"] == [75.0, 345.0]
    np.testing.assert_allclose(leg["heading_probability"], [0.6, 0.4])


def test_heading_source_is_recorded_and_validation_is_idempotent(cfg):
    cfg = course_leg(cfg, course_deg=0.0, heading_step_deg=30,
                     wave_directions={"from_deg": [0.0], "probability": [1.0]})
    cfg["routes"]["default"]["legs"] += [
        {"name": "b", "scatter": TABLE, "duration_h": 5.0},
        {"name": "c", "scatter": TABLE, "duration_h": 5.0, "headings_deg": [90, 270],
         "heading_probability": [0.5, 0.5]}]
    out = validate(cfg, base_dir=ROOT)
    legs = out["routes"]["default"]["legs"]
    assert [leg["heading_source"] for leg in legs] == ["course_directions", "default", "given"]
    assert legs[1]["headings_deg"] == [90] and legs[0]["headings_deg"] == [180.0]
    assert validate(copy.deepcopy(out), base_dir=ROOT) == out


@pytest.mark.parametrize("keys, match", [
    ({"course_deg": 0.0, "headings_deg": [90]}, "remove headings_deg"),
    ({"course_deg": 0.0, "waypoints": [{"lat_deg": 0, "lon_deg": 0}, {"lat_deg": 1, "lon_deg": 0}]},
     "not both"),
    ({"wave_directions": {"from_deg": [0.0], "probability": [1.0]}}, "needs the vessel's course"),
    ({"course_deg": 0.0, "wave_directions": {"from_deg": [0.0, 90.0], "probability": [0.5, 0.4]}},
     "summing to 1"),
    ({"course_deg": 0.0, "heading_step_deg": 25,
      "wave_directions": {"from_deg": [0.0], "probability": [1.0]}},
     "divide 360"),
    ({"course_deg": 0.0}, "direction-resolved table"),
    ({"waypoints": [{"lat_deg": 5, "lon_deg": 5}, {"lat_deg": 5, "lon_deg": 5}],
      "wave_directions": {"from_deg": [0.0], "probability": [1.0]}}, "no length"),
])
def test_bad_heading_input_is_named(cfg, keys, match):
    with pytest.raises(InputError, match=match) as exc:
        validate(course_leg(cfg, **keys), base_dir=ROOT)
    assert "legs[0]" in exc.value.field


def test_missing_rao_file_for_binning_is_named(cfg, tmp_path):
    cfg["vessel"]["rao_file"] = "nowhere.nc"
    with pytest.raises(InputError, match="heading_step_deg"):
        validate(course_leg(cfg, course_deg=0.0, wave_directions={"from_deg": [0.0], "probability": [1.0]}),
                 base_dir=tmp_path)


# --- direction-resolved tables and the joint probability ----------------------------

def write_table(path, rows):
    path.write_text("# hs_bins: edges\n# tz_bins: edges\nhs,tz,direction,probability\n"
                    + "".join(f"{r}\n" for r in rows))
    return path.name


def test_a_direction_resolved_table_needs_the_course(tmp_path):
    name = write_table(tmp_path / "t.csv", ["0-1,4-6,0,1.0"])
    leg = {"name": "a", "scatter": name, "layout": "long", "duration_h": 1.0,
           "headings_deg": [90], "heading_probability": [1.0], "heading_source": "given"}
    with pytest.raises(InputError, match="course"):
        read_leg(leg, tmp_path, "study", 3.3, 9.81)


def _legs(cfg, tmp_path, rows, **keys):
    """A validated one-leg route on a direction-resolved table, and its dataset."""
    name = write_table(tmp_path / "dir.csv", rows)
    cfg = course_leg(cfg, **keys)
    cfg["routes"]["default"]["legs"][0].update(scatter=name, layout="long")
    leg = validate(cfg, base_dir=tmp_path)["routes"]["default"]["legs"][0]
    return leg, read_leg(leg, tmp_path, "study", 3.3, 9.81)


@pytest.fixture
def cfg_tmp(cfg, tmp_path):
    cfg["vessel"]["rao_file"] = str(ROOT / cfg["vessel"]["rao_file"])
    return cfg


ROWS = ["0-1,4-6,0,0.2", "1-2,4-6,0,0.3", "1-2,6-8,90,0.1", "2-3,6-8,180,0.25", "0-1,6-8,270,0.15"]


def test_joint_probability_of_a_direction_resolved_table(cfg_tmp, tmp_path):
    leg, ds = _legs(cfg_tmp, tmp_path, ROWS, course_deg=0.0, heading_step_deg=90)
    assert leg["heading_source"] == "direction_table"
    # heading north: from 0 -> 180, from 90 -> 90, from 180 -> 0, from 270 -> 270
    assert leg["headings_deg"] == [0.0, 90.0, 180.0, 270.0]
    np.testing.assert_allclose(leg["heading_probability"], [0.25, 0.1, 0.5, 0.15])
    cell = ds["cell_probability"]
    assert float(cell.sel(heading=180.0, hs=1.5, tz=5.0)) == pytest.approx(0.3)
    assert float(cell.sel(heading=0.0, hs=2.5, tz=7.0)) == pytest.approx(0.25)
    sea = sea_states({"name": "r", "legs": [leg]}, {"a": ds})
    assert float(sea["cell_probability"].sum()) == pytest.approx(1.0)
    xr.testing.assert_allclose(sea["cell_probability"].sum("heading"), sea["probability"])
    np.testing.assert_allclose(sea["heading_probability"].sel(leg="a").values,
                               leg["heading_probability"])
    assert sea.attrs["heading_source_a"] == "direction_table"


def test_joint_probabilities_sum_to_one_per_leg(cfg_tmp, tmp_path):
    leg_t, ds_t = _legs(cfg_tmp, tmp_path, ROWS, waypoints=[
        {"lat_deg": 40, "lon_deg": -70}, {"lat_deg": 35, "lon_deg": -75}, {"lat_deg": 29, "lon_deg": -79}])
    plain = scatter_dataset(np.array([[1, 2], [3, 4]], float), hs_lower=[0, 1], hs_upper=[1, 2],
                            tz_lower=[4, 6], tz_upper=[6, 8])
    leg_c = validate(course_leg(copy.deepcopy(cfg_tmp), course_deg=200.0,
                                wave_directions={"from_deg": [0, 45, 90, 135, 180],
                                                 "probability": [0.1, 0.2, 0.3, 0.25, 0.15]}),
                     base_dir=tmp_path)["routes"]["default"]["legs"][0]
    leg_c["name"] = "c"
    route = {"name": "r", "legs": [leg_t, leg_c]}
    sea = sea_states(route, {"a": ds_t, "c": plain})
    np.testing.assert_allclose(sea["cell_probability"].sum(("heading", "hs", "tz")), [1.0, 1.0])
    np.testing.assert_allclose(sea["heading_probability"].sum("heading"), [1.0, 1.0])
    xr.testing.assert_allclose(sea["cell_probability"].sum("heading"), sea["probability"])
    # the independent leg is the product of its marginals
    c = sea.sel(leg="c")
    xr.testing.assert_allclose(c["cell_probability"],
                               (c["probability"] * c["heading_probability"]).transpose("heading", "hs", "tz"))


def _response(headings_deg, mpm_sway):
    """Unit-Hs sway MPM per (heading, tz = 5, 7)."""
    mpm = np.zeros((1, 1, len(headings_deg), 4, 2))
    mpm[:, :, :, 0, :] = np.asarray(mpm_sway, float)
    return xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                      coords={"candidate": ["baseline"], "tugger": ["none"],
                              "heading": [float(h) for h in headings_deg],
                              "response": ["relative_sway", "relative_heave", "relative_roll",
                                           "relative_yaw"], "tz": [5.0, 7.0]})


def test_a_direction_table_with_one_direction_equals_the_single_heading_result(cfg_tmp, tmp_path):
    # All energy from the north, the vessel heading west: beam seas from starboard (90).
    rows = ["0-1,4-6,0,1", "1-2,4-6,0,3", "2-3,4-6,0,5", "0-1,6-8,0,2", "1-2,6-8,0,4",
            "2-3,6-8,0,6", "2-3,6-8,180,0"]
    leg_d, ds_d = _legs(cfg_tmp, tmp_path, rows, course_deg=270.0)
    assert leg_d["headings_deg"] == [90.0]
    plain = scatter_dataset(np.array([[1, 2], [3, 4], [5, 6]], float), hs_lower=[0, 1, 2],
                            hs_upper=[1, 2, 3], tz_lower=[4, 6], tz_upper=[6, 8])
    leg_h = {"name": "h", "duration_h": 10.0, "headings_deg": [90.0], "heading_probability": [1.0]}
    resp = _response([90.0], [[1.0, 2.0]])
    one = assess(resp, sea_states({"name": "r", "legs": [leg_d]}, {"a": ds_d}), {"relative_sway_m": 3.0})
    ref = assess(resp, sea_states({"name": "r", "legs": [leg_h]}, {"h": plain}), {"relative_sway_m": 3.0})
    assert one["workability_route"].item() == pytest.approx(ref["workability_route"].item())
    assert one["workability_route"].item() == pytest.approx(15 / 21)
    np.testing.assert_allclose(one["governing_share"].values, ref["governing_share"].values)


def test_cell_probability_workability_equals_the_product_form_for_independent_legs():
    legs = {n: scatter_dataset(np.asarray(v, float), hs_lower=[0, 1, 2], hs_upper=[1, 2, 3],
                               tz_lower=[4, 6], tz_upper=[6, 8])
            for n, v in (("a", [[1, 2], [3, 4], [5, 6]]), ("b", [[2, 0], [1, 7], [0, 3]]))}
    route = {"name": "r", "legs": [
        {"name": "a", "duration_h": 30, "headings_deg": [90, 150], "heading_probability": [0.3, 0.7]},
        {"name": "b", "duration_h": 10, "headings_deg": [60, 90], "heading_probability": [0.6, 0.4]}]}
    sea = sea_states(route, legs)
    resp = _response([60.0, 90.0, 150.0], [[0.9, 1.3], [1.0, 2.0], [0.5, 1.6]])
    ds = assess(resp, sea, {"relative_sway_m": 3.0})
    product = sea["probability"] * sea["heading_probability"]
    expected = (product * ds["passes"]).sum(("heading", "hs", "tz"))
    xr.testing.assert_allclose(ds["workability_leg"], expected.transpose(*ds["workability_leg"].dims))
    assert 0.0 < ds["workability_route"].item() < 1.0


def test_a_direction_resolved_hindcast_gives_the_headings(cfg_tmp):
    # Five hourly records coming from 10, 350, 95, 185 and 360 deg; four 90-deg sectors
    # centred on north, east, south, west. Heading east (90): from north -> 270 (port
    # beam), from east -> 180 (head seas), from south -> 90 (starboard beam).
    src = ROOT / "tests" / "data" / "sea" / "hindcast_direction.txt"
    cfg = course_leg(cfg_tmp, course_deg=90.0)
    cfg["routes"]["default"]["legs"][0] = {
        "name": "a", "duration_h": 5.0, "course_deg": 90.0,
        "hindcast": {"file": str(src), "hs_edges_m": [0, 1, 2], "tz_edges_s": [4, 5, 6],
                     "dir_edges_deg": [-45, 45, 135, 225, 315]}}
    leg = validate(cfg, base_dir=ROOT)["routes"]["default"]["legs"][0]
    assert leg["headings_deg"] == [90.0, 180.0, 270.0]
    np.testing.assert_allclose(leg["heading_probability"], [0.2, 0.2, 0.6])
    ds = read_leg(leg, ROOT, "study", 3.3, 9.81)
    # (1.2 m, 5.1 s) came from 95 deg: head seas; (1.1 m, 5.4 s) from north: port beam
    assert float(ds["cell_probability"].sel(heading=180.0, hs=1.5, tz=5.5)) == pytest.approx(0.2)
    assert float(ds["cell_probability"].sel(heading=270.0, hs=1.5, tz=5.5)) == pytest.approx(0.2)
    assert float(ds["cell_probability"].sum()) == pytest.approx(1.0)


def test_a_course_added_to_a_validated_leg_with_given_headings_is_a_conflict(cfg):
    out = validate(course_leg(cfg, headings_deg=[90], heading_probability=[1.0]), base_dir=ROOT)
    leg = out["routes"]["default"]["legs"][0]
    assert leg["heading_source"] == "given"
    leg.update(course_deg=0.0, wave_directions={"from_deg": [0.0], "probability": [1.0]})
    with pytest.raises(InputError, match="remove headings_deg"):
        validate(out, base_dir=ROOT)
