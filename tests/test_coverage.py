"""Sea-state energy outside the RAO range: zero motion only in a stated band."""

import numpy as np
import pytest

from jls.errors import InputError
from jls.response.coverage import ENERGY_OUTSIDE_LIMIT, check_coverage, coverage, describe, zero_bands
from jls.response.statistics import energy_outside

ABOVE_3 = {"zero_above_rad_s": 3.0, "reason": "waves shorter than 7 m against a 382 m hull"}


def test_band_above_the_rao_range_explains_the_short_waves():
    # RAOs to 3 rad/s: a Tz = 3 s sea has several % of its energy above; stated, it passes
    # and the zeroed fraction is returned.
    frac = check_coverage(0.1, 3.0, [3.0, 14.0], 3.3, ABOVE_3)
    assert frac[0] == pytest.approx(energy_outside(0.1, 3.0, [3.0])[0]) and frac[0] > 0.01
    assert frac[1] < ENERGY_OUTSIDE_LIMIT
    with pytest.raises(InputError, match=r"Tz = 3 s.*no zero-motion band stated"):
        check_coverage(0.1, 3.0, [3.0, 14.0], 3.3, None)


def test_truncated_rao_is_an_error_despite_a_stated_band():
    # A WAMIT file cut at 1.2 rad/s: the band starts at 3 rad/s, the gap 1.2-3 is not
    # explained, so a Tz = 5 s sea state stops the run.
    zeroed, unexplained = coverage(0.1, 1.2, [5.0], 3.3, ABOVE_3)
    gap = energy_outside(0.1, 1.2, [5.0])[0] - energy_outside(0.0, 3.0, [5.0])[0]
    assert unexplained[0] == pytest.approx(gap, rel=1e-6) and unexplained[0] > 0.05
    with pytest.raises(InputError, match=r"vessel\.outside_rao_range.*Tz = 5 s.*outside the RAO"):
        check_coverage(0.1, 1.2, [5.0], 3.3, ABOVE_3)


@pytest.mark.parametrize("lo, hi, tz, what", [
    (2.0, 60.0, [8.0], "RAO periods 2-60 s read as rad/s"),
    (0.1 / (2 * np.pi), 3.0 / (2 * np.pi), [8.0], "RAO frequencies in Hz read as rad/s"),
    (0.1, 3.0, [80.0], "Tz of 8 s written in tenths of a second"),
])
def test_unit_slips_put_the_energy_outside(lo, hi, tz, what):
    zeroed, unexplained = coverage(lo, hi, tz, 3.3, ABOVE_3)
    assert unexplained[0] > 0.5, what
    with pytest.raises(InputError, match="outside the RAO range"):
        check_coverage(lo, hi, tz, 3.3, ABOVE_3)


def test_band_below_the_range():
    policy = {"zero_below_rad_s": 0.3, "reason": "swell longer than this never occurs here"}
    assert zero_bands(policy) == (0.3, np.inf)
    # RAOs from 0.3 rad/s: a long swell Tz = 18 s is partly below; stated, it passes.
    assert check_coverage(0.3, 3.0, [18.0], 3.3, policy)[0] > ENERGY_OUTSIDE_LIMIT
    with pytest.raises(InputError):
        check_coverage(0.3, 3.0, [18.0], 3.3, None)


@pytest.mark.parametrize("policy, match", [
    ("zero", "no longer accepted"),
    ({"zero_above_rad_s": 3.0}, "needs a reason"),
    ({"reason": "no band at all here"}, "zero_above_rad_s"),
    ({"zero_above_rad_s": 0.5, "zero_below_rad_s": 0.8, "reason": "crossed band"}, "below"),
])
def test_bad_policies_are_named(policy, match):
    with pytest.raises(InputError, match=match):
        zero_bands(policy, source="cfg.yaml")


def test_description_states_band_and_reason():
    assert describe(None).startswith("none: sea states with more than 0.1 %")
    assert describe(ABOVE_3) == "zero motion above 3 rad/s: " + ABOVE_3["reason"]
