"""AQWA-LINE listing reader: a real 2020 R1 listing (WEC-Sim's cylinder, Apache 2.0), its
conventions against the physics of long waves, the stated x axis, and malformed listings
refused with the line number."""

from pathlib import Path

import numpy as np
import pytest

from jls.config.plausible import check_rao_magnitudes, wavenumber
from jls.errors import InputError
from jls.vessel import load_rao
from jls.vessel.aqwa import read_aqwa_lis
from jls.vessel.conventions import AFT_SIGNS
from jls.vessel.phase_checks import check_long_wave_phases

REAL = Path(__file__).resolve().parent / "data" / "vessel" / "aqwa" / "cylinder_raos.LIS"
G = 9.807                          # the listing's gravity


@pytest.fixture(scope="module")
def cylinder():
    return read_aqwa_lis(REAL)


def test_real_listing_grid_and_provenance(cylinder):
    assert cylinder.sizes == {"omega": 50, "wave_direction": 2, "dof": 6}
    assert np.degrees(cylinder["wave_direction"].values).tolist() == [0.0, 180.0]
    assert cylinder.attrs["aqwa_directions_dropped"].startswith("180 deg (the direction of -180")
    assert cylinder.attrs["water_depth_m"] == 3.0
    assert cylinder.attrs["reference_point_m"] == [0.0, 0.0, 0.0]
    assert cylinder.attrs["aqwa_version"] == "2020 R1"
    assert cylinder.attrs["source_format"] == "aqwa_lis"
    w = cylinder["omega"].values
    # 157.08 s (printed 0.040 rad/s): omega from the period, the more precise column;
    # 0.60 s (printed 10.500 rad/s): from the frequency
    assert w[0] == pytest.approx(2 * np.pi / 157.08, rel=1e-12)
    assert w[-1] == 10.5


def test_real_listing_long_wave_limits_and_phases(cylinder):
    """In 3 m of water at 157 s the cylinder rides the wave: heave 1 in phase, pitch with
    the slope k (finite depth), surge with the particle excursion 1/(k h); a quarter
    period behind the crest in waves travelling along +x, ahead of it against them."""
    assert check_rao_magnitudes(cylinder, {}, file=REAL, g=G) == []
    assert check_long_wave_phases(cylinder, file=REAL, g=G) == []
    r = cylinder["rao"].isel(omega=0).values
    k = wavenumber(cylinder["omega"].values[0], 3.0, G)
    along = 0                                        # 0 deg
    assert abs(r[along, 2]) == pytest.approx(1.0007) and abs(np.angle(r[along, 2])) < 1e-3
    assert abs(r[along, 4]) / k == pytest.approx(1.0, abs=0.01)
    assert abs(r[along, 0]) * k * 3.0 == pytest.approx(1.0, abs=0.01)
    assert np.degrees(np.angle(r[along, 0])) == pytest.approx(-89.96)
    assert np.degrees(np.angle(r[along, 4])) == pytest.approx(90.74)
    assert np.degrees(np.angle(r[1, 0])) == pytest.approx(89.96)       # -180 deg
    assert np.degrees(np.angle(r[1, 4])) == pytest.approx(-90.74)


def test_real_listing_beyond_ten_rad_per_s_is_refused_by_the_frequency_bound():
    # a model-scale body: 10.5 rad/s lies beyond the 0.01-10 rad/s of a vessel's RAOs
    with pytest.raises(InputError, match="outside 0.01-10 rad/s"):
        load_rao(REAL)


def test_x_axis_aft_turns_the_rao_as_predicted(cylinder):
    aft = read_aqwa_lis(REAL, conventions={"x_axis": "aft"})
    beta = np.degrees(aft["wave_direction"].values)
    assert beta.tolist() == [0.0, 180.0]                     # 180 (-180) and 0 turned
    assert np.array_equal(aft["rao"].values, cylinder["rao"].values[:, ::-1] * AFT_SIGNS)
    # the phase relations cannot tell: a frame turned about z is as physical
    assert check_long_wave_phases(aft, g=G) == []


def test_the_phase_convention_aqwa_fixes_cannot_be_restated(cylinder):
    with pytest.raises(InputError, match=r"rao_conventions.phase.*AQWA prints phase lags"):
        read_aqwa_lis(REAL, conventions={"phase": "lead"})
    with pytest.raises(InputError, match=r"rao_conventions.direction"):
        read_aqwa_lis(REAL, conventions={"direction": "from"})
    same = read_aqwa_lis(REAL, conventions={"phase": "lag", "direction": "to", "x_axis": "forward"})
    assert np.array_equal(same["rao"].values, cylinder["rao"].values)


def edit(tmp_path, change):
    lines = REAL.read_text(encoding="latin-1").splitlines()
    path = tmp_path / "bad.LIS"
    path.write_text("\n".join(change(lines)) + "\n", encoding="latin-1")
    return path


def replace_line(n, text):
    def change(lines):
        lines[n - 1] = text(lines[n - 1])
        return lines
    return change


@pytest.mark.parametrize("change, needles", [
    (replace_line(36, lambda s: s.replace("2020 R1", "19.1")), ["line 36", "AQWA-LINE 19.1", "2020 R1"]),
    (replace_line(36, lambda s: "  "), ["not an AQWA-LINE listing"]),
    (replace_line(77, lambda s: s.replace("(SECS)", "(HZ)  ")), ["line 77", "(SECS)", "(HZ)"]),
    (replace_line(75, lambda s: s.replace("FREQ", "WAVELENGTH")), ["line 75", "header"]),
    (replace_line(80, lambda s: s.replace("157.08", "127.08")), ["line 80", "disagree", "127.08"]),
    (replace_line(81, lambda s: s[:s.rindex("  ")]), ["line 81", "6 amplitude-phase pairs"]),
    (replace_line(81, lambda s: ""), ["incomplete grid", "period 157.08 s, heading 0 deg, surge"]),
    (replace_line(80, lambda s: " " * 19 + s[19:]), ["line 80", "give the period"]),
    (replace_line(81, lambda s: s.replace("45.2109", "-45.2109")), ["line 81", ">= 0"]),
    (replace_line(52, lambda s: s.replace("9.807", "32.17")), ["line 52", "metres"]),
    (replace_line(62, lambda s: "  "), ["STRUCTURE C.O.G."]),
    (lambda lines: lines + [next(s for s in lines if "H Y D R O" in s).replace("E   1", "E   2")],
     ["several structures", "[1, 2]"]),
    (lambda lines: [s.replace("R.A.O.S-VARIATION", "R.A.O.S - VARIATION") for s in lines],
     ["no 'R.A.O.S-VARIATION WITH WAVE DIRECTION' table"]),
])
def test_malformed_listings_are_refused_with_the_line(tmp_path, change, needles):
    with pytest.raises(InputError) as err:
        read_aqwa_lis(edit(tmp_path, change))
    message = str(err.value)
    assert "\n" not in message and "bad.LIS" in message
    for needle in needles:
        assert needle in message, message


def test_periods_rounded_into_one_row_are_refused(tmp_path):
    # two periods printed alike (0.61 s, 10.287 and 10.500 rad/s -> 10.287): a duplicate row
    def change(lines):
        n = next(i for i, s in enumerate(lines) if s.lstrip().startswith("0.60  10.500"))
        lines[n] = lines[n].replace("0.60  10.500", "0.61  10.287")
        return lines
    with pytest.raises(InputError, match=r"line \d+.*duplicate row"):
        read_aqwa_lis(edit(tmp_path, change))


def test_a_full_circle_listing_in_minus_180_to_180_serves_any_route_heading(tmp_path):
    from jls.vessel import mirror_headings
    from jls.vessel.export import aqwa_text, write_text
    from jls.vessel.headings import select_headings

    hull = mirror_headings(load_rao(Path(__file__).resolve().parents[1] / "config" / "vessel"
                                    / "representative_hlv.nc").isel(omega=[0, 30, 60]))
    beta = hull["wave_direction"].values
    signed = hull.assign_coords(wave_direction=np.where(beta > np.pi, beta - 2 * np.pi, beta))
    ds = read_aqwa_lis(write_text(aqwa_text(signed), tmp_path / "full.lis"))
    assert np.degrees(ds["wave_direction"].values).round(9).tolist() == list(range(0, 360, 15))
    port = select_headings(ds, [270.0])["rao"].values[:, 0]             # the listing's -90
    assert np.allclose(port, hull["rao"].sel(wave_direction=3 * np.pi / 2).values, rtol=1e-12)
