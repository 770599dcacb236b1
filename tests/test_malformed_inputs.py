"""Catalogue of malformed inputs: every one stops with one line naming file, key and value.

Each case calls the library's readers and validators, or the checks the workflow runs
when it is parsed (:mod:`jls.config.workflow_inputs`), in-process so the catalogue stays fast;
a few go through ``snakemake -n`` (marked slow). Every case asserts the error type, a
single-line message holding the file and the key or value, and that nothing was written
under results/ or reports/. The case files are in tests/data/malformed/ (written by
make_cases.py there).
"""

import copy
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from jls.cli import main
from jls.config import plausible
from jls.config.loader import fill_defaults, load, load_yaml
from jls.config.workflow_inputs import (
    BEM_RAO_FILE,
    check_config_files,
    check_rao,
    job_errors,
    outside_roots,
    rao_file,
)
from jls.errors import InputError
from jls.plant.model import from_matrices
from jls.sea.hindcast import read_hindcast
from jls.sea.legs import read_leg
from jls.vessel.files import load_rao

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "malformed"
BASE = load_yaml(ROOT / "config" / "config.yaml")


@pytest.fixture(autouse=True)
def project_dir(tmp_path, monkeypatch):
    """Each case runs in an empty project directory that must stay without outputs."""
    monkeypatch.chdir(tmp_path)
    yield tmp_path
    assert not (tmp_path / "results").exists() and not (tmp_path / "reports").exists()


def one_line_error(call, *needles, kind=InputError):
    with pytest.raises(kind) as err:
        call()
    text = str(err.value)
    assert "\n" not in text, text
    for needle in needles:
        assert needle in text, f"{needle!r} not in {text!r}"
    return err.value


# --- configuration files: the YAML level -------------------------------------------------

YAML_CASES = [
    ("config_duplicate_key.yaml", ["key given twice", "m_kin_t", "line 11"]),
    ("config_nested_duplicate.yaml", ["key given twice", "splash_clearance_m"]),
    ("config_latin1.yaml", ["not a UTF-8 text file", "line 1"]),
    ("config_empty.yaml", ["empty configuration"]),
    ("config_comments_only.yaml", ["empty configuration"]),
    ("config_list.yaml", ["top level must be a mapping", "a list"]),
    ("config_scalar.yaml", ["top level must be a mapping"]),
    ("config_tab.yaml", ["tab character in the indentation", "line 10"]),
    ("config_syntax.yaml", ["not valid YAML", "line"]),
    ("config_yte.yaml", ["__use_yte__"]),
    ("config_alias_bomb.yaml", ["alias bomb"]),
]


@pytest.mark.parametrize("name, needles", YAML_CASES, ids=[c[0] for c in YAML_CASES])
def test_configuration_file(name, needles):
    one_line_error(lambda: load(DATA / name), name, *needles)


@pytest.mark.parametrize("name", ["config_duplicate_key.yaml", "config_latin1.yaml",
                                  "config_list.yaml", "config_empty.yaml", "no_such.yaml"])
def test_jls_modes_prints_one_line_and_exits_2(name, capsys):
    assert main(["modes", "--config", str(DATA / name)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("jls: error: ") and err.count("\n") == 1 and name in err


# --- configuration values: schema bounds, consistency, the file they came from ----------

def set_key(cfg, path, value):
    keys = path.replace("]", "").replace("[", ".").split(".")
    node = cfg
    for k in keys[:-1]:
        node = node[int(k)] if isinstance(node, list) else node.setdefault(k, {})
    last = keys[-1]
    if value is DELETE:
        if isinstance(node, list):
            node.pop(int(last))
        else:
            del node[last]
    elif isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value


DELETE = object()
WIRES = BASE["rigging"]["wires"]
LEG = BASE["routes"]["default"]["legs"][0]

VALUE_CASES = [
    # jacket: absurd magnitudes
    ("jacket.m_grav_t", -5, "jacket.m_grav_t"),
    ("jacket.m_grav_t", 1e9, "maximum"),
    ("jacket.m_kin_t", 1e-9, "jacket.m_kin_t"),
    ("jacket.ixx_t_m2", 1e30, "jacket.ixx_t_m2"),
    ("jacket.ixx_t_m2", 10, "minimum"),
    ("jacket.izz_t_m2", 1e30, "jacket.izz_t_m2"),
    ("jacket.z_p_m", -3, "jacket.z_p_m"),
    ("jacket.z_p_m", 900, "jacket.z_p_m"),
    ("jacket.ixx_t_m2", "4.55e6 t m2", "not of type"),
    ("jacket.ixx_t_m2", DELETE, "required key is missing"),
    # rigging
    ("rigging.h_drop_m", 5000, "rigging.h_drop_m"),
    ("rigging.wire_stiffness_kN_per_m", 1e30, "rigging.wire_stiffness_kN_per_m"),
    ("rigging.wire_stiffness_kN_per_m", 1, "rigging.wire_stiffness_kN_per_m"),
    ("rigging.damping_ratio", 0.9, "rigging.damping_ratio"),
    ("rigging.mass_lumping.block_mass_t", 1e6, "block_mass_t"),
    ("rigging.limits.hinge_height_m", 1e4, "hinge_height_m"),
    ("rigging.limits.hinge_height_m", 130.0, "given twice and the two disagree"),
    ("rigging.design_space.drop_height_m", [66.5, 50.0], "lower bound must be below"),
    ("rigging.wires[2].padeye_m", [-6.737, -24.444, 90.0], "not below its anchor"),
    ("rigging.wires[0].anchor_m", [1e5, 0.0, 0.0], "rigging.wires[0].anchor_m"),
    ("rigging.wires[1].name", WIRES[0]["name"], "wire names must be unique"),
    ("rigging.wires[3]", DELETE, "rigging.wires"),
    ("rigging.wire_segments", [{"length_m": 1, "ea_kN": 1}], "rigging"),
    # vessel
    ("vessel.hinge_m", [-215.263, 1.0, -99.998], "is the sign of z flipped"),
    ("vessel.hinge_m", [-215.263, 1.0, 1e5], "vessel.hinge_m[2]"),
    ("vessel.fairlead_drop_m", -1, "vessel.fairlead_drop_m"),
    ("vessel.outside_rao_range", "zero", "vessel.outside_rao_range"),
    ("vessel.outside_rao_range", {"zero_above_rad_s": 3.0}, "reason"),
    ("vessel.outside_rao_range", {"zero_above_rad_s": 300, "reason": "waves too short here"},
     "zero_above_rad_s"),
    ("vessel.outside_rao_range", {"reason": "no band is stated at all"}, "outside_rao_range"),
    ("vessel.rao_format", "xls", "vessel.rao_format"),
    ("vessel.rao_file", DELETE, "vessel.rao_file"),
    ("vessel.rao_reference_point_height_m", 500, "rao_reference_point_height_m"),
    ("vessel.rao_reference_point_height_m", -99.5, "the hinge would sit"),
    # sea and assessment
    ("sea.gamma", 20, "sea.gamma"),
    ("sea.steepness_rule", "none", "sea.steepness_rule"),
    ("sea.hs_in_bin", "lower", "sea.hs_in_bin"),
    ("assessment.exposure_h", 0, "assessment.exposure_h"),
    ("assessment.exposure_h", 1e6, "assessment.exposure_h"),
    ("assessment.operability_tz_s", {"min": 14.0, "max": 3.0, "step": 0.25}, "min must be below max"),
    ("assessment.operability_tz_s", {"min": 3.0, "max": 1e7, "step": 0.25}, "operability_tz_s.max"),
    ("assessment.operability_tz_s", {"min": 3.0, "max": 14.0, "step": 0.001}, "step"),
    ("assessment.criteria.relative_sway_m", -3, "relative_sway_m"),
    ("assessment.criteria.relative_roll_deg", 1000, "relative_roll_deg"),
    ("assessment.criteria", {}, "assessment.criteria"),
    ("assessment.mpm_cycles", "all", "assessment.mpm_cycles"),
    ("response.omega_step_rad_s", 1e-9, "response.omega_step_rad_s"),
    ("g_m_per_s2", 98.1, "g_m_per_s2"),
    ("jaket", {"m_grav_t": 1}, "unknown key"),
    ("g_m_per_s2", float("nan"), "finite"),
    # candidates
    ("candidates", [{"name": "baseline"}], "candidates[0].name"),
    ("candidates", [{"name": "a b"}], "candidates[0].name"),
    ("candidates", [{"name": "x"}, {"name": "x"}], "candidate names must be unique"),
    ("candidates", [{"name": "x", "top_spread_y_m": 1e4}], "top_spread_y_m"),
    ("candidates", [{"name": "x", "drop_height_m": 0}], "drop_height_m"),
    ("candidates", [{"name": "x", "drop_m": 60}], "unknown key"),
    ("candidate_grid", {k: np.linspace(40, 50, 15).tolist() for k in
                        ("top_spread_y_m", "bottom_spread_y_m", "bottom_spread_x_m",
                         "drop_height_m")}, "50627 rigging candidates"),
    ("candidate_grid", {"drop_height_m": np.linspace(50, 66, 51).tolist()}, "candidate_grid"),
    # tuggers
    ("tuggers", [{"name": "t", "c_kN_s_per_m": -1}], "tuggers[0].c_kN_s_per_m"),
    ("tuggers", [{"name": "t", "c_kN_s_per_m": 1e9}], "tuggers[0].c_kN_s_per_m"),
    ("tuggers", [{"name": "t", "c_kN_s_per_m": 1}, {"name": "t", "c_kN_s_per_m": 2}],
     "tugger names must be unique"),
    ("tuggers", [{"name": "a b", "c_kN_s_per_m": 1}], "tuggers[0].name"),
    ("tuggers", [], "tuggers"),
    ("tuggers", [{"name": f"t{i}", "c_kN_s_per_m": i} for i in range(21)], "tuggers"),
    ("tuggers", [{"name": "t"}], "tuggers[0].c_kN_s_per_m"),
    # routes
    ("routes", {}, "routes"),
    ("routes.default.legs", [], "routes.default.legs"),
    ("routes.default.legs[0].hindcast", {"file": "h.txt", "hs_edges_m": [0, 1],
                                         "tz_edges_s": [1, 2]}, "routes.default.legs[0]"),
    ("routes.default.legs[0].duration_h", DELETE, "duration_h"),
    ("routes.default.legs[0].duration_h", -1, "routes.default.legs[0].duration_h"),
    ("routes.default.legs[0].duration_h", 1e6, "routes.default.legs[0].duration_h"),
    ("routes.default.legs[0].name", "a b", "routes.default.legs[0].name"),
    ("routes.default.legs[1].name", LEG["name"], "leg names must be unique"),
    ("routes.default.legs[0].headings_deg", [400], "headings_deg[0]"),
    ("routes.default.legs[0].headings_deg", [90, 180], "heading_probability"),
    ("routes.default.legs[0].heading_probability", [0.6], "heading_probability"),
    ("routes.default.legs[0].layout", "wide", "layout"),
    ("routes.a b", {"legs": [LEG]}, "routes"),
    # keys the pipeline cannot honour
    ("plant_matrices", "tests/data/appendix_a1_plant.yaml", "is read by 'jls modes' only"),
    ("vessel.bem", {"box": {"length_m": 100, "beam_m": 30, "draught_m": 6, "kg_m": 5},
                    "radii_of_gyration_m": [10, 25, 26], "roll_damping_ratio": 0.05,
                    "omega_rad_s": {"min": 0.1, "max": 3.0, "n": 30}, "headings_deg": [90]},
     "give rao_file or bem, not both"),
    ("vessel.bem", {"box": {"length_m": 100, "beam_m": 30, "draught_m": 6, "kg_m": 5},
                    "radii_of_gyration_m": [10, 25, 26], "roll_damping_ratio": 0.05,
                    "omega_rad_s": {"min": 3.0, "max": 0.1, "n": 30}, "headings_deg": [90]},
     "vessel.bem.omega_rad_s"),
]


def _case_id(case):
    value = case[1]
    text = "deleted" if value is DELETE else repr(value)
    return f"{case[0]}={text[:24]}"


@pytest.mark.parametrize("key, value, needle", VALUE_CASES, ids=[_case_id(c) for c in VALUE_CASES])
def test_configuration_value_in_the_default_file(key, value, needle):
    cfg = copy.deepcopy(BASE)
    set_key(cfg, key, value)
    layers = [("config/config.yaml", cfg)]
    one_line_error(lambda: check_config_files(copy.deepcopy(cfg), layers),
                   "config/config.yaml", needle)


OVERRIDE_CASES = [
    ({"assessment": {"exposure_h": -2}}, "assessment.exposure_h"),
    ({"jacket": {"ixx_t_m2": 4.55e36}}, "jacket.ixx_t_m2"),
    ({"assessment": {"operability_tz_s": {"min": 14, "max": 3, "step": 0.25}}}, "min must be below"),
    ({"vessel": {"hinge_m": [-215.263, 1.0, -99.998]}}, "vessel.hinge_m[2]"),
    ({"plant_matrices": "m.yaml"}, "plant_matrices"),
]


@pytest.mark.parametrize("override, needle", OVERRIDE_CASES, ids=[c[1] for c in OVERRIDE_CASES])
def test_configuration_value_blamed_on_the_file_that_set_it(override, needle):
    merged = copy.deepcopy(BASE)
    for top, value in override.items():
        if isinstance(value, dict):
            for k, v in value.items():
                merged.setdefault(top, {})[k] = v
        else:
            merged[top] = value
    layers = [("config/config.yaml", BASE), ("my.yaml", override)]
    err = one_line_error(lambda: check_config_files(merged, layers), "my.yaml", needle)
    assert err.file == "my.yaml"
    err = one_line_error(lambda: check_config_files(merged, layers[:1], overrides=override),
                         "--config", needle)


def test_bem_without_capytaine_is_named(monkeypatch):
    import importlib.util
    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "capytaine" else real(name, *a))
    cfg = copy.deepcopy(BASE)
    del cfg["vessel"]["rao_file"]
    # the computed hull places its own waterline (its CoG): the default hull's reference
    # height and the hinge height derived from it would state the geometry a second time
    del cfg["vessel"]["rao_reference_point_height_m"]
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    cfg["vessel"]["bem"] = VALUE_CASES[-1][1] | {"omega_rad_s": {"min": 0.1, "max": 3, "n": 5}}
    one_line_error(lambda: check_config_files(cfg, [("config/config.yaml", cfg)]),
                   "vessel.bem", "Capytaine", "pip install")


def test_computed_raos_go_to_results_never_to_a_configured_path():
    cfg = copy.deepcopy(BASE)
    assert rao_file(cfg) == cfg["vessel"]["rao_file"]
    cfg["vessel"]["bem"] = {}
    assert rao_file(cfg) == BEM_RAO_FILE and BEM_RAO_FILE.startswith("results/")
    rules = [("ok", ["results/x.nc", "logs/a.log"]), ("abs", ["/home/user/hull.nc"]),
             ("up", ["results/../../hull.nc"]), ("cfg", ["config/vessel/x.nc"])]
    assert outside_roots(rules) == [("abs", "/home/user/hull.nc"),
                                    ("up", "results/../../hull.nc"),
                                    ("cfg", "config/vessel/x.nc")]


# --- route tables: scatter and hindcast through the leg reader ---------------------------

SCATTER_CASES = [
    ("scatter_zero_bytes.csv", ["empty file"]),
    ("scatter_comments_only.csv", ["no table"]),
    ("scatter_no_rows.csv", ["empty table"]),
    ("scatter_header_only_row.csv", ["empty table"]),
    ("scatter_semicolons.csv", ["separated by semicolons", "line 5"]),
    ("scatter_tabs.csv", ["separated by tabs", "line 5"]),
    ("scatter_latin1.csv", ["not a UTF-8 text file"]),
    ("scatter_hs_cm.csv", ["Hs above 25 m", "legs[north]", "50"]),
    ("scatter_tz_hz.csv", ["Tz outside 1-25 s", "legs[north]", "0.15"]),
    ("scatter_tz_tenths.csv", ["Tz outside 1-25 s", "55"]),
    ("scatter_swapped.csv", ["Hs and Tz swapped", "hs 5.5 m, tz 1.5 s"]),
    ("no_such.csv", ["file not found", "legs[north].scatter"]),
]
SEA_DIR = ROOT / "tests" / "data" / "sea"
SCATTER_CASES += [(f"../sea/{p.name}", []) for p in sorted(SEA_DIR.glob("bad_*.csv"))]


@pytest.mark.parametrize("name, needles", SCATTER_CASES, ids=[c[0] for c in SCATTER_CASES])
def test_scatter_table(name, needles):
    leg = {"name": "north", "scatter": str(DATA / name), "duration_h": 10}
    one_line_error(lambda: read_leg(leg, ".", "study", 3.3, 9.81), Path(name).name, *needles)


HINDCAST_CASES = [
    ("hindcast_empty.txt", {}, ["empty hindcast file"]),
    ("hindcast_latin1.txt", {}, ["not a UTF-8 text file"]),
    ("hindcast_commas.txt", {}, ["line 1"]),
    ("hindcast_outside.txt", {}, ["1 records lie outside the bins", "outside: report",
                                  "legs[south].hindcast.bins"]),
    ("hindcast_ok.txt", {"hs_edges_m": [2, 1, 3]}, ["legs[south].hindcast.hs_edges_m",
                                                   "strictly increasing"]),
    ("hindcast_ok.txt", {"tz_edges_s": [5]}, ["legs[south].hindcast.tz_edges_s"]),
    ("hindcast_swapped.txt", {"hs_edges_m": [0, 10], "tz_edges_s": [1, 2]},
     ["Hs and Tz swapped"]),
    ("no_such.txt", {}, ["file not found", "legs[south].hindcast.file"]),
]
HINDCAST_CASES += [(f"../sea/{p.name}", {}, ["line"])
                   for p in sorted(SEA_DIR.glob("hindcast_bad_*.txt"))]


@pytest.mark.parametrize("name, edges, needles", HINDCAST_CASES,
                         ids=[f"{c[0]}{sorted(c[1])}" for c in HINDCAST_CASES])
def test_hindcast(name, edges, needles):
    h = {"file": str(DATA / name), "hs_edges_m": [0, 1, 2, 3], "tz_edges_s": [3, 5, 7, 9],
         "outside": "error"}
    h.update(edges)
    leg = {"name": "south", "hindcast": h, "duration_h": 10}
    one_line_error(lambda: read_leg(leg, ".", "study", 3.3, 9.81), Path(name).name, *needles)


def test_hindcast_outside_report_counts_instead():
    h = {"file": str(DATA / "hindcast_outside.txt"), "hs_edges_m": [0, 1, 2, 3],
         "tz_edges_s": [3, 5, 7, 9], "outside": "report"}
    ds = read_leg({"name": "south", "hindcast": h, "duration_h": 10}, ".", "study", 3.3, 9.81)
    assert ds.attrs["n_outside"] == 1 and ds.attrs["n_records"] == 2
    assert read_hindcast(DATA / "hindcast_ok.txt").shape == (2, 2)


# --- RAO files: each format -------------------------------------------------------------

RAO_CASES = [
    ("rao_truncated.4", {}, ["incomplete grid", "8 of 36", "period 5 s, heading 180 deg"]),
    ("rao_missing_dof.4", {}, ["missing dof", "pitch"]),
    ("rao_six_columns.4", {}, ["expected 7 columns", "line 4"]),
    ("rao_text.4", {}, ["not a number", "line 4", "abc"]),
    ("rao_reim_mismatch.4", {}, ["Re/Im columns disagree", "line 6"]),
    ("rao_mode7.4", {}, ["integer 1..6", "line 3"]),
    ("rao_duplicate_row.4", {}, ["duplicate row", "line 37"]),
    ("rao_degrees.4", {}, ["looks like deg/m", "RAO peaks at"]),
    ("rao_periods_as_omega.4", {}, ["outside 0.01-10 rad/s"]),
    ("rao_ok.4", {"abscissa": "omega"}, ["outside 0.01-10 rad/s"]),
    ("rao_negative_period.4", {}, ["must be positive", "line 2"]),
    ("rao_empty.4", {}, ["no data lines"]),
    ("rao_latin1.4", {}, ["cannot read file"]),
    ("rao_ok.4", {"ulen": -1.0}, ["ULEN must be a positive length"]),
    ("rao_deg_undeclared.csv", {}, ["looks like deg/m", "rotation_units: deg/m"]),
    ("rao_deg_declared.csv", {"rotation_units": "rad/m"}, ["declares rotation_units: deg/m"]),
    ("rao_bad_rotation_units.csv", {}, ["rotation_units must be", "line 1", "grad/m"]),
    ("rao_periods_in_omega.csv", {}, ["outside 0.01-10 rad/s", "periods or Hz"]),
    ("rao_hz.csv", {}, ["outside 0.01-10 rad/s"]),
    ("rao_csv_truncated.csv", {}, ["incomplete grid", "omega 1.2 rad/s, heading 180 deg"]),
    ("rao_csv_unknown_dof.csv", {}, ["unknown dof", "line 4", "heav"]),
    ("rao_csv_missing_column.csv", {}, ["missing column dof", "line 1"]),
    ("rao_csv_both_freq.csv", {}, ["exactly one of omega_rad_s or period_s"]),
    ("rao_csv_negative_amp.csv", {}, ["negative amplitude", "line 3"]),
    ("rao_csv_ragged.csv", {}, ["expected 5 columns", "line 3"]),
    ("rao_csv_duplicate.csv", {}, ["duplicate row", "line 38"]),
    ("rao_csv_empty.csv", {}, ["empty file"]),
    ("rao_ok.csv", {"phase": "behind"}, ["phase must be 'lead' or 'lag'"]),
    ("rao_not_netcdf.nc", {}, ["cannot read NetCDF file"]),
    ("rao_unknown_suffix.txt", {}, ["cannot infer the RAO format"]),
    ("rao_ok.4", {"format": "xls"}, ["unknown RAO format"]),
    ("no_such.4", {}, ["RAO file not found"]),
]


@pytest.mark.parametrize("name, kwargs, needles", RAO_CASES,
                         ids=[f"{c[0]}{sorted(c[1])}" for c in RAO_CASES])
def test_rao_file(name, kwargs, needles):
    one_line_error(lambda: load_rao(DATA / name, **kwargs), name, *needles)


def test_valid_rao_files_read():
    assert load_rao(DATA / "rao_ok.4").sizes["omega"] == 3
    deg = load_rao(DATA / "rao_deg_declared.csv")
    rad = load_rao(DATA / "rao_ok.csv")
    np.testing.assert_allclose(abs(deg["rao"].sel(dof="roll")),
                               abs(rad["rao"].sel(dof="roll")) * 57.3 * np.pi / 180, rtol=1e-4)


def _netcdf_case(tmp_path, edit):
    from jls.vessel.rao import save_rao
    ds = load_rao(DATA / "rao_ok.4")
    path = save_rao(ds, tmp_path / "cases" / "rao.nc")
    import xarray as xr
    with xr.open_dataset(path) as raw:
        raw = raw.load()
    raw = edit(raw)
    out = tmp_path / "cases" / "bad.nc"
    raw.to_netcdf(out)
    return out


NETCDF_CASES = [
    ("no rao variable", lambda d: d.drop_vars("rao"), ["rao"]),
    ("nan value", lambda d: d.assign(rao=d["rao"].where(d["omega"] < 1.0)), ["non-finite RAO value"]),
    ("omega descending", lambda d: d.assign_coords(omega=-d["omega"].values + 10), ["omega"]),
    ("complex labels", lambda d: d.assign_coords(complex=["a", "b"]), ["complex dimension"]),
    ("rotations in degrees", lambda d: d.assign(rao=d["rao"] * xr_scale(d)), ["looks like deg/m"]),
]


def xr_scale(d):
    import xarray as xr
    return xr.DataArray([1, 1, 1, 57.3 * 30, 1, 1], dims="dof", coords={"dof": d["dof"].values})


@pytest.mark.parametrize("what, edit, needles", NETCDF_CASES, ids=[c[0] for c in NETCDF_CASES])
def test_netcdf_rao_file(tmp_path, what, edit, needles):
    path = _netcdf_case(tmp_path, edit)
    one_line_error(lambda: load_rao(path), "bad.nc", *needles)


# --- RAO against the routes, as the workflow checks it when parsed ----------------------

def test_rao_range_short_of_the_sea_states_stops_at_parse_time():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["vessel"]["rao_file"] = str(DATA / "rao_ok.csv")         # 0.3-1.2 rad/s
    err = one_line_error(lambda: check_rao(cfg, {"north": ([5.0, 6.0], [90.0])}),
                         "rao_ok.csv", "route 'north'", "outside the RAO range",
                         "vessel.outside_rao_range")
    assert err.value == 5.0


def test_route_heading_missing_from_the_rao_file():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["vessel"]["rao_file"] = str(DATA / "rao_ok.4")
    cfg["vessel"]["wamit_ulen_m"] = 1.0
    cfg["vessel"]["outside_rao_range"] = {"zero_above_rad_s": 0.5, "zero_below_rad_s": 0.3,
                                          "reason": "test of the heading check only"}
    one_line_error(lambda: check_rao(cfg, {"north": ([8.0], [45.0])}), "rao_ok.4",
                   "heading 45", "not in the RAO file")


def test_response_arrays_too_large_for_memory_stop_at_parse_time():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["candidates"] = [{"name": f"c{i}", "drop_height_m": 55 + 0.01 * i} for i in range(1500)]
    cfg["tuggers"] = [{"name": f"t{i}", "c_kN_s_per_m": 100 * i} for i in range(10)]
    cfg["response"] = {"omega_step_rad_s": 0.0005}
    # 1500 candidates' boundary cells would exceed timedomain.max_cells: name the few
    # (every assessed candidate, the default, is refused for this many; test_timedomain_recommendation)
    cfg["timedomain"]["boundary_candidates"] = ["baseline"]
    check_config_files(copy.deepcopy(cfg), [("config/config.yaml", cfg)])   # each bound holds
    cfg["vessel"]["rao_file"] = str(ROOT / BASE["vessel"]["rao_file"])
    one_line_error(lambda: check_rao(cfg, {"r": ([8.0], [0.0, 90.0, 180.0])},
                                     [("config/config.yaml", cfg)]),
                   "config/config.yaml", "response.omega_step_rad_s", "1566 candidates at once",
                   "transfer-function values")


def test_missing_rao_file_names_the_configuration():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["vessel"]["rao_file"] = "vessel/none.nc"
    one_line_error(lambda: check_rao(cfg, {"r": ([8.0], [90.0])}, [("my.yaml", cfg)]),
                   "my.yaml", "vessel.rao_file", "none.nc")


# --- plant matrices --------------------------------------------------------------------

PLANT_CASES = [
    ("plant_duplicate_key.yaml", ["key given twice", "zeta"]),
    ("plant_latin1.yaml", ["not a UTF-8 text file"]),
    ("plant_empty.yaml", ["empty plant matrices file"]),
    ("plant_list.yaml", ["top level must be a mapping"]),
    ("plant_missing_K.yaml", ["missing matrix", "K"]),
    ("plant_3x3.yaml", ["must be 4x4", "K"]),
    ("plant_text.yaml", ["4x4 array of numbers", "K"]),
    ("plant_nan.yaml", ["non-finite entry", "K"]),
    ("plant_asymmetric.yaml", ["must be symmetric", "K"]),
    ("plant_negative_mass.yaml", ["positive diagonal", "M"]),
    ("plant_unknown_key.yaml", ["unknown key", "Cc"]),
    ("plant_zeta_and_C.yaml", ["C or zeta, not both"]),
    ("plant_zeta_range.yaml", ["zeta", "0.98"]),
    ("plant_tab.yaml", ["tab character"]),
    ("plant_duplicate.json", ["key given twice", "M"]),
    ("plant_invalid.json", ["not valid JSON", "line 1"]),
    ("plant_unstable.yaml", ["K"]),
    ("no_such.yaml", ["not found"]),
]


@pytest.mark.parametrize("name, needles", PLANT_CASES, ids=[c[0] for c in PLANT_CASES])
def test_plant_matrices_file(name, needles):
    one_line_error(lambda: from_matrices(DATA / name, g=9.81, zeta=0.0098), name, *needles)


def test_plausibility_of_a_valid_route_and_vessel():
    """The shipped inputs pass every plausibility check (the checks are not too tight)."""
    plausible.check_config(load(ROOT / "config" / "config.yaml"), "config/config.yaml")
    for leg in BASE["routes"]["default"]["legs"]:
        read_leg({**leg, "scatter": str(ROOT / leg["scatter"])}, ".", "study", 3.3, 9.81)
    load_rao(ROOT / BASE["vessel"]["rao_file"])


# --- failed jobs: the one jls line out of the logs --------------------------------------

def test_onerror_lines_come_from_the_job_logs(tmp_path):
    log = tmp_path / "logs" / "r" / "response"
    log.mkdir(parents=True)
    (log / "leg-abc.log").write_text(
        "2026-01-01 00:00:00,000 INFO jls.response: leg a\n"
        "2026-01-01 00:00:01,000 ERROR jls.response: input error: x.4: omega: bad (got 1)\n")
    (tmp_path / "logs" / "r" / "plant.log").write_text("2026 INFO jls.plant.model: fine\n")
    lines = job_errors(tmp_path / "logs")
    assert lines == [f"jls response ({log / 'leg-abc.log'}): input error: x.4: omega: bad (got 1)"]
    assert job_errors(tmp_path / "logs", since=4e9) == []
    shutil.rmtree(tmp_path / "logs")


# --- through Snakemake (slow): what only the real parse shows ---------------------------

def _workdir(tmp_path):
    work = tmp_path / "wf"
    work.mkdir()
    shutil.copy(ROOT / "Snakefile", work)
    shutil.copytree(ROOT / "workflow", work / "workflow")
    shutil.copytree(ROOT / "config", work / "config")
    return work


def _snakemake(cwd, *args):
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "1", "-n", *args],
                       cwd=cwd, capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


@pytest.mark.slow
def test_snakemake_duplicate_key_in_configfile_names_it(tmp_path):
    work = _workdir(tmp_path)
    (work / "my.yaml").write_text("sea:\n  gamma: 3.3\n  gamma: 1.0\n")
    code, out = _snakemake(work, "--configfile", "my.yaml")
    assert code != 0
    assert "my.yaml: line 3: key given twice" in out and "gamma" in out


@pytest.mark.slow
def test_snakemake_unknown_route_is_named(tmp_path):
    code, out = _snakemake(_workdir(tmp_path), "reports/nosuch.pdf")
    assert code != 0
    assert "route 'nosuch' is not in the configuration (routes: default)" in out
    assert "KeyError" not in out


@pytest.mark.slow
def test_snakemake_never_targets_a_configured_rao_path(tmp_path):
    work = _workdir(tmp_path)
    outside = tmp_path / "precious_hull.nc"
    outside.write_bytes(b"do not touch")
    text = (work / "config" / "config.yaml").read_text()
    (work / "config" / "config.yaml").write_text(text.replace(
        "rao_file: config/vessel/representative_hlv.nc",
        f"rao_file: {outside}\n  bem: {{box: {{length_m: 100, beam_m: 30, draught_m: 6, "
        "kg_m: 5}, radii_of_gyration_m: [10, 25, 26], roll_damping_ratio: 0.05, "
        "omega_rad_s: {min: 0.1, max: 3.0, n: 30}, headings_deg: [90]}"))
    code, out = _snakemake(work)
    assert code != 0 and "give rao_file or bem, not both" in out
    assert outside.read_bytes() == b"do not touch"


# --- jls check: the workflow's parse-time checks from the command line -------------------

def test_jls_check_passes_the_shipped_configuration(project_dir, capsys):
    shutil.copytree(ROOT / "config", project_dir / "config")
    assert main(["check"]) == 0
    assert "config/config.yaml: valid; routes default (2 legs)" in capsys.readouterr().out


@pytest.mark.parametrize("content, needles", [
    (b"sea:\n  gamma: 3.3 # caf\xe9\n", ["not a UTF-8 text file", "line 2"]),
    (b"sea:\n  gamma: 3.3\n  gamma: 1.0\n", ["line 3: key given twice"]),
    (b"jacket:\n  ixx_t_m2: 4.55e+36\n", ["jacket.ixx_t_m2", "maximum"]),
    (b"routes:\n  default:\n    legs:\n      - {name: a, scatter: nope.csv, duration_h: 5}\n",
     ["route 'default', leg 'a'", "nope.csv", "file not found"]),
])
def test_jls_check_names_the_configfile(project_dir, capsys, content, needles):
    shutil.copytree(ROOT / "config", project_dir / "config")
    (project_dir / "my.yaml").write_bytes(content)
    assert main(["check", "--config", "my.yaml"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    for needle in needles:
        assert needle in err, err
    if b"nope" not in content:
        assert "my.yaml" in err
