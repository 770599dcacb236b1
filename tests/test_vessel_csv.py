"""CSV RAO reader: the documented example and malformed files."""

from pathlib import Path

import numpy as np
import pytest

from jls.errors import InputError
from jls.vessel.csv_io import read_rao_csv
from jls.vessel.files import load_rao

EXAMPLE = Path(__file__).parent / "data" / "vessel" / "example_rao.csv"
HEADER = "omega_rad_s,wave_direction_deg,dof,amplitude,phase_deg"
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


def test_example_file():
    ds = load_rao(EXAMPLE)
    assert ds.sizes == {"omega": 3, "wave_direction": 2, "dof": 6}
    assert ds.attrs["source"] == "example_rao.csv" and ds.attrs["source_format"] == "csv"
    sway = ds["rao"].sel(omega=2 * np.pi / 20, wave_direction=np.pi / 2, dof="sway").item()
    assert abs(sway) == pytest.approx(0.95)
    assert np.degrees(np.angle(sway)) == pytest.approx(-90.0)
    roll = ds["rao"].sel(omega=2 * np.pi / 6, wave_direction=np.pi / 2, dof="roll").item()
    assert roll == pytest.approx(0.004 * np.exp(1j * np.radians(-150.0)))


def rows(fmt="polar", omegas=(0.5, 1.0), headings=(90, 180)):
    out = []
    for w in omegas:
        for h in headings:
            for k, d in enumerate(DOFS):
                amp, ph = 0.1 * (k + 1), 10.0 * k
                if fmt == "polar":
                    out.append(f"{w},{h},{d},{amp},{ph}")
                else:
                    out.append(f"{w},{h},{d},{float(amp * np.cos(np.radians(ph)))!r},"
                               f"{float(amp * np.sin(np.radians(ph)))!r}")
    return out


def write(tmp_path, header, body, name="rao.csv"):
    path = tmp_path / name
    path.write_text("# comment line\n\n" + header + "\n" + "\n".join(body) + "\n")
    return path


def test_polar_and_cartesian_agree_and_options(tmp_path):
    polar = read_rao_csv(write(tmp_path, HEADER, rows(), "p.csv"))
    cart = read_rao_csv(write(tmp_path, "omega_rad_s,wave_direction_deg,dof,re,im",
                              rows("cart"), "c.csv"))
    np.testing.assert_allclose(polar["rao"].values, cart["rao"].values, rtol=1e-12)
    lag = read_rao_csv(write(tmp_path, HEADER, rows(), "l.csv"), phase="lag")
    np.testing.assert_allclose(lag["rao"].values, np.conj(polar["rao"].values))
    deg = read_rao_csv(write(tmp_path, HEADER, rows(), "d.csv"), rotation_units="deg/m")
    np.testing.assert_allclose(deg["rao"].values[..., 3:],
                               polar["rao"].values[..., 3:] * np.pi / 180)
    np.testing.assert_allclose(deg["rao"].values[..., :3], polar["rao"].values[..., :3])
    header_period = HEADER.replace("omega_rad_s", "period_s")
    by_period = read_rao_csv(write(tmp_path, header_period, rows(omegas=(4.0, 8.0)), "t.csv"))
    assert by_period["omega"].values == pytest.approx([np.pi / 4, np.pi / 2])


def test_all_four_columns_must_agree(tmp_path):
    header = HEADER + ",re,im"
    body = [r + ",0.0,0.1" for r in rows()]
    with pytest.raises(InputError) as err:
        read_rao_csv(write(tmp_path, header, body))
    assert err.value.field == "line 4"


@pytest.mark.parametrize("header, edit, field, value", [
    (HEADER, lambda r: [x for x in r if ",yaw," not in x], "dof", ["yaw"]),
    (HEADER, lambda r: r[:-1], "grid", None),
    (HEADER, lambda r: r + [r[0]], "line 28", None),
    (HEADER, lambda r: [r[0].replace(",0.1,", ",-0.1,")] + r[1:], "line 4, amplitude", -0.1),
    (HEADER, lambda r: [r[0].replace(",0.1,", ",inf,")] + r[1:], "line 4, amplitude", "inf"),
    (HEADER, lambda r: [r[0].replace(",0.1,", ",x,")] + r[1:], "line 4, amplitude", "x"),
    (HEADER, lambda r: [r[0].replace("surge", "surf")] + r[1:], "line 4, dof", "surf"),
    (HEADER, lambda r: [r[0] + ",9"] + r[1:], "line 4", None),
    (HEADER, lambda r: [r[0].replace("0.5,", "-0.5,", 1)] + r[1:], "line 4, omega_rad_s",
     -0.5),
    ("omega_rad_s,wave_direction_deg,dof,amplitude", lambda r: r, "line 3, header", None),
    ("omega_rad_s,period_s,wave_direction_deg,dof,amplitude,phase_deg", lambda r: r,
     "line 3, header", None),
    ("omega_rad_s,dof,amplitude,phase_deg", lambda r: r, "line 3, header", None),
    (HEADER + ",colour", lambda r: r, "line 3, header", ["colour"]),
])
def test_malformed(tmp_path, header, edit, field, value):
    path = write(tmp_path, header, edit(rows()))
    with pytest.raises(InputError) as err:
        read_rao_csv(path)
    assert err.value.file == str(path)
    assert err.value.field == field
    if value is not None:
        assert err.value.value == value


def test_bad_options_and_empty(tmp_path):
    path = write(tmp_path, HEADER, rows())
    with pytest.raises(InputError):
        read_rao_csv(path, rotation_units="grad")
    with pytest.raises(InputError):
        read_rao_csv(path, phase="ahead")
    empty = tmp_path / "empty.csv"
    empty.write_text("# nothing\n")
    with pytest.raises(InputError):
        read_rao_csv(empty)
    only_header = write(tmp_path, HEADER, [], "header.csv")
    with pytest.raises(InputError):
        read_rao_csv(only_header)
