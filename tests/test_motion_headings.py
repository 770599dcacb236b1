"""RAO headings: exact selection, snapping within a tolerance, complex interpolation, and
the port/starboard mirror of a symmetric vessel."""

from pathlib import Path

import numpy as np
import pytest

from jls.errors import InputError
from jls.stages.vessel_motion import vessel_motion
from jls.vessel.headings import select_headings
from jls.vessel.rao import make_rao_dataset

ROOT = Path(__file__).resolve().parents[1]


def rao(headings_deg):
    rng = np.random.default_rng(7)
    omega = np.linspace(0.2, 1.5, 5)
    values = rng.normal(size=(5, len(headings_deg), 6)) + 1j * rng.normal(size=(5, len(headings_deg), 6))
    return make_rao_dataset(omega, np.radians(headings_deg), values)


def at(ds, heading):
    i = int(np.argmin(np.abs(np.degrees(ds["wave_direction"].values) - heading)))
    return ds["rao"].isel(wave_direction=i).values


def test_a_heading_between_rao_headings_is_an_error_by_default():
    ds = rao([0, 30, 60, 90])
    with pytest.raises(InputError, match="heading 45 deg is not in the RAO file.*heading_interpolation"):
        select_headings(ds, [45])
    np.testing.assert_array_equal(select_headings(ds, [60])["rao"].values[:, 0], at(ds, 60))


def test_nearest_snaps_within_the_tolerance_only():
    ds = rao([0, 30, 60, 90])
    out = select_headings(ds, [58, 3], interpolation="nearest", tolerance_deg=5)
    np.testing.assert_array_equal(out["rao"].values[:, 0], at(ds, 60))
    np.testing.assert_array_equal(out["rao"].values[:, 1], at(ds, 0))
    np.testing.assert_allclose(np.degrees(out["wave_direction"].values), [58, 3])
    with pytest.raises(InputError, match="beyond heading_tolerance_deg 5"):
        select_headings(ds, [45], interpolation="nearest", tolerance_deg=5)


def test_linear_interpolates_the_complex_rao_between_neighbours():
    ds = rao([0, 30, 60, 90])
    out = select_headings(ds, [45, 40, 30], interpolation="linear")
    np.testing.assert_allclose(out["rao"].values[:, 0], 0.5 * (at(ds, 30) + at(ds, 60)), rtol=1e-12)
    np.testing.assert_allclose(out["rao"].values[:, 1], (2 * at(ds, 30) + at(ds, 60)) / 3, rtol=1e-12)
    np.testing.assert_array_equal(out["rao"].values[:, 2], at(ds, 30))


def test_linear_interpolation_wraps_through_north_on_mirrored_headings():
    # A symmetric hull given 0-180: 350 deg lies between 330 (the mirror of 30, sway, roll
    # and yaw change sign) and 0.
    ds = rao([0, 30, 60, 90, 120, 150, 180])
    sign = np.array([1, -1, 1, -1, 1, -1])
    out = select_headings(ds, [350], interpolation="linear")
    expected = (1 / 3) * at(ds, 30) * sign + (2 / 3) * at(ds, 0)
    np.testing.assert_allclose(out["rao"].values[:, 0], expected, rtol=1e-12)


def _vessel(**kw):
    from jls.config.loader import fill_defaults, schema
    vessel = {"rao_file": "config/vessel/representative_hlv.nc", "rao_reference_point_height_m": 19.462, **kw}
    fill_defaults(vessel, schema()["properties"]["vessel"])
    return vessel


def test_interpolated_hinge_motion_is_the_interpolated_rao_carried_to_the_hinge():
    # The hinge motion is linear in the vessel RAO, so interpolating the RAO and then
    # carrying it to the hinge equals interpolating the hinge motion.
    m = vessel_motion(_vessel(heading_interpolation="linear"), [75.0, 80.0, 90.0], base_dir=ROOT)
    np.testing.assert_allclose(m["hinge"].sel(heading=80.0).values,
                               (2 * m["hinge"].sel(heading=75.0).values
                                + m["hinge"].sel(heading=90.0).values) / 3, rtol=1e-10, atol=1e-14)
    assert m.attrs["heading_interpolation"].startswith("linear")
    assert vessel_motion(_vessel(), [90.0], base_dir=ROOT).attrs["heading_interpolation"].startswith("none")


def test_beam_seas_from_either_side_give_the_same_relative_sway_on_a_symmetric_vessel():
    from jls.config.builders import rigging_from_config
    from jls.config.loader import load
    from jls.plant.candidates import plant_dataset
    from jls.stages.response import response_dataset
    cfg = load(ROOT / "config" / "config.yaml")
    vessel = dict(cfg["vessel"], hinge_m=[-215.263, 0.0, 99.998])       # on the centreplane
    motion = vessel_motion(vessel, [90.0, 270.0], base_dir=ROOT)
    plant, _ = plant_dataset(rigging_from_config(cfg), {"baseline": {}})
    ds = response_dataset(plant, motion, [6.5, 9.5], [90.0, 270.0], {"none": 0.0}, gamma=3.3,
                          omega_step=0.02, outside_policy=cfg["vessel"]["outside_rao_range"])
    mpm = ds["mpm"].sel(response="relative_sway", candidate="baseline", tugger="none")
    assert float(mpm.sel(heading=90.0, tz=9.5)) > 0.1
    np.testing.assert_allclose(mpm.sel(heading=270.0).values, mpm.sel(heading=90.0).values, rtol=1e-9)
    # the hinge sways the other way: a mirror, not a copy
    y90 = motion["hinge"].sel(heading=90.0, dof=motion["dof"].values[0])
    y270 = motion["hinge"].sel(heading=270.0, dof=motion["dof"].values[0])
    np.testing.assert_allclose(y270.values, -y90.values, rtol=1e-12)


def test_linear_does_not_extrapolate_beyond_the_rao_headings():
    # 0-90 only (no mirror is made for headings up to 180): 120 deg has neighbours 90 and
    # 0 across a 270-deg gap, which is extrapolation, not interpolation.
    with pytest.raises(InputError, match="heading 120 deg is not in the RAO file"):
        select_headings(rao([0, 30, 60, 90]), [120], interpolation="linear")
