"""Margins as a budget (issue 20, item 1): every safety constraint keeps a configured
tolerance budget of named components (defaults in the schema); a candidate inside its
budget is infeasible with the reason; the screening and its refinement optimise within
the budget; the report shows what margin costs, from the screening dataset."""

import copy
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr
import yaml

from jls.config.builders import (
    margin_families,
    rigging_from_config,
    scoring_from_config,
    screening_settings_from_config,
)
from jls.config.loader import validate
from jls.design.margins import margin_grid, margin_sweep
from jls.design.screening import screening_dataset
from jls.plant.candidates import plant_dataset
from jls.plant.rigging import Budget
from jls.report.margins import margin_rows, margin_table
from jls.sea.legs import read_leg
from jls.stages.sea_states import sea_states
from jls.stages.vessel_motion import vessel_motion

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = ROOT / "jls" / "schemas" / "config.schema.yaml"


def schema_budget() -> dict:
    spec = yaml.safe_load(SCHEMA.read_text())
    limits = spec["properties"]["rigging"]["properties"]["limits"]["properties"]
    return {k: v["default"] for k, v in limits["tolerance_budget"]["properties"].items()}


def test_budget_defaults_come_from_the_schema(cfg, rig):
    defaults = schema_budget()
    assert cfg["rigging"]["limits"]["tolerance_budget"] == defaults
    b = rig.limits.budget
    assert dict(b.splash_clearance_m) == defaults["splash_clearance_m"]
    assert dict(b.lead_angle_deg) == defaults["lead_angle_deg"]
    assert dict(b.tension_percent) == defaults["tension_percent"]
    assert b.splash == pytest.approx(sum(defaults["splash_clearance_m"].values()))   # components add up
    assert set(defaults["splash_clearance_m"]) == {"wire_length_and_creep", "hinge_height",
                                                   "draught_and_trim_change", "tip_fabrication"}
    assert b.splash > 0 and b.lead_angle > 0
    # A mapping given replaces the default components whole; {} is no allowance.
    c = copy.deepcopy(cfg)
    c["rigging"]["limits"]["tolerance_budget"] = {"splash_clearance_m": {"crane_survey": 0.2}}
    b2 = rigging_from_config(validate(c)).limits.budget
    assert dict(b2.splash_clearance_m) == {"crane_survey": 0.2}
    assert dict(b2.lead_angle_deg) == defaults["lead_angle_deg"]
    assert Budget().splash == 0.0                       # the library's own: no budget


def test_candidate_inside_its_budget_is_infeasible_with_the_reason(rig):
    b = rig.limits.budget.splash
    top = rig.limits.max_drop()
    ds, _ = plant_dataset(rig, {"on_limit": {"drop_height": top}, "inside": {"drop_height": top - 0.5 * b},
                                "on_budget": {"drop_height": top - b}, "beyond": {"drop_height": top - b - 0.3},
                                "short": {"drop_height": top + 0.02}})
    row = {str(c): ds.sel(candidate=c) for c in ds["candidate"].values}
    for name in ("on_limit", "inside"):
        assert not bool(row[name]["feasible"]), name
        assert str(row[name]["at_limit"].values) == ""
    margin = 0.5 * b
    assert (f"splash clearance margin {margin:.2f} m inside its tolerance budget {b:.2f} m "
            "(wire length and creep 0.30 m, hinge height 0.10 m, draught and trim change 0.30 m, "
            "tip fabrication 0.05 m)") in str(row["inside"]["infeasible_reason"].values)
    assert "splash clearance margin 0.00 m inside its tolerance budget 0.75 m" in \
        str(row["on_limit"]["infeasible_reason"].values)
    assert bool(row["on_budget"]["feasible"])
    assert str(row["on_budget"]["at_limit"].values) == \
        "at limit: splash clearance margin 0.75 m, its whole tolerance budget"
    assert bool(row["beyond"]["feasible"]) and str(row["beyond"]["at_limit"].values) == ""
    assert "splash clearance short by 0.02 m" in str(row["short"]["infeasible_reason"].values)
    assert ds.attrs["splash_clearance_budget_m"] == pytest.approx(b)


def test_lead_angle_and_tension_inside_their_budgets_are_infeasible(rig):
    base, _ = plant_dataset(rig, {"baseline": {}})
    side = rig.limits.side_lead_max_deg - float(base["side_lead_margin"][0])
    tension = float(base["tension"].max())
    lim = replace(rig.limits, side_lead_max_deg=side + 0.3, max_tension_kN=1.03 * tension)
    ds, _ = plant_dataset(replace(rig, limits=lim), {"baseline": {}})
    reason = str(ds["infeasible_reason"][0].values)
    assert not bool(ds["feasible"][0])
    assert ("side lead angle margin 0.30 deg inside its tolerance budget 0.50 deg "
            "(positions as built 0.25 deg, vessel heel and trim 0.25 deg)") in reason
    assert (f"static tension margin {0.03 * tension:.0f} kN inside its tolerance budget "
            f"{0.05 * tension:.0f} kN (weight contingency 5 %)") in reason


@pytest.fixture(scope="module")
def route(cfg):
    spec = dict(cfg["routes"]["default"], name="default")
    legs = {leg["name"]: read_leg(leg, ROOT, "study", 3.3, cfg["g_m_per_s2"]) for leg in spec["legs"]}
    return sea_states(spec, legs), vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT), scoring_from_config(cfg)


@pytest.mark.parametrize("splash", [None, 2.0])
def test_screening_optimises_within_the_budget(cfg, rig, route, splash):
    sea, motion, scoring = route
    if splash is not None:                       # a larger budget moves the optimum with it
        rig = replace(rig, limits=replace(rig.limits, budget=replace(
            rig.limits.budget, splash_clearance_m=(("measured_survey", splash),))))
    st = replace(screening_settings_from_config(cfg), grid_points={"top_spread_y": 4, "drop_height": 4},
                 sensitivity_points=5)
    ds = screening_dataset(rig, motion, sea, scoring, st)
    o = ds.sel(candidate=ds.attrs["optimum_candidate"])
    b, tol = rig.limits.budget, rig.limits.at_limit_tolerance_m
    assert bool(o["feasible"])
    assert float(o["splash_clearance_margin"]) >= b.splash - tol
    assert float(o["side_lead_margin"]) >= b.lead_angle - rig.limits.at_limit_tolerance_deg
    assert float(o["fore_aft_lead_margin"]) >= b.lead_angle
    # Detuning lowers the jacket as far as it may: onto the budget, not onto the limit.
    assert float(o["drop_height"]) == pytest.approx(rig.limits.max_drop() - b.splash, abs=0.02)
    assert "its whole tolerance budget" in ds.attrs["active_constraints"]
    feasible = ds["feasible"].values.astype(bool)
    assert np.all(ds["splash_clearance_margin"].values[feasible] >= b.splash - tol)
    assert ds.attrs["splash_clearance_budget_m"] == pytest.approx(b.splash)


def test_margin_sweep_costs_the_budget_and_each_metre(cfg, rig, route):
    sea, motion, scoring = route
    st = screening_settings_from_config(cfg)
    fam = margin_families(cfg, {"top_spread_y": 35.3, "drop_height": 65.71})
    assert list(fam) == ["baseline", "detuned", "optimised"]
    from jls.plant.rigging import design_variables
    base = design_variables(rig.layout)                                     # the others at the baseline
    assert fam["optimised"]["bottom_spread_y"] == pytest.approx(float(np.max(base["bottom_spread_y"])))
    margins = [0.0, 1.0, 2.0]
    sweep = margin_sweep(rig, {k: fam[k] for k in ("detuned", "optimised")}, margins, motion, sea, scoring, st)
    np.testing.assert_allclose(sweep["splash_margin"].values, margin_grid(margins, 0.75))
    np.testing.assert_allclose(sweep["splash_margin"].values, [0.0, 0.75, 1.0, 2.0])
    np.testing.assert_allclose(sweep["margin_drop_height"].sel(margin_family="optimised").values,
                               rig.limits.max_drop() - sweep["splash_margin"].values)
    assert sweep["margin_feasible"].sel(margin_family="optimised").values.tolist() == [False, True, True, True]
    assert float(sweep["family_splash_margin"].sel(margin_family="optimised")) == pytest.approx(0.75)
    w = sweep["margin_route_workability"].sel(margin_family="optimised", tugger="none").values
    assert np.all(np.isfinite(w)) and np.all((0 < w) & (w <= 1))
    assert np.all(np.diff(w) <= 1e-12)      # raising the jacket shortens the pendulum: no gain
    # The same numbers as the screening's scoring of the same designs.
    from jls.design.screening import evaluate
    again = evaluate(rig, {"m1": {**fam["optimised"], "drop_height": rig.limits.max_drop() - 1.0}},
                     motion, sea, scoring, st)
    assert float(again["route_workability"].sel(tugger="none")[0]) == pytest.approx(w[2], abs=1e-12)


def test_report_shows_the_margin_tradeoff_from_the_dataset():
    margins = np.array([0.0, 0.5, 0.75, 1.0, 2.0])
    work = np.array([0.975, 0.972, 0.970, 0.969, 0.960])
    ds = xr.Dataset({
        "margin_route_workability": (("margin_family", "splash_margin", "tugger"),
                                     np.stack([work, work - 0.01])[:, :, None]),
        "margin_feasible": (("margin_family", "splash_margin"), [[False, False, True, True, True]] * 2),
        "margin_drop_height": (("margin_family", "splash_margin"), np.tile(66.46 - margins, (2, 1))),
        "family_splash_margin": ("margin_family", [0.75, 6.37]),
    }, coords={"margin_family": ["optimised", "baseline"], "splash_margin": margins, "tugger": ["none"]},
        attrs={"splash_clearance_budget_m": 0.75})
    ds["margin_route_workability"].attrs["note"] = "a stated basis"
    cx = SimpleNamespace(screening=ds, dg=SimpleNamespace(best=("optimised", "none")))
    rows, sentence = margin_rows(cx)
    assert [r[0] for r in rows] == ["0.00", "0.50", "0.75", "1.00", "2.00"]
    assert [r[2] for r in rows] == ["97.50", "97.20", "97.00", "96.90", "96.00"]
    assert [r[3] for r in rows] == ["0.00", "-0.30", "-0.50", "-0.60", "-1.50"]
    assert [r[4] for r in rows] == ["–", "-0.60", "-0.80", "-0.40", "-0.90"]
    assert rows[2][5] == "the tolerance budget, the optimised design" and rows[0][5] == "inside the budget"
    assert sentence.startswith("For the optimised rigging with tugger none, keeping the 0.75 m "
                               "tolerance budget costs 0.50 percentage points")
    assert "each further metre of margin costs on average 0.80 percentage points (to 2.00 m)." in sentence
    text = margin_table(cx)
    assert "What margin costs" in text and "a stated basis" in text and "[per metre \\[pp" in text
    # The baseline's own margin lies beyond the sweep: said so.
    cx.dg.best = ("baseline", "none")
    assert "keeps 6.37 m, beyond the swept margins" in margin_rows(cx)[1]
    cx.dg.best = ("detuned", "none")                  # a rigging the sweep does not hold
    assert margin_table(cx) == ""
