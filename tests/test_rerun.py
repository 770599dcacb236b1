"""A killed run recovers with --unlock and --rerun-incomplete; with SOURCE_DATE_EPOCH
two runs of the same inputs give the same report bytes."""

import hashlib
import os
import signal
import subprocess
import sys
import time

import pytest
from test_pipeline import make_workdir

from jls.errors import InputError
from jls.report.control import created

EPOCH = "1767225600"          # 2026-01-01 00:00:00 UTC


def test_source_date_epoch_fixes_the_creation_time(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", EPOCH)
    assert created({"created": "2030-05-05T00:00:00+00:00"}) == "2026-01-01T00:00:00+00:00"
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    with pytest.raises(InputError, match="SOURCE_DATE_EPOCH.*whole seconds"):
        created({})
    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    assert created({"created": "2030-05-05T00:00:00+00:00"}) == "2030-05-05T00:00:00+00:00"


def _workdir(tmp_path):
    return make_workdir(tmp_path)


def _env():
    return {**os.environ, "SOURCE_DATE_EPOCH": EPOCH}


def _snakemake(cwd, *args):
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", *args], cwd=cwd,
                       capture_output=True, text=True, env=_env())
    return r.returncode, r.stdout + r.stderr


def _sha(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.slow
def test_killed_run_recovers_and_reports_are_reproducible(tmp_path):
    work = _workdir(tmp_path)
    # Start a run and kill it (and its jobs) once the first job has started.
    proc = subprocess.Popen([sys.executable, "-m", "snakemake", "--cores", "2"], cwd=work,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env(),
                            start_new_session=True)
    deadline = time.time() + 120
    while time.time() < deadline and not list((work / "logs").rglob("*.log")):
        time.sleep(0.2)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    assert not (work / "reports" / "tiny.pdf").exists()

    # The killed run left its lock and an incomplete output: a plain rerun refuses,
    # naming the recovery (which of the two it meets first depends on when the kill came).
    code, out = _snakemake(work)
    assert code != 0 and ("--unlock" in out or "--rerun-incomplete" in out), out[-2000:]
    code, out = _snakemake(work, "--unlock")
    assert code == 0, out
    code, out = _snakemake(work, "--rerun-incomplete")
    assert code == 0, out[-3000:]
    pdf = work / "reports" / "tiny.pdf"
    first = _sha(pdf)

    # Same inputs, same SOURCE_DATE_EPOCH: the same bytes.
    pdf.unlink()
    code, out = _snakemake(work)
    assert code == 0, out[-3000:]
    assert _sha(pdf) == first


@pytest.mark.slow
def test_failed_job_error_is_printed_at_the_end(tmp_path):
    work = _workdir(tmp_path)
    # Most bad input stops the workflow when it is parsed; stand in for an input fault
    # that only a job can find with a plant step that meets one.
    (work / "workflow" / "scripts" / "plant.py").write_text(
        "from jls.errors import InputError\n"
        "from jls.io.provenance import workflow_step\n"
        "with workflow_step(snakemake.log[0], 'plant'):\n"
        "    raise InputError('wire is slack or in compression', file='config/config.yaml',\n"
        "                     field='rigging.wires[0]', value=-12.5)\n")
    code, out = _snakemake(work, "results/tiny/plant.nc")
    assert code != 0
    tail = next(line for line in out.splitlines() if line.startswith("jls plant ("))
    assert tail == ("jls plant (logs/tiny/plant.log): input error: config/config.yaml: "
                    "rigging.wires[0]: wire is slack or in compression (got -12.5)")
    assert not (work / "results" / "tiny" / "plant.nc").exists()


@pytest.mark.slow
def test_a_failing_rerun_leaves_no_earlier_success_line_in_the_log(tmp_path):
    """The plant succeeds, then its rerun fails: its log holds the failure (the
    traceback's exception), none of the first run's lines, and the end-of-run summary
    names it."""
    work = _workdir(tmp_path)
    code, out = _snakemake(work, "results/tiny/plant.nc")
    assert code == 0, out[-3000:]
    log = work / "logs" / "tiny" / "plant.log"
    first = log.read_text()
    assert "wrote" in first or "INFO jls.plant" in first, first
    (work / "workflow" / "scripts" / "plant.py").write_text(
        "from jls.io.provenance import workflow_step\n"
        "with workflow_step(snakemake.log[0], 'plant') as log:\n"
        "    log.info('building the plant')\n"
        "    raise RuntimeError('the matrices file is truncated')\n")
    code, out = _snakemake(work, "results/tiny/plant.nc", "--forcerun", "plant")
    assert code != 0
    text = log.read_text()
    assert not set(first.splitlines()) & set(text.splitlines()), text
    assert "ERROR jls.plant: failed: RuntimeError: the matrices file is truncated" in text
    assert "Traceback (most recent call last)" in text
    summary = out[out.index("Failed jobs:"):]
    assert ("failed: rule plant (results/tiny/plant.nc)\n    logs/tiny/plant.log: " in summary
            and "failed: RuntimeError: the matrices file is truncated" in summary), summary


@pytest.mark.slow
def test_a_deleted_dataset_is_rebuilt_on_the_next_run(tiny_done):
    """Deleting an intermediate dataset (response.nc) by hand: the next run names it, sets
    the report aside and rebuilds both; with the same inputs the report's bytes are the
    same (before: Snakemake said "Nothing to be done")."""
    work = tiny_done                 # the clean run (tests/conftest.py: tiny_run), a copy
    pdf, response = work / "reports" / "tiny.pdf", work / "results" / "tiny" / "response.nc"
    first = _sha(pdf)
    response.unlink()
    code, out = _snakemake(work, "-n")
    assert "results/tiny/response.nc is missing (deleted?); a run rebuilds it" in out
    assert response.exists() is False and pdf.exists()
    code, out = _snakemake(work)
    assert code == 0, out[-3000:]
    assert "results/tiny/response.nc is missing (deleted?); rebuilt" in out
    assert "Nothing to be done" not in out and response.exists()
    assert _sha(pdf) == first
