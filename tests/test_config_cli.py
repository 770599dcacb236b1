"""Configuration validation and the ``jls modes`` command."""

import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from jls.cli import main
from jls.config.builders import plant_from_config
from jls.config.loader import load, load_yaml, validate
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
    with pytest.raises(InputError, match=r"wire 'port-aft-padeye' is slack or in compression"
                                         r".*tension -\d{6}\.\d kN"):
        plant_from_config(cfg)


def test_baseline_out_of_balance_names_the_residual(cfg):
    # The anchors of the wires to the forward padeyes moved 30 m aft: every wire stays
    # taut, but no tensions can hold the jacket in surge and pitch (pitch is the larger
    # residual of the inverted-V layout, whose anchors of a side share the beam tip).
    for i in (0, 2):
        cfg["rigging"]["wires"][i]["anchor_m"][0] = -30.0
    validate(cfg)
    with pytest.raises(InputError, match=r"not hold the jacket in equilibrium: pitch residual 6\.\d+e-02"):
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


def _schema_defaults(node=None, found=None):
    """Names of every configuration key the schema gives a default."""
    from jls.config.loader import schema
    node = schema() if node is None else node
    found = set() if found is None else found
    if isinstance(node, dict):
        for key, sub in node.get("properties", {}).items():
            if isinstance(sub, dict) and "default" in sub:
                found.add(key)
        for value in node.values():
            _schema_defaults(value, found)
    elif isinstance(node, list):
        for value in node:
            _schema_defaults(value, found)
    return found


def test_defaults_come_from_the_schema(cfg):
    for section in ("sea", "assessment", "response", "tuggers"):
        del cfg[section]
    for key in ("hinge_m", "fairlead_drop_m", "fairlead_half_span_m"):
        del cfg["vessel"][key]
    for leg in cfg["routes"]["default"]["legs"]:
        del leg["headings_deg"], leg["heading_probability"]
    out = validate(cfg)
    assert out["sea"] == {"gamma": 3.3, "steepness_rule": "study", "hs_in_bin": "centre",
                          "spreading": {"wind": "cos2s:4", "swell": "cos2s:13"}}
    crit = dict(out["assessment"]["criteria"])
    wire = crit.pop("wire_tension")
    assert crit == {"relative_sway_m": 3.0, "tip_air_gap_m": 1.5}
    assert wire["floor_fraction_of_static"] == 0.1 and wire["daf_limit"] == 1.1
    assert wire["swl_factors"] == {} and "safe_working_load_kN" not in wire
    assert out["assessment"]["tip_clearance"] == {"crest": "forristall_long_crested"}
    assert out["assessment"]["exposure_h"] == 3.0 and out["assessment"]["mpm_cycles"] == "response"
    assert out["tuggers"] == [{"name": "none", "c_kN_s_per_m": 0, "max_force_kN": 1000, "min_force_kN": 20,
                              "lag_s": 0, "attachment_half_width_m": 22.5}]
    assert out["vessel"]["hinge_m"] == [-215.263, 1.0, 99.998]
    assert out["vessel"]["fairlead_drop_m"] == 82.5
    leg = out["routes"]["default"]["legs"][0]
    assert leg["headings_deg"] == [90] and leg["heading_probability"] == [1.0]
    # the filled configuration is itself valid and unchanged by a second pass
    assert validate(copy.deepcopy(out)) == out


def test_no_code_supplies_its_own_default_for_a_schema_key():
    names = _schema_defaults()
    assert {"gamma", "headings_deg", "exposure_h", "hinge_m"} <= names
    offenders = []
    for path in [*ROOT.joinpath("jls").rglob("*.py"), *ROOT.joinpath("workflow").rglob("*.py"),
                 *ROOT.joinpath("workflow").rglob("*.smk")]:
        text = path.read_text()
        text = text.replace("attrs.get(", "")        # dataset attributes: see the registry
        offenders += [f"{path.relative_to(ROOT)}: .get({name!r}, ...)" for name in names
                      if f'.get("{name}",' in text or f".get('{name}'," in text]
    assert not offenders, offenders


def test_several_headings_need_their_probabilities(cfg):
    leg = cfg["routes"]["default"]["legs"][0]
    leg["headings_deg"] = [60, 90]
    del leg["heading_probability"]
    with pytest.raises(InputError, match=r"heading_probability"):
        validate(cfg)


def test_partial_override_is_merged_over_the_default(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    over = tmp_path / "override.yaml"
    over.write_text("jacket: {m_kin_t: 8000}\nassessment: {criteria: {relative_sway_m: 2.5}}\n")
    cfg = load(CONFIG, over)
    assert cfg["jacket"]["m_kin_t"] == 8000 and cfg["jacket"]["m_grav_t"] == 7650
    crit = {k: v for k, v in cfg["assessment"]["criteria"].items() if k != "wire_tension"}
    assert crit == {"relative_sway_m": 2.5, "tip_air_gap_m": 1.5}
    assert cfg["assessment"]["criteria"]["wire_tension"]["floor_fraction_of_static"] == 0.1
    assert main(["modes", "--json", "--config", str(over)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["M"][0][0] == pytest.approx(8000)


def test_error_names_the_file_the_bad_value_came_from(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    over = tmp_path / "override.yaml"
    over.write_text("jacket: {m_grav_t: -5}\n")
    with pytest.raises(InputError) as err:
        load(CONFIG, over)
    assert str(err.value).startswith(str(over)) and "jacket.m_grav_t" in str(err.value)
    assert "config/config.yaml" not in str(err.value)
    over.write_text("sea: {gamma: 3.0}\n")
    bad = dict(load_yaml(CONFIG))
    bad["jacket"] = dict(bad["jacket"], ixx_t_m2=-1)
    base = tmp_path / "base.yaml"
    base.write_text(yaml.safe_dump(bad))
    with pytest.raises(InputError) as err:
        load(base, over)
    assert str(err.value).startswith(str(base))
