"""The recommendation's exclusion rules and the Tz window of the chapter "Rigging"."""

from __future__ import annotations

import pickle
from types import SimpleNamespace

import numpy as np
import pytest
import report_fixtures as rf
import xarray as xr

from jls.assessment import recommendation as rules
from jls.assessment.recommendation import Reason
from jls.report import summary
from jls.report.context import Context
from jls.report.contract import digest
from jls.report.rigging_compare import tz_window
from jls.report.summary import recommendation

# 'low' hangs the jacket 15 m deeper than the baseline: a longer sway period (better
# workability) but its tip in the splash zone.
CANDIDATES = {"baseline": {}, "low": {"drop_height": 75.0}}


@pytest.fixture(scope="module")
def data():
    return rf.datasets(candidates=CANDIDATES, tuggers={"none": 0.0})


@pytest.fixture(scope="module")
def dg(data):
    return digest("r", data["sea_states"], data["vessel_motion"], data["plant"], data["response"],
                  data["workability"], rf.provenance())


def _context(data, dg):
    return Context(sea=data["sea_states"], vessel=data["vessel_motion"], plant=data["plant"],
                   resp=data["response"], work=data["workability"], prov=rf.provenance(), dg=dg, figs={})


def test_infeasible_candidate_is_excluded_and_the_reason_stated(data, dg):
    plant, work = data["plant"], data["workability"]
    assert not bool(plant["feasible"].sel(candidate="low"))
    reason = str(plant["infeasible_reason"].sel(candidate="low").values)
    assert "splash clearance short" in reason
    # Without the exclusion 'low' would win: the rule, not the ranking, removes it.
    wr = work["workability_route"]
    assert float(wr.sel(candidate="low", tugger="none")) > float(wr.sel(candidate="baseline", tugger="none"))
    assert dg.best_any[0] == "low" and dg.best[0] == "baseline"
    assert set(dg.excluded) == {("low", t) for t in dg.tuggers}
    assert all(reason in why for why in dg.excluded.values())
    text = " ".join(recommendation(_context(data, dg)).split())
    assert "Excluded: low: " in text and "splash clearance short" in text
    assert "the larger smallest safety margin first" in text   # the tie-break rule, disclosed


def test_exclusion_rules_compose(data):
    combos = [(c, t) for c in CANDIDATES for t in rf.TUGGERS]

    def no_reference_tugger(d, cs):            # stands in for a second rule (e.g. a saturated winch)
        return {ct: "tugger reference saturates" for ct in cs if ct[1] == "reference"}

    out = rules.exclusions({"plant": data["plant"]}, combos,
                             [rules.infeasible_rigging, no_reference_tugger])
    assert set(out) == {("low", "none"), ("low", "reference"), ("baseline", "reference")}
    both = out[("low", "reference")]
    assert both.startswith("rigging low is not feasible") and both.endswith("; tugger reference saturates")
    assert out[("baseline", "reference")] == "tugger reference saturates"
    assert both.short == "infeasible rigging, tugger reference saturates"   # table 1's column
    assert pickle.loads(pickle.dumps(both)).short == both.short
    single = rules.exclusions(dict(data, c_tugger={"none": 0.0}),     # the default rules
                              [(c, "none") for c in CANDIDATES])
    assert set(single) == {("low", "none")}
    assert {why.short for why in single.values()} == {rules.INFEASIBLE}
    assert rules.exclusions({"plant": data["plant"]}, combos, []) == {}


def _curve(hs_of_tz):
    tz = np.arange(3.0, 14.0001, 0.25)
    hs = hs_of_tz(tz)
    return xr.Dataset({"hs_limit_curve": (("candidate", "tugger", "heading", "tz_curve"), hs[None, None, None]),
                       "hs_limit_curve_criterion": (("candidate", "tugger", "heading", "tz_curve", "criterion"),
                                                    hs[None, None, None, :, None])},
                      coords={"candidate": ["baseline"], "tugger": ["none"], "heading": [90.0],
                              "tz_curve": tz, "criterion": ["relative_sway_m"]})


def _stated_exclusions(n_infeasible: int, n_saturating: int) -> str:
    """Page 1's exclusion sentence for a route with that many infeasible riggings and
    feasible riggings whose 'high' tugger saturates (tuggers none and high)."""
    tugs = ["none", "high"]
    winch = Reason("winches saturate", "winch 2.0\u00a0%", "winch x\u00a0%: the winches saturate")
    excluded = {}
    for k in range(n_infeasible):
        for tg in tugs:
            excluded[(f"bad{k}", tg)] = Reason(f"rigging bad{k} is not feasible: splash {k} m short",
                                               rules.INFEASIBLE)
        excluded[(f"bad{k}", "high")] = excluded[(f"bad{k}", "high")] + winch
    for k in range(n_saturating):
        excluded[(f"ok{k}", "high")] = winch
    dg = SimpleNamespace(excluded=excluded, tuggers=tugs, tugger_min_gain=0.01, tie_tolerance=0.001,
                         infeasible={f"bad{k}": f"splash {k} m short" for k in range(n_infeasible)})
    return " ".join(summary._selection_rule(dg).replace("\u00a0", " ").split())


def test_exclusions_on_page_1_are_named_when_few_and_counted_when_many():
    few = _stated_exclusions(2, 3)
    assert "Excluded: bad0: splash 0 m short; bad1: splash 1 m short; " in few
    assert "ok0 rigging with tugger high (winch 2.0 %); ok1 rigging" in few and "ok2 rigging" in few
    assert few.endswith("(winch x %: the winches saturate)")
    assert "bad0 rigging" not in few                 # an infeasible rigging: its reason only
    many = _stated_exclusions(5, 7)
    assert "Excluded: 5 rigging candidates that are not feasible; " in many
    assert "7 combinations of 7 feasible rigging candidates" in many
    assert "ok0" not in many and "bad0" not in many
    assert many.endswith("(winch x %: the winches saturate)")
    assert "Excluded" not in _stated_exclusions(0, 0)


def test_tz_window_ends_where_the_limiting_hs_crosses_the_design_hs():
    # A tent: rises 1 m/s from 0 at 3 s to 4 m at 7 s, falls 2 m/s to 0 at 9 s.
    work = _curve(lambda tz: np.clip(np.minimum(tz - 3.0, 4.0 - 2.0 * (tz - 7.0)), 0.0, None))
    lo, hi = tz_window(work, ("baseline", "none"), 90.0, 2.4)
    assert lo == pytest.approx(5.4, abs=1e-9) and hi == pytest.approx(7.8, abs=1e-9)
    assert np.isnan(tz_window(work, ("baseline", "none"), 90.0, 4.5)[0])      # never reached
