"""The shipped vessel written as an OrcaFlex vessel type and as AQWA-LINE listing tables by
scripts/export_vessel.py reads back to the same RAOs, and the workflow assesses it to the
clean run's workability (slow)."""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from jls.io.netcdf import read
from jls.vessel import load_rao
from jls.vessel.export import aqwa_text, orcaflex_text, write_text

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = ROOT / "config" / "vessel" / "representative_hlv.nc"
sys.path.insert(0, str(ROOT / "scripts"))
import export_vessel  # noqa: E402


@pytest.fixture(scope="module")
def hull():
    return load_rao(DEFAULT)


def assert_same_rao(a, b):
    """The same vessel to rounding: omega, directions, reference point and every value."""
    assert a.sizes == b.sizes
    assert np.allclose(a["omega"].values, b["omega"].values, rtol=1e-15, atol=0)
    assert np.allclose(a["wave_direction"].values, b["wave_direction"].values, rtol=0, atol=1e-15)
    assert a.attrs["reference_point_m"] == b.attrs["reference_point_m"]
    scale = np.abs(b["rao"].values).max()
    assert np.abs(a["rao"].values - b["rao"].values).max() <= 1e-9 * scale
    assert np.abs(a["rao"].values - b["rao"].values).max() <= 1e-15 * scale    # in fact


def test_orcaflex_round_trip(hull, tmp_path):
    path = write_text(orcaflex_text(hull, vessel_type="HLV", draught="operating"), tmp_path / "v.yml")
    back = load_rao(path, vessel_type="HLV", draught="operating")       # format from .yml
    assert back.attrs["source_format"] == "orcaflex"
    assert_same_rao(back, hull)


def test_aqwa_round_trip(hull, tmp_path):
    path = write_text(aqwa_text(hull), tmp_path / "v.lis")
    back = load_rao(path)                                                 # format from .lis
    assert back.attrs["source_format"] == "aqwa_lis"
    assert np.array_equal(back["omega"].values, hull["omega"].values)    # from FREQ, exact
    assert_same_rao(back, hull)


def test_a_round_trip_keeps_the_water_depth(hull, tmp_path):
    shallow = hull.assign_attrs(water_depth_m=60.0)
    back = load_rao(write_text(aqwa_text(shallow), tmp_path / "v.lis"))
    assert back.attrs["water_depth_m"] == 60.0


def test_the_script_writes_and_prints_the_vessel_block(tmp_path, capsys):
    for fmt, suffix in (("orcaflex", ".yml"), ("aqwa_lis", ".lis")):
        out = tmp_path / f"v{suffix}"
        assert export_vessel.main(["--format", fmt, "--output", str(out)]) == 0
        text = capsys.readouterr().out
        block = yaml.safe_load(text[text.index("vessel:"):])["vessel"]
        assert block["rao_format"] == fmt and Path(block["rao_file"]) == out
        kw = {k: block[k] for k in ("orcaflex_vessel_type", "orcaflex_draught") if k in block}
        back = load_rao(out, fmt, **({"vessel_type": kw["orcaflex_vessel_type"],
                                      "draught": kw["orcaflex_draught"]} if kw else {}))
        assert np.abs(back["rao"].values - load_rao(DEFAULT)["rao"].values).max() < 1e-12


def test_the_script_refuses_an_unreadable_source(tmp_path, capsys):
    bad = tmp_path / "bad.csv"
    bad.write_text("period_s,wave_direction_deg,dof,amplitude,phase_deg\n")
    assert export_vessel.main(["--format", "orcaflex", "--rao", str(bad),
                               "--output", str(tmp_path / "x.yml")]) == 1
    assert "bad.csv" in capsys.readouterr().err
    assert not (tmp_path / "x.yml").exists()


@pytest.mark.slow
def test_workflow_with_either_export_gives_the_clean_runs_workability(tiny_run, tmp_path):
    from test_pipeline import make_workdir, snakemake, tiny_config

    # the clean run: the tiny route as tests/test_pipeline.py configures it (tiny_run)
    runs = {"clean": read(tiny_run / "results" / "tiny" / "workability.nc")}
    for name in ("orcaflex", "aqwa_lis"):
        work = tmp_path / name
        work.mkdir()
        cfg = tiny_config(work)
        out = work / "vessel" / f"exported{'.yml' if name == 'orcaflex' else '.lis'}"
        r = subprocess.run([sys.executable, str(ROOT / "scripts" / "export_vessel.py"),
                            "--format", name, "--output", str(out),
                            "--vessel-type", "HLV", "--draught", "operating"],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        cfg["vessel"].update(rao_file=str(out), rao_format=name)
        if name == "orcaflex":
            cfg["vessel"].update(orcaflex_vessel_type="HLV", orcaflex_draught="operating")
        make_workdir(work, cfg)
        r = snakemake(work, "results/tiny/workability.nc")
        assert r.returncode == 0, r.stderr[-3000:]
        runs[name] = read(work / "results" / "tiny" / "workability.nc")
    clean = runs["clean"]
    for name in ("orcaflex", "aqwa_lis"):
        ds = runs[name]
        assert set(ds.data_vars) == set(clean.data_vars)
        for var in clean.data_vars:
            a, b = ds[var].values, clean[var].values
            if np.issubdtype(b.dtype, np.number):
                assert np.allclose(a, b, rtol=1e-9, atol=1e-12, equal_nan=True), (name, var)
            else:
                assert np.array_equal(a, b), (name, var)
        assert ds.attrs.get("warnings") == clean.attrs.get("warnings")
