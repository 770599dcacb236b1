"""The 6-DOF nonlinear reference (MoorDyn) against the ROM: statics, free decay,
harmonic transfer function, slack wires, irregular sea, tugger, and the periods of the
modes the ROM does not carry. Skipped, with the reason, where MoorDyn cannot be
imported (then nothing is verified)."""

import numpy as np
import pytest

from jls.config.builders import plant_from_config
from jls.config.loader import load
from jls.tugger.setting import Tugger
from jls.verify import build_reference, chapter4, reference_available, rom, simulate, statics, still

OK, WHY = reference_available()
needs_moordyn = pytest.mark.skipif(not OK, reason=f"{WHY}; the recommendation is unverified")


@pytest.fixture(scope="module")
def plant():
    return plant_from_config(load("config/config.yaml"))


@pytest.fixture(scope="module")
def ref(plant):
    return build_reference(plant)


def _sway(plant):
    i = int(np.argmax(plant.modes.energy_fraction[:, 0]))
    return float(plant.modes.period[i]), float(plant.damping_ratio[i])


def test_static_pose_and_tensions_match_the_plant(plant, ref):
    # the reference's own six-equation pose: tensions within 0.1 % of the ROM's
    assert np.max(np.abs(ref.tension / plant.tension - 1)) < 1e-3
    assert np.max(np.abs(ref.pose[:3] - ref.cog_rest)) < 1e-3 * ref.lever
    assert np.max(np.abs(ref.pose[3:])) < 1e-3


@needs_moordyn
def test_moordyn_holds_the_static_pose(plant, ref):
    r = simulate.run(ref, still(0.02, 10.0))
    assert np.max(np.abs(r.tension[1:] / plant.tension - 1)) < 1e-3
    assert np.max(np.abs(r.pose[:, :3] - ref.pose[:3])) < 1e-4
    assert np.max(np.abs(r.pose[:, 3:] - ref.pose[3:])) < 1e-6


@needs_moordyn
def test_free_decay_period_and_damping_against_the_rom(plant, ref):
    period, zeta = _sway(plant)
    d = chapter4.free_decay(ref, plant, release_m=0.54)
    assert d.reference.period_undamped == pytest.approx(period, rel=2e-3)
    assert d.reference.zeta == pytest.approx(zeta, rel=0.10)
    assert d.reference.r2 > 0.999
    # the ROM through the same identifier gives its own modal values
    assert d.rom.period_undamped == pytest.approx(period, rel=1e-4)
    assert d.rom.zeta == pytest.approx(zeta, rel=1e-2)


@needs_moordyn
def test_transfer_function_at_small_amplitude(plant, ref):
    h = chapter4.harmonic(ref, plant, periods_s=(13.9, 17.0), amplitudes_m=(0.05,))
    assert np.all(np.abs(h["gain_ratio"].values - 1) < 0.01)
    dphase = (h["phase_rom"] - h["phase_reference"] + 180) % 360 - 180
    assert np.all(np.abs(dphase.values) < 1.0)


@needs_moordyn
def test_a_slack_wire_carries_no_compression(ref):
    # lifted 0.5 m: every wire is shorter than its unstretched length (stretch ~0.3 m)
    pose0 = ref.pose + np.array([0, 0, 0.5, 0, 0, 0])
    r = simulate.run(ref, still(0.02, 3.0), pose=pose0)
    length = np.array([statics.loads(ref, *statics.pose_matrix(p)).length for p in r.pose])
    slack = length < ref.L0
    assert slack[:5].all()                                   # slack at the start
    assert np.all(r.tension[1:][slack[1:]] == 0.0)           # and then carrying nothing
    assert (~slack).any() and np.all(r.tension >= 0.0)       # it falls until they pull again
    # while all four are slack the jacket falls under its net weight against the
    # heave dashpots alone: z'' = -g_net - a z', a = c_zz / M_kin
    g_net = ref.g * ref.m_grav / ref.m_kin
    a = ref.dashpots.matrix()[2, 2] / ref.m_kin
    k = int(np.flatnonzero(~slack.all(axis=1))[0]) - 1
    t = r.time[1:k]
    fall = g_net / a * (t - (1 - np.exp(-a * t)) / a)
    assert k > 5
    assert r.pose[1:k, 2] == pytest.approx(pose0[2] - fall, abs=1e-6)


@needs_moordyn
def test_reference_modes_include_surge_and_pitch(ref):
    m = chapter4.reference_modes(ref, cycles=5)
    dom = list(m["dominant_dof"].values)
    assert sorted(dom) == sorted(["surge", "sway", "heave", "roll", "pitch", "yaw"])
    assert np.all(np.abs(m["period_decay"] / m["period_linearised"] - 1) < 5e-3)
    assert np.all(np.abs(m["damping_ratio_decay"] / m["damping_ratio_target"] - 1) < 0.1)
    surge = m["period_linearised"].values[dom.index("surge")]
    assert 15.0 < surge < 25.0                              # a second pendulum, fore-aft


@needs_moordyn
def test_tugger_decay_against_the_linear_rom(plant):
    tug = Tugger(name="low", c=300.0, max_force=1000.0)
    ref_t = build_reference(plant, tugger=tug)
    # the pretensioned pair cancels in sway; its lines' tension stiffens surge a little
    ref0 = build_reference(plant)
    assert ref_t.pose[1] == pytest.approx(ref0.pose[1], abs=1e-9)
    assert np.allclose(ref_t.pose[:3], ref0.pose[:3], atol=1e-3)
    d = chapter4.free_decay(ref_t, plant, release_m=0.54, cycles=6)
    n = d.time.size
    x = rom.simulate(plant, 0.02, np.zeros((n, 4)), x0=rom.condensed_release(plant, 0.54),
                     c_tugger=tug.c)
    from jls.verify.identify import log_decrement
    z_rom = log_decrement(d.time, x[:, 0]).zeta
    assert z_rom > 2 * _sway(plant)[1]
    assert d.reference.zeta == pytest.approx(z_rom, rel=0.05)


@needs_moordyn
def test_irregular_sea_at_identical_excitation(plant):
    from jls.stages.vessel_motion import vessel_motion
    cfg = load("config/config.yaml")
    mo = vessel_motion(cfg["vessel"], [90.0], base_dir=".")
    ref = build_reference(plant, vessel_lever_m=mo.attrs["hinge_m"])
    out = chapter4.irregular_sea(ref, plant, mo, 2.4, 6.6, 90.0, duration_s=600.0,
                                 transient=300.0, kinematics="linear")
    assert out["sigma_ratio_rom_to_reference"] == pytest.approx(1.0, abs=0.01)
    assert out["comparison"]["r"] > 0.999 and out["comparison"]["r2"] > 0.998
    assert out["slack_fraction"] == 0.0


@needs_moordyn
def test_wires_of_several_segments_with_mass(plant):
    ref = build_reference(plant, wire_mass_t_per_m=0.05, segments=4)
    r = simulate.run(ref, still(0.02, 5.0))
    assert np.max(np.abs(r.pose[-1] - ref.pose)) < 1e-4     # holds its pose
    # padeye tensions within 0.1 % of the static solve, which lumps each wire's weight
    # half at either end (four segments spread it along the wire)
    assert np.all(np.abs(r.tension[-1] / ref.tension - 1) < 1e-3)
    with pytest.raises(Exception, match="mass per length"):
        build_reference(plant, segments=4)


@needs_moordyn
def test_tugger_line_setter_keeps_none_alive(plant):
    # MoorDyn 2.7's wrapper drops a reference to None per setter call; a long tugger
    # run (about 90 000 steps) then crashed the interpreter
    import sys

    from jls.verify.moordyn_model import Session
    from jls.verify.simulate import _setter
    ref = build_reference(plant, tugger=Tugger(name="low", c=300.0))
    with Session(ref) as s:
        import cmoordyn
        set_ea = _setter(cmoordyn.line_set_const_ea, s.tugger_lines[0], 500.0)
        before = sys.getrefcount(None)
        for _ in range(2000):
            set_ea(s.tugger_lines[0], 1e3)
        after = sys.getrefcount(None)
    assert abs(after - before) <= 2           # a leak would be 2000


@pytest.mark.parametrize("shortest_s, step", [(1.14, 0.1), (0.5, 0.05), (0.2, 0.02)])
def test_the_rk4_step_keeps_ten_steps_in_the_shortest_period_of_either_model(shortest_s, step):
    from types import SimpleNamespace

    from jls.verify.cell import STEPS_PER_PERIOD, rk4_step
    ref = SimpleNamespace(modes=SimpleNamespace(period=np.array([19.1, 15.7, 3.5, shortest_s, 1.8, 1.2])))
    rom = SimpleNamespace(modes=SimpleNamespace(period=np.array([15.7, 3.5, 1.22, 1.14])))
    assert STEPS_PER_PERIOD == 10
    assert rk4_step(0.1, ref, rom) == pytest.approx(step)
    assert rk4_step(0.01, ref, rom) == 0.01                 # a shorter step stays
