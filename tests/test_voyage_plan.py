"""The voyage plan stage (voyage_plan.nc): the contract's variables and dims, a route of
tables only (class verdict, and why no departure simulation), a table and its records
checked against each other, both verdicts of the unrestricted check, a weather-restricted
route that departs at once and one that waits."""

import numpy as np
import pytest
import report_fixtures as fx

from jls.io import registry


@pytest.fixture(scope="module")
def data():
    return fx.datasets()


@pytest.fixture(scope="module")
def records(tmp_path_factory):
    return fx.write_records(tmp_path_factory.mktemp("records"))


def test_tables_only_route_gets_the_class_verdict_and_says_why_no_simulation(data):
    ds = fx.voyage_plan(data)
    registry.check(ds, "voyage_plan")
    assert "plan_exceedance_probability" not in ds
    assert "scatter table only" in ds.attrs["plan_reason"] and "north_sea, biscay" in ds.attrs["plan_reason"]
    assert ds.attrs["route_class"] == "unrestricted"             # 60 h + 96 h, one stretch
    assert "leg biscay (96 h) is longer than 72 h" in ds.attrs["class_statement"]
    assert set(ds["design_acceptable"].dims) == {"candidate", "tugger"}
    assert (ds["leg_design_basis"].values == "scatter table (all year)").all()
    # the design level is the largest over the contour and the design point lies on it
    lvl = ds["design_level"].sel(candidate="baseline", tugger="none", criterion="relative_sway_m", leg="north_sea")
    hs = float(ds["design_hs"].sel(candidate="baseline", tugger="none", criterion="relative_sway_m", leg="north_sea"))
    assert float(lvl) > 0 and np.isclose(ds["contour_hs"].sel(leg="north_sea").values, hs).any()


def test_contract_variables_with_records(data, records):
    ds = fx.voyage_plan(data, records=records, hold_points=("biscay",))
    registry.check(ds, "voyage_plan")
    for v in ("plan_exceedance_probability", "plan_departure_fraction", "plan_not_sailed_fraction"):
        assert ds[v].dims == ("candidate", "tugger")
        assert ds[v + "_month"].dims == ("candidate", "tugger", "month")
    for v in ("plan_wait_h", "plan_transit_h"):
        assert ds[v].dims == ("candidate", "tugger", "quantile")
        assert ds[v + "_month"].dims == ("candidate", "tugger", "month", "quantile")
    assert ds["quantile"].values.tolist() == [0.5, 0.9]
    assert ds["hold_point"].values.tolist() == ["north_sea", "biscay"]
    # the synthetic records were not binned into the synthetic tables: the check says so
    assert "differ from the table" in ds.attrs["consistency"]
    p = ds["plan_exceedance_probability"].values
    assert np.all((p >= 0) & (p <= 1))
    # the rule removes risk: never more than departing at any hour
    assert np.all(p <= ds["reference_exceedance_probability"].values + 1e-12)


def test_both_verdicts_of_the_unrestricted_check(data):
    fails = fx.voyage_plan(data, criteria={"relative_sway_m": 0.5, "relative_yaw_deg": 2.0})
    assert not fails["design_acceptable"].any()
    holds = fx.voyage_plan(data, criteria={"relative_sway_m": 1000.0, "relative_yaw_deg": 1000.0})
    assert holds["design_acceptable"].all()


def test_restricted_route_departs_at_once_or_waits(data, records):
    short = {"north_sea": 30.0, "biscay": 40.0}
    calm = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=short,
                          criteria={"relative_sway_m": 1000.0, "relative_yaw_deg": 1000.0})
    assert calm.attrs["route_class"] == "weather-restricted" and calm.attrs["class_statement"] == ""
    assert (calm["plan_departure_fraction"] == 1.0).all()
    assert (calm["plan_wait_h"] == 0.0).all()
    tight = fx.voyage_plan(data, records=records, hold_points=("biscay",), durations=short,
                           criteria={"relative_sway_m": 0.6, "relative_yaw_deg": 1000.0})
    f = tight["plan_departure_fraction"].sel(candidate="baseline", tugger="none")
    assert 0.0 < float(f) < 1.0
    assert float(tight["plan_wait_h"].sel(candidate="baseline", tugger="none", quantile=0.9)) > 0
    # a 72-h perfect forecast covers each 30-40 h stretch: no sailed voyage exceeds
    assert (tight["plan_exceedance_probability"].fillna(0.0) == 0.0).all()


def test_compressed_records_read_and_a_corrupt_one_named(tmp_path):
    import gzip

    from jls.errors import InputError
    from jls.sea.hindcast import read_hindcast
    text = ("time (YYYY-MM-DD-HH); significant wave height (m); zero-up-crossing period (s)\n"
            "2001-01-01-00; 1.0; 5.0\n2001-01-01-01; 1.2; 5.5\n")
    good = tmp_path / "leg.txt.gz"
    good.write_bytes(gzip.compress(text.encode()))
    assert read_hindcast(good)["hs"].tolist() == [1.0, 1.2]
    bad = tmp_path / "bad.txt.gz"
    bad.write_bytes(b"not gzip at all")
    with pytest.raises(InputError, match="bad.txt.gz.*not a readable gzip file"):
        read_hindcast(bad)


def test_default_route_records_equal_its_tables():
    """The shipped records binned on the shipped tables' bins are the tables (the check
    the stage makes; an independent reading of the two files)."""
    from jls.config.loader import load
    from jls.sea.scatter import read_scatter
    from jls.stages.sea_states import sea_states
    from jls.stages.voyage_plan import CONSISTENT, consistency, leg_records
    cfg = load(fx.ROOT / "config" / "config.yaml")
    route = cfg["routes"]["default"]
    legs = {leg["name"]: read_scatter(fx.ROOT / leg["scatter"]) for leg in route["legs"]}
    sea = sea_states(dict(route, name="default"), legs, "study")
    recs = leg_records(route, fx.ROOT, gamma=3.3)
    for name in legs:
        assert consistency(sea, name, recs[name]) == CONSISTENT


def test_reference_without_rule_equals_the_route_simulation(data, records):
    """Departing at every hour without the rule is the existing route simulation's
    voyage: its share beyond a limit equals 1 - pass_probability (two code paths)."""
    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.route_hours import common_hours
    from jls.assessment.route_simulation import route_simulation
    from jls.assessment.workability import criteria_array
    from jls.stages.voyage_plan import leg_records
    plan = fx.voyage_plan(data, records=records)
    route = fx.route_config()
    for leg in route["legs"]:
        leg["records"] = {"file": records[leg["name"]]}
    recs = leg_records(route, gamma=fx.GAMMA)
    hours = common_hours({n: recs[n] for n in ("north_sea", "biscay")})
    limit = criteria_array(fx.CRITERIA)
    st = criterion_statistics(data["response"], limit)
    sim = route_simulation(st, hours, data["sea_states"]["heading_probability"],
                           data["sea_states"]["duration_h"], st["limit"], strict=limit["strict"])
    np.testing.assert_allclose(plan["reference_exceedance_probability"].values,
                               (1 - sim["pass_probability"]).transpose("candidate", "tugger").values, atol=1e-12)
