"""The hoist-wire tension criterion ``wire_tension``: a slack wire fails its cell in the
frequency domain and in the time domain; the floor is a fraction of the static tension,
the maximum the safe working load times its factors; the voyage level and the DAF."""

from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from test_workability import tiny_response, tiny_sea

from jls.assessment import wire_tension as wt
from jls.assessment.criterion_levels import criterion_statistics
from jls.assessment.winch_limits import apply_timedomain
from jls.assessment.workability import assess, assessed_hs
from jls.config.loader import load
from jls.errors import InputError
from jls.names import TIME_DOMAIN, WIRE_TENSION_CRITERION
from jls.stages.workability import amplification

ROOT = Path(__file__).resolve().parents[1]
STATIC = np.array([20000.0, 17000.0, 20000.0, 17000.0])      # kN, mirror pairs
WIRES = ["pf", "pa", "sf", "sa"]


def with_tension(resp, mpm_tz5, mpm_tz7, sigma_ratio=0.25):
    """Unit-Hs tension MPM per wire (kN per m Hs) at Tz 5 and 7 s and static tensions."""
    mpm = np.stack([mpm_tz5, mpm_tz7], axis=0)[None, None, None]      # (1, 1, 1, tz, wire)
    dims = ("candidate", "tugger", "heading", "tz", "wire")
    out = resp.copy()
    out["tension_mpm"] = (dims, mpm)
    out["tension_sigma"] = (dims, sigma_ratio * mpm)
    out["tension_tz_response"] = (dims, np.full_like(mpm, 8.0))
    out["tension_static"] = (("candidate", "wire"), STATIC[None].copy())
    return out.assign_coords(wire=WIRES)


def sea():
    return tiny_sea([[1, 2], [3, 4], [5, 6]], [[0, 0], [0, 0], [0, 10]])


def criteria(**wire):
    return {"relative_sway_m": 3.0, WIRE_TENSION_CRITERION: {"floor_fraction_of_static": 0.1, **wire}}


def test_frequency_domain_fails_a_cell_whose_wire_goes_slack():
    # The 17 MN wires lose 8 MN/m at Tz 7: at Hs 2.5 m the MPM drop (20 MN) exceeds the
    # static tension, the wire goes slack; the floor 10 % leaves 15.3 MN of allowance, so
    # Hs_lim = 15300 / 8000 = 1.9125 m; the Hs 0.5 and 1.5 m cells pass.
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [2000, 8000, 2000, 8000])
    ds = assess(resp, sea(), criteria())
    slack = dict(candidate="baseline", tugger="none", heading=90.0, leg="a", hs=2.5, tz=7.0)
    low = ds["mpm"].sel(**slack, criterion=WIRE_TENSION_CRITERION).item()
    assert low == pytest.approx((17000 - 2.5 * 8000) / 17000)            # negative: slack
    assert low < 0
    assert not ds["passes"].sel(**slack).item()
    gov = ds["governing"].sel(**slack).item()
    assert ds["governing"].attrs["flag_meanings"].split()[gov] == WIRE_TENSION_CRITERION
    hs_lim = ds["hs_limit_criterion"].sel(criterion=WIRE_TENSION_CRITERION, tz=7.0).item()
    assert hs_lim == pytest.approx(17000 * 0.9 / 8000)
    assert ds["passes"].sel(**{**slack, "hs": 1.5}).item()
    assert ds["workability_leg"].sel(leg="a").item() == pytest.approx(15 / 21)
    assert ds["limit"].sel(criterion=WIRE_TENSION_CRITERION).item() == pytest.approx(0.1)
    assert np.isnan(ds["limit"]["tension_ceiling_kN"].sel(criterion=WIRE_TENSION_CRITERION).item())
    # Without the criterion the same cell passes: the criterion is what fails it.
    assert assess(resp, sea(), {"relative_sway_m": 3.0})["passes"].sel(**slack).item()


def test_floor_zero_still_fails_slack_and_is_strict():
    # f = 0: the allowance is the static tension itself. Tz 7, 17 MN wires at 34 MN/m:
    # Hs_lim = 0.5 m, so the Hs 0.5 m cell reaches T = 0 exactly: slack, it fails.
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [100, 34000, 100, 34000])
    ds = assess(resp, sea(), {"relative_sway_m": 3.0, WIRE_TENSION_CRITERION: {"floor_fraction_of_static": 0.0}})
    cell = dict(leg="a", hs=0.5, tz=7.0)
    assert ds["mpm"].sel(**cell, criterion=WIRE_TENSION_CRITERION).item() == pytest.approx(0.0, abs=1e-12)
    assert not ds["passes"].sel(**cell).item()


def test_safe_working_load_times_factors_bounds_the_maximum():
    # SWL 25 MN x 0.9 = 22.5 MN: the 20 MN wires have 2.5 MN up (the floor leaves 18 MN
    # down), the 17 MN wires 5.5 MN up; with 1 MN/m on every wire at Tz 7, Hs_lim = 2.5 m
    # from the 20 MN wires: the 2.5 m cell sits on the maximum and fails (strict).
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [1000] * 4)
    ds = assess(resp, sea(), criteria(safe_working_load_kN=25000.0, swl_factors={"skew": 0.9}))
    ceiling = ds["limit"]["tension_ceiling_kN"].sel(criterion=WIRE_TENSION_CRITERION).item()
    assert ceiling == pytest.approx(22500.0)
    assert ds["hs_limit_criterion"].sel(criterion=WIRE_TENSION_CRITERION, tz=7.0).item() == pytest.approx(2.5)
    assert not ds["passes"].sel(leg="a", hs=2.5, tz=7.0).item()
    # Without the SWL only the floor judges: 18 MN / 1 MN/m, every cell passes.
    assert assess(resp, sea(), criteria())["passes"].sel(leg="a", hs=2.5, tz=7.0).item()
    # A static tension beyond the allowed maximum fails at any Hs.
    low = assess(resp, sea(), criteria(safe_working_load_kN=19000.0))
    assert low["workability_route"].item() == 0.0


def test_settings_refuse_a_floor_outside_zero_to_one():
    with pytest.raises(InputError, match="floor_fraction_of_static"):
        wt.settings({"floor_fraction_of_static": 1.0})
    assert wt.settings({"floor_fraction_of_static": 0.2, "safe_working_load_kN": 100.0,
                        "swl_factors": {"a": 0.5, "b": 0.8}}) == (0.2, pytest.approx(40.0))


def td_cell(wire_min, wire_max, slack, sway=(1.0, 1.0)):
    return xr.Dataset({"mpm_sigma": ("tugger", list(sway)), "slack_events": ("tugger", list(slack)),
                       "wire_tension_min": ("tugger", list(wire_min)),
                       "wire_tension_max": ("tugger", list(wire_max)),
                       "limit_fraction": ("tugger", [0.0, 0.0])}, coords={"tugger": ["none", "weak"]},
                      attrs={"candidate": "baseline", "heading_deg": 90.0, "hs_m": 1.5, "tz_s": 7.0,
                             "duration_s": 10800.0, "sway_damping_ratio": 0.0098,
                             "sway_natural_period_s": 15.44})


def two_tugger_response():
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [100] * 4)
    return xr.concat([resp, resp.assign_coords(tugger=["weak"])], dim="tugger",
                     data_vars="minimal", coords="minimal", compat="override").assign(
        tension_static=resp["tension_static"])


def assessed(resp, s, crit):
    """The workability with every verdict from the frequency domain (no winch limits)."""
    work = assess(resp, s, crit)
    work["verdict_source"] = xr.zeros_like(work["passes"], dtype=np.int8)
    return work


def test_time_domain_fails_a_cell_whose_wire_went_slack():
    # The frequency domain passes every cell (100 kN/m of dynamic tension). The record of
    # (Hs 1.5, Tz 7) without tugger has a slack wire (minimum 0, 6 slack events): the cell
    # fails, decided in the time domain, though its relative sway is far inside its limit.
    # With the weak tugger the record's lowest tension, 1.5 MN, is under the floor
    # 0.1 x 20 MN = 2 MN of the most loaded wire: it fails too. A third record passes.
    s, resp = sea(), two_tugger_response()
    work = assessed(resp, s, criteria())
    assert bool(work["passes"].all())
    hs = assessed_hs(s)
    out = apply_timedomain(work.copy(deep=True), s, [td_cell([0.0, 1500.0], [25000, 21000], [6, 0])], hs,
                           resp["tension_static"])
    cell = dict(candidate="baseline", leg="a", heading=90.0, hs=1.5, tz=7.0)
    for tug in ("none", "weak"):
        assert not bool(out["passes"].sel(**cell, tugger=tug))
        assert int(out["verdict_source"].sel(**cell, tugger=tug)) == TIME_DOMAIN
    ok = apply_timedomain(work.copy(deep=True), s, [td_cell([9000.0, 9000.0], [25000, 21000], [0, 0])], hs,
                          resp["tension_static"])
    assert bool(ok["passes"].sel(**cell).all())
    # The safe working load judges the recorded maximum.
    capped = assessed(resp, s, criteria(safe_working_load_kN=24000.0))
    out = apply_timedomain(capped, s, [td_cell([9000.0, 9000.0], [25000, 21000], [0, 0])], hs,
                           resp["tension_static"])
    assert not bool(out["passes"].sel(**cell, tugger="none"))
    assert bool(out["passes"].sel(**cell, tugger="weak"))
    with pytest.raises(InputError, match="static"):
        apply_timedomain(assessed(resp, s, criteria()), s, [td_cell([0, 0], [1, 1], [0, 0])], hs)


def test_voyage_level_is_the_governing_wire_utilisation():
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [2000, 8000, 2000, 8000])
    from jls.assessment.workability import criteria_array
    lim = criteria_array({WIRE_TENSION_CRITERION: criteria()[WIRE_TENSION_CRITERION]})
    st = criterion_statistics(resp, lim).sel(criterion=WIRE_TENSION_CRITERION, tz=7.0)
    assert float(st["limit"]) == 1.0
    assert float(st["mpm"].squeeze()) == pytest.approx(8000 / (0.9 * 17000))
    assert float(st["sigma"].squeeze()) == pytest.approx(0.25 * 8000 / (0.9 * 17000))


def test_amplification_over_the_workable_cells():
    # Tz 7, 1 MN/m on every wire: the workable cells of leg a reach Hs 2.5 m (floor 18 MN
    # down), DAF = (17000 + 2.5 x 1000) / 17000 on the lighter wires.
    s = sea()
    resp = with_tension(tiny_response([0.01, 0.01], [0.0, 0.0]), [100] * 4, [1000] * 4)
    work = assess(resp, s, criteria())
    amplification(work, resp, s, criteria(daf_limit=1.1, daf_source="test", floor_source="test"), "centre")
    daf = float(work["dynamic_amplification"].sel(candidate="baseline", tugger="none"))
    assert daf == pytest.approx(19500 / 17000)
    assert work.attrs["daf_limit"] == 1.1


def test_shipped_configuration_holds_the_criterion_with_its_sources():
    cfg = load(ROOT / "config" / "config.yaml")
    conf = cfg["assessment"]["criteria"][WIRE_TENSION_CRITERION]
    assert conf["floor_fraction_of_static"] == pytest.approx(0.1)
    assert "DNV" in conf["floor_source"] and "DNV-ST-N001" in conf["daf_source"]
    assert conf["daf_limit"] == pytest.approx(1.1)


def test_page_one_figures_name_the_tension_when_it_binds():
    from types import SimpleNamespace

    from jls.report.wire_loads import binding_figures
    crit = ["relative_sway_m", WIRE_TENSION_CRITERION]
    share = xr.DataArray([[[[0.02, 0.01]]]], dims=("candidate", "tugger", "leg", "criterion"),
                         coords={"candidate": ["detuned"], "tugger": ["none"], "leg": ["a"], "criterion": crit})
    work = xr.Dataset({"governing_share": share,
                       "dynamic_amplification": (("candidate", "tugger"), [[1.28]])},
                      coords={"candidate": ["detuned"], "tugger": ["none"]}, attrs={"daf_limit": 1.1})
    dg = SimpleNamespace(criteria=crit, limits={WIRE_TENSION_CRITERION: 0.1}, best=("detuned", "none"))
    cx = SimpleNamespace(work=work, dg=dg, sea=xr.Dataset({"leg_weight": ("leg", [1.0])}, coords={"leg": ["a"]}),
                         sec=lambda key: "section 13")
    text = binding_figures(cx)
    assert "tension governs 1.0" in text and "1.28, above the design value 1.10" in text
    # neither binds: nothing for page 1
    work["governing_share"][:] = 0.0
    work["dynamic_amplification"][:] = 1.05
    assert binding_figures(cx) == ""
    dg.criteria = ["relative_sway_m"]
    assert binding_figures(cx) == ""
