"""Response of directional sea states of several systems (jls.response.sea_state): the
long-crested limit is the pipeline's long-crested response, systems add their variances, a
swell at the sway period adds what the transfer function predicts, and a spread sea agrees
with the measured-spectrum machinery (jls.response.directional) on the same E(f, theta)."""

import numpy as np
import pytest
import xarray as xr

from jls.errors import InputError
from jls.names import RESPONSES
from jls.response.directional import directional_moments
from jls.response.moments import unit_moments
from jls.response.sea_state import (
    cross_spectra,
    equivalent_excitations,
    sea_state_moments,
    sea_state_statistics,
    sea_state_transfer,
)
from jls.response.solver import relative_power
from jls.response.statistics import trapezoid_weights
from jls.sea.headings import rao_grid
from jls.sea.sea_state import SeaState, Spreading, WaveSystem, wave_system
from jls.sea.spectra import tp_from_tz
from jls.stages.plant import plant as plant_of
from jls.stages.vessel_motion import vessel_motion

TUGGERS = {"none": 0.0, "reference": 1000.0}
LONG = Spreading("long-crested")


@pytest.fixture(scope="module")
def tr(cfg):
    plant = plant_of(cfg)
    motion = vessel_motion(cfg["vessel"], rao_grid(np.arange(0.0, 181.0, 15.0)), base_dir=".")
    return sea_state_transfer(plant, motion, TUGGERS, cfg["response"]["omega_step_rad_s"],
                              cfg["vessel"]["outside_rao_range"])


def _jonswap(hs, tz, from_deg, spreading=LONG, kind="wind"):
    return WaveSystem("jonswap", hs, float(tp_from_tz(tz, 3.3)), from_deg, spreading, kind, 3.3)


@pytest.mark.parametrize("course, from_deg, beta", [(0.0, 90.0, 90.0), (200.0, 245.0, 135.0), (10.0, 160.0, 30.0)])
def test_long_crested_limit_equals_the_pipelines_long_crested_response(tr, course, from_deg, beta):
    hs, tz = 2.0, 8.0
    m0, m2 = sea_state_moments(tr, [[_jonswap(hs, tz, from_deg)]], course)
    u0, u2, _ = unit_moments(tr.plant, tr.exc, [tz], list(TUGGERS.values()), 3.3)
    i = int(np.argmin(np.abs(tr.exc.headings - beta)))
    assert tr.exc.headings[i] == beta
    np.testing.assert_allclose(m0[0], hs**2 * u0[:, :, i, :, 0], rtol=1e-6)
    np.testing.assert_allclose(m2[0], hs**2 * u2[:, :, i, :, 0], rtol=1e-6)


def test_two_systems_give_the_sum_of_their_variances(tr):
    wind = _jonswap(2.0, 6.0, 30.0, Spreading("cos2s", 4.0))
    swell = _jonswap(1.0, 12.0, 100.0, Spreading("cos2s", 13.0), "swell")
    m0, m2 = sea_state_moments(tr, [[wind, swell], [wind], [swell]], 0.0)
    np.testing.assert_allclose(m0[0], m0[1] + m0[2], rtol=1e-9)
    np.testing.assert_allclose(m2[0], m2[1] + m2[2], rtol=1e-9)


def test_a_swell_at_the_sway_period_raises_sigma_as_the_transfer_function_predicts(tr):
    """sigma^2 of wind + swell = sigma^2 of the wind sea + int |H(omega, 90)|^2 S_swell domega,
    with |H|^2 from the solver at the beam heading itself; and a swell peaking at the sway
    period drives far more sway than the same swell at 8 s."""
    t_sway = float(tr.plant["natural_period"].values[0, 0])
    wind = _jonswap(1.5, 5.0, 90.0)
    swell = WaveSystem("jonswap", 0.5, t_sway, 90.0, LONG, "swell", 5.0)
    ds = sea_state_statistics(tr, [[wind], [wind, swell]], 0.0)
    i = list(tr.exc.headings).index(90.0)
    p = tr.plant
    P = relative_power(p["M"].values, p["K"].values, p["Kb"].values, p["C"].values, tr.exc.omega,
                       tr.exc.qb[i:i + 1], tr.exc.fairlead_sway[i:i + 1], list(TUGGERS.values()))[:, :, 0]
    predicted = P @ (trapezoid_weights(tr.exc.omega) * swell.spectrum(tr.exc.omega))   # (c, t, 4)
    sway = RESPONSES.index("relative_sway")
    s0 = ds["sigma"].isel(sea_state=0).values[..., sway]
    s1 = ds["sigma"].isel(sea_state=1).values[..., sway]
    np.testing.assert_allclose(s1**2, s0**2 + predicted[..., sway], rtol=1e-9)
    assert s1[0, 0] > 2 * s0[0, 0]                          # a 0.5 m swell doubles it at least
    off = WaveSystem("jonswap", 0.5, 8.0, 90.0, LONG, "swell", 5.0)
    s_off = sea_state_statistics(tr, [[wind, off]], 0.0)["sigma"].values[0, 0, 0, sway]
    assert s1[0, 0] > 2 * s_off


def test_a_spread_sea_agrees_with_the_measured_spectrum_integration(tr):
    """The same short-crested sea given as E(f, theta) on 10-deg bins to the measured-spectrum
    machinery (|H|^2 interpolated in heading there too) gives the same sway sigma."""
    sys = _jonswap(2.0, 9.0, 60.0, Spreading("cos2s", 6.0))
    ds = sea_state_statistics(tr, [[sys]], 340.0)
    dirs, w = sys.directions()
    order = np.argsort(dirs)
    freq = np.arange(0.02, 0.47, 0.0005)
    E = (2 * np.pi * sys.spectrum(2 * np.pi * freq))[:, None] * (w[order] / 10.0)[None, :]
    efth = xr.DataArray(E[None], dims=("time", "freq", "dir"),
                        coords={"time": [np.datetime64("2020-01-01T00")], "freq": freq, "dir": dirs[order]})
    p = tr.plant
    P = relative_power(p["M"].values, p["K"].values, p["Kb"].values, p["C"].values, tr.exc.omega,
                       tr.exc.qb, tr.exc.fairlead_sway, list(TUGGERS.values()))[:, :, :, 0]
    power = xr.DataArray(P, dims=("candidate", "tugger", "heading", "omega"),
                         coords={"heading": tr.exc.headings, "omega": tr.exc.omega})
    ref = directional_moments(efth, power, 340.0)["sigma"].values[0]
    np.testing.assert_allclose(ds["sigma"].values[0, :, :, 0], ref, rtol=2e-3)
    # and spreading takes sway off a beam sea
    lc = sea_state_statistics(tr, [[_jonswap(2.0, 9.0, 70.0)]], 340.0)["sigma"].values[0, 0, 0, 0]
    assert ds["sigma"].values[0, 0, 0, 0] < lc


def test_equivalent_excitations_reproduce_the_cross_spectral_matrix(tr):
    sea = [_jonswap(2.0, 6.0, 30.0, Spreading("cos2s", 4.0)), _jonswap(1.0, 12.0, 100.0, Spreading("cosn", 8.0))]
    Q = cross_spectra(tr, [sea], 15.0)
    qb, yf = equivalent_excitations(Q)
    x = np.concatenate([qb, yf[..., None]], axis=-1)[0]           # (K, n_w, 5)
    back = np.einsum("kwi,kwj->wij", x, x.conj())
    np.testing.assert_allclose(back, Q[0], atol=1e-12 * np.abs(Q).max())
    # a long-crested sea has one equivalent excitation
    assert equivalent_excitations(cross_spectra(tr, [[_jonswap(1.0, 7.0, 90.0)]], 0.0))[0].shape[1] == 1


def test_statistics_are_those_of_the_moments_and_energy_outside_is_refused(tr):
    ds = sea_state_statistics(tr, [SeaState((_jonswap(2.0, 8.0, 90.0),))], 0.0, exposure_h=3.0)
    sig, tz, mpm = (ds[k].values[0, 0, 0, 0] for k in ("sigma", "tz_response", "mpm"))
    m0, m2 = ds["m0"].values[0, 0, 0, 0], ds["m2"].values[0, 0, 0, 0]
    assert sig == pytest.approx(np.sqrt(m0)) and tz == pytest.approx(2 * np.pi * np.sqrt(m0 / m2))
    assert mpm == pytest.approx(sig * np.sqrt(2 * np.log(3 * 3600 / tz)))
    assert ds["criterion"].values.tolist()[0] == "relative_sway_m"
    # a swell of 40 s lies mostly below the RAOs' 0.1 rad/s: refused, naming the setting
    far = wave_system("jonswap", 1.0, "tp", 90.0, gamma=3.3, from_deg=0, spreading="long")
    with pytest.raises(InputError, match="outside the RAO range"):
        sea_state_statistics(tr, [[far]], 0.0)


def test_the_system_table_gives_the_hours_what_the_direct_integration_gives(tr):
    """Hours of two spread systems from the table (Tp interpolated on a 0.05 s grid) against
    sea_state_moments of the same hours: within 0.3 % on every response; exactly at grid Tps."""
    from jls.response.system_table import hourly_moments, system_table
    table = system_table(tr, np.arange(4.0, 20.0001, 0.05), 3.3)
    wind, swell = Spreading("cos2s", 4.0), Spreading("cos2s", 13.0)
    hs_w, tp_w, d_w = np.array([1.0, 1.5, 2.0]), np.array([6.0, 7.23, 8.51]), np.array([10.0, 95.0, 300.0])
    hs_s, tp_s, d_s = np.array([0.8, 0.0, 1.2]), np.array([14.0, 15.0, 15.77]), np.array([100.0, 0.0, 250.0])
    course = np.array([0.0, 200.0, 35.0])
    m0, m2 = hourly_moments(table, [(hs_w, tp_w, d_w, wind), (hs_s, tp_s, d_s, swell)], course)
    for k in range(3):
        systems = [WaveSystem("jonswap", hs_w[k], tp_w[k], d_w[k], wind, "wind", 3.3)]
        if hs_s[k] > 0:
            systems.append(WaveSystem("jonswap", hs_s[k], tp_s[k], d_s[k], swell, "swell", 3.3))
        r0, r2 = sea_state_moments(tr, [systems], course[k])
        tol = 1e-9 if k == 0 else 3e-3                     # hour 0: both Tps on the grid
        np.testing.assert_allclose(m0[k], r0[0], rtol=tol)
        np.testing.assert_allclose(m2[k], r2[0], rtol=tol)
