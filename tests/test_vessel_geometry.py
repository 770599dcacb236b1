"""One geometry (issue 18, item 2): the vessel block places the waterline, the hinge's
height above water is derived from it and vessel.hinge_m, never given twice."""

from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import rigging_from_config
from jls.config.loader import HINGE_HEIGHT_TOLERANCE_M, load, load_yaml, merge, validate
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"


def raw():
    return load_yaml(CONFIG)


def test_hinge_height_is_derived_from_the_vessel_block():
    cfg = load(CONFIG)
    v = cfg["vessel"]
    expected = v["hinge_m"][2] - v["rao_reference_point_m"][2] + v["rao_reference_point_height_m"]
    assert cfg["rigging"]["limits"]["hinge_height_m"] == pytest.approx(expected)
    assert expected == pytest.approx(119.46, abs=HINGE_HEIGHT_TOLERANCE_M)   # the study's
    # the splash clearance uses it
    rig = rigging_from_config(cfg)
    assert rig.limits.hinge_height_m == pytest.approx(expected)
    assert rig.limits.max_drop() == pytest.approx(expected - 48.0 - 5.0)


def test_a_lower_waterline_moves_the_splash_clearance_and_nothing_is_given_twice():
    cfg = raw()
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    merge(cfg, {"vessel": {"rao_reference_point_height_m": 15.0}})
    cfg = validate(cfg)
    assert cfg["rigging"]["limits"]["hinge_height_m"] == pytest.approx(99.998 + 15.0)
    # the reference point may be given in another frame: only the difference counts
    cfg = raw()
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    merge(cfg, {"vessel": {"hinge_m": [-215.263, 1.0, 109.998], "rao_reference_point_m": [0, 0, 10.0],
                           "rao_reference_point_height_m": 15.0}})
    assert validate(cfg)["rigging"]["limits"]["hinge_height_m"] == pytest.approx(114.998)


def test_the_hinge_height_given_twice_and_inconsistently_is_an_error(tmp_path):
    over = tmp_path / "my.yaml"
    over.write_text("rigging:\n  limits:\n    hinge_height_m: 125.0\n")
    with pytest.raises(InputError) as err:
        load(CONFIG, over)
    e = err.value
    assert e.field == "rigging.limits.hinge_height_m" and e.value == 125.0
    assert str(over) in str(e.file)
    assert "given twice" in e.message and "119.460" in e.message
    # within the tolerance it is the same geometry
    over.write_text("rigging:\n  limits:\n    hinge_height_m: 119.465\n")
    assert load(CONFIG, over)["rigging"]["limits"]["hinge_height_m"] == pytest.approx(119.46)
    # and the vessel block moved under a given limit is caught the same way
    over.write_text("vessel:\n  rao_reference_point_height_m: 10.0\n"
                    "rigging:\n  limits:\n    hinge_height_m: 119.46\n")
    with pytest.raises(InputError) as err:
        load(CONFIG, over)
    assert err.value.field == "rigging.limits.hinge_height_m" and "109.998" in err.value.message


def test_neither_way_given_is_an_error_and_the_old_way_places_the_waterline():
    cfg = raw()
    cfg["vessel"].pop("rao_reference_point_height_m")
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    with pytest.raises(InputError) as err:
        validate(cfg, source="config/config.yaml")
    assert err.value.field == "vessel.rao_reference_point_height_m"
    assert "required key is missing" in err.value.message
    cfg = raw()
    cfg["vessel"].pop("rao_reference_point_height_m")
    cfg["rigging"]["limits"]["hinge_height_m"] = 110.0
    cfg = validate(cfg)
    assert cfg["vessel"]["rao_reference_point_height_m"] == pytest.approx(110.0 - 99.998)


def test_a_hinge_below_the_water_is_refused():
    cfg = raw()
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    cfg["vessel"]["rao_reference_point_height_m"] = -99.5
    with pytest.raises(InputError) as err:
        validate(cfg)
    assert err.value.field == "vessel.rao_reference_point_height_m"
    assert "0.498 m above the water" in err.value.message


def test_bem_gives_the_reference_height_of_the_computed_hull():
    cfg = raw()
    cfg["vessel"].pop("rao_file")
    cfg["vessel"].pop("rao_reference_point_height_m")
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    box = {"length_m": 382, "beam_m": 124, "draught_m": 20, "kg_m": 39.462}
    cfg["vessel"]["bem"] = {"box": box, "radii_of_gyration_m": [43, 95, 99],
                            "roll_damping_ratio": 0.02, "omega_rad_s": {"min": 0.1, "max": 3, "n": 50},
                            "headings_deg": [90]}
    out = validate(cfg)
    assert out["vessel"]["rao_reference_point_height_m"] == pytest.approx(19.462)
    assert out["rigging"]["limits"]["hinge_height_m"] == pytest.approx(119.46)
    cfg["vessel"]["rao_reference_point_height_m"] = 0.0       # given too, and otherwise
    with pytest.raises(InputError) as err:
        validate(cfg)
    assert err.value.field == "vessel.rao_reference_point_height_m"


def test_datasets_carry_the_hinge_height_and_the_lever_arm():
    from jls.stages.vessel_motion import vessel_motion
    cfg = load(CONFIG)
    m = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    assert m.attrs["hinge_height_above_water_m"] == pytest.approx(119.46, abs=0.01)
    np.testing.assert_allclose(m.attrs["hinge_lever_arm_m"], [-215.263, 1.0, 99.998])
    assert m.attrs["rao_reference_point_height_m"] == pytest.approx(19.462)
    assert m.attrs["vessel_data"] == "representative"
    assert m.attrs["vessel_statement"].startswith("The vessel motions are those of a representative")
    assert "times the study's" in m.attrs["vessel_sway_against_study"]
