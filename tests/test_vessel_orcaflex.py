"""OrcaFlex vessel-type reader: a real OrcaFlex text data file, every convention setting
converted (checked against the same RAOs written in the jls convention), the flipped
conventions the long-wave checks catch, and malformed files refused naming key and line."""

from pathlib import Path

import numpy as np
import pytest

from jls.config.plausible import check_rao_magnitudes
from jls.errors import InputError
from jls.vessel import load_rao, mirror_headings
from jls.vessel.orcaflex import COLUMNS, read_orcaflex_vessel_type
from jls.vessel.phase_checks import check_long_wave_phases

ROOT = Path(__file__).resolve().parents[1]
REAL = ROOT / "tests" / "data" / "vessel" / "orcaflex" / "vessel_type1.yml"
DEFAULT = ROOT / "config" / "vessel" / "representative_hlv.nc"

SETTINGS = {"RAOResponseUnits": "degrees", "RAOWaveUnit": "amplitude",
            "WavesReferredToBy": "frequency (rad/s)", "RAOPhaseConvention": "lags",
            "RAOPhaseUnitsConvention": "degrees", "RAOPhaseRelativeToConvention": "crest",
            "SurgePositive": "forward", "SwayPositive": "port", "HeavePositive": "up",
            "RollPositiveStarboard": "down", "PitchPositiveBow": "down", "YawPositiveBow": "port",
            "Symmetry": "None"}


@pytest.fixture(scope="module")
def hull():
    """The shipped hull at a few frequencies (its longest period first) and directions."""
    ds = load_rao(DEFAULT)
    return ds.isel(omega=[0, 5, 20, 40, 75], wave_direction=[0, 6, 12])


def write(path, ds, settings=None, rows=None, drop=(), draughts=("D1",), extra="", origin=None):
    """An OrcaFlex text data file of ``ds`` with ``settings`` (``drop``: keys left out);
    ``rows(omega, amp, lag_deg)`` gives each row's 13 numbers (default: the jls values as
    lags in degrees, rotations in degrees, frequency in rad/s)."""
    settings = {**SETTINGS, **(settings or {})}
    rao = ds["rao"].transpose("omega", "wave_direction", "dof").values
    scale = np.array([1, 1, 1] + [180 / np.pi] * 3)

    def default_rows(w, amp, lag):
        return [w] + [v for pair in zip(amp, lag) for v in pair]

    rows = rows or default_rows
    ref = origin or ds.attrs["reference_point_m"]
    text = ["General:", "  UnitsSystem: SI", "VesselTypes:", "  - Name: HLV"]
    text += [f"    {k}: {v}" for k, v in settings.items() if k not in drop]
    text += [extra] if extra else []
    text += ["    Draughts:"]
    for name in draughts:
        text += [f"      - Name: {name}", "        DisplacementRAOs:",
                 f"          RAOOrigin: [{', '.join(repr(float(v)) for v in ref)}]",
                 "          PhaseOrigin: [~, ~, ~]", "          RAOs:"]
        for j, beta in enumerate(np.degrees(ds["wave_direction"].values)):
            text += [f"            - RAODirection: {float(beta)!r}", f"              {', '.join(COLUMNS)}:"]
            for i, w in enumerate(ds["omega"].values):
                amp = np.abs(rao[i, j]) * scale
                lag = -np.degrees(np.angle(rao[i, j]))
                text.append("                - [" + ", ".join(repr(float(v)) for v in
                                                             rows(w, amp, lag)) + "]")
    path.write_text("\n".join(text) + "\n")
    return path


def same(a, b, tol=1e-12):
    assert np.allclose(a["omega"].values, b["omega"].values, rtol=tol, atol=0)
    assert np.allclose(a["wave_direction"].values, b["wave_direction"].values, atol=1e-12)
    assert np.abs(a["rao"].values - b["rao"].values).max() <= tol * np.abs(b["rao"].values).max()


# --- a real OrcaFlex file ----------------------------------------------------------------

def test_real_orcaflex_file_reads_with_its_conventions_and_long_wave_limits():
    ds = read_orcaflex_vessel_type(REAL)
    # 24 periods 4-22 s; the rows of period 0 and Infinity skipped in each of 9 tables;
    # 0-180 deg given, Symmetry xz plane adds 202.5-337.5
    assert ds.sizes == {"omega": 24, "wave_direction": 16, "dof": 6}
    assert ds.attrs["orcaflex_limit_rows_skipped"] == 18
    assert ds.attrs["reference_point_m"] == [2.53, 0.0, -1.974]
    assert ds.attrs["orcaflex_vessel_type"] == "Vessel type1"
    assert ds.attrs["orcaflex_defaults_taken"] == "none"
    assert 2 * np.pi / ds["omega"].values[0] == pytest.approx(22.0)
    assert check_rao_magnitudes(ds, {}, file=REAL) == []
    assert check_long_wave_phases(ds, file=REAL) == []
    r = ds["rao"].isel(omega=0)
    phase = np.degrees(np.angle(r.values))
    heading = np.degrees(ds["wave_direction"].values)
    following, beam, head = (int(np.argmin(abs(heading - h))) for h in (0, 90, 180))
    # the jls convention at 22 s: heave with the crest, surge a quarter period behind the
    # crest in following seas and ahead of it in head seas, beam-sea sway and roll -90 deg
    assert abs(r.values[following, 2]) == pytest.approx(0.979, abs=0.001)
    assert abs(phase[following, 2]) < 2 and abs(phase[head, 2]) < 2
    assert phase[following, 0] == pytest.approx(-91.4, abs=0.1)
    assert phase[head, 0] == pytest.approx(91.4, abs=0.1)
    assert phase[beam, 1] == pytest.approx(-90.0, abs=0.1)
    assert phase[beam, 3] == pytest.approx(-94.3, abs=0.1)
    # pitch follows the slope: k at 22 s in deep water, +90 following, -90 head
    k = ds["omega"].values[0] ** 2 / 9.81
    assert abs(r.values[following, 4]) / k == pytest.approx(1.0, abs=0.02)
    assert phase[following, 4] == pytest.approx(90.2, abs=0.1)
    assert phase[head, 4] == pytest.approx(-90.2, abs=0.1)


def test_xz_symmetry_adds_the_mirror_image(tmp_path):
    whole = read_orcaflex_vessel_type(REAL)
    half = REAL.read_text().replace("Symmetry: xz plane", "Symmetry: None")
    ds = read_orcaflex_vessel_type(_put(tmp_path / "half.yml", half))
    assert ds.sizes["wave_direction"] == 9
    same(whole, mirror_headings(ds), tol=1e-15)


def _put(path, text):
    path.write_text(text)
    return path


# --- each convention setting converted -----------------------------------------------------

def test_the_file_in_the_jls_convention_reads_to_the_same_rao(hull, tmp_path):
    ds = read_orcaflex_vessel_type(write(tmp_path / "v.yml", hull))
    same(ds, hull)
    assert ds.attrs["reference_point_m"] == hull.attrs["reference_point_m"]
    assert ds.attrs["source_format"] == "orcaflex"


@pytest.mark.parametrize("settings, rows", [
    ({"RAOPhaseConvention": "leads"},
     lambda w, a, p: [w] + [v for pair in zip(a, -p) for v in pair]),
    ({"RAOResponseUnits": "radians"},
     lambda w, a, p: [w] + [v for pair in zip(a * np.radians([57.29577951308232] * 3 + [1] * 3),
                                              p) for v in pair]),
    ({"WavesReferredToBy": "period (s)"},
     lambda w, a, p: [2 * np.pi / w] + [v for pair in zip(a, p) for v in pair]),
    ({"WavesReferredToBy": "frequency (Hz)"},
     lambda w, a, p: [w / (2 * np.pi)] + [v for pair in zip(a, p) for v in pair]),
    ({"RAOPhaseUnitsConvention": "radians"},
     lambda w, a, p: [w] + [v for pair in zip(a, np.radians(p)) for v in pair]),
    ({"RAOPhaseRelativeToConvention": "trough"},
     lambda w, a, p: [w] + [v for pair in zip(a, p - 180) for v in pair]),
    ({"RAOPhaseRelativeToConvention": "zero up-crossing"},
     lambda w, a, p: [w] + [v for pair in zip(a, p - 270) for v in pair]),
    ({"RAOPhaseRelativeToConvention": "zero down-crossing", "RAOPhaseConvention": "leads"},
     lambda w, a, p: [w] + [v for pair in zip(a, -p + 90) for v in pair]),
    ({"RollPositiveStarboard": "up", "SwayPositive": "starboard", "PitchPositiveBow": "up"},
     lambda w, a, p: [w] + [v for pair in zip(a, p + [0, 180, 0, 180, 180, 0]) for v in pair]),
    ({"SurgePositive": "aft", "HeavePositive": "down", "YawPositiveBow": "starboard"},
     lambda w, a, p: [w] + [v for pair in zip(a, p + [180, 0, 180, 0, 0, 180]) for v in pair]),
])
def test_each_convention_setting_is_converted(hull, tmp_path, settings, rows):
    ds = read_orcaflex_vessel_type(write(tmp_path / "v.yml", hull, settings, rows))
    same(ds, hull, tol=1e-12)


def test_settings_left_out_take_orcaflex_defaults_and_are_named(hull, tmp_path):
    path = write(tmp_path / "v.yml", hull, {"WavesReferredToBy": "period (s)"},
                 lambda w, a, p: [2 * np.pi / w] + [v for pair in zip(a, p) for v in pair],
                 drop=("WavesReferredToBy", "RAOResponseUnits", "SwayPositive"))
    ds = read_orcaflex_vessel_type(path)
    same(ds, hull)
    assert ds.attrs["orcaflex_defaults_taken"] == "WavesReferredToBy, RAOResponseUnits, SwayPositive"


def test_the_phase_convention_is_never_guessed(hull, tmp_path):
    path = write(tmp_path / "v.yml", hull, drop=("RAOPhaseConvention",))
    with pytest.raises(InputError, match=r"vessel.rao_conventions.phase.*does not state"):
        read_orcaflex_vessel_type(path)
    same(read_orcaflex_vessel_type(path, conventions={"phase": "lag"}), hull)
    with pytest.raises(InputError) as err:          # the file's own, contradicted
        read_orcaflex_vessel_type(write(tmp_path / "w.yml", hull), conventions={"phase": "lead"})
    assert "RAOPhaseConvention: lags" in str(err.value) and "rao_conventions.phase" in str(err.value)
    with pytest.raises(InputError, match="rao_conventions.x_axis"):
        read_orcaflex_vessel_type(write(tmp_path / "x.yml", hull), conventions={"x_axis": "aft"})


# --- a flipped convention is caught by the long-wave checks --------------------------------

@pytest.mark.parametrize("settings, needle", [
    ({"RAOPhaseConvention": "leads"}, "following seas (0 deg) the pitch leads the heave by -"),
    ({"RollPositiveStarboard": "up"}, "beam seas (90 deg) the roll leads the sway by"),
    ({"PitchPositiveBow": "up"}, "the pitch leads the heave by -"),
    ({"RAOPhaseRelativeToConvention": "trough"}, "the heave phase"),
])
def test_a_wrongly_declared_convention_is_caught_with_the_numbers(hull, tmp_path, settings, needle):
    # the data are in the jls convention as lags; the file declares otherwise
    ds = read_orcaflex_vessel_type(write(tmp_path / "v.yml", hull, settings))
    with pytest.raises(InputError) as err:
        check_long_wave_phases(ds, file="v.yml")
    assert needle in str(err.value) and "vessel.rao_conventions" in str(err.value)
    assert "62.83 s" in str(err.value)


# --- malformed files -----------------------------------------------------------------------

def test_several_vessel_types_or_draughts_need_a_choice(hull, tmp_path):
    path = write(tmp_path / "v.yml", hull, draughts=("light", "deep"))
    with pytest.raises(InputError) as err:
        read_orcaflex_vessel_type(path)
    assert "vessel.orcaflex_draught" in str(err.value) and "['light', 'deep']" in str(err.value)
    same(read_orcaflex_vessel_type(path, draught="deep"), hull)
    with pytest.raises(InputError, match="vessel.orcaflex_vessel_type.*'Other'"):
        read_orcaflex_vessel_type(path, vessel_type="Other", draught="deep")
    two = path.read_text().replace("VesselTypes:\n", "VesselTypes:\n  - Name: Barge\n    Draughts: []\n")
    with pytest.raises(InputError, match="vessel.orcaflex_vessel_type.*2 vessel types"):
        read_orcaflex_vessel_type(_put(tmp_path / "two.yml", two), draught="deep")


def test_load_raos_only_are_refused_naming_the_key(tmp_path):
    text = REAL.read_text()
    start = text.index("        DisplacementRAOs:")
    text = text[:start] + "        LoadRAOs:\n          RAOOrigin: [0, 0, 0]\n"
    with pytest.raises(InputError) as err:
        read_orcaflex_vessel_type(_put(tmp_path / "load.yml", text))
    assert "Draughts[Draught1].DisplacementRAOs" in str(err.value)
    assert "load RAOs only" in str(err.value)


@pytest.mark.parametrize("edit, needles", [
    (lambda t: t.replace(", RAOPitchAmp, RAOPitchPhase", "", 1),
     ["RAOs[0] (line 25)", "RAOPitchAmp"]),
    (lambda t: t.replace("RAOWaveUnit: amplitude", "RAOWaveUnit: max wave slope"),
     ["VesselTypes[HLV].RAOWaveUnit (line 6)", "max wave slope"]),
    (lambda t: t.replace("WavesReferredToBy: frequency (rad/s)", "WavesReferredToBy: wavelength"),
     ["WavesReferredToBy (line 7)", "wavelength"]),
    (lambda t: t.replace("PhaseOrigin: [~, ~, ~]", "PhaseOrigin: [0, 0, 0]"),
     ["DisplacementRAOs.PhaseOrigin (line 22)", "away from the RAO origin"]),
    (lambda t: t.replace("Symmetry: None", "Symmetry: circular"), ["Symmetry (line 17)"]),
    (lambda t: t.replace("UnitsSystem: SI", "UnitsSystem: US"), ["General.UnitsSystem (line 2)"]),
    (lambda t: t.replace("RAODirection: 90.0", "RAODirection: 0.0"),
     ["RAOs[1].RAODirection (line 31)", "also at line 24", "given twice"]),
    (lambda t: t.replace("RAODirection: 90.0\n", "RAODirection: 90.0\n              RAODirection: 91\n"),
     ["line 32", "key given twice"]),
    (lambda t: t.replace("- [0.1, ", "- [0.1x, ", 1), ["RAOs[0] (line 26)", "not a number", "0.1x"]),
    (lambda t: t.replace("- [0.1, ", "- [", 1), ["RAOs[0] (line 26)", "13 numbers"]),
    (lambda t: t.replace("RAOs:\n            - RAODirection: 0.0", "RAOs:\n            - RAOHeading: 0.0"),
     ["RAOs[0] (line 24)", "without RAODirection"]),
])
def test_malformed_files_are_refused_naming_key_line_and_value(hull, tmp_path, edit, needles):
    text = edit(write(tmp_path / "ok.yml", hull).read_text())
    with pytest.raises(InputError) as err:
        read_orcaflex_vessel_type(_put(tmp_path / "bad.yml", text))
    message = str(err.value)
    assert "\n" not in message and "bad.yml" in message
    for needle in needles:
        assert needle in message, message


def test_periods_rounded_into_one_row_are_refused_as_duplicates(hull, tmp_path):
    path = write(tmp_path / "v.yml", hull.isel(omega=[1, 2]), {"WavesReferredToBy": "period (s)"},
                 lambda w, a, p: [6.3] + [v for pair in zip(a, p) for v in pair])
    with pytest.raises(InputError, match=r"line \d+.*duplicate|duplicate.*line \d+"):
        read_orcaflex_vessel_type(path)


def test_no_vessel_types_and_broken_yaml_are_refused(tmp_path):
    with pytest.raises(InputError, match="VesselTypes"):
        read_orcaflex_vessel_type(_put(tmp_path / "a.yml", "General:\n  UnitsSystem: SI\n"))
    with pytest.raises(InputError, match="line 3"):
        read_orcaflex_vessel_type(_put(tmp_path / "b.yml", "VesselTypes:\n  - [1, 2\n"))


def test_yz_and_both_planes_add_the_fore_and_aft_images(hull, tmp_path):
    quarter = load_rao(DEFAULT).isel(omega=[0, 20], wave_direction=[0, 3, 6])     # 0, 45, 90
    ds = read_orcaflex_vessel_type(write(tmp_path / "v.yml", quarter, {"Symmetry": "yz plane"}))
    heading = np.degrees(ds["wave_direction"].values).round(9).tolist()
    assert heading == [0.0, 45.0, 90.0, 135.0, 180.0]
    fore_aft = np.array([-1, 1, 1, 1, -1, -1])          # surge, pitch and yaw change sign
    assert np.allclose(ds["rao"].values[:, 3], quarter["rao"].values[:, 1] * fore_aft, rtol=1e-14)
    both = read_orcaflex_vessel_type(write(tmp_path / "w.yml", quarter,
                                           {"Symmetry": "xz and yz planes"}))
    assert np.degrees(both["wave_direction"].values).round(9).tolist() == [
        0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0]
    # 225 = the port-starboard image of 135: sway, roll and yaw change sign again
    assert np.allclose(both["rao"].values[:, 5], quarter["rao"].values[:, 1] * fore_aft
                       * np.array([1, -1, 1, -1, 1, -1]), rtol=1e-14)


def test_frequencies_declared_as_periods_are_refused_by_the_frequency_bound(hull, tmp_path):
    path = write(tmp_path / "v.yml", hull, {"WavesReferredToBy": "period (s)"})   # rad/s inside
    with pytest.raises(InputError, match="outside 0.01-10 rad/s"):
        load_rao(path)


def test_negative_directions_are_wrapped(hull, tmp_path):
    text = write(tmp_path / "v.yml", hull).read_text().replace("RAODirection: 90.0", "RAODirection: -270")
    ds = read_orcaflex_vessel_type(_put(tmp_path / "w.yml", text))
    same(ds, hull)
