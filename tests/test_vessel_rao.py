"""RAO dataset layout: construction, validation, interpolation, NetCDF round trip."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.errors import InputError
from jls.vessel.files import load_rao
from jls.vessel.rao import (
    DOFS,
    frequency_range,
    interp_rao,
    make_rao_dataset,
    mirror_headings,
    read_rao_netcdf,
    save_rao,
    validate_rao,
)

DATA = Path(__file__).parent / "data" / "vessel"


def synthetic(omega=(0.2, 0.4, 0.6, 0.8), headings_deg=(0.0, 90.0, 180.0)):
    omega = np.asarray(omega, float)
    beta = np.radians(headings_deg)
    rng = np.random.default_rng(1)
    values = (rng.normal(size=(omega.size, beta.size, 6))
              + 1j * rng.normal(size=(omega.size, beta.size, 6)))
    values[..., 3:] *= 0.05                # rotations of a ship: a few deg/m at most
    return make_rao_dataset(omega, beta, values, reference_point_m=(1.0, 0.0, -2.0),
                            source="synthetic", source_format="test")


def test_layout_dims_coords_units_and_attrs():
    ds = synthetic()
    assert ds["rao"].dims == ("omega", "wave_direction", "dof")
    assert ds["rao"].dtype == complex
    assert list(ds["dof"].values) == list(DOFS)
    assert list(ds["dof_units"].values) == ["m/m"] * 3 + ["rad/m"] * 3
    for name in ("omega", "wave_direction", "dof", "dof_units", "rao"):
        assert "units" in ds[name].attrs and "long_name" in ds[name].attrs
    assert ds["omega"].attrs["units"] == "rad/s"
    assert ds["wave_direction"].attrs["units"] == "rad"
    for key in ("reference_point_m", "heading_convention", "phase_convention", "source",
                "source_sha256", "source_format"):
        assert key in ds.attrs
    assert ds.attrs["reference_point_m"] == [1.0, 0.0, -2.0]
    assert "exp(+i omega t)" in ds.attrs["phase_convention"]
    assert "pi/2 = beam seas travelling toward +y" in ds.attrs["heading_convention"]


def test_omega_sorted_on_construction():
    values = np.zeros((3, 1, 6), complex)
    values[:, 0, 2] = [3, 1, 2]
    ds = make_rao_dataset([0.9, 0.1, 0.5], [0.0], values, source="s", source_format="t")
    assert ds["omega"].values.tolist() == [0.1, 0.5, 0.9]
    assert ds["rao"].sel(dof="heave").values[:, 0].tolist() == [1, 2, 3]


@pytest.mark.parametrize("mutate, field", [
    (lambda ds: ds.assign(rao=ds["rao"].where(ds["omega"] < 0.5, np.nan)), "rao["),
    (lambda ds: ds.assign_coords(omega=[0.2, 0.4, 0.4, 0.8]), "omega"),
    (lambda ds: ds.assign_coords(omega=[-0.2, 0.4, 0.6, 0.8]), "omega"),
    (lambda ds: ds.assign_coords(wave_direction=[0.0, 0.0, 1.0]), "wave_direction"),
    (lambda ds: ds.assign_coords(dof=["surge", "sway", "heave", "roll", "pitch", "yawn"]),
     "dof"),
    (lambda ds: ds.assign(rao=ds["rao"].real), "rao"),
    (lambda ds: ds.drop_attrs(deep=False), "attrs"),
])
def test_validate_rejects(mutate, field):
    with pytest.raises(InputError) as err:
        validate_rao(mutate(synthetic()), file="x.nc")
    assert err.value.field.startswith(field)
    assert err.value.file == "x.nc"


def test_frequency_range():
    assert frequency_range(synthetic()) == (0.2, 0.8)


def test_interp_hits_grid_points_exactly_and_refuses_extrapolation():
    ds = synthetic()
    for method in ("polar", "cartesian"):
        same = interp_rao(ds, ds["omega"].values, method=method)
        np.testing.assert_allclose(same["rao"].values, ds["rao"].values, rtol=1e-12,
                                   atol=1e-12)
    with pytest.raises(InputError) as err:
        interp_rao(ds, [0.1, 0.3])
    assert err.value.field == "omega" and err.value.value == 0.1
    with pytest.raises(InputError):
        interp_rao(ds, [0.81])
    with pytest.raises(InputError):
        interp_rao(ds, [0.3], method="cubic")


def test_polar_interpolation_keeps_a_turning_phasor_amplitude():
    omega = np.array([1.0, 2.0])
    values = np.zeros((2, 1, 6), complex)
    values[:, 0, 3] = [1.0, 1j]   # amplitude 1, phase turns by 90 deg
    ds = make_rao_dataset(omega, [0.0], values, source="s", source_format="t")
    mid_polar = interp_rao(ds, [1.5])["rao"].sel(dof="roll").item()
    mid_cart = interp_rao(ds, [1.5], method="cartesian")["rao"].sel(dof="roll").item()
    assert abs(mid_polar) == pytest.approx(1.0)
    assert np.degrees(np.angle(mid_polar)) == pytest.approx(45.0)
    assert abs(mid_cart) == pytest.approx(np.sqrt(0.5))


def test_interp_keeps_layout():
    ds = synthetic()
    out = interp_rao(ds, np.linspace(0.2, 0.8, 7))
    assert out["rao"].dims == ("omega", "wave_direction", "dof")
    assert out.attrs["reference_point_m"] == ds.attrs["reference_point_m"]
    assert out["omega"].attrs["units"] == "rad/s"
    validate_rao(out)


def test_save_and_load_round_trip(tmp_path):
    ds = synthetic()
    path = save_rao(ds, tmp_path / "rao.nc")
    with xr.open_dataset(path) as raw:   # stored split along complex = [re, im]
        assert raw["rao"].dims[0] == "complex"
        assert list(raw["complex"].values) == ["re", "im"]
        assert raw["rao"].dtype == float
    back = read_rao_netcdf(path)
    xr.testing.assert_allclose(back["rao"], ds["rao"])
    assert back.attrs["reference_point_m"] == ds.attrs["reference_point_m"]
    assert back.attrs["phase_convention"] == ds.attrs["phase_convention"]
    again = load_rao(path)          # suffix dispatch recognises a jls file
    xr.testing.assert_allclose(again["rao"], ds["rao"])
    for fmt in ("jls", "netcdf", "JLS"):
        xr.testing.assert_allclose(load_rao(path, format=fmt)["rao"], ds["rao"])


def test_load_rao_errors(tmp_path):
    with pytest.raises(InputError) as err:
        load_rao(tmp_path / "missing.4")
    assert err.value.field == "path"
    odd = tmp_path / "rao.xyz"
    odd.write_text("1 2 3\n")
    with pytest.raises(InputError) as err:
        load_rao(odd)
    assert err.value.field == "format" and err.value.value == ".xyz"
    with pytest.raises(InputError):
        load_rao(odd, format="nope")
    bad_nc = tmp_path / "bad.nc"
    bad_nc.write_text("not netcdf")
    with pytest.raises(InputError) as err:
        load_rao(bad_nc)
    assert err.value.file == str(bad_nc)


def test_mirror_headings_symmetry():
    ds = synthetic(headings_deg=(0.0, 45.0, 90.0, 180.0))
    full = mirror_headings(ds)
    assert np.degrees(full["wave_direction"].values).round(6).tolist() == [
        0, 45, 90, 180, 270, 315]
    a = ds["rao"].sel(wave_direction=np.radians(45.0))
    b = full["rao"].sel(wave_direction=np.radians(315.0))
    sign = np.array([1, -1, 1, -1, 1, -1])
    np.testing.assert_allclose(b.values, a.values * sign)
    with pytest.raises(InputError):
        mirror_headings(full)
