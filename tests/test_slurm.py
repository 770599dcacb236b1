"""A real scheduler: a one-node SLURM cluster on localhost (tests/slurm/cluster.sh:
munged, slurmctld, slurmd, all under a temporary directory), and the chunked tiny route
through sbatch with ``--profile profiles/slurm``.

Checked: every job ran as a SLURM job, with the CPUs of its threads and the memory of
its rule; the datasets equal a local run's, bit for bit; a job killed for memory reruns
with more memory; a job killed for memory every time, and an input error, are named in
the end-of-run summary; a failed job's log holds no line of an earlier run.

Needs root and the Debian packages slurm-wlm and munge (.ci/run installs them) and
snakemake-executor-plugin-slurm. Skipped, with the reason, where they are missing or
SLURM cannot start; in CI (CI=true) that is a failure.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from test_pipeline import make_workdir, tiny_config

from jls.io.netcdf import read

ROOT = Path(__file__).resolve().parents[1]
CLUSTER = ROOT / "tests" / "slurm" / "cluster.sh"
SITE = ROOT / "tests" / "slurm" / "profile"
pytestmark = [pytest.mark.slow, pytest.mark.slurm]
IN_CI = os.environ.get("CI") == "true"


def _unavailable(reason):
    if IN_CI:
        pytest.fail(f"SLURM test cluster: {reason}")
    pytest.skip(f"SLURM test cluster: {reason}")


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    try:
        import snakemake_executor_plugin_slurm  # noqa: F401
    except ImportError:
        _unavailable("snakemake-executor-plugin-slurm is not installed (pip install -e '.[slurm]')")
    d = tmp_path_factory.mktemp("cluster")
    r = subprocess.run(["bash", str(CLUSTER), "start", str(d)], capture_output=True, text=True,
                       timeout=120)
    if r.returncode != 0:
        subprocess.run(["bash", str(CLUSTER), "stop", str(d)], capture_output=True, timeout=60)
        _unavailable(f"did not start: {r.stderr.strip()[-2000:]}")
    env = {**os.environ, "SLURM_CONF": str(d / "slurm.conf"),
           "PATH": f"{d / 'bin'}{os.pathsep}{os.environ['PATH']}"}
    try:
        yield SimpleNamespace(dir=d, env=env)
    finally:
        subprocess.run(["bash", str(CLUSTER), "stop", str(d)], capture_output=True, timeout=60)


def chunked_workdir(path):
    """The tiny route with one response_chunk job per candidate, and the profiles."""
    path.mkdir()
    cfg = tiny_config(path)
    cfg["response"]["chunk_candidates"] = 1
    make_workdir(path, cfg)
    shutil.copytree(ROOT / "profiles", path / "profiles")
    return path


def on_cluster(cluster, work, *args):
    return subprocess.run([sys.executable, "-m", "snakemake", "--profile", "profiles/slurm",
                           "--profile", str(SITE), *args], cwd=work, env=cluster.env,
                          capture_output=True, text=True, timeout=900)


def records(cluster, work):
    """The cluster's record of every finished job run from ``work`` (jobcomp/filetxt)."""
    out = []
    path = cluster.dir / "jobcomp.txt"
    for line in (path.read_text().splitlines() if path.exists() else []):
        rec = dict(re.findall(r"(\w+)=(\S*)", line))
        if rec.get("WorkDir") == str(work):
            rec["mem_mb"] = int(re.search(r"mem=(\d+)M", rec["Tres"]).group(1))
            out.append(rec)
    return out


def rules_of(cluster):
    """SLURM job id -> rule name, from the jobs' comments (squeue keeps finished jobs
    for MinJobAge)."""
    r = subprocess.run(["squeue", "--states=all", "-h", "-o", "%i|%k"], env=cluster.env,
                       capture_output=True, text=True, check=True)
    return {i: re.sub(r"^rule_(\w+?)(_wildcards_.*)?$", r"\1", c)
            for i, c in (ln.split("|", 1) for ln in r.stdout.split())}


def submitted(out):
    """SLURM job ids of the jobs Snakemake submitted, from its output (each once)."""
    return list(dict.fromkeys(re.findall(r"has been submitted with SLURM jobid (\d+)", out)))


def test_chunked_route_runs_as_slurm_jobs_and_equals_a_local_run(cluster, tmp_path):
    work = chunked_workdir(tmp_path / "slurm")
    target = "results/tiny/workability.nc"
    # The local run to compare with runs meanwhile (the cluster's jobs leave the CPUs
    # idle between the scheduler's polls).
    local = chunked_workdir(tmp_path / "local")
    local_run = subprocess.Popen([sys.executable, "-m", "snakemake", "--cores", "2", target],
                                 cwd=local, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 text=True)
    r = on_cluster(cluster, work, target)
    local_out = local_run.communicate(timeout=900)[0]
    out = r.stdout + r.stderr
    assert r.returncode == 0, out[-4000:]
    # Every job of the run was a SLURM job, and completed.
    finished = list(dict.fromkeys(re.findall(r"Finished jobid: \d+ \(Rule: \w+\)", out)))
    finished = [re.search(r"Rule: (\w+)", f).group(1) for f in finished]
    ids = submitted(out)
    assert len(ids) == len(finished) >= 10 and "response_chunk" in finished, out[-3000:]
    recs = {rec["JobId"]: rec for rec in records(cluster, work)}
    assert sorted(recs) == sorted(ids)
    assert {rec["JobState"] for rec in recs.values()} == {"COMPLETED"}
    rule = rules_of(cluster)
    assert sorted(rule[i] for i in ids) == sorted(finished)
    # Threads follow the CPUs SLURM granted: a chunk job has 2 threads and 2 CPUs.
    for i in ids:
        if rule[i] == "response_chunk":
            assert recs[i]["ProcCnt"] == "2"
        if rule[i] == "plant":
            assert recs[i]["ProcCnt"] == "1" and recs[i]["mem_mb"] == 1000  # job_resources()
    for log in (work / "logs" / "tiny" / "response").glob("chunk-*.log"):
        assert "; 2 threads;" in log.read_text()
    # The datasets equal a local run's, bit for bit.
    assert local_run.returncode == 0, local_out[-3000:]
    for name in ("response", "operability", "workability"):
        a, b = read(work / "results" / "tiny" / f"{name}.nc"), read(local / "results" / "tiny" / f"{name}.nc")
        assert sorted(a.data_vars) == sorted(b.data_vars)
        for v in a.data_vars:
            if a[v].dtype.kind in "fc":
                assert np.array_equal(a[v].values, b[v].values, equal_nan=True), (name, v)


PLANT_FAILS = ("from jls.errors import InputError\n"
               "from jls.io.provenance import workflow_step\n"
               "with workflow_step(snakemake.log[0], 'plant'):\n"
               "    raise InputError('wire is slack or in compression', file='config/config.yaml',\n"
               "                     field='rigging.wires[0]', value=-12.5)\n")


def test_memory_kills_rerun_with_more_memory_and_failures_are_named(cluster, tmp_path):
    """sea_states killed for memory at its first attempt reruns with twice the memory and
    completes; vessel_motion, killed at every attempt, and plant, which meets an input
    error, are listed at the end with their causes; plant's log from an earlier run
    keeps none of its lines."""
    work = chunked_workdir(tmp_path / "fail")
    (work / "workflow" / "scripts" / "plant.py").write_text(PLANT_FAILS)
    (work / "logs" / "tiny").mkdir(parents=True)
    for name in ("plant", "vessel_motion"):     # the logs of an earlier, successful run
        stale = work / "logs" / "tiny" / f"{name}.log"
        stale.write_text(f"2026-01-01 00:00:00,000 INFO jls.{name}: wrote results/tiny/{name}.nc\n")
        os.utime(stale, (1.7e9, 1.7e9))
    # vessel_motion's 60 MB is less than the job's Snakemake holds within its first second
    # (accounting polls every second), so it is killed before its step at every attempt;
    # at 150 MB a fast job could finish its step before a poll saw it over the limit.
    r = on_cluster(cluster, work, "--keep-going", "--retries", "1",
                   "--set-resources", "sea_states:mem_mb=150*attempt", "vessel_motion:mem_mb=60",
                   "--", "results/tiny/sea_states.nc", "results/tiny/vessel_motion.nc",
                   "results/tiny/plant.nc")
    out = r.stdout + r.stderr
    assert r.returncode != 0, out[-3000:]
    rule = rules_of(cluster)
    recs = records(cluster, work)
    by_rule = {}
    for rec in sorted(recs, key=lambda x: int(x["JobId"])):
        by_rule.setdefault(rule[rec["JobId"]], []).append(rec)
    # Killed for memory, then rerun with twice the memory, and completed.
    sea = by_rule["sea_states"]
    assert [(x["JobState"], x["mem_mb"]) for x in sea] == [("FAILED", 150), ("COMPLETED", 300)], sea
    slurm_log = next((work / ".snakemake" / "slurm_logs" / "rule_sea_states").rglob(f"{sea[0]['JobId']}.log"))
    assert "memory limit" in slurm_log.read_text()
    assert (work / "results" / "tiny" / "sea_states.nc").exists()
    # The summary names every failed job and its cause.
    summary = out[out.index("Failed jobs:"):]
    assert re.search(r"failed: rule plant \(results/tiny/plant.nc\), scheduler job \d+, 2 attempts\n"
                     r"    logs/tiny/plant.log: .* ERROR jls.plant: input error: config/config.yaml: "
                     r"rigging.wires\[0\]: wire is slack or in compression \(got -12.5\)", summary), summary
    m = re.search(r"failed: rule vessel_motion \(results/tiny/vessel_motion.nc\), scheduler job \d+, "
                  r"2 attempts\n    logs/tiny/vessel_motion.log: older than this run \(rewritten\); the last lines of "
                  r"\S+slurm_logs/rule_vessel_motion/\S+\.log:\n((        .*\n?)+)", summary)
    assert m and "memory limit" in m.group(1), summary
    assert "jls plant (logs/tiny/plant.log): input error: config/config.yaml" in out
    # No line of the earlier run in a failed job's log: plant's step truncated it, and
    # vessel_motion's, killed before its step began, says so.
    text = (work / "logs" / "tiny" / "plant.log").read_text()
    assert "wrote results/tiny/plant.nc" not in text and "input error" in text
    text = (work / "logs" / "tiny" / "vessel_motion.log").read_text()
    assert "wrote" not in text and "failed before its step began" in text
    assert [x["mem_mb"] for x in by_rule["plant"]] == [1000, 2000]
