"""Weather windows from hourly hindcasts: limits, hand counts, gaps, alpha factor."""

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from jls.assessment.windows import leg_windows, window_starts, windows_dataset
from jls.assessment.workability import criteria_array, unit_utilisation
from jls.errors import InputError

RESPONSES = ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]
SWAY = {"relative_sway_m": 3.0}


def stats(sway_mpm=(1.0, 1.0), tz=(2.0, 20.0), headings=(90.0,)):
    """Unit-Hs MPM per Tz: relative sway ``sway_mpm`` (m per m Hs) at the Tz values."""
    mpm = np.zeros((1, 1, len(headings), 4, len(tz)))
    mpm[:, :, :, 0, :] = np.asarray(sway_mpm, float)
    return xr.Dataset({"mpm": (("candidate", "tugger", "heading", "response", "tz"), mpm)},
                      coords={"candidate": ["baseline"], "tugger": ["none"],
                              "heading": list(headings), "response": RESPONSES, "tz": list(tz)})


def hindcast(hs, start="2001-01-01 00:00", tz=6.0):
    hs = np.asarray(hs, float)
    idx = pd.date_range(start, periods=hs.size, freq="1h", tz="UTC", name="time")
    df = pd.DataFrame({"hs": hs, "tz": np.full(hs.size, tz)}, index=idx)
    df.attrs["source"] = "synthetic"
    return df


def unit(stats_ds, criteria=SWAY):
    return unit_utilisation(stats_ds, criteria_array(criteria))


def one(ds, var):
    return ds[var].sel(candidate="baseline", tugger="none", heading=90.0).values


def test_always_below_the_limit_gives_one_and_always_above_zero():
    hours = 24 * 59                                    # January and February 2001
    calm = leg_windows(hindcast(np.full(hours, 1.0)), unit(stats()), 48.0)
    rough = leg_windows(hindcast(np.full(hours, 4.0)), unit(stats()), 48.0)
    assert one(calm, "window_probability_all") == 1.0
    assert one(rough, "window_probability_all") == 0.0
    np.testing.assert_array_equal(one(calm, "window_probability")[:2], [1.0, 1.0])
    np.testing.assert_array_equal(one(rough, "window_probability")[:2], [0.0, 0.0])
    assert np.isnan(one(calm, "window_probability")[2:]).all()      # no start in March-December
    assert one(calm, "workable_hourly").min() == 1 and one(rough, "workable_hourly").max() == 0


def test_alternating_series_matches_a_hand_count():
    # Three calm hours then two rough ones, repeated; a 2-hour window opens at the first
    # two calm hours of each run: 2 of every 5 starts.
    pattern = np.tile([1.0, 1.0, 1.0, 5.0, 5.0], 40)
    hs = np.concatenate([pattern, [1.0]])             # 201 hours -> 200 starts of 2 hours
    ds = leg_windows(hindcast(hs), unit(stats()), 2.0)
    assert one(ds, "window_probability_all") == pytest.approx(2 / 5)
    assert int(ds["window_hours"]) == 2
    # A 3-hour window (2.5 h rounded up) fits only at the first calm hour of each run:
    # 40 of the 199 starts; 4 hours never.
    assert one(leg_windows(hindcast(hs), unit(stats()), 2.5), "window_probability_all") == \
        pytest.approx(40 / 199)
    assert one(leg_windows(hindcast(hs), unit(stats()), 4.0), "window_probability_all") == 0.0
    assert one(ds, "workable_fraction") == pytest.approx(121 / 201)


def test_windows_are_counted_in_the_month_they_start():
    # January calm, February rough, 10-hour windows: the last nine January starts run
    # into February and fail.
    jan, feb = 31 * 24, 28 * 24
    ds = leg_windows(hindcast(np.r_[np.full(jan, 1.0), np.full(feb, 4.0)]), unit(stats()), 10.0)
    p = one(ds, "window_probability")
    assert p[0] == pytest.approx((jan - 9) / jan)
    assert p[1] == 0.0
    np.testing.assert_array_equal(ds["window_starts"].values[:2], [jan, feb - 9])


def test_gaps_are_left_out_or_counted_unworkable_as_stated():
    workable = np.array([1, 1, 1, 1, 0, 1, 1, 1], bool)
    known = np.array([1, 1, 0, 1, 1, 1, 1, 1], bool)     # hour 2 missing
    ok, judged = window_starts(workable, known, 2, "exclude")
    # starts 0..6; windows over hour 2 (starts 1, 2) cannot be judged
    np.testing.assert_array_equal(judged, [1, 0, 0, 1, 1, 1, 1])
    np.testing.assert_array_equal(ok, [1, 0, 0, 0, 0, 1, 1])
    ok_u, judged_u = window_starts(workable, known, 2, "unworkable")
    assert judged_u.all()
    np.testing.assert_array_equal(ok_u, [1, 0, 0, 0, 0, 1, 1])
    # Through a record with a missing hour: the dataset marks it and reports it.
    df = hindcast(np.full(48, 1.0)).drop(pd.Timestamp("2001-01-01 05:00", tz="UTC"))
    ds = leg_windows(df, unit(stats()), 6.0)
    assert int(ds["missing_hours"]) == 1
    assert one(ds, "workable_hourly")[5] == -1
    assert int(ds["window_starts"][0]) == 43 - 6           # 43 starts, 6 of them span the gap
    assert one(ds, "window_probability_all") == 1.0
    worst = leg_windows(df, unit(stats()), 6.0, gaps="unworkable")
    assert one(worst, "window_probability_all") == pytest.approx(37 / 43)


def test_alpha_factor_is_monotone():
    rng = np.random.default_rng(11)
    hs = np.clip(2.0 + np.cumsum(rng.normal(0.0, 0.15, 24 * 90)), 0.2, 6.0)   # a wandering sea
    p = [one(leg_windows(hindcast(hs), unit(stats()), 24.0, alpha=a), "window_probability_all")
         for a in (0.5, 0.6, 0.7, 0.8, 0.9, 1.0)]
    assert np.all(np.diff(p) >= 0.0)
    assert p[0] < p[-1]
    with pytest.raises(InputError, match="alpha"):
        leg_windows(hindcast(hs), unit(stats()), 24.0, alpha=1.2)


def test_tz_interpolation_and_outside_range():
    # Unit sway MPM 1 m/m at 5 s, 3 m/m at 9 s: at 7 s it is 2, so Hs 1.4 m gives 2.8 m.
    u = unit(stats(sway_mpm=(1.0, 3.0), tz=(5.0, 9.0)))
    assert one(leg_windows(hindcast(np.full(10, 1.4), tz=7.0), u, 1.0), "workable_hourly").all()
    assert not one(leg_windows(hindcast(np.full(10, 1.6), tz=7.0), u, 1.0), "workable_hourly").any()
    with pytest.raises(InputError, match="outside"):
        leg_windows(hindcast(np.full(10, 0.5), tz=12.0), u, 1.0)
    near = leg_windows(hindcast(np.full(10, 0.5), tz=12.0), u, 1.0, tz_outside="nearest")
    assert one(near, "workable_hourly").all() and int(near["hours_outside_tz"]) == 10
    cons = leg_windows(hindcast(np.full(10, 0.5), tz=12.0), u, 1.0, tz_outside="unworkable")
    assert not one(cons, "workable_hourly").any()


def test_route_dataset_weights_headings_and_aligns_legs():
    s = stats(sway_mpm=(1.0, 1.0), headings=(90.0, 135.0))
    s["mpm"].loc[dict(heading=135.0, response="relative_sway")] = 10.0   # never workable
    legs = [{"name": "a", "duration_h": 5, "headings_deg": [90.0, 135.0],
             "heading_probability": [0.75, 0.25]},
            {"name": "b", "duration_h": 5, "headings_deg": [90.0], "heading_probability": [1.0]}]
    hc = {"a": hindcast(np.full(48, 1.0)), "b": hindcast(np.full(24, 1.0), start="2001-01-03")}
    ds = windows_dataset(legs, hc, s, SWAY)
    p = ds["window_probability_all"].sel(candidate="baseline", tugger="none")
    np.testing.assert_allclose(p.values, [0.75, 1.0])
    assert ds["workable_hourly"].dims == ("candidate", "tugger", "heading", "leg", "time")
    assert ds.sizes["time"] == 72
    flags = ds["workable_hourly"].sel(candidate="baseline", tugger="none", heading=90.0)
    assert (flags.sel(leg="b").values[:48] == -1).all() and (flags.sel(leg="a").values[48:] == -1).all()
    # Leg b never meets 135 deg: no flags there.
    assert (ds["workable_hourly"].sel(leg="b", heading=135.0) == -1).all()
    assert ds.attrs["gaps"] == "exclude" and ds.attrs["alpha"] == 1.0
    with pytest.raises(InputError, match="hindcast"):
        windows_dataset(legs, {"a": hc["a"]}, s, SWAY)


def test_reads_a_hindcast_file_with_its_gap():
    from pathlib import Path

    from jls.sea.hindcast import read_hindcast
    df = read_hindcast(Path(__file__).parent / "data" / "sea" / "hindcast_valid.txt")
    ds = leg_windows(df, unit(stats()), 2.0)
    flags = one(ds, "workable_hourly")
    assert flags.size == int(ds["missing_hours"]) + len(df)
    assert (flags == -1).sum() == int(ds["missing_hours"]) > 0
    # Every recorded hour is calm against a 3 m limit at 1 m/m: every judged window opens.
    assert one(ds, "window_probability_all") == 1.0


def test_route_hindcasts_are_read_for_hindcast_legs_only():
    from pathlib import Path

    from jls.assessment.windows import read_route_hindcasts
    base = Path(__file__).parent / "data" / "sea"
    hindcast = {"file": "hindcast_valid.txt", "hs_edges_m": [0, 5], "tz_edges_s": [0, 10]}
    route = {"legs": [{"name": "h", "duration_h": 3, "hindcast": hindcast},
                      {"name": "s", "duration_h": 3, "scatter": "matrix_counts_edges.csv"}]}
    got = read_route_hindcasts(route, base, gamma=3.3)
    assert list(got) == ["h"] and len(got["h"]) == 8
    route["legs"][0]["hindcast"]["file"] = "absent.txt"
    with pytest.raises(InputError, match="not found"):
        read_route_hindcasts(route, base, gamma=3.3)


def test_the_windows_attributes_are_the_registrys():
    """Units and long names come from the dataset registry (the per-option variables are
    the file's ``*_options``), so the library's dataset and the file cannot drift."""
    from jls.assessment.windows import PER_OPTION
    from jls.io import registry
    leg = {"name": "leg", "duration_h": 2.0, "headings_deg": [90.0], "heading_probability": [1.0]}
    ds = windows_dataset([leg], {"leg": hindcast(np.ones(48))}, stats(), SWAY)
    spec = registry.layout("weather_windows")
    entries = {**spec["coordinates"], **spec["variables"]}
    for var in ds.variables:
        name = f"{var}_options" if var in PER_OPTION else var
        if name in entries and "units" in entries[name]:
            assert ds[var].attrs["units"] == entries[name]["units"], var
            assert ds[var].attrs["long_name"] == entries[name]["long_name"], var
    assert ds["window_probability"].attrs["long_name"] == spec["variables"]["window_probability_options"]["long_name"]
