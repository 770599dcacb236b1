"""The departure rule at hold points, simulated through hourly records: storms known by
hand, the perfect forecast never departing into a failing hour, the waiting-time
distribution of a periodic record, the maximum wait, month selection, several hold
points against a brute-force sailing of every departure."""

import numpy as np
import pandas as pd
import pytest

from jls.assessment.departure_rule import (
    NOT_JUDGED,
    NOT_SAILED,
    SAILED,
    Stretch,
    next_allowed,
    simulate_departures,
    stretches,
    summarise,
)


def storms(period_h, storm_h, n_periods, calm=0.5, storm=2.0):
    """Utilisation of a record with a storm of ``storm_h`` hours at the start of every
    ``period_h`` hours."""
    u = np.full(period_h * n_periods, calm)
    for k in range(n_periods):
        u[k * period_h: k * period_h + storm_h] = storm
    return u


def smooth(rng, shape, mean=-0.7, sd=0.45, phi=0.97):
    """A persistent record: exp of an AR(1) series along the last axis."""
    e = rng.normal(0.0, sd * np.sqrt(1 - phi ** 2), shape)
    x = np.empty(shape)
    x[..., 0] = rng.normal(0.0, sd, shape[:-1])
    for i in range(1, shape[-1]):
        x[..., i] = phi * x[..., i - 1] + e[..., i]
    return np.exp(mean + x)


def one_leg(u, hours, horizon, max_wait=10_000, contingency=0, departures=None):
    util = np.asarray(u, float)[None, None, :]
    st = [Stretch((0,), (hours,), contingency)]
    dep = np.arange(util.shape[-1]) if departures is None else departures
    return simulate_departures(util, util, st, dep, horizon_h=horizon, max_wait_h=max_wait)


def test_next_allowed_is_the_first_allowed_hour_at_or_after():
    a = np.array([0, 1, 0, 0, 1, 0], bool)
    assert next_allowed(a).tolist() == [1, 1, 4, 4, 4, 6]


def test_stretches_follow_the_hold_points_and_sum_the_contingency():
    st = stretches([False, False, True], [10.0, 20.5, 30.0], [1.0, 2.2, None])
    assert [s.legs for s in st] == [(0, 1), (2,)]
    assert [s.hours for s in st] == [(10, 21), (30,)]
    assert [s.contingency_h for s in st] == [4, 0]       # ceil(3.2)
    assert st[0].windows(100) == [(0, 0, 10), (1, 10, 25)]   # contingency on the last leg
    assert st[0].windows(15) == [(0, 0, 10), (1, 10, 5)]     # cut at the horizon


def test_storm_every_two_days_known_by_hand():
    # storms of 6 h every 48 h, a 12-h stretch, the forecast covers it: the hours from
    # the storm's end to 12 h before the next storm allow departure (48 - 6 - 12 + 1 = 31
    # of 48), the others wait to the storm's end; nobody sails into a storm
    P, L, D, K = 48, 6, 12, 40
    d = one_leg(storms(P, L, K), D, horizon=72, departures=np.arange(P * (K - 2)))
    assert (d.status == SAILED).all()
    s = summarise(d, np.ones(P * (K - 2), int))
    assert s["departure_fraction"][0] == pytest.approx((P - L - D + 1) / P)
    assert s["exceedance_probability"][0] == 0.0
    assert s["not_sailed_fraction"][0] == 0.0
    # without the rule, departures meeting a storm: starts in the storm or up to D-1 h before
    assert s["reference_exceedance_probability"][0] == pytest.approx((L + D - 1) / P)
    waits = d.wait_h[0, 0].reshape(K - 2, P)
    expect = np.array([L - t if t < L else (0 if t <= P - D else P + L - t) for t in range(P)])
    assert (waits == expect).all()
    assert (d.transit_h[0] == D).all()


def test_perfect_forecast_exceeds_only_beyond_its_horizon():
    # horizon 4 h short of the 12-h stretch: the last D - H allowed starts of each period
    # sail into the next storm, and only those: exceedance (D - H) / P
    P, L, D, H, K = 48, 6, 12, 8, 30
    d = one_leg(storms(P, L, K), D, horizon=H, departures=np.arange(P * (K - 2)))
    s = summarise(d, np.ones(P * (K - 2), int))
    assert s["exceedance_probability"][0] == pytest.approx((D - H) / P)
    assert s["departure_fraction"][0] == pytest.approx((P - L - H + 1) / P)


def test_random_record_never_departs_into_a_failing_forecast_hour():
    rng = np.random.default_rng(3)
    m = 3000
    u = smooth(rng, (3, 2, m))                                      # 3 options, 2 legs
    u[:, :, 1000:1010] = np.nan                                     # a gap
    alpha = 0.8
    st = stretches([True, True], [20.0, 30.0], [5.0, 5.0])
    H = 24                                      # the 30-h second leg's last 6 h unforecast
    dep = np.arange(m)
    d = simulate_departures(u, u / alpha, st, dep, horizon_h=H, max_wait_h=500)
    assert (d.status == SAILED).sum() > 100 and (d.exceeds).sum() > 0
    for r in range(3):
        for i in np.flatnonzero(d.status[r] == SAILED)[::7]:
            for s, stretch in enumerate(st):
                t = int(dep[i] + np.nansum(d.wait_h[r, : s + 1, i]) + sum(x.sail_h for x in st[:s]))
                leg = stretch.legs[0]
                span = min(stretch.sail_h + stretch.contingency_h, H)
                fc = u[r, leg, t: t + span]
                assert np.all(fc <= alpha), "departed into a forecast failing hour"
            # an exceeding voyage fails only in hours beyond the horizon of its stretch
            if d.exceeds[r, i]:
                beyond = []
                for s, stretch in enumerate(st):
                    t = int(dep[i] + np.nansum(d.wait_h[r, : s + 1, i]) + sum(x.sail_h for x in st[:s]))
                    beyond.append(np.nanmax(u[r, stretch.legs[0], t + H: t + stretch.sail_h],
                                            initial=0.0))
                assert max(beyond) > 1.0


def brute(u, stl, dep, H, W):
    """Sail each departure hour by hour, the rule as written."""
    rows, _, m = u.shape
    out = []
    for r in range(rows):
        res = []
        for t0 in dep:
            t, waits, status, exc = int(t0), [], SAILED, False
            for st in stl:
                w = 0
                while True:
                    span = min(st.sail_h + st.contingency_h, H)
                    need = max(span, st.sail_h)
                    if t + w + need > m:
                        status = NOT_JUDGED if w <= W else NOT_SAILED
                        break
                    ok, gap = True, False
                    for k, s, n in st.windows(H):
                        f = u[r, k, t + w + s: t + w + s + n]
                        ok &= bool(np.all(f <= 1.0))
                        gap |= bool(np.isnan(f).any())
                    if ok:
                        break
                    if gap:                        # waiting on a forecast the record lacks
                        status = NOT_JUDGED
                        break
                    w += 1
                    if w > W:
                        status = NOT_SAILED
                        break
                if status != SAILED:
                    break
                waits.append(w)
                t += w
                for k, s, n in st.sailed():
                    a = u[r, k, t + s: t + s + n]
                    if np.isnan(a).any():
                        status = NOT_JUDGED
                    exc |= bool(np.nanmax(a) > 1.0) if not np.isnan(a).all() else False
                t += st.sail_h
                if status != SAILED:
                    break
            res.append((status, exc and status == SAILED, sum(waits) if status == SAILED else None))
        out.append(res)
    return out


def test_two_hold_points_agree_with_sailing_hour_by_hour():
    rng = np.random.default_rng(11)
    m = 700
    u = smooth(rng, (2, 3, m), mean=-0.5)
    u[1, 2, 300:305] = np.nan
    stl = stretches([True, False, True], [7.0, 5.5, 9.0], [1.0, 0.0, 2.0])
    dep = np.arange(0, m, 3)
    for H, W in ((40, 60), (8, 15)):
        d = simulate_departures(u, u, stl, dep, horizon_h=H, max_wait_h=W)
        ref = brute(u, stl, dep, H, W)
        for r in range(2):
            assert [x[0] for x in ref[r]] == d.status[r].tolist()
            assert [x[1] for x in ref[r]] == d.exceeds[r].tolist()
            total = np.nansum(d.wait_h[r], axis=0)
            for i, x in enumerate(ref[r]):
                if x[2] is not None:
                    assert total[i] == x[2]


def test_periodic_record_wait_distribution_and_maximum_wait():
    # storms of 6 h every 48 h, 12-h stretch: per period 31 departures at once and
    # one each with waits 1..17 h; the 90 % wait is the 44th of the 48 sorted waits, 13 h
    P, L, D, K = 48, 6, 12, 22
    dep = np.arange(P * (K - 2))
    d = one_leg(storms(P, L, K), D, horizon=72, departures=dep)
    s = summarise(d, np.ones(dep.size, int))
    assert s["wait_h"][0].tolist() == [0.0, 13.0]
    # a maximum wait of 10 h: the departures that would wait 11..17 h are not sailed
    d = one_leg(storms(P, L, K), D, horizon=72, max_wait=10, departures=dep)
    s = summarise(d, np.ones(dep.size, int))
    assert s["not_sailed_fraction"][0] == pytest.approx(7 / P)
    assert (d.status == NOT_SAILED).sum() == 7 * (K - 2)
    # among the sailed: 31 zeros and 1..10
    assert s["wait_h"][0].tolist() == [0.0, np.sort(np.r_[np.zeros(31), np.arange(1, 11)])[int(np.ceil(0.9 * 41)) - 1]]


def test_months_are_selected_by_departure_month():
    t = pd.date_range("2001-01-01", "2001-12-31 23:00", freq="1h")
    u = np.full(t.size, 0.5)
    feb = np.flatnonzero(t.month == 2)
    u[feb[::48]] = 2.0                                   # a one-hour storm every two days in February
    month = t.month.to_numpy()
    dep = np.flatnonzero(np.isin(month, [2, 7]))
    d = one_leg(u, 10, horizon=24, departures=dep)
    s = summarise(d, month[dep])
    assert s["judged_month"][0].tolist() == [0, 24 * 28, 0, 0, 0, 0, 24 * 31, 0, 0, 0, 0, 0]
    assert np.isnan(s["exceedance_probability_month"][0, 0])         # no departure in January
    assert s["departure_fraction_month"][0, 6] == 1.0                 # July: always
    # 14 storms each barring the 10 start hours whose window holds it; the first storm's
    # 9 earlier hours lie in January
    assert s["departure_fraction_month"][0, 1] == pytest.approx(1 - (14 * 10 - 9) / (24 * 28))
    assert s["departure_fraction"][0] == pytest.approx((24 * 31 + s["departure_fraction_month"][0, 1] * 24 * 28)
                                                       / (24 * 59))


def test_a_voyage_past_the_record_is_not_judged():
    d = one_leg(np.full(30, 0.5), 12, horizon=12)
    assert (d.status[0, :19] == SAILED).all() and (d.status[0, 19:] == NOT_JUDGED).all()
    s = summarise(d, np.ones(30, int))
    assert s["judged"][0] == 19


# ---- the plan of every option from unit statistics ---------------------------------------

def plan_inputs(hs_leg, tz=6.0, mpm_per_m=(1.0, 0.2), limits=(3.0, 1.0)):
    """Two options x 2 criteria with unit MPMs flat in Tz, one leg with the hourly Hs."""
    import xarray as xr

    from jls.assessment.route_hours import common_hours
    t = pd.date_range("2001-03-01", periods=len(hs_leg), freq="1h", tz="UTC", name="time")
    rec = pd.DataFrame({"hs": hs_leg, "tz": np.full(len(hs_leg), tz)}, index=t)
    hours = common_hours({"only": rec})
    grid = np.arange(3.0, 12.01, 1.0)
    mpm = np.array([[[m] * grid.size for m in mpm_per_m], [[2 * m] * grid.size for m in mpm_per_m]])
    dims = ("candidate", "criterion", "heading", "tz")
    stats = xr.Dataset({"mpm": (dims, mpm[:, :, None, :]), "sigma": (dims, mpm[:, :, None, :] / 3),
                        "tz_response": (dims, np.full(mpm[:, :, None, :].shape, 10.0))},
                       coords={"candidate": ["a", "b"], "criterion": ["sway", "roll"], "heading": [90.0],
                               "tz": grid})
    limit = xr.DataArray(list(limits), dims="criterion", coords={"criterion": ["sway", "roll"]})
    hp = xr.DataArray([[1.0]], dims=("leg", "heading"), coords={"leg": ["only"], "heading": [90.0]})
    return stats, hours, hp, limit


def test_plan_of_two_options_from_unit_statistics_and_alpha():
    from jls.assessment.operation import AlphaTable
    from jls.assessment.voyage_plan import voyage_plan
    # Hs 1 m calm, 2.5 m storms of 6 h every 48 h; option a: sway MPM 1 m per m (limit 3 m,
    # utilisation 0.33 calm, 0.83 in the storm: never fails); option b twice: 0.67 calm,
    # 1.67 in the storm; roll 0.2 deg per m against 1 deg never governs a's
    P, L, K = 48, 6, 20
    hs = np.where(storms(P, L, K) > 1, 2.5, 1.0)
    stats, hours, hp, limit = plan_inputs(hs)
    common = dict(strict=False, hold_point=[True], contingency_h=[None], horizon_h=72, max_wait_h=1000,
                  months=[3, 4])
    ds = voyage_plan(stats, hours, hp, [12.0], limit, **common)
    p = ds["plan_departure_fraction"]
    assert float(p.sel(candidate="a")) == pytest.approx(1.0)
    assert float(p.sel(candidate="b")) == pytest.approx((P - L - 12 + 1) / P, abs=0.01)
    assert float(ds["plan_exceedance_probability"].sel(candidate="b")) == 0.0
    assert float(ds["reference_exceedance_probability"].sel(candidate="b")) > 0.3
    assert ds["plan_wait_h"].dims == ("candidate", "quantile")
    assert ds["plan_wait_h_month"].dims == ("candidate", "month", "quantile")
    # an alpha of 0.3 at every Hs bars option a's calm hours too (utilisation 0.33 > 0.3)
    table = AlphaTable("test table", [1.0, 100.0], [1.0, 10.0], [[0.3, 0.3], [0.3, 0.3]])
    ds = voyage_plan(stats, hours, hp, [12.0], limit, alpha=table, **dict(common, max_wait_h=100))
    assert float(ds["plan_departure_fraction"].sel(candidate="a")) == 0.0
    assert float(ds["plan_not_sailed_fraction"].sel(candidate="a")) == 1.0
    # alpha 0.9: option a departs always (0.83 <= 0.9), option b in the calm (0.67)
    table = AlphaTable("test table", [1.0, 100.0], [1.0, 10.0], [[0.9, 0.9], [0.9, 0.9]])
    ds = voyage_plan(stats, hours, hp, [12.0], limit, alpha=table, **common)
    assert float(ds["plan_departure_fraction"].sel(candidate="a")) == 1.0


def test_strict_criterion_at_its_limit_fails():
    from jls.assessment.voyage_plan import utilisation
    level = np.array([[[[3.0]], [[0.5]]]])                      # (group, criterion, leg, time)
    assert utilisation(level, [3.0, 1.0], [False, False])[0, 0, 0] == 1.0
    assert utilisation(level, [3.0, 1.0], [True, False])[0, 0, 0] > 1.0


def test_master_table_is_the_hs_the_rule_allows():
    import xarray as xr

    from jls.assessment.operation import AlphaTable
    from jls.assessment.voyage_plan import forecast_table
    stats, hours, hp, limit = plan_inputs(np.ones(10))
    table = AlphaTable("test table", [1.0, 100.0], [1.0, 10.0], [[0.8, 0.9], [0.8, 0.9]])
    m = forecast_table(stats, hp, ["only"], limit, xr.DataArray([False, False], dims="criterion",
                                                                 coords={"criterion": ["sway", "roll"]}),
                       [5.0, 7.0], [12.0], table)
    # option a: sway 1 m per m against 3 m (roll 0.2 deg per m against 1 deg): OP_LIM 3 m;
    # option b: 2 m per m: 1.5 m; alpha read at OP_LIM: 0.8 + 0.1 (3 - 1) / 9, 0.8 + 0.1 0.5 / 9
    assert m["master_hs_oplim"].sel(candidate="a").values.tolist() == [[3.0, 3.0]]
    assert m["master_hs_oplim"].sel(candidate="b").values.tolist() == [[1.5, 1.5]]
    assert float(m["master_alpha"].sel(candidate="a", leg="only", tz=5.0)) == pytest.approx(0.8 + 0.1 * 2 / 9)
    assert float(m["master_hs_opwf"].sel(candidate="b", leg="only", tz=7.0)) == pytest.approx(1.5 * (0.8 + 0.1 * 0.5 / 9))


def test_an_hour_whose_forecast_window_lacks_a_record_is_not_counted_as_barred():
    u = np.full(100, 0.5)
    u[40:45] = np.nan                                       # a gap of 5 h
    d = one_leg(u, 10, horizon=10)
    # the starts 31..44 see the gap in their window: neither allowed nor barred
    assert (d.immediate[0, 31:45] == -1).all()
    assert (d.immediate[0, :31] == 1).all() and (d.immediate[0, 45:91] == 1).all()
    s = summarise(d, np.ones(100, int))
    assert s["departure_fraction"][0] == 1.0
    # and their voyages, which wait through the gap or sail into it, are not judged
    assert (d.status[0, 31:45] == NOT_JUDGED).all()
