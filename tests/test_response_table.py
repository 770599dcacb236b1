"""The response table (jls.response.response_table) against the exact per-hour path: every
criterion's sigma of random hours of two spread JONSWAP systems within the stated 0.5 %;
an hour of two systems is the sum of its systems' variances for the tip and the tensions
too; a table sea state at a grid Tp and an RAO heading is the exact one to round-off; the
hourly utilisation of many hours equals the exact path's; the rule keeps measured
spectra and few hours on the exact path; energy outside the RAO range is refused."""

import numpy as np
import pytest

from jls.config.builders import tip_settings_from_config
from jls.errors import InputError
from jls.response import response_table as rt
from jls.response.sea_state import heading_moments
from jls.response.sea_state_tip_tension import tip_tension_moments
from jls.sea.sea_state import SeaState, Spreading, WaveSystem

BOUND = 0.005           # the module's stated bound on sigma


@pytest.fixture(scope="module")
def tr(cfg):
    from jls.commands.response import transfer_from_config
    return transfer_from_config(cfg, ".")


def _hours(n, seed=3):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        out.append(SeaState((
            WaveSystem("jonswap", rng.uniform(0.3, 3.0), rng.uniform(4.0, 9.0), rng.uniform(0, 360),
                       Spreading("cos2s", 4.0), "wind", 3.3),
            WaveSystem("jonswap", rng.uniform(0.2, 2.0), rng.uniform(10.0, 18.0), rng.uniform(0, 360),
                       Spreading("cos2s", 13.0), "swell", 3.3))))
    return out, rng.uniform(0, 360, n)


def _settings(cfg):
    lever = np.subtract(cfg["vessel"]["hinge_m"], cfg["vessel"]["rao_reference_point_m"])[:2]
    return dict(tip=tip_settings_from_config(cfg), hinge_xy=lever, g=float(cfg["g_m_per_s2"]), tensions=True)


def _exact(tr, cfg, states, course):
    m0, m2 = heading_moments(tr, states, np.asarray(course, float))
    return m0, m2, tip_tension_moments(tr, states, course, **_settings(cfg))


def _table(tr, cfg, states, course):
    tp = [s.tp for st in states for s in st.systems]
    tab = rt.response_table(tr, rt.tp_grid(tp), 3.3, **_settings(cfg))
    return tab, rt.table_moments({3.3: tab}, states, course, tr=tr)


def test_random_hours_are_within_the_stated_bound_on_sigma_of_every_criterion(cfg, tr):
    states, course = _hours(40)
    m0, m2, ex = _exact(tr, cfg, states, course)
    _, t = _table(tr, cfg, states, course)
    worst = {}
    for name, a, b in (("motions", m0, t["m0"]), ("tip", ex["tip_m0"], t["tip_m0"]),
                       ("tension", ex["tension_m0"], t["tension_m0"]), ("wave", ex["wave_m0"], t["wave_m0"])):
        err = np.abs(np.sqrt(b) / np.sqrt(a) - 1.0)
        worst[name] = float(np.nanmax(err))
    assert max(worst.values()) < BOUND, worst
    assert worst["motions"] > 1e-6          # interpolated, not the exact path by another name
    np.testing.assert_allclose(t["m2"], m2, rtol=2 * BOUND)
    np.testing.assert_allclose(t["tip_m2"], ex["tip_m2"], rtol=4 * BOUND)
    np.testing.assert_allclose(t["tension_m2"], ex["tension_m2"], rtol=4 * BOUND)
    np.testing.assert_allclose(t["wave_t1"], ex["wave_t1"], rtol=1e-3)
    np.testing.assert_allclose(t["hs"], ex["hs"], rtol=1e-12)
    from jls.response.sea_state import energy_outside
    np.testing.assert_allclose(t["energy_outside"], energy_outside(tr, states), atol=1e-4)
    assert t["energy_outside"].max() > 1e-3                # the wind seas reach above the RAO range


def test_a_table_sea_at_a_grid_tp_and_an_rao_heading_is_exact_and_two_systems_add(cfg, tr):
    tab, _ = _table(tr, cfg, *_hours(3))
    tp = float(tab.tp[7])
    h = float(tr.exc.headings[3])
    # from (course + 180 - h) deg true: met at relative heading h; long-crested
    a = WaveSystem("jonswap", 1.7, tp, float(np.mod(200.0 + 180.0 - h, 360.0)), Spreading("long-crested"), "swell", 3.3)
    b = WaveSystem("jonswap", 1.1, float(tab.tp[2]), 10.0, Spreading("cos2s", 4.0), "wind", 3.3)
    t = rt.table_moments({3.3: tab}, [SeaState((a,)), SeaState((b,)), SeaState((a, b))], [200.0] * 3)
    ex = tip_tension_moments(tr, [SeaState((a,))], [200.0], **_settings(cfg))
    np.testing.assert_allclose(t["tip_m0"][0], ex["tip_m0"][0], rtol=1e-10)
    np.testing.assert_allclose(t["tension_m0"][0], ex["tension_m0"][0], rtol=1e-10)
    np.testing.assert_allclose(t["m0"][0], heading_moments(tr, [SeaState((a,))], np.array([200.0]))[0][0], rtol=1e-10)
    # the two systems' sea is the sum of its systems' variances, every output
    ex2 = tip_tension_moments(tr, [SeaState((a, b))], [200.0], **_settings(cfg))
    for k in ("tip_m0", "tension_m0", "wave_m0"):
        np.testing.assert_allclose(t[k][2], t[k][0] + t[k][1], rtol=1e-12)
        np.testing.assert_allclose(t[k][2], ex2[k][0], rtol=BOUND)


def test_many_hours_take_the_table_and_give_the_exact_utilisation(cfg, tr, monkeypatch):
    from jls.stages import hourly_seas
    states, course = _hours(30, seed=5)
    crit_e, u_e, v_e = hourly_seas.sea_state_utilisation(tr, cfg, states, course)
    monkeypatch.setattr(rt, "TABLE_HOURS", 10)
    monkeypatch.setattr(hourly_seas, "CHUNK", 7)                   # chunks of several sizes
    assert rt.use_table(states)
    crit_t, u_t, v_t = hourly_seas.sea_state_utilisation(tr, cfg, states, course)
    assert crit_t == crit_e
    assert not np.array_equal(u_t, u_e)
    np.testing.assert_allclose(u_t, u_e, rtol=2 * BOUND, atol=1e-9)
    np.testing.assert_allclose(v_t, v_e, rtol=2 * BOUND, atol=1e-6)
    assert u_t.dtype == np.float32 and u_e.dtype == np.float64
    # a leg of these hours on one course: the table's utilisation stored at the hour's heading
    leg = {"name": "p", "course_deg": 200.0, "headings_deg": [90.0, 270.0], "heading_probability": [0.5, 0.5]}
    w = np.zeros((30, 2))
    w[::2, 0] = w[1::2, 1] = 1.0
    ds = hourly_seas.leg_utilisation(tr, cfg, leg, states, w, directional=True)
    _, u_c, _ = hourly_seas.sea_state_utilisation(tr, cfg, states, [200.0] * 30)
    got = ds["utilisation"].values
    assert got.dtype == np.float32
    np.testing.assert_array_equal(got[::2, 0], u_c[::2])
    assert np.isnan(got[::2, 1]).all() and np.isnan(got[1::2, 0]).all()


def test_the_rule_keeps_measured_spectra_torsethaugen_and_few_hours_exact():
    states, _ = _hours(3)
    assert not rt.use_table(states)                                # few hours
    assert rt.use_table(states * (rt.TABLE_HOURS // 3 + 1))
    w = np.linspace(0.2, 2.0, 50)
    measured = WaveSystem("measured", 1.0, 10.0, 0.0, Spreading("long-crested"), omega=w, density=np.ones(50))
    assert not rt.use_table(states * rt.TABLE_HOURS + [SeaState((measured,))])
    tor = WaveSystem("torsethaugen", 1.0, 10.0, 0.0, Spreading("long-crested"), "swell", 2.0)
    assert not rt.use_table(states * rt.TABLE_HOURS + [SeaState((tor,))])


def test_energy_outside_the_rao_range_is_refused(cfg, tr):
    tab, _ = _table(tr, cfg, *_hours(3))
    lo = float(tr.exc.omega[0])
    tp = 2 * np.pi / lo * 1.6                          # a long swell peaking below the RAO range
    tab2 = rt.response_table(tr, rt.tp_grid([tp]), 3.3)
    s = SeaState((WaveSystem("jonswap", 2.0, tp, 0.0, Spreading("long-crested"), "swell", 3.3),))
    with pytest.raises(InputError, match="outside the RAO range"):
        rt.table_moments({3.3: tab2}, [s], [0.0], tr=tr, source="hours.csv")


def test_hours_with_a_missing_system_pm_and_two_gammas_match_the_exact_path(cfg, tr):
    rng = np.random.default_rng(9)
    s7 = Spreading("cos2s", 7.25)
    states = []
    for i in range(12):
        wind = WaveSystem("pm", rng.uniform(0.5, 2.5), rng.uniform(4.0, 8.0), rng.uniform(0, 360), s7, "wind")
        swell = WaveSystem("jonswap", rng.uniform(0.3, 1.5), rng.uniform(11.0, 17.0), rng.uniform(0, 360),
                           Spreading("long-crested"), "swell", 2.0)
        states.append(SeaState((wind, swell) if i % 3 else (swell,) if i % 2 else (wind,)))
    course = rng.uniform(0, 360, 12)
    tabs = {}
    for gamma in (1.0, 2.0):
        tp = [x.tp for st in states for x in st.systems if (1.0 if x.shape == "pm" else x.gamma) == gamma]
        tabs[gamma] = rt.response_table(tr, rt.tp_grid(tp), gamma, **_settings(cfg))
    t = rt.table_moments(tabs, states, course, tr=tr)
    m0, _, ex = _exact(tr, cfg, states, course)
    for a, b in ((m0, t["m0"]), (ex["tip_m0"], t["tip_m0"]), (ex["tension_m0"], t["tension_m0"])):
        assert np.nanmax(np.abs(np.sqrt(b / a) - 1.0)) < BOUND
    np.testing.assert_allclose(t["wave_t1"], ex["wave_t1"], rtol=1e-3)
