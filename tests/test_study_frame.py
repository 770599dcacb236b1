"""The study's z-down plant frame and jls's z-up frame (issue 18, item 3).

The appendix A.1 matrices are the Hessians of the study's Lagrangian (section 3.3.2),
written with z down. ``jls.plant.study_frame`` converts them with T = diag(1, -1, -1, 1)
(heave and roll reversed); these tests derive T from the study's coordinate definitions,
check that the printed Kb is the study-frame rigid-body identity of the printed K entry
by entry, and that the committed matrices file is the converted plant.
"""

from pathlib import Path

import numpy as np
import pytest
from finite_differences import hessian

from jls.plant import study_frame as sf
from jls.plant.linearise import rotation, stiffness_matrices
from jls.plant.model import from_matrices

ROOT = Path(__file__).resolve().parents[1]
A1 = ROOT / "tests" / "data" / "appendix_a1_plant.yaml"
S = np.diag([1.0, 1.0, -1.0])          # project -> study coordinates: z reversed


def _study_potential(q_s, qb_s, anchors_s, padeyes_s, z_eq, k, L0, m_grav, g):
    """Eqs. 3.5-3.8 literally, in the study's frame: r_CoG = (0, y, z + z_eq),
    V = -M g (z + z_eq) + 1/2 sum k (L - L0)^2, R = Rz(psi) Rx(phi) (textbook matrices
    in the study's coordinates)."""
    y, z, phi, psi = q_s
    yb, zb, phib, psib = qb_s
    r_cog = np.array([0.0, y, z + z_eq])
    r_hinge = np.array([0.0, yb, zb])
    d = (r_hinge + anchors_s @ rotation(phib, psib).T) - (r_cog + padeyes_s @ rotation(phi, psi).T)
    length = np.linalg.norm(d, axis=-1)
    return -m_grav * g * (z + z_eq) + 0.5 * np.sum(k * (length - L0) ** 2)


def test_rotation_about_a_reversed_z_axis():
    """S Rx(phi) S = Rx(-phi) and S Rz(psi) S = Rz(psi): roll changes sign, yaw does not."""
    for angle in (0.1, -0.37):
        np.testing.assert_allclose(S @ rotation(angle, 0.0) @ S, rotation(-angle, 0.0), atol=1e-15)
        np.testing.assert_allclose(S @ rotation(0.0, angle) @ S, rotation(0.0, angle), atol=1e-15)


def test_T_converts_the_study_lagrangian_hessians_into_jls_K_and_Kb():
    """The study's Lagrangian of a layout written in its own coordinates, differentiated
    numerically, gives T K T and T Kb T of jls's analytical matrices (an asymmetric
    layout, so every coupling is present)."""
    rng = np.random.default_rng(11)
    anchors = np.array([[8.0, 23.0, 0.0], [-9.0, 22.0, 0.0], [7.5, -24.0, 0.0], [-8.5, -21.0, 0.0]])
    padeyes = np.array([[16.0, 21.0, 22.41], [-17.0, 23.5, 22.41], [15.0, -22.0, 22.41],
                        [-16.5, -23.0, 22.41]]) + rng.normal(0, 0.5, (4, 3)) * [1, 1, 0]
    depth, k = 82.501, np.array([63e3, 61e3, 66e3, 64e3])
    tension = np.array([19e3, 18e3, 20e3, 21e3])
    K, Kb = stiffness_matrices(anchors, padeyes, depth, k, tension)
    d = anchors - padeyes + [0, 0, depth]
    L0 = np.linalg.norm(d, axis=-1) - tension / k

    def V(x):
        return _study_potential(x[:4], x[4:], anchors @ S, padeyes @ S, depth, k, L0, 7650.0, 9.81)

    H = hessian(V, 8)
    scale = np.abs(H).max()
    np.testing.assert_allclose(sf.to_project(H[:4, :4]), K, atol=2e-6 * scale, rtol=1e-5)
    np.testing.assert_allclose(sf.to_project(H[:4, 4:]), Kb, atol=2e-6 * scale, rtol=1e-5)


def test_printed_kb_is_the_study_frame_identity_of_the_printed_K():
    """Every printed Kb entry (and K entry) is reproduced within half its last digit
    (0.00005e8 = 5000); the roll column (0.0002, -1.1794, 0.0653)e8 and the diagnostic
    Kb33 + K33 = 3.048e6 come out of the z-down identity."""
    study = sf.appendix_a1("study")
    assert sf.printed_deviation(study["Kb"]).max() <= sf.A1_PRINT_HALF_STEP
    assert sf.printed_deviation(study["K"], sf.A1_K_PRINTED).max() <= sf.A1_PRINT_HALF_STEP
    np.testing.assert_allclose(study["Kb"][[0, 2, 3], 2] / 1e8, [0.0002, -1.1794, 0.0653],
                               atol=0.5e-4)
    assert study["Kb"][2, 2] + study["K"][2, 2] == pytest.approx(sf.A1_KB33_PLUS_K33, abs=500)


def test_the_z_up_identity_applied_to_the_unconverted_K_contradicts_the_print():
    """What the matrices file held before: the project-frame identity applied to the
    printed (z-down) K gives (-0.0009, -1.2404, -0.0242)e8 against the printed
    (0.0002, -1.1794, 0.0653)e8: three printed entries missed by 2 to 60 print steps."""
    wrong = sf.kb_from_rigid_body(sf.A1_K_STUDY, sf.A1_Z_EQ, sf.A1_M_GRAV * sf.A1_G, "project")
    np.testing.assert_allclose(wrong[[0, 2, 3], 2] / 1e8, [-0.0009, -1.2404, -0.0242], atol=0.5e-4)
    missed = sf.printed_deviation(wrong) > sf.A1_PRINT_HALF_STEP
    assert [tuple(ij) for ij in np.argwhere(missed)] == [(0, 2), (2, 2), (3, 2)]


def test_the_two_identities_are_the_same_physics():
    rng = np.random.default_rng(2)
    A = rng.normal(size=(4, 4))
    K = A + A.T
    for z_eq, W in [(82.501, 75046.5), (40.0, 1.0e4)]:
        np.testing.assert_allclose(
            sf.to_project(sf.kb_from_rigid_body(K, z_eq, W, "study")),
            sf.kb_from_rigid_body(sf.to_project(K), z_eq, W, "project"), atol=1e-12)


def test_matrices_file_is_the_converted_appendix_plant():
    """The committed file holds T M T, T K T, T Kb T: sway-roll K13 = -3.695e4 and
    roll-yaw K34 = +2.052e6 in the project frame, sway-yaw K14 = +5.425e4 unchanged."""
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    want = sf.appendix_a1("project")
    for name, got in (("M", p.M), ("K", p.K), ("Kb", p.Kb)):
        np.testing.assert_allclose(got, want[name], rtol=1e-9, atol=1e-6, err_msg=name)
    assert p.K[0, 2] == pytest.approx(-3.695e4) and p.K[2, 3] == pytest.approx(2.052e6)
    assert p.K[0, 3] == pytest.approx(5.425e4)
    back = sf.to_study(p.Kb)
    assert sf.printed_deviation(back).max() <= sf.A1_PRINT_HALF_STEP
    np.testing.assert_allclose(
        p.Kb, sf.kb_from_rigid_body(p.K, sf.A1_Z_EQ, sf.A1_M_GRAV * sf.A1_G, "project"), atol=1e-6)


def test_conversion_keeps_periods_damping_and_energy_fractions():
    """T is orthogonal: the study's periods 15.70 / 3.543 / 1.218 / 1.141 s and the
    modal energy fractions are those of the printed matrices in either frame."""
    from jls.plant.modes import modal_analysis

    study, project = sf.appendix_a1("study"), sf.appendix_a1("project")
    a, b = modal_analysis(study["M"], study["K"]), modal_analysis(project["M"], project["K"])
    np.testing.assert_allclose(a.period, b.period, rtol=1e-12)
    np.testing.assert_allclose(a.energy_fraction, b.energy_fraction, atol=1e-12)
    np.testing.assert_allclose(b.period, [15.70, 3.543, 1.218, 1.141], rtol=2e-3)


def test_right_handed_z_down_reading_gives_the_same_symmetric_plant():
    """T' = diag(-1, -1, 1, -1) (x forward, y to starboard, z down) differs from T by the
    port/starboard mirror; for the printed plant (no heave coupling) both agree."""
    Tp = np.diag([-1.0, -1.0, 1.0, -1.0])
    study = sf.appendix_a1("study")
    for name in ("M", "K", "Kb"):
        np.testing.assert_array_equal(Tp @ study[name] @ Tp, sf.to_project(study[name]))
