"""Fixtures several test files share: the shipped configuration, validated, and its
rigging (each built once per test module, as the files built them); the slow tests'
shared workflow runs (the tiny route, the default route), each run once per session."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from jls.config.builders import rigging_from_config
from jls.config.loader import load

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "config" / "config.yaml"


@pytest.fixture(scope="module")
def cfg():
    """The shipped configuration (config/config.yaml), loaded and validated."""
    return load(CONFIG)


@pytest.fixture(scope="module")
def rig(cfg):
    """The shipped rigging (:func:`jls.config.builders.rigging_from_config`)."""
    return rigging_from_config(cfg)



@pytest.fixture(scope="module")
def baseline_reference(cfg):
    """(plant, MoorDyn reference, vessel motion at heading 90 deg) of the shipped baseline
    rigging: the verification reference's tests start from it."""
    from jls.config.builders import candidate_plant
    from jls.stages.vessel_motion import vessel_motion
    from jls.verify import build_reference
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=str(ROOT))
    plant = candidate_plant(cfg, "baseline")
    return plant, build_reference(plant, vessel_lever_m=motion.attrs["hinge_m"]), motion

# -- shared end-to-end runs (slow tests) ------------------------------------------------
# A full workflow run costs minutes on CI. Tests that only read a run's results share one
# run; a test that edits the configuration or reruns works on its own copy of that run
# (``shutil.copytree`` keeps the files' times, so Snakemake sees the copy as up to date).

#: SOURCE_DATE_EPOCH of the shared runs: 2026-01-01 00:00:00 UTC (the reports' bytes
#: depend only on the inputs)
EPOCH = "1767225600"


def copy_run(src: Path, dest: Path) -> Path:
    """A copy of the run in ``src`` at ``dest`` (times kept: nothing is out of date)."""
    shutil.copytree(src, dest, symlinks=True, dirs_exist_ok=True)
    return dest


@pytest.fixture(scope="session")
def tiny_run(tmp_path_factory):
    """The tiny route of tests/test_pipeline.py (its ``tiny_config``), run once to its
    report with ``SOURCE_DATE_EPOCH`` set. Read only: use ``tiny_done`` to change it."""
    from test_pipeline import make_workdir

    work = make_workdir(tmp_path_factory.mktemp("tiny_run"))
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2"], cwd=work,
                       capture_output=True, text=True, env={**os.environ, "SOURCE_DATE_EPOCH": EPOCH})
    assert r.returncode == 0, r.stderr[-3000:]
    return work


@pytest.fixture()
def tiny_done(tiny_run, tmp_path):
    """This test's own copy of the finished tiny run (``tiny_run``)."""
    return copy_run(tiny_run, tmp_path)


@pytest.fixture(scope="session")
def default_run(tmp_path_factory):
    """The shipped default route (config/config.yaml), run once by the workflow's default
    target in a copy of the repository, with ``SOURCE_DATE_EPOCH`` set. Read only: a test
    that edits or reruns copies it (``copy_run``)."""
    work = tmp_path_factory.mktemp("default_run")
    for name in ("Snakefile", "workflow", "config", "profiles"):
        src = ROOT / name
        (shutil.copytree if src.is_dir() else shutil.copy)(src, work / name)
    env = dict(os.environ, SOURCE_DATE_EPOCH=EPOCH,
               PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", "-q"], cwd=work, env=env,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-3000:]
    return work
