"""The sea-model response of a leg (jls.stages.measured_response with the sea models of
jls.stages.sea_model_spectra): the short-crested JONSWAP reference, a JONSWAP sea given as
spread partitions has both ratios as its spreading says, Torsethaugen cells weigh by their
probability."""

import numpy as np
import pandas as pd
import pytest
from test_measured_response import LEG, _power

from jls.sea.partitions import directional_spectra
from jls.sea.sea_state import SeaState, Spreading, WaveSystem
from jls.sea.spectra import tp_from_tz
from jls.stages.measured_response import leg_response
from jls.stages.sea_model_spectra import leg_spectra

SPREAD = Spreading("cos2s", 4.0)


def _sea(spreading, hs=(1.5, 2.0, 2.5), tz=(6.0, 7.0, 8.0), d=(120.0, 105.0, 90.0)):
    states = [SeaState((WaveSystem("jonswap", h, float(tp_from_tz(t, 3.3)), x, spreading, "wind", 3.3),))
              for h, t, x in zip(hs, tz, d)]
    return directional_spectra(states, pd.date_range("2021-03-01", periods=len(states), freq="h"))


def test_a_spread_jonswap_has_the_short_crested_ratio_one_and_less_sway_than_long_crested():
    """On course 30 the waves from 120-90 deg meet the vessel at 90-120 deg: a beam sea. A
    JONSWAP spread as the reference is has the short-crested ratio 1 (the same sea twice) and
    a long-crested ratio below 1 (spreading takes sway off a beam sea)."""
    ds = leg_response(LEG, _power(), gamma=3.3, efth=_sea(SPREAD), short_crested=SPREAD)
    # within 2 %: the reference's Tz is the laid-out spectrum's Tm02 (its tail ends at 1 Hz),
    # and the sway at 15.5 s is steep in Tz (as for the long-crested reference)
    np.testing.assert_allclose(ds["sigma_ratio_short_crested"].values, 1.0, atol=2e-2)
    assert float(ds["sigma_ratio"].max()) < 0.97
    # a long-crested sea against the short-crested reference: above 1
    lc = leg_response(LEG, _power(), gamma=3.3, efth=_sea(Spreading("long-crested")), short_crested=SPREAD)
    assert float(lc["sigma_ratio_short_crested"].min()) > 1.03
    np.testing.assert_allclose(lc["sigma_ratio"].values, 1.0, atol=2e-2)


def test_torsethaugen_cells_weigh_by_their_probability(tmp_path):
    (tmp_path / "t.csv").write_text("# layout: matrix\n# hs_bins: edges\n# tz_bins: edges\n# values: counts\n"
                                    "hs\\tp,8-10,14-16\n1-2,30,10\n2-3,0,60\n")
    leg = {"name": "t", "duration_h": 3, "headings_deg": [90.0], "heading_probability": [1.0],
           "scatter": "t.csv", "period": "tp", "spectrum": "torsethaugen"}
    sea = {"spreading": {"wind": "cos2s:4", "swell": "cos2s:13"}, "hs_in_bin": "centre"}
    efth, w, cases = leg_spectra(leg, tmp_path, gamma=3.3, sea=sea)
    assert efth.sizes["time"] == 3 and w.tolist() == [0.3, 0.1, 0.6]
    ds = leg_response(leg, _power(), gamma=3.3, efth=efth, weights=w, cases=cases)
    assert "spread (wind cos2s:4, swell cos2s:13)" in ds.attrs["integration"]
    # spread about the beam, the sway is below that of the same systems long-crested
    lc = leg_spectra(leg, tmp_path, gamma=3.3, sea={**sea, "spreading": {"wind": "long-crested",
                                                                          "swell": "long-crested"}})
    lc_ds = leg_response(leg, _power(), gamma=3.3, efth=lc[0], weights=lc[1], cases=lc[2])
    assert np.all(ds["sigma_measured"].values < lc_ds["sigma_measured"].values)
    np.testing.assert_allclose(ds["heading_weight"].values[:, 0], [0.9, 0.3, 1.8])
    np.testing.assert_allclose(ds["hs"].values, [1.5, 1.5, 2.5], rtol=2e-2)
    p = ds["heading_weight"].sum("heading")
    r = (ds["sigma_measured"] * p).sum("time") / (ds["sigma_jonswap"] * p).sum("time")
    np.testing.assert_allclose(ds["sigma_ratio"].values, r.values)
    with pytest.raises(Exception, match="sea block"):
        leg_spectra(leg, tmp_path, gamma=3.3, sea=None)
    assert leg_spectra({**leg, "headings_deg": [0.0], "heading_probability": [1.0]}, tmp_path, gamma=3.3,
                       sea=sea)[2][0][0][0]["dir"].size == 36
