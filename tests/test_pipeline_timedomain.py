"""End-to-end: time-domain cells in the workflow on the tiny route of test_pipeline (one
job per cell, registry layout, verdicts replacing the frequency domain's, reruns of an
edited cell only, the 'timedomain' winch policy)."""

import json

import numpy as np
import pypdf
import pytest
import yaml
from test_pipeline import planned_outputs, snakemake

from jls.io import registry
from jls.io.netcdf import read
from jls.names import TIME_DOMAIN

pytestmark = pytest.mark.slow


def _set(workdir, **timedomain):
    path = workdir / "config" / "config.yaml"
    cfg = yaml.safe_load(path.read_text())
    cfg["timedomain"].update(timedomain)
    path.write_text(yaml.safe_dump(cfg))


def test_timedomain_cells_replace_verdicts_and_rerun_one_by_one(tiny_done):
    workdir = tiny_done        # a copy of the clean tiny run: the edit reruns what it changes
    # a cell where no tugger setting saturates its winch, so the time domain decides for all
    _set(workdir, cells=[{"candidate": "detuned", "heading_deg": 90, "hs_m": 1.5, "tz_s": 7.5}])
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    cells = json.loads((res / "timedomain" / "cells.json").read_text())
    names = [c["name"] for c in cells]
    # One boundary cell per leg for the baseline (the same cell may serve both), plus the configured one.
    assert "detuned__h90__hs1.5__tz7.5" in names
    assert any(c["candidate"] == "baseline" and any("boundary" in x for x in c["reasons"]) for c in cells)
    for name in names:
        ds = read(res / "timedomain" / f"{name}.nc")
        registry.check(ds, "timedomain_cell")
        assert list(ds["tugger"].values) == ["none", "reference"]
        # Small seas, no limit reached: time and frequency domain agree on sigma, within
        # 5 % and four standard errors of the pooled records' random amplitudes.
        ok = (ds["limit_fraction"] == 0).values
        n = ds.sizes["seed"]
        assert n == 3 and ds.attrs["amplitudes"] == "rayleigh"
        tol = 0.05 * ds["sigma_fd"] + 4 * ds["sigma_seed_std_expected"] / np.sqrt(n)
        assert (np.abs(ds["sigma"] - ds["sigma_fd"]) < tol).values[ok].all()
        assert ds.attrs["components_per_bandwidth"] >= 2 and ds.attrs["record_warning"] == ""
        assert (ds["line_contact_fraction"] == 0).all()
    work = read(res / "workability.nc")
    src = work["verdict_source"]
    replaced = src.sel(candidate="detuned", heading=90.0, hs=1.5, tz=7.5)
    assert (replaced == TIME_DOMAIN).all()                    # both legs hold that cell
    assert int((src == TIME_DOMAIN).sum()) >= 2 * 2
    # The workability is recomputed from the pass flags it stores.
    sea = read(res / "sea_states.nc")
    leg = (sea["cell_probability"] * work["passes"]).sum(("heading", "hs", "tz"))
    np.testing.assert_allclose(work["workability_leg"], leg.transpose(*work["workability_leg"].dims))
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(workdir / "reports" / "tiny.pdf").pages)
    assert "Damping tuggers" in text and "Time-domain cells" in text

    # Edit the configured cell: the choice of cells reruns; once it has, the dry run plans
    # exactly one time-domain job, the edited cell's.
    _set(workdir, cells=[{"candidate": "detuned", "heading_deg": 90, "hs_m": 1.5, "tz_s": 6.5}])
    plan = planned_outputs(workdir)
    assert "results/tiny/timedomain/cells.json" in plan
    assert "results/tiny/response.nc" not in plan and "results/tiny/tugger_studies.nc" not in plan
    r = snakemake(workdir, "results/tiny/timedomain/cells.json")
    assert r.returncode == 0, r.stderr[-3000:]
    plan = planned_outputs(workdir)
    td_jobs = [p for p in plan if p.startswith("results/tiny/timedomain/")]
    assert td_jobs == ["results/tiny/timedomain/detuned__h90__hs1.5__tz6.5.nc"], plan
    assert sorted(set(plan) - set(td_jobs)) == ["reports/tiny.pdf", "results/tiny/verification/cells.json",
                                                 "results/tiny/workability.nc"]
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    assert planned_outputs(workdir) == []
