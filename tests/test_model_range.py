"""The linear model's range (:mod:`jls.report.model_range`): each threshold just below
and just above, the slack wire, and
"beyond the model" never printed with the figure."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from jls.report import model_range as mr
from jls.report import plan_verdict as pv
from jls.report import voyage
from jls.report.basis import BEYOND_MODEL

EPS = 1e-6


def levels_ds(sway=(2.0, 2.5), tension=(0.5, 0.6), angle=(1.0, 1.5)):
    """voyage.nc-like levels of one option: relative sway [m], yaw [deg], wire tension [1]."""
    lv = np.array([[[sway, angle, tension]]])
    da = xr.DataArray(lv, dims=("candidate", "tugger", "criterion", "non_exceedance"),
                      coords={"candidate": ["a"], "tugger": ["n"],
                              "criterion": ["relative_sway_m", "relative_yaw_deg", "wire_tension"],
                              "non_exceedance": [0.5, 0.9]})
    return xr.Dataset({"voyage_level": da, "limit": ("criterion", [3.0, 2.0, 1.0])}).assign_coords(
        level_units=("criterion", ["m", "degree", "1"]))


def plant_ds(margin_deg=2.0, drop=60.0, side_max=10.0, static=(20000.0, 19000.0)):
    return xr.Dataset(
        {"side_lead_margin": ("candidate", [margin_deg]), "drop_height": ("candidate", [drop]),
         "tension": (("candidate", "wire"), [list(static)])},
        coords={"candidate": ["a"], "wire": ["w1", "w2"][:len(static)]},
        attrs={"side_lead_max_deg": side_max})


def work_ds(floor=0.1, ceiling=np.nan):
    lim = xr.DataArray([3.0, 2.0, floor], dims="criterion",
                       coords={"criterion": ["relative_sway_m", "relative_yaw_deg", "wire_tension"],
                               "tension_ceiling_kN": ("criterion", [np.nan, np.nan, ceiling])})
    return xr.Dataset({"limit": lim})


def study_ds(mpm=5.0):
    return xr.Dataset(attrs={"linear_range_mpm_inside_m": mpm, "linear_range_hs_leaves_m": 3.0})


def test_stated_sway_threshold_just_below_and_above():
    rng = mr.model_range(levels_ds())
    assert rng.beyond("relative_sway_m", ("a", "n"), 6.0 - EPS) is None
    b = rng.beyond("relative_sway_m", ("a", "n"), 6.0 + EPS)
    assert b.threshold == 6.0 and b.reason == mr.STATED_SWAY


def test_angle_threshold_just_below_and_above():
    rng = mr.model_range(levels_ds())
    assert rng.beyond("relative_yaw_deg", ("a", "n"), 5.0 - EPS) is None
    assert rng.beyond("relative_yaw_deg", ("a", "n"), 5.0 + EPS).reason == mr.STATED_ANGLE


def test_measured_range_applies_when_smaller_than_the_stated_one():
    rng = mr.model_range(levels_ds(), study=study_ds(5.0))
    assert rng.beyond("relative_sway_m", ("a", "n"), 5.0 - EPS) is None
    b = rng.beyond("relative_sway_m", ("a", "n"), 5.0 + EPS)
    assert (b.threshold, b.reason) == (5.0, mr.MEASURED)
    # a measured range wider than the stated one: the stated one applies
    b = mr.model_range(levels_ds(), study=study_ds(9.0)).beyond("relative_sway_m", ("a", "n"), 6.5)
    assert (b.threshold, b.reason) == (6.0, mr.STATED_SWAY)
    # the reference did not run: no measured range
    failed = study_ds(5.0)
    failed.attrs["reason"] = "no reference"
    assert mr.model_range(levels_ds(), study=failed).measured_sway_m is None


def test_slack_threshold_of_the_wire_tension_level():
    # level = MPM / (T_s (1 - f)); slack when MPM reaches T_s: level 1 / (1 - f) = 1.25 for f = 0.2
    rng = mr.model_range(levels_ds(), work=work_ds(floor=0.2), plant=plant_ds())
    assert rng.beyond("wire_tension", ("a", "n"), 1.25 - EPS) is None
    b = rng.beyond("wire_tension", ("a", "n"), 1.25 + EPS)
    assert b.reason == mr.SLACK and b.threshold == pytest.approx(1.25)
    # a ceiling that governs the allowance of one wire: A = C - T_s = 2000 kN on the
    # 20 000 kN wire (slack at 10), 19000*0.8 on the other... the smallest T_s / A applies
    rng = mr.model_range(levels_ds(), work=work_ds(floor=0.2, ceiling=22000.0), plant=plant_ds())
    a = [min(20000 * 0.8, 2000.0), min(19000 * 0.8, 3000.0)]
    assert rng.slack_level[("a", "wire_tension")] == pytest.approx(min(20000 / a[0], 19000 / a[1]))


def test_a_slack_wire_takes_every_level_of_the_same_point_beyond_the_model():
    rng = mr.model_range(levels_ds(), work=work_ds(floor=0.1), plant=plant_ds())
    inside = {"relative_sway_m": 2.0, "relative_yaw_deg": 1.0, "wire_tension": 1.0}
    assert rng.beyond("relative_sway_m", ("a", "n"), 2.0, inside) is None
    slack = dict(inside, wire_tension=1.2)                  # above 1 / 0.9
    b = rng.beyond("relative_sway_m", ("a", "n"), 2.0, slack)
    assert b.reason == mr.SLACK and b.criterion == "wire_tension"


def test_voyage_table_never_prints_the_figure_beyond_the_model():
    v = levels_ds(sway=(2.0, 7.5), tension=(0.5, 1.3))     # 90 %: sway beyond 6 m, wire slack
    rng = mr.model_range(v, work=work_ds(floor=0.1), plant=plant_ds(margin_deg=9.0))
    assert voyage._voyage_level(rng, v, ("a", "n"), "relative_sway_m", 0.5) == "2.0 m"
    text = voyage._voyage_level(rng, v, ("a", "n"), "relative_sway_m", 0.9)
    assert text.startswith(BEYOND_MODEL) and "7.5" not in text
    yaw = voyage._voyage_level(rng, v, ("a", "n"), "relative_yaw_deg", 0.9)
    assert yaw == f"{BEYOND_MODEL} ({mr.SLACK})" and "1.5" not in yaw
    assert voyage.beyond_linear(v, ("a", "n"), rng) == []    # the medians lie inside


def test_design_level_text_never_carries_the_figure():
    p = levels_ds().rename(non_exceedance="leg").assign_coords(leg=["l1", "l2"])
    p = p.rename(voyage_level="design_level")
    rng = mr.model_range(p, work=work_ds(floor=0.1), plant=plant_ds(), study=study_ds(5.0))
    below = pv.level_text(p, "relative_sway_m", 4.99, ("a", "n"), "l1", rng)
    assert below == "4.99 m"
    above = pv.level_text(p, "relative_sway_m", 5.5, ("a", "n"), "l2", rng)
    assert above.startswith(BEYOND_MODEL) and "5.50" not in above and mr.MEASURED in above
    assert pv.level_cell(p, "relative_sway_m", 5.5, ("a", "n"), "l2", rng).count("5.5") == 0


def test_page_one_voyage_sentence_names_the_reason_without_the_figure():
    from types import SimpleNamespace

    from jls.report import summary

    v = levels_ds(sway=(4.0, 5.0), tension=(1.3, 1.5))       # sway inside 6 m, but a wire slack
    v["exceedance_probability_any"] = xr.DataArray([[0.4]], dims=("candidate", "tugger"),
                                                   coords={"candidate": ["a"], "tugger": ["n"]})
    cx = SimpleNamespace(dg=SimpleNamespace(best=("a", "n")), voyage=v, work=work_ds(floor=0.1),
                         plant=plant_ds(margin_deg=9.0), verification_study=None,
                         sec=lambda key, *a: "section 9")
    text = summary.voyage_sentence(cx)
    assert f"{BEYOND_MODEL} ({mr.SLACK})" in text and "4.0" not in text
    # taut wires: the figure is printed, with how many times the limit
    cx2 = SimpleNamespace(**{k: val for k, val in vars(cx).items() if k != "_model_range"})
    cx2.voyage = levels_ds(sway=(4.0, 5.0), tension=(0.5, 0.6)).assign(
        exceedance_probability_any=v["exceedance_probability_any"])
    text = summary.voyage_sentence(cx2)
    assert "4.0 m" in text and BEYOND_MODEL not in text


def test_statement_names_the_threshold_that_applies_per_rigging():
    rng = mr.model_range(levels_ds(), work=work_ds(floor=0.1), plant=plant_ds(), study=study_ds(5.0))
    text = mr.statement(rng, ["a"])
    assert text.startswith(f"a: relative sway 5.0 m, set by {mr.MEASURED} (")
    assert "stated 6.0 m, measured 5.0 m" in text
    assert "wire tension level 1.11 (a hoist wire goes slack)" in text


def cell_ds(cand, rom, ref, within, ran=True):
    return xr.Dataset({"mpm": ("model", [rom, ref]), "verified": ((), np.bool_(ran)),
                       "within_tolerance": ((), np.bool_(within))},
                      coords={"model": ["rom", "reference"]}, attrs={"candidate": cand})


def test_a_verification_cell_out_of_tolerance_ends_the_rigging_range():
    cells = [cell_ds("a", 4.0, 3.0, within=False), cell_ds("a", 7.0, 5.0, within=False),
             cell_ds("a", 2.0, 2.0, within=True), cell_ds("a", 1.0, 0.5, within=False, ran=False),
             cell_ds("b", 3.0, 2.0, within=False)]
    assert mr.measured_cells(cells) == {"a": 4.0, "b": 3.0}
    rng = mr.model_range(levels_ds(), cells=cells)
    assert rng.beyond("relative_sway_m", ("a", "n"), 4.0 - EPS) is None
    b = rng.beyond("relative_sway_m", ("a", "n"), 4.0 + EPS)
    assert (b.threshold, b.reason) == (4.0, mr.MEASURED_CELL)
    # every cell within tolerance: no measured end, the stated range applies
    assert mr.model_range(levels_ds(), cells=cells[2:3]).threshold("relative_sway_m", "a").reason == mr.STATED_SWAY
