"""A bad input found while the workflow is parsed stops it with the one line `jls check`
prints for it (file, key or line, value, what to do), no stack frames, exit status
non-zero (issue 35, item 5)."""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BAD = {
    "schema": "jacket:\n  m_grav_t: -5\n",
    "duplicate_key": "sea:\n  gamma: 3.3\n  gamma: 2.0\n",
    "table": "routes:\n  default:\n    legs:\n      - {name: x, duration_h: 5, scatter: tests/data/sea/bad_negative.csv}\n",
    "rao_coverage": "vessel:\n  rao_file: tests/data/vessel/example_rao.csv\n",
    "optimised": "candidates:\n  - {name: optimised, top_spread_y_m: 30}\n",
}


@pytest.fixture(scope="module")
def repo(tmp_path_factory):
    dest = tmp_path_factory.mktemp("repo")
    shutil.copy(ROOT / "Snakefile", dest)
    for sub in ("workflow", "config", "profiles"):
        shutil.copytree(ROOT / sub, dest / sub, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "tests" / "data", dest / "tests" / "data")
    return dest


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_parse_error_is_one_clean_line(repo, case):
    bad = repo / f"bad_{case}.yaml"
    bad.write_text(BAD[case])
    r = subprocess.run([sys.executable, "-m", "snakemake", "-n", "--configfile", bad.name],
                       cwd=repo, capture_output=True, text=True)
    assert r.returncode != 0
    lines = (r.stdout + r.stderr).splitlines()
    assert not [line for line in lines if line.startswith('  File "')], r.stderr
    assert not [line for line in lines if "Traceback" in line or "WorkflowError" in line], r.stderr
    errors = [line for line in lines if line.startswith("jls: error: ")]
    assert len(errors) == 1, r.stderr
    if case != "optimised":          # a rule of the workflow's, which jls check does not hold
        check = subprocess.run([sys.executable, "-m", "jls.cli", "check", "--config", bad.name],
                               cwd=repo, capture_output=True, text=True)
        assert check.returncode != 0
        assert errors[0] in check.stderr.splitlines(), (errors[0], check.stderr)
    assert bad.name in errors[0] or "tests/data" in errors[0]
