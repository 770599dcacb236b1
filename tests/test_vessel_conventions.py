"""RAO conventions (jls.vessel.conventions): stated or refused, converted, and the long-wave
phase relations that catch a flipped convention with the numbers; a convention the
relations cannot see (the x axis) moves the hinge as predicted."""

import copy
from pathlib import Path

import numpy as np
import pytest

from jls.config.loader import fill_defaults, load
from jls.config.workflow_inputs import check_rao
from jls.errors import InputError
from jls.vessel import load_rao, point_motion
from jls.vessel.conventions import AFT_SIGNS, resolve_conventions, to_jls
from jls.vessel.export import aqwa_text, orcaflex_text, write_text
from jls.vessel.phase_checks import check_long_wave_phases

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ROOT / "config" / "vessel" / "representative_hlv.nc"
TANKER = ROOT / "tests" / "data" / "vessel" / "mss_tanker" / "tanker.4"


@pytest.fixture(scope="module")
def hull():
    return load_rao(DEFAULT)


def with_rao(ds, values, directions=None):
    out = ds.copy()
    out["rao"] = ds["rao"].copy(data=values)
    if directions is not None:
        out = out.assign_coords(wave_direction=directions)
    return out


# --- stating conventions -------------------------------------------------------------------

def test_resolve_takes_the_files_and_completes_from_the_configuration():
    got = resolve_conventions({"phase": "lag", "direction": "to"}, None)
    assert got == {"phase": "lag", "direction": "to", "x_axis": "forward"}
    got = resolve_conventions({"phase": None, "direction": "to"}, {"phase": "lead", "x_axis": "aft"})
    assert got == {"phase": "lead", "direction": "to", "x_axis": "aft"}


@pytest.mark.parametrize("given, configured, needles", [
    ({"phase": None, "direction": "to"}, None, ["vessel.rao_conventions.phase", "does not state"]),
    ({"phase": "lag", "direction": None}, {}, ["vessel.rao_conventions.direction", "from or to"]),
    ({"phase": "lag", "direction": "to"}, {"phase": "lead"}, ["rao_conventions.phase", "'lag'", "'lead'"]),
    ({"phase": "lag", "direction": "to"}, {"x_axis": "port"}, ["rao_conventions.x_axis", "'port'"]),
    ({"phase": "lag", "direction": "to"}, {"heading": "to"}, ["unknown RAO convention", "heading"]),
])
def test_a_missing_contradicted_or_unknown_convention_is_refused(given, configured, needles):
    with pytest.raises(InputError) as err:
        resolve_conventions(given, configured, file="f.yml")
    for needle in needles:
        assert needle in str(err.value)


def test_to_jls_conjugates_lags_and_turns_directions(hull):
    v = hull["rao"].values
    beta = np.degrees(hull["wave_direction"].values)
    out, b = to_jls(v, beta, {"phase": "lag", "direction": "to", "x_axis": "forward"})
    assert np.array_equal(out, np.conj(v)) and np.array_equal(b, beta)
    out, b = to_jls(v, beta, {"phase": "lead", "direction": "from", "x_axis": "forward"})
    assert np.array_equal(out, v) and np.allclose(b, (beta + 180) % 360)
    out, b = to_jls(v, beta, {"phase": "lead", "direction": "to", "x_axis": "aft"})
    assert np.array_equal(out, v * AFT_SIGNS) and np.allclose(b, (beta + 180) % 360)
    out, b = to_jls(v, beta, {"phase": "lead", "direction": "from", "x_axis": "aft"})
    assert np.array_equal(out, v * AFT_SIGNS) and np.array_equal(b, beta)


# --- the long-wave phase relations ---------------------------------------------------------

def test_physical_files_pass(hull):
    assert check_long_wave_phases(hull) == []
    if TANKER.exists():
        assert check_long_wave_phases(load_rao(TANKER, ulen=246.0)) == []


def flipped(hull, kind):
    v = hull["rao"].values
    beta = hull["wave_direction"].values
    if kind == "phase":                     # lags read as leads
        return with_rao(hull, np.conj(v))
    if kind == "direction":                 # "from" read as "to"
        return with_rao(hull, v, np.mod(beta + np.pi, 2 * np.pi))
    if kind in ("roll", "sway", "pitch", "heave"):
        sign = np.ones(6)
        sign[{"sway": 1, "heave": 2, "roll": 3, "pitch": 4}[kind]] = -1
        return with_rao(hull, v * sign)
    if kind == "trough":                    # phases on the trough read as on the crest
        return with_rao(hull, -v)
    raise ValueError(kind)


@pytest.mark.parametrize("kind, needles", [
    ("phase", ["following seas (0 deg) the pitch leads the heave by -89.2 deg", "+90"]),
    ("direction", ["head seas (180 deg) the pitch leads the heave by 89.2 deg", "'from' read as 'to'"]),
    ("pitch", ["the pitch leads the heave by -90.8 deg", "bow up"]),
    ("roll", ["beam seas (75 deg) the roll leads the sway by 179.8 deg"]),
    ("sway", ["beam seas (75 deg) the roll leads the sway by"]),
    ("heave", ["the heave phase in waves from", "180.0 deg"]),
    ("trough", ["the heave phase", "trough (180)"]),
])
def test_each_flipped_convention_is_caught_with_the_numbers(hull, kind, needles):
    with pytest.raises(InputError) as err:
        check_long_wave_phases(flipped(hull, kind), file="v.nc")
    text = str(err.value)
    assert "v.nc: vessel.rao_conventions" in text and "62.83 s" in text
    for needle in needles:
        assert needle in text, text


def test_short_files_are_not_judged_and_say_so(hull):
    short = hull.isel(omega=slice(30, None))
    notes = check_long_wave_phases(flipped(short, "phase"))
    assert len(notes) == 1 and "phase conventions were not checked" in notes[0]


def test_the_x_axis_is_not_seen_by_the_phases_but_moves_the_hinge_as_predicted(hull, tmp_path):
    path = write_text(aqwa_text(hull), tmp_path / "v.lis")     # AQWA's axes are the model's
    aft = load_rao(path, conventions={"x_axis": "aft"})
    assert check_long_wave_phases(aft) == []             # a turned frame is as physical
    # the file's x aft: the motion at r (file frame) is that at R r in the jls frame, its
    # horizontal components turned, with the wave from beta - 180
    r = np.array([-215.263, 1.0, 99.998])
    turn = np.array([-1.0, -1.0, 1.0])
    ahead = point_motion(aft, r * turn).values                      # jls frame
    for j, b in enumerate(hull["wave_direction"].values):
        k = int(np.argmin(np.abs(np.mod(aft["wave_direction"].values - b - np.pi + 1, 2 * np.pi) - 1)))
        theirs = point_motion(hull, r).values[:, j] * turn
        assert np.allclose(ahead[:, k], theirs, rtol=1e-12, atol=1e-15)
    # and the hinge sway in beam seas changes: the lever arm's other end
    beam = int(np.argmin(np.abs(hull["wave_direction"].values - np.pi / 2)))
    as_read = np.abs(point_motion(aft, r).values[:, :, 1])
    assert np.max(np.abs(as_read[:, beam] - np.abs(point_motion(hull, r).values[:, beam, 1]))) > 0.1


# --- in the workflow's parse-time check ----------------------------------------------------

def test_the_workflow_check_stops_a_wrongly_declared_file(hull, tmp_path):
    cfg = fill_defaults(copy.deepcopy(load(ROOT / "config" / "config.yaml")))
    text = orcaflex_text(hull, vessel_type="HLV", draught="d")
    good = write_text(text, tmp_path / "good.yml")
    bad = write_text(text.replace("RAOPhaseConvention: lags", "RAOPhaseConvention: leads"),
                     tmp_path / "bad.yml")
    need = {"default": ([6.0, 8.0], [90.0, 180.0])}
    cfg["vessel"].update(rao_file=str(good), rao_format="orcaflex", orcaflex_vessel_type="HLV",
                         orcaflex_draught="d")
    assert check_rao(cfg, need) == []
    cfg["vessel"]["rao_file"] = str(bad)
    with pytest.raises(InputError) as err:
        check_rao(cfg, need)
    assert "bad.yml: vessel.rao_conventions" in str(err.value)
    assert "pitch leads the heave by -89.2 deg" in str(err.value)


def test_rao_conventions_and_orcaflex_keys_only_where_they_apply(tmp_path):
    cfg = fill_defaults(copy.deepcopy(load(ROOT / "config" / "config.yaml")))
    cfg["vessel"]["rao_file"] = str(DEFAULT)
    need = {"default": ([6.0, 8.0], [90.0])}
    cfg["vessel"]["rao_conventions"] = {"phase": "lead"}
    with pytest.raises(InputError, match="vessel.rao_conventions.*OrcaFlex and AQWA"):
        check_rao(cfg, need)
    del cfg["vessel"]["rao_conventions"]
    cfg["vessel"]["orcaflex_draught"] = "d"
    with pytest.raises(InputError, match="vessel.orcaflex_draught.*OrcaFlex vessel-type files only"):
        check_rao(cfg, need)
