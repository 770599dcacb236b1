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
