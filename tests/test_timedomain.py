"""Nonlinear time-domain model: compiled plant, sea realisation, runs and the CLI."""

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jls.cli import main
from jls.config.builders import dataset_from_config, plant_from_config, settings_from_config
from jls.config.loader import load
from jls.stages.vessel_motion import vessel_motion
from jls.timedomain import dynamics as dyn
from jls.timedomain.run import Case, frequency_domain_sigma, parameters, run_cells
from jls.timedomain.sea import realise, synthesise, wave_elevation
from jls.tugger.setting import Tugger

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
REFERENCE = Tugger("reference", 1000.0)
DEFAULTS = load(CONFIG)
# The model checks compare with the frequency domain: deterministic amplitudes, so a
# record's variance is the discretised spectral sum whatever the seed (the scatter of
# random amplitudes is tested in test_timedomain_records.py).
SETTINGS = replace(settings_from_config(DEFAULTS), amplitudes="deterministic")
GAMMA = DEFAULTS["sea"]["gamma"]


@pytest.fixture(scope="module")
def plant(cfg):
    return plant_from_config(cfg)


@pytest.fixture(scope="module")
def motion(cfg):
    return vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)


def test_compiled_forces_linearise_to_K_and_Kb(plant):
    """At rest the exact nonlinear forces balance, and their Jacobians are -K and -Kb."""
    par = parameters(plant, None)
    f0, _ = dyn.generalised_force(par, np.zeros(4))
    assert np.all(np.abs(f0) < 1e-6 * plant.m_grav * plant.g)
    h = np.array([1e-4, 1e-4, 1e-6, 1e-6])
    K = np.empty((4, 4))
    Kb = np.empty((4, 4))
    for j in range(4):
        dq = np.zeros(4)
        dq[j] = h[j]
        e = np.zeros(dyn.N_CH)
        e[j] = h[j]
        K[:, j] = -(dyn.generalised_force(par, dq)[0] - dyn.generalised_force(par, -dq)[0]) / (2 * h[j])
        Kb[:, j] = -(dyn.generalised_force(par, np.zeros(4), e=e)[0]
                     - dyn.generalised_force(par, np.zeros(4), e=-e)[0]) / (2 * h[j])
    scale = np.abs(plant.K).max(axis=1, keepdims=True)
    assert np.all(np.abs(K - plant.K) < 1e-7 * scale)
    assert np.all(np.abs(Kb - plant.Kb) < 1e-7 * np.abs(plant.Kb).max(axis=1, keepdims=True))


def test_slack_wire_carries_no_tension(plant):
    """Lifting the jacket by more than the wire stretch (T/k, about 0.34 m) slackens every
    wire: tensions are zero, never negative, and only gravity acts."""
    par = parameters(plant, None)
    stretch = plant.tension / plant.wire_stiffness
    f, info = dyn.generalised_force(par, np.array([0.0, stretch.max() + 0.2, 0.0, 0.0]))
    np.testing.assert_array_equal(info[6:10], 0.0)
    np.testing.assert_allclose(f, [0.0, -plant.m_grav * plant.g, 0.0, 0.0], atol=1e-9)
    # Half the stretch: still taut, tensions reduced by k dz along the near-vertical wires.
    f, info = dyn.generalised_force(par, np.array([0.0, 0.1, 0.0, 0.0]))
    assert np.all(info[6:10] > 0) and np.all(info[6:10] < plant.tension)


def test_sea_realisation_has_the_spectrum_variance_and_is_seeded():
    a = realise(2.0, 6.6, 3.3, (0.1, 3.0), 0.025, 3600.0, 500.0, seed=4)
    b = realise(2.0, 6.6, 3.3, (0.1, 3.0), 0.025, 3600.0, 500.0, seed=4)
    c = realise(2.0, 6.6, 3.3, (0.1, 3.0), 0.025, 3600.0, 500.0, seed=5)
    np.testing.assert_array_equal(a.phase, b.phase)
    assert not np.allclose(a.phase, c.phase)
    # Hs = 4 sqrt(m0) (the spectrum's own range holds all but a trace of the energy)
    assert abs(4 * np.sqrt(np.sum(a.amplitude**2) / 2) - 2.0) < 0.01
    assert a.repeat_period >= 3600.0
    never = realise(2.0, 6.6, 3.3, (0.1, 3.0), 0.025, 3600.0, 500.0, seed=4, repeat="never")
    assert never.repeat_period >= 4100.0 and never.d_omega < a.d_omega
    fixed = realise(2.0, 6.6, 3.3, (0.1, 3.0), 0.025, 3600.0, 500.0, seed=4, n_components=200)
    assert abs(fixed.omega.size - 200) <= 1
    # FFT synthesis equals the direct sum, and the record does not repeat within it.
    eta = synthesise(a, np.ones((dyn.N_CH, a.omega.size)), -500.0, 0.025, 4001)[:, 0]
    t = -500.0 + 0.025 * np.arange(4001)
    np.testing.assert_allclose(eta, wave_elevation(a, t), atol=1e-9)


@pytest.mark.parametrize("kw", [{}, {"repeat": "never"}, {"n_components": 37}], ids=["record", "never", "n37"])
def test_synthesis_on_coarse_grids_equals_one_inverse_fft_and_the_direct_sum(kw):
    """The record is synthesised on D interleaved coarse grids; every channel and every row,
    those past the repeat period (wrapped) included, equals the single full-length inverse
    FFT over the period to round-off, and sampled rows equal the direct sum."""
    from jls.timedomain.sea import _decimation
    h, t0 = 0.025, -500.0
    real = realise(2.0, 6.6, 3.3, (0.1, 3.0), h, 3600.0, 500.0, seed=4, amplitudes="rayleigh", **kw)
    n_fft = int(round(real.repeat_period / h))
    assert _decimation(n_fft, int(real.harmonic.max())) > 1
    rng = np.random.default_rng(2)
    transfer = rng.normal(size=(dyn.N_CH, real.omega.size)) + 1j * rng.normal(size=(dyn.N_CH, real.omega.size))
    n = 2 * n_fft + 123
    exc = synthesise(real, transfer, t0, h, n)
    assert exc.shape == (n, dyn.N_CH) and exc.flags.c_contiguous
    coef = np.zeros((dyn.N_CH, n_fft // 2 + 1), complex)
    coef[:, real.harmonic] = transfer * real.amplitude * np.exp(1j * (real.phase + real.omega * t0))
    ref = (np.fft.irfft(coef, n=n_fft, axis=-1) * (n_fft / 2.0)).T[np.arange(n) % n_fft]
    scale = np.abs(ref).max(axis=0)
    assert np.max(np.abs(exc - ref) / scale) < 1e-13
    j = rng.integers(0, n, 50)
    t = t0 + h * j
    direct = (transfer[0] * real.amplitude * np.exp(1j * (real.omega * t[:, None] + real.phase))).real.sum(axis=1)
    np.testing.assert_allclose(exc[j, 0], direct, rtol=0, atol=1e-9 * scale[0])


def test_rk4_converges_at_fourth_order(plant, motion):
    """Halving the step cuts the error by about 16 on a smooth (unsaturated) run."""
    ends = {}
    for dt in (0.2, 0.1, 0.05, 0.025):
        case = Case(plant, motion, 1.0, 7.5, 90.0, gamma=GAMMA, duration_s=300.0,
                    settings=replace(SETTINGS, dt=dt, transient_s=0.0, repeat="never"))
        r = case.run(REFERENCE, keep_record=True)
        ends[dt] = r["relative_sway"][:: int(round(0.2 / dt))]
    e1 = np.max(np.abs(ends[0.2] - ends[0.025]))
    e2 = np.max(np.abs(ends[0.1] - ends[0.025]))
    assert e1 / e2 > 10
    assert e2 < 1e-4 * np.std(ends[0.025])


@pytest.mark.parametrize("tugger", [None, REFERENCE], ids=["none", "reference"])
def test_small_motion_matches_frequency_domain(plant, motion, tugger):
    """No limit reached, small motion: time-domain sigma equals frequency-domain sigma."""
    case = Case(plant, motion, 1.0, 6.6, 90.0, gamma=GAMMA, duration_s=3600.0, settings=SETTINGS)
    r = case.run(tugger)
    t = tugger or Tugger("none", 0.0)
    fd = frequency_domain_sigma(plant, motion, [t], 1.0, 6.6, 90.0)[0]
    assert r["limit_fraction"] == 0.0 and r["slack_events"] == 0
    assert abs(r["sigma"] / fd - 1) < 0.05
    # MPM from sigma and from the counted up-crossings agree, and exceed sigma.
    assert 2.5 * r["sigma"] < r["mpm_upcrossing"] < 5 * r["sigma"]
    assert abs(r["mpm_sigma"] / r["mpm_upcrossing"] - 1) < 0.05


def test_winch_power_matches_frequency_domain(plant, motion):
    from jls.response.solver import transfer_functions
    from jls.vessel.transfer import channel_transfer
    case = Case(plant, motion, 1.0, 6.6, 90.0, gamma=GAMMA, duration_s=3600.0, settings=SETTINGS)
    r = case.run(REFERENCE)
    om = case.realisation.omega
    tr = channel_transfer(motion, 90.0, om)
    fl = 0.5 * (tr[5] + tr[8])
    Hq, _ = transfer_functions(plant.M, plant.K, plant.Kb, plant.C, om, tr[None, :4].transpose(0, 2, 1),
                               fl[None], [1000.0])
    u = 1j * om * (Hq[0, 0, :, 0] - fl)
    # discrete spectrum: mean power c sum |u_k a_k|^2 / 2
    p_fd = 1000.0 * np.sum(np.abs(u * case.realisation.amplitude) ** 2) / 2
    assert abs(r["power_mean"] / p_fd - 1) < 0.05
    assert r["power_peak"] > r["power_mean"] > 0


def test_limit_occupancy_zero_when_capacity_is_huge(plant, motion):
    case = Case(plant, motion, 2.4, 8.5, 90.0, gamma=GAMMA, duration_s=3600.0, settings=SETTINGS)
    big = case.run(Tugger("big", 1000.0, max_force=1e5))
    real = case.run(REFERENCE)
    assert big["limit_fraction"] == 0.0
    assert real["limit_fraction"] > 0.0
    assert real["line_tension_max"] <= REFERENCE.max_force + 1e-9
    assert real["line_tension_min"] >= REFERENCE.min_force - 1e-9
    # saturation costs damping: the capped winch leaves more motion
    assert real["sigma"] > big["sigma"]


def test_seed_reproduces_the_run(plant, motion):
    def run(seed):
        return Case(plant, motion, 2.0, 7.0, 90.0, gamma=GAMMA, duration_s=900.0, seed=seed,
                    settings=SETTINGS).run(REFERENCE, keep_record=True)

    a, b, c = run(7), run(7), run(8)
    np.testing.assert_array_equal(a["relative_sway"], b["relative_sway"])
    assert not np.allclose(a["relative_sway"], c["relative_sway"])


def test_wires_go_slack_in_an_extreme_sea_without_negative_tension(plant, motion):
    """Swings of well over 10 m unload a wire of each crossed pair: it goes slack and
    carries zero tension, never a push."""
    r = Case(plant, motion, 3.6, 8.5, 90.0, gamma=GAMMA, duration_s=3600.0, settings=SETTINGS).run(None)
    assert r["wire_tension_min"] == 0.0 and r["slack_events"] > 0 and r["slack_fraction"] > 0


def test_cells_dataset(plant, motion, tmp_path):
    tugs = [Tugger("none", 0.0), REFERENCE]
    ds = run_cells(plant, motion, tugs, [1.0, 1.5], [6.6, 7.0], 90.0, gamma=GAMMA, duration_s=600.0,
                   settings=replace(SETTINGS, transient_s=200.0), workers=2)
    assert ds["sigma"].dims == ("cell", "tugger") and ds.sizes == {"cell": 2, "tugger": 2}
    for v in ds.data_vars:
        assert ds[v].attrs["units"] and ds[v].attrs["long_name"]
    assert ds.attrs["transient_s"] == 200.0 and ds.attrs["seed"] == 1
    assert (ds["sigma"].sel(tugger="reference") < ds["sigma"].sel(tugger="none")).all()
    # the same record for every setting of a cell, and a pipeline can write it as it is
    from jls.io.netcdf import read, write
    back = read(write(ds, tmp_path / "td.nc", config_sha256="0" * 64, created_by="test"))
    np.testing.assert_allclose(back["sigma"].values, ds["sigma"].values)


def test_dataset_from_config(cfg, motion):
    c = dict(cfg, assessment=dict(cfg["assessment"], exposure_h=0.2),
             timedomain=dict(cfg["timedomain"], transient_s=100.0, seed=3))
    ds = dataset_from_config(c, motion, [1.0], [6.6], 90.0, tuggers=["none", "high"])
    assert list(ds["tugger"].values) == ["none", "high"] and ds.attrs["seed"] == 3
    assert ds.attrs["duration_s"] == pytest.approx(720.0)
    from jls.errors import InputError
    with pytest.raises(InputError, match="nope"):
        dataset_from_config(c, motion, [1.0], [6.6], 90.0, tuggers=["nope"])


def test_matrices_plant_is_refused():
    from jls.errors import InputError
    from jls.plant.model import from_matrices
    p = from_matrices(ROOT / "tests" / "data" / "appendix_a1_plant.yaml", g=9.81, zeta=0.0098)
    with pytest.raises(InputError, match="wire geometry"):
        parameters(p, None)


def test_cli_simulate_json_contract(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    assert main(["simulate", "--hs", "1.0", "--tz", "6.6", "--heading", "90", "--tugger", "reference",
                 "--duration-h", "0.5", "--seed", "3", "--amplitudes", "deterministic", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    for key in ("sigma_relative_sway_m", "sigma_relative_sway_fd_m", "mpm_relative_sway_m",
                "tugger_limit_fraction", "wire_tension_min_kN", "wire_tension_max_kN", "wall_time_s",
                "components_per_bandwidth", "line_length_min_m", "line_contact_fraction"):
        assert isinstance(out[key], float), key
    assert out["amplitudes"] == "deterministic" and out["components_per_bandwidth"] >= 2
    assert out["line_contact_fraction"] == 0.0 and out["line_length_min_m"] > 10
    assert abs(out["sigma_relative_sway_m"] / out["sigma_relative_sway_fd_m"] - 1) < 0.05
    assert 0 < out["wire_tension_min_kN"] < out["wire_tension_max_kN"]
    assert out["tugger_limit_fraction"] == 0.0


@pytest.mark.parametrize("argv, text", [
    (["--hs", "-1", "--tz", "6.6"], "--hs"),
    (["--hs", "abc", "--tz", "6.6"], "--hs"),
    (["--hs", "1", "--tz", "6.6", "--tugger", "nope"], "nope"),
    (["--hs", "1", "--tz", "6.6", "--heading", "33"], "heading"),
    (["--tz", "6.6"], "--hs"),
    (["--hs", "1", "--tz", "6.6", "--duration-h", "0.2"], "--duration-h"),
])
def test_cli_simulate_bad_input_is_one_line_and_exit_2(capsys, monkeypatch, argv, text):
    monkeypatch.chdir(ROOT)
    with pytest.raises(SystemExit) as exc:
        rc = main(["simulate", *argv])
        raise SystemExit(rc)
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("jls: error:") and text in err[0]
