"""Two-peak spectra and the period conventions (jls.sea.two_peak, jls.sea.periods)."""

import math

import numpy as np
import pytest

from jls.errors import InputError
from jls.sea import periods, spectra, two_peak
from jls.sea.two_peak import Partition


def _grid(tp, upper=80.0, n=800001):
    return np.linspace(0.0, upper * 2 * np.pi / tp, n)


def _m(w, S, n, tail_power):
    """m_n on the grid plus the analytic tail of an omega^-p spectrum beyond it."""
    m = spectra.spectral_moment(w, S, n)
    return m + S[-1] * w[-1] ** (n + 1) / (tail_power - n - 1)


# --- Torsethaugen ---------------------------------------------------------------------

@pytest.mark.parametrize("hs, tp", [(4.0, 12.0), (4.0, 7.0), (2.0, 15.0), (6.0, 10.5), (1.0, 5.0),
                                    (8.0, 18.0), (0.5, 4.0)])
def test_torsethaugen_integrates_to_hs2_over_16_and_peaks_at_tp(hs, tp):
    w = _grid(min(tp, 6.0))
    S = two_peak.torsethaugen(w, hs, tp)
    assert _m(w, S, 0, 4) == pytest.approx(hs**2 / 16, rel=1e-5)
    assert two_peak.torsethaugen_moment(0, hs, tp) == pytest.approx(hs**2 / 16, rel=1e-12)
    # the primary system peaks exactly at Tp; the sum within 1 % of it (the secondary
    # system's slope moves the maximum by 0.0-0.9 % over these sea states)
    s1, _ = two_peak.torsethaugen(w, hs, tp, systems=True)
    assert 2 * np.pi / w[np.argmax(s1)] == pytest.approx(tp, rel=2e-4)
    assert 2 * np.pi / w[np.argmax(S)] == pytest.approx(tp, rel=1e-2)
    assert periods.spectrum_periods("torsethaugen", hs=hs, tp=tp)["tp"] == pytest.approx(
        2 * np.pi / w[np.argmax(S)], rel=1e-4)


def test_torsethaugen_peak_parameters_by_hand_dnv_rp_c205():
    """DNV-RP-C205 3.5.7 (the simplified model of Torsethaugen and Haver 2004, table 1),
    evaluated by hand for a swell-dominated and a wind-dominated sea state of Hs = 4 m.

    Tf = 6.6 * 4^(1/3) = 10.4768 s.
    Tp = 12 s > Tf: eps_u = (12 - 10.4768) / (25 - 10.4768) = 0.10488,
      r_ps = 0.4 exp(-(0.10488/0.3)^2) + 0.6 = 0.95398, Hs1 = 3.8159 m,
      Hs2 = 4 sqrt(1 - 0.95398^2) = 1.1994 m, Tp2 = 6.6 * 1.1994^(1/3) = 7.012 s,
      gamma = 35 (2 pi 4 / (9.81 * 10.4768^2))^(6/7) (1 + 6 * 0.10488) = 1.3979 * 1.6293 = 2.277.
    Tp = 7 s <= Tf: Tl = 2 * 4^(1/2) = 4 s, eps_l = (10.4768 - 7) / (10.4768 - 4) = 0.53681,
      r_pw = 0.3 exp(-(0.53681/0.5)^2) + 0.7 = 0.79474, Hs1 = 3.1790 m,
      Hs2 = 4 sqrt(1 - 0.79474^2) = 2.4278 m, Tp2 = 10.4768 + 2 = 12.477 s,
      gamma = 35 (2 pi 3.1790 / (9.81 * 7^2))^(6/7) = 2.291.
    """
    p = two_peak.torsethaugen_parameters(4.0, 12.0)
    assert not p["wind_dominated"]
    assert float(p["tf"]) == pytest.approx(10.4768, abs=1e-4)
    for key, hand in (("hs1", 3.8159), ("hs2", 1.1994), ("tp2", 7.012), ("gamma1", 2.277)):
        assert float(p[key]) == pytest.approx(hand, rel=5e-4), key
    assert float(p["tp1"]) == 12.0 and float(p["gamma2"]) == 1.0
    p = two_peak.torsethaugen_parameters(4.0, 7.0)
    assert p["wind_dominated"]
    for key, hand in (("hs1", 3.1790), ("hs2", 2.4278), ("tp2", 12.477), ("gamma1", 2.291)):
        assert float(p[key]) == pytest.approx(hand, rel=5e-4), key
    # the standard's closed-form A(gamma) at gamma = 3.3: (1 + 1.1 * 1.19392^1.19) / 3.3
    assert two_peak.a_gamma_dnv(3.3) == pytest.approx(0.71464, abs=2e-5)
    # ... against the exact normalisation of the x^-4 shape (3 % lower)
    assert two_peak.torsethaugen_normalisation(3.3) == pytest.approx(0.6925, abs=5e-4)
    assert two_peak.torsethaugen_normalisation(1.0) == pytest.approx(1.0, abs=1e-12)
    # with the closed form, m0 is off by the same 3 %
    w = _grid(6.0)
    S = two_peak.torsethaugen(w, 4.0, 7.0, normalisation="dnv")
    assert _m(w, S, 0, 4) / 1.0 == pytest.approx(1.0, abs=0.035)


def test_torsethaugen_continuous_across_tf_and_gamma_floor():
    hs = 3.0
    tf = 6.6 * hs ** (1 / 3)
    w = np.linspace(0.05, 3.0, 2000)
    below = two_peak.torsethaugen(w, hs, tf * (1 - 1e-9))
    above = two_peak.torsethaugen(w, hs, tf * (1 + 1e-9))
    np.testing.assert_allclose(below, above, rtol=1e-6, atol=1e-12)
    # small steep-less seas: the gamma formula falls below 1; the PM shape (1) is used
    assert float(two_peak.torsethaugen_parameters(0.3, 6.6 * 0.3 ** (1 / 3) + 0.1)["gamma1"]) == 1.0
    assert float(two_peak.torsethaugen(0.5, 0.0, 8.0)) == 0.0


def test_torsethaugen_moments_exact_against_grid():
    hs, tp = 3.0, 11.0
    w = _grid(6.0)
    S = two_peak.torsethaugen(w, hs, tp)
    for n in (-1, 1, 2):
        assert two_peak.torsethaugen_moment(n, hs, tp) == pytest.approx(_m(w, S, n, 4), rel=2e-4), n
    with pytest.raises(InputError, match="< 3"):
        two_peak.torsethaugen_moment(3, hs, tp)


# --- Ochi-Hubble ----------------------------------------------------------------------

def test_ochi_hubble_integrates_to_hs2_over_16_and_peaks_at_each_tp():
    args = dict(hs1=2.5, tp1=14.0, lambda1=3.0, hs2=1.5, tp2=6.5, lambda2=1.2)
    w = _grid(6.0)
    S = two_peak.ochi_hubble(w, **args)
    hs = math.hypot(2.5, 1.5)
    assert _m(w, S, 0, 4 * 1.2 + 1) == pytest.approx(hs**2 / 16, rel=1e-5)
    assert two_peak.ochi_hubble_moment(0, **args) == pytest.approx(hs**2 / 16, rel=1e-12)
    for n in (-1, 1, 2):
        assert two_peak.ochi_hubble_moment(n, **args) == pytest.approx(_m(w, S, n, 4 * 1.2 + 1), rel=1e-4)
    # each component alone peaks at its own Tp
    for h, t, lam in ((2.5, 14.0, 3.0), (1.5, 6.5, 1.2)):
        s = two_peak.ochi_hubble(w, h, t, lam, 0.0, 10.0, 1.0)
        assert 2 * np.pi / w[np.argmax(s)] == pytest.approx(t, rel=2e-4)
    # lambda = 1 is Pierson-Moskowitz
    wpm = np.linspace(0.3, 3.0, 500)
    np.testing.assert_allclose(two_peak.ochi_hubble(wpm, 2.0, 9.0, 1.0, 0.0, 5.0, 1.0),
                               spectra.pierson_moskowitz(wpm, 2.0, 9.0), rtol=1e-10)
    assert periods.spectrum_periods("ochi_hubble", **args)["tp"] == pytest.approx(14.0, rel=1e-6)
    with pytest.raises(InputError, match="lambda2"):
        two_peak.ochi_hubble_moment(2, 1.0, 10.0, 1.0, 1.0, 5.0, 0.4)


# --- wind sea + swell -----------------------------------------------------------------

def test_wind_swell_partitions_keep_their_own_hs_and_tp():
    wind = Partition(hs=1.5, tp=6.0, gamma=3.3, from_deg=40.0)
    swell = Partition(hs=1.2, tp=14.0, gamma=6.0, from_deg=110.0)
    w = _grid(6.0, upper=60.0, n=400001)
    s_w, s_s = two_peak.wind_swell(w, wind, swell, partitions=True)
    for p, s in ((wind, s_w), (swell, s_s)):
        assert spectra.spectral_moment(w, s, 0, tail=True) == pytest.approx(p.hs**2 / 16, rel=1e-4)
        assert 2 * np.pi / w[np.argmax(s)] == pytest.approx(p.tp, rel=2e-4)
    total = two_peak.wind_swell_moment(0, wind, swell)
    assert total == pytest.approx((1.5**2 + 1.2**2) / 16, rel=1e-12)
    per = periods.spectrum_periods("wind_swell", wind=wind, swell=swell)
    assert per["hs"] == pytest.approx(math.hypot(1.5, 1.2))
    # the higher peak is the swell's (gamma 6, long period): the spectrum's Tp
    assert per["tp"] == pytest.approx(14.0, rel=1e-6)
    with pytest.raises(InputError, match="from_deg"):
        Partition(hs=1.0, tp=8.0, from_deg=400.0)


# --- periods --------------------------------------------------------------------------

def test_periods_of_jonswap_are_the_pipelines():
    p = periods.spectrum_periods("jonswap", hs=2.0, tp=10.0, gamma=3.3)
    assert p["tz"] == pytest.approx(float(spectra.tz_from_tp(10.0)))
    assert p["tz"] == pytest.approx(10.0 / 1.286, rel=1e-3)             # Tp = 1.286 Tz, gamma 3.3
    assert periods.tp_from_period("jonswap", "tz", 7.7768, gamma=3.3) == pytest.approx(10.0, rel=1e-4)
    assert periods.tp_from_period("jonswap", "te", p["te"], gamma=3.3) == pytest.approx(10.0, rel=1e-12)
    assert periods.tp_from_period("jonswap", "tp", 9.0) == 9.0
    exact = periods.spectrum_periods("jonswap", hs=2.0, tp=10.0, gamma=3.3, method="exact")
    assert exact["tz"] == pytest.approx(p["tz"], rel=2e-3)          # DNV's polynomial within 0.2 %
    with pytest.raises(InputError, match="needs hs, tp, gamma"):
        periods.spectrum_periods("jonswap", hs=2.0, tp=10.0)


def test_periods_from_moments_match_grid_integration():
    hs, tp = 4.0, 12.0
    w = _grid(6.0)
    S = two_peak.torsethaugen(w, hs, tp)
    m = {n: _m(w, S, n, 4) for n in (-1, 0, 1, 2)}
    grid = periods.from_moments(m[-1], m[0], m[1], m[2])
    exact = periods.spectrum_periods("torsethaugen", hs=hs, tp=tp)
    for k in ("tm01", "tz", "te"):
        assert float(grid[k]) == pytest.approx(exact[k], rel=2e-4), k
    assert exact["te"] > exact["tm01"] > exact["tz"]


def test_declared_tz_gives_the_torsethaugen_tp():
    tp = periods.tp_from_period("torsethaugen", "tz", 6.0, hs=4.0)
    assert periods.spectrum_periods("torsethaugen", hs=4.0, tp=tp)["tz"] == pytest.approx(6.0, abs=1e-9)
    with pytest.raises(InputError, match="no Torsethaugen sea state"):
        periods.tp_from_period("torsethaugen", "tz", 8.0, hs=4.0)
    with pytest.raises(InputError, match="unknown spectrum"):
        periods.spectrum_periods("bretschneider", hs=1.0, tp=8.0)
    with pytest.raises(InputError, match="needs hs, tp"):
        periods.spectrum_periods("torsethaugen", hs=1.0)
    with pytest.raises(InputError, match="period must be"):
        periods.tp_from_period("jonswap", "t13", 8.0)
