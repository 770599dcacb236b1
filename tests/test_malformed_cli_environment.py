"""Round three of the input checks, class (a): command-line arguments at their bounds and
the environment a run inherits. Each case ends in one ``jls: error:`` line naming the
argument or variable and its value, never a traceback (docs/inputs.md)."""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sea_fixtures as fx
import xarray as xr

from jls.cli import main
from jls.config import environment
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]


def _error(capsys, argv) -> str:
    rc = main(argv)
    assert rc == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("jls: error:"), err
    return err[0]


def test_verify_harmonic_period_zero_is_named(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    line = _error(capsys, ["verify", "--harmonic-period-s", "0"])
    assert "--harmonic-period-s" in line and "[2, 60]" in line and "(got 0.0)" in line


@pytest.mark.parametrize("argv, name", [
    (["--harmonic-period-s", "13.9", "nan"], "--harmonic-period-s"),
    (["--pitch-inertia-t-m2", "-5"], "--pitch-inertia-t-m2"),
    (["--wire-mass-t-per-m", "2"], "--wire-mass-t-per-m"),
    (["--seed", "-1"], "--seed"),
    (["--transient-s", "inf"], "--transient-s"),
    (["--highpass-hz", "nan"], "--highpass-hz"),
    (["--tz", "0.2"], "--tz"),
    (["--record", ""], "--record"),
    (["--assessed-plant", " "], "--assessed-plant"),
])
def test_verify_number_options_bounded(capsys, monkeypatch, argv, name):
    monkeypatch.chdir(ROOT)
    line = _error(capsys, ["verify", *argv])
    assert name in line and "got" in line


def test_simulate_steeper_than_breaking(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    line = _error(capsys, ["simulate", "--hs", "25", "--tz", "3"])
    # L = 9.81 * 9 / (2 pi) = 14.05 m; Hs/L = 1.78; the steepest Hs is L/7 = 2.01 m
    assert "--hs, --tz" in line and "steeper than breaking" in line and "1.78" in line
    assert "2.01 m" in line and "(25.0, 3.0)" in line
    line = _error(capsys, ["verify", "--hs", "25", "--tz", "3"])
    assert "steeper than breaking" in line


def test_breaking_limit_itself_is_accepted():
    from jls.sea.steepness import require_not_breaking
    length = 9.81 * 8.0**2 / (2 * np.pi)
    require_not_breaking(length / 7 * 0.999, 8.0)          # just below: a possible sea
    with pytest.raises(InputError, match="steeper than breaking"):
        require_not_breaking(length / 7 * 1.01, 8.0)


def test_spectrum_of_a_device_is_refused_at_once(capsys):
    line = _error(capsys, ["spectrum", "/dev/zero", "--format", "ndbc"])
    assert "/dev/zero" in line and "character device" in line
    line = _error(capsys, ["spectrum", "/dev/zero", "--format", "ww3"])
    assert "/dev/zero" in line and "not a regular file" in line


def test_spectrum_gzip_bomb_bounded(tmp_path, monkeypatch):
    import gzip

    from jls.sea import ndbc
    monkeypatch.setattr(ndbc, "MAX_TABLE_BYTES", 1000)
    path = tmp_path / "41010w2019.txt.gz"
    path.write_bytes(gzip.compress(b"#YY MM DD hh mm .02 .03\n" + b"2019 01 01 00 00 1.0 2.0\n" * 100))
    with pytest.raises(InputError, match="decompresses to more than"):
        ndbc.read_table(path, spectral=True)


def _two_stations(path):
    freq = 0.04 * 1.1 ** np.arange(25)
    dirs = np.arange(0.0, 360.0, 15.0)
    one = xr.open_dataset(fx.ww3_spectra(path.with_suffix(".one.nc"), freq, dirs,
                                         np.full((2, freq.size, dirs.size), 0.01))).load()
    two = xr.concat([one, one.assign_coords(station=[2])], dim="station")
    two.to_netcdf(path)
    return path


@pytest.mark.parametrize("station", ["99", "-1", "2"])
def test_spectrum_station_out_of_range(capsys, tmp_path, station):
    pytest.importorskip("wavespectra")
    path = _two_stations(tmp_path / "ww3.nc")
    line = _error(capsys, ["spectrum", str(path), "--format", "ww3", "--station", station])
    assert "--station" in line or "station" in line
    assert station in line and "ww3.nc" in line
    assert main(["spectrum", str(path), "--format", "ww3", "--station", "1", "--json"]) == 0


@pytest.mark.parametrize("value, text", [
    ("yesterday", "whole seconds since 1970"),
    ("1.5e9", "whole seconds since 1970"),
    ("99999999999", "lies in the future"),
    (str(10**30), "beyond the year 9999"),
])
def test_source_date_epoch_checked_at_parse(value, text):
    with pytest.raises(InputError) as exc:
        environment.check_source_date_epoch({"SOURCE_DATE_EPOCH": value})
    assert str(exc.value).startswith("environment: SOURCE_DATE_EPOCH:") and text in str(exc.value)
    assert repr(value) in str(exc.value)


def test_source_date_epoch_accepted():
    environment.check_source_date_epoch({"SOURCE_DATE_EPOCH": "1700000000"})
    environment.check_source_date_epoch({"SOURCE_DATE_EPOCH": ""})
    environment.check_source_date_epoch({})


@pytest.mark.parametrize("value", ["0", "-2", "two", "1.5"])
def test_numba_threads_checked(value):
    with pytest.raises(InputError, match="NUMBA_NUM_THREADS") as exc:
        environment.check_numba_threads({"NUMBA_NUM_THREADS": value})
    assert repr(value) in str(exc.value)
    environment.check_numba_threads({"NUMBA_NUM_THREADS": "2"})


def test_numba_threading_layer_checked():
    with pytest.raises(InputError, match=r"environment: NUMBA_THREADING_LAYER: is not a threading layer.*'bogus'"):
        environment.check_numba_layer({"NUMBA_THREADING_LAYER": "bogus"})
    environment.check_numba_layer({"NUMBA_THREADING_LAYER": "workqueue"})


def test_unwritable_cache_named(tmp_path):
    blocker = tmp_path / "home"
    blocker.write_text("a file where the home folder should be")
    with pytest.raises(InputError) as exc:
        environment.check_cache_dir({"HOME": str(blocker)})
    text = str(exc.value)
    assert "environment: HOME:" in text and str(blocker / ".cache" / "snakemake") in text
    assert "XDG_CACHE_HOME=" in text
    environment.check_cache_dir({"HOME": str(blocker), "XDG_CACHE_HOME": str(tmp_path / "c")})
    assert (tmp_path / "c" / "snakemake").is_dir()


@pytest.mark.parametrize("env, text", [
    ({"NUMBA_NUM_THREADS": "0"}, "environment: NUMBA_NUM_THREADS: "),
    ({"SOURCE_DATE_EPOCH": "yesterday"}, "environment: SOURCE_DATE_EPOCH: "),
])
def test_jls_check_names_the_variable(env, text):
    import os
    r = subprocess.run([sys.executable, "-m", "jls.cli", "check"], cwd=ROOT, capture_output=True,
                       text=True, env={**os.environ, **env}, timeout=300)
    assert r.returncode == 2 and "Traceback" not in r.stderr and text in r.stderr


def test_empty_path_names_no_file(capsys):
    line = _error(capsys, ["spectrum", "", "--format", "ndbc"])
    assert "an empty path names no NDBC spectral density file" in line and "(got '')" in line


@pytest.mark.slow
@pytest.mark.parametrize("env, text", [
    ({"NUMBA_NUM_THREADS": "0"}, "invalid environment: environment: NUMBA_NUM_THREADS: must be a whole number"),
    ({"SOURCE_DATE_EPOCH": "99999999999"}, "invalid environment: environment: SOURCE_DATE_EPOCH: lies in the future"),
])
def test_the_workflow_refuses_the_environment_before_any_job(tmp_path, env, text):
    """The Snakefile checks the environment first, before the job server starts: no job,
    no dataset."""
    import os

    from test_pipeline import make_workdir
    work = make_workdir(tmp_path)
    r = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2"], cwd=work,
                       capture_output=True, text=True, env={**os.environ, **env}, timeout=600)
    assert r.returncode != 0 and text in r.stdout + r.stderr
    assert not (work / "results").exists() and not (work / "reports").exists()


def test_every_command_checks_the_environment_first(capsys, monkeypatch):
    """numpy.f2py, imported with numba, reads SOURCE_DATE_EPOCH with int(): a command
    would stop with a traceback before its own checks."""
    monkeypatch.chdir(ROOT)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    line = _error(capsys, ["decay", "--release-m", "1"])
    assert "environment: SOURCE_DATE_EPOCH: must be whole seconds" in line
