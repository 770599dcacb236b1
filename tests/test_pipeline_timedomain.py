"""End-to-end: time-domain cells in the workflow on the tiny route of test_pipeline (one
job per cell, registry layout, verdicts replacing the frequency domain's, reruns of an
edited cell only, the 'timedomain' winch policy)."""

import json

import numpy as np
import pypdf
import pytest
import yaml

from jls import registry
from jls.netcdf import read
from jls.stages.winch_limits import SATURATED_UNRESOLVED, TIME_DOMAIN
from test_pipeline import planned_outputs, planned_outputs_with, snakemake, workdir  # noqa: F401

pytestmark = pytest.mark.slow


def _set(workdir, **timedomain):
    path = workdir / "config" / "config.yaml"
    cfg = yaml.safe_load(path.read_text())
    cfg["timedomain"].update(timedomain)
    path.write_text(yaml.safe_dump(cfg))


def test_timedomain_cells_replace_verdicts_and_rerun_one_by_one(workdir):
    _set(workdir, cells=[{"candidate": "detuned", "heading_deg": 90, "hs_m": 2.5, "tz_s": 7.5}])
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    cells = json.loads((res / "timedomain" / "cells.json").read_text())
    names = [c["name"] for c in cells]
    # One boundary cell per leg for the baseline (the same cell may serve both), plus the configured one.
    assert "detuned__h90__hs2.5__tz7.5" in names
    assert any(c["candidate"] == "baseline" and any("boundary" in x for x in c["reasons"]) for c in cells)
    for name in names:
        ds = read(res / "timedomain" / f"{name}.nc")
        registry.check(ds, "timedomain_cell")
        assert list(ds["tugger"].values) == ["none", "reference"]
        # Small seas, no limit reached: time and frequency domain agree on sigma.
        ok = ds["limit_fraction"] == 0
        np.testing.assert_allclose(ds["sigma"].where(ok), ds["sigma_fd"].where(ok), rtol=0.1)
    work = read(res / "workability.nc")
    src = work["verdict_source"]
    replaced = src.sel(candidate="detuned", heading=90.0, hs=2.5, tz=7.5)
    assert (replaced == TIME_DOMAIN).all()                    # both legs hold that cell
    assert int((src == TIME_DOMAIN).sum()) >= 2 * 2
    # The workability is recomputed from the pass flags it stores.
    sea = read(res / "sea_states.nc")
    leg = (sea["cell_probability"] * work["passes"]).sum(("heading", "hs", "tz"))
    np.testing.assert_allclose(work["workability_leg"], leg.transpose(*work["workability_leg"].dims))
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(workdir / "reports" / "tiny.pdf").pages)
    assert "Damping tuggers" in text and "Time-domain cells" in text

    # Edit the configured cell: only that cell's job (and what reads the cells) reruns.
    _set(workdir, cells=[{"candidate": "detuned", "heading_deg": 90, "hs_m": 2.5, "tz_s": 6.5}])
    plan = planned_outputs(workdir)
    td_jobs = [p for p in plan if p.startswith("results/tiny/timedomain/") and p.endswith(".nc")]
    assert "results/tiny/timedomain/cells.json" in plan
    assert "results/tiny/response.nc" not in plan and "results/tiny/tugger_studies.nc" not in plan
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    ran = sorted(p.name for p in (workdir / "logs" / "tiny" / "timedomain").glob("*__*.log")
                 if p.stat().st_mtime > (res / "timedomain" / f"{names[0]}.nc").stat().st_mtime)
    assert ran == ["detuned__h90__hs2.5__tz6.5.log"], (ran, td_jobs)


def test_timedomain_policy_sends_every_saturating_cell_to_the_time_domain(workdir):
    (workdir / "over.yaml").write_text(yaml.safe_dump({
        "assessment": {"winch_saturation": "timedomain"},
        "tuggers": [{"name": "none", "c_kN_s_per_m": 0},
                    {"name": "reference", "c_kN_s_per_m": 1000, "max_force_kN": 200}],
        "timedomain": {"boundary_cells_per_leg": 0}}))
    r = snakemake(workdir, "--configfile", "over.yaml")
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    work = read(res / "workability.nc")
    sea = read(res / "sea_states.nc")
    live = sea["cell_probability"] > 0
    flagged = work["winch_saturates"] & live
    assert int(flagged.sum()) > 0
    # Every live flagged cell got its verdict from the time domain; none is left unresolved.
    assert bool((work["verdict_source"].where(flagged) == TIME_DOMAIN).sum() == flagged.sum())
    assert not bool(((work["verdict_source"] == SATURATED_UNRESOLVED) & live).any())
    # The winch sits at a limit in the time domain where the flag says it saturates.
    assert float(work["timedomain_limit_fraction"].sel(candidate="baseline", tugger="reference")) > 0
