"""Catalogue of malformed inputs, continued: values that are each within their bounds but
wrong together, YAML that two readers read differently, and inputs without bounds.

As in tests/test_malformed_inputs.py: each case stops with one line naming the file, the
key or line and the value, and nothing is written under results/ or reports/ (the
autouse fixture ``project_dir`` checks it). Case files are in tests/data/malformed/
(written by make_cases.py there).
"""

import copy
import math
import os
import shutil
from pathlib import Path

import numpy as np
import pytest
from test_malformed_inputs import BASE, DATA, ROOT, one_line_error, project_dir, set_key  # noqa: F401

from jls.cli import main
from jls.config.loader import fill_defaults, load, validate
from jls.config.plausible import check_rao_magnitudes
from jls.config.workflow_inputs import check_config_files, check_rao, check_run
from jls.errors import InputError
from jls.io import yamlio
from jls.sea.legs import read_leg
from jls.vessel.files import load_rao

TANKER = ROOT / "tests" / "data" / "vessel" / "mss_tanker" / "tanker.4"


# --- YAML read differently by YAML 1.1 (Snakemake) and 1.2; keys that are not text -------

YAML_CASES = [
    ("config_sexagesimal.yaml", ["line 144", "'50:00'", "sexagesimal", "3000"]),
    ("config_route_no.yaml", ["line 137", "'NO'", "boolean False", "keys must be text"]),
    ("config_route_number.yaml", ["line 137", "'2024'", "a number", "keys must be text"]),
    ("config_yes.yaml", ["line 58", "'yes'", "boolean True"]),
    ("config_octal.yaml", ["line 92", "'017'", "octal"]),
    ("config_underscore.yaml", ["line 10", "'7_650'", "underscores"]),
    ("config_date.yaml", ["line 160", "'2026-01-05'", "a date"]),
]


@pytest.mark.parametrize("name, needles", YAML_CASES, ids=[c[0] for c in YAML_CASES])
def test_yaml_read_differently_by_two_readers(name, needles):
    one_line_error(lambda: load(DATA / name), name, *needles)


@pytest.mark.parametrize("name", [c[0] for c in YAML_CASES[:3]])
def test_jls_check_refuses_them_in_a_configfile(project_dir, capsys, name):
    shutil.copytree(ROOT / "config", project_dir / "config")
    shutil.copy(DATA / name, project_dir / "my.yaml")
    assert main(["check", "--config", "my.yaml"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "my.yaml: line" in err


def test_one_reading_of_numbers_everywhere():
    """4.55e6 is a number for jls check and for the workflow (which runs on the project
    loader's reading, jls.config.workflow_inputs.merged_config); quoted text stays text."""
    data = yamlio.loads("a: 4.55e6\nb: 'NO'\nc: 1.5e-3\nd: '50:00'\n")
    assert data == {"a": 4.55e6, "b": "NO", "c": 1.5e-3, "d": "50:00"}


def test_keys_that_are_not_text_are_refused_in_validation_too():
    cfg = copy.deepcopy(BASE)
    cfg["routes"][2024] = cfg["routes"]["default"]
    one_line_error(lambda: validate(cfg, source="config/config.yaml"), "config/config.yaml",
                   "routes", "2024", "a number, not text")


# --- values against each other -------------------------------------------------------

CROSS_CASES = [
    # masses: a weight in kN as a mass in t
    ("jacket.m_grav_t", 75046.5, ["jacket.m_grav_t", "0.103 x", "75046.5"]),
    ("jacket.m_kin_t", 771.9, ["jacket.m_grav_t", "inertial mass m_kin_t 771.9 t"]),
    # inertia against the jacket's size
    ("jacket.ixx_t_m2", 4.55e7, ["jacket.ixx_t_m2", "radius of gyration", "2.4 x"]),
    ("jacket.ixx_t_m2", 4.55e5, ["jacket.ixx_t_m2", "0.24 x"]),
    ("jacket.izz_t_m2", 3.286e7, ["jacket.izz_t_m2", "2.3 x"]),
    ("jacket.izz_t_m2", 3.286e5, ["jacket.izz_t_m2", "0.23 x"]),
    # static tensions against the wires and the tension criteria
    ("assessment.criteria.max_wire_tension_kN", 19000, ["max_wire_tension_kN", "19534 kN",
                                                        "above the safe working load"]),
    ("assessment.criteria.min_wire_tension_kN", 19600, ["min_wire_tension_kN", "19503 kN",
                                                        "below the no-slack floor"]),
    ("rigging.wire_capacity", {"breaking_load_kN": 40000, "max_static_fraction": 0.4},
     ["rigging.wire_capacity.breaking_load_kN", "0.488 of the breaking load"]),
    ("rigging.wire_stiffness_kN_per_m", 630, ["rigging.wire_stiffness_kN_per_m", "stretches",
                                              "630"]),
    # tugger slopes against the critical damping of the sway mode
    ("tuggers[2].c_kN_s_per_m", 1.0e6, ["tuggers[2].c_kN_s_per_m", "162 x the critical damping",
                                        "N s/m"]),
    ("timedomain.slope_sweep.slopes_kN_s_per_m", [300, 90000], [
        "timedomain.slope_sweep.slopes_kN_s_per_m[1]", "14.6 x"]),
    # angles in degrees that look like radians
    ("routes.default.legs[0].headings_deg", [1.5708], ["routes.default.legs[0].headings_deg",
                                                       "looks like radians", "90 deg"]),
    ("routes.default.legs[1].headings_deg", [0.7854], ["legs[1].headings_deg", "45 deg"]),
    ("screening.envelope.heading_deg", 1.5708, ["screening.envelope.heading_deg"]),
    ("assessment.criteria.relative_roll_deg", 0.0175, ["relative_roll_deg", "1 deg if it was radians"]),
    ("rigging.limits.fore_aft_lead_max_deg", 0.873, ["fore_aft_lead_max_deg", "50 deg"]),
    # durations against the exposure; fractions as percent
    ("routes.default.legs[1].duration_h", 2.5, ["legs[1].duration_h", "less than the 3 h exposure"]),
    ("assessment.max_saturation_fraction", 1, ["max_saturation_fraction", "100 %", "0.01"]),
    ("assessment.max_saturation_fraction", 0.5, ["max_saturation_fraction", "50 %"]),
    # time-domain cells: a candidate and a heading the pipeline has
    ("timedomain.cells", [{"hs_m": 2.0, "tz_s": 7.0, "heading_deg": 45}],
     ["timedomain.cells[0].heading_deg", "route 'default'", "45"]),
    ("timedomain.cells", [{"hs_m": 2.0, "tz_s": 7.0, "candidate": "detuned2"}],
     ["timedomain.cells[0].candidate", "detuned2"]),
    ("timedomain.boundary_candidates", ["baseline", "nope"], ["boundary_candidates[1]", "nope"]),
    ("candidates", [{"name": "detuned__x", "drop_height_m": 62}], ["candidates[0].name", "__"]),
    # the screening needs a motion criterion
    ("assessment.criteria", {"max_wire_tension_kN": 30000}, ["assessment.criteria",
                                                            "all wire tensions"]),
]


def _ids(cases):
    return [f"{c[0]}={str(c[1])[:20]}" for c in cases]


@pytest.mark.parametrize("key, value, needles", CROSS_CASES, ids=_ids(CROSS_CASES))
def test_values_checked_against_each_other(key, value, needles):
    cfg = copy.deepcopy(BASE)
    set_key(cfg, key, value)
    one_line_error(lambda: check_config_files(copy.deepcopy(cfg), [("config/config.yaml", cfg)]),
                   "config/config.yaml", *needles)


def test_a_configfile_slip_is_named_in_that_file():
    cfg = copy.deepcopy(BASE)
    over = {"jacket": {"m_grav_t": 75046.5}}
    layers = [("config/config.yaml", cfg), ("my.yaml", over)]
    merged = copy.deepcopy(cfg)
    merged["jacket"]["m_grav_t"] = 75046.5
    one_line_error(lambda: check_config_files(merged, layers), "my.yaml", "jacket.m_grav_t")


def test_warnings_not_errors():
    """Slopes between twice and ten times the critical damping are allowed with a
    warning; a tension criterion with the screening on is stated on page 1."""
    cfg = copy.deepcopy(BASE)
    cfg["tuggers"].append({"name": "stiff", "c_kN_s_per_m": 20000})
    cfg["assessment"]["criteria"]["max_wire_tension_kN"] = 25000
    from jls.config.workflow_inputs import config_warnings
    lines = config_warnings(check_config_files(cfg, [("config/config.yaml", cfg)]))
    assert any("tugger 'stiff'" in w and "3.2 x the critical damping" in w for w in lines)
    assert any("max_wire_tension_kN is applied" in w for w in lines)


def test_the_shipped_configuration_passes_every_cross_check():
    cfg = load(ROOT / "config" / "config.yaml")
    from jls.config.cross_checks import check_values
    assert check_values(cfg) == []


# --- RAO magnitudes in the long-wave limit: ULEN, heave, rotation units ------------------

@pytest.mark.parametrize("ulen, factor", [(382.0, 380.0), (10.0, 9.95), (3.5, 3.48)])
def test_wamit_ulen_too_large(ulen, factor):
    rao = load_rao(TANKER, ulen=ulen)
    err = one_line_error(lambda: check_rao_magnitudes(rao, {}, file=TANKER), "tanker.4",
                         "vessel.wamit_ulen_m", "too small by a factor",
                         "the file's own ULEN would be about 1.005 m")
    assert err.value == ulen
    assert f"{factor:.3g}" in str(err)


def test_wamit_ulen_too_small_by_10_is_caught_by_either_check():
    one_line_error(lambda: load_rao(TANKER, ulen=0.1), "tanker.4", "rad/m")
    rao = load_rao(TANKER, ulen=0.3)        # peaks below 0.5 rad/m: the long-wave check
    one_line_error(lambda: check_rao_magnitudes(rao, {}, file=TANKER), "too large by a factor 3.34",
                   "the file's own ULEN would be about 1.001 m")


@pytest.mark.parametrize("name, needles", [
    ("rao_heave_cm.csv", ["rao[heave]", "40 s", "99.9 m/m", "tends to 1 m/m"]),
    ("rao_rotations_x10.csv", ["vessel.rao_file", "pitch in head or following seas is 9.99 x"]),
    ("rao_rotations_per_length.csv", ["vessel.rao_file", "too small by a factor 20"]),
])
def test_rao_magnitudes(name, needles):
    rao = load_rao(DATA / name)
    one_line_error(lambda: check_rao_magnitudes(rao, {}, file=DATA / name), name, *needles)


def test_rao_magnitudes_of_real_hulls_and_a_warning_when_too_short():
    for path, kw in [(TANKER, {"ulen": 1.0}), (ROOT / BASE["vessel"]["rao_file"], {}),
                     (DATA / "rao_physical.csv", {}),
                     (ROOT / "tests" / "data" / "vessel" / "capytaine_rao_split.nc", {})]:
        assert check_rao_magnitudes(load_rao(path, **kw), {}, file=path) == []
    short = check_rao_magnitudes(load_rao(DATA / "rao_ok.csv"), {}, file=DATA / "rao_ok.csv")
    assert len(short) == 1 and "too short for the long-wave checks" in short[0]


def test_wrong_ulen_stops_the_workflow_check():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["vessel"].update(rao_file=str(TANKER), wamit_ulen_m=246.0)
    one_line_error(lambda: check_rao(cfg, {"default": ([6.0, 8.0], [90.0])}), "tanker.4",
                   "vessel.wamit_ulen_m", "246")


def test_heading_interpolation_is_honoured_by_the_parse_time_check():
    cfg = fill_defaults(copy.deepcopy(BASE))
    cfg["vessel"]["rao_file"] = str(ROOT / BASE["vessel"]["rao_file"])
    need = {"default": ([6.0, 8.0], [80.0, 90.0])}              # 80 deg: not in the file
    one_line_error(lambda: check_rao(cfg, need), "heading 80.0 deg is not in the RAO file")
    cfg["vessel"]["heading_interpolation"] = "linear"
    assert check_rao(cfg, need) == []
    cfg["vessel"].update(heading_interpolation="nearest", heading_tolerance_deg=2.0)
    one_line_error(lambda: check_rao(cfg, need), "beyond heading_tolerance_deg 2")


# --- bounded: special files, sizes, candidate counts and the DAG -------------------------

def _leg(path):
    return {"name": "north", "scatter": str(path), "duration_h": 10}


def test_a_named_pipe_as_table_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "table.csv"
    os.mkfifo(fifo)
    one_line_error(lambda: read_leg(_leg(fifo), ".", "study", 3.3, 9.81), "table.csv",
                   "legs[north].scatter", "a named pipe")
    h = {"name": "south", "hindcast": {"file": str(fifo), "hs_edges_m": [0, 1], "tz_edges_s": [1, 2],
                                       "outside": "error"}, "duration_h": 10}
    one_line_error(lambda: read_leg(h, ".", "study", 3.3, 9.81), "legs[south].hindcast.file", "pipe")


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_device_as_table_or_configuration_is_refused(device):
    one_line_error(lambda: read_leg(_leg(device), ".", "study", 3.3, 9.81), device,
                   "a character device")
    one_line_error(lambda: load(device), device, "a character device")
    one_line_error(lambda: load_rao(device, format="csv"), device, "not a regular file")


def test_a_huge_table_is_refused_before_it_is_read(tmp_path):
    big = tmp_path / "big.csv"
    with open(big, "wb") as fh:                   # sparse: takes no disk space
        fh.truncate(300 * (1 << 20))
    one_line_error(lambda: read_leg(_leg(big), ".", "study", 3.3, 9.81), "big.csv", "300 MB",
                   "more than the 200 MB")


@pytest.mark.parametrize("key, value, needles", [
    ("screening.grid_points", {k: 201 for k in ("top_spread_y_m", "bottom_spread_y_m",
                                                "bottom_spread_x_m", "drop_height_m")},
     ["screening.grid_points", "1.632e+09 candidates"]),
    ("screening.grid_points", {"top_spread_y_m": 201, "drop_height_m": 201, "bottom_spread_x_m": 3},
     ["screening.grid_points", "1.212e+05"]),
    ("response.chunk_candidates", 1, ["response.chunk_candidates", "jobs, more than 10000"]),
    ("timedomain.max_cells", 5000, ["timedomain.max_cells", "2000"]),
], ids=["four-variable grid", "three-variable grid", "one candidate a job", "max cells"])
def test_candidates_and_jobs_are_bounded_before_the_dag(key, value, needles):
    cfg = copy.deepcopy(BASE)
    set_key(cfg, key, value)
    if key == "response.chunk_candidates":
        cfg["candidate_grid"] = {"drop_height_m": list(np.linspace(50, 66, 50)),
                                 "top_spread_y_m": list(np.linspace(36, 60, 50)),
                                 "bottom_spread_y_m": [31.0, 33.0, 35.0, 37.0, 39.0]}
    one_line_error(lambda: check_config_files(copy.deepcopy(cfg), [("config/config.yaml", cfg)]),
                   "config/config.yaml", *needles)


def test_jls_check_states_a_configuration_warning(project_dir, capsys):
    shutil.copytree(ROOT / "config", project_dir / "config")
    (project_dir / "my.yaml").write_text("assessment:\n  criteria:\n    relative_sway_m: 3.0\n"
                                         "    max_wire_tension_kN: 25000\n")
    assert main(["check", "--config", "my.yaml"]) == 0
    out = capsys.readouterr().out
    assert "valid" in out and "jls: warning: the rigging screening ranks" in out
    summary = check_run([Path("config/config.yaml"), Path("my.yaml")])
    assert len(summary["warnings"]) == 1 and math.isfinite(len(summary["routes"]))


def test_input_errors_are_one_line_for_every_case_here():
    """Every InputError message of this module's checks is a single line (the catalogue's
    rule), including the long cross-check explanations."""
    cfg = copy.deepcopy(BASE)
    cfg["jacket"]["m_grav_t"] = 75046.5
    with pytest.raises(InputError) as err:
        check_config_files(cfg, [("config/config.yaml", cfg)])
    assert "\n" not in str(err.value)
