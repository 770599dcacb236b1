"""End-to-end: the Snakemake workflow on a tiny route, incremental reruns, bad input.

Each test copies the workflow into a temporary directory with a small configuration
(one or two legs, a few cells, a coarse frequency grid) so the repository is untouched.
"""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pypdf
import pytest
import yaml

from jls.io.netcdf import read

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow

LEG_A = """# layout: matrix
# hs_bins: edges
# tz_bins: edges
# values: counts
hs \\ tz,5.0-6.0,6.0-7.0,7.0-8.0
0.0-1.0,20,10,5
1.0-2.0,10,8,4
2.0-3.0,2,3,2
"""
LEG_B = """# layout: long
# hs_bins: centres
# tz_bins: centres
hs,tz,probability
0.5,6.5,0.5
1.5,6.5,0.3
2.5,7.5,0.2
"""


def tiny_config(tmp: Path) -> dict:
    cfg = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    cfg["candidates"] = [{"name": "detuned", "top_spread_y_m": 37.845, "drop_height_m": 65.71}]   # on its budget
    cfg.pop("screening", None)          # the screening's own end-to-end test turns it on
    cfg["tuggers"] = [{"name": "none", "c_kN_s_per_m": 0}, {"name": "reference", "c_kN_s_per_m": 1000}]
    cfg["response"] = {"omega_step_rad_s": 0.01}
    # Short time-domain records (still 2 wave components per sway half-power bandwidth for
    # the detuned candidate's 17.3 s) and a one-point slope sweep (and the critical slope)
    # keep the tiny run quick.
    cfg["timedomain"] = {**cfg["timedomain"], "duration_h": 0.6, "trace_s": 100,
                         "slope_sweep": {"slopes_kN_s_per_m": [1000], "tz_s": [6.6], "duration_h": 0.6}}
    # Verification on, with short records and no harmonic test; without the study's
    # comparison and the wires as wires (MoorDyn runs of minutes that no tiny-route test
    # reads: the default route's run checks both, tests/test_verification_pipeline.py).
    cfg["verification"] = {"duration_s": 120, "transient_time_constants": 1, "harmonic_periods_s": [],
                           "trace_s": 60, "study_comparison": False, "wires": {"enabled": False}}
    cfg["vessel"]["rao_file"] = str(ROOT / cfg["vessel"]["rao_file"])
    cfg["routes"] = {"tiny": {"description": "two short legs", "legs": [
        {"name": "north", "scatter": "tables/a.csv", "duration_h": 30, "headings_deg": [90]},
        {"name": "south", "scatter": "tables/b.csv", "duration_h": 10, "headings_deg": [90]}]}}
    return cfg


def make_workdir(tmp_path, cfg=None):
    """A copy of the workflow with the two tiny leg tables and ``cfg`` (default: the tiny
    configuration) in ``tmp_path``."""
    shutil.copy(ROOT / "Snakefile", tmp_path)
    shutil.copytree(ROOT / "workflow", tmp_path / "workflow")
    (tmp_path / "config").mkdir()
    (tmp_path / "tables").mkdir()
    (tmp_path / "tables" / "a.csv").write_text(LEG_A)
    (tmp_path / "tables" / "b.csv").write_text(LEG_B)
    cfg = tiny_config(tmp_path) if cfg is None else cfg
    (tmp_path / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    return tmp_path


@pytest.fixture()
def workdir(tmp_path):
    return make_workdir(tmp_path)


def snakemake(cwd, *args):
    return subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", *args], cwd=cwd,
                          capture_output=True, text=True)


def planned_outputs(cwd, *args):
    """Output files of the jobs a dry run (with ``args``) would execute."""
    r = snakemake(cwd, "-n", *args)
    assert r.returncode == 0, r.stderr
    text = r.stdout + r.stderr
    return [out.strip() for line in text.splitlines() if line.strip().startswith("output:")
            for out in line.split(":", 1)[1].split(",")]


def test_tiny_route_end_to_end_and_incremental_reruns(tiny_done):
    workdir = tiny_done              # the clean run (tests/conftest.py: tiny_run), a copy
    res = workdir / "results" / "tiny"
    for name in ("sea_states", "vessel_motion", "plant", "response", "operability", "workability"):
        ds = read(res / f"{name}.nc")
        assert ds.attrs["jls_version"] and len(ds.attrs["config_sha256"]) == 64
    pdf = workdir / "reports" / "tiny.pdf"
    work = read(res / "workability.nc")
    # The report's headline is the number in workability.nc.
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(pdf).pages).replace("\xa0", " ")
    base = 100 * work["workability_route"].sel(candidate="baseline", tugger="none").item()
    m = re.search(r"Route workability, baseline rigging, no tugger\s+(\d+\.\d) %", text)
    assert m and m.group(1) == f"{base:.1f}"
    assert read(res / "sea_states.nc").attrs["input_sha256_leg_north"] in text
    frac = work["workability_route"]
    assert np.all((frac >= 0) & (frac <= 1))
    # Damping never makes the relative sway worse in this linear model.
    mpm = read(res / "response.nc")["mpm"].sel(response="relative_sway")
    assert np.all(mpm.sel(tugger="reference") <= mpm.sel(tugger="none") * (1 + 1e-9))
    # Route fraction = duration-weighted mean of the legs (30 h and 10 h).
    legs = work["workability_leg"]
    np.testing.assert_allclose(frac, 0.75 * legs.sel(leg="north") + 0.25 * legs.sel(leg="south"))
    # Every step logged.
    assert (workdir / "logs" / "tiny" / "workability.log").read_text().count("route workability") == 4

    # Nothing to do on a second run.
    assert planned_outputs(workdir) == []

    # Probabilities only: sea states, the choice of time-domain cells (which depends on
    # the probabilities), aggregation, the voyage extremes, the voyage plan (its design
    # contours of a table leg) and report rerun; no response job.
    (workdir / "tables" / "a.csv").write_text(LEG_A.replace("20,10,5", "25,10,5"))
    plan = planned_outputs(workdir)
    assert sorted(plan) == sorted(["results/tiny/sea_states.nc", "results/tiny/timedomain/cells.json",
                                   "results/tiny/workability.nc", "results/tiny/voyage.nc",
                                   "results/tiny/voyage_plan.nc", "results/tiny/verification/cells.json",
                                   "reports/tiny.pdf"])

    # A new Tz column on leg 'south' (off the operability grid): the route's response job
    # reruns and evaluates that one sea state; plant and vessel do not rerun.
    (workdir / "tables" / "b.csv").write_text(LEG_B + "1.0,8.6,0.0\n")
    plan = planned_outputs(workdir)
    assert "results/tiny/response.nc" in plan
    assert "results/tiny/plant.nc" not in plan and "results/tiny/vessel_motion.nc" not in plan
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    log = (workdir / "logs" / "tiny" / "response.log").read_text()
    assert re.search(r"; 1 of \d+ sea states evaluated", log), log
    assert 8.6 in read(res / "response.nc")["tz"].values


SUBMIT = """#!/bin/sh
# A local stand-in for a batch scheduler: run the job script detached, print a job id.
nohup sh "$1" > "$1.out" 2>&1 &
echo $!
"""


def test_chunked_jobs_run_self_contained_through_a_cluster_executor(workdir):
    """Every job runs from its own job script, as on a cluster (the cluster-generic
    executor with a local submit command), the candidates in one response job each; the
    result equals the library's unchunked computation."""
    pytest.importorskip("snakemake_executor_plugin_cluster_generic")
    cfg = yaml.safe_load((workdir / "config" / "config.yaml").read_text())
    cfg["response"]["chunk_candidates"] = 1
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    submit = workdir / "submit.sh"
    submit.write_text(SUBMIT)
    submit.chmod(0o755)
    r = subprocess.run([sys.executable, "-m", "snakemake", "--executor", "cluster-generic",
                        "--cluster-generic-submit-cmd", str(submit), "--jobs", "2",
                        "--latency-wait", "5", "--seconds-between-status-checks", "1", "all"],
                       cwd=workdir, capture_output=True, text=True)
    assert r.returncode == 0, (r.stdout + r.stderr)[-3000:]
    logs = sorted((workdir / "logs" / "tiny" / "response").glob("chunk-*.log"))
    assert [p.name for p in logs] == ["chunk-0.log", "chunk-1.log"]
    from jls.stages.response import response_dataset
    res = workdir / "results" / "tiny"
    plant, motion, got = (read(res / f"{n}.nc") for n in ("plant", "vessel_motion", "response"))
    tuggers = {t["name"]: t["c_kN_s_per_m"] for t in cfg["tuggers"]}
    tz = np.concatenate([got["tz"].values, read(res / "operability.nc")["tz"].values])
    ref = response_dataset(plant, motion, tz, [90.0], tuggers, omega_step=0.01,
                           outside_policy={"zero_above_rad_s": 3.0, "reason": "the hull no longer responds above 3 rad/s"}, shown=["baseline", "detuned"])
    for name in ("sigma", "mpm", "tz_response"):
        assert np.array_equal(got[name].values, ref[name].sel(tz=got["tz"]).values), name
    np.testing.assert_array_equal(got["transfer"].values, ref["transfer"].values)


def test_malformed_leg_table_stops_run_with_named_error(workdir):
    (workdir / "tables" / "a.csv").write_text(LEG_A.replace("10,8,4", "10,-8,4"))
    r = snakemake(workdir)
    assert r.returncode != 0
    text = r.stdout + r.stderr
    assert "a.csv" in text and "-8" in text
    assert not (workdir / "results").exists()
    assert not (workdir / "reports").exists()


def test_invalid_config_stops_run_with_named_error(workdir):
    cfg = yaml.safe_load((workdir / "config" / "config.yaml").read_text())
    cfg["jacket"]["m_grav_t"] = -5
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    r = snakemake(workdir)
    assert r.returncode != 0
    assert "jacket.m_grav_t" in r.stdout + r.stderr
    assert not (workdir / "results").exists()


def test_bem_rule_computes_the_rao_file_when_asked(workdir):
    cfg = yaml.safe_load((workdir / "config" / "config.yaml").read_text())
    del cfg["vessel"]["rao_file"]
    # the computed box places its own waterline (its CoG, 1 m below it): the default hull's
    # reference height and the hinge height derived from it would state it a second time
    del cfg["vessel"]["rao_reference_point_height_m"]
    cfg["rigging"]["limits"].pop("hinge_height_m", None)
    cfg["vessel"]["bem"] = {"box": {"length_m": 100, "beam_m": 30, "draught_m": 6, "kg_m": 5},
                            "radii_of_gyration_m": [10.5, 25, 26], "roll_damping_ratio": 0.05,
                            "omega_rad_s": {"min": 0.1, "max": 3.0, "n": 30},
                            "headings_deg": [90], "panel_size_m": 4}
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    pytest.importorskip("capytaine", reason="the 'bem' extra is not installed")
    plan = planned_outputs(workdir)
    assert "results/vessel/bem_rao.nc" in plan and "results/tiny/vessel_motion.nc" in plan
    r = snakemake(workdir, "results/vessel/bem_rao.nc")
    assert r.returncode == 0, r.stderr[-3000:]
    from jls.vessel.files import load_rao
    ds = load_rao(workdir / "results" / "vessel" / "bem_rao.nc")
    heave = abs(ds["rao"].sel(dof="heave").isel(omega=0, wave_direction=0).item())
    assert heave == pytest.approx(1.0, abs=0.05)          # long waves: the box rides them


def test_error_in_a_configfile_names_that_file(workdir):
    (workdir / "over.yaml").write_text("jacket: {m_grav_t: -5}\n")
    r = snakemake(workdir, "-n", "--configfile", "over.yaml")
    assert r.returncode != 0
    text = r.stdout + r.stderr
    assert "over.yaml: jacket.m_grav_t" in text and "config/config.yaml: jacket" not in text


def test_a_workflow_script_runs_by_hand_as_its_rule_would(workdir):
    r = subprocess.run([sys.executable, "workflow/scripts/plant.py", "route=tiny"], cwd=workdir,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
    ds = read(workdir / "results" / "tiny" / "plant.nc")
    assert list(ds["candidate"].values) == ["baseline", "detuned"]
    assert (workdir / "logs" / "tiny" / "plant.log").read_text().count("candidate") == 2


def test_criterion_only_rerun_has_no_configuration_mismatch(tiny_done):
    workdir = tiny_done              # the clean run, a copy
    (workdir / "over.yaml").write_text("assessment: {criteria: {relative_sway_m: 2.5}}\n")
    plan = planned_outputs(workdir, "--configfile", "over.yaml")
    assert sorted(plan) == ["reports/tiny.pdf", "results/tiny/timedomain/cells.json",
                            "results/tiny/verification/cells.json", "results/tiny/voyage.nc",
                            "results/tiny/voyage_plan.nc", "results/tiny/workability.nc"]
    r = snakemake(workdir, "--configfile", "over.yaml")
    assert r.returncode == 0, r.stderr[-3000:]
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(workdir / "reports" / "tiny.pdf").pages)
    assert "Configuration mismatch" not in text
    assert read(workdir / "results" / "tiny" / "workability.nc")["limit"].sel(criterion="relative_sway_m").item() == 2.5


def test_a_named_variant_writes_its_own_datasets_and_report(tiny_done):
    workdir = tiny_done              # the clean run, a copy
    before = (workdir / "reports" / "tiny.pdf").read_bytes()
    (workdir / "v1.yaml").write_text("variant: sway25\nassessment: {criteria: {relative_sway_m: 2.5}}\n")
    plan = planned_outputs(workdir, "--configfile", "v1.yaml")
    assert "reports/tiny-sway25.pdf" in plan and "reports/tiny.pdf" not in plan
    assert all(p.startswith(("results/variants/sway25/", "reports/tiny-sway25", "results/cache"))
               for p in plan), plan
    r = snakemake(workdir, "--configfile", "v1.yaml")
    assert r.returncode == 0, r.stderr[-3000:]
    assert (workdir / "reports" / "tiny.pdf").read_bytes() == before
    sway = {"criterion": "relative_sway_m"}
    assert read(workdir / "results" / "variants" / "sway25" / "tiny" / "workability.nc")["limit"].sel(sway).item() == 2.5
    assert read(workdir / "results" / "tiny" / "workability.nc")["limit"].sel(sway).item() == 3.0
    assert planned_outputs(workdir) == []            # the default's run is still up to date
