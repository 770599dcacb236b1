"""Response moments over directional spectra (jls.response.directional): against the
parametric spectral integral, a swell partition at the sway period, the committed NDBC
spectra by an independent sum, and the heading geometry."""

import numpy as np
import pytest
import sea_fixtures as fx
import xarray as xr

from jls.errors import InputError
from jls.response import directional as dr
from jls.sea import directional, measured, spectra
from jls.sea.two_peak import Partition

T_SWAY, ZETA = 15.5, 0.01
W_N = 2 * np.pi / T_SWAY
HEADINGS = np.arange(0.0, 360.0, 15.0)


def _omega():
    """A solver-like grid: a base step and the resonance refined (as frequency_grid)."""
    return np.union1d(np.arange(0.1, 2.5, 0.002), W_N + np.arange(-0.02, 0.02, 2 * ZETA * W_N / 6))


def _power(omega, scale=1.0):
    """|H|^2 of a base-excited oscillator's relative motion (the sway mode) times a
    heading factor (beam seas strongest): (n_h, n_w)."""
    r = omega / W_N
    h2 = r**4 / ((1 - r**2) ** 2 + (2 * ZETA * r) ** 2)
    return scale * np.sin(np.radians(HEADINGS))[:, None] ** 2 * h2[None, :] + 1e-3 * h2[None, :]


def _parametric(omega, P_beta, S):
    """The direct spectral integral on the solver's grid: m0, m2."""
    return np.trapezoid(P_beta * S, omega), np.trapezoid(P_beta * S * omega**2, omega)


def test_jonswap_given_as_measured_equals_the_parametric_response():
    omega = _omega()
    P = _power(omega)
    hs, tp, from_deg, course = 2.5, 13.0, 120.0, 30.0      # waves from 120 deg: met at 90 (beam)
    freq = np.arange(0.016, 0.398, 0.0005)                   # a fine "measured" band grid
    E = (spectra.jonswap(2 * np.pi * freq, hs, tp) * 2 * np.pi)[:, None] * \
        directional.long_crested(directional.DEFAULT_DIRS, from_deg)[None, :]
    G = dr.response_matrix(P, omega, HEADINGS, freq, directional.DEFAULT_DIRS, course)
    m0, m2, outside = dr.response_moments(E[None], G)
    beta = (course - from_deg + 180) % 360
    assert beta == 90.0
    ref0, ref2 = _parametric(omega, P[list(HEADINGS).index(beta)], spectra.jonswap(omega, hs, tp))
    assert float(m0[0, 0]) == pytest.approx(ref0, rel=1e-3)
    assert float(m2[0, 0]) == pytest.approx(ref2, rel=1e-3)
    assert float(outside[0]) < 1e-3
    # on NDBC's own bands (0.005 Hz at the sway period) the interpolation of the sampled
    # spectrum costs a few per cent at this steep flank of the spectrum
    nd = np.array([float(f) for f in fx.historical_rows("w")[0][5:]])
    E = (spectra.jonswap(2 * np.pi * nd, hs, tp) * 2 * np.pi)[:, None] * \
        directional.long_crested(directional.DEFAULT_DIRS, from_deg)[None, :]
    m0n = dr.response_moments(E[None], dr.response_matrix(P, omega, HEADINGS, nd, directional.DEFAULT_DIRS,
                                                          course))[0]
    assert abs(float(m0n[0, 0]) / ref0 - 1) < 0.05


def test_swell_at_the_sway_period_raises_sigma_as_the_transfer_function_predicts():
    omega = _omega()
    P = _power(omega)
    course = 0.0
    wind = Partition(hs=2.0, tp=7.0, gamma=3.3, from_deg=0.0)       # head seas: little sway
    swell = Partition(hs=1.0, tp=T_SWAY, gamma=5.0, from_deg=270.0)  # beam swell at the sway period
    freq = np.arange(0.016, 0.398, 0.00025)
    dirs = directional.DEFAULT_DIRS
    E_wind = directional.partitions_on_grid(freq, dirs, [wind])
    E_both = directional.partitions_on_grid(freq, dirs, [wind, swell])
    G = dr.response_matrix(P, omega, HEADINGS, freq, dirs, course)
    m0, _, _ = dr.response_moments(np.stack([E_wind, E_both]), G)
    # prediction: each partition at its own heading, integrated with |H|^2 directly
    k = {b: list(HEADINGS).index(b) for b in (180.0, 90.0)}
    pred_wind = _parametric(omega, P[k[180.0]], wind.spectrum(omega))[0]
    pred_swell = _parametric(omega, P[k[90.0]], swell.spectrum(omega))[0]
    assert float(m0[0, 0]) == pytest.approx(pred_wind, rel=1e-3)
    assert float(m0[1, 0]) == pytest.approx(pred_wind + pred_swell, rel=1e-3)
    sigma_wind, sigma_both = np.sqrt(m0[:, 0])
    assert sigma_both / sigma_wind == pytest.approx(np.sqrt(1 + pred_swell / pred_wind), rel=1e-3)
    assert sigma_both / sigma_wind > 5.0      # a 1 m swell at the sway period governs
    # a single JONSWAP on the combined Hs and Tz misses it: far less sway
    hs = np.hypot(2.0, 1.0)
    single = _parametric(omega, P[k[90.0]], spectra.jonswap(omega, hs, 9.0))[0]
    assert np.sqrt(single) < 0.5 * sigma_both


def _direct_sum(E, freq, dirs, omega, P, course):
    """Independent reference: interpolate each record's spectrum onto the solver's grid
    (linear between band centres, flat over the outer half-bands) and integrate the
    product with |H|^2 at each bin's heading."""
    width = directional.direction_widths(dirs)
    df = np.gradient(freq)
    lo, hi = freq[0] - df[0] / 2, freq[-1] + df[-1] / 2
    f = omega / (2 * np.pi)
    out = []
    for e in E:
        m0 = 0.0
        for j, d in enumerate(dirs):
            beta = (course - d + 180) % 360
            Pj = np.array([np.interp(beta, np.r_[HEADINGS, 360.0], np.r_[P[:, i], P[0, i]])
                           for i in range(omega.size)])
            s = np.where((f >= lo) & (f <= hi), np.interp(f, freq, e[:, j]), 0.0)
            m0 += width[j] * np.trapezoid(Pj * s, f)
        out.append(m0)
    return np.array(out)


def test_ndbc_spectra_one_matrix_product_equals_a_direct_sum():
    efth = measured.read_ndbc_spectra(fx.NDBC_DENSITY)
    omega = np.union1d(np.arange(0.05, 3.2, 0.01), W_N + np.arange(-0.02, 0.02, 0.0005))
    P = _power(omega)
    course = 17.0                                        # headings between the RAO's: interpolated
    G = dr.response_matrix(P, omega, HEADINGS, efth["freq"].values, efth["dir"].values, course)
    m0, m2, _ = dr.response_moments(efth, G)
    ref = _direct_sum(efth.values[:3], efth["freq"].values, efth["dir"].values, omega, P, course)
    np.testing.assert_allclose(m0[:3, 0], ref, rtol=2e-3)
    # chunks and float32 change nothing beyond rounding
    m0c, m2c, _ = dr.response_moments(efth, G, chunk=7)
    np.testing.assert_allclose(m0c, m0, rtol=1e-13)
    G32 = dr.response_matrix(P, omega, HEADINGS, efth["freq"].values, efth["dir"].values, course,
                             dtype=np.float32)
    np.testing.assert_allclose(dr.response_moments(efth, G32)[0], m0, rtol=1e-4)
    # |H| = 1 gives the spectrum's own m0 (the band integration of jls.sea.measured)
    G1 = dr.response_matrix(np.ones((HEADINGS.size, omega.size)), omega, HEADINGS, efth["freq"].values,
                            efth["dir"].values, course)
    ones, _, outside = dr.response_moments(efth, G1)
    np.testing.assert_allclose(ones[:, 0], measured.spectral_moments(efth, (0,))[0].values, rtol=1e-12)
    assert outside.max() < 1e-12
    # transfer functions from 0.4 rad/s only: the energy below is reported, not counted
    cut = omega >= 0.4
    G1c = dr.response_matrix(np.ones((HEADINGS.size, cut.sum())), omega[cut], HEADINGS, efth["freq"].values,
                             efth["dir"].values, course)
    part, _, outside = dr.response_moments(efth, G1c)
    np.testing.assert_allclose(part[:, 0], ones[:, 0] * (1 - outside), rtol=1e-9)
    assert 0 < outside.max() < 0.5


def test_heading_geometry_and_symmetry():
    omega = _omega()
    P = _power(omega)
    dirs = np.array([0.0, 90.0, 180.0, 270.0])
    G = dr.response_matrix(P, omega, HEADINGS, np.array([0.05, 0.06, 0.07]), dirs, course_deg=90.0)
    # waves from dead ahead (from = course) are head seas; from 90 deg to starboard, beam seas 90
    np.testing.assert_allclose(G.headings_deg, [270.0, 180.0, 90.0, 0.0])
    # a hull's RAOs given over 0-180 serve 180-360 by symmetry
    half = HEADINGS <= 180
    Gs = dr.response_matrix(P[half], omega, HEADINGS[half], np.array([0.05, 0.06, 0.07]), dirs, 90.0,
                            symmetric=True)
    np.testing.assert_allclose(Gs.G, G.G, rtol=1e-12)
    with pytest.raises(InputError, match="one heading cannot serve"):
        dr.response_matrix(P[:1], omega, HEADINGS[:1], np.array([0.05, 0.06]), dirs, 0.0)
    with pytest.raises(InputError, match=r"spectra must be \(records, 3 frequencies, 4 directions\)"):
        dr.response_moments(np.zeros((2, 3, 5)), G)


def test_dataset_interface_with_options_and_courses():
    efth = measured.read_ndbc_spectra(fx.NDBC_DENSITY).isel(time=slice(0, 6))
    omega = _omega()
    P = np.stack([_power(omega, s) for s in (1.0, 0.5, 2.0)])              # three options
    power = xr.DataArray(P[:, None], dims=("candidate", "tugger", "heading", "omega"),
                         coords={"candidate": ["a", "b", "c"], "tugger": ["none"], "heading": HEADINGS,
                                 "omega": omega})
    course = np.array([0, 0, 0, 90, 90, 90.0])
    ds = dr.directional_moments(efth, power, course)
    assert ds["m0"].dims == ("time", "candidate", "tugger") and ds["m0"].shape == (6, 3, 1)
    for c in (0.0, 90.0):
        rows = np.flatnonzero(course == c)
        G = dr.response_matrix(P, omega, HEADINGS, efth["freq"].values, efth["dir"].values, c)
        m0, m2, _ = dr.response_moments(efth.values[rows], G)
        np.testing.assert_allclose(ds["m0"].values[rows, :, 0], m0, rtol=1e-12)
        np.testing.assert_allclose(ds["tz"].values[rows, :, 0], 2 * np.pi * np.sqrt(m0 / m2), rtol=1e-12)
    np.testing.assert_allclose(ds["sigma"].sel(candidate="c"), np.sqrt(2) * ds["sigma"].sel(candidate="a"),
                               rtol=1e-3)
    with pytest.raises(InputError, match="needs directions"):
        dr.directional_moments(measured.frequency_spectrum(efth), power, 0.0)
