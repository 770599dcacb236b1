"""Tugger loads in the fast solver path, winch saturation in the workability, time-domain
verdicts replacing cells, and the recommendation's exclusion of saturating settings."""

import numpy as np
import pytest
import xarray as xr

from jls.assessment.recommendation import exclusions, winch_saturation
from jls.assessment.winch_limits import apply_timedomain, apply_winch_limits, damping_capacity
from jls.assessment.workability import assess, assessed_hs
from jls.errors import InputError
from jls.names import FREQUENCY_DOMAIN, SATURATED_FAIL, SATURATED_UNRESOLVED, TIME_DOMAIN
from jls.response.statistics import trapezoid_weights, unit_spectra
from jls.sea.scatter import scatter_dataset
from jls.stages.sea_states import sea_states
from jls.tugger.loads import load_statistics, payout_moments
from jls.tugger.setting import Tugger

TUGGERS = {"none": Tugger("none", 0.0), "weak": Tugger("weak", 1000.0, max_force=100.0, min_force=20.0)}


# -- loads --------------------------------------------------------------------------------
def stiff_plant(k=1e12):
    M = np.diag([7719.0, 7719.0, 4.55e6, 3.286e6])
    K = np.diag([k, k, k, k])
    return M, K, np.zeros((4, 4)), np.diag([1e3, 1e3, 1e5, 1e4])


def test_payout_of_a_fixed_jacket_is_the_fairlead_velocity():
    # A jacket held still (huge stiffness, no hinge drive) sees the line pay out at the
    # fairlead's own velocity: u = -i w y_f, so with y_f = 1 the moments are those of the
    # wave spectrum times w^2: m0 = int w^2 S, m2 = int w^4 S.
    M, K, Kb, C = stiff_plant()
    omega = np.linspace(0.2, 3.0, 1401)
    qb = np.zeros((1, omega.size, 4), complex)
    yf = np.ones((1, omega.size), complex)
    tz = np.array([6.0, 9.0])
    m0, m2 = payout_moments(M, K, Kb, C, omega, qb, yf, [0.0, 1000.0], tz)
    S = unit_spectra(omega, tz)
    w = trapezoid_weights(omega)
    np.testing.assert_allclose(m0[0, 0, 0], (S * w * omega**2).sum(-1), rtol=1e-6)
    np.testing.assert_allclose(m0[0, 1, 0], (S * w * omega**2).sum(-1), rtol=1e-6)
    np.testing.assert_allclose(m2[0, 1, 0], (S * w * omega**4).sum(-1), rtol=1e-6)


def test_a_jacket_moving_with_the_fairlead_loads_no_line():
    # Hinge sway equal to the fairlead sway and a stiff suspension: y = y_b = y_f, u = 0.
    M, K, _, C = stiff_plant()
    omega = np.linspace(0.2, 3.0, 301)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 0.7 * np.exp(0.3j * omega)
    m0, _ = payout_moments(M, K, -K, C, omega, qb, qb[..., 0], [500.0], [7.0])
    S0, _ = payout_moments(M, K, np.zeros((4, 4)), C, omega, qb, qb[..., 0], [500.0], [7.0])
    assert m0.item() < 1e-12 * S0.item()


def test_force_and_power_follow_the_damper_law():
    m0 = np.full((1, 2, 1, 1), 0.04)
    m2 = np.full((1, 2, 1, 1), 0.04 * (2 * np.pi / 8.0) ** 2)
    st = load_statistics(m0, m2, [300.0, 2000.0])
    np.testing.assert_allclose(st["tugger_sigma_payout_velocity"], 0.2)
    np.testing.assert_allclose(st["tugger_sigma_force"].ravel(), [60.0, 400.0])
    np.testing.assert_allclose(st["tugger_power_mean"].ravel(), [300 * 0.04, 2000 * 0.04])
    # MPM with N = 3 h / 8 s cycles: sigma sqrt(2 ln N)
    mpm = 0.2 * np.sqrt(2 * np.log(3 * 3600 / 8.0))
    np.testing.assert_allclose(st["tugger_mpm_force"].ravel(), [300 * mpm, 2000 * mpm])
    np.testing.assert_allclose(st["tugger_power_peak"].ravel(), [300 * mpm**2, 2000 * mpm**2])


# -- workability ---------------------------------------------------------------------------
def tiny_response(force_per_m=50.0, sway_per_m=1.0):
    """One candidate, tuggers none and weak, Tz 5 and 7 s; MPM force 50 kN per m of Hs."""
    mpm = np.zeros((1, 2, 1, 4, 2))
    mpm[..., 0, :] = sway_per_m
    force = np.zeros((1, 2, 1, 2))
    force[:, 1] = force_per_m
    return xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm),
                       "tugger_mpm_force": (("candidate", "tugger", "heading", "tz"), force)},
                      coords={"candidate": ["baseline"], "tugger": ["none", "weak"], "heading": [90.0],
                              "response": ["relative_sway", "relative_heave", "relative_roll",
                                           "relative_yaw"], "tz": [5.0, 7.0]})


def tiny_sea():
    leg = scatter_dataset(np.array([[1.0, 2], [3, 4], [5, 6]]), hs_lower=[0, 1, 2], hs_upper=[1, 2, 3],
                          tz_lower=[4, 6], tz_upper=[6, 8], values_kind="counts")
    route = {"name": "tiny", "legs": [{"name": "a", "duration_h": 30, "headings_deg": [90],
                                       "heading_probability": [1.0]}]}
    return sea_states(route, {"a": leg})


def assessed(policy):
    sea, resp = tiny_sea(), tiny_response()
    work = assess(resp, sea, {"relative_sway_m": 3.0})
    hs = assessed_hs(sea)
    work = apply_winch_limits(work, resp, sea, TUGGERS, hs, policy)
    return apply_timedomain(work, sea, [], hs), sea


def test_damping_capacity_is_n_times_capacity_above_pretension():
    cap = damping_capacity(TUGGERS, ["none", "weak"])
    # T0 = (100 + 20) / 2 = 60 kN; two lines: 2 (100 - 60) = 80 kN; no tugger never saturates.
    assert float(cap.sel(tugger="weak")) == pytest.approx(80.0)
    assert np.isinf(float(cap.sel(tugger="none")))


def test_small_winch_flags_the_high_cells_and_fail_policy_fails_them():
    work, sea = assessed("fail")
    sat = work["winch_saturates"].sel(candidate="baseline", leg="a", heading=90.0)
    # Hs 0.5, 1.5, 2.5 m x 50 kN/m = 25, 75, 125 kN against 80 kN: only Hs 2.5 m saturates.
    np.testing.assert_array_equal(sat.sel(tugger="weak").values, [[0, 0], [0, 0], [1, 1]])
    assert not sat.sel(tugger="none").any()
    src = work["verdict_source"].sel(candidate="baseline", leg="a", heading=90.0, tugger="weak")
    np.testing.assert_array_equal(src.values, [[FREQUENCY_DOMAIN] * 2] * 2 + [[SATURATED_FAIL] * 2])
    # Sway MPM 1 m/m passes everywhere under 3 m; the weak tugger loses the Hs 2.5 row (11/21).
    wr = work["workability_route"].sel(candidate="baseline")
    assert float(wr.sel(tugger="none")) == pytest.approx(1.0)
    assert float(wr.sel(tugger="weak")) == pytest.approx(10 / 21)
    assert float(work["saturation_share_route"].sel(candidate="baseline", tugger="weak")) == pytest.approx(11 / 21)
    assert work["winch_saturates"].attrs["long_name"].startswith("frequency domain unreliable: winch saturates")


def test_timedomain_policy_keeps_the_verdict_until_a_run_replaces_it():
    work, sea = assessed("timedomain")
    assert float(work["workability_route"].sel(candidate="baseline", tugger="weak")) == pytest.approx(1.0)
    src = work["verdict_source"].sel(candidate="baseline", leg="a", heading=90.0, tugger="weak")
    assert (src.sel(hs=2.5) == SATURATED_UNRESOLVED).all()
    # The time domain finds the (Hs 2.5, Tz 7) cell fails with the weak winch, passes without.
    td = xr.Dataset({"mpm_sigma": ("tugger", [2.6, 3.4]), "slack_events": ("tugger", [0, 0]),
                     "limit_fraction": ("tugger", [0.0, 0.12])}, coords={"tugger": ["none", "weak"]},
                    attrs={"candidate": "baseline", "heading_deg": 90.0, "hs_m": 2.5, "tz_s": 7.0,
                           "duration_s": 10800.0, "sway_damping_ratio": 0.0098,
                           "sway_natural_period_s": 15.44})     # standard error 7.6 %: decided
    work = apply_timedomain(work, sea, [td], assessed_hs(sea))
    cell = dict(candidate="baseline", leg="a", heading=90.0, hs=2.5, tz=7.0)
    assert not bool(work["passes"].sel(**cell, tugger="weak"))
    assert bool(work["passes"].sel(**cell, tugger="none"))
    assert int(work["verdict_source"].sel(**cell, tugger="weak")) == TIME_DOMAIN
    assert int((work["verdict_source"] == TIME_DOMAIN).sum()) == 2       # one cell, two tuggers
    assert float(work["workability_route"].sel(candidate="baseline", tugger="weak")) == pytest.approx(15 / 21)
    assert float(work["timedomain_limit_fraction"].sel(candidate="baseline", tugger="weak")) == pytest.approx(0.12)


def test_unknown_policy_and_missing_loads_are_input_errors():
    sea, resp = tiny_sea(), tiny_response()
    work = assess(resp, sea, {"relative_sway_m": 3.0})
    with pytest.raises(InputError, match="winch_saturation"):
        apply_winch_limits(work, resp, sea, TUGGERS, assessed_hs(sea), "ignore")
    with pytest.raises(InputError, match="tugger_mpm_force"):
        apply_winch_limits(work, resp.drop_vars("tugger_mpm_force"), sea, TUGGERS, assessed_hs(sea))


# -- recommendation -------------------------------------------------------------------------
def test_exclusion_rule_names_the_setting_and_the_reason():
    work, _ = assessed("fail")
    work.attrs["max_saturation_fraction"] = 0.01
    combos = [("baseline", "none"), ("baseline", "weak")]
    out = exclusions({"workability": work}, combos, [winch_saturation])
    assert list(out) == [("baseline", "weak")]
    assert "52.4 % of the route" in out[("baseline", "weak")]
    work.attrs["max_saturation_fraction"] = 0.6              # 52 % of the route is allowed now
    assert exclusions({"workability": work}, combos, [winch_saturation]) == {}
    work["timedomain_limit_fraction"][:] = [[0.0, 0.7]]
    assert "70.0 % of the time" in winch_saturation({"workability": work}, combos)[("baseline", "weak")]


def test_exclusion_rules_compose():
    work, _ = assessed("fail")
    work.attrs["max_saturation_fraction"] = 0.01

    def no_baseline(data, combos):
        return {("baseline", "none"): "rigging not feasible in the yard"}
    combos = [("baseline", "none"), ("baseline", "weak")]
    out = exclusions({"workability": work}, combos, [winch_saturation, no_baseline])
    assert set(out) == {("baseline", "weak"), ("baseline", "none")}


def test_too_many_time_domain_cells_is_an_input_error():
    from jls.stages.timedomain_cell import choose_cells
    work, sea = assessed("timedomain")
    cfg = {"assessment": {"winch_saturation": "timedomain"},
           "timedomain": {"boundary_candidates": ["baseline"], "boundary_cells_per_leg": 1, "cells": [],
                          "max_cells": 1}}
    with pytest.raises(InputError, match="timedomain.max_cells"):
        choose_cells(work, sea, assessed_hs(sea), cfg)
    cfg["timedomain"]["max_cells"] = 10
    cells = choose_cells(work, sea, assessed_hs(sea), cfg)
    # The two saturating cells (Hs 2.5 m at Tz 5 and 7 s) and the boundary cell.
    assert {(c["hs"], c["tz"]) for c in cells if "winch saturates in the frequency domain" in c["reasons"]} \
        == {(2.5, 5.0), (2.5, 7.0)}
