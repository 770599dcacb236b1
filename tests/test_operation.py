"""Operational basis (DNV-ST-N001): the class of an operation by its planned period and
reference period, and the forecast limits OP_WF = alpha OP_LIM."""

import numpy as np
import pytest
import xarray as xr

from jls.assessment.operation import RESTRICTED, UNRESTRICTED, AlphaTable, classify, forecast_limits
from jls.errors import InputError


@pytest.mark.parametrize("planned, contingency, expected", [
    (24.0, 24.0, RESTRICTED),          # T_R 48 h
    (72.0, 24.0, RESTRICTED),          # both at their limits
    (72.0, 24.1, UNRESTRICTED),        # T_R just above 96 h
    (72.1, 0.0, UNRESTRICTED),         # T_POP above 72 h
    (125.0, None, UNRESTRICTED),       # the default route's transit
    (48.0, None, RESTRICTED),
])
def test_class_follows_the_planned_and_reference_periods(planned, contingency, expected):
    b = classify(planned, contingency)
    assert b.operation_class == expected
    assert b.reference_h == planned + (contingency or 0.0)
    assert ("lower bound" in b.reason) == (contingency is None)


def test_a_non_positive_period_is_refused():
    with pytest.raises(InputError, match="operation.planned_period_h"):
        classify(0.0, 1.0)


TABLE = AlphaTable(source="constructed for the test", period_h=[12.0, 48.0], hs_m=[1.0, 4.0],
                   alpha=[[0.8, 0.9], [0.6, 0.7]])


def test_alpha_interpolates_in_period_and_hs_and_holds_at_the_hs_ends():
    assert TABLE.factor(12.0, 1.0) == pytest.approx(0.8)
    assert TABLE.factor(30.0, 1.0) == pytest.approx(0.7)             # half way in period
    assert TABLE.factor(30.0, 2.5) == pytest.approx(0.75)            # and in Hs
    assert TABLE.factor(48.0, 10.0) == pytest.approx(0.7)            # held above the table
    with pytest.raises(InputError, match="outside the alpha table"):
        TABLE.factor(60.0, 2.0)


def test_forecast_limit_is_alpha_times_the_operational_limit_when_restricted():
    oplim = xr.DataArray([[1.0, 4.0], [2.5, np.nan]], dims=("heading", "tz"))
    restricted = forecast_limits(oplim, classify(30.0, 0.0), TABLE)
    np.testing.assert_allclose(restricted["hs_opwf"].values,
                               [[0.7 * 1.0, 0.8 * 4.0], [0.75 * 2.5, np.nan]])
    assert "hs_opwf" not in forecast_limits(oplim, classify(30.0, 0.0), None)      # no table
    assert "hs_opwf" not in forecast_limits(oplim, classify(125.0, 0.0), TABLE)    # unrestricted


@pytest.mark.parametrize("kw, field", [
    (dict(alpha=[[0.8, 0.9]]), "alpha_factors.alpha"),
    (dict(alpha=[[0.8, 1.2], [0.6, 0.7]]), "alpha_factors.alpha"),
    (dict(hs_m=[4.0, 1.0]), "alpha_factors.hs_m"),
])
def test_a_malformed_alpha_table_names_its_field(kw, field):
    args = dict(source="x", period_h=[12.0, 48.0], hs_m=[1.0, 4.0], alpha=[[0.8, 0.9], [0.6, 0.7]])
    with pytest.raises(InputError, match=field):
        AlphaTable(**{**args, **kw})
