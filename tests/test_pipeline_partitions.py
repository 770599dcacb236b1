"""End-to-end: the SYNTHETIC partitioned-sea example route (config/examples/partitions_route.yaml,
files written by scripts/make_partitions_example.py) through the workflow: an hourly CSV of
wind-sea and swell partitions and an ERA5-like file's partitions assessed hour by hour on
their spread systems, a Torsethaugen table in Hs-Tp on its cells' two systems."""

import shutil
import subprocess
import sys

import numpy as np
import pytest
import yaml
from test_pipeline import ROOT, make_workdir, snakemake, tiny_config

from jls.io.netcdf import read

pytestmark = pytest.mark.slow
EXAMPLE = ROOT / "config" / "examples" / "partitions_route.yaml"


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("partitions")
    # the example's files are the project script's: written again, they are the same
    out = tmp / "made"
    code = (f"import sys; sys.path.insert(0, {str(ROOT / 'scripts')!r}); import make_partitions_example as m; "
            f"from pathlib import Path; m.OUT = Path({str(out)!r}); m.main()")
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)
    for name in ("partitions_synthetic.csv", "torsethaugen_hs_tp_synthetic.csv"):
        assert (out / name).read_bytes() == (ROOT / "tests/data/partitions" / name).read_bytes(), name
    cfg = tiny_config(tmp)
    cfg["routes"] = {"synthetic": yaml.safe_load(EXAMPLE.read_text())["routes"]["synthetic_partitions"]}
    work = make_workdir(tmp, cfg)
    shutil.copytree(ROOT / "tests/data/partitions", work / "tests/data/partitions")
    r = snakemake(work)
    assert r.returncode == 0, r.stderr[-4000:]
    return work


def test_partition_legs_are_judged_hour_by_hour_and_the_table_on_its_cells(run):
    res = run / "results" / "synthetic"
    m = read(res / "measured_response.nc")
    assert m["leg"].values.tolist() == ["csv_partitions", "era5_partitions", "torsethaugen_table"]
    assert int(m["hours"].sel(leg="csv_partitions")) == 168 == int(m["hours"].sel(leg="era5_partitions"))
    assert m.attrs["integration_csv_partitions"].startswith("partitions: directional spectrum, course 200")
    assert m.attrs["integration_torsethaugen_table"].startswith("torsethaugen:")
    # the two files describe the same week: the same hourly sway within the ERA5 rounding of Te
    a = m["sigma_measured"].sel(leg="csv_partitions")
    b = m["sigma_measured"].sel(leg="era5_partitions")
    np.testing.assert_allclose(a.values, b.values, rtol=1e-3)
    # the swell at 12-16 s drives more sway than a JONSWAP on the hour's combined (Hs, Tz)
    assert float(m["sigma_ratio"].sel(leg="csv_partitions").min()) > 1.0
    # a table's cells weigh by their probability: the heading weights sum to its cells
    hw = m["heading_weight"].sel(leg="torsethaugen_table")
    assert float(hw.sum()) == pytest.approx(int(m["hours"].sel(leg="torsethaugen_table")))
    work = read(res / "workability.nc")
    assert all(bool(work["leg_hourly"].sel(leg=leg)) for leg in m["leg"].values.tolist())
    assert np.all((work["workability_leg"] >= 0) & (work["workability_leg"] <= 1))
    win = read(res / "weather_windows.nc")
    assert win.attrs["measured_sway_legs"] == "csv_partitions era5_partitions"
    # every criterion of each hour on its own sea: the CSV and the ERA5 file's week agree
    # (within the ERA5 rounding of Te), and the windows' verdicts use them (no leg left out)
    ua = m["utilisation"].sel(leg="csv_partitions")
    ub = m["utilisation"].sel(leg="era5_partitions")
    assert set(ua["criterion"].values) == set(work["criterion"].values)
    np.testing.assert_allclose(ua.values, ub.values, rtol=2e-2)
    assert win.attrs["own_sea_not_used"] == ""
    # a route with a table leg has no extreme of the hours; its scatter-cell extreme takes
    # every leg's own-sea records (nothing left on JONSWAP): by hand from the stored
    # per-record level, period and probability (sigma: its 3-h MPM the level), Lambda(voyage level) = -ln(q)
    from jls.assessment.hourly import own_sigma
    voy = read(res / "voyage.nc")
    assert "hindcast_voyage_level" not in voy
    assert voy.attrs["own_sea_not_used"] == ""
    sea = read(res / "sea_states.nc")
    assert set(sea["leg"].values.tolist()) == set(m["leg"].values.tolist())      # every leg its own sea
    c, g = str(voy["candidate"].values[0]), str(voy["tugger"].values[-1])
    for crit in voy["criterion"].values.tolist():
        for q in voy["non_exceedance"].values:
            x = float(voy["voyage_level"].sel(candidate=c, tugger=g, criterion=crit, non_exceedance=q))
            lam = 0.0
            for leg in m["leg"].values.tolist():
                o = m.sel(leg=leg, candidate=c, tugger=g, criterion=crit)
                p, u, tz = (o[v].transpose("time", "heading").values for v in ("probability", "utilisation",
                                                                                 "tz_response_own"))
                s = own_sigma(u * float(voy["limit"].sel(criterion=crit)), tz, float(voy.attrs["exposure_h"]),
                              voy.attrs["mpm_cycles"])
                live = np.nan_to_num(p) > 0
                with np.errstate(divide="ignore", invalid="ignore"):
                    lam += float(np.nansum(np.where(live & (s > 0), p * float(sea["duration_h"].sel(leg=leg)) * 3600.0
                                                    / tz * np.exp(-x * x / (2 * s * s)), 0.0)))
            assert lam == pytest.approx(-np.log(q), rel=1e-6), (crit, q)
    np.testing.assert_allclose(voy["own_sea_level_ratio"].values,
                               (voy["voyage_level"] / voy["voyage_level_jonswap"]).values, rtol=1e-12)
    # each leg's typical spectrum on the response's grid: its variance the mean of its hours'
    omega = read(res / "response.nc")["omega"].values
    np.testing.assert_array_equal(m["omega"].values, omega)
    m0 = np.trapezoid(m["spectrum_mean"].sel(leg="csv_partitions").values, omega)
    assert m0 == pytest.approx(float((m["hs"].sel(leg="csv_partitions") ** 2).mean()) / 16, rel=0.02)


def test_time_domain_cells_run_on_the_legs_own_sea_and_verification_refuses_those_legs(run):
    """Every time-domain cell of these legs is its leg's own (named __leg-<leg>), run on a
    multi-directional record of the leg's sea against that sea's frequency-domain sigma; the
    verification leaves the legs out with the reason (the reference runs a JONSWAP)."""
    import json
    res = run / "results" / "synthetic"
    cells = json.loads((res / "timedomain" / "cells.json").read_text())
    assert cells and all(c["name"].endswith("__leg-" + c["leg"]) for c in cells)
    for c in cells:
        td = read(res / "timedomain" / f"{c['name']}.nc")
        assert td.attrs["sea_leg"] == c["leg"]
        assert td.attrs["sea"].startswith("torsethaugen:" if c["leg"] == "torsethaugen_table" else "partitions:")
        err = np.abs(td["sigma"].values - td["sigma_fd"].values)
        assert np.all(err <= 4 * td["sigma_seed_std_expected"].values + 0.1 * td["sigma_fd"].values), c["name"]
    work = read(res / "workability.nc")
    refused = work.attrs["verification_refused_legs"]
    assert all(f"{leg} (" in refused for leg in ("csv_partitions", "era5_partitions", "torsethaugen_table"))
    assert json.loads((res / "verification" / "cells.json").read_text()) == []


def test_the_report_says_what_each_legs_sea_model_costs(run):
    """The chapter Wave spectra: per leg its sea model and the ratios to a long- and a
    short-crested JONSWAP on the same (Hs, Tz), the recommendation's, as the dataset holds
    them (three decimals)."""
    import pypdf
    m = read(run / "results" / "synthetic" / "measured_response.nc")
    win = read(run / "results" / "synthetic" / "weather_windows.nc")
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "synthetic.pdf").pages)
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    assert "What each leg\u2019s sea model costs" in text
    rec = read(run / "results" / "synthetic" / "workability.nc")
    c, g = win.attrs["option_candidate"], win.attrs["option_tugger"]
    assert c in rec["candidate"].values
    for leg, model in (("csv_partitions", "partitions"), ("torsethaugen_table", "torsethaugen")):
        lc = float(m["sigma_ratio"].sel(leg=leg, candidate=c, tugger=g))
        sc = float(m["sigma_ratio_short_crested"].sel(leg=leg, candidate=c, tugger=g))
        assert f"{model} {lc:.3f} {sc:.3f}" in text, (leg, lc, sc)
    assert np.all(np.isfinite(m["sigma_ratio_short_crested"].values) & (m["sigma_ratio_short_crested"].values > 0))


def test_page_one_prints_the_swell_table_of_the_partitioned_legs(run):
    """voyage_plan.nc holds the swell limits of the partitioned legs (none for the table
    leg), every criterion counted; page 1 prints the recommendation's as the dataset has
    them (docs/voyage_plan.md, "Partitioned seas: the swell table")."""
    import re

    import pypdf

    from jls.report.swell_table import swell_cell
    p = read(run / "results" / "synthetic" / "voyage_plan.nc")
    assert p["swell_hs_opwf"].sel(leg="torsethaugen_table").isnull().all()
    wf = p["swell_hs_opwf"].sel(leg="csv_partitions")
    assert np.all(wf.values >= 0) and np.all(wf.values <= p["swell_hs_oplim"].sel(leg="csv_partitions").values)
    assert {"tip_air_gap_m", "wire_tension"} <= set(p.attrs["swell_criteria"].split(", "))
    page = pypdf.PdfReader(run / "reports" / "synthetic.pdf").pages[0].extract_text()
    page = " ".join(page.replace("\xa0", " ").replace("\u2009", " ").split())
    c, g = re.search(r"Swell OP_WF \[m\], (\S+) rigging, tugger (\S+):", page).groups()
    row = " ".join(swell_cell(float(x)) for x in wf.sel(candidate=c, tugger=g).values)
    assert row in page, row
