"""Frequency-domain response and short-term statistics."""

from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from jls.errors import InputError
from jls.plant.model import from_matrices
from jls.response.coverage import check_coverage
from jls.response.solver import frequency_grid, transfer_functions
from jls.response.statistics import energy_outside, unit_statistics
from jls.sea.spectra import jonswap, tp_from_tz

A1 = Path(__file__).resolve().parent / "data" / "appendix_a1_plant.yaml"


def sdof_plant(m=7719.0, period=15.7, zeta=0.0098):
    """Sway-only pendulum: the other DOFs stiff, uncoupled."""
    wn = 2 * np.pi / period
    M = np.diag([m, m, 4.55e6, 3.286e6])
    K = np.diag([m * wn**2, 2.3e5, 1.2e8, 1.0e7])
    C = np.diag([2 * zeta * m * wn, 1e3, 1e5, 1e4])
    return M, K, -K, C, wn


def test_sdof_relative_sway_matches_closed_form():
    M, K, Kb, C, wn = sdof_plant()
    omega = np.linspace(0.1, 1.5, 400)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0
    _, Hrel = transfer_functions(M, K, Kb, C, omega, qb)
    r = omega / wn
    # Eq. 3.10: the hinge drives through the stiffness (-Kb qb) and the damping acts on
    # the absolute motion, so (y - y_b) / y_b = (r^2 - 2 i zeta r) / (1 - r^2 + 2 i zeta r).
    expected = (r**2 - 2j * 0.0098 * r) / (1 - r**2 + 2j * 0.0098 * r)
    np.testing.assert_allclose(Hrel[0, 0, :, 0], expected, rtol=1e-9)


def test_appendix_a1_harmonic_hinge_sway_matches_time_integration():
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    w = 2 * np.pi / 12.0            # a harmonic test period of section 4.2
    qb_amp = np.array([0.5, 0, 0, 0], complex)
    Hq, _ = transfer_functions(p.M, p.K, p.Kb, p.C, np.array([w]), qb_amp[None, None, :])
    Minv = np.linalg.inv(p.M)

    def rhs(t, s):
        q, v = s[:4], s[4:]
        qb = np.real(qb_amp * np.exp(1j * w * t))
        return np.concatenate([v, Minv @ (-p.C @ v - p.K @ q - p.Kb @ qb)])

    # Start on the frequency-domain steady state: if it is the true periodic solution,
    # no transient appears (a wrong one would ring at the sway period, 0.98 % damped).
    h = Hq[0, 0, 0]
    s0 = np.concatenate([h.real, (1j * w * h).real])
    t_end = 200.0
    sol = solve_ivp(rhs, (0, t_end), s0, max_step=0.05, rtol=1e-10, atol=1e-12, dense_output=True)
    t = np.linspace(0.0, t_end, 4001)
    y = sol.sol(t)[0]
    steady = np.real(Hq[0, 0, 0, 0] * np.exp(1j * w * t))
    assert np.max(np.abs(y - steady)) < 1e-4 * np.abs(Hq[0, 0, 0, 0])


def test_tugger_adds_damping_at_resonance():
    M, K, Kb, C, wn = sdof_plant()
    omega = np.array([wn])
    qb = np.zeros((1, 1, 4), complex)
    qb[..., 0] = 1.0
    fair = np.ones((1, 1), complex)            # fairlead moving with the hinge
    _, Hrel = transfer_functions(M, K, Kb, C, omega, qb, fair, [0.0, 1000.0])
    zeta_t = 0.0098 + 1000.0 / (2 * 7719.0 * wn)
    # At resonance |y - y_b| / |y_b| = sqrt(1 + 4 zeta^2) / (2 (zeta + zeta_tugger)).
    amp = np.sqrt(1 + 4 * 0.0098**2)
    assert abs(Hrel[0, 0, 0, 0]) == pytest.approx(amp / (2 * 0.0098), rel=1e-9)
    assert abs(Hrel[1, 0, 0, 0]) == pytest.approx(amp / (2 * zeta_t), rel=1e-9)


def test_sigma_from_spectrum_equals_time_series_realisation():
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    wn = 2 * np.pi / p.modes.period[:2]
    omega = frequency_grid(0.05, 3.0, 0.002, wn, p.damping_ratio[:2])
    # A hinge that sways with a smooth roll-like RAO.
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 8.0 / (1 + ((omega - 0.45) / 0.15) ** 2) * np.exp(-0.5j * omega)
    _, Hrel = transfer_functions(p.M, p.K, p.Kb, p.C, omega, qb)
    H = Hrel[0, 0, :, 0]
    tz = 7.5
    stats = unit_statistics(omega, H, [tz], 3.3)
    # Realisation: random phases on a fine uniform grid, long record.
    rng = np.random.default_rng(3)
    dw = 0.0005
    wf = np.arange(0.05, 3.0, dw)
    Hf = np.interp(wf, omega, H.real) + 1j * np.interp(wf, omega, H.imag)
    S = jonswap(wf, 1.0, tp_from_tz(tz), 3.3)
    amp = np.sqrt(2 * S * dw)
    t = np.arange(0.0, 2 * np.pi / dw, 0.5)      # one full period of the synthetic record
    phase = rng.uniform(0, 2 * np.pi, wf.size)
    x = np.zeros_like(t)
    for chunk in np.array_split(np.arange(wf.size), 20):
        x += (np.abs(Hf[chunk]) * amp[chunk] * np.cos(
            np.outer(t, wf[chunk]) + phase[chunk] + np.angle(Hf[chunk]))).sum(axis=1)
    assert np.std(x) == pytest.approx(stats["sigma"][0], rel=0.05)


def test_mpm_peak_factor_and_cycles():
    omega = np.linspace(0.2, 8.0, 20000)
    H = np.ones_like(omega)
    fixed = unit_statistics(omega, H, [6.0], cycles=1000)
    assert fixed["mpm"][0] / fixed["sigma"][0] == pytest.approx(np.sqrt(2 * np.log(1000)))
    assert np.sqrt(2 * np.log(1000)) == pytest.approx(3.72, abs=0.005)     # study's 3.72 sigma
    resp = unit_statistics(omega, H, [6.0], exposure_s=10800)
    # |H| = 1: the response is the wave itself; its Tz is the sea state's (within the grid).
    assert resp["tz_response"][0] == pytest.approx(6.0, rel=0.02)
    assert resp["n_cycles"][0] == pytest.approx(10800 / resp["tz_response"][0])
    assert resp["sigma"][0] == pytest.approx(0.25, rel=0.01)        # Hs/4 at Hs = 1 m


def test_response_grid_resolves_resonance():
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    wn = 2 * np.pi / p.modes.period[:2]
    coarse = frequency_grid(0.1, 2.0, 0.01)
    fine = frequency_grid(0.1, 2.0, 0.01, wn, p.damping_ratio[:2])
    qb = np.zeros((1, 1, 4), complex)

    def sigma(omega):
        q = np.zeros((1, omega.size, 4), complex)
        q[..., 0] = 1.0
        _, H = transfer_functions(p.M, p.K, p.Kb, p.C, omega, q)
        return unit_statistics(omega, H[0, 0, :, 0], [10.0])["sigma"][0]

    reference = sigma(np.linspace(0.1, 2.0, 200_001))
    assert sigma(fine) == pytest.approx(reference, rel=2e-3)
    assert qb.shape == (1, 1, 4)
    assert len(fine) < len(coarse) + 1300


def test_energy_outside_range_is_an_error_unless_allowed():
    assert energy_outside(0.01, 50.0, [8.0])[0] < 1e-6
    short = energy_outside(0.2, 1.5, [3.0])[0]
    assert short > 0.05
    with pytest.raises(InputError, match=r"Tz = 3 s.*outside the RAO range"):
        check_coverage(0.2, 1.5, [3.0, 8.0], 3.3, "error")
    frac = check_coverage(0.2, 1.5, [3.0, 8.0], 3.3,
                          {"zero_above_rad_s": 1.5, "zero_below_rad_s": 0.2,
                           "reason": "no motion outside the computed range"})
    assert frac[0] == pytest.approx(short)


HEADINGS_OFF_THE_RADIAN_ROUND_TRIP = [15, 30, 60, 105, 120, 210, 240]


def test_headings_are_kept_as_given_through_motion_and_response():
    from jls.config.builders import rigging_from_config
    from jls.config.loader import load
    from jls.plant.candidates import plant_dataset
    from jls.stages.response import response_dataset
    from jls.stages.vessel_motion import vessel_motion
    root = Path(__file__).resolve().parents[1]
    cfg = load(root / "config" / "config.yaml")
    motion = vessel_motion(cfg["vessel"], HEADINGS_OFF_THE_RADIAN_ROUND_TRIP, base_dir=root)
    assert motion["heading"].values.tolist() == HEADINGS_OFF_THE_RADIAN_ROUND_TRIP
    plant, _ = plant_dataset(rigging_from_config(cfg), {"baseline": {}})
    ds = response_dataset(plant, motion, [6.5], HEADINGS_OFF_THE_RADIAN_ROUND_TRIP, {"none": 0.0},
                          gamma=3.3, omega_step=0.02,
                          outside_policy=cfg["vessel"]["outside_rao_range"])
    assert ds["heading"].values.tolist() == HEADINGS_OFF_THE_RADIAN_ROUND_TRIP
    # mirrored headings: a port/starboard-symmetric hull gives the same sway amplitude
    s = ds["sigma"].sel(response="relative_sway", candidate="baseline", tugger="none", tz=6.5)
    assert float(s.sel(heading=240)) == pytest.approx(float(s.sel(heading=120)), rel=1e-9)
    assert float(s.sel(heading=210)) > 0


def test_a_heading_the_rao_file_lacks_is_named():
    from jls.config.loader import load
    from jls.errors import InputError
    from jls.stages.vessel_motion import vessel_motion
    root = Path(__file__).resolve().parents[1]
    cfg = load(root / "config" / "config.yaml")
    with pytest.raises(InputError, match=r"heading 250"):
        vessel_motion(cfg["vessel"], [90, 250], base_dir=root)


def test_response_drives_the_plant_with_the_vessel_rao_interpolated_then_transferred():
    """One owner, one order: the response interpolates the vessel's six RAOs per DOF onto
    its grid and then carries them to the hinge and fairleads (jls.vessel.transfer.
    motion_on_grid); the stored hinge and fairlead of vessel_motion.nc (the same transfer
    on the RAO's own grid) do not drive it, the vessel RAO and the lever arm do."""
    from jls.config.builders import rigging_from_config
    from jls.config.loader import load
    from jls.plant.candidates import plant_dataset
    from jls.response.moments import excitation
    from jls.stages.vessel_motion import vessel_motion
    from jls.vessel.rao import interp_rao, make_rao_dataset
    from jls.vessel.transfer import fairlead_motion, hinge_excitation
    root = Path(__file__).resolve().parents[1]
    cfg = load(root / "config" / "config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0, 120.0], base_dir=root)
    plant, _ = plant_dataset(rigging_from_config(cfg), {"baseline": {}})
    exc = excitation(plant, motion, [90.0, 120.0], omega_step=0.01)
    # the stored hinge and fairlead motions are not what drives
    scaled = motion.copy()
    scaled["hinge"] = motion["hinge"] * 2.0
    scaled["fairlead"] = motion["fairlead"] * 3.0
    same = excitation(plant, scaled, [90.0, 120.0], omega_step=0.01)
    np.testing.assert_array_equal(same.qb, exc.qb)
    np.testing.assert_array_equal(same.fairlead_sway, exc.fairlead_sway)
    # the vessel RAO is (linear in it)
    scaled = motion.copy()
    scaled["rao"] = motion["rao"] * 2.0
    np.testing.assert_allclose(excitation(plant, scaled, [90.0, 120.0], omega_step=0.01).qb,
                               2.0 * exc.qb, rtol=1e-12)
    # and it is the per-DOF interpolation of the vessel RAO, then the rigid-body transfer
    rao = make_rao_dataset(motion["omega"].values, np.radians([90.0, 120.0]),
                           motion["rao"].transpose("omega", "heading", "vessel_dof").values,
                           reference_point_m=motion.attrs["reference_point_m"])
    on_grid = interp_rao(rao, exc.omega)
    lever = tuple(motion.attrs["hinge_lever_arm_m"])
    direct = hinge_excitation(on_grid, lever).transpose("wave_direction", "omega", ...).values
    np.testing.assert_allclose(exc.qb, direct, rtol=1e-12, atol=1e-15)
    fl = fairlead_motion(on_grid, lever, drop=cfg["vessel"]["fairlead_drop_m"],
                         half_span=cfg["vessel"]["fairlead_half_span_m"])
    np.testing.assert_allclose(exc.fairlead_sway,
                               fl.sel(axis="y").mean("side").transpose("wave_direction", "omega").values,
                               rtol=1e-12, atol=1e-15)
    # on the RAO's own frequencies the stored hinge motion is that same transfer
    at = np.isin(exc.omega, motion["omega"].values)
    stored = motion["hinge"].sel(omega=exc.omega[at]).transpose("heading", "omega", "dof").values
    np.testing.assert_allclose(exc.qb[:, at], stored, rtol=1e-12, atol=1e-15)
