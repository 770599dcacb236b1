"""The recommendation's rules: a tugger must earn its place, ties go to the larger smallest
safety margin and then to fewer changes, and nothing depends on the configuration order."""

import itertools

import numpy as np
import pytest
import xarray as xr

from jls.assessment.recommendation import recommend, smallest_margin, tugger_gain

C_TUG = {"none": 0.0, "low": 300.0}


def plant(cands, splash, side=(5.0,), feasible=None):
    n = len(cands)
    side = np.broadcast_to(np.asarray(side, float), (n,))
    return xr.Dataset(
        {"feasible": ("candidate", np.ones(n, int) if feasible is None else np.asarray(feasible)),
         "infeasible_reason": ("candidate", ["" if f else "a constraint is violated"
                                             for f in (feasible or [1] * n)]),
         "splash_clearance_margin": ("candidate", np.asarray(splash, float)),
         "side_lead_margin": ("candidate", side),
         "fore_aft_lead_margin": ("candidate", np.full(n, 30.0))},
        coords={"candidate": list(cands)},
        attrs={"splash_clearance_m": 5.0, "side_lead_max_deg": 10.0, "fore_aft_lead_max_deg": 50.0})


def work(cands, route, variants=None, min_gain=0.01, tie=0.001):
    """route: {(cand, tug): workability}; variants: {(cand, tug): [per-variant values]}."""
    tugs = list(C_TUG)
    wr = np.array([[route[(c, t)] for t in tugs] for c in cands])
    ds = xr.Dataset({"workability_route": (("candidate", "tugger"), wr),
                     "saturation_share_route": (("candidate", "tugger"), np.zeros_like(wr))},
                    coords={"candidate": list(cands), "tugger": tugs},
                    attrs={"tugger_min_gain": min_gain, "tie_tolerance": tie,
                           "max_saturation_fraction": 0.01, "winch_saturation": "fail"})
    if variants is not None:
        v = np.array([[variants.get((c, t), [route[(c, t)]] * 3) for t in tugs] for c in cands])
        ds["workability_route_variant"] = (("candidate", "tugger", "damping_factor"), v)
        ds = ds.assign_coords(damping_factor=[0.5, 1.0, 2.0])
    return ds


def test_a_tugger_gaining_less_than_the_minimum_is_excluded():
    cands = ["baseline", "detuned"]
    route = {("baseline", "none"): 0.948, ("baseline", "low"): 0.962,
             ("detuned", "none"): 0.970, ("detuned", "low"): 0.976}      # +0.6 pp over passive
    data = {"plant": plant(cands, [6.0, 1.6]), "workability": work(cands, route)}
    best, _, excluded = recommend(data, cands, list(C_TUG), C_TUG)
    assert best == ("detuned", "none")
    reason = excluded[("detuned", "low")]
    assert "+0.60 percentage points" in reason and "detuned rigging without tugger" in reason
    assert reason.short == "tugger +0.60\u00a0pp"
    assert ("baseline", "low") in excluded                               # below the passive best


def test_a_tugger_whose_gain_is_negative_in_one_variant_is_excluded():
    cands = ["baseline"]
    route = {("baseline", "none"): 0.90, ("baseline", "low"): 0.95}      # +5 pp nominal
    variants = {("baseline", "none"): [0.90, 0.90, 0.93], ("baseline", "low"): [0.95, 0.95, 0.92]}
    data = {"plant": plant(cands, [6.0]), "workability": work(cands, route, variants)}
    rules = tugger_gain({**data, "c_tugger": C_TUG}, [("baseline", t) for t in C_TUG])
    assert list(rules) == [("baseline", "low")]
    assert "damping_factor 2.0" in rules[("baseline", "low")]
    assert rules[("baseline", "low")].short == "tugger not robust"


def test_a_tugger_whose_variants_or_best_passives_were_not_computed_is_not_recommended():
    # a candidate grid's variants are those of the shown candidates: the others' are NaN,
    # and a gain that cannot be judged robust is not taken for robust
    cands = ["baseline", "grid_1"]
    route = {("baseline", "none"): 0.90, ("baseline", "low"): 0.95,
             ("grid_1", "none"): 0.92, ("grid_1", "low"): 0.97}
    nan = [np.nan] * 3
    variants = {("baseline", "none"): [0.88, 0.90, 0.92], ("baseline", "low"): [0.93, 0.95, 0.96],
                ("grid_1", "none"): nan, ("grid_1", "low"): nan}
    data = {"plant": plant(cands, [6.0, 6.0]), "workability": work(cands, route, variants)}
    best, _, excluded = recommend(data, cands, list(C_TUG), C_TUG)
    assert best == ("grid_1", "none")
    for combo in (("baseline", "low"), ("grid_1", "low")):
        assert excluded[combo].short == "tugger robustness not assessed"
        assert "the grid_1 rigging having no variants" in excluded[combo]


def test_a_robust_tugger_with_a_clear_gain_is_recommended():
    cands = ["baseline"]
    route = {("baseline", "none"): 0.90, ("baseline", "low"): 0.95}
    variants = {("baseline", "none"): [0.88, 0.90, 0.92], ("baseline", "low"): [0.93, 0.95, 0.96]}
    data = {"plant": plant(cands, [6.0]), "workability": work(cands, route, variants)}
    best, _, excluded = recommend(data, cands, list(C_TUG), C_TUG)
    assert best == ("baseline", "low") and not excluded


def test_ties_go_to_the_larger_smallest_margin_whatever_the_configuration_order():
    cands = ["baseline", "detuned", "optimised"]
    route = {("baseline", "none"): 0.948, ("detuned", "none"): 0.9757,
             ("optimised", "none"): 0.9760}                             # within 0.1 pp
    route.update({(c, "low"): 0.0 for c in cands})
    margins = [6.0, 0.0, 1.6]                                           # splash clearance [m]
    picks = set()
    for order in itertools.permutations(range(3)):
        cs = [cands[i] for i in order]
        data = {"plant": plant(cs, [margins[i] for i in order]), "workability": work(cs, route)}
        best, ties, _ = recommend(data, cs, list(C_TUG), C_TUG)
        picks.add(best)
        assert ties == [("detuned", "none")]
    assert picks == {("optimised", "none")}          # 1.6 m of margin beats 0.0 m


def test_smallest_margin_is_relative_to_each_limit():
    m = smallest_margin(plant(["a", "b"], [2.5, 4.0], side=[5.0, 1.0]))
    assert m["a"] == pytest.approx(0.5)              # splash 2.5 / 5 m (side lead 5 / 10 deg)
    assert m["b"] == pytest.approx(0.1)              # side lead 1 / 10 deg


def test_ranked_by_the_voyage_the_option_most_likely_to_stay_inside_wins():
    cands = ["baseline", "detuned"]
    route = {("baseline", "none"): 0.97, ("detuned", "none"): 0.95,
             ("baseline", "low"): 0.0, ("detuned", "low"): 0.0}
    w = work(cands, route)
    w["voyage_inside_probability"] = (("candidate", "tugger"), [[0.40, 0.0], [0.80, 0.0]])
    data = {"plant": plant(cands, [6.0, 6.0]), "workability": w}
    assert recommend(data, cands, list(C_TUG), C_TUG)[0] == ("baseline", "none")
    w.attrs["recommendation_objective"] = "voyage_exceedance"
    assert recommend(data, cands, list(C_TUG), C_TUG)[0] == ("detuned", "none")


def test_ranked_by_the_voyage_plan_then_the_shorter_wait():
    cands = ["baseline", "detuned"]
    route = {("baseline", "none"): 0.97, ("detuned", "none"): 0.95,
             ("baseline", "low"): 0.0, ("detuned", "low"): 0.0}
    w = work(cands, route)
    w.attrs["recommendation_objective"] = "voyage_plan"
    data = {"plant": plant(cands, [6.0, 6.0]), "workability": w}
    # without a departure simulation the plan's objective ranks by workability
    assert recommend(data, cands, list(C_TUG), C_TUG)[0] == ("baseline", "none")
    # the lower sailed-voyage exceedance probability wins
    w["plan_inside_probability"] = (("candidate", "tugger"), [[0.80, 0.0], [0.87, 0.0]])
    w["plan_wait_median_h"] = (("candidate", "tugger"), [[2.0, 0.0], [9.0, 0.0]])
    w["plan_wait_p90_h"] = (("candidate", "tugger"), [[30.0, 0.0], [60.0, 0.0]])
    assert recommend(data, cands, list(C_TUG), C_TUG)[0] == ("detuned", "none")
    # equal probabilities: the shorter median wait wins over the tie rule (the baseline)
    w["plan_inside_probability"] = (("candidate", "tugger"), [[0.87, 0.0], [0.87, 0.0]])
    w["plan_wait_median_h"] = (("candidate", "tugger"), [[9.0, 0.0], [2.0, 0.0]])
    best, ties, _ = recommend(data, cands, list(C_TUG), C_TUG)
    assert best == ("detuned", "none") and ties == [("baseline", "none")]
    # equal waits: the existing tie rule (no change from the baseline first)
    w["plan_wait_median_h"] = (("candidate", "tugger"), [[2.0, 0.0], [2.0, 0.0]])
    w["plan_wait_p90_h"] = (("candidate", "tugger"), [[30.0, 0.0], [30.0, 0.0]])
    assert recommend(data, cands, list(C_TUG), C_TUG)[0] == ("baseline", "none")
