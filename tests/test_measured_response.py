"""The measured-spectrum response of a spectra leg (jls.stages.measured_response): a
JONSWAP given as "measured" has the ratio 1 against the pipeline's JONSWAP on the same
(Hs, Tz); swell at the sway period raises it; the cases of a leg (course, given headings)."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from jls.sea import directional, spectra
from jls.sea.headings import hour_headings
from jls.sea.measured import spectra_array
from jls.stages.measured_response import leg_response

T_SWAY, ZETA = 15.5, 0.01
W_N = 2 * np.pi / T_SWAY
HEADINGS = np.arange(0.0, 360.0, 15.0)


def _power():
    omega = np.union1d(np.arange(0.1, 3.0, 0.002), W_N + np.arange(-0.02, 0.02, 2 * ZETA * W_N / 6))
    r = omega / W_N
    h2 = r**4 / ((1 - r**2) ** 2 + (2 * ZETA * r) ** 2)
    P = np.sin(np.radians(HEADINGS))[:, None] ** 2 * h2[None, :] + 1e-3 * h2[None, :]
    P = np.stack([np.stack([P, 0.5 * P])])                  # (candidate 1, tugger 2, h, w)
    return xr.DataArray(P, dims=("candidate", "tugger", "heading", "omega"),
                        coords={"candidate": ["baseline"], "tugger": ["none", "half"],
                                "heading": HEADINGS, "omega": omega})


def _efth(E, n=3):
    times = pd.date_range("2019-02-06", periods=n, freq="h").values
    # fine bands over the sway resonance, coarse ones in the tail (its m2 sets Tm02)
    freq = np.concatenate([np.arange(0.016, 0.3, 0.0005), np.arange(0.3, 1.5, 0.005)])
    vals = np.stack([E(freq, k) for k in range(n)])
    return spectra_array(vals, times, freq, directional.DEFAULT_DIRS, attrs={"source": "synthetic"})


def _jonswap_e(freq, hs, tz, from_deg):
    tp = float(spectra.tp_from_tz(tz, 3.3))
    return (spectra.jonswap(2 * np.pi * freq, hs, tp) * 2 * np.pi)[:, None] * \
        directional.long_crested(directional.DEFAULT_DIRS, from_deg)[None, :]


# a course leg whose relative headings come from its own directions (as jls.config.headings
# resolves them): directions 120, 105, 90 deg on course 30 meet the vessel at 90, 105, 120 deg
LEG = {"name": "spec", "duration_h": 3, "course_deg": 30.0, "heading_source": "direction_table",
       "headings_deg": [90.0, 105.0, 120.0], "heading_probability": [1 / 3, 1 / 3, 1 / 3],
       "spectra": {"file": "x", "format": "ndbc", "dir_edges_deg": list(np.arange(-7.5, 353, 15.0))}}


def test_each_hour_is_met_at_the_heading_of_its_own_mean_direction():
    """heading_weight bins each hour's mean direction as the leg's sea states bin it: on
    course 30 deg, waves from 120, 105 and 90 deg meet the vessel at 90, 105 and 120 deg."""
    efth = _efth(lambda f, k: _jonswap_e(f, 1.5 + k, 6.0 + k, 120.0 - 15 * k))
    ds = leg_response(LEG, _power(), gamma=3.3, efth=efth)
    np.testing.assert_array_equal(ds["heading_weight"].values, np.eye(3))
    # a leg with given headings: every hour at the leg's heading probabilities
    given = {"name": "spec", "duration_h": 3, "headings_deg": [90.0, 180.0], "heading_probability": [0.25, 0.75],
             "spectra": {"file": "x", "format": "ndbc"}}
    np.testing.assert_allclose(hour_headings(given, [10.0, np.nan]), [[0.25, 0.75], [0.25, 0.75]])
    # a direction outside the leg's direction bins (or unknown) is met at no heading
    part = dict(LEG, spectra=dict(LEG["spectra"], dir_edges_deg=[80.0, 130.0]))
    np.testing.assert_array_equal(hour_headings(part, [120.0, 200.0, np.nan]).sum(1), [1.0, 0.0, 0.0])


def test_a_jonswap_given_as_measured_has_the_ratio_one():
    efth = _efth(lambda f, k: _jonswap_e(f, 1.5 + k, 6.0 + k, 120.0 - 15 * k))
    ds = leg_response(LEG, _power(), gamma=3.3, efth=efth)
    np.testing.assert_allclose(ds["hs"].values, [1.5, 2.5, 3.5], rtol=1e-3)
    # within 1.5 %: the sampled spectrum's Tm02 (its tail ends at 1.5 Hz) is the reference's
    # Tz, and the sway at 15.5 s is steep in Tz
    np.testing.assert_allclose(ds["sigma_measured"].values, ds["sigma_jonswap"].values, rtol=1.5e-2)
    np.testing.assert_allclose(ds["sigma_ratio"].values, 1.0, atol=1e-2)
    # the ratio is the ratio of the sums over the hours
    r = ds["sigma_measured"].sum("time") / ds["sigma_jonswap"].sum("time")
    np.testing.assert_allclose(ds["sigma_ratio"].values, r.values)
    assert int(ds["hours"]) == 3 and "course 30 deg" in ds.attrs["integration"]


def test_swell_at_the_sway_period_raises_the_ratio():
    def sea(f, k):
        return _jonswap_e(f, 1.5, 6.0, 120.0)

    def sea_swell(f, k):
        tp = 15.5
        sw = (spectra.jonswap(2 * np.pi * f, 0.8, tp, 5.0) * 2 * np.pi)[:, None] * \
            directional.long_crested(directional.DEFAULT_DIRS, 120.0)[None, :]
        return sea(f, k) + sw
    base = leg_response(LEG, _power(), gamma=3.3, efth=_efth(sea, 1))
    swell = leg_response(LEG, _power(), gamma=3.3, efth=_efth(sea_swell, 1))
    assert float(base["sigma_ratio"].sel(tugger="none").squeeze()) == pytest.approx(1.0, abs=5e-3)
    # the combined (Hs, Tm02) JONSWAP puts little energy at 15.5 s: the ratio far above 1
    assert float(swell["sigma_ratio"].sel(tugger="none").squeeze()) > 1.5


def test_without_a_course_the_spectrum_is_long_crested_at_the_given_headings():
    efth = _efth(lambda f, k: _jonswap_e(f, 2.0, 7.0, 0.0), 2)
    leg = {"name": "spec", "duration_h": 3, "headings_deg": [90.0, 180.0], "heading_probability": [0.25, 0.75],
           "spectra": {"file": "x", "format": "ndbc"}}
    ds = leg_response(leg, _power(), gamma=3.3, efth=efth)
    one = {h: leg_response({**leg, "headings_deg": [h], "heading_probability": [1.0]}, _power(),
                           gamma=3.3, efth=efth) for h in (90.0, 180.0)}
    np.testing.assert_allclose(ds["sigma_measured"].values, 0.25 * one[90.0]["sigma_measured"].values
                               + 0.75 * one[180.0]["sigma_measured"].values)
    np.testing.assert_allclose(ds["sigma_ratio"].values, 1.0, atol=5e-3)
    assert "directions not used" in ds.attrs["integration"]
