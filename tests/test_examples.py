"""Every example configuration (config/examples/*.yaml) names its command in its header,
and that command works as printed in a copy of the repository: as a dry run (``-n``) for
every example, which must plan the report the header names; in full for two of them in
the slow suite (an own vessel on an own route, the 21 x 21 candidate grid)."""

import importlib.util
import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "config" / "examples").glob("*.yaml"))
BIN = Path(sys.executable).parent
#: The optional extra a `pip install -e '.[extra]'` line of a header installs, and the
#: module that tells whether it is installed here.
EXTRAS = {"spectra": "wavespectra", "slurm": "snakemake_executor_plugin_slurm"}


def header(path: Path) -> list[str]:
    lines = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("#"):
            break
        lines.append(line[1:].strip())
    return lines


def commands(path: Path) -> list[str]:
    """The header's command lines (those calling the environment's programs)."""
    return [line for line in header(path) if line.startswith(".venv/bin/")]


def reports(path: Path) -> list[str]:
    return re.findall(r"reports/[\w.-]+\.pdf", " ".join(header(path)))


def copy_repository(dest: Path) -> Path:
    """What the examples read: the workflow, the configuration and profiles, the tests' data."""
    shutil.copy(ROOT / "Snakefile", dest)
    for sub in ("workflow", "config", "profiles"):
        shutil.copytree(ROOT / sub, dest / sub, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "tests" / "data", dest / "tests" / "data")
    return dest


def argv(command: str) -> list[str]:
    args = shlex.split(command)
    return [str(BIN / args[0].removeprefix(".venv/bin/")), *args[1:]]


def run_header(path: Path, cwd: Path, dry: bool) -> subprocess.CompletedProcess:
    """Run the header's commands in ``cwd`` (a pip line only checks that its extra is
    installed, skipping with the reason when it is not); returns the last run."""
    result = None
    for command in commands(path):
        if "pip install" in command:
            extra = re.search(r"\.\[(\w+)\]", command).group(1)
            if importlib.util.find_spec(EXTRAS[extra]) is None:
                pytest.skip(f"{path.name} needs the extra [{extra}] ({EXTRAS[extra]}), not installed here")
            continue
        args = argv(command) + (["-n"] if dry and "snakemake" in command else [])
        result = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
        assert result.returncode == 0, f"{path.name}: {command}\n{result.stderr[-3000:]}"
    return result


def test_the_examples_are_there():
    names = {p.stem for p in EXAMPLES}
    assert {"own_route", "own_vessel", "hindcast_route", "spectra_route", "candidate_grid",
            "cluster"} <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_header_names_its_command_and_report(path):
    cmds = commands(path)
    runs = [c for c in cmds if c.startswith(".venv/bin/snakemake ")]
    assert len(runs) == 1, f"{path.name}: its header must name one snakemake command"
    assert f"--configfile config/examples/{path.name}" in runs[0]
    assert "--cores" in runs[0] or "--profile" in runs[0]    # Snakemake refuses a local run without
    assert reports(path), f"{path.name}: its header must name the report it writes"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_header_command_dry_run(path, tmp_path):
    result = run_header(path, copy_repository(tmp_path), dry=True)
    planned = result.stdout + result.stderr
    for report in reports(path):
        assert report in planned, f"{path.name}: the dry run does not plan {report}"
    # the run is the example's routes alone: the shipped default route's report only
    # where the example assesses the default route
    if "reports/default" not in " ".join(reports(path)):
        assert "reports/default.pdf" not in planned


@pytest.mark.slow
@pytest.mark.parametrize("name", ["own_vessel", "candidate_grid"])
def test_the_header_command_full_run(name, tmp_path):
    path = ROOT / "config" / "examples" / f"{name}.yaml"
    work = copy_repository(tmp_path)
    run_header(path, work, dry=False)
    for report in reports(path):
        assert (work / report).stat().st_size > 10_000
    if name == "own_vessel":
        # another vessel without its hull: the lift system was not checked against a hull,
        # and the report's input warnings say so (jls.config.hull_checks)
        import xarray as xr
        with xr.open_dataset(work / "results/tanker_route/workability.nc") as ds:
            assert "vessel.hull is not given" in ds.attrs["warnings"]
    if name == "candidate_grid":
        # 441 grid candidates, yet the time domain ran the named candidates' cells and the
        # grid's five best: 2 legs x (3 + 5) at most
        cells = json.loads((work / "results/variants/grid/default/timedomain/cells.json").read_text())
        assert 0 < len(cells) <= 16
        grid = {c["candidate"] for c in cells} - {"baseline", "detuned", "optimised"}
        assert 0 < len(grid) <= 5
        # the report states the rule and the exclusion it implies (page 1 counts the
        # exclusions; chapter 2 gives each with its reason)
        from pypdf import PdfReader
        pages = [" ".join(p.extract_text().split()) for p in PdfReader(work / "reports/default-grid.pdf").pages]
        assert "exclude" in pages[0]
        assert "no time domain" in " ".join(pages)
        assert any("a rule that does not grow with the grid" in p for p in pages)
