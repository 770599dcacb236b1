"""Wave records of the time domain: the record length against the sway resonance, random
(Rayleigh) amplitudes and their scatter over seeds, several seeds per pipeline cell, and
tugger-line contact with the fairlead."""

import copy
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from scipy import stats

from jls.config.builders import plant_from_config, settings_from_config
from jls.config.loader import load, load_yaml, validate
from jls.errors import InputError
from jls.io import registry
from jls.stages.timedomain_cell import cell_dataset
from jls.stages.vessel_motion import vessel_motion
from jls.timedomain import dynamics as dyn
from jls.timedomain import resolution as res
from jls.timedomain.run import Case, initial_state, integrate_run, parameters, record_spacing
from jls.timedomain.sea import independent_components, realise
from jls.tugger.setting import Tugger

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
CFG = load(CONFIG)
SETTINGS, GAMMA = settings_from_config(CFG), CFG["sea"]["gamma"]
REFERENCE = Tugger("reference", 1000.0)


@pytest.fixture(scope="module")
def plant():
    return plant_from_config(CFG)


@pytest.fixture(scope="module")
def motion():
    return vessel_motion(CFG["vessel"], [90.0], base_dir=ROOT)


# -- record length ------------------------------------------------------------------------

def test_resolution_bounds_and_the_shipped_plant(plant):
    """2 zeta w_n of the shipped plant, the record that gives 2 components per bandwidth
    (0.45 h, below the schema's 0.5 h floor) and the Lorentzian's bounds."""
    i = int(plant.modes.mode_of("sway"))
    B = res.half_power_bandwidth(plant)
    assert B == pytest.approx(2 * plant.damping_ratio[i] * plant.modes.omega[i])
    assert res.shortest_record_s(plant) / 3600 == pytest.approx(0.445, abs=0.002)
    lo, hi = res.resonant_bias_bounds(2.0)
    assert -0.004 < lo < 0 < hi < 0.004
    lo, hi = res.resonant_bias_bounds(0.23)                 # 0.05 h, the former schema floor
    assert lo < -0.6 and hi > 1.5


def test_grid_bias_falls_within_the_lorentzian_bounds(plant, motion):
    """The linear model on a record's own grid against the converged sigma (Tz 8.5 s, no
    tugger, where the resonance carries most of the variance): off by about -19 % at the
    former schema floor of 0.05 h, under 0.2 % from 2 components per bandwidth on."""
    from jls.timedomain.run import frequency_domain_sigma
    tug = [Tugger("none", 0.0)]
    fd = frequency_domain_sigma(plant, motion, tug, 1.0, 8.5, 90.0, GAMMA)[0]
    om = motion["omega"].values
    for hours, lo, hi in ((0.05, -0.25, -0.12), (0.5, -0.002, 0.002), (3.0, -0.001, 0.001)):
        r = realise(1.0, 8.5, GAMMA, (om.min(), om.max()), 0.025, hours * 3600, 0.0, 1)
        g = res.linear_grid(plant, motion, tug, r.omega, r.d_omega, 1.0, 8.5, 90.0, GAMMA)
        assert lo < g["sigma"][0] / fd - 1 < hi, hours


def test_a_record_too_short_for_the_resonance_is_refused(motion):
    """The cell's job names the key and the value; the schema's floor is 0.5 h."""
    cfg = copy.deepcopy(CFG)
    cfg["timedomain"].update(duration_h=0.25)
    cell = {"candidate": "baseline", "heading": 90.0, "hs": 1.0, "tz": 6.6}
    with pytest.raises(InputError, match=r"timedomain\.duration_h.*0\.25|0\.25.*timedomain\.duration_h") as e:
        cell_dataset(cfg, motion, cell)
    assert "components per half-power bandwidth" in str(e.value) and "0.45 h" in str(e.value)
    # without duration_h the exposure sets the record
    cfg["timedomain"].pop("duration_h")
    cfg["assessment"]["exposure_h"] = 0.3
    with pytest.raises(InputError, match=r"assessment\.exposure_h"):
        cell_dataset(cfg, motion, cell)
    for key in (("timedomain", "duration_h"), ("timedomain", "slope_sweep", "duration_h")):
        raw = copy.deepcopy(load_yaml(CONFIG))
        node = raw
        for k in key[:-1]:
            node = node.setdefault(k, {})
        node[key[-1]] = 0.3
        with pytest.raises(InputError, match=key[-1]):
            validate(raw, source="my.yaml")


def test_record_spacing_is_the_realised_one(plant, motion):
    om = motion["omega"].values
    for s in (SETTINGS, replace(SETTINGS, repeat="never"), replace(SETTINGS, n_components=300)):
        case = Case(plant, motion, 1.0, 6.6, 90.0, gamma=GAMMA, duration_s=1800.0, settings=s)
        assert record_spacing(plant, s, 1800.0, (om.min(), om.max())) == pytest.approx(
            case.realisation.d_omega, rel=1e-12)


# -- random amplitudes --------------------------------------------------------------------

def test_rayleigh_amplitudes_keep_the_phases_and_the_expected_variance():
    kw = dict(hs=2.0, tz=6.6, gamma=3.3, omega_range=(0.1, 3.0), half_step=0.025, duration=3600.0,
              transient=0.0, seed=4)
    det, ray = realise(**kw), realise(**kw, amplitudes="rayleigh")
    np.testing.assert_array_equal(det.phase, ray.phase)
    live = det.amplitude > 0
    e = (ray.amplitude[live] / det.amplitude[live]) ** 2     # standard exponential draws
    assert abs(e.mean() - 1) < 4 / np.sqrt(e.size) and abs(e.var() - 1) < 0.2
    assert stats.kstest(e, "expon").pvalue > 0.001
    with pytest.raises(InputError, match="timedomain.amplitudes"):
        realise(**kw, amplitudes="gaussian")
    assert independent_components(np.ones(50)) == pytest.approx(50.0)


N_SEEDS = 40


@pytest.fixture(scope="module")
def seeded(plant, motion):
    """sigma^2 of 40 records of 0.5 h (Hs 0.5 m, Tz 8.5 s: linear, resonance-dominated),
    random and deterministic amplitudes, without tugger and with the reference setting,
    and the linear model on the records' grid."""
    tuggers = [Tugger("none", 0.0), REFERENCE]
    out = {}
    for amp in ("rayleigh", "deterministic"):
        s = replace(SETTINGS, amplitudes=amp)
        runs = []
        for seed in range(N_SEEDS):
            case = Case(plant, motion, 0.5, 8.5, 90.0, gamma=GAMMA, duration_s=1800.0, settings=s,
                        seed=(11, seed))
            runs.append([case.run(t)["sigma"] ** 2 for t in tuggers])
        out[amp] = np.array(runs).T                           # (tugger, seed)
    r = case.realisation
    out["linear"] = res.linear_grid(plant, motion, tuggers, r.omega, r.d_omega, 0.5, 8.5, 90.0, GAMMA)
    return out


def test_seeds_with_rayleigh_amplitudes_scatter_as_chi_square(seeded):
    """sigma^2 of a record is sum_k v_k E_k (E_k standard exponential): mean sum v_k,
    variance sum v_k^2 = (sum v)^2 / N_eff, close to chi-square with 2 N_eff degrees of
    freedom over 2 N_eff. Over 40 fixed seeds: the mean within 3.5 standard errors, the
    sample variance inside its 99.9 % interval (chi-square with the degrees of freedom of a
    sample variance of that kurtosis), and the probability-integral transform through
    chi-square(2 N_eff) uniform (Kolmogorov-Smirnov p > 0.001)."""
    lin = seeded["linear"]
    for i in range(2):
        n_eff = lin["n_eff"][i]
        x = seeded["rayleigh"][i] / lin["sigma"][i] ** 2      # mean 1, variance 1 / N_eff
        assert abs(x.mean() - 1) < 3.5 / np.sqrt(n_eff * N_SEEDS), i
        excess = 6.0 / n_eff                                   # chi-square(2 N_eff) / (2 N_eff)
        dof = 2.0 / (2.0 / (N_SEEDS - 1) + excess / N_SEEDS)
        ratio = x.var(ddof=1) * n_eff
        assert stats.chi2.ppf(0.0005, dof) / dof < ratio < stats.chi2.ppf(0.9995, dof) / dof, (i, ratio)
        u = stats.chi2.cdf(2 * n_eff * x, 2 * n_eff)
        assert stats.kstest(u, "uniform").pvalue > 0.001, i
    # a wider band (the tugger) holds more independent components and scatters less
    assert lin["n_eff"][1] > 2 * lin["n_eff"][0]
    assert seeded["rayleigh"][1].std() / seeded["rayleigh"][1].mean() \
        < seeded["rayleigh"][0].std() / seeded["rayleigh"][0].mean()


def test_deterministic_amplitudes_do_not_sample_the_scatter(seeded):
    """With deterministic amplitudes every seed's variance is the discretised sum: seeds
    differ by the nonlinearity only (under 1 % here: 0.7 % without tugger), less than a
    tenth of the about 1 / sqrt(N_eff) of random ones."""
    det, lin = seeded["deterministic"], seeded["linear"]
    rel = det.std(axis=1) / det.mean(axis=1)
    assert np.all(rel < 0.01) and np.all(rel < 0.1 / np.sqrt(lin["n_eff"]))
    # the nonlinear wire geometry: the variance 2.2 % above the linear model's without
    # tugger, 0.2 % with it
    np.testing.assert_allclose(det.mean(axis=1), lin["sigma"] ** 2, rtol=0.03)


def test_cell_runs_several_seeds_and_reports_their_spread(motion):
    cfg = copy.deepcopy(CFG)
    cfg["timedomain"].update(duration_h=0.5, trace_s=60, seeds_per_cell=3)
    cfg["tuggers"] = [t for t in cfg["tuggers"] if t["name"] in ("none", "reference")]
    cell = {"candidate": "baseline", "heading": 90.0, "hs": 2.4, "tz": 8.0}
    ds = cell_dataset(cfg, motion, cell)
    registry.check(ds, "timedomain_cell")
    assert ds["sigma_seed"].dims == ("tugger", "seed") and ds.sizes["seed"] == 3
    assert ds.attrs["amplitudes"] == "rayleigh" and ds.attrs["seeds_per_cell"] == 3
    assert ds.attrs["components_per_bandwidth"] >= 2 and ds.attrs["record_warning"] == ""
    # the pooled sigma is the root-mean-square of the records', MPMs from it
    np.testing.assert_allclose(ds["sigma"], np.sqrt((ds["sigma_seed"] ** 2).mean("seed")))
    np.testing.assert_allclose(ds["sigma_seed_mean"], ds["sigma_seed"].mean("seed"))
    np.testing.assert_allclose(ds["sigma_seed_std"], ds["sigma_seed"].std("seed", ddof=1))
    np.testing.assert_allclose(ds["mpm_seed_std"], ds["mpm_seed"].std("seed", ddof=1))
    assert (ds["sigma_seed_std"] > 0).all() and (ds["mpm_sigma"] > 3 * ds["sigma"]).all()
    # the spread random amplitudes give, from the independent components
    linear = ds["sigma_fd"] * (1 + ds["sigma_grid_bias"])
    np.testing.assert_allclose(ds["sigma_seed_std_expected"],
                               linear / (2 * np.sqrt(ds["n_independent_components"])), rtol=1e-12)
    assert (np.abs(ds["sigma_grid_bias"]) < 0.005).all()
    # one seed is the first record of three: the trace and its statistics match
    one = cell_dataset({**cfg, "timedomain": {**cfg["timedomain"], "seeds_per_cell": 1}}, motion, cell)
    np.testing.assert_array_equal(one["trace_relative_sway"], ds["trace_relative_sway"])
    np.testing.assert_allclose(one["sigma"], ds["sigma_seed"].isel(seed=0))
    assert np.isnan(one["sigma_seed_std"]).all()


# -- line contact -------------------------------------------------------------------------

def test_line_contact_is_counted_on_a_constructed_case(plant):
    """The jacket at rest; the port fairlead moves towards it, y_f(t) = 37.5 - 15 + 5
    cos(w t), so the port line is 5 cos(w t) long and passes the jacket end for half of
    the time. With a 2 m minimum, contact is every step with 5 cos(w t) < 2 (the passes
    included), 1 - arccos(0.4) / pi = 63.1 % of the time; the starboard line stays 15 m.
    A winch of 0.02 kN leaves the jacket where it is."""
    weak = Tugger("weak", 1.0, max_force=0.02, min_force=0.0)
    off = (0.0, 37.5, -plant.layout.cog_depth)
    dt, periods, T = 0.05, 10, 20.0
    n = int(round(periods * T / dt))
    t = np.arange(2 * n + 1) * dt / 2
    w = 2 * np.pi / T
    exc = np.zeros((t.size, dyn.N_CH))
    exc[:, 5] = -15.0 + 5.0 * np.cos(w * t)                  # port fairlead, y
    exc[:, 11] = -5.0 * w * np.sin(w * t)                    # and its velocity
    length = 5.0 * np.cos(w * t[0:-1:2])                     # at the step starts
    for lmin, expected in ((2.0, np.mean(length < 2.0)), (0.0, np.mean(length <= 0.0))):
        par = parameters(plant, weak, off, min_line_length=lmin)
        _, raw, _ = integrate_run(par, initial_state(plant, weak), exc, dt, n, 0)
        s = dict(zip(dyn.STATS, raw))
        # within a step of each crossing (the jacket moves by microns)
        assert s["n_line_contact"] / n == pytest.approx(expected, abs=2 * periods / n), lmin
        assert s["line_length_min"] == 0.0
    assert expected == pytest.approx(0.5, abs=0.01)
    assert np.mean(length < 2.0) == pytest.approx(1 - np.arccos(0.4) / np.pi, abs=0.01)
    # the same fairlead at rest: no contact, the shortest line the rest length
    par = parameters(plant, weak, off, min_line_length=2.0)
    _, raw, _ = integrate_run(par, initial_state(plant, weak), np.zeros_like(exc), dt, n, 0)
    s = dict(zip(dyn.STATS, raw))
    assert s["n_line_contact"] == 0 and s["line_length_min"] == pytest.approx(15.0, abs=0.01)


def test_line_contact_in_a_severe_sea(plant, motion):
    """Hs 6 m, Tz 8.5 s, one hour: the low setting's jacket end passes its fairlead (6 414
    of 72 000 steps on the deterministic record of seed 1); the high setting's stiffer damper
    touches a third as often (2 161 steps)."""
    s = replace(SETTINGS, amplitudes="deterministic")
    case = Case(plant, motion, 6.0, 8.5, 90.0, gamma=GAMMA, duration_s=3600.0, settings=s)
    low = case.run(Tugger("low", 300.0, 1000.0))
    high = case.run(Tugger("high", 2000.0, 2000.0))
    steps = case.n_steps - case.n_skip
    assert 4000 < low["line_contact_fraction"] * steps < 9000 and low["line_length_min"] == 0.0
    assert 0.0 < high["line_contact_fraction"] < 0.5 * low["line_contact_fraction"]
    bare = case.run(None)
    assert bare["line_contact_fraction"] == 0.0 and np.isnan(bare["line_length_min"])
