"""Sea states of one or more wave systems (jls.sea.sea_state): every shape carries Hs^2/16
and peaks at its Tp, periods converted by the shape's relation, spreading functions that
integrate to 1 with the declared mean and spread, and the Torsethaugen split."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from jls.errors import InputError
from jls.sea import periods, spectra, two_peak
from jls.sea.sea_state import (
    SeaState,
    Spreading,
    WaveSystem,
    parse_spreading,
    torsethaugen_systems,
    wave_system,
)

LONG = Spreading("long-crested")
SPREAD = {"wind": "cos2s:4", "swell": "cos2s:13"}


def _m(w, S, n=0):
    return float(np.trapezoid(S * w**n, w))


def _grid(tp):
    return np.linspace(1e-3, 60 * 2 * np.pi / tp, 400001)


@pytest.mark.parametrize("shape, gamma", [("jonswap", 3.3), ("jonswap", 1.5), ("pm", 1.0)])
def test_jonswap_and_pm_systems_integrate_to_hs2_over_16_and_peak_at_tp(shape, gamma):
    s = wave_system(shape, 2.5, "tp", 11.0, gamma=gamma, from_deg=10, spreading="long")
    w = _grid(11.0)
    S = s.spectrum(w)
    tail = S[-1] * w[-1] / 4                                      # omega^-5 beyond the grid
    assert _m(w, S) + tail == pytest.approx(2.5**2 / 16, rel=1e-5)
    assert 2 * np.pi / w[np.argmax(S)] == pytest.approx(11.0, rel=1e-4)
    assert s.m0() == 2.5**2 / 16


@pytest.mark.parametrize("hs, tp", [(3.0, 12.0), (4.0, 7.0), (2.0, 16.0)])
def test_torsethaugen_systems_each_carry_their_hs_and_peak_at_their_tp(hs, tp):
    systems = torsethaugen_systems(hs, "tp", tp, from_deg=200, spreading=SPREAD)
    p = two_peak.torsethaugen_parameters(hs, tp)
    assert [s.kind for s in systems] == (["wind", "swell"] if p["wind_dominated"] else ["swell", "wind"])
    w = np.linspace(1e-3, 40.0, 800001)
    for s in systems:
        S = s.spectrum(w)
        tail = S[-1] * w[-1] / 3                                  # omega^-4 beyond the grid
        assert _m(w, S) + tail == pytest.approx(s.hs**2 / 16, rel=1e-5)
        assert 2 * np.pi / w[np.argmax(S)] == pytest.approx(s.tp, rel=2e-4)
    # the two systems are the Torsethaugen spectrum, and carry its Hs
    sea = SeaState(tuple(systems))
    np.testing.assert_allclose(sea.spectrum(w), two_peak.torsethaugen(w, hs, tp), rtol=1e-12, atol=1e-15)
    assert sea.hs == pytest.approx(hs, rel=1e-12)
    assert systems[0].tp == tp


def test_torsethaugen_against_dnv_rp_c205_by_hand():
    """DNV-RP-C205 (2010) 3.5.7 evaluated by hand for Hs 4 m, Tp 12 s (swell-dominated:
    Tf = 6.6 * 4^(1/3) = 10.477 s): Hs1 = 3.8159 m at 12 s, gamma1 = 2.277; Hs2 = 1.1994 m
    at Tp2 = 6.6 Hs2^(1/3) = 7.012 s, gamma2 = 1; the standard's closed-form spectrum of
    the primary at its peak, Hs1^2/(16 wp) A(gamma) G0 e^-1 gamma with A = (1 + 1.1 ln(gamma)^1.19)/gamma
    and G0 = 3.26 (the standard prints G0 = 3.26), within the 3 % the closed-form A differs
    from the exact normalisation."""
    primary, secondary = torsethaugen_systems(4.0, "tp", 12.0, from_deg=0, spreading=SPREAD)
    assert (primary.kind, secondary.kind) == ("swell", "wind")
    assert primary.hs == pytest.approx(3.8159, rel=5e-4) and primary.gamma == pytest.approx(2.277, rel=5e-4)
    assert secondary.hs == pytest.approx(1.1994, rel=5e-4) and secondary.tp == pytest.approx(7.012, rel=5e-4)
    wp = 2 * np.pi / 12.0
    a = (1 + 1.1 * math.log(2.277) ** 1.19) / 2.277
    printed = 3.8159**2 / (16 * wp) * a * 3.26 * math.exp(-1) * 2.277
    assert float(primary.spectrum(wp)) == pytest.approx(printed, rel=0.035)


def test_a_declared_tz_te_or_tm01_is_converted_by_the_shapes_own_relation():
    for period in ("tz", "tm01", "te"):
        s = wave_system("jonswap", 2.0, period, 8.0, gamma=3.3, from_deg=0, spreading="long")
        got = periods.spectrum_periods("jonswap", hs=2.0, tp=s.tp, gamma=3.3)[period]
        assert got == pytest.approx(8.0, rel=1e-9), period
    assert wave_system("jonswap", 2.0, "tz", 8.0, gamma=3.3, from_deg=0,
                       spreading="long").tp == pytest.approx(float(spectra.tp_from_tz(8.0, 3.3)), rel=1e-12)
    # Torsethaugen: the primary system peaks at the sea state's Tp, whose Tz is the one declared
    ts = torsethaugen_systems(3.0, "tz", 5.5, from_deg=0, spreading=SPREAD)
    assert periods.spectrum_periods("torsethaugen", hs=3.0, tp=ts[0].tp)["tz"] == pytest.approx(5.5, rel=1e-8)


@pytest.mark.parametrize("text, r1", [("cos2s:4", 4 / 5), ("cos2s:13", 13 / 14), ("cos2s:75", 75 / 76),
                                      ("cosn:2", 8 / (3 * math.pi)), ("cosn:6", None)])
def test_spreading_integrates_to_one_with_the_declared_mean_and_spread(text, r1):
    sp = parse_spreading(text)
    total, _ = quad(lambda t: sp.density(t), -180, 180, points=[0.0], limit=200)
    assert total * math.pi / 180 == pytest.approx(1.0, abs=1e-10)
    sin_mean, _ = quad(lambda t: sp.density(t) * math.sin(math.radians(t)), -180, 180, limit=200)
    assert sin_mean == pytest.approx(0.0, abs=1e-12)             # mean direction: the declared one
    cos_mean, _ = quad(lambda t: sp.density(t) * math.cos(math.radians(t)), -180, 180, limit=200)
    cos_mean *= math.pi / 180
    assert sp.r1() == pytest.approx(cos_mean, rel=1e-9)
    if r1 is not None:                                           # closed forms
        assert sp.r1() == pytest.approx(r1, rel=1e-12)
    assert sp.spread_deg() == pytest.approx(math.degrees(math.sqrt(2 * (1 - cos_mean))), rel=1e-8)
    # on the grid of a system: weights sum to 1, mean at the declared direction, spread close
    s = WaveSystem("jonswap", 1.0, 10.0, 350.0, sp, "wind", 3.3)
    d, w = s.directions()
    assert w.sum() == pytest.approx(1.0, abs=1e-14)
    z = np.sum(w * np.exp(1j * np.radians(d)))
    assert np.degrees(np.angle(z)) % 360 == pytest.approx(350.0, abs=1e-9)
    assert math.degrees(math.sqrt(2 * (1 - abs(z)))) == pytest.approx(sp.spread_deg(), rel=0.02)


def test_long_crested_is_one_direction_and_explicit():
    s = WaveSystem("jonswap", 1.0, 10.0, 123.0, parse_spreading("long-crested"), "swell", 3.3)
    d, w = s.directions()
    assert d.tolist() == [123.0] and w.tolist() == [1.0]
    for bad in ("cos2s", "cos2s:-1", "cos3:4", "", "cosn:abc"):
        with pytest.raises(InputError, match="spreading"):
            parse_spreading(bad)
    with pytest.raises(InputError, match="0-360"):
        WaveSystem("jonswap", 1.0, 10.0, 2 * math.pi * 100, LONG)
    with pytest.raises(InputError, match="spectrum"):
        WaveSystem("ochi", 1.0, 10.0, 0.0, LONG)


def test_two_systems_sum_their_variances_and_a_measured_system_integrates_as_given():
    wind = wave_system("jonswap", 2.0, "tp", 7.0, gamma=3.3, from_deg=0, spreading="cos2s:4")
    swell = wave_system("jonswap", 1.5, "tp", 15.0, gamma=5.0, from_deg=90, spreading="cos2s:13", kind="swell")
    sea = SeaState((wind, swell))
    assert sea.hs == pytest.approx(math.hypot(2.0, 1.5), rel=1e-12)
    w = np.linspace(0.05, 4.0, 40001)
    meas = WaveSystem("measured", 0.0, 15.0, 90.0, LONG, "swell", omega=w, density=swell.spectrum(w))
    assert meas.m0() == pytest.approx(_m(w, swell.spectrum(w)), rel=1e-12)
    np.testing.assert_allclose(meas.spectrum(w[::7]), swell.spectrum(w[::7]), rtol=1e-12)
