"""Criterion sensitivity: workability over trial limits without re-solving."""

import numpy as np
import pytest
from test_uncertainty import config_plant, route_sea, unit_stats
from test_workability import tiny_response
from test_workability_tension import sea as tension_sea
from test_workability_tension import with_tension

from jls.assessment.criterion_sweep import criterion_sensitivity
from jls.assessment.workability import assess
from jls.errors import InputError

TZ = [6.5, 7.5, 8.5, 9.5]


def test_route_workability_is_monotone_in_the_sway_limit_and_matches_assess():
    stats = unit_stats(config_plant(), TZ, tuggers=(0.0, 1000.0))
    sea = route_sea(TZ)
    limits = np.arange(2.0, 4.01, 0.25)
    ds = criterion_sensitivity(stats, sea, {"relative_sway_m": 3.0}, limits=limits)
    route = ds["workability_route"]
    assert route.dims == ("candidate", "tugger", "trial_limit")
    assert float(route.diff("trial_limit").min()) >= 0.0
    assert float(route.diff("trial_limit").max()) > 0.0
    for value in (2.5, 3.0, 3.75):
        direct = assess(stats, sea, {"relative_sway_m": value})["workability_route"]
        np.testing.assert_allclose(route.sel(trial_limit=value).transpose(*direct.dims).values,
                                   direct.values, rtol=1e-12)
    assert ds["trial_limit"].attrs["units"] == "m"


def test_other_criteria_keep_their_limits_and_tension_limits_sweep_both_ways():
    resp = with_tension(tiny_response([1.0, 2.0], [0.5, 0.5]), [500, 800, 500, 800],
                        [1000, 2000, 1000, 2000])
    sea = tension_sea()
    # A tight yaw limit caps the workability whatever the sway limit.
    capped = criterion_sensitivity(resp, sea, {"relative_sway_m": 3.0, "relative_yaw_deg": 0.3},
                                   limits=[2.0, 3.0, 10.0])
    direct = assess(resp, sea, {"relative_sway_m": 10.0, "relative_yaw_deg": 0.3})
    assert capped["workability_route"].sel(trial_limit=10.0).item() == pytest.approx(
        direct["workability_route"].item())
    swl = criterion_sensitivity(resp, sea, {"relative_sway_m": 30.0}, "max_wire_tension_kN",
                                limits=[20500.0, 21000.0, 21500.0, 23000.0])
    assert float(swl["workability_route"].diff("trial_limit").min()) >= 0.0
    assert float(swl["workability_route"].diff("trial_limit").max()) > 0.0
    floor = criterion_sensitivity(resp, sea, {"relative_sway_m": 30.0}, "min_wire_tension_kN",
                                  limits=[12000.0, 15000.0, 16000.0, 16900.0])
    assert float(floor["workability_route"].diff("trial_limit").max()) <= 0.0
    assert float(floor["workability_route"].diff("trial_limit").min()) < 0.0
    with pytest.raises(InputError, match="unknown criterion"):
        criterion_sensitivity(resp, sea, {"relative_sway_m": 3.0}, "clearance_m")
