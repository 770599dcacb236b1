"""End-to-end: the rigging screening in the workflow on a tiny route with a 3 x 3 grid.

screening.nc has its contract, the optimum flows through plant, response, workability
and the report as "optimised", the chunked workflow equals the library's unchunked
screening, and editing a leg's probabilities reruns no plant and no chunk's solve, and
no response job while the optimum stays.
"""

import re

import numpy as np
import pypdf
import pytest
import yaml
from test_pipeline import LEG_A, make_workdir, planned_outputs, snakemake, tiny_config

from jls.config.builders import rigging_from_config, scoring_from_config, screening_settings_from_config
from jls.config.loader import load
from jls.design.screening import screening_dataset
from jls.io.netcdf import read
from jls.plant import same_rigging

pytestmark = pytest.mark.slow
SCREENING = {"enabled": True, "grid_points": {"top_spread_y_m": 3, "drop_height_m": 3},
             "chunk_candidates": 4, "sensitivity_points": 5, "max_evaluations": 20,
             "tolerance_m": 0.05}


@pytest.fixture()
def workdir(tmp_path):
    cfg = tiny_config(tmp_path)
    cfg["screening"] = SCREENING
    return make_workdir(tmp_path, cfg)


def test_screening_flows_through_the_workflow(workdir):
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    s = read(res / "screening.nc")
    # Contract.
    assert {"candidate", "mode", "tugger"} <= set(s.dims)
    assert s.sizes["mode"] == 4 and list(s["tugger"].values) == ["none", "reference"]
    for v in ("top_spread_y", "bottom_spread_y", "bottom_spread_x", "drop_height"):
        assert s[v].dims == ("candidate",) and s[v].attrs["units"] == "m"
    # bool, stored as a CF flag (netCDF has no boolean type)
    assert s["feasible"].attrs["flag_meanings"] == "false true"
    assert set(np.unique(s["feasible"].values)) <= {0, 1}
    feasible = s["feasible"].values.astype(bool)
    reason = s["infeasible_reason"].values.astype(str)
    assert np.all((reason == "") == feasible) and not feasible.all()
    assert s["natural_period"].dims == ("candidate", "mode") and s["natural_period"].attrs["units"] == "s"
    assert s["screening_sigma"].dims == ("candidate", "tugger") and s["screening_sigma"].attrs["units"] == "m"
    w = s["route_workability"]
    assert w.dims == ("candidate", "tugger") and w.attrs["units"] == "1"
    assert np.all((w.values[feasible] >= 0) & (w.values[feasible] <= 1))
    assert s.sizes["candidate"] in (10, 11)                     # baseline, 3 x 3 grid, refined
    opt = s.attrs["optimum_candidate"]
    assert opt in s["candidate"].values and bool(s["feasible"].sel(candidate=opt))
    i_opt = list(s["candidate"].values).index(opt)
    assert w.values[i_opt, 0] >= np.nanmax(np.where(feasible, w.values[:, 0], -1))   # objective tugger: first
    # The chunk jobs (3 of 4, 4, 2 candidates) equal the library's unchunked screening:
    # bit for bit in one process (tests/test_screening.py); here, across processes whose
    # BLAS threading differs (Snakemake pins it per job), to the last bits of the moments.
    cfg = load(workdir / "config" / "config.yaml")
    lib = screening_dataset(rigging_from_config(cfg), read(res / "vessel_motion.nc"),
                            read(res / "sea_states.nc"), scoring_from_config(cfg),
                            screening_settings_from_config(cfg), chunk_size=10 ** 6)
    for v in ("route_workability", "feasible", "natural_period"):
        np.testing.assert_array_equal(s[v].values, lib[v].values, err_msg=v)
    for v in ("screening_sigma", "screening_mpm", "workability_surrogate"):
        np.testing.assert_allclose(s[v].values, lib[v].values, rtol=1e-13, atol=0, err_msg=v)
    assert lib.attrs["optimum_candidate"] == opt
    # The optimum, assessed as "optimised" beside the configured candidates.
    plant = read(res / "plant_assessed.nc")
    assert list(plant["candidate"].values) == ["baseline", "detuned", "optimised"]
    for v in ("top_spread_y", "drop_height"):
        assert float(plant[v].sel(candidate="optimised")) == pytest.approx(float(s[v].sel(candidate=opt)))
    np.testing.assert_allclose(plant["natural_period"].sel(candidate="optimised"),
                               s["natural_period"].sel(candidate=opt), rtol=1e-12)
    resp, work = read(res / "response.nc"), read(res / "workability.nc")
    assert "optimised" in resp["candidate"].values and "optimised" in resp["shown_candidate"].values
    assert same_rigging.alias(work, "optimised") is not None     # itself, or the same rigging
    pdf = workdir / "reports" / "tiny.pdf"
    text = " ".join(p.extract_text() for p in pypdf.PdfReader(pdf).pages).replace("\xa0", " ")
    text = " ".join(text.split())
    assert re.search(r"\d+\. Rigging", text)
    assert "optimised / none" in text and "Workable Tz window at the design Hs of 2.4 m" in text
    if int(s.attrs["optimum_on_constraint"]):
        assert f"The optimum lies on a constraint: {s.attrs['active_constraints']}" in text
    else:
        assert "The optimum lies on no constraint" in text

    chunk_log = (workdir / "logs" / "tiny" / "screening" / "chunk-0.log").read_text()
    assert re.search(r"; 13 of 13 sea states evaluated", chunk_log), chunk_log   # 13 Tz, 1 heading
    # A new table (every count doubled): the screening is re-scored from its chunks (no
    # chunk job, no plant job). The optimum is continuous, so any change of the
    # probabilities may move it; with the same probabilities it stays.
    doubled = LEG_A.replace("20,10,5", "40,20,10").replace("10,8,4", "20,16,8").replace("2,3,2", "4,6,4")
    assert doubled.count("\n") == LEG_A.count("\n") and doubled != LEG_A
    (workdir / "tables" / "a.csv").write_text(doubled)
    plan = planned_outputs(workdir)
    assert "results/tiny/screening.nc" in plan
    assert not [p for p in plan if "screening/chunk-" in p]
    assert "results/tiny/plant.nc" not in plan and "results/tiny/vessel_motion.nc" not in plan
    assessed = (res / "plant_assessed.nc").read_bytes()
    stamps = {n: (res / f"{n}.nc").stat().st_mtime_ns for n in ("response", "response_variants")}
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    # The optimum stays where it was: the assessed plant is rewritten with the same bytes, so (checkpoint and checksum) no response job reruns, while the
    # aggregation and the report do.
    assert (res / "plant_assessed.nc").read_bytes() == assessed
    assert {n: (res / f"{n}.nc").stat().st_mtime_ns for n in stamps} == stamps
    assert (res / "workability.nc").stat().st_mtime_ns > stamps["response"]
    assert planned_outputs(workdir) == []
    # A changed assessed plant (here a configured candidate's drop height; the response's
    # own parameters stay) reruns the response on the new plant.
    cfg = yaml.safe_load((workdir / "config" / "config.yaml").read_text())
    cfg["candidates"][0]["drop_height_m"] = 60.0
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    after = read(res / "plant_assessed.nc")
    assert float(after["drop_height"].sel(candidate="detuned")) == pytest.approx(60.0)
    assert (res / "response.nc").stat().st_mtime_ns > stamps["response"]
    assert not np.allclose(read(res / "response.nc")["sigma"].sel(candidate="detuned"),
                           resp["sigma"].sel(candidate="detuned"))
