"""Time-domain cells of legs whose sea is their own (jls.timedomain.cell_sea): a partitions
or Torsethaugen leg's cell runs on a multi-directional record of the leg's systems, and its
sigma reproduces the frequency-domain sigma of the same sea (sea_state_statistics) within
the statistical spread of the record; never a JONSWAP on the cell's (Hs, Tz)."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import plant_from_config, settings_from_config, tuggers_from_config
from jls.config.loader import load
from jls.errors import InputError
from jls.response.solver import relative_power
from jls.sea.headings import rao_grid
from jls.sea.records import leg_series
from jls.sea.sea_state import wave_system
from jls.stages.timedomain_cell import cell_dataset, choose_cells, directional_sigma
from jls.stages.vessel_motion import vessel_motion
from jls.timedomain.cell_sea import cell_hours, cell_systems
from jls.timedomain.cells import cell_name, parse_cell
from jls.timedomain.directional import DirectionalCase, direction_spread, heading_shares
from jls.vessel.transfer import motion_on_grid

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "config" / "examples" / "partitions_route.yaml"


@pytest.fixture(scope="module")
def pcfg():
    return load(ROOT / "config" / "config.yaml", EXAMPLE)


@pytest.fixture(scope="module")
def legs(pcfg):
    return {leg["name"]: leg for leg in pcfg["routes"]["synthetic_partitions"]["legs"]}


@pytest.fixture(scope="module")
def motion(pcfg):
    return vessel_motion(pcfg["vessel"], rao_grid(np.arange(0.0, 181.0, 15.0)), base_dir=ROOT)


def test_a_leg_cell_is_named_with_its_leg_and_parsed_back():
    name = cell_name("baseline", 90, 1.25, 7.5, "csv_partitions")
    assert name == "baseline__h90__hs1.25__tz7.5__leg-csv_partitions"
    assert parse_cell(name) == {"candidate": "baseline", "heading": 90.0, "hs": 1.25, "tz": 7.5,
                                "leg": "csv_partitions"}
    assert "leg" not in parse_cell("baseline__h90__hs1.25__tz7.5")
    with pytest.raises(InputError, match="leg-"):
        parse_cell("baseline__h90__hs1.25__tz7.5__other")


def test_choose_cells_names_a_model_legs_cell_by_its_leg(pcfg):
    import xarray as xr
    work = xr.Dataset({"utilisation": (("candidate", "tugger", "leg", "heading", "hs", "tz", "criterion"),
                                       np.full((1, 1, 2, 1, 1, 1, 1), 0.9))},
                      coords={"candidate": ["baseline"], "tugger": ["none"], "leg": ["a", "b"], "heading": [90.0],
                              "hs": [1.0], "tz": [7.5], "criterion": ["relative_sway_m"]})
    sea = xr.Dataset({"cell_probability": (("leg", "heading", "hs", "tz"), np.ones((2, 1, 1, 1)))},
                     coords=work.drop_vars("utilisation").drop_dims(["candidate", "tugger", "criterion"]).coords)
    hs = xr.DataArray([[1.25], [1.25]], dims=("leg", "hs"), coords={"leg": ["a", "b"]})
    cfg = {"timedomain": {"boundary_candidates": ["baseline"], "boundary_cells_per_leg": 1, "cells": [],
                          "max_cells": 10}, "assessment": {"winch_saturation": "fail"}}
    cells = choose_cells(work, sea, hs, cfg, model_legs=["b"])
    assert [c["name"] for c in cells] == ["baseline__h90__hs1.25__tz7.5", "baseline__h90__hs1.25__tz7.5__leg-b"]
    assert cells[1]["leg"] == "b" and "leg" not in cells[0]
    # a saturating cell sent to the time domain: a leg's own only where that leg has the cell
    work["winch_saturates"] = xr.ones_like(work["utilisation"].isel(criterion=0, drop=True), dtype=bool)
    cfg["assessment"]["winch_saturation"] = "timedomain"
    cfg["timedomain"]["boundary_cells_per_leg"] = 0
    for p_b, expected in ((1.0, ["baseline__h90__hs1.25__tz7.5", "baseline__h90__hs1.25__tz7.5__leg-b"]),
                          (0.0, ["baseline__h90__hs1.25__tz7.5"])):
        sea["cell_probability"].loc[dict(leg="b")] = p_b
        assert [c["name"] for c in choose_cells(work, sea, hs, cfg, model_legs=["b"])] == expected


def busy_cell(leg, series):
    """The leg's most populated (Hs, Tz) bin at the first of its headings holding two hours
    or more: (cell, hour weights, the bins' indices)."""
    edges_h, edges_t = leg["metocean"]["hs_edges_m"], leg["metocean"]["tz_edges_s"]
    ih = np.clip(np.searchsorted(edges_h, series["hs"], side="right") - 1, 0, len(edges_h) - 2)
    it = np.clip(np.searchsorted(edges_t, series["tz"], side="right") - 1, 0, len(edges_t) - 2)
    pairs, counts = np.unique(np.c_[ih, it], axis=0, return_counts=True)
    i, j = (int(x) for x in pairs[int(np.argmax(counts))])
    hs = 0.5 * (edges_h[i] + edges_h[i + 1])
    tz = 0.5 * (edges_t[j] + edges_t[j + 1])
    for h in leg["headings_deg"]:
        cell = {"candidate": "baseline", "heading": float(h), "hs": hs, "tz": tz}
        w = cell_hours(leg, series, cell)
        if np.count_nonzero(w) >= 2:
            return cell, w, (i, j)
    raise AssertionError("no heading of the leg holds two hours of its busiest bin")


def test_a_partitions_cell_is_the_weighted_mixture_of_its_hours(pcfg, legs):
    leg = legs["csv_partitions"]
    series = leg_series(leg, ROOT, gamma=pcfg["sea"]["gamma"])
    edges_h = leg["metocean"]["hs_edges_m"]
    cell, w, (i, j) = busy_cell(leg, series)
    hs = cell["hs"]
    systems, course, text = cell_systems(leg, cell, sea=pcfg["sea"], gamma=pcfg["sea"]["gamma"], base_dir=ROOT)
    # every hour in the cell lies in its bins; the mixture holds each hour's partitions
    inside = series[w > 0]
    assert np.all((inside["hs"] >= edges_h[i]) & (inside["hs"] <= edges_h[i + 1]))
    assert len(systems) >= np.count_nonzero(w) and {s.kind for s in systems} == {"wind", "swell"}
    assert {s.spreading.kind for s in systems} == {"cos2s"}           # spread, never long-crested
    # scaled to the cell's Hs; the swell keeps its Tp (no JONSWAP on the cell's Tz)
    assert 4 * np.sqrt(sum(s.m0() for s in systems)) == pytest.approx(hs, rel=1e-9)
    assert max(s.tp for s in systems if s.kind == "swell") > 10.0
    assert course == 0.0 and f"{np.count_nonzero(w)} hours" in text


def test_a_torsethaugen_cell_is_its_two_spread_systems(pcfg, legs):
    leg = legs["torsethaugen_table"]
    cell = {"candidate": "baseline", "heading": 90.0, "hs": 2.0, "tz": 14.0}
    systems, course, text = cell_systems(leg, cell, sea=pcfg["sea"], gamma=pcfg["sea"]["gamma"], base_dir=ROOT)
    assert [s.kind for s in systems] == ["swell", "wind"] and course == 0.0
    assert text.startswith("torsethaugen: ") and "Tp 14 s" in text
    assert all(s.from_deg == 90.0 for s in systems)                  # met at 90 deg on course 0
    assert 4 * np.sqrt(sum(s.m0() for s in systems)) == pytest.approx(2.0, rel=1e-6)
    with pytest.raises(InputError, match="JONSWAP"):
        cell_systems({**leg, "spectrum": "jonswap", "period": "tz"}, cell, sea=pcfg["sea"], gamma=3.3)


def test_time_domain_sigma_of_a_two_system_directional_sea_is_the_frequency_domain_one(pcfg, motion):
    """The record's sigma (nonlinear model, small sea) against sea_state_statistics of the
    same two spread systems, within four standard deviations of the direction draws and the
    component grid's resolution."""
    plant = plant_from_config(pcfg)
    settings = replace(settings_from_config(pcfg), amplitudes="deterministic")
    systems = [wave_system("jonswap", 0.5, "tp", 7.0, gamma=3.3, from_deg=230.0, spreading="cos2s:4"),
               wave_system("jonswap", 0.3, "tp", 14.0, gamma=5.0, from_deg=300.0, spreading="cos2s:13",
                           kind="swell")]
    tuggers = list(tuggers_from_config(pcfg).values())[:2]
    fd = directional_sigma(pcfg, "baseline", None, motion, tuggers, systems, 200.0)
    case = DirectionalCase(plant, motion, systems, 200.0, duration_s=3 * 3600.0, settings=settings)
    assert np.unique(case.heading_index).size >= 5                   # multi-directional
    real = case.realisation
    gm = motion_on_grid(motion, case.headings, real.omega)
    P = relative_power(plant.M, plant.K, plant.Kb, plant.C, real.omega, gm.hinge, gm.fairlead_sway,
                       [t.c for t in tuggers])[0, :, :, 0, :]
    A = heading_shares(systems, 200.0, case.headings, real.omega)
    for k, tug in enumerate(tuggers):
        r = case.run(tug)
        assert r["limit_fraction"] == 0.0
        _, spread = direction_spread(real, case.heading_index, P[k].T, A)
        # sigma^2 within 4 standard deviations of the draws plus 3 % for the component grid
        assert abs(r["sigma"] ** 2 - fd[k] ** 2) <= 4 * spread + 0.03 * fd[k] ** 2, (tug.name, r["sigma"], fd[k])
    # the swell at the sway period: the sea of both systems drives more than its wind sea alone
    wind_only = directional_sigma(pcfg, "baseline", None, motion, tuggers, systems[:1], 200.0)
    assert np.all(fd > 1.5 * wind_only)


@pytest.mark.slow
def test_a_partitions_cell_dataset_runs_on_the_legs_sea(pcfg, legs, motion):
    leg = legs["csv_partitions"]
    series = leg_series(leg, ROOT, gamma=pcfg["sea"]["gamma"])
    cell, _, _ = busy_cell(leg, series)
    cell = {**cell, "leg": "csv_partitions"}
    cfg = {**pcfg, "timedomain": {**pcfg["timedomain"], "seeds_per_cell": 1, "duration_h": 3.0,
                                  "amplitudes": "deterministic"}}
    ds = cell_dataset(cfg, motion, cell, leg=leg, base_dir=ROOT)
    assert ds.attrs["sea_leg"] == "csv_partitions" and ds.attrs["sea"].startswith("partitions:")
    assert ds.attrs["cell"].endswith("__leg-csv_partitions")
    # the direction draws' spread is reported, and the record lies within four of it of the
    # frequency-domain sigma of the same sea (plus 3 % for the component grid)
    std = ds["sigma_seed_std_expected"].values
    assert np.all(std > 0)
    fd = ds["sigma_fd"].values
    assert np.all(np.abs(ds["sigma"].values - fd) <= 4 * std + 0.03 * fd), (ds["sigma"].values, fd, std)
    # the swell drives the cell: far more sway than a long-crested JONSWAP on the cell's (Hs, Tz)
    from jls.timedomain.run import frequency_domain_sigma
    jonswap = frequency_domain_sigma(plant_from_config(pcfg), motion, list(tuggers_from_config(pcfg).values()),
                                     cell["hs"], cell["tz"], cell["heading"], pcfg["sea"]["gamma"])
    assert fd[0] > 2 * jonswap[0]
