"""Verification in the pipeline (jls.stages.verification_cell, workflow/rules/verification.smk):
the choice of cells on a constructed workability, the cell dataset against the registry,
the optimised candidate rebuilt from the assessed plant, the dataset written where
MoorDyn cannot be imported, and (slow) the shipped default route end to end."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.config.builders import candidate_plant, rigging_from_config
from jls.errors import InputError
from jls.io import registry
from jls.io.netcdf import read, write
from jls.plant.candidates import plant_dataset
from jls.stages.verification_cell import cell_dataset, cell_plant, choose_cells
from jls.stages.vessel_motion import vessel_motion
from jls.verify import reference_available
from jls.verify.cell import LAYOUT, parse_cell

ROOT = Path(__file__).resolve().parents[1]
C_TUGGER = {"none": 0.0, "low": 300.0}


def constructed(best="detuned"):
    """Workability of two candidates and two tuggers on two legs: ``best`` with the low
    tugger has the highest route workability; utilisations chosen per combination."""
    cands, tugs, legs = ["baseline", "detuned"], ["none", "low"], ["north", "south"]
    hs, tz = np.array([0.75, 1.25, 1.75]), np.array([6.5, 7.5, 8.5])
    u = np.full((2, 2, 2, 1, 3, 3), 0.3)
    u[0, 0, 1, 0, 1, 1] = 0.99           # baseline / none: nearest 1 on leg south, Hs 1.25, Tz 7.5
    u[0, 0, 0, 0, 2, 2] = 1.2
    u[1, 1, 0, 0, 0, 2] = 1.02           # detuned / low: Hs 0.75, Tz 8.5 on leg north
    u[1, 1, 1, 0, 0, 2] = 1.05           # the same cell on leg south: counted once
    u[1, 1, 0, 0, 2, 0] = 0.999          # ... but a dead cell (no probability) is nearer
    u[1, 1, 1, 0, 2, 0] = 0.999
    wr = np.array([[0.90, 0.92], [0.93, 0.95]])
    if best != "detuned":
        wr = wr[::-1]
    work = xr.Dataset(
        {"utilisation": (("candidate", "tugger", "leg", "heading", "hs", "tz"), u),
         "workability_route": (("candidate", "tugger"), wr)},
        coords={"candidate": cands, "tugger": tugs, "leg": legs, "heading": [90.0], "hs": hs, "tz": tz})
    work["utilisation"] = work["utilisation"].expand_dims(criterion=["relative_sway_m"], axis=-1)
    work.attrs.update(max_saturation_fraction=0.01, winch_saturation="timedomain",
                      tugger_min_gain=0.0, tie_tolerance=1e-9)   # any gain earns a tugger its place
    prob = np.ones((2, 1, 3, 3))
    prob[:, 0, 2, 0] = 0.0
    sea = xr.Dataset({"cell_probability": (("leg", "heading", "hs", "tz"), prob),
                      "hs_upper": (("leg", "hs"), np.tile(hs + 0.25, (2, 1)))},
                     coords={"leg": legs, "heading": [90.0], "hs": hs, "tz": tz})
    plant = xr.Dataset({"feasible": ("candidate", [True, True]), "infeasible_reason": ("candidate", ["", ""])},
                       coords={"candidate": cands})
    return work, sea, plant


def settings(**kw):
    v = {"enabled": True, "combinations": ["recommendation", "baseline"], "boundary_cells": 1,
         "design_corner": {"enabled": False, "hs_m": 2.4, "tz_s": 6.6, "heading_deg": 90},
         "max_cells": 20, "stressed_cells": False}
    v.update(kw)
    return {"verification": v, "sea": {"hs_in_bin": "centre"}}


def test_checkpoint_chooses_the_boundary_cells_of_the_recommendation_and_the_baseline():
    work, sea, plant = constructed()
    cells = choose_cells(work, sea, plant, C_TUGGER, settings())
    assert [c["name"] for c in cells] == ["detuned__low__h90__hs0.75__tz8.5",
                                         "baseline__none__h90__hs1.25__tz7.5"]
    assert [c["roles"] for c in cells] == [["recommendation"], ["baseline"]]
    assert "utilisation 1.020, leg north" in cells[0]["reasons"][0]
    assert "utilisation 0.990, leg south" in cells[1]["reasons"][0]
    assert all(parse_cell(c["name"])["tugger"] == c["tugger"] for c in cells)
    # the recommendation follows the workability: the baseline rigging with the low tugger
    work, sea, plant = constructed(best="baseline")
    cells = choose_cells(work, sea, plant, C_TUGGER, settings(combinations=["recommendation"]))
    assert [(c["candidate"], c["tugger"]) for c in cells] == [("baseline", "low")]


def test_choice_merges_roles_adds_the_design_corner_and_is_bounded():
    work, sea, plant = constructed()
    cells = choose_cells(work, sea, plant, C_TUGGER, settings(
        combinations=["baseline", {"candidate": "baseline", "tugger": "none"}], boundary_cells=2,
        design_corner={"enabled": True, "hs_m": 2.4, "tz_s": 6.6, "heading_deg": 90}))
    names = [c["name"] for c in cells]
    assert names == ["baseline__none__h90__hs1.25__tz7.5", "baseline__none__h90__hs1.75__tz8.5",
                     "baseline__none__h90__hs2.4__tz6.6"]
    assert cells[0]["roles"] == ["baseline", "configured"] and cells[2]["reasons"] == ["design corner"]
    assert choose_cells(work, sea, plant, C_TUGGER, settings(enabled=False)) == []
    with pytest.raises(InputError, match="verification.max_cells"):
        choose_cells(work, sea, plant, C_TUGGER, settings(boundary_cells=3, max_cells=4))
    with pytest.raises(InputError, match=r"verification.combinations\[0\]"):
        choose_cells(work, sea, plant, C_TUGGER, settings(combinations=[{"candidate": "x", "tugger": "none"}]))
    with pytest.raises(InputError, match="design_corner.heading_deg"):
        choose_cells(work, sea, plant, C_TUGGER, settings(
            design_corner={"enabled": True, "hs_m": 2.4, "tz_s": 6.6, "heading_deg": 45}))


def test_legs_of_their_own_sea_are_refused_with_the_reason_not_verified_on_a_jonswap():
    """The reference runs a long-crested JONSWAP: a partitions (or measured, Torsethaugen)
    leg's cells are left out, the reason stated; the other legs keep theirs."""
    from jls.stages.verification_cell import refused_legs
    work, sea, plant = constructed()
    cells = choose_cells(work, sea, plant, C_TUGGER, settings(), refused=["south"])
    # the baseline's nearest cell was on leg south: now the nearest of leg north
    assert all("leg south" not in r for c in cells for r in c["reasons"])
    assert [c["name"] for c in cells][0] == "detuned__low__h90__hs0.75__tz8.5"
    assert "leg north" in cells[1]["reasons"][0] and cells[1]["name"] != "baseline__none__h90__hs1.25__tz7.5"
    # every leg refused: no cell but the configured design corner
    only = choose_cells(work, sea, plant, C_TUGGER, settings(
        design_corner={"enabled": True, "hs_m": 2.4, "tz_s": 6.6, "heading_deg": 90}), refused=["north", "south"])
    assert [c["reasons"] for c in only] == [["design corner"], ["design corner"]]
    text = refused_legs({"south": "partitions"})
    assert text.startswith("south (partitions): ") and "left out" in text and "JONSWAP" in text
    assert refused_legs({}) == ""


def test_stressed_cells_are_the_design_corner_and_the_heaviest_legs_largest_workable_sea():
    work, sea, plant = constructed()
    # every criterion holds where the utilisation is at most 1
    work["passes"] = (work["utilisation"].max("criterion") <= 1).astype("int8")
    # leg south is the heavier: its Hs 1.75 cells carry more probability
    sea["cell_probability"].loc[{"leg": "south", "hs": 1.75}] = 5.0
    work["utilisation"].loc[{"candidate": "baseline", "tugger": "none", "leg": "south", "hs": 1.75,
                             "tz": 8.5}] = 0.8
    work["passes"] = (work["utilisation"].max("criterion") <= 1).astype("int8")
    cells = choose_cells(work, sea, plant, C_TUGGER, settings(combinations=["baseline"], boundary_cells=0,
                                                              stressed_cells=True))
    # baseline / none: the workable cell of the highest utilisation is 0.99 (south, Hs 1.25,
    # Tz 7.5); the largest workable sea of leg south is Hs 1.75, at the Tz of the highest
    # utilisation there (0.8 at Tz 8.5 against 0.3)
    assert [c["name"] for c in cells] == ["baseline__none__h90__hs1.25__tz7.5",
                                         "baseline__none__h90__hs1.75__tz8.5"]
    assert "design corner" in cells[0]["reasons"][0] and "0.990" in cells[0]["reasons"][0]
    assert "heaviest leg (south" in cells[1]["reasons"][0]
    # nothing workable: no stressed cell
    work["passes"][:] = 0
    assert choose_cells(work, sea, plant, C_TUGGER, settings(combinations=["baseline"], boundary_cells=0,
                                                             stressed_cells=True)) == []


def test_schema_defaults_verify_the_recommendation_and_the_baseline(cfg):
    v = cfg["verification"]
    assert v["enabled"] is True and v["combinations"] == ["recommendation", "baseline"]
    assert v["boundary_cells"] == 1 and v["tolerance"] == 0.1 and v["duration_s"] == 1200


def test_optimised_is_rebuilt_from_the_assessed_plant(cfg):
    values = {"baseline": {}, "optimised": {"top_spread_y": 27.40, "drop_height": 65.71}}   # detuned's
    ds, _ = plant_dataset(rigging_from_config(cfg), values)
    p = cell_plant(cfg, "optimised", ds)
    ref = candidate_plant(cfg, "detuned")                 # the same design, configured
    np.testing.assert_allclose(p.K, ref.K, rtol=1e-10, atol=1e-12 * np.abs(ref.K).max())
    np.testing.assert_allclose(p.modes.period, ref.modes.period, rtol=1e-10)
    with pytest.raises(InputError, match="no such rigging candidate"):
        cell_plant(cfg, "optimised", None)


def test_jls_verify_takes_the_optimised_candidate_from_an_assessed_plant(cfg, tmp_path):
    """``jls verify --candidate optimised --assessed-plant plant_assessed.nc`` rebuilds the
    screening's optimum as the pipeline's cells do; without the file it is refused with
    the option named."""
    from jls.commands.verify import candidate_plant as verify_plant
    values = {"baseline": {}, "optimised": {"top_spread_y": 27.40, "drop_height": 65.71}}
    ds, _ = plant_dataset(rigging_from_config(cfg), values)
    path = tmp_path / "plant_assessed.nc"
    write(ds, path, config_sha256="0" * 64, created_by="test")
    p, wires = verify_plant(cfg, "optimised", "config/config.yaml", path)
    ref = candidate_plant(cfg, "detuned").K
    np.testing.assert_allclose(p.K, ref, rtol=1e-10, atol=1e-12 * np.abs(ref).max())
    assert len(wires) == 4
    with pytest.raises(InputError, match="--assessed-plant"):
        verify_plant(cfg, "optimised", "config/config.yaml")
    with pytest.raises(InputError, match="no such rigging candidate in the assessed plant"):
        verify_plant(cfg, "other", "config/config.yaml", path)


def test_start_up_transient_with_a_tugger_follows_the_damped_rom(cfg):
    from jls.verify.chapter4 import transient_s
    p = candidate_plant(cfg, "detuned")
    i = int(np.argmax(p.modes.energy_fraction[:, 0]))
    assert transient_s(p) == pytest.approx(5 / (p.damping_ratio[i] * 2 * np.pi / p.modes.period[i]))
    assert transient_s(p, 5, 0.0) == transient_s(p)
    # a 300 kN s/m damper quadruples the sway's decay rate; the slowest mode is then
    # another, and the transient about a quarter of the undamped one
    assert 0.15 < transient_s(p, 5, 300.0) / transient_s(p) < 0.35
    assert transient_s(p, 5, 1000.0) <= transient_s(p, 5, 300.0)


def _short(cfg):
    out = json.loads(json.dumps(cfg))
    out["verification"].update(duration_s=120.0, transient_time_constants=0.5, harmonic_periods_s=[],
                               trace_s=60.0)
    return out


@pytest.mark.skipif(not reference_available()[0], reason="MoorDyn cannot be imported")
def test_cell_dataset_follows_the_registry(cfg, tmp_path):
    c = _short(cfg)
    motion = vessel_motion(c["vessel"], [90.0], base_dir=ROOT)
    cell = parse_cell("detuned__low__h90__hs1.25__tz7.5")
    ds = cell_dataset(c, motion, cell)
    registry.check(ds, LAYOUT)
    declared = registry.layout(LAYOUT)["variables"]
    missing = set(declared) - set(ds.data_vars) - {"harmonic_gain", "harmonic_phase"}
    assert not missing, missing              # a verified cell carries every result
    for var in ds.variables:                 # every attribute from the registry
        assert ds[var].attrs.get("long_name") == {**declared, **registry.layout(LAYOUT)["coordinates"]}[var]["long_name"]
    assert ds.attrs["status"] == "verified" and ds.attrs["tugger"] == "low"
    assert float(ds["tugger_limit_fraction"]) >= 0.0
    assert abs(float(ds["sigma_ratio"]) - 1) < 0.1 and bool(ds["verified"])
    # both models' free decay carry the tugger: damping several times the sway's own (the
    # reference's lines pull along their own direction, the ROM's damper along the sway:
    # about 10 % apart on this rigging)
    z = ds["decay_damping_ratio"]
    sway = float(ds["damping_ratio_rom"].where(ds["rom_dominant_dof"] == "sway", drop=True).item())
    assert min(float(z.sel(model="rom")), float(z.sel(model="reference"))) > 4 * sway
    assert float(z.sel(model="rom")) == pytest.approx(float(z.sel(model="reference")), rel=0.15)
    write(ds, tmp_path / "c.nc", config_sha256="0" * 64, created_by="test", dataset=LAYOUT)
    assert float(read(tmp_path / "c.nc")["mpm_ratio"]) == pytest.approx(float(ds["mpm_ratio"]))


def test_without_moordyn_the_cell_says_so(cfg, monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "moordyn", None)          # import moordyn now fails
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=ROOT)
    ds = cell_dataset(cfg, motion, parse_cell("baseline__none__h90__hs1.25__tz7.5"))
    registry.check(ds, LAYOUT)
    assert ds.attrs["status"] == "unavailable" and "pip install moordyn" in ds.attrs["reason"]
    assert not bool(ds["verified"]) and np.isnan(float(ds["sigma_ratio"]))
    write(ds, tmp_path / "c.nc", config_sha256="0" * 64, created_by="test", dataset=LAYOUT)


@pytest.mark.skipif(not reference_available()[0], reason="MoorDyn cannot be imported")
def test_jls_verify_one_case_from_the_command_line(tmp_path):
    over = tmp_path / "over.yaml"
    over.write_text("verification: {tolerance: 0.05, dt_s: 0.04}\n")
    r = subprocess.run([sys.executable, "-m", "jls.cli", "verify", "--config", str(over),
                        "--candidate", "detuned", "--tugger", "low", "--hs", "0.75", "--tz", "9.5",
                        "--duration-h", "0.05", "--transient-s", "100", "--harmonic-period-s", "--json"],
                       cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
    out = json.loads(r.stdout)
    assert out["cell"] == "detuned__low__h90__hs0.75__tz9.5" and out["status"] == "verified"
    v = out["verdict"]
    assert v["tolerance"] == 0.05 and v["verified"] and v["within_tolerance"] == (abs(v["mpm_ratio"] - 1) <= 0.05
                                                                                  and abs(v["sigma_ratio"] - 1) <= 0.05)
    assert "harmonic" not in out and set(out["natural_period_reference_s"]) >= {"surge", "pitch"}


# -- the shipped default route, end to end ----------------------------------------------
def _snakemake(cwd, *args, env=None):
    return subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", *args], cwd=cwd,
                          capture_output=True, text=True, env=env)


def _planned(cwd):
    r = _snakemake(cwd, "-n")
    assert r.returncode == 0, r.stderr[-3000:]
    return [p.strip() for line in (r.stdout + r.stderr).splitlines() if line.strip().startswith("output:")
            for p in line.split(":", 1)[1].split(",")]


@pytest.mark.slow
def test_default_route_verifies_and_the_report_receives_the_cells(default_run, tmp_path, monkeypatch):
    import os

    import yaml
    from conftest import copy_run
    work = copy_run(default_run, tmp_path / "jls")      # the clean run, this test's own copy
    res = work / "results" / "default" / "verification"
    cells = json.loads((res / "cells.json").read_text())
    roles = {role for c in cells for role in c["roles"]}
    assert {"recommendation", "baseline"} <= roles
    for c in cells:
        ds = read(res / f"{c['name']}.nc")
        registry.check(ds, LAYOUT)
        assert ds.attrs["status"] == "verified" and abs(float(ds["mpm_ratio"]) - 1) < 0.1
        # the contract: a verdict of the three, and a verified cell's reference damped as stated
        assert ds.attrs["verdict"] in ("verified", "not comparable", "outside tolerance")
        off = np.abs(ds["damping_ratio_achieved"] / ds["damping_ratio_target"] - 1)
        assert (ds.attrs["verdict"] != "verified") or bool((off <= 0.02).all())
    corner = [c for c in cells if "recommendation" in c["roles"]
              and any(r.startswith("design corner: the workable cell") for r in c["reasons"])]
    assert len(corner) == 1
    assert read(res / f"{corner[0]['name']}.nc").attrs["verdict"] == "verified"
    # the study comparison beside the cells' folder (every file in it is a cell)
    assert (res.parent / "verification_study.nc").exists() and len(list((res / "wires").glob("*.nc"))) == len(
        {(c["candidate"], c["tugger"]) for c in cells})
    # its parts, each a job of its own, assemble into it number for number
    from jls.verify import study
    from jls.verify.names import STUDY_PARTS
    parts = [read(res.parent / "verification_study" / f"{p}.nc") for p in STUDY_PARTS]
    whole = read(res.parent / "verification_study.nc")
    again = study.assemble(parts, tolerance=whole.attrs["tolerance"])
    for v in whole.data_vars:
        np.testing.assert_array_equal(whole[v].values, again[v].values, err_msg=v)
    for k in ("linear_range_hs_inside_m", "linear_range_hs_leaves_m", "linear_range_mpm_inside_m"):
        np.testing.assert_equal(whole.attrs[k], again.attrs[k])
    log = (work / "logs" / "default" / "report.log").read_text()
    assert f"{len(cells)} verification cells: " in log
    assert all(f"{c['name']} (verified)" in log for c in cells)
    assert _planned(work) == []

    # Where MoorDyn cannot be imported, the job writes a dataset that says so.
    fake = tmp_path / "nomoordyn"
    fake.mkdir()
    (fake / "moordyn.py").write_text("raise ImportError('moordyn made unimportable for the test')\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(fake), os.environ.get("PYTHONPATH", "")]))
    target = f"results/default/verification/{cells[0]['name']}.nc"
    r = _snakemake(work, "--force", target, env=env)
    assert r.returncode == 0, r.stderr[-3000:]
    ds = read(work / target)
    registry.check(ds, LAYOUT)
    assert ds.attrs["status"] == "unavailable" and "made unimportable" in ds.attrs["reason"]

    # A new design corner: the choice reruns, then only the corner's cells do.
    path = work / "config" / "config.yaml"
    cfg = yaml.safe_load(path.read_text())
    cfg["verification"] = {"design_corner": {"enabled": True, "hs_m": 2.0, "tz_s": 7.0}}
    path.write_text(yaml.safe_dump(cfg, sort_keys=False))    # the other settings as they were
    assert "results/default/verification/cells.json" in _planned(work)
    r = _snakemake(work, "results/default/verification/cells.json")
    assert r.returncode == 0, r.stderr[-3000:]
    plan = _planned(work)
    jobs = sorted(p for p in plan if p.startswith("results/default/verification/"))
    combos = sorted({(c["candidate"], c["tugger"]) for c in cells})
    assert jobs == sorted(f"results/default/verification/{c}__{t}__h90__hs2__tz7.nc" for c, t in combos)
    assert sorted(set(plan) - set(jobs)) == ["reports/default.pdf"]
