"""Spectra, period relations and the steepness ceiling (jls.sea.spectra, jls.sea.steepness)."""

import numpy as np
import pytest
from scipy.special import gamma as gamma_fn

from jls.errors import InputError
from jls.sea.spectra import (
    gamma_dnv,
    jonswap,
    jonswap_normalisation,
    jonswap_shape_moment,
    pierson_moskowitz,
    spectral_moment,
    t1_from_tp,
    te_from_tp,
    tp_from_tz,
    tz_from_tp,
)
from jls.sea.steepness import exceeds_steepness, steepness_limit_hs

GAMMAS = np.array([1.0, 1.5, 2.0, 3.3, 5.0, 6.9])


def _grid(tp, upper=20.0, n=40001):
    """Frequency grid 0 .. upper * omega_p [rad/s]."""
    return np.linspace(0.0, upper * 2 * np.pi / tp, n)


@pytest.mark.parametrize("gamma", [1.0, 2.0, 3.3, 5.0, 7.0, 10.0])
@pytest.mark.parametrize("sigmas", [(0.07, 0.09), (0.05, 0.15)])
def test_continuous_m0_is_exactly_hs2_over_16(gamma, sigmas):
    hs, tp = 3.0, 9.0
    w = np.linspace(0.0, 60 * 2 * np.pi / tp, 400001)
    S = jonswap(w, hs, tp, gamma, *sigmas)
    m0 = spectral_moment(w, S, 0, tail=True)
    assert m0 == pytest.approx(hs**2 / 16, rel=1e-4)


def test_broadcasting_shapes():
    w = np.linspace(0.1, 3.0, 50)
    hs = np.array([[1.0], [2.0], [3.0]])
    tp = np.array([[8.0], [10.0], [12.0]])
    g = np.array([[1.0], [3.3], [5.0]])
    S = jonswap(w, hs, tp, g)
    assert S.shape == (3, 50)
    # each row equals the scalar call
    for k in range(3):
        np.testing.assert_allclose(S[k], jonswap(w, hs[k, 0], tp[k, 0], g[k, 0]))
    # three broadcast axes: (hs, tz, omega)
    S3 = jonswap(w, hs[:, :, None], tp.T[:, :, None] * np.ones((1, 1, 1)), 3.3)
    assert S3.shape == (3, 3, 50)
    # S scales with Hs^2 (linear response at unit Hs)
    np.testing.assert_allclose(jonswap(w, 2.0, 9.0), 4 * jonswap(w, 1.0, 9.0))


def test_pierson_moskowitz_closed_form_and_zero_frequency():
    hs, tp = 2.5, 8.0
    wp = 2 * np.pi / tp
    w = np.array([0.0, 0.3, 0.6, 0.8, 1.5])
    expected = np.zeros_like(w)
    expected[1:] = 5 / 16 * hs**2 * wp**4 * w[1:] ** -5 * np.exp(-1.25 * (wp / w[1:]) ** 4)
    np.testing.assert_allclose(pierson_moskowitz(w, hs, tp), expected, rtol=1e-12)
    assert jonswap(0.0, hs, tp) == 0.0


def test_peak_at_tp_and_enhancement():
    tp = 10.0
    w = np.linspace(0.2, 2.0, 20001)
    for g in (1.0, 3.3, 6.0):
        S = jonswap(w, 2.0, tp, g)
        assert w[np.argmax(S)] == pytest.approx(2 * np.pi / tp, rel=2e-3)
    # at the peak, S_J / S_PM = A(gamma) * gamma
    wp = 2 * np.pi / tp
    assert jonswap(wp, 2.0, tp, 3.3) / pierson_moskowitz(wp, 2.0, tp) == pytest.approx(
        3.3 * jonswap_normalisation(3.3))


def test_normalisation_close_to_dnv_closed_form():
    a = jonswap_normalisation(GAMMAS)
    assert a[0] == pytest.approx(1.0, abs=1e-12)
    # DNV's approximation is good to ~0.3 % up to gamma 5, ~2 % at the top of its range
    np.testing.assert_allclose(a, 1 - 0.287 * np.log(GAMMAS), rtol=0.02)
    np.testing.assert_allclose(a[:5], 1 - 0.287 * np.log(GAMMAS[:5]), rtol=0.005)
    assert np.all(np.diff(a) < 0)


@pytest.mark.parametrize("tail,tol", [(False, 0.005), (True, 5e-4)])
def test_recover_hs_and_tz_from_built_spectrum(tail, tol):
    tz = np.array([4.0, 6.0, 8.0, 10.0, 14.0])[:, None, None]
    g = GAMMAS[None, :, None]
    hs = 2.0 + 0.5 * tz  # any Hs
    tp = tp_from_tz(tz, g, method="exact")
    x = np.linspace(0.0, 20.0, 40001)  # omega / omega_p, up to 20 omega_p
    w = x * 2 * np.pi / tp
    S = jonswap(w, hs, tp, g)
    m0 = spectral_moment(w, S, 0, tail=tail)
    m2 = spectral_moment(w, S, 2, tail=tail)
    assert m0.shape == (5, 6)
    np.testing.assert_allclose(4 * np.sqrt(m0), np.broadcast_to(hs[..., 0], m0.shape), rtol=tol)
    np.testing.assert_allclose(2 * np.pi * np.sqrt(m0 / m2), np.broadcast_to(tz[..., 0], m0.shape), rtol=tol)


def test_exact_period_ratios_match_built_spectrum():
    tp = 11.0
    w = _grid(tp, 40.0, 80001)
    for g in (1.0, 3.3, 5.0):
        S = jonswap(w, 1.0, tp, g)
        m = {n: spectral_moment(w, S, n, tail=True) for n in (-1, 0, 1, 2)}
        assert 2 * np.pi * m[0] / m[1] == pytest.approx(t1_from_tp(tp, g, method="exact"), rel=1e-4)
        assert 2 * np.pi * m[-1] / m[0] == pytest.approx(te_from_tp(tp, g), rel=1e-4)
        assert 2 * np.pi * np.sqrt(m[0] / m[2]) == pytest.approx(tz_from_tp(tp, g, method="exact"), rel=1e-4)


def test_pm_moment_ratios_analytic():
    # M_n = 1.25^(n/4) Gamma(1 - n/4) for the PM shape
    for n in (-1, 1, 2, 3):
        assert jonswap_shape_moment(n, 1.0) == pytest.approx(1.25 ** (n / 4) * gamma_fn(1 - n / 4), rel=1e-9)
    assert te_from_tp(1.0, 1.0) == pytest.approx(1.25**-0.25 * gamma_fn(1.25), rel=1e-9)
    with pytest.raises(InputError):
        jonswap_shape_moment(4, 3.3)


def test_tp_is_1p286_tz_at_gamma_3p3():
    assert tp_from_tz(1.0) == pytest.approx(1.286, abs=5e-4)
    assert tp_from_tz(6.6, 3.3) == pytest.approx(1.286 * 6.6, rel=5e-4)
    tz = np.linspace(3, 15, 7)
    np.testing.assert_allclose(tz_from_tp(tp_from_tz(tz, 2.0), 2.0), tz, rtol=1e-12)
    np.testing.assert_allclose(tz_from_tp(tp_from_tz(tz, 2.0, "exact"), 2.0, "exact"), tz, rtol=1e-12)


def test_dnv_polynomials_agree_with_exact_moment_ratios():
    g = np.linspace(1.0, 6.99, 40)
    np.testing.assert_allclose(tz_from_tp(1.0, g), tz_from_tp(1.0, g, method="exact"), rtol=0.01)
    np.testing.assert_allclose(t1_from_tp(1.0, g), t1_from_tp(1.0, g, method="exact"), rtol=0.01)
    # ordering of periods for a spectrum: Tz < T1 < Te < Tp
    assert np.all(tz_from_tp(1.0, g, "exact") < t1_from_tp(1.0, g, "exact"))
    assert np.all(t1_from_tp(1.0, g, "exact") < te_from_tp(1.0, g))
    assert np.all(te_from_tp(1.0, g) < 1.0)


def test_dnv_relation_range_and_bad_input():
    with pytest.raises(InputError, match="gamma"):
        tp_from_tz(8.0, 8.0)
    # exact works beyond the polynomial's range; Tp/Tz falls as the peak sharpens
    assert tp_from_tz(8.0, 8.0, method="exact") < tp_from_tz(8.0, 6.9)
    with pytest.raises(InputError, match="method"):
        tz_from_tp(8.0, 3.3, method="poly")
    with pytest.raises(InputError) as e:
        jonswap(1.0, -1.0, 8.0)
    assert e.value.field == "hs" and e.value.value == -1.0
    for bad in (dict(tp=0.0), dict(tp=np.nan), dict(gamma=0.0)):
        kw = dict(hs=1.0, tp=8.0) | bad
        with pytest.raises(InputError):
            jonswap(0.5, **kw)


def test_gamma_dnv_rule():
    hs = 4.0  # sqrt = 2
    tp = np.array([6.0, 7.2, 8.6, 10.0, 14.0])  # phi = 3, 3.6, 4.3, 5, 7
    expected = [5.0, 5.0, np.exp(5.75 - 1.15 * 4.3), 1.0, 1.0]
    np.testing.assert_allclose(gamma_dnv(hs, tp), expected)
    assert gamma_dnv(0.0, 8.0) == 1.0
    assert gamma_dnv(np.full((2, 1), 4.0), np.ones((1, 3)) * 8.0).shape == (2, 3)


def test_spectral_moment_trapezoid_and_tail():
    w = np.linspace(0.0, 2.0, 201)
    S = np.ones_like(w)
    assert spectral_moment(w, S, 0) == pytest.approx(2.0)
    assert spectral_moment(w, S, 1) == pytest.approx(2.0, rel=1e-4)
    assert np.isfinite(spectral_moment(w, pierson_moskowitz(w, 1.0, 8.0), -1))
    # pure omega^-5 tail: beyond the grid adds S_L w_L^(n+1)/(4-n)
    w2 = np.linspace(1.0, 2.0, 2001)
    S2 = w2**-5.0
    assert spectral_moment(w2, S2, 0, tail=True) == pytest.approx(0.25, rel=1e-5)


# --- steepness ceiling -------------------------------------------------------------

TABLE_6_9_TZ = [6.00, 6.25, 6.50, 6.75, 7.00, 7.25, 7.50, 8.00]
TABLE_6_9_HS = [3.75, 4.07, 4.40, 4.74, 5.10, 5.47, 5.85, 6.66]


def test_study_steepness_ceiling_reproduces_table_6_9():
    np.testing.assert_array_equal(np.round(steepness_limit_hs(TABLE_6_9_TZ), 2), TABLE_6_9_HS)
    assert steepness_limit_hs(6.0) == pytest.approx(9.81 * 36 / (2 * np.pi * 15))
    assert steepness_limit_hs(6.0, steepness=1 / 20) == pytest.approx(9.81 * 36 / (2 * np.pi * 20))


def test_dnv_steepness_rule():
    g = 9.81
    tz = np.linspace(3.0, 16.0, 300)
    hs = steepness_limit_hs(tz, "dnv")
    tp = tp_from_tz(tz, 3.3)
    sp = 2 * np.pi * hs / (g * tp**2)
    np.testing.assert_allclose(sp[tp <= 8], 1 / 15)
    np.testing.assert_allclose(sp[tp >= 15], 1 / 25)
    mid = (tp > 8) & (tp < 15)
    np.testing.assert_allclose(sp[mid], 1 / 15 + (tp[mid] - 8) / 7 * (1 / 25 - 1 / 15))
    assert np.all(np.diff(hs) > 0)  # the ceiling rises with period
    # with Tp = 1.286 Tz and 1/15 the DNV rule allows 1.286^2 times the study's Hs
    assert steepness_limit_hs(5.0, "dnv") / steepness_limit_hs(5.0) == pytest.approx(tp_from_tz(1.0) ** 2)
    with pytest.raises(InputError, match="rule"):
        steepness_limit_hs(6.0, "iso")


def test_exceeds_steepness_on_and_above_ceiling():
    lim = steepness_limit_hs(6.0)
    assert not exceeds_steepness(lim, 6.0)
    assert exceeds_steepness(lim + 0.01, 6.0)
    flags = exceeds_steepness(np.array([[1.0], [4.0]]), np.array([5.0, 7.0]))
    np.testing.assert_array_equal(flags, [[False, False], [True, False]])
