"""The weather windows use the alpha of the master's table (issue 34, Build item 5): with
the operation's alpha table (``operation.alpha_factors``) an hour is workable when its Hs
is at most OP_WF = alpha OP_LIM, alpha read at the hour's limiting Hs and the planned
period of the leg's stretch, exactly as the voyage plan's forecast utilisation reads it;
the constant alpha and the table together are an error; the report states which alpha."""

import numpy as np
import pytest
from test_windows import hindcast, one, stats, unit

from jls.assessment.operation import AlphaTable
from jls.assessment.voyage_plan import forecast_utilisation
from jls.assessment.windows import leg_windows
from jls.errors import InputError
from jls.stages.weather_windows import operational_alpha

TABLE = {"source": "DNV-ST-N001 (2021) table 4-4, level B", "planned_period_h": [12.0, 24.0, 48.0, 72.0],
         "hs_m": [1.0, 2.0, 4.0, 6.0],
         "alpha": [[0.80, 0.84, 0.88, 0.92], [0.76, 0.80, 0.84, 0.88],
                   [0.70, 0.74, 0.78, 0.82], [0.64, 0.68, 0.72, 0.76]]}


def table():
    return AlphaTable(source=TABLE["source"], period_h=TABLE["planned_period_h"], hs_m=TABLE["hs_m"],
                      alpha=TABLE["alpha"])


def test_an_hour_is_workable_exactly_when_the_voyage_plan_would_start_on_it():
    # OP_LIM is 3 m (sway 1 m per m Hs against 3 m); Hs sweeps 2.0-3.2 m: alpha at OP_LIM
    # 3 m and 30 h lies between the table's rows, so OP_WF is not a round number
    hs = np.linspace(2.0, 3.2, 121)
    ds = leg_windows(hindcast(hs), unit(stats()), 1.0, alpha_factors=table(), planned_h=30.0)
    flag = one(ds, "workable_hourly")
    # the voyage plan's forecast utilisation of the same hours (its own function)
    fc = forecast_utilisation((hs / 3.0)[None, None, :], hs[None, :], [30.0], table())[0, 0]
    np.testing.assert_array_equal(flag == 1, fc <= 1.0)
    # independently: OP_WF = alpha(30 h, 3 m) x 3 m, alpha interpolated by hand
    a = np.interp(30.0, [24.0, 48.0], [np.interp(3.0, [2.0, 4.0], [0.80, 0.84]),
                                       np.interp(3.0, [2.0, 4.0], [0.74, 0.78])])
    assert a == pytest.approx(0.805)
    np.testing.assert_array_equal(flag == 1, hs <= a * 3.0 + 1e-12)
    assert 0 < flag.sum() < hs.size                           # both verdicts occur
    # a table of one constant alpha is the constant: the same flags
    const = AlphaTable(source="constant", period_h=[1.0, 100.0], hs_m=[0.5, 10.0], alpha=[[0.8, 0.8], [0.8, 0.8]])
    np.testing.assert_array_equal(
        one(leg_windows(hindcast(hs), unit(stats()), 1.0, alpha_factors=const, planned_h=30.0), "workable_hourly"),
        one(leg_windows(hindcast(hs), unit(stats()), 1.0, alpha=0.8), "workable_hourly"))


def test_the_table_and_a_constant_alpha_together_are_an_error():
    with pytest.raises(InputError, match="two alphas") as e:
        leg_windows(hindcast(np.ones(10)), unit(stats()), 1.0, alpha=0.9, alpha_factors=table(), planned_h=30.0)
    assert "weather_windows.alpha" in str(e.value)


def test_the_windows_read_alpha_at_the_stretch_the_voyage_plan_reads_it_at():
    legs = [{"name": "a", "duration_h": 10.0, "hold_point": False}, {"name": "b", "duration_h": 20.0, "hold_point": False},
            {"name": "c", "duration_h": 30.0, "hold_point": True}]
    t, periods = operational_alpha(legs, {"alpha_factors": TABLE, "contingency_h": 6.0})
    assert t.source == TABLE["source"]
    assert periods == {"a": 30.0, "b": 30.0, "c": 30.0}       # two stretches of 30 h each
    one_stretch, p1 = operational_alpha(legs[:2], {"alpha_factors": TABLE, "contingency_h": 6.0})
    assert p1 == {"a": 30.0, "b": 30.0}
    none, _ = operational_alpha(legs, {})
    assert none is None
