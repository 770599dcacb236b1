"""Free decay from a sway release (section 6.6)."""

import json
from pathlib import Path

import numpy as np
import pytest

from jls.cli import main
from jls.config.builders import plant_from_config
from jls.config.loader import load
from jls.timedomain.decay import decay, first_cycle_damping, time_to_fraction
from jls.tugger.setting import Tugger

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"
LOW, HIGH = Tugger("low", 300.0, 1000.0), Tugger("high", 2000.0, 2000.0)


@pytest.fixture(scope="module")
def plant():
    return plant_from_config(load(CONFIG))


@pytest.mark.parametrize("tugger, study_s", [(None, 581.0), (LOW, 95.0), (HIGH, 17.0)],
                         ids=["none", "low", "high"])
def test_time_to_10pct_reproduces_the_study(plant, tugger, study_s):
    d = decay(plant, tugger, release_m=3.0)
    assert abs(d.time_to_10pct / study_s - 1) < 0.10


def test_first_cycle_damping_is_plant_plus_tugger(plant):
    """Unsaturated (a 3 m release at 0.41 rad/s pays out at most 1.2 m/s, below the low
    setting's 3.27 m/s), the tugger adds c / (2 M w_n): about 1 % -> 5.5 % (section 6.6)."""
    i = int(plant.modes.mode_of("sway"))
    wn, zeta = plant.modes.omega[i], plant.damping_ratio[i]
    bare = decay(plant, None).zeta_first_cycle
    low = decay(plant, LOW).zeta_first_cycle
    assert abs(bare / zeta - 1) < 0.1
    assert abs(low / (zeta + LOW.c / (2 * plant.M[0, 0] * wn)) - 1) < 0.05
    assert abs(low / 0.055 - 1) < 0.1


def test_decay_is_exponential_without_tugger(plant):
    """A linear oscillator decays to 10 % in ln(10) / (zeta w_n), to within half a period."""
    i = int(plant.modes.mode_of("sway"))
    wn, zeta = plant.modes.omega[i], plant.damping_ratio[i]
    d = decay(plant, None)
    assert abs(d.time_to_10pct - np.log(10) / (zeta * wn)) < np.pi / wn


def test_actuator_lag_costs_damping(plant):
    ideal = decay(plant, LOW).time_to_10pct
    lagged = decay(plant, Tugger("low", 300.0, 1000.0, lag=4.0)).time_to_10pct
    assert lagged > ideal


def test_measures_on_a_constructed_record():
    t = np.linspace(0, 100, 100001)
    wn, z = 0.5, 0.05
    y = 2.0 * np.exp(-z * wn * t) * np.cos(wn * np.sqrt(1 - z**2) * t)
    assert abs(first_cycle_damping(y, 2.0) - z) < 1e-3
    assert np.isnan(time_to_fraction(t, y, 2.0, 0.01))
    t10 = time_to_fraction(t, y, 2.0, 0.1)
    assert abs(y[t <= t10][-1]) == pytest.approx(0.2, rel=1e-3)
    assert np.all(np.abs(y[t > t10 + 1e-3]) <= 0.2)


def test_cli_decay_json_contract(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    assert main(["decay", "--release-m", "3.0", "--json", "--config", str(CONFIG)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["tugger"] == ["none", "low", "reference", "high"]
    assert len(out["time_to_10pct_s"]) == 4
    t = dict(zip(out["tugger"], out["time_to_10pct_s"]))
    assert t["none"] > t["low"] > t["reference"] > t["high"] > 0
    assert out["c_kN_s_per_m"] == [0.0, 300.0, 1000.0, 2000.0]


def test_cli_decay_bad_release(capsys):
    assert main(["decay", "--release-m", "-3", "--json"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("jls: error:") and "--release-m" in err[0]


@pytest.mark.parametrize("release_m", [3.0, 10.0])
@pytest.mark.parametrize("tugger", [None, LOW, Tugger("lagged", 300.0, 1000.0, lag=4.0)],
                         ids=["none", "low", "lagged"])
def test_release_starts_from_the_nonlinear_static_equilibrium(plant, tugger, release_m):
    """Held at the offset in the time domain's own forces (exact wire geometry), the jacket
    starts with zero heave, roll and yaw acceleration (M is diagonal, so zero generalised
    forces are zero accelerations); only the sway is restored. A linear condensation
    leaves the pendulum's lift out: at 3 m it starts with a heave acceleration of about
    2.3 m/s^2 and 18 600 kN of extra wire tension, at 10 m it slackens wires."""
    from jls.timedomain import dynamics as dyn
    from jls.timedomain.run import initial_state, integrate_run, parameters
    d = decay(plant, tugger, release_m=release_m, duration_s=60.0)
    par = parameters(plant, tugger)
    x0 = initial_state(plant, tugger, q=d.q0)
    dx, info = np.empty(dyn.N_STATE), np.empty(dyn.N_INFO)
    dyn.deriv(x0, np.zeros(dyn.N_CH), par, dx, info)
    g = plant.g
    assert d.q0[0] == release_m and d.q0[1] > 0              # held, and lifted by the swing
    assert abs(dx[5]) < 1e-9 * g                             # heave
    assert abs(dx[6]) < 1e-12 and abs(dx[7]) < 1e-12          # roll, yaw [rad/s^2]
    k_sway = plant.K[0, 0]
    assert dx[4] < 0 and abs(dx[4] * plant.M[0, 0] / (-k_sway * release_m) - 1) < 0.25
    np.testing.assert_allclose(info[dyn.I_TWIRE:dyn.I_TWIRE + 4], d.wire_tension0)
    # the weight hangs on the wires, taut, with little extra tension in all
    assert np.all(d.wire_tension0 > 0.1 * plant.tension)
    assert abs(d.wire_tension0.sum() / plant.tension.sum() - 1) < 0.02
    _, raw, _ = integrate_run(par, x0, np.zeros((2 * 3000 + 1, dyn.N_CH)), 0.02, 3000, 0)
    assert dict(zip(dyn.STATS, raw))["slack_events"] == 0
    if tugger is None:
        K = plant.K
        lin = np.zeros(4)
        lin[0] = release_m
        lin[1:] = -np.linalg.solve(K[1:, 1:], K[1:, 0] * release_m)
        dyn.deriv(initial_state(plant, None, q=lin), np.zeros(dyn.N_CH), par, dx, info)
        assert dx[5] > 0.2 * release_m**2 / 9.0               # the condensation's heave kick
        assert info[dyn.I_TWIRE:dyn.I_TWIRE + 4].sum() > plant.tension.sum() + 4000 * release_m**2 / 9.0
