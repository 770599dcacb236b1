"""Choosing what to run (issue 35, item 4): ``run_routes`` keeps only the routes it names,
so an own vessel is assessed on an own route alone, without the shipped default route's
sea states being checked against its RAOs."""

import copy

import pytest

from jls.config.loader import load, validate
from jls.config.workflow_inputs import check_run
from jls.errors import InputError

ROOT = __import__("pathlib").Path(__file__).resolve().parents[1]
OWN = {"legs": [{"name": "only", "duration_h": 24,
                 "hindcast": {"file": "tests/data/metocean/ndbc41009_hourly_hs_tz_1996.txt",
                              "hs_edges_m": [0, 1, 2, 3, 4, 6, 8], "tz_edges_s": [2, 4, 6, 8, 10, 12, 14, 16]}}]}


@pytest.fixture
def two_routes():
    cfg = load(ROOT / "config/config.yaml")
    raw = copy.deepcopy(cfg)
    raw["routes"]["own"] = copy.deepcopy(OWN)
    return raw


def test_every_route_without_a_selection(two_routes):
    assert list(validate(copy.deepcopy(two_routes))["routes"]) == ["default", "own"]


@pytest.mark.parametrize("chosen", [["own"], "own"])
def test_the_selection_keeps_only_the_named_routes(two_routes, chosen):
    two_routes["run_routes"] = chosen
    cfg = validate(two_routes)
    assert list(cfg["routes"]) == ["own"]
    assert cfg["routes"]["own"]["legs"][0]["headings_deg"] == [90]      # defaults filled in


def test_the_selection_keeps_its_order(two_routes):
    two_routes["run_routes"] = ["own", "default"]
    assert list(validate(two_routes)["routes"]) == ["own", "default"]


@pytest.mark.parametrize("chosen, match", [(["nope"], "names a route that is not in the configuration"),
                                           ([], "run_routes"), (["own", "own"], "run_routes"),
                                           ([3], "run_routes")])
def test_a_bad_selection_names_the_key_and_value(two_routes, chosen, match):
    two_routes["run_routes"] = chosen
    with pytest.raises(InputError, match=match) as err:
        validate(two_routes)
    assert err.value.field.startswith("run_routes")


def test_an_own_vessel_on_an_own_route_alone_passes_the_checks(tmp_path):
    """The tanker's WAMIT RAOs on the default route and an own route, then on the own
    route alone: the checks (tables, RAO coverage) cover the selected route only."""
    vessel = {"vessel": {"rao_file": "tests/data/vessel/mss_tanker/tanker.4", "wamit_ulen_m": 1.0,
                         "hinge_m": [-100.0, 0.0, 110.0], "rao_reference_point_height_m": 9.46}}
    import yaml
    mine = tmp_path / "mine.yaml"
    mine.write_text(yaml.safe_dump({**vessel, "routes": {"own": OWN}}))
    alone = tmp_path / "alone.yaml"
    alone.write_text(yaml.safe_dump({**vessel, "routes": {"own": OWN}, "run_routes": ["own"]}))
    both = check_run([ROOT / "config/config.yaml", mine], base_dir=ROOT)
    assert list(both["routes"]) == ["default", "own"]
    out = check_run([ROOT / "config/config.yaml", alone], base_dir=ROOT)
    assert list(out["routes"]) == ["own"]


def test_the_default_routes_sea_states_no_longer_stop_an_own_vessel(tmp_path):
    """RAOs of a short range (0.4-2 rad/s, taken as zero above) do not cover the default route's long swells;
    assessed on an own route of 6-8 s seas alone, the same file passes."""
    import yaml
    table = tmp_path / "own.csv"
    table.write_text("# layout: matrix\n# hs_bins: edges\n# tz_bins: edges\n# values: counts\n"
                     "hs\\tz,6.0-7.0,7.0-8.0\n0.0-1.0,10,20\n1.0-2.0,3,40\n")
    mine = {"vessel": {"rao_file": "tests/data/vessel/capytaine_rao_split.nc",
                       "outside_rao_range": {"zero_above_rad_s": 2.0, "reason": "a test's stated band"}},
            "assessment": {"operability_tz_s": {"min": 6, "max": 8, "step": 0.5}},
            "routes": {"own": {"legs": [{"name": "only", "duration_h": 24, "scatter": str(table)}]}}}
    both, alone = tmp_path / "both.yaml", tmp_path / "alone.yaml"
    both.write_text(yaml.safe_dump(mine))
    alone.write_text(yaml.safe_dump({**mine, "run_routes": ["own"]}))
    with pytest.raises(InputError, match="route 'default'.*outside the RAO range"):
        check_run([ROOT / "config/config.yaml", both], base_dir=ROOT)
    assert list(check_run([ROOT / "config/config.yaml", alone], base_dir=ROOT)["routes"]) == ["own"]
