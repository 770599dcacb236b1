"""A workflow step in its own process: its log, its one-line input errors, and a
garbage collector that leaves the process's objects to the OS."""

import subprocess
import sys

STEP = """
import gc, sys
from jls.errors import InputError
from jls.io.provenance import workflow_step
before = gc.get_freeze_count()
with workflow_step(sys.argv[1], "demo") as log:
    cycle = []
    cycle.append(cycle)
    log.info("frozen %d of %d", before, gc.get_freeze_count())
    if sys.argv[2] == "bad":
        raise InputError("bad value", field="legs[0].scatter", value="x.csv")
"""


def run_step(tmp_path, mode):
    log = tmp_path / f"{mode}.log"
    r = subprocess.run([sys.executable, "-c", STEP, str(log), mode], capture_output=True,
                       text=True, timeout=60)
    return r, log.read_text()


def test_a_step_freezes_what_it_starts_with_and_exits_cleanly(tmp_path):
    r, log = run_step(tmp_path, "good")
    assert r.returncode == 0, r.stderr
    frozen = log.split("frozen ")[1].split()
    assert int(frozen[0]) == 0 and int(frozen[2]) > 1000       # the imported modules
    assert "INFO jls.demo: frozen" in log                        # the log is complete


def test_a_bad_input_ends_the_step_with_one_line(tmp_path):
    r, log = run_step(tmp_path, "bad")
    assert r.returncode == 1
    assert r.stderr.strip().splitlines()[-1] == (
        "jls demo: input error: legs[0].scatter: bad value (got 'x.csv')")
    assert "Traceback" not in r.stderr
    assert "ERROR jls.demo: input error: legs[0].scatter" in log


CRASH = """
import sys
from jls.io.provenance import workflow_step
with workflow_step(sys.argv[1], "demo") as log:
    log.info("reading the plant")
    {}["plant"]
"""


def test_a_failure_writes_its_traceback_to_the_log(tmp_path):
    """Not only stderr (on a cluster, the scheduler's log): the step's own log ends with
    the traceback and the exception."""
    log = tmp_path / "crash.log"
    r = subprocess.run([sys.executable, "-c", CRASH, str(log)], capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 1
    assert r.stderr.strip().splitlines()[-1] == (
        f"jls demo: failed: KeyError: 'plant' (traceback in {log})")
    text = log.read_text()
    assert "ERROR jls.demo: failed: KeyError: 'plant'" in text
    assert "Traceback (most recent call last)" in text and text.rstrip().endswith("KeyError: 'plant'")


def test_the_log_is_truncated_when_the_step_starts(tmp_path):
    log = tmp_path / "good.log"
    log.write_text("2026-01-01 00:00:00,000 INFO jls.demo: wrote results/old.nc\n")
    r, text = run_step(tmp_path, "good")
    assert r.returncode == 0, r.stderr
    assert "old.nc" not in text
