"""The reconstructed baseline rigging against the study (issue 18, items 3 and 5).

The configured layout is the fit of ``scripts/fit_baseline_rigging.py`` (targets in
``jls.plant.reconstruction``): appendix A.1's K in the project frame, table 3.1's
periods, table 3.3's mean wire length, equilibrium in six equations, and chapter 5's
sensitivities. Achieved (config/config.yaml):

    periods 15.7008 / 3.5431 / 1.2181 / 1.1413 s (study 15.70 / 3.543 / 1.218 / 1.141)
    K11 1558.6, K22 2.3394e5, K33 1.2101e8, K44 1.02402e7, K13 -3.6940e4, K14 5.4237e4,
    K34 2.0525e6 (study, z up: 1559, 2.339e5, 1.2099e8, 1.024e7, -3.695e4, 5.425e4,
    2.052e6), all within 0.03 %; mean wire length 62.516 m (62.515)
    top spread (study datum, anchors from the centreline) 22.477 m (table 5.2: 22.48)
    figure 5.3, top spread 10.5 m: sway 18.11 s (over 18), yaw 7.28 s (towards 7)
                 top spread 36 m:   sway 11.66 s (11.5)
                 bottom spread X 10 / 34.2 m: yaw 8.79 / 3.52 s (9 / 3.5)
    table 5.2, 13.05 m and drop 66.46 m: sway 18.387 s (18.39), yaw 6.49 s (section 5.7:
    6.52 s, not a target), side lead 9.94 deg (the corner of the study's optimum)
"""

from pathlib import Path

import numpy as np
import pytest

from jls.config.loader import load
from jls.plant import reconstruction as rec
from jls.plant import study_frame as sf
from jls.plant.candidates import plant_dataset
from jls.plant.model import build, from_matrices
from jls.plant.rigging import apply_design, design_variables

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
A1 = ROOT / "tests" / "data" / "appendix_a1_plant.yaml"
TARGET = {t.key: t for t in rec.TARGETS}


@pytest.fixture(scope="module")
def got(rig):
    return rec.achieved(rig.layout, rig.jacket, rig.wire_stiffness, rig.g)


def test_periods_and_stiffness_match_the_study_in_the_project_frame(got):
    """Periods within 0.05 % of table 3.1 / the A.1 plant, every K term within 0.1 % of
    appendix A.1 converted to z up, mean wire length within 0.05 % of table 3.3."""
    for t in rec.TARGETS:
        if t.group != "plant":
            continue
        tol = 1e-3 if t.key.startswith("K") else 5e-4
        assert got[t.key] == pytest.approx(t.study, rel=tol), t.key
    assert max(abs(got["surge_residual"]), abs(got["pitch_residual"])) < 1e-5


def test_fitted_layout_has_the_study_s_sway_roll_coupling(rig):
    """Converted to the study's z-down frame, the fitted K has the printed signs
    (K13 > 0, K14 > 0, K34 < 0), and the sway mode rolls and yaws with the same phase
    relative to sway as the appendix A.1 plant's (project frame)."""
    p = build(rig.layout, rig.jacket, rig.wire_stiffness, g=rig.g)
    k_study = sf.to_study(p.K)
    for i, j in [(0, 2), (0, 3), (2, 3)]:
        assert np.sign(k_study[i, j]) == np.sign(sf.A1_K_STUDY[i, j]), (i, j)
    assert p.K[0, 2] < 0 and p.K[2, 3] > 0 and p.K[0, 3] > 0
    a1 = from_matrices(A1, g=9.81, zeta=0.0098)
    mine, theirs = p.modes.shapes[:, 0], a1.modes.shapes[:, 0]
    for dof in (2, 3):      # roll, yaw relative to sway in the sway mode
        assert np.sign(mine[dof] / mine[0]) == np.sign(theirs[dof] / theirs[0])
        assert mine[dof] / mine[0] == pytest.approx(theirs[dof] / theirs[0], rel=0.02)
    # Table 3.1: the sway mode carries 98.7 % sway, the yaw mode 98.5 % yaw.
    assert p.modes.energy_fraction[0, 0] == pytest.approx(0.987, abs=2e-3)
    assert p.modes.energy_fraction[1, 3] == pytest.approx(0.985, abs=2e-3)


def test_fitted_kb_is_the_printed_kb_within_the_fit(rig):
    """The geometric Kb, taken to the study's frame, is the printed one within the
    fit's 0.1 % on K (or half a printed digit where that is larger)."""
    p = build(rig.layout, rig.jacket, rig.wire_stiffness, g=rig.g)
    dev = sf.printed_deviation(sf.to_study(p.Kb))
    allowed = np.maximum(sf.A1_PRINT_HALF_STEP, 1e-3 * np.abs(sf.A1_KB_PRINTED) * sf.A1_PRINT_SCALE)
    assert np.all(dev <= allowed)


def test_chapter_5_sensitivity_within_the_study_s_stated_precision(got):
    """Every chapter-5 target is met within the precision the study states it to
    (table 5.2 to its last digit, figure 5.3's periods as the text rounds them to 0.5 s):
    top spread 22.477 m (22.48), sway 18.11 s at 10.5 m (over 18), yaw 7.28 s there
    (towards 7), sway 11.66 s at 36 m (11.5), optimum 18.387 s (18.39), yaw 8.79 s at a
    bottom spread X of 10 m (9) and 3.52 s at 34.2 m (3.5). The largest relative misses,
    the sway at 36 m (+1.4 %) and the yaw at 10.5 m (+4 %), are what the plant targets
    leave: the fit without chapter 5 gives 11.66 s and 7.33 s."""
    for t in rec.TARGETS:
        if t.group == "chapter5":
            assert t.met(got[t.key]), (t.key, got[t.key], t.study)
    assert got["optimum_sway"] == pytest.approx(18.39, abs=0.005)
    assert got["optimum_yaw"] == pytest.approx(6.52, rel=0.01)      # section 5.7, untargeted


def test_the_study_s_optimum_sits_on_the_side_lead_and_splash_limits(rig):
    """Table 5.2's 13.05 m / 66.46 m: the drop at the splash-clearance limit and the
    side lead angle within 0.1 deg of its 10 deg limit, so the study's optimum is the
    corner of the feasible region it describes (section 5.4). With the tolerance budgets
    that corner is infeasible (no margin to spare), and the configured 'detuned'
    candidate is the same corner moved inside them: the splash clearance and the side
    lead keep exactly their budgets."""
    ds, _ = plant_dataset(rig, {"study": {"top_spread_y": rec.project_top_spread(13.05),
                                          "drop_height": 66.46}})
    assert 0.0 < float(ds["side_lead_margin"][0]) < 0.1
    assert abs(float(ds["splash_clearance_margin"][0])) <= rig.limits.at_limit_tolerance_m
    assert not bool(ds["feasible"][0])                        # inside its budgets
    cfg = load(CONFIG)
    detuned = {c["name"]: c for c in cfg["candidates"]}["detuned"]
    assert detuned["drop_height_m"] == pytest.approx(66.46 - rig.limits.budget.splash)
    ds, _ = plant_dataset(rig, {"detuned": {"top_spread_y": detuned["top_spread_y_m"],
                                            "drop_height": detuned["drop_height_m"]}})
    assert bool(ds["feasible"][0])
    lead_budget = rig.limits.budget.lead_angle
    assert float(ds["side_lead_margin"][0]) == pytest.approx(lead_budget, abs=0.01)
    assert float(ds["splash_clearance_margin"][0]) == pytest.approx(rig.limits.budget.splash, abs=0.01)
    lo, hi = rig.design_space["top_spread_y"]
    assert (lo, hi) == pytest.approx(tuple(rec.project_top_spread([10.5, 36.0])))


def test_a_port_to_starboard_datum_cannot_reproduce_figure_5_3(rig):
    """Applying only half of each study change to each anchor (the study's top spread
    read as the port-starboard distance, the excursion carried about the baseline)
    gives 13.8-17.0 s over the range and 17.5 s at the optimum: figure 5.3's 11.5 to
    over 18 s and table 5.2's 18.39 s are out of reach, whatever the layout, because
    the plant targets fix the layout's sensitivity (test docstring of the module)."""
    base = design_variables(rig.layout)
    s0 = float(rec.study_top_spread(base["top_spread_y"]))
    cases = [(10.5, None), (36.0, None), (13.05, 66.46)]
    top = np.array([base["top_spread_y"] + (s - s0) for s, _ in cases])
    drop = np.array([h if h else base["drop_height"] for _, h in cases])
    p = build(apply_design(rig.layout, rig.jacket.z_p, top_spread_y=top, drop_height=drop),
              rig.jacket, rig.wire_stiffness, g=rig.g)
    sway = p.modes.period[:, 0]
    assert sway[0] < 17.1 and sway[1] > 13.7 and sway[2] < 17.6


def test_the_configured_layout_is_the_fit_s_result(rig):
    """Started from the configured layout, the fit moves no coordinate by more than 5 mm
    and lowers its cost by under 3 % (the rounding of the coordinates to the millimetre
    costs 1.3 %)."""
    h_drop = float(rig.layout.cog_depth) - rig.jacket.z_p
    before = 0.5 * np.sum(rec.residuals(rec.achieved(rig.layout, rig.jacket, rig.wire_stiffness)) ** 2)
    lay, _, cost = rec.fit(rig.layout, rig.jacket, rig.wire_stiffness, h_drop, max_nfev=200)
    moved = np.abs(rec.parameters_from_layout(lay) - rec.parameters_from_layout(rig.layout))
    assert moved.max() < 5e-3
    assert cost > 0.97 * before


def test_unstretched_wire_is_the_study_s_suspension(rig):
    """Not a target: the fitted wires' unstretched length is the study's suspension of
    38.61 m steel + 23.60 m Dyneema = 62.21 m (appendix A.3) within 2 cm (62.20-62.21 m;
    the equilibrium length 62.515 m of table 3.3 is that stretched by T/k = 0.31 m)."""
    p = build(rig.layout, rig.jacket, rig.wire_stiffness, g=rig.g)
    np.testing.assert_allclose(p.unstretched_length, 38.61 + 23.60, atol=0.02)


def test_geometric_baseline_responds_as_the_appendix_plant(rig):
    """Driven by the same hinge motion (sway, roll and yaw, smooth RAO-like shapes), the
    fitted layout and the converted appendix matrices give the relative sway, roll and
    yaw sigma within 0.5 % at Tz 6.6 and 8.5 s (achieved 0.12 %; the layout fitted with
    the old signs was 23 % low in relative roll on the default vessel)."""
    from jls.response.solver import frequency_grid, transfer_functions
    from jls.response.statistics import unit_statistics

    geo = build(rig.layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta,
                anchor_modes=rig.anchor_modes)
    a1 = from_matrices(A1, g=9.81, zeta=0.0098)
    wn = 2 * np.pi / a1.modes.period
    omega = frequency_grid(0.1, 3.0, 0.005, wn, a1.damping_ratio)
    shape = 1.0 / (1 + ((omega - 0.45) / 0.15) ** 2) * np.exp(-0.5j * omega)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0], qb[..., 2], qb[..., 3] = 4.0 * shape, 0.02 * shape, 0.002 * shape * 1j
    sig = {}
    for name, p in (("geo", geo), ("a1", a1)):
        _, H = transfer_functions(p.M, p.K, p.Kb, p.C, omega, qb)
        sig[name] = np.array([unit_statistics(omega, H[0, 0, :, i], [6.6, 8.5])["sigma"]
                              for i in (0, 2, 3)])
    np.testing.assert_allclose(sig["geo"], sig["a1"], rtol=5e-3)
