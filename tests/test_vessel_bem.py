"""BEM RAOs with Capytaine (optional "bem" extra).

The analytical helpers run by default. The Capytaine runs use a tiny mesh, are
marked slow and run only when asked for: ``pytest -m slow`` or JLS_RUN_BEM=1
(the default test run never starts Capytaine).
"""

import os

import numpy as np
import pytest

from jls.errors import InputError
from jls.vessel import bem
from jls.vessel.rao import validate_rao

BOX = dict(length=40.0, beam=12.0, draught=4.0, kg=4.0)


@pytest.fixture
def capytaine_requested(request):
    asked = "slow" in (request.config.getoption("markexpr", default="") or "")
    if not (asked or os.environ.get("JLS_RUN_BEM") == "1"):
        pytest.skip("Capytaine runs only with `pytest -m slow` or JLS_RUN_BEM=1")
    return pytest.importorskip("capytaine")
RADII = (0.35 * 12.0, 0.25 * 40.0, 0.26 * 40.0)


def test_box_hydrostatics_by_hand():
    h = bem.box_hydrostatics(382.0, 124.0, 20.0, 20.0)
    assert h["volume_m3"] == pytest.approx(382 * 124 * 20)
    assert h["displacement_t"] == pytest.approx(1.025 * 382 * 124 * 20)
    assert h["gm_t_m"] == pytest.approx(10.0 + 124.0 ** 2 / 240.0 - 20.0)   # 54.07 m
    assert h["gm_l_m"] == pytest.approx(10.0 + 382.0 ** 2 / 240.0 - 20.0)
    assert h["c44_knm_rad"] == pytest.approx(h["displacement_t"] * 9.81 * h["gm_t_m"])
    assert h["cog_z_m"] == 0.0
    with pytest.raises(InputError) as err:
        bem.box_hydrostatics(382.0, 124.0, 20.0, 90.0)
    assert err.value.field == "kg"
    with pytest.raises(InputError):
        bem.box_hydrostatics(-1.0, 124.0, 20.0, 20.0)


def test_roll_natural_frequency_interpolates_the_crossing():
    omega = np.array([0.2, 0.4, 0.6])
    a44 = np.zeros(3)
    # c44 / i44 = 0.25 -> omega_n = 0.5; the residual c44 - w^2 i44 is interpolated
    # linearly in omega between grid points: 0.09/(0.09 + 0.11) of the way = 0.49
    w = bem.roll_natural_frequency(omega, a44, 1.0, 0.25)
    assert w == pytest.approx(0.4 + 0.2 * 0.09 / 0.20, rel=1e-9)
    fine = np.linspace(0.2, 0.6, 401)
    assert bem.roll_natural_frequency(fine, np.zeros(401), 1.0, 0.25) == pytest.approx(
        0.5, abs=1e-4)
    with pytest.raises(InputError):
        bem.roll_natural_frequency(omega, a44, 1.0, 4.0)


@pytest.mark.slow
def test_tiny_box_raos(capytaine_requested):
    omega = np.array([0.3, 0.8, 1.2, 1.6, 2.2])
    ds = bem.compute_box_raos(**BOX, radii=RADII, roll_damping_ratio=0.05, omega=omega,
                              headings=np.radians([90.0, 180.0]), panel_size=4.0)
    validate_rao(ds)
    assert ds.attrs["reference_point_m"] == [0.0, 0.0, 0.0]       # CoG at the waterline
    beam = ds["rao"].sel(wave_direction=np.pi / 2)
    heave = beam.sel(dof="heave").values[0]
    assert abs(heave) == pytest.approx(1.0, abs=0.05)              # long wave
    assert abs(np.degrees(np.angle(heave))) < 5.0
    sway = beam.sel(dof="sway").values[0]
    assert np.degrees(np.angle(sway)) == pytest.approx(-90.0, abs=5.0)   # exp(+i w t)
    head = ds["rao"].sel(wave_direction=np.pi)
    assert np.all(np.abs(head.sel(dof=["sway", "roll", "yaw"]).values) < 1e-6)
    assert 0 < ds.attrs["roll_radiation_damping_ratio_at_resonance"] < 1
    assert ds.attrs["roll_viscous_damping_ratio"] == 0.05


@pytest.mark.slow
def test_mesh_file_with_symmetry(tmp_path, capytaine_requested):
    cpt = capytaine_requested

    mesh = cpt.mesh_parallelepiped(size=(40.0, 12.0, 4.0), center=(0, 0, -2.0),
                                   resolution=(10, 4, 1), missing_sides={"top"})
    path = tmp_path / "box.gdf"
    _write_gdf(path, mesh)
    omega = np.array([0.3, 1.0, 1.6])
    mass = 1.025 * 40 * 12 * 4
    ds = bem.compute_mesh_raos(path, mass, (0.0, 0.0, 0.0), RADII, 0.05, omega,
                               np.radians([90.0]), symmetry="xOz")
    box = bem.compute_box_raos(**BOX, radii=RADII, roll_damping_ratio=0.05, omega=omega,
                               headings=np.radians([90.0]), panel_size=4.0)
    np.testing.assert_allclose(np.abs(ds["rao"].sel(dof=["heave", "roll"]).values),
                               np.abs(box["rao"].sel(dof=["heave", "roll"]).values),
                               rtol=0.1, atol=1e-3)
    with pytest.raises(InputError) as err:
        bem.compute_mesh_raos(path, 2 * mass, (0.0, 0.0, 0.0), RADII, 0.05, omega,
                              np.radians([90.0]))
    assert err.value.field == "mass"


def _write_gdf(path, mesh):
    """Minimal WAMIT GDF writer (quadrilateral panels) for the test mesh."""
    vertices = mesh.vertices
    lines = ["jls test box", "1.0 9.81", "0 0", str(mesh.nb_faces)]
    for face in mesh.faces:
        for v in face:
            lines.append(" ".join(f"{c:.6f}" for c in vertices[v]))
    path.write_text("\n".join(lines) + "\n")


def _closed_volume(vertices, faces):
    """Volume enclosed by the panels and the waterplane (divergence theorem, z-component:
    V = sum over panels of z n_z A with outward normals, the waterplane z = 0 adding
    nothing)."""
    v = vertices[faces]                                   # (m, 4, 3)
    n = np.cross(v[:, 2] - v[:, 0], v[:, 3] - v[:, 1]) / 2    # area-weighted normal
    return float(np.sum(v.mean(axis=1)[:, 2] * n[:, 2]))


def test_slotted_twin_hull_mesh_by_hand():
    from jls.vessel.hulls import slotted_twin_hull
    hm = slotted_twin_hull(382.0, 124.0, 14.0, 122.0, 59.0, 12.0)
    area = 382 * 124 - 122 * 59
    assert hm.facts["waterplane_area_m2"] == pytest.approx(area)
    assert hm.facts["volume_m3"] == pytest.approx(area * 14.0)
    # the slot moves the centre of buoyancy aft: 122 x 59 m missing 130 m forward of midship
    assert hm.facts["x_b_m"] == pytest.approx(-122 * 59 * 130 / area)
    assert hm.facts["waterplane_i_t_m4"] == pytest.approx(382 * 124 ** 3 / 12 - 122 * 59 ** 3 / 12)
    # the y <= 0 half with outward normals encloses half the volume; the lid covers half
    # the waterplane at 2 % of the draught below it, normals down
    assert np.all(hm.vertices[:, 1] <= 1e-9) and hm.vertices[:, 2].min() == pytest.approx(-14.0)
    assert 2 * _closed_volume(hm.vertices, hm.faces) == pytest.approx(area * 14.0, rel=1e-9)
    lv = hm.lid_vertices[hm.lid_faces]
    lid_n = np.cross(lv[:, 2] - lv[:, 0], lv[:, 3] - lv[:, 1]) / 2
    assert np.all(lid_n[:, 2] < 0) and 2 * -lid_n[:, 2].sum() == pytest.approx(area)
    assert np.allclose(hm.lid_vertices[:, 2], -0.28)
    # no panel in the slot (open water between the demi-hulls)
    centres = hm.vertices[hm.faces].mean(axis=1)
    assert not np.any((centres[:, 0] > 191 - 122 + 1) & (centres[:, 1] > -29.5 + 1e-6)
                      & (centres[:, 2] < -1e-6) & (np.abs(centres[:, 1]) > 1e-6)
                      & (np.isclose(centres[:, 2], -14.0)))
    with pytest.raises(InputError):
        slotted_twin_hull(382.0, 124.0, 14.0, 400.0, 59.0, 12.0)


def test_ship_hull_mesh_is_closed_and_outward():
    from jls.vessel.hulls import ship_hull
    hm = ship_hull(300.0, 50.0, 15.0, 6.0)
    volume = 2 * _closed_volume(hm.vertices, hm.faces)
    assert 0.6 * 300 * 50 * 15 < volume < 0.85 * 300 * 50 * 15      # a ship's block coefficient
    v = hm.vertices[hm.faces]
    n = np.cross(v[:, 2] - v[:, 0], v[:, 3] - v[:, 1])
    assert np.all(n[:, 1] <= 1e-9)                                   # away from the centreplane


@pytest.mark.slow
def test_hull_path_equals_the_box_path_for_a_slotless_hull(capytaine_requested):
    """A slotted twin hull without a slot is a box: the hull path (DOFs about the
    waterline point, mass properties added afterwards) gives the box path's RAOs (DOFs
    about the CoG); the slot then yaws the hull in beam seas."""
    from jls.vessel.hulls import slotted_twin_hull
    omega, headings = np.array([0.5, 1.0, 1.4]), np.radians([60.0, 90.0])
    box = bem.compute_box_raos(**BOX, radii=RADII, roll_damping_ratio=0.05, omega=omega,
                               headings=headings, panel_size=4.0)
    hm = slotted_twin_hull(40.0, 12.0, 4.0, 0.0, 0.0, 4.0, lid_panel_size=4.0)
    hull = bem.compute_hull_raos(hm, BOX["kg"] - BOX["draught"], RADII, 0.05, omega, headings)
    assert hull.attrs["reference_point_m"] == pytest.approx(box.attrs["reference_point_m"], abs=1e-9)
    np.testing.assert_allclose(np.abs(hull["rao"].values), np.abs(box["rao"].values),
                               rtol=0.05, atol=2e-3)
    assert hull.attrs["roll_natural_period_s"] == pytest.approx(box.attrs["roll_natural_period_s"],
                                                                rel=0.02)
    slotted = bem.compute_hull_raos(slotted_twin_hull(40.0, 12.0, 4.0, 12.0, 4.0, 4.0),
                                    -0.5, RADII, 0.05, omega, np.radians([90.0]))
    assert np.abs(slotted["rao"].sel(dof="yaw").values).max() > 1e-4
