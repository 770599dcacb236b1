"""The frequency-domain solver: exact against a direct solve, analytic limits, the
resonance integral, linear work in candidates, chunking and the sea-state cache."""

from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import rigging_from_config
from jls.plant.candidates import plant_dataset
from jls.plant.model import from_matrices
from jls.response.moments import BLOCK, excitation, unit_moments
from jls.response.solver import (
    SCALE,
    frequency_grid,
    moment_weights,
    relative_power,
    spectral_moments,
    transfer_functions,
)
from jls.response.statistics import unit_spectra, unit_statistics
from jls.stages.response import response_dataset
from jls.stages.vessel_motion import vessel_motion

ROOT = Path(__file__).resolve().parents[1]
A1 = ROOT / "tests" / "data" / "appendix_a1_plant.yaml"
TUGGERS = {"none": 0.0, "reference": 1000.0, "high": 2000.0}


def plants(cfg, values):
    ds, _ = plant_dataset(rigging_from_config(cfg), values)
    return ds


@pytest.fixture(scope="module")
def grid_plants(cfg):
    """70 candidates over the design space (more than one solver block)."""
    rng = np.random.default_rng(7)
    values = {"baseline": {}, "detuned": {"top_spread_y": 37.845, "drop_height": 66.46}}
    for i in range(68):
        values[f"c{i}"] = {"top_spread_y": rng.uniform(38, 55), "drop_height": rng.uniform(55, 66)}
    return plants(cfg, values)


@pytest.fixture(scope="module")
def motion(cfg):
    return vessel_motion(cfg["vessel"], [60.0, 90.0], base_dir=ROOT)


def direct_solve(M, K, Kb, C, omega, qb, yf, c_t):
    """The reference: numpy's batched LAPACK solve of every system, (c, t, h, w, 4)."""
    w = omega[None, None, :, None, None]
    A = K[:, None, None] - w**2 * M[:, None, None] + 1j * w * C[:, None, None]
    A = np.broadcast_to(A, (M.shape[0], len(c_t), omega.size, 4, 4)).copy()
    A[..., 0, 0] += 1j * np.asarray(c_t)[None, :, None] * omega
    load = -np.einsum("cij,hwj->chwi", Kb, qb)
    b = np.broadcast_to(load[:, None], (M.shape[0], len(c_t)) + load.shape[1:]).copy()
    b[..., 0] += 1j * np.asarray(c_t)[None, :, None, None] * omega * yf
    return np.linalg.solve(A[:, :, None], b[..., None])[..., 0]


def test_solver_matches_direct_solve_with_tuggers(grid_plants):
    """Candidates whose coupling makes the LU pivot, random hinge and fairlead motion."""
    M, K, Kb, C = (grid_plants[k].values[:12] for k in ("M", "K", "Kb", "C"))
    rng = np.random.default_rng(1)
    omega = np.linspace(0.1, 3.0, 301)
    qb = rng.standard_normal((2, omega.size, 4)) + 1j * rng.standard_normal((2, omega.size, 4))
    yf = rng.standard_normal((2, omega.size)) + 1j * rng.standard_normal((2, omega.size))
    c_t = list(TUGGERS.values())
    ref = direct_solve(M, K, Kb, C, omega, qb, yf, c_t)
    Hq, Hrel = transfer_functions(M, K, Kb, C, omega, qb, yf, c_t)
    scale = np.abs(ref).max(axis=-2, keepdims=True)
    assert np.max(np.abs(Hq - ref) / scale) < 1e-10
    np.testing.assert_allclose(Hrel, Hq - qb)
    P = relative_power(M, K, Kb, C, omega, qb, yf, c_t)
    P_ref = np.moveaxis(np.abs((ref - qb) * SCALE) ** 2, -1, -2)
    assert np.max(np.abs(P - P_ref) / P_ref.max(axis=-1, keepdims=True)) < 1e-10
    # Slices of the candidates on threads: the same numbers, bit for bit, whatever the
    # number of threads (also more threads than candidates).
    for threads in (2, 5, 40):
        np.testing.assert_array_equal(relative_power(M, K, Kb, C, omega, qb, yf, c_t,
                                                     threads=threads), P)
        np.testing.assert_array_equal(transfer_functions(M, K, Kb, C, omega, qb, yf, c_t,
                                                         threads=threads)[0], Hq)


def test_pivoting_on_a_permuted_system():
    """A system whose first pivot is zero: only a pivoting solve gets it right."""
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    perm = [3, 2, 1, 0]
    M, K, C = (a[np.ix_(perm, perm)] for a in (p.M, p.K, p.C))
    Kb = p.Kb[perm][:, perm]
    K = K.copy()
    K[0, 0] = 0.0                                   # zero stiffness on the first row ...
    M = M.copy()
    M[0, 0] = 0.0                                   # ... and no mass: A[0, 0] = i w C00
    C = C.copy()
    C[0, :] = C[:, 0] = 0.0
    C[0, 0] = 0.0
    omega = np.array([0.3, 0.7, 1.9])
    qb = np.ones((1, 3, 4), complex)
    # A[0, 0] = 0 exactly: solvable only with pivoting
    ref = direct_solve(M[None], K[None], Kb[None], C[None], omega, qb, np.zeros((1, 3)), [0.0])
    Hq, _ = transfer_functions(M, K, Kb, C, omega, qb)
    np.testing.assert_allclose(Hq, ref[0], rtol=1e-10)


def test_base_excited_oscillator_with_tugger_is_analytic():
    """Sway-only pendulum driven at the hinge; the tugger fairlead moves with the hinge:
    y / y_b = (k + i w c_t) / (k - w^2 m + i w (c + c_t)) (damping on the absolute motion)."""
    m, period, zeta = 7719.0, 15.7, 0.0098
    wn = 2 * np.pi / period
    k, c = m * wn**2, 2 * zeta * m * wn
    M = np.diag([m, m, 4.55e6, 3.286e6])
    K = np.diag([k, 2.3e5, 1.2e8, 1.0e7])
    C = np.diag([c, 1e3, 1e5, 1e4])
    omega = np.linspace(0.05, 2.0, 500)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0
    _, Hrel = transfer_functions(M, K, -K, C, omega, qb, qb[..., 0], [0.0, 1500.0])
    for i, ct in enumerate([0.0, 1500.0]):
        expected = (k + 1j * omega * ct) / (k - omega**2 * m + 1j * omega * (c + ct)) - 1.0
        np.testing.assert_allclose(Hrel[i, 0, :, 0], expected, rtol=1e-10)
        assert np.all(Hrel[i, 0, :, 1:] == 0)


@pytest.mark.parametrize("step, tol", [(0.002, 1e-5), (0.01, 5e-4)])
def test_resonance_integral_converges(step, tol):
    """sigma on the refined grid vs a uniform grid 100x finer than the refinement."""
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    wn = 2 * np.pi / p.modes.period

    def m0(omega):
        qb = np.zeros((1, omega.size, 4), complex)
        qb[..., 0] = 8.0 / (1 + ((omega - 0.45) / 0.15) ** 2) * np.exp(-0.5j * omega)
        qb[..., 3] = 0.01 * np.exp(-1j * omega)
        P = relative_power(p.M, p.K, p.Kb, p.C, omega, qb, qb[..., 0], [0.0, 1000.0])
        return spectral_moments(P, moment_weights(omega, unit_spectra(omega, [5.0, 8.0, 11.0])))[0]

    grid = frequency_grid(0.1, 3.0, step, wn, p.damping_ratio)
    ref = m0(np.linspace(0.1, 3.0, 500_001))
    got = m0(grid)
    sway, yaw = (np.s_[..., r, :] for r in (0, 3))
    assert np.max(np.abs(got[sway] / ref[sway] - 1)) < tol
    assert np.max(np.abs(got[yaw] / ref[yaw] - 1)) < tol
    # the uniform base grid alone misses the 1 %-damped peak at the coarse step
    if step >= 0.01:
        base = np.linspace(0.1, 3.0, int(round(2.9 / step)) + 1)
        assert np.max(np.abs(m0(base)[sway] / ref[sway] - 1)) > 100 * tol


def test_grid_size_does_not_grow_with_candidates():
    """Frequencies per candidate: bounded by the range over the finest step, whatever the
    number of candidates (the old shared grid added ~800 per candidate)."""
    rng = np.random.default_rng(0)
    sizes = {}
    for n in (1, 10, 1000, 10_000):
        wn = np.stack([2 * np.pi / rng.uniform(12, 20, n), 2 * np.pi / rng.uniform(3, 4.5, n)], -1)
        sizes[n] = frequency_grid(0.1, 3.0, 0.002, wn, 0.0098).size
    bound = 2.9 / (2 * 0.0098 * 2 * np.pi / 20 / 6) + 1
    assert all(s <= bound for s in sizes.values())
    assert sizes[10_000] <= 1.25 * sizes[10]
    # solver work = candidates x frequencies: linear
    assert sizes[10_000] * 10_000 / (sizes[1000] * 1000) == pytest.approx(10, rel=0.05)


def test_blas_moments_equal_the_statistics_integral():
    p = from_matrices(A1, g=9.81, zeta=0.0098)
    omega = frequency_grid(0.1, 3.0, 0.002, 2 * np.pi / p.modes.period, p.damping_ratio)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0 / (1 + omega**2)
    _, Hrel = transfer_functions(p.M, p.K, p.Kb, p.C, omega, qb)
    stats = unit_statistics(omega, np.moveaxis(Hrel, -1, -2) * SCALE[:, None], [6.0, 9.0])
    P = relative_power(p.M, p.K, p.Kb, p.C, omega, qb)
    m0, _ = spectral_moments(P, moment_weights(omega, unit_spectra(omega, [6.0, 9.0])))
    np.testing.assert_allclose(np.sqrt(m0[0, 0]), stats["sigma"][0], rtol=1e-12)


def test_chunked_equals_unchunked_and_cache_evaluates_only_new_sea_states(grid_plants, motion, tmp_path):
    exc = excitation(grid_plants, motion, [60.0, 90.0], 0.004)
    c_t = list(TUGGERS.values())
    tz = [5.5, 7.5, 9.5]
    whole = unit_moments(grid_plants, exc, tz, c_t)
    n = grid_plants.sizes["candidate"]
    assert n > BLOCK
    for size in (1, 7, 50):
        parts = [unit_moments(grid_plants, exc, tz, c_t, candidates=slice(i, min(i + size, n)))
                 for i in range(0, n, size)]
        for k in (0, 1):
            assert np.array_equal(np.concatenate([p[k] for p in parts]), whole[k])
    # The cache: every sea state once; an added Tz column evaluates that column alone.
    cache = tmp_path / "cache"
    first = unit_moments(grid_plants, exc, tz, c_t, cache=cache)
    assert first[2] == 3 * 2
    again = unit_moments(grid_plants, exc, tz + [11.5], c_t, cache=cache)
    assert again[2] == 2                                   # one Tz x two headings
    assert np.array_equal(again[0][..., :3], whole[0])
    one_heading = excitation(grid_plants, motion, [90.0], 0.004)
    assert unit_moments(grid_plants, one_heading, [7.5, 11.5], c_t, cache=cache)[2] == 0
    # another chunk of candidates is another set: evaluated, not mixed up
    sub = unit_moments(grid_plants, exc, tz, c_t, candidates=slice(0, 5), cache=cache)
    assert sub[2] == 6 and np.array_equal(sub[0], whole[0][:5])


def test_response_dataset_keeps_transfer_for_shown_candidates(grid_plants, motion):
    ds = response_dataset(grid_plants.isel(candidate=slice(0, 4)), motion, [6.5, 8.5], [90.0],
                          TUGGERS, outside_policy={"zero_above_rad_s": 3.0, "reason": "the hull no longer responds above 3 rad/s"}, omega_step=0.004,
                          shown=["baseline", "detuned"])
    assert ds["transfer"].dims == ("shown_candidate", "tugger", "heading", "response", "omega")
    assert ds["shown_candidate"].values.tolist() == ["baseline", "detuned"]
    assert ds["mpm"].sizes["candidate"] == 4
    # damping never increases the relative sway in this linear model
    sway = ds["mpm"].sel(response="relative_sway")
    assert np.all(sway.sel(tugger="high") <= sway.sel(tugger="none") * (1 + 1e-12))
