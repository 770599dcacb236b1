"""Plant physics: linearisation, equilibrium, modes, damping, the study's numbers."""

from pathlib import Path

import numpy as np
import pytest
from finite_differences import hessian

from jls.config.builders import plant_from_config, rigging_from_config
from jls.config.loader import load
from jls.plant import equilibrium
from jls.plant.linearise import potential, stiffness_matrices
from jls.plant.model import Jacket, build, from_matrices
from jls.plant.modes import modal_analysis, rayleigh_coefficients
from jls.plant.rigging import (
    Layout,
    Limits,
    apply_design,
    design_variables,
    lumped_inertial_mass,
    series_stiffness,
)
from jls.plant.study_frame import A1_K_STUDY, to_project

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
A1 = ROOT / "tests" / "data" / "appendix_a1_plant.yaml"
G = 9.81

# Appendix A.1 (reference study), t, kN, m, rad, converted from the study's z-down frame
# to the project's (jls.plant.study_frame: K13 and K34 change sign).
K_STUDY = to_project(A1_K_STUDY)
T_STUDY = np.array([15.70, 3.543, 1.218, 1.141])


def symmetric_layout(half_x=8.0, half_y=22.0, drop=60.0, z_p=22.41, lean_y=0.0, cross=0.0):
    """Four wires, port/starboard mirror-symmetric; lean_y moves anchors outboard and
    cross shifts anchors fore-aft in opposite senses (crossed pairs)."""
    ax = np.array([half_x + cross, -half_x - cross, half_x + cross, -half_x - cross])
    ay = np.array([half_y + lean_y, half_y + lean_y, -half_y - lean_y, -half_y - lean_y])
    anchors = np.stack([ax, ay, np.zeros(4)], -1)
    padeyes = np.stack([np.array([half_x, -half_x, half_x, -half_x]),
                        np.array([half_y, half_y, -half_y, -half_y]), np.full(4, z_p)], -1)
    return Layout(anchors=anchors, padeyes=padeyes, cog_depth=np.asarray(drop + z_p))


def test_parallel_vertical_wires_pendulum_and_heave():
    m, h, k = 7650.0, 60.0, 63274.0
    lay = symmetric_layout(drop=h, z_p=0.0)
    p = build(lay, Jacket(m_grav=m, m_kin=m, ixx=4.55e6, izz=3.286e6, z_p=0.0), k, g=G)
    periods = dict(zip(["sway", "heave", "roll", "yaw"], [None] * 4))
    for i, dom in enumerate(p.modes.dominant):
        periods[["sway", "heave", "roll", "yaw"][dom]] = p.modes.period[i]
    assert periods["sway"] == pytest.approx(2 * np.pi * np.sqrt(h / G), rel=1e-9)
    assert periods["heave"] == pytest.approx(2 * np.pi * np.sqrt(m / (4 * k)), rel=1e-9)
    np.testing.assert_allclose(p.tension, m * G / 4, rtol=1e-12)


def test_pendulum_limit_with_lifting_points_above_cog():
    # Stiff wires: the sway period tends to the simple pendulum of the drop height.
    m, h = 7650.0, 60.0
    p = build(symmetric_layout(drop=h), Jacket(m, m, 4.55e6, 3.286e6, 22.41), 1e9, g=G)
    assert p.modes.period[0] == pytest.approx(2 * np.pi * np.sqrt(h / G), rel=2e-3)


def _asymmetric_state():
    rng = np.random.default_rng(7)
    lay = symmetric_layout(lean_y=1.5, cross=6.0)
    lay = Layout(anchors=lay.anchors + rng.normal(0, 1.0, (4, 3)) * [1, 1, 0.2],
                 padeyes=lay.padeyes + rng.normal(0, 1.0, (4, 3)) * [1, 1, 0.2],
                 cog_depth=lay.cog_depth)
    k = np.array([63e3, 60e3, 70e3, 65e3])
    tension = np.array([20e3, 17e3, 19e3, 22e3])     # any state: the Hessian is exact
    return lay, k, tension


def test_K_and_Kb_equal_finite_differences_of_V():
    lay, k, tension = _asymmetric_state()
    K, Kb = stiffness_matrices(lay.anchors, lay.padeyes, lay.cog_depth, k, tension)
    d = lay.anchors - lay.padeyes + [0, 0, float(lay.cog_depth)]
    L0 = np.linalg.norm(d, axis=-1) - tension / k

    def V(x):
        return potential(x[:4], x[4:], lay.anchors, lay.padeyes, lay.cog_depth, k, L0, 7650, G)

    H = hessian(V, 8)
    scale = np.abs(H).max()
    np.testing.assert_allclose(K, H[:4, :4], atol=2e-6 * scale, rtol=1e-5)
    np.testing.assert_allclose(Kb, H[:4, 4:], atol=2e-6 * scale, rtol=1e-5)


def test_vectorised_equals_one_by_one():
    lay, k, tension = _asymmetric_state()
    many = Layout(anchors=np.stack([lay.anchors, lay.anchors * 1.1]),
                  padeyes=np.stack([lay.padeyes, lay.padeyes]),
                  cog_depth=np.array([lay.cog_depth, lay.cog_depth + 3]))
    K, Kb = stiffness_matrices(many.anchors, many.padeyes, many.cog_depth, k, tension)
    K1, Kb1 = stiffness_matrices(many.anchors[1], many.padeyes[1], many.cog_depth[1], k, tension)
    np.testing.assert_allclose(K[1], K1)
    np.testing.assert_allclose(Kb[1], Kb1)


def test_mirror_symmetric_layout_has_no_heave_coupling():
    p = build(symmetric_layout(lean_y=2.0, cross=7.0), Jacket(7650, 7719, 4.55e6, 3.286e6, 22.41), 63274)
    for j in (0, 2, 3):
        assert p.K[1, j] == pytest.approx(0.0, abs=1e-9 * p.K[1, 1])
        assert p.Kb[1, j] == pytest.approx(0.0, abs=1e-9 * p.K[1, 1])
        assert p.Kb[j, 1] == pytest.approx(0.0, abs=1e-9 * p.K[1, 1])
    np.testing.assert_allclose(p.K, p.K.T, atol=1e-9 * np.abs(p.K).max())


def test_rigid_body_invariance_of_Kb():
    """A common translation or yaw of hinge and jacket strains no wire; a common roll
    about the hinge only tilts gravity: Kb columns follow from K."""
    cfg = load(CONFIG)
    p = plant_from_config(cfg)
    W, z_eq = p.m_grav * p.g, float(p.layout.cog_depth)
    tol = 1e-9 * np.abs(p.K).max()
    np.testing.assert_allclose(p.Kb[:, 0], -p.K[:, 0], atol=tol)
    np.testing.assert_allclose(p.Kb[:, 1], -p.K[:, 1], atol=tol)
    # Yaw carries the small surge/pitch residual of the equilibrium (< 1e-4 W).
    np.testing.assert_allclose(p.Kb[:, 3], -p.K[:, 3], atol=1e-4 * p.m_grav * p.g)
    expected = -p.K[:, 2] - z_eq * p.K[:, 0] + np.array([W, 0, 0, 0])
    np.testing.assert_allclose(p.Kb[:, 2], expected, atol=1e-5 * np.abs(p.K).max())


def test_equilibrium_balances_all_six_equations():
    cfg = load(CONFIG)
    rig = rigging_from_config(cfg)
    eq = equilibrium.solve(rig.layout.anchors, rig.layout.padeyes, rig.layout.cog_depth,
                           rig.jacket.m_grav * G)
    assert np.all(eq.tension > 0)
    assert bool(eq.balanced)
    A, _ = equilibrium.equilibrium_matrix(rig.layout.anchors, rig.layout.padeyes, rig.layout.cog_depth)
    assert np.sum(eq.tension * A[2]) == pytest.approx(rig.jacket.m_grav * G, rel=1e-12)


def test_layout_out_of_surge_pitch_balance_is_reported():
    # Anchors all shifted forward: the wires pull the jacket forward; no tension set
    # can hold it in surge, and the residual says so.
    lay = symmetric_layout()
    lay = Layout(anchors=lay.anchors + [6.0, 0, 0], padeyes=lay.padeyes, cog_depth=lay.cog_depth)
    eq = equilibrium.solve(lay.anchors, lay.padeyes, lay.cog_depth, 7650 * G)
    assert not bool(eq.balanced)
    assert abs(eq.residual[0]) > 1e-3
    np.testing.assert_allclose(eq.residual[[1, 2, 3, 5]], 0.0, atol=1e-12)


def test_appendix_a1_matrices_reproduce_study_periods_and_damping():
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    np.testing.assert_allclose(p.modes.period, T_STUDY, rtol=2e-3)
    alpha, beta = p.rayleigh
    assert alpha == pytest.approx(6.40e-3, rel=5e-3)
    assert beta == pytest.approx(9.02e-3, rel=5e-3)
    # Section 3.5: roll and heave receive 2.39 % and 2.54 %.
    np.testing.assert_allclose(p.damping_ratio, [0.0098, 0.0098, 0.0239, 0.0254], atol=1e-4)
    # Table 3.1: sway mode 98.7 % sway kinetic energy, yaw mode 98.5 % yaw.
    assert p.modes.energy_fraction[0, 0] == pytest.approx(0.987, abs=2e-3)
    assert p.modes.energy_fraction[1, 3] == pytest.approx(0.985, abs=2e-3)


def test_baseline_matches_study_within_issue_tolerances():
    p = plant_from_config(load(CONFIG))
    t = p.modes.period
    assert abs(t[0] / T_STUDY[0] - 1) < 0.02            # sway
    np.testing.assert_array_less(np.abs(t[1:] / T_STUDY[1:] - 1), 0.01)
    for i in range(4):
        assert abs(p.K[i, i] / K_STUDY[i, i] - 1) < 0.05
    for i, j in [(0, 2), (0, 3), (2, 3)]:
        assert np.sign(p.K[i, j]) == np.sign(K_STUDY[i, j])
        assert abs(p.K[i, j] / K_STUDY[i, j] - 1) < 0.15
    assert bool(p.balanced)
    assert [int(d) for d in p.modes.dominant] == [0, 3, 2, 1]   # sway, yaw, roll, heave
    # Mean equilibrium wire length of table 3.3, 62.515 m.
    d = p.layout.anchors - p.layout.padeyes + [0, 0, float(p.layout.cog_depth)]
    assert np.linalg.norm(d, axis=-1).mean() == pytest.approx(62.515, rel=2e-3)


def test_series_stiffness_and_mass_lumping_match_study():
    # Appendix A.3: 38.61 m steel (EA 9.64e6 kN) + 23.60 m Dyneema (EA 2.0e6 kN).
    assert series_stiffness([(38.61, 9.64e6), (23.60, 2.0e6)]) == pytest.approx(63270, rel=1e-4)
    # Table A.1: free blocks (4 x 190 t at 38.61 m of 62.21 m) give 7940 t.
    m = lumped_inertial_mass(7650, np.full(4, 62.21), 190, 38.61)
    assert m == pytest.approx(7940, abs=5)


def test_rayleigh_gives_equal_damping_at_anchors():
    a, b = rayleigh_coefficients(0.4, 1.8, 0.01)
    for w in (0.4, 1.8):
        assert 0.5 * (a / w + b * w) == pytest.approx(0.01)


def test_design_variables_round_trip_and_drop_height_limit():
    rig = rigging_from_config(load(CONFIG))
    base = design_variables(rig.layout)
    same = apply_design(rig.layout, rig.jacket.z_p, **{k: v for k, v in base.items()})
    np.testing.assert_allclose(same.anchors, rig.layout.anchors, atol=1e-12)
    np.testing.assert_allclose(same.padeyes, rig.layout.padeyes, atol=1e-12)
    for name, (lo, hi) in rig.design_space.items():
        assert lo <= base[name] <= hi, name
    moved = apply_design(rig.layout, rig.jacket.z_p, top_spread_y=np.array([40.0, 50.0]),
                         drop_height=np.array([55.0, 66.0]))
    got = design_variables(moved)
    np.testing.assert_allclose(got["top_spread_y"], [40.0, 50.0])
    np.testing.assert_allclose(got["drop_height"], [55.0, 66.0])
    np.testing.assert_allclose(got["bottom_spread_y"], base["bottom_spread_y"])
    # Section 5.1: 119.46 m hinge, 48 m padeye to tip, 5 m clearance -> 66.46 m.
    assert Limits().max_drop() == pytest.approx(66.46)
    margins = Limits().check(moved)
    assert margins["splash_clearance_margin_m"][1] == pytest.approx(0.46)


def test_narrowing_top_spread_lengthens_sway_period():
    # Chapter 5: the top spread is the strongest lever on the sway period.
    rig = rigging_from_config(load(CONFIG))
    lay = apply_design(rig.layout, rig.jacket.z_p, top_spread_y=np.array([40.0, 47.3, 55.0]))
    p = build(lay, rig.jacket, rig.wire_stiffness, g=G)
    sway = p.modes.period[:, 0]
    assert sway[0] > sway[1] > sway[2]


def test_modal_analysis_sorts_by_period_and_normalises_energy():
    md = modal_analysis(np.diag([7719, 7719, 4.55e6, 3.286e6]), K_STUDY)
    assert np.all(np.diff(md.period) < 0)
    np.testing.assert_allclose(md.energy_fraction.sum(-1), 1.0)


def test_wire_slack_in_exact_arithmetic_is_slack_whatever_the_round_off():
    # One anchor pulled 80 m to port: sway balance leaves that wire and its mirror with
    # zero tension in exact arithmetic; the solver returns a round-off of either sign.
    rig = rigging_from_config(load(CONFIG))
    anchors = rig.layout.anchors.copy()
    anchors[0] = [8.297, 80.0, 0.0]
    lay = Layout(anchors=anchors, padeyes=rig.layout.padeyes, cog_depth=rig.layout.cog_depth)
    p = build(lay, rig.jacket, rig.wire_stiffness, g=G)
    W = rig.jacket.m_grav * G
    assert np.all(np.abs(p.tension[[0, 2]]) < 1e-6 * W)
    np.testing.assert_array_equal(equilibrium.slack(p.tension, W), [True, False, True, False])
    assert np.all(np.isnan(p.K))
    # The rule: at or below 1e-6 of the weight is slack, above it is taut.
    t = np.array([-1.0, 0.0, 1e-6 * W, 1.001e-6 * W])
    np.testing.assert_array_equal(equilibrium.slack(t, W), [True, True, True, False])
