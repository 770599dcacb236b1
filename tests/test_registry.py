"""The registry of dataset layouts (jls/schemas/datasets.yaml) and its use."""

import copy
from pathlib import Path

import numpy as np
import pytest

from jls.config.dataset_hash import config_hash
from jls.errors import InputError
from jls.io import registry
from jls.sea.legs import read_leg
from jls.stages.sea_states import sea_states
from jls.stages.vessel_motion import vessel_motion

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def sea(cfg):
    route = cfg["routes"]["default"]
    legs = {leg["name"]: read_leg(leg, ROOT, cfg["sea"]["steepness_rule"], cfg["sea"]["gamma"],
                                        cfg["g_m_per_s2"])
            for leg in route["legs"]}
    return sea_states(dict(route, name="default"), legs, cfg["sea"]["steepness_rule"])


@pytest.mark.parametrize("text, ok", [
    ("m", True), ("kN s m-1", True), ("degree m-1", True), ("rad s-1", True), ("1", True),
    ("m or degree", False), ("m/m or rad/m", False), ("furlong", False), ("", False)])
def test_udunits_strings(text, ok):
    assert registry.valid_units(text) is ok


def test_every_registry_entry_is_complete():
    for name in registry.names():
        entry = registry.layout(name)
        assert entry["config"], name
        for var, spec in entry["variables"].items():
            assert spec["long_name"] and isinstance(spec["dims"], list), (name, var)   # [] a scalar
            units = spec.get("units")
            assert ("units_from" in spec) or units == "mixed" or registry.valid_units(units), (name, var)
            if units == "mixed":
                assert spec["units_note"], (name, var)
            if "units_from" in spec:
                assert spec["units_from"] in entry["coordinates"], (name, var)
        for coord, spec in entry["coordinates"].items():
            assert spec["long_name"], (name, coord)
            assert "units" not in spec or registry.valid_units(spec["units"]), (name, coord)


def test_builders_follow_the_registry(cfg, sea):
    registry.check(sea, "sea_states")
    motion = vessel_motion(cfg["vessel"], [90], base_dir=ROOT)
    registry.check(motion, "vessel_motion")
    assert motion["vessel_dof_units"].values.tolist()[3] == "rad m-1"


def test_check_names_what_is_wrong(sea):
    bad = sea.drop_vars("leg_weight")
    with pytest.raises(InputError, match="missing variable leg_weight"):
        registry.check(bad, "sea_states")
    bad = sea.assign(extra=("leg", np.zeros(sea.sizes["leg"])))
    with pytest.raises(InputError, match="undeclared variable"):
        registry.check(bad, "sea_states")
    bad = sea.copy()
    bad["hs_lower"] = bad["hs_lower"].transpose("hs", "leg").expand_dims(tz=bad["tz"].values)
    with pytest.raises(InputError, match="hs_lower has dims"):
        registry.check(bad, "sea_states")
    bad = sea.copy()
    bad["duration_h"].attrs["units"] = "hours or days"
    with pytest.raises(InputError, match="not a UDUNITS string"):
        registry.check(bad, "sea_states")


def test_config_hash_covers_only_what_a_dataset_depends_on(cfg):
    other = copy.deepcopy(cfg)
    other["assessment"]["criteria"]["relative_sway_m"] = 2.5
    changed = {n for n in registry.names()
               if config_hash(cfg, n, "default") != config_hash(other, n, "default")}
    # the screening scores route workability; measured_response holds each hour's utilisation
    assert changed == {"workability", "screening", "weather_windows", "voyage", "voyage_plan", "measured_response"}
    other = copy.deepcopy(cfg)
    other["routes"]["default"]["legs"][0]["duration_h"] = 60
    changed = {n for n in registry.names()
               if config_hash(cfg, n, "default") != config_hash(other, n, "default")}
    # measured_response reads the route's legs (its spectra legs' files, courses, headings)
    assert changed == {"sea_states", "workability", "screening", "weather_windows", "voyage",
                       "measured_response", "voyage_plan"}
    other = copy.deepcopy(cfg)
    other["screening"]["objective"] = "screening_sigma"
    changed = {n for n in registry.names()
               if config_hash(cfg, n, "default") != config_hash(other, n, "default")}
    assert changed == {"screening"}
    other = copy.deepcopy(cfg)
    other["tuggers"][1]["c_kN_s_per_m"] = 1500
    changed = {n for n in registry.names()
               if config_hash(cfg, n, "default") != config_hash(other, n, "default")}
    assert changed == {"response", "operability", "response_variants", "workability", "screening",
                       "weather_windows", "timedomain_cell", "tugger_studies", "voyage",
                       "verification_cell", "verification_wires", "measured_response", "voyage_plan"}
    other = copy.deepcopy(cfg)
    other["timedomain"]["cells"] = [{"candidate": "baseline", "heading_deg": 90, "hs_m": 2.0, "tz_s": 7.0}]
    changed = {n for n in registry.names()
               if config_hash(cfg, n, "default") != config_hash(other, n, "default")}
    assert changed == {"workability"}    # its verdicts; no cell's own settings change
    other = copy.deepcopy(cfg)
    other["verification"]["combinations"] = ["baseline"]
    other["verification"]["design_corner"]["enabled"] = True
    assert all(config_hash(cfg, n, "default") == config_hash(other, n, "default")
               for n in registry.names())    # which cells run, not what a cell computes
    other["verification"]["duration_s"] = 3600.0
    assert {n for n in registry.names()
            if config_hash(cfg, n, "default") != config_hash(other, n, "default")} == {"verification_cell",
                                                                                     "verification_study",
                                                                                     "verification_study_part"}
