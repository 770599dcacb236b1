"""End-to-end: inputs the workflow used to refuse although valid, and inputs it used to
crash on or quietly use, through Snakemake on a copy of the workflow.

One run of a tiny route carries three documented features that the workflow refused:
a wire-tension criterion with the screening on (``max_wire_tension_kN: 25000`` as
commented in config/config.yaml), a heading between the RAO file's with
``heading_interpolation: linear``, and ``4.55e6`` in a --configfile (a number for jls
check and the workflow alike). A seasonal hindcast leg shows its record's warning on the
report's first page (workability.nc, attribute ``warnings``). The same run's results are
then damaged to show what the workflow does with corrupt intermediate files and
symbolic links among its outputs.
"""

from pathlib import Path

import numpy as np
import pytest
import yaml
from test_pipeline import make_workdir, snakemake, tiny_config
from test_screening_pipeline import SCREENING

from jls.cli import main
from jls.io.netcdf import read, warnings_of
from jls.plant import same_rigging

ROOT = Path(__file__).resolve().parents[1]
HINDCAST = ROOT / "tests" / "data" / "metocean" / "ndbc44007_hourly_hs_tz_1996.txt"
pytestmark = pytest.mark.slow

MY_YAML = "jacket:\n  ixx_t_m2: 4.55e6\n"


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The tiny route with the three features and a seasonal hindcast leg, run once."""
    work = tmp_path_factory.mktemp("inputs")
    cfg = tiny_config(work)
    cfg["screening"] = SCREENING
    cfg["assessment"]["criteria"] = {"relative_sway_m": 3.0, "max_wire_tension_kN": 25000}
    cfg["vessel"]["heading_interpolation"] = "linear"
    cfg["routes"]["tiny"]["legs"][0]["headings_deg"] = [80]         # RAO headings: every 15 deg
    cfg["routes"]["tiny"]["legs"].append({
        "name": "summer", "duration_h": 24, "headings_deg": [90],
        "hindcast": {"file": "tables/summer.txt", "hs_edges_m": [0, 1, 2, 3, 4, 6, 10],
                     "tz_edges_s": [2, 4, 5, 6, 7, 8, 9, 10, 12, 16]}})
    make_workdir(work, cfg)
    lines = HINDCAST.read_text().splitlines()
    (work / "tables" / "summer.txt").write_text(
        "\n".join([lines[0]] + [ln for ln in lines[1:] if "-04-" <= ln[4:8] <= "-09-"]) + "\n")
    (work / "my.yaml").write_text(MY_YAML)
    r = snakemake(work, "--configfile", "my.yaml")
    assert r.returncode == 0, r.stderr[-4000:]
    return work


def test_a_tension_criterion_with_the_screening_works_end_to_end(run):
    work = read(run / "results" / "tiny" / "workability.nc")
    assert "max_wire_tension_kN" in work["criterion"].values.tolist()
    assert float(work["limit"].sel(criterion="max_wire_tension_kN")) == 25000
    assert same_rigging.alias(work, "optimised") is not None     # itself, or the same rigging
    assert any("max_wire_tension_kN is applied" in w for w in warnings_of(work))
    assert (run / "reports" / "tiny.pdf").stat().st_size > 10_000


def test_linear_heading_interpolation_works_end_to_end(run):
    motion = read(run / "results" / "tiny" / "vessel_motion.nc")
    assert 80.0 in motion["heading"].values.tolist()
    assert motion.attrs["heading_interpolation"].startswith("linear")
    from jls.vessel.files import load_rao
    rao = load_rao(ROOT / "config" / "vessel" / "representative_hlv.nc")["rao"]
    at = {h: rao.sel(wave_direction=np.radians(h), method="nearest").values for h in (75, 90)}
    expected = at[75] * 2 / 3 + at[90] / 3                  # 80 deg: a third of the way to 90
    np.testing.assert_allclose(motion["rao"].sel(heading=80.0).values, expected, rtol=1e-9, atol=1e-12)
    assert (run / "results" / "tiny" / "workability.nc").exists()


def test_engineering_notation_in_a_configfile_is_a_number_everywhere(run, capsys, monkeypatch):
    plant = read(run / "results" / "tiny" / "plant_assessed.nc")
    np.testing.assert_allclose(plant["M"].sel(dof="roll", dof_col="roll").values, 4.55e6)
    monkeypatch.chdir(run)
    assert main(["check", "--config", "my.yaml"]) == 0
    assert "valid" in capsys.readouterr().out


def test_a_seasonal_hindcast_reaches_the_first_page(run):
    lines = warnings_of(read(run / "results" / "tiny" / "workability.nc"))
    assert any("leg summer" in w and "covers 6 of the 12 calendar months" in w for w in lines)
    sea = read(run / "results" / "tiny" / "sea_states.nc")
    assert "months Apr May Jun Jul Aug Sep" in sea.attrs["record_summer"]


def _state(work):
    return sorted((str(p.relative_to(work)), p.stat().st_size) for p in (work / "results").rglob("*")
                  if p.is_file())


def test_a_truncated_intermediate_is_named_and_rebuilt(run):
    path = run / "results" / "tiny" / "response.nc"
    good = read(path)
    path.write_bytes(path.read_bytes()[:5000])
    before = _state(run)
    r = snakemake(run, "--configfile", "my.yaml", "-n")
    assert r.returncode == 0, r.stderr[-3000:]
    assert "results/tiny/response.nc: cannot read the dataset" in r.stderr
    assert "a run sets it aside and rebuilds it" in r.stderr and _state(run) == before   # dry run
    r = snakemake(run, "--configfile", "my.yaml")
    assert r.returncode == 0, r.stderr[-3000:]
    assert "set aside as results/tiny/response.nc.rejected and rebuilt" in r.stderr
    assert (run / "results" / "tiny" / "response.nc.rejected").stat().st_size == 5000
    np.testing.assert_array_equal(read(path)["sigma"].values, good["sigma"].values)
    assert (run / "reports" / "tiny.pdf").exists() and (run / "reports" / "tiny.pdf.rejected").exists()
    r = snakemake(run, "--configfile", "my.yaml", "-n")
    assert "Nothing to be done" in r.stdout + r.stderr


def test_a_dataset_of_another_configuration_is_rebuilt(run):
    import netCDF4
    path = run / "results" / "tiny" / "sea_states.nc"
    with netCDF4.Dataset(path, "a") as nc:
        nc.setncattr("config_sha256", "0" * 64)
    r = snakemake(run, "--configfile", "my.yaml")
    assert r.returncode == 0, r.stderr[-3000:]
    assert "sea_states.nc: made with another configuration" in r.stderr
    assert read(path).attrs["config_sha256"] != "0" * 64


def test_a_symlinked_log_is_refused_before_anything_runs(run, tmp_path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    log = run / "logs" / "tiny" / "plant.log"
    log.parent.mkdir(parents=True, exist_ok=True)
    log.unlink(missing_ok=True)
    log.symlink_to(victim)
    try:
        before = _state(run)
        r = snakemake(run, "--configfile", "my.yaml", "-n")
        assert r.returncode != 0
        assert "logs/tiny/plant.log is a symbolic link" in r.stderr + r.stdout
        assert victim.read_text() == "precious" and _state(run) == before
    finally:
        log.unlink()


def test_yaml_a_reader_would_read_differently_stops_the_workflow(run):
    (run / "bad.yaml").write_text("routes:\n  tiny:\n    legs:\n      - {name: north, scatter: "
                                  "tables/a.csv, duration_h: 30:00}\n")
    before = _state(run)
    r = snakemake(run, "--configfile", "bad.yaml", "-n")
    assert r.returncode != 0 and "bad.yaml: line 4: '30:00' is a base-60" in r.stderr + r.stdout
    assert _state(run) == before


def test_a_large_screening_grid_stops_before_the_dag(run):
    cfg = yaml.safe_load((run / "config" / "config.yaml").read_text())
    (run / "big.yaml").write_text(yaml.safe_dump({"screening": {"grid_points": {
        k: 201 for k in ("top_spread_y_m", "bottom_spread_y_m", "bottom_spread_x_m", "drop_height_m")}}}))
    r = snakemake(run, "--configfile", "big.yaml", "-n")
    assert r.returncode != 0 and "big.yaml: screening.grid_points" in r.stderr + r.stdout
    assert cfg["screening"]["enabled"]
