"""Tugger settings, setpoint law and loads in the frequency domain (chapter 6)."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import settings_from_config, tuggers_from_config
from jls.config.loader import load
from jls.errors import InputError
from jls.response.solver import transfer_functions
from jls.tugger.loads import fixed_line_force, frequency_domain_loads, load_transfer
from jls.tugger.setting import STUDY_SETTINGS, Tugger, settings_table, tension

CONFIG = Path(__file__).resolve().parents[1] / "config" / "config.yaml"


def study_tuggers():
    return [Tugger(name, c, max_force=cap) for name, (c, cap) in STUDY_SETTINGS.items()]


def test_table_6_3_saturation_speed_and_net_force():
    ds = settings_table(study_tuggers())
    # Section 6.4: the net force stops growing at 3.27, 0.98 and 0.99 m/s of pay-out speed
    # and is capped at 980, 980 and 1980 kN; pretension 510, 510, 1010 kN.
    np.testing.assert_allclose(ds["saturation_velocity"], [3.27, 0.98, 0.99], atol=0.005)
    np.testing.assert_allclose(ds["net_force_limit"], [980, 980, 1980])
    np.testing.assert_allclose(ds["pretension"], [510, 510, 1010])


def test_setpoint_law_is_a_damper_between_its_limits():
    t = Tugger("reference", 1000.0)
    u = np.linspace(-0.9, 0.9, 7)                       # inside the 0.98 m/s linear range
    net = tension(t, -u) - tension(t, u)                # port pays out -u, starboard +u
    np.testing.assert_allclose(net, -1000.0 * u, atol=1e-9)
    assert tension(t, 50.0) == t.max_force and tension(t, -50.0) == t.min_force


def test_configured_settings_are_the_study_table():
    tugs = tuggers_from_config(load(CONFIG))
    for name, (c, cap) in STUDY_SETTINGS.items():
        assert tugs[name].c == c and tugs[name].max_force == cap and tugs[name].min_force == 20
    assert not tugs["none"].active


def test_capacity_below_floor_is_an_input_error():
    cfg = {"tuggers": [{"name": "x", "c_kN_s_per_m": 100, "max_force_kN": 10, "min_force_kN": 20,
                        "lag_s": 0.0, "attachment_half_width_m": 22.5}]}
    with pytest.raises(InputError, match=r"tuggers\[0\]\.max_force_kN"):
        tuggers_from_config(cfg, "my.yaml")


def test_fixed_line_force_table_6_1():
    # Table 6.1 in tonnes-force, M_i = 7719 t. The study's 5.5 s row (1016 t) is 1.1 %
    # below M_i w^2 X / g; the other rows agree to 0.6 %.
    table = {5.5: 1016, 8.0: 485, 10.0: 311, 10.9: 260, 15.7: 126}
    F = fixed_line_force(7719.0, list(table), [1.0, 2.0, 3.0]) / 9.81
    np.testing.assert_allclose(F.sel(amplitude=1.0), list(table.values()), rtol=0.012)
    np.testing.assert_allclose(F.sel(amplitude=3.0), 3 * F.sel(amplitude=1.0))


def sdof(m=7719.0, period=15.7):
    wn = 2 * np.pi / period
    M = np.diag([m, m, 4.55e6, 3.286e6])
    K = np.diag([m * wn**2, 2.3e5, 1.2e8, 1.0e7])
    C = np.zeros((4, 4))                                # the tugger is the only damper
    return M, K, -K, C, wn


def test_damper_only_plant_matches_closed_form_sdof():
    """m y'' + c (y' - y_f') + k (y - y_b) = 0 with y_b = y_f = 1: y = (k + iwc)/(k - w^2 m + iwc);
    the tugger force and the pay-out velocity follow from the relative motion."""
    M, K, Kb, C, wn = sdof()
    m, k, c = M[0, 0], K[0, 0], 1000.0
    omega = np.linspace(0.05, 2.0, 500)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0
    fl = np.ones((1, omega.size), complex)
    Hq, _ = transfer_functions(M, K, Kb, C, omega, qb, fl, [c])
    y = (k + 1j * omega * c) / (k - omega**2 * m + 1j * omega * c)
    np.testing.assert_allclose(Hq[0, 0, :, 0], y, rtol=1e-10)
    u, F = load_transfer(omega, Hq[:, 0, :, 0], fl[0], [c])
    np.testing.assert_allclose(F[0], -c * 1j * omega * (y - 1), rtol=1e-10)
    # Newton on the jacket: the spring and the tugger carry its inertia force.
    np.testing.assert_allclose(F[0] - k * (y - 1), -omega**2 * m * y, rtol=1e-9)
    np.testing.assert_allclose(u[0], 1j * omega * (y - 1), rtol=1e-10)


def test_loads_scale_with_hs_and_flag_saturation():
    M, K, Kb, C, wn = sdof()
    C = 0.0098 * 2 * M[0, 0] * wn * np.diag([1.0, 0, 0, 0]) + np.diag([0, 1e3, 1e5, 1e4])
    omega = np.linspace(0.05, 2.5, 3000)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 1.0
    fl = np.full((1, omega.size), 0.5 + 0j)
    tugs = [Tugger("weak", 1000.0, max_force=60.0), Tugger("strong", 1000.0, max_force=1e5)]
    Hq, _ = transfer_functions(M, K, Kb, C, omega, qb, fl, [t.c for t in tugs])
    ds = frequency_domain_loads(omega, Hq[:, 0, :, 0], fl[0], tugs, tz=[6.6, 12.0], hs=[1.0, 2.0])
    np.testing.assert_allclose(ds["mpm_force"].sel(hs=2.0), 2 * ds["mpm_force"].sel(hs=1.0))
    np.testing.assert_allclose(ds["power_mean"].sel(hs=2.0), 4 * ds["power_mean"].sel(hs=1.0))
    # Same slope, same loads; only the winch that cannot deliver the MPM force is flagged.
    np.testing.assert_allclose(ds["mpm_force"].sel(tugger="weak"), ds["mpm_force"].sel(tugger="strong"))
    weak = ds["saturates"].sel(tugger="weak").values
    assert weak.all() and not ds["saturates"].sel(tugger="strong").values.any()
    assert (ds["mpm_force"].sel(tugger="weak") > ds["force_available"].sel(tugger="weak")).all()
    # mean power = c sigma_u^2 and the force is c times the pay-out velocity
    np.testing.assert_allclose(ds["sigma_force"], 1000.0 * ds["sigma_payout_velocity"], rtol=1e-12)
    for v in ("sigma_force", "mpm_force", "power_mean", "saturates"):
        assert "units" in ds[v].attrs and "long_name" in ds[v].attrs


def test_slope_sweep_saturates_at_long_periods():
    """Section 6.5.1: at a fixed 1000 kN winch a steeper law spends more time at capacity,
    and the sway keeps falling with the slope."""
    from jls.config.builders import plant_from_config
    from jls.stages.vessel_motion import vessel_motion
    from jls.timedomain.sweep import critical_slope, slope_sweep
    cfg = load(CONFIG)
    plant = plant_from_config(cfg)
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=CONFIG.parents[1])
    assert abs(critical_slope(plant) / (2 * 7719 * 2 * np.pi / 15.70) - 1) < 1e-3
    sw = cfg["timedomain"]["slope_sweep"]
    ds = slope_sweep(plant, motion, [300.0, 1000.0, 3000.0], [8.5], 2.4, 90.0,
                     capacity_kN=sw["capacity_kN"], floor_kN=sw["floor_kN"], gamma=cfg["sea"]["gamma"],
                     duration_s=1800.0,
                     settings=replace(settings_from_config(cfg), transient_s=600.0,
                                      amplitudes="deterministic"))
    cap = ds["at_capacity_fraction"].sel(tz=8.5).values
    assert cap[0] <= cap[1] < cap[2] and cap[2] > 0
    assert np.all(np.diff(ds["sigma"].sel(tz=8.5).values) < 0)
    assert np.all(ds["sigma_reduction"].values > 0)


def test_saturation_flag_agrees_with_the_time_domain():
    """The reference winch (980 kN net) never reaches a limit at Tz 6.6 s and does at
    8.5 s (Hs 2.4 m); the frequency-domain flag says the same."""
    from jls.config.builders import plant_from_config
    from jls.stages.vessel_motion import vessel_motion
    from jls.timedomain.run import Case
    from jls.tugger.loads import plant_loads
    cfg = load(CONFIG)
    plant = plant_from_config(cfg)
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=CONFIG.parents[1])
    ref = tuggers_from_config(cfg)["reference"]
    ds = plant_loads(plant, motion, [ref], [6.6, 8.5], [2.4])
    flag = ds["saturates"].sel(tugger="reference", hs=2.4).values
    assert list(flag) == [0, 1]
    settings = replace(settings_from_config(cfg), amplitudes="deterministic")
    td = [Case(plant, motion, 2.4, tz, 90.0, gamma=cfg["sea"]["gamma"], duration_s=3600.0,
               settings=settings).run(ref)["limit_fraction"]
          for tz in (6.6, 8.5)]
    assert td[0] == 0.0 and td[1] > 0.0


@pytest.mark.parametrize("path, value, field", [
    (("tuggers", 1, "max_force_kN"), -5, "max_force_kN"),
    (("tuggers", 1, "lag_s"), 1000, "lag_s"),
    (("timedomain", "dt_s"), 0.0, "dt_s"),
    (("timedomain", "repeat"), "sometimes", "repeat"),
])
def test_schema_bounds_of_tugger_and_timedomain_keys(path, value, field):
    import copy

    from jls.config.loader import load_yaml, validate
    cfg = copy.deepcopy(load_yaml(CONFIG))
    node = cfg
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    with pytest.raises(InputError, match=field):
        validate(cfg, source="my.yaml")


def test_slope_sweep_ends_at_the_plants_critical_slope():
    """The study's last slope, 6178 kN s/m, is its own critical damping; the sweep ends at
    the plant's, 2 M w_n, and says so. The shipped plant sways at the study's 15.70 s, so
    its critical slope is the study's to 0.5 kN s/m."""
    from jls.config.builders import plant_from_config
    from jls.io import registry
    from jls.stages.tugger_studies import tugger_studies
    from jls.stages.vessel_motion import vessel_motion
    from jls.timedomain.sweep import critical_slope, sweep_slopes
    cfg = load(CONFIG)
    plant = plant_from_config(cfg)
    crit = critical_slope(plant)
    assert crit == pytest.approx(6178.0, abs=0.5)
    sw = cfg["timedomain"]["slope_sweep"]
    assert sw["end_at_critical"] is True and max(sw["slopes_kN_s_per_m"]) < 0.95 * crit
    slopes, left = sweep_slopes(plant, [300.0, 1000.0, 6178.0], True)
    np.testing.assert_array_equal(slopes, [300.0, 1000.0, crit])
    np.testing.assert_array_equal(left, [6178.0])
    slopes, left = sweep_slopes(plant, [300.0, 8000.0], True)
    np.testing.assert_array_equal(slopes, [300.0, crit])
    np.testing.assert_array_equal(left, [8000.0])
    slopes, left = sweep_slopes(plant, [300.0, 6178.0], False)
    np.testing.assert_array_equal(slopes, [300.0, 6178.0])
    assert left.size == 0
    cfg["timedomain"]["slope_sweep"] = {**sw, "slopes_kN_s_per_m": [1000.0, 6178.0], "tz_s": [6.6],
                                        "duration_h": 0.5}
    cfg["tuggers"] = [t for t in cfg["tuggers"] if t["name"] in ("none", "low")]
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=CONFIG.parents[1])
    ds = tugger_studies(cfg, motion)
    registry.check(ds, "tugger_studies")
    np.testing.assert_allclose(ds["slope"].values, [1000.0, crit])
    assert ds.attrs["critical_slope_kN_s_per_m"] == pytest.approx(crit)
    assert ds.attrs["sweep_ends_at_critical"] == 1
    assert "6178 kN s/m" in ds.attrs["sweep_note"]
    assert "nonlinear static equilibrium" in ds.attrs["decay_release_state"]
    assert (ds["decay_initial_heave"] > 0).all()
    # critical damping does more than the reference slope at the design period
    mpm = ds["sweep_mpm"].sel(sweep_tz=6.6).values
    assert mpm[1] < mpm[0] < float(ds["sweep_mpm_no_tugger"].sel(sweep_tz=6.6))
    # a sweep record too short for the resonance is refused, naming its key
    cfg["timedomain"]["slope_sweep"]["duration_h"] = 0.3
    with pytest.raises(InputError, match=r"timedomain\.slope_sweep\.duration_h"):
        tugger_studies(cfg, motion)
