"""Configuration validation and the ``jls modes`` command."""

import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from jls.assembly import plant_from_config
from jls.cli import main
from jls.config import load, load_yaml, validate
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"


@pytest.fixture()
def cfg():
    return copy.deepcopy(load_yaml(CONFIG))


def write(tmp_path, data):
    path = tmp_path / "config.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


@pytest.mark.parametrize("key, value, field", [
    (("jacket", "m_grav_t"), -7650, "jacket.m_grav_t"),
    (("jacket", "m_kin_t"), 0, "jacket.m_kin_t"),
    (("jacket", "ixx_t_m2"), 0.0, "jacket.ixx_t_m2"),
    (("jacket", "izz_t_m2"), -1.0, "jacket.izz_t_m2"),
    (("rigging", "wire_stiffness_kN_per_m"), 0, "rigging.wire_stiffness_kN_per_m"),
    (("rigging", "h_drop_m"), float("nan"), "rigging.h_drop_m"),
    (("jacket", "z_p_m"), float("inf"), "jacket.z_p_m"),
    (("jacket", "m_grav_t"), "heavy", "jacket.m_grav_t"),
])
def test_bad_values_name_key_and_value(cfg, key, value, field):
    cfg[key[0]][key[1]] = value
    with pytest.raises(InputError) as err:
        validate(cfg, source="my.yaml")
    text = str(err.value)
    assert "my.yaml" in text and field in text and repr(value) in text


def test_missing_key_is_named(cfg):
    del cfg["jacket"]["ixx_t_m2"]
    with pytest.raises(InputError, match=r"jacket\.ixx_t_m2.*required"):
        validate(cfg, source="my.yaml")


def test_unknown_key_is_rejected(cfg):
    cfg["rigging"]["wire_stifness"] = 1.0
    with pytest.raises(InputError, match="wire_stifness"):
        validate(cfg)


def test_padeye_above_anchor_is_rejected(cfg):
    cfg["rigging"]["wires"][2]["padeye_m"][2] = 90.0     # above the hinge
    with pytest.raises(InputError, match=r"wires\[2\]\.padeye_m.*not below its anchor"):
        validate(cfg)


def test_slack_wire_is_named_with_its_tension(cfg):
    # Every anchor 5 m to port: the sway and roll balance then needs two wires to push,
    # by hundreds of meganewtons, far from any round-off.
    for wire in cfg["rigging"]["wires"]:
        wire["anchor_m"][1] += 5.0
    validate(cfg)
    with pytest.raises(InputError, match=r"wire 'port-fwd-anchor' is slack or in compression"
                                         r".*tension -\d{6}\.\d kN"):
        plant_from_config(cfg)


def test_baseline_out_of_balance_names_the_residual(cfg):
    # Forward anchors moved 38 m aft: every wire stays taut, but no tensions can hold
    # the jacket in surge and pitch.
    for i in (0, 2):
        cfg["rigging"]["wires"][i]["anchor_m"][0] = -30.0
    validate(cfg)
    with pytest.raises(InputError, match=r"not hold the jacket in equilibrium: surge residual -3\.\d+e-01"):
        plant_from_config(cfg)


def test_segments_in_series_replace_stiffness(cfg):
    del cfg["rigging"]["wire_stiffness_kN_per_m"]
    cfg["rigging"]["wire_segments"] = [{"length_m": 38.61, "ea_kN": 9.64e6},
                                       {"length_m": 23.60, "ea_kN": 2.0e6}]
    p = plant_from_config(validate(cfg))
    assert p.wire_stiffness[0] == pytest.approx(63270, rel=1e-4)


def test_both_stiffness_forms_is_an_error(cfg):
    cfg["rigging"]["wire_segments"] = [{"length_m": 38.61, "ea_kN": 9.64e6}]
    with pytest.raises(InputError):
        validate(cfg)


def test_mass_lumping_when_inertial_mass_absent(cfg):
    del cfg["jacket"]["m_kin_t"]
    p = plant_from_config(validate(cfg))
    # 4 x 190 t at 38.61 m on ~62.5 m wires: about +290 t (eq. 3.3).
    assert 7650 + 270 < p.M[0, 0] < 7650 + 300


def test_modes_json_contract(capsys):
    assert main(["modes", "--json", "--config", str(CONFIG)]) == 0
    out = json.loads(capsys.readouterr().out)
    for key in ["dof", "natural_period_s", "damping_ratio", "energy_fraction", "M", "K", "Kb", "C",
                "anchors_m", "padeyes_m", "cog_depth_m", "wire_stiffness_kN_per_m", "tension_kN",
                "unstretched_length_m", "m_grav_t", "g_m_per_s2"]:
        assert key in out, key
    assert out["dof"] == ["sway", "heave", "roll", "yaw"]
    assert len(out["energy_fraction"]) == 4 and len(out["energy_fraction"][0]) == 4
    assert out["cog_depth_m"] == pytest.approx(60.091 + 22.41)
    assert sum(out["tension_kN"]) > 7650 * 9.81       # inclined wires carry more than W


def test_modes_table_and_matrices_file(capsys, tmp_path, cfg):
    assert main(["modes", "--config", str(CONFIG)]) == 0
    text = capsys.readouterr().out
    assert "period" in text and "Kb" in text and "Wires" in text
    cfg["plant_matrices"] = str(ROOT / "tests" / "data" / "appendix_a1_plant.yaml")
    assert main(["modes", "--json", "--config", str(write(tmp_path, cfg))]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["natural_period_s"][0] == pytest.approx(15.70, rel=2e-3)


def test_user_error_prints_one_line_no_traceback(tmp_path, cfg):
    cfg["jacket"]["m_grav_t"] = -1
    path = write(tmp_path, cfg)
    r = subprocess.run([sys.executable, "-m", "jls.cli", "modes", "--config", str(path)],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert "Traceback" not in r.stderr
    assert "jacket.m_grav_t" in r.stderr and "-1" in r.stderr


def test_missing_config_file_is_named(tmp_path):
    with pytest.raises(InputError, match="nope.yaml"):
        load(tmp_path / "nope.yaml")
