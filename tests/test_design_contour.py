"""The class of each stretch of a route and the unrestricted design check: a leg over
72 h named, the IFORM contour of a fitted model against its closed form, the design
level on a one-cell table against a hand calculation, both verdicts."""

import numpy as np
import pytest
import xarray as xr
from scipy.special import ndtr, ndtri
from scipy.stats import exponweib

from jls.assessment.design_contour import contours, design_check, fit, reliability_index, verdict
from jls.assessment.operation import RESTRICTED, UNRESTRICTED, stretch_classes
from jls.errors import InputError


def test_a_leg_over_72_h_is_named_and_must_be_split():
    st = stretch_classes(["north", "south"], [50.0, 75.0], [True, True], [None, None])
    assert [s.basis.operation_class for s in st] == [RESTRICTED, UNRESTRICTED]
    assert "leg south (75 h) is longer than 72 h" in st[1].statement
    assert "must be split at a hold point" in st[1].statement
    assert st[0].statement == ""
    # without the hold point the route is one 125-h stretch
    (one,) = stretch_classes(["north", "south"], [50.0, 75.0], [True, False], [None, None])
    assert one.basis.operation_class == UNRESTRICTED and "needs a hold point between" in one.statement


def test_contingency_decides_the_reference_period():
    a, b = stretch_classes(["a", "b"], [50.0, 70.0], [True, True], [10.0, 30.0])
    assert a.restricted and a.basis.reference_h == 60.0
    assert not b.restricted and "T_R 100 h > 96 h" in b.basis.reason


def test_reliability_index_of_ten_years_of_three_hour_sea_states():
    beta = reliability_index(10.0, 3.0)
    assert beta == pytest.approx(ndtri(1 - 3.0 / (10 * 8766.0)))
    assert 3.9 < beta < 4.1
    # a season of three months: a quarter of the sea states, a lower index
    assert reliability_index(10.0, 3.0, 0.25) < beta


def test_fit_recovers_a_known_model_and_its_contour():
    rng = np.random.default_rng(5)
    lam, k, a = 1.1, 1.4, 1.6
    hs = exponweib.rvs(a, k, scale=lam, size=60_000, random_state=rng)
    c, d, s = 3.5, 1.6, 0.1
    tz = (c + d * np.sqrt(hs)) * np.exp(rng.normal(0.0, s, hs.size))
    m = fit(hs, tz)
    beta = 3.0
    want = exponweib.ppf(ndtr(beta), a, k, scale=lam)
    hs_c, tz_c = m.contour(beta, 360)
    assert hs_c.max() == pytest.approx(want, rel=0.05)
    assert m.d == pytest.approx(d, rel=0.1) and m.s == pytest.approx(s, rel=0.15)
    # at the largest Hs the period is the conditional median
    i = int(np.argmax(hs_c))
    assert tz_c[i] == pytest.approx(c + d * np.sqrt(hs_c[i]), rel=0.05)


def test_no_sea_state_is_an_error_naming_the_file():
    with pytest.raises(InputError, match="leg.csv"):
        fit([0.0], [5.0], source="leg.csv")


def unit_stats(mpm_per_m, tz=(4.0, 6.0, 8.0, 10.0)):
    """Unit statistics of two options (a, b) and two criteria at one heading."""
    mpm = np.array(mpm_per_m, float)[:, :, None, None] * np.ones((1, 1, 1, len(tz)))
    mpm[..., 2] *= 1.5                                   # a peak at Tz 8 s
    dims = ("candidate", "criterion", "heading", "tz")
    return xr.Dataset({"mpm": (dims, mpm), "sigma": (dims, mpm / 3.0),
                       "tz_response": (dims, np.full(mpm.shape, 10.0))},
                      coords={"candidate": ["a", "b"], "criterion": ["sway", "roll"],
                              "heading": [90.0], "tz": list(tz)})


def test_one_cell_table_design_level_by_hand():
    # a table whose every sea state is Hs 2.5 m, Tz 7 s: the contour is that sea state,
    # and the design MPM is Hs times the unit MPM interpolated at 7 s
    m = fit([2.5], [7.0], [1.0])
    c = contours({"only": m}, reliability_index(10.0, 3.0))
    assert np.allclose(c["contour_hs"], 2.5) and np.allclose(c["contour_tz"], 7.0)
    stats = unit_stats([[1.0, 0.3], [0.5, 0.1]])
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["only"], "heading": [90.0]})
    limit = xr.DataArray([3.0, 1.0], dims="criterion", coords={"criterion": ["sway", "roll"]})
    d = design_check(stats, c, hp, limit)
    # unit sway MPM at 7 s: midway between 1.0 (6 s) and 1.5 (8 s) = 1.25 per m
    sway_a = 2.5 * 1.25
    assert float(d["design_level"].sel(candidate="a", criterion="sway", leg="only")) == pytest.approx(sway_a)
    assert float(d["design_utilisation"].sel(candidate="a", criterion="sway", leg="only")) == \
        pytest.approx(sway_a / 3.0)
    roll_a = 2.5 * 0.3 * 1.25
    assert float(d["design_utilisation"].sel(candidate="a", criterion="roll", leg="only")) == pytest.approx(roll_a)
    ok = verdict(d)
    assert not bool(ok.sel(candidate="a"))          # 3.125 m against 3 m: not acceptable
    assert bool(ok.sel(candidate="b"))              # half of it: acceptable
    assert float(d["design_hs"].sel(candidate="a", criterion="sway", leg="only")) == 2.5


def test_design_point_is_the_worst_on_the_contour():
    m = fit(*np.meshgrid([1.0, 2.0, 3.0], [5.0, 7.0, 9.0]), weight=np.ones((3, 3)))
    c = contours({"leg": m}, 2.5)
    stats = unit_stats([[1.0, 0.3], [0.5, 0.1]])
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["leg"], "heading": [90.0]})
    limit = xr.DataArray([3.0, 1.0], dims="criterion", coords={"criterion": ["sway", "roll"]})
    d = design_check(stats, c, hp, limit)
    lvl = float(d["design_level"].sel(candidate="a", criterion="sway", leg="leg"))
    hs, tz = c["contour_hs"].values[0], c["contour_tz"].values[0]
    unit = np.interp(np.clip(tz, 4, 10), [4, 6, 8, 10], [1.0, 1.0, 1.5, 1.0])
    assert lvl == pytest.approx(float(np.max(hs * unit)))
