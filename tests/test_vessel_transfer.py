"""Rigid-body transfer u_P = u + theta x r, hinge excitation (eq. 3.1) and fairleads."""

from pathlib import Path

import numpy as np
import pytest

from jls.errors import InputError
from jls.vessel.rao import make_rao_dataset
from jls.vessel.transfer import (
    HINGE_POSITION_M,
    fairlead_motion,
    hinge_excitation,
    point_motion,
    shift_reference_point,
)

R = np.array([-215.263, 1.0, 99.998])


def unit(dof, value=1.0 + 0.0j, omega=(0.5, 1.0)):
    values = np.zeros((len(omega), 1, 6), complex)
    values[:, 0, ["surge", "sway", "heave", "roll", "pitch", "yaw"].index(dof)] = value
    return make_rao_dataset(omega, [np.pi / 2], values, source="unit", source_format="test")


def xyz(da):
    return da.isel(omega=0, wave_direction=0).values


def test_pure_roll():
    # roll about +x: (theta, 0, 0) x (dx, dy, dz) = (0, -theta dz, theta dy)
    dx, dy, dz = R
    np.testing.assert_allclose(xyz(point_motion(unit("roll"), R)), [0.0, -dz, dy])


def test_pure_pitch():
    # pitch about +y: (0, theta, 0) x r = (theta dz, 0, -theta dx)
    dx, dy, dz = R
    np.testing.assert_allclose(xyz(point_motion(unit("pitch"), R)), [dz, 0.0, -dx])


def test_pure_yaw():
    # yaw about +z: (0, 0, theta) x r = (-theta dy, theta dx, 0)
    dx, dy, dz = R
    np.testing.assert_allclose(xyz(point_motion(unit("yaw"), R)), [-dy, dx, 0.0])


def test_translations_pass_through_and_complex_phase_is_kept():
    ds = unit("sway", value=0.3 - 0.4j)
    np.testing.assert_allclose(xyz(point_motion(ds, R)), [0.0, 0.3 - 0.4j, 0.0])
    roll = unit("roll", value=1j * 0.01)
    np.testing.assert_allclose(xyz(point_motion(roll, R)), 1j * 0.01 * np.array(
        [0.0, -R[2], R[1]]))


def test_point_motion_layout():
    da = point_motion(unit("roll"), (1.0, 2.0, 3.0))
    assert da.dims == ("omega", "wave_direction", "axis")
    assert list(da["axis"].values) == ["x", "y", "z"]
    assert da.attrs["units"] == "m/m" and da.attrs["lever_arm_m"] == [1.0, 2.0, 3.0]


def test_hinge_excitation_matches_eq_3_1():
    rng = np.random.default_rng(7)
    values = rng.normal(size=(3, 2, 6)) + 1j * rng.normal(size=(3, 2, 6))
    ds = make_rao_dataset([0.3, 0.6, 0.9], [np.pi / 2, np.pi], values, source="r",
                          source_format="test")
    qb = hinge_excitation(ds)
    assert qb.name == "qb"
    assert qb.dims == ("omega", "wave_direction", "dof_b")
    assert list(qb["dof_b"].values) == ["sway", "heave", "roll", "yaw"]
    surge, sway, heave, roll, pitch, yaw = np.moveaxis(values, -1, 0)
    dx, dy, dz = HINGE_POSITION_M
    np.testing.assert_allclose(qb.sel(dof_b="sway").values, sway + yaw * dx - roll * dz)
    np.testing.assert_allclose(qb.sel(dof_b="heave").values, heave + roll * dy - pitch * dx)
    np.testing.assert_allclose(qb.sel(dof_b="roll").values, roll)
    np.testing.assert_allclose(qb.sel(dof_b="yaw").values, yaw)


def test_fairleads():
    roll = unit("roll")
    da = fairlead_motion(roll)
    assert da.dims == ("omega", "wave_direction", "side", "axis")
    assert list(da["side"].values) == ["port", "starboard"]
    port = R + (0.0, 37.5, -82.5)
    stbd = R + (0.0, -37.5, -82.5)
    np.testing.assert_allclose(da["position_m"].values, [port, stbd])
    # pure roll: y = -dz, z = +dy at each fairlead
    np.testing.assert_allclose(da.sel(side="port").isel(omega=0, wave_direction=0).values,
                               [0.0, -port[2], port[1]])
    np.testing.assert_allclose(da.sel(side="starboard").isel(omega=0, wave_direction=0).values,
                               [0.0, -stbd[2], stbd[1]])
    # the fairleads sit lower than the hinge, so roll moves them less transversely
    hinge_y = hinge_excitation(roll).sel(dof_b="sway").isel(omega=0, wave_direction=0).item()
    assert abs(da.sel(side="port", axis="y").values[0, 0]) < abs(hinge_y)


def test_shift_reference_point_round_trip():
    rng = np.random.default_rng(3)
    values = rng.normal(size=(2, 1, 6)) + 1j * rng.normal(size=(2, 1, 6))
    ds = make_rao_dataset([0.4, 0.8], [0.0], values, source="r", source_format="test",
                          reference_point_m=(0.0, 0.0, 0.0))
    r = np.array([3.93, 0.0, 2.5])
    moved = shift_reference_point(ds, r)
    assert moved.attrs["reference_point_m"] == pytest.approx(list(r))
    np.testing.assert_allclose(moved["rao"].values[..., 3:], values[..., 3:])
    # a point P seen from either reference point moves the same
    p = np.array([-50.0, 4.0, 20.0])
    np.testing.assert_allclose(point_motion(moved, p - r).values, point_motion(ds, p).values)
    back = shift_reference_point(moved, -r)
    np.testing.assert_allclose(back["rao"].values, values)


@pytest.mark.parametrize("call", [
    lambda ds: point_motion(ds, (1.0, 2.0)),
    lambda ds: point_motion(ds, (1.0, np.nan, 2.0)),
    lambda ds: hinge_excitation(ds, r_hinge="up"),
    lambda ds: fairlead_motion(ds, drop=-1.0),
    lambda ds: fairlead_motion(ds, half_span=np.inf),
])
def test_bad_positions(call):
    with pytest.raises(InputError):
        call(unit("roll"))


def _vessel(**kw):
    from jls.config.loader import fill_defaults, schema
    vessel = {"rao_file": "tests/data/vessel/mss_tanker/tanker.4", "rao_reference_point_height_m": 0.0, **kw}
    fill_defaults(vessel, schema()["properties"]["vessel"])
    return vessel


def test_wamit_file_needs_its_ulen_and_ulen_scales_rotations_only():
    from jls.errors import InputError
    from jls.stages.vessel_motion import vessel_motion
    root = Path(__file__).resolve().parents[1]
    with pytest.raises(InputError, match="wamit_ulen_m"):
        vessel_motion(_vessel(), [90], base_dir=root)
    one = vessel_motion(_vessel(wamit_ulen_m=1.0), [90], base_dir=root)
    two = vessel_motion(_vessel(wamit_ulen_m=2.0), [90], base_dir=root)
    rot = ["roll", "pitch", "yaw"]
    np.testing.assert_allclose(two["rao"].sel(vessel_dof=rot), one["rao"].sel(vessel_dof=rot) / 2)
    np.testing.assert_allclose(two["rao"].sel(vessel_dof="heave"), one["rao"].sel(vessel_dof="heave"))


def test_rao_reference_point_moves_the_hinge_lever_arm():
    from jls.stages.vessel_motion import vessel_motion
    root = Path(__file__).resolve().parents[1]
    base = vessel_motion(_vessel(wamit_ulen_m=1.0, hinge_m=[-100.0, 1.0, 40.0]), [90], base_dir=root)
    # the same hinge, measured in a frame whose origin is 5 m below the RAO reference point
    moved = vessel_motion(_vessel(wamit_ulen_m=1.0, hinge_m=[-100.0, 1.0, 45.0],
                                  rao_reference_point_m=[0.0, 0.0, 5.0]), [90], base_dir=root)
    np.testing.assert_allclose(moved["hinge"].values, base["hinge"].values)
    # and 5 m higher above the reference point the hinge sways by roll x 5 m more
    high = vessel_motion(_vessel(wamit_ulen_m=1.0, hinge_m=[-100.0, 1.0, 45.0]), [90], base_dir=root)
    roll = base["rao"].sel(vessel_dof="roll").values
    np.testing.assert_allclose(high["hinge"].sel(dof="sway").values,
                               base["hinge"].sel(dof="sway").values - 5.0 * roll, atol=1e-12)
