"""The reference started in the ROM's state (verification.reference_start_time_constants):
the body's velocity set through MoorDyn's serialised state, and the start itself.

* A run continued from one of its own states (pose and velocity at a sample) follows
  the run it came from: the velocity is set, not lost (a body at rest there would
  start a new free oscillation of the sway's amplitude).
* On a small sea state (the reference linear) the reference started in the ROM's state
  at the first sample of the statistics follows the ROM from that sample on, where a
  start from rest at that instant leaves the whole start-up to settle.
* On the study's stress case S1 (the reference nonlinear) one ROM sway time constant of
  settling gives the sigma ratio of the full start from rest within 0.5 %, and no
  settling at all visibly does not (the check can fail)."""

import numpy as np
import pytest

from jls.verify import chapter4, reference_available, simulate, statics
from jls.verify import excitation as exc_mod

OK, WHY = reference_available()
needs_moordyn = pytest.mark.skipif(not OK, reason=f"{WHY}; nothing is verified")
HEADING, DT = 90.0, 0.1


@pytest.fixture(scope="module")
def setup(baseline_reference):
    return baseline_reference


@needs_moordyn
def test_a_run_continued_from_its_own_state_follows_it(setup):
    _, ref, _ = setup
    pose0 = statics.solve_pose(ref, ref.pose, fixed={1: ref.pose[1] + 0.5})
    whole = simulate.run(ref, exc_mod.still(DT, 60.0), pose=pose0)
    k = 45                                   # mid-swing: the sway velocity is near its largest
    assert abs(whole.velocity[k, 1]) > 0.1
    cont = simulate.run(ref, exc_mod.still(DT, 60.0 - k * DT), pose=whole.pose[k], velocity=whole.velocity[k])
    rest = simulate.run(ref, exc_mod.still(DT, 60.0 - k * DT), pose=whole.pose[k])
    amp = np.abs(whole.pose[k:, 1] - ref.pose[1]).max()
    assert np.abs(cont.pose[:, 1] - whole.pose[k:, 1]).max() < 1e-4 * amp
    for dof in (2, 3, 5):                    # heave, roll, yaw follow too
        scale = np.abs(whole.pose[k:, dof] - ref.pose[dof]).max()
        assert np.abs(cont.pose[:, dof] - whole.pose[k:, dof]).max() < 1e-3 * scale + 1e-9
    assert np.abs(rest.pose[:, 1] - whole.pose[k:, 1]).max() > 0.1 * amp
    assert np.allclose(cont.velocity[0], whole.velocity[k])


@needs_moordyn
def test_the_reference_started_in_the_roms_state_has_no_start_up_left(setup):
    plant, ref, motion = setup
    kw = dict(duration_s=300.0, transient=chapter4.transient_s(plant), dt=DT, seed=3,
              kinematics="rigid", frequency_domain=False, keep_records=True)
    linear = chapter4.irregular_sea(ref, plant, motion, 0.5, 9.0, HEADING, settle=0.0, **kw)
    rec = linear["records"]
    head = rec["time"] < 60.0                # the first minute after the start
    y_rom, y_ref = rec["relative_rom"][head, 0], rec["relative_reference"][head, 0]
    err = np.sqrt(np.mean((y_ref - y_rom) ** 2)) / y_rom.std()
    assert err < 0.02
    # from rest at the same instant: the jacket still at its static pose while the ROM swings
    cold = chapter4.irregular_sea(ref, plant, motion, 0.5, 9.0, HEADING, **{**kw, "transient": 0.0})
    c = cold["records"]
    first = c["time"] < 60.0
    rom_there = np.interp(c["time"][first], rec["time"], rec["relative_rom"][:, 0])
    err_cold = np.sqrt(np.mean((c["relative_reference"][first, 0] - rom_there) ** 2)) / y_rom.std()
    assert err_cold > 10 * err
    # the ROM's record is the same either way: only the reference starts later
    whole = chapter4.irregular_sea(ref, plant, motion, 0.5, 9.0, HEADING, **kw)
    assert np.array_equal(whole["records"]["relative_rom"], rec["relative_rom"])
    assert linear["rom"]["sigma"] == whole["rom"]["sigma"]


@needs_moordyn
@pytest.mark.slow
def test_one_time_constant_of_settling_gives_the_ratio_of_the_start_from_rest(setup):
    plant, ref, motion = setup
    tau = chapter4.transient_s(plant, 1.0)
    kw = dict(duration_s=1200.0, transient=5 * tau, dt=DT, seed=1, kinematics="rigid", frequency_domain=False)
    full = chapter4.irregular_sea(ref, plant, motion, 2.7, 9.0, HEADING, **kw)["sigma_ratio_rom_to_reference"]
    one = chapter4.irregular_sea(ref, plant, motion, 2.7, 9.0, HEADING, settle=tau, **kw)["sigma_ratio_rom_to_reference"]
    none = chapter4.irregular_sea(ref, plant, motion, 2.7, 9.0, HEADING, settle=0.0, **kw)["sigma_ratio_rom_to_reference"]
    assert full > 1.1                        # S1: the geometric nonlinearity shows
    assert abs(one / full - 1) < 0.005
    assert abs(none / full - 1) > 0.005      # without settling the nonlinear difference shows
