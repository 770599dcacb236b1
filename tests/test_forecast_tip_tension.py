"""``jls forecast`` evaluates the dynamic tip clearance and the hoist-wire tension hour by
hour, from the hour's directional sea, as the workability defines them: a steep short
sea takes the tip of the detuned rigging (the lower one) into the air gap and calm does
not; the tip and wire-tension utilisation of a long-crested single-system hour equal the
workflow's (``response.nc``'s unit-Hs statistics of the JONSWAP of that Tz, gamma 3.3,
at that heading, times Hs, with Forristall's crest); a slack wire fails the hour; the
shipped configuration leaves no criterion unevaluated; a tension floor is strict."""

import copy

import numpy as np
import pytest
from test_forecast import _answer, _forecast

from jls.assessment import tip_clearance
from jls.assessment import wire_tension as wt
from jls.assessment.go_no_go import decide
from jls.config.builders import tip_settings_from_config
from jls.response.tip import still_water_height, tip_response
from jls.response.wire_loads import tension_response
from jls.sea.spectra import tp_from_tz

TIP, WIRE = "tip_air_gap_m", "wire_tension"


def _criterion(ds, name):
    return ds["criterion_utilisation"].sel(criterion=name).values        # (time, candidate, tugger)


def test_the_shipped_configuration_leaves_no_criterion_unevaluated(cfg, tmp_path):
    ds, out = _answer(cfg, _forecast(tmp_path / "calm.csv", 60, wind=(0.2, 4.0, 290.0)))
    assert out["criteria_not_evaluated"] == []
    assert {TIP, WIRE, "relative_sway_m"} <= set(out["criteria"])
    assert out["criteria"][WIRE] == pytest.approx(0.1)                   # the floor fraction of static
    assert out["criteria"][TIP] == pytest.approx(1.5)


def test_the_tip_fails_in_a_steep_short_sea_and_passes_in_calm(cfg, tmp_path):
    gap = cfg["assessment"]["criteria"][TIP]
    steep, _ = _answer(cfg, _forecast(tmp_path / "steep.csv", 60, wind=(4.0, 7.0, 290.0)))   # S1 ~ 0.07
    calm, _ = _answer(cfg, _forecast(tmp_path / "calm.csv", 60, wind=(0.2, 4.0, 290.0)))
    assert (_criterion(steep, TIP)[:, 1] > 1).all()                     # detuned: the lower tip
    assert (_criterion(calm, TIP) < 0.2).all()
    assert (_criterion(steep, TIP)[:, 0] < 1).all()                     # baseline: 5.6 m higher
    for ds in (steep, calm):                                            # u > 1 exactly when clearance < gap
        clearance = ds["mpm"].sel(criterion=TIP).values
        assert ((_criterion(ds, TIP) > 1) == (clearance < gap)).all()
    # the demand grows with the sea: the clearance left is lower in the steep sea
    assert (steep["mpm"].sel(criterion=TIP) < calm["mpm"].sel(criterion=TIP)).all()


@pytest.fixture(scope="module")
def long_crested(cfg, tmp_path_factory):
    """A forecast of one long-crested JONSWAP swell (Tp = 1.286 Tz, gamma 3.3) from 290 deg on
    a course of 200 deg (relative heading 90 deg, an RAO heading), Hs 2 m then 4 m."""
    from jls.sea.headings import relative_heading
    c = copy.deepcopy(cfg)
    c["sea"]["spreading"] = {"wind": "long-crested", "swell": "long-crested"}
    tz = 8.0
    tp = float(tp_from_tz(tz, 3.3))
    assert tp == pytest.approx(1.286 * tz, rel=1e-3)
    path = _forecast(tmp_path_factory.mktemp("lc") / "lc.csv", 60, wind=(0.0, 5.0, 200.0),
                     swell=(2.0, tp, 290.0), storm=(30, 59, (4.0, tp, 290.0)))
    ds, out = _answer(c, path)
    assert float(relative_heading(200.0, 290.0)) == 90.0
    return c, ds, tz


def _pipeline_transfer(c):
    from jls.commands.forecast import options_transfer
    tr, _ = options_transfer(c, "default", ".", "no-results")
    assert 90.0 in tr.exc.headings.tolist()
    return tr


def test_tip_utilisation_of_a_long_crested_hour_is_the_workabilitys(long_crested):
    c, ds, tz = long_crested
    tr = _pipeline_transfer(c)
    a, v = c["assessment"], c["vessel"]
    lever = np.subtract(v["hinge_m"], v["rao_reference_point_m"])[:2]
    tip = tip_settings_from_config(c)
    stats = tip_response(tr.plant, tr.exc, lever, [tz], tr.tuggers, tip, gamma=3.3, exposure_h=a["exposure_h"],
                         cycles=a["mpm_cycles"], g=c["g_m_per_s2"])
    stats.attrs["tip_crest"] = tip.crest
    u_unit = tip_clearance.unit_utilisation(stats, a["criteria"][TIP]).sel(heading=90.0, tz=tz)
    for hour, hs in ((0, 2.0), (40, 4.0)):
        got = _criterion(ds, TIP)[hour]
        np.testing.assert_allclose(got, hs * u_unit.transpose("candidate", "tugger").values, rtol=1e-7)
    # Forristall's crest: the demand (still-water height less the clearance left) grows
    # faster than Hs (the utilisation Hs / Hs_lim of the same spectral shape does not)
    h = still_water_height(tip, tr.plant["drop_height"].values)[:, None]
    demand = h - ds["mpm"].sel(criterion=TIP).values
    assert (demand[40] > 2.0 * demand[0]).all()
    np.testing.assert_allclose(_criterion(ds, TIP)[40], 2.0 * _criterion(ds, TIP)[0], rtol=1e-9)


def test_wire_tension_utilisation_of_a_long_crested_hour_is_the_workabilitys(long_crested):
    c, ds, tz = long_crested
    tr = _pipeline_transfer(c)
    a = c["assessment"]
    stats = tension_response(tr.plant, tr.exc, [tz], tr.tuggers, gamma=3.3, exposure_h=a["exposure_h"],
                             cycles=a["mpm_cycles"])
    floor, ceiling = wt.settings(a["criteria"][WIRE])
    u_unit = wt.unit_utilisation(stats, floor, ceiling).sel(heading=90.0, tz=tz)
    lowest = wt.lowest_fraction(stats, 4.0).sel(heading=90.0, tz=tz)
    for hour, hs in ((0, 2.0), (40, 4.0)):
        np.testing.assert_allclose(_criterion(ds, WIRE)[hour], hs * u_unit.transpose("candidate", "tugger").values,
                                   rtol=1e-7)
    np.testing.assert_allclose(ds["mpm"].sel(criterion=WIRE).values[40], lowest.transpose("candidate", "tugger").values,
                               rtol=1e-7)


def test_a_slack_wire_fails_the_hour(cfg, tmp_path):
    # 3 m of 15-s swell on the beam slackens the baseline's wires (tension MPM above static)
    c = copy.deepcopy(cfg)
    c["assessment"]["criteria"][WIRE]["floor_fraction_of_static"] = 0.0     # the floor at zero: slack alone
    ds, out = _answer(c, _forecast(tmp_path / "beam.csv", 60, swell=(3.0, 15.0, 290.0)))
    lowest = ds["mpm"].sel(criterion=WIRE).values                           # lowest tension / static
    u = _criterion(ds, WIRE)
    assert (lowest[:, 0, 0] < 0).all()                                      # baseline, no tugger: slack
    assert (u[:, 0, 0] > 1).all()
    assert ((u > 1) == (lowest < 0)).all()                                  # slack exactly when it fails
    o = out["options"]["baseline"]["none"]
    assert not o["go"] and all(h["utilisation"] > 1 for h in o["hourly"])
    assert (lowest[:, 1] > 0).all() and (u[:, 1] < 1).all()                 # detuned: taut, passes


def test_a_strict_floor_fails_at_exactly_one():
    u = np.array([[0.5, 1.0, 0.5]])
    cu = np.stack([u, np.array([[0.1, 1.0, 0.1]])], axis=-1)[0][None]      # second criterion reaches 1
    lax = decide(u, cu, ["relative_sway_m", "wire_tension"], 0, 3)
    strict = decide(u, cu, ["relative_sway_m", "wire_tension"], 0, 3, strict=[False, True])
    assert lax[0].go and not strict[0].go
    assert "strict" in strict[0].reason


def test_a_tip_below_the_air_gap_at_rest_fails_even_a_calm_hour(cfg, tmp_path):
    c = copy.deepcopy(cfg)
    c["assessment"]["criteria"][TIP] = 8.0          # above the detuned tip's 5 m, below the baseline's 10.6 m
    ds, out = _answer(c, _forecast(tmp_path / "calm.csv", 60, wind=(0.0, 4.0, 290.0)))     # no system at all
    assert ds["calm"].all()
    assert np.isinf(_criterion(ds, TIP)[:, 1]).all() and (_criterion(ds, TIP)[:, 0] == 0).all()
    assert not any(o["go"] for o in out["options"]["detuned"].values())
    assert all(o["go"] for o in out["options"]["baseline"].values())


def test_a_plant_without_its_rigging_geometry_lists_tip_and_wires_as_not_evaluated(cfg, tmp_path):
    import pypdf

    from jls.commands.forecast import forecast_answer
    from jls.report.forecast import write_pdf
    from jls.stages.plant import plant as plant_of
    p = plant_of(cfg)
    bare = p.drop_vars([v for v in ("anchor", "padeye", "drop_height", "tension", "wire_stiffness", "cog_depth")
                        if v in p])
    path = _forecast(tmp_path / "calm.csv", 60, wind=(0.2, 4.0, 290.0))
    ds, out = forecast_answer(cfg, ".", str(path), "partitions-csv", "default", "gulf_of_maine", course=200.0,
                              results="no-results", plant=bare, plant_source="matrices")
    assert out["criteria_not_evaluated"] == [TIP, WIRE]
    assert list(out["criteria"]) == ["relative_sway_m"]
    text = pypdf.PdfReader(write_pdf(ds, out, tmp_path / "f.pdf")).pages[0].extract_text()
    assert TIP in text and WIRE in text and "Check them separately" in text
