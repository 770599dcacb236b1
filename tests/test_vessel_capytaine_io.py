"""Capytaine RAO NetCDF reader (fixtures made by tests/data/vessel/make_capytaine_fixture.py)."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.errors import InputError
from jls.vessel.capytaine_io import read_capytaine_nc
from jls.vessel.files import load_rao

DATA = Path(__file__).parent / "data" / "vessel"
SPLIT = DATA / "capytaine_rao_split.nc"   # capytaine separate_complex_values layout
REIM = DATA / "capytaine_rao_reim.nc"     # rao_re / rao_im, lower-case dof names


def test_split_layout_is_conjugated_to_exp_plus_i_omega_t():
    ds = read_capytaine_nc(SPLIT, reference_point=(0.0, 0.0, -1.0))
    assert ds.sizes == {"omega": 5, "wave_direction": 2, "dof": 6}
    assert ds.attrs["source_format"] == "capytaine"
    assert ds.attrs["reference_point_m"] == [0.0, 0.0, -1.0]
    beam = ds["rao"].sel(wave_direction=np.pi / 2)
    # long wave (lambda = 385 m on a 10 m wide box): sway follows the particle orbit,
    # a 90 deg lag in the jls exp(+i omega t) convention (+90 deg in Capytaine's).
    sway = beam.sel(dof="sway").values[0]
    assert abs(sway) == pytest.approx(1.0, abs=0.06)
    assert np.degrees(np.angle(sway)) == pytest.approx(-90.0, abs=1.0)
    heave = beam.sel(dof="heave").values[0]
    assert abs(heave) == pytest.approx(1.0, abs=0.02)
    assert abs(np.degrees(np.angle(heave))) < 1.0
    with xr.open_dataset(SPLIT) as raw:
        stored = (raw["rao"].sel(complex="re") + 1j * raw["rao"].sel(complex="im"))
        stored = stored.sel(radiating_dof="Sway", wave_direction=np.pi / 2).values
    np.testing.assert_allclose(beam.sel(dof="sway").values, np.conj(stored))


def test_reim_layout_and_dispatch_agree():
    a = read_capytaine_nc(SPLIT)
    b = load_rao(REIM)       # .nc without a jls 'rao'/'dof' -> Capytaine reader
    xr.testing.assert_allclose(a["rao"], b["rao"])
    assert "assumed" in b.attrs["reference_point_source"]


def test_rotation_center_in_file_is_used(tmp_path):
    with xr.open_dataset(SPLIT) as raw:
        ds = raw.load()
    ds["rotation_center"] = ("space_coordinate", [0.0, 0.0, -1.0])
    path = tmp_path / "rc.nc"
    ds.to_netcdf(path)
    assert read_capytaine_nc(path).attrs["reference_point_m"] == [0.0, 0.0, -1.0]


def _copy(tmp_path, edit, name="bad.nc"):
    with xr.open_dataset(REIM) as raw:
        ds = edit(raw.load())
    path = tmp_path / name
    ds.to_netcdf(path)
    return path


@pytest.mark.parametrize("edit, field", [
    (lambda ds: ds.isel(radiating_dof=slice(0, 5)), "radiating_dof"),
    (lambda ds: ds.assign_coords(radiating_dof=["surge", "sway", "heave", "roll", "pitch",
                                                "wobble"]), "radiating_dof"),
    (lambda ds: ds.assign(rao_re=ds["rao_re"].where(ds["omega"] < 1.0)), "rao[omega=1.2"),
    (lambda ds: ds.rename(rao_re="x_re", rao_im="y_im"), "variable"),
    (lambda ds: ds.drop_vars("rao_im").rename(rao_re="rao"), "rao"),
])
def test_malformed(tmp_path, edit, field):
    path = _copy(tmp_path, edit)
    with pytest.raises(InputError) as err:
        read_capytaine_nc(path)
    assert err.value.file == str(path)
    assert err.value.field.startswith(field)


def test_unreadable_file(tmp_path):
    path = tmp_path / "junk.nc"
    path.write_bytes(b"\x00\x01junk")
    with pytest.raises(InputError):
        read_capytaine_nc(path)
