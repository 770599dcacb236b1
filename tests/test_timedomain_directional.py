"""Time-domain records of a two-system directional sea (jls.timedomain.directional): each
component from one direction drawn from the systems' spreading, met at its RAO heading; a
record's relative-sway variance is that of its draws (periodic steady state), and it
reproduces the frequency-domain sigma of the same sea within the spread of the draws."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import plant_from_config, settings_from_config
from jls.response.sea_state import sea_state_moments, sea_state_transfer
from jls.response.solver import relative_power
from jls.sea.headings import rao_grid
from jls.sea.sea_state import wave_system
from jls.stages.plant import plant as plant_dataset
from jls.stages.vessel_motion import vessel_motion
from jls.timedomain.directional import DirectionalCase, direction_spread, heading_shares
from jls.vessel.transfer import motion_on_grid

ROOT = Path(__file__).resolve().parents[1]


def test_a_two_system_directional_record_reproduces_the_frequency_domain_sigma(cfg):
    plant = plant_from_config(cfg)
    motion = vessel_motion(cfg["vessel"], rao_grid(np.arange(0.0, 181.0, 15.0)), base_dir=ROOT)
    settings = replace(settings_from_config(cfg), amplitudes="deterministic")
    systems = [wave_system("jonswap", 0.6, "tp", 7.0, gamma=3.3, from_deg=250.0, spreading="cos2s:4"),
               wave_system("jonswap", 0.15, "tp", 15.0, gamma=5.0, from_deg=300.0, spreading="cos2s:13",
                           kind="swell")]
    case = DirectionalCase(plant, motion, systems, 200.0, duration_s=3600.0, settings=settings)
    r = case.run(None)
    assert r["limit_fraction"] == 0.0 and r["slack_events"] == 0
    real = case.realisation
    w = real.omega
    # the components meet several RAO headings (a multi-directional record, not one direction)
    assert np.unique(case.heading_index).size >= 5
    gm = motion_on_grid(motion, case.headings, w)
    P = relative_power(plant.M, plant.K, plant.Kb, plant.C, w, gm.hinge, gm.fairlead_sway, [0.0])[0, 0, :, 0, :]
    A = heading_shares(systems, 200.0, case.headings, w)
    drawn, spread = direction_spread(real, case.heading_index, P.T, A)
    # the record's variance is that of its own draws (linear plant, periodic steady state)
    assert r["sigma"] ** 2 == pytest.approx(drawn, rel=0.03)
    # the frequency domain of the same sea on the solver's grid ...
    ds = plant_dataset(cfg).isel(candidate=[0])
    tr = sea_state_transfer(ds, motion, {"none": 0.0}, cfg["response"]["omega_step_rad_s"],
                            cfg["vessel"]["outside_rao_range"])
    fd = float(sea_state_moments(tr, [systems], 200.0)[0][0, 0, 0, 0])
    # ... equals the expectation over the draws on the components' grid within 3 %
    expected = float((A * 0.5 * real.amplitude[:, None] ** 2 * P.T).sum())
    assert expected == pytest.approx(fd, rel=0.03)
    # and the record lies within four standard deviations of the direction draws of it
    assert abs(drawn - expected) <= 4 * spread
    assert abs(r["sigma"] ** 2 - fd) <= 4 * spread + 0.06 * fd
