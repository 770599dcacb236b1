"""Wire tensions in the response stage, uncertainty bands and criterion sensitivity in the
workability dataset, the recommendation's verdict over the band, the route's window file
and the per-leg energy outside the RAO range."""

import numpy as np
import pandas as pd
import pytest
import report_fixtures as rf
import xarray as xr

from jls.assessment.bands import band_variables, merge_into, sensitivity_variables
from jls.assessment.uncertainty import plant_variants
from jls.assessment.winch_limits import apply_winch_limits
from jls.assessment.workability import assess, assessed_hs
from jls.report.context import Context, eligible
from jls.report.contract import digest
from jls.report.robustness import recommendation_holds, sensitivity_switches
from jls.response.moments import excitation
from jls.response.solver import transfer_functions
from jls.response.tension import tension_dataset
from jls.response.wire_loads import tension_response
from jls.stages.response import response_dataset
from jls.stages.weather_windows import assessed_option, route_windows
from jls.tugger.setting import Tugger

TZ = np.array([5.0, 6.5, 8.0])


@pytest.fixture(scope="module")
def setup():
    plant, motion = rf.plant(), rf.vessel_motion()
    return plant, motion, excitation(plant, motion, rf.HEADINGS, 0.004)


def test_tension_response_in_blocks_equals_the_library_on_full_transfer_functions(setup):
    plant, _, exc = setup
    blocked = tension_response(plant, exc, TZ, rf.TUGGERS, block=1)
    Hq, _ = transfer_functions(plant["M"].values, plant["K"].values, plant["Kb"].values,
                               plant["C"].values, exc.omega, exc.qb, exc.fairlead_sway,
                               list(rf.TUGGERS.values()))
    ref = tension_dataset(plant, exc.omega, Hq, exc.qb, TZ, tuggers=list(rf.TUGGERS),
                          headings_deg=exc.headings)
    for name in ("tension_sigma", "tension_mpm", "tension_tz_response"):
        np.testing.assert_allclose(blocked[name].values, ref[name].values, rtol=1e-12)
    np.testing.assert_array_equal(blocked["tension_static"].values, plant["tension"].values)
    # Linear in the wave amplitude: the statistics are per metre of Hs and positive.
    assert (blocked["tension_mpm"] > 0).all()


def test_response_dataset_carries_the_tension_statistics_only_when_asked(setup):
    plant, motion, _ = setup
    with_t = response_dataset(plant, motion, TZ, rf.HEADINGS, rf.TUGGERS, omega_step=0.004,
                              outside_policy=rf.VESSEL["outside_rao_range"], shown=())
    without = response_dataset(plant, motion, TZ, rf.HEADINGS, rf.TUGGERS, omega_step=0.004,
                               outside_policy=rf.VESSEL["outside_rao_range"], shown=(), tensions=False)
    assert "tension_mpm" in with_t and "tension_mpm" not in without
    assert with_t["tension_mpm"].attrs["units"] == "kN m-1"
    xr.testing.assert_identical(with_t["mpm"], without["mpm"])


@pytest.fixture(scope="module")
def bands(setup):
    plant, motion, _ = setup
    sea = rf.sea_states()
    kw = dict(omega_step=0.004, outside_policy=rf.VESSEL["outside_rao_range"], shown=(), tensions=False,
              tugger_loads=True)
    tz = sea["tz"].values
    resp = response_dataset(plant, motion, tz, rf.HEADINGS, rf.TUGGERS, **kw)
    variants = plant_variants(plant)
    vresp = response_dataset(variants, motion, tz, rf.HEADINGS, rf.TUGGERS, **kw)
    vresp = vresp.assign_coords(base_candidate=("candidate", variants["base_candidate"].values),
                                damping_factor=("candidate", variants["damping_factor"].values),
                                sway_frequency_factor=("candidate", variants["sway_frequency_factor"].values))
    work = assess(resp, sea, rf.CRITERIA)
    work.attrs.update(tie_tolerance=1e-9, tugger_min_gain=0.0)    # any robust gain earns a place
    return sea, resp, work, band_variables(vresp, sea, rf.CRITERIA, work), vresp


def test_bands_contain_the_nominal_value_and_the_nominal_variant_is_close(bands):
    _, _, work, b, _ = bands
    for name in ("workability_route", "workability_leg"):
        assert (b[f"{name}_min"] <= work[name] + 1e-12).all()
        assert (work[name] <= b[f"{name}_max"] + 1e-12).all()
    nominal = b["workability_route_variant"].sel(damping_factor=1.0, sway_frequency_factor=1.0,
                                                 hs_in_bin="centre")
    # The same plant on a grid refined around the variants' modes as well.
    np.testing.assert_allclose(nominal.values, work["workability_route"].values, atol=0.01)
    # Less damping never helps the route.
    v = b["workability_route_variant"]
    assert (v.sel(damping_factor=0.5) <= v.sel(damping_factor=2.0) + 1e-12).all()


def test_variants_are_held_to_the_winch_limits_as_the_nominal_plant(bands):
    """With a winch that saturates, under 'fail' every variant loses its saturated cells:
    the band of the damped setting drops below the unlimited one, the undamped setting's
    band is unchanged, and the nominal (limited) value stays inside its band."""
    sea, resp, work, free, vresp = bands
    tuggers = {"none": Tugger("none", 0.0), "reference": Tugger("reference", 1000.0, max_force=60.0)}
    hs = assessed_hs(sea)
    limited = apply_winch_limits(work.copy(), resp, sea, tuggers, hs, "fail")
    b = band_variables(vresp, sea, rf.CRITERIA, limited, tuggers=tuggers, winch_saturation="fail")
    v, v_free = b["workability_route_variant"], free["workability_route_variant"]
    assert (v <= v_free + 1e-12).all()
    assert (v.sel(tugger="reference") < v_free.sel(tugger="reference") - 1e-6).any()
    np.testing.assert_allclose(v.sel(tugger="none"), v_free.sel(tugger="none"), rtol=1e-12)
    for name in ("workability_route", "workability_leg"):
        assert (b[f"{name}_min"] <= limited[name] + 1e-12).all()
        assert (limited[name] <= b[f"{name}_max"] + 1e-12).all()
    # Under the time-domain policy the flags fail nothing: the unlimited bands.
    td = band_variables(vresp, sea, rf.CRITERIA, work, tuggers=tuggers, winch_saturation="timedomain")
    np.testing.assert_allclose(td["workability_route_variant"], v_free, rtol=1e-12)


def test_the_band_verdict_compares_the_recommendation_with_the_options_it_was_chosen_among(bands):
    """A tugger setting excluded for its saturating winches takes no part in the band's
    verdict on page 1: the recommendation is judged against the options not excluded."""
    sea, resp, work, _, vresp = bands
    tuggers = {"none": Tugger("none", 0.0), "reference": Tugger("reference", 1000.0, max_force=60.0)}
    limited = apply_winch_limits(work.copy(), resp, sea, tuggers, assessed_hs(sea), "fail")
    limited.attrs["max_saturation_fraction"] = 0.01
    b = band_variables(vresp, sea, rf.CRITERIA, limited, tuggers=tuggers, winch_saturation="fail")
    merged = merge_into(limited, b)
    dg = digest("r", sea, rf.vessel_motion(), rf.plant(), resp, merged, rf.provenance())
    assert dg.excluded and all(t == "reference" for _, t in dg.excluded)
    cx = Context(sea=sea, vessel=rf.vessel_motion(), plant=rf.plant(), resp=resp, work=merged,
                 prov=rf.provenance(), dg=dg, figs={})
    assert set(eligible(cx)) == set(dg.combos) - set(dg.excluded)
    v = recommendation_holds(merged, dg.best, eligible(cx))
    assert all(not w.endswith("/ reference") for _, w in v.losers)


def test_sensitivity_is_monotone_and_matches_assess_at_the_configured_limit(bands):
    sea, resp, work, _, _ = bands
    s = sensitivity_variables(resp, sea, rf.CRITERIA, limits=(2.0, 3.0, 4.0))
    w = s["workability_route_sensitivity"]
    assert (w.diff("trial_limit") >= -1e-12).all()
    np.testing.assert_allclose(w.sel(trial_limit=3.0).values, work["workability_route"].values)


def test_a_candidate_not_varied_has_no_band_and_is_left_out_of_the_verdict(bands):
    sea, _, work, _, vresp = bands
    only = vresp.isel(candidate=(vresp["base_candidate"] == "baseline").values)
    b = band_variables(only, sea, rf.CRITERIA, work)
    assert b["workability_route_min"].sel(candidate="detuned").isnull().all()
    assert b["workability_route_min"].sel(candidate="baseline").notnull().all()
    merged = xr.merge([work, b], compat="override")
    combos = [(c, t) for c in ("baseline", "detuned") for t in rf.TUGGERS]
    v = recommendation_holds(merged, ("baseline", "reference"), combos)
    assert v.variants == 18 and all("detuned" not in w for _, w in v.losers)


def _variant_work(values):
    """workability_route_variant over 2 candidates x 1 tugger x 2 damping factors."""
    da = xr.DataArray(np.asarray(values, float).reshape(2, 1, 2, 1, 1),
                      dims=("candidate", "tugger", "damping_factor", "sway_frequency_factor", "hs_in_bin"),
                      coords={"candidate": ["a", "b"], "tugger": ["none"], "damping_factor": [0.5, 2.0],
                              "sway_frequency_factor": [1.0], "hs_in_bin": ["centre"]})
    return xr.Dataset({"workability_route_variant": da}, attrs={"tie_tolerance": 1e-9})


def test_recommendation_verdict_names_the_variant_and_respects_exclusions():
    work = _variant_work([[0.90, 0.95], [0.92, 0.94]])      # b beats a at damping x 0.5
    v = recommendation_holds(work, ("a", "none"), [("a", "none"), ("b", "none")])
    assert not v.holds and v.variants == 2
    assert v.losers[0][0]["damping_factor"] == 0.5 and v.losers[0][1] == "b / none"
    # An option excluded from the recommendation (e.g. infeasible) cannot overturn it.
    assert recommendation_holds(work, ("a", "none"), [("a", "none")]).holds
    tied = _variant_work([[0.92, 0.95], [0.92, 0.94]])
    assert recommendation_holds(tied, ("a", "none"), [("a", "none"), ("b", "none")]).holds


def test_sensitivity_switches_report_where_the_best_option_changes():
    s = xr.DataArray([[[0.5, 0.7, 0.9]], [[0.6, 0.7, 0.8]]], dims=("candidate", "tugger", "trial_limit"),
                     coords={"candidate": ["a", "b"], "tugger": ["none"], "trial_limit": [2.0, 3.0, 4.0]})
    runs = sensitivity_switches(xr.Dataset({"workability_route_sensitivity": s}, attrs={"tie_tolerance": 1e-9}),
                                [("a", "none"), ("b", "none")], lambda ct: ct[0])
    assert runs == [(2.0, ("b", "none")), (3.0, ("a", "none"))]     # tie at 3 m goes to a


def test_route_windows_meets_the_leg_month_and_leg_time_layout():
    mpm = np.zeros((2, 1, 1, 4, 2))
    mpm[0, :, :, 0, :] = 1.0           # candidate a: sway MPM 1 m per m of Hs
    mpm[1, :, :, 0, :] = 2.0           # candidate b: twice as much
    stats = xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                       coords={"candidate": ["a", "b"], "tugger": ["none"], "heading": [90.0],
                               "response": ["relative_sway", "relative_heave", "relative_roll",
                                            "relative_yaw"], "tz": [2.0, 20.0]})
    hs = np.tile([1.0, 1.0, 2.0, 2.0], 48)          # 2 m: workable for a (MPM 2 m), not for b (4 m)
    idx = pd.date_range("2001-01-01", periods=hs.size, freq="1h", tz="UTC", name="time")
    df = pd.DataFrame({"hs": hs, "tz": 6.0}, index=idx)
    df.attrs["source"] = "synthetic"
    legs = [{"name": "buoy", "duration_h": 2, "headings_deg": [90.0], "heading_probability": [1.0]},
            {"name": "table", "duration_h": 5, "headings_deg": [90.0], "heading_probability": [1.0]}]
    ds = route_windows(legs, {"buoy": df}, stats, {"relative_sway_m": 3.0}, ("b", "none"))
    assert ds["window_probability"].dims == ("leg", "month")
    assert ds["workable_hourly"].dims == ("leg", "time")
    assert ds["leg"].values.tolist() == ["buoy"]
    # b: workable 2 hours in 4; a 2-hour window opens at 1 start in 4 (the last start is
    # cut by the record's end).
    assert float(ds["workable_fraction"].sel(leg="buoy")) == pytest.approx(0.5)
    assert float(ds["window_probability_all"].sel(leg="buoy")) == pytest.approx(48 / 191)
    assert float(ds["window_probability_all_options"].sel(candidate="a", tugger="none", leg="buoy")) == 1.0
    assert ds.attrs["option_candidate"] == "b"


def test_the_windows_option_is_the_recommendation_with_its_exclusions():
    """The weather windows are computed for the report's recommendation: not for an
    infeasible rigging nor for a tugger whose winches saturate (policy 'fail'), even when
    their route workability is the highest."""
    cands, tugs = ["baseline", "tall", "wide"], ["none", "high"]
    wr = np.array([[0.90, 0.996], [0.97, 0.995], [0.999, 0.999]])
    share = np.array([[0.0, 0.05], [0.0, 0.0], [0.0, 0.0]])      # baseline/high saturates
    work = xr.Dataset({"workability_route": (("candidate", "tugger"), wr),
                       "saturation_share_route": (("candidate", "tugger"), share)},
                      coords={"candidate": cands, "tugger": tugs},
                      attrs={"max_saturation_fraction": 0.01, "winch_saturation": "fail",
                             "tie_tolerance": 1e-9, "tugger_min_gain": 0.01})
    plant = xr.Dataset({"feasible": ("candidate", [1, 1, 0]),
                        "infeasible_reason": ("candidate", ["", "", "wire angle"])},
                       coords={"candidate": cands})
    c_tug = {"none": 0.0, "high": 2000.0}
    assert assessed_option(work, plant, c_tug) == ("tall", "high")
    # Under the time-domain policy the frequency-domain flag excludes nothing.
    work.attrs["winch_saturation"] = "timedomain"
    assert assessed_option(work, plant, c_tug) == ("baseline", "high")
    # Every option excluded: the best of all, as the report (which then says so).
    plant["feasible"][:] = 0
    assert assessed_option(work, plant, c_tug) == ("wide", "none")


def test_tensions_of_the_named_candidates_only_leave_the_others_nan(setup):
    plant, _, exc = setup
    names = plant["candidate"].values.tolist()
    every = tension_response(plant, exc, TZ, rf.TUGGERS)
    some = tension_response(plant, exc, TZ, rf.TUGGERS, candidates=names[:1])
    np.testing.assert_array_equal(some["tension_sigma"].sel(candidate=names[0]),
                                  every["tension_sigma"].sel(candidate=names[0]))
    assert np.isnan(some["tension_sigma"].sel(candidate=names[1:]).values).all()
    np.testing.assert_array_equal(some["tension_static"], every["tension_static"])
