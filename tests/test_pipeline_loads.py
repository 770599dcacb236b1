"""End-to-end: wire-tension criteria, uncertainty bands, criterion sensitivity and weather
windows through the workflow on a tiny route."""

import shutil

import numpy as np
import pandas as pd
import pypdf
import pytest
import yaml
from test_pipeline import ROOT, snakemake, workdir  # noqa: F401 - the fixture is used by name
from test_screening_pipeline import SCREENING

from jls.io.netcdf import read

pytestmark = pytest.mark.slow
HINDCAST = ROOT / "tests" / "data" / "metocean" / "ndbc44007_hourly_hs_tz_1996.txt"


def _edit(workdir, change):
    path = workdir / "config" / "config.yaml"
    cfg = yaml.safe_load(path.read_text())
    change(cfg)
    path.write_text(yaml.safe_dump(cfg))


def _pdf_text(path):
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(path).pages)
    return text.replace("\xa0", " ").replace("\u2009", " ")


def test_tension_criteria_bands_and_sensitivity_through_the_workflow(tiny_done):
    workdir = tiny_done        # a copy of the clean tiny run: the edit reruns what it changes
    # A safe working load just above the highest static tension (19 534 kN), so the
    # tension criterion decides some cells of the tiny route.
    def change(cfg):
        cfg["assessment"]["criteria"]["max_wire_tension_kN"] = 19800.0
    _edit(workdir, change)
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    resp, work, sea = read(res / "response.nc"), read(res / "workability.nc"), read(res / "sea_states.nc")
    for name in ("tension_static", "tension_sigma", "tension_mpm"):
        assert name in resp and name in read(res / "operability.nc")
    assert set(resp["tension_mpm"].dims) == {"candidate", "tugger", "heading", "tz", "wire"}
    # Per cell: the tension criterion passes exactly when the worst wire stays at or below
    # the safe working load, T_s + Hs MPM(Hs = 1) <= SWL.
    hs = sea["hs"].broadcast_like(sea["hs_upper"])
    unit = resp["tension_mpm"].sel(tz=sea["tz"])
    t_max = (resp["tension_static"] + hs * unit).max("wire")
    util = work["utilisation"].sel(criterion="max_wire_tension_kN")
    expected = (t_max <= 19800.0).transpose(*util.dims)
    live = (sea["cell_probability"] > 0).transpose(*[d for d in util.dims if d in sea["cell_probability"].dims])
    np.testing.assert_array_equal((util <= 1.0).where(live, True).values,
                                  expected.where(live, True).values)
    share = work["governing_share"].sel(criterion="max_wire_tension_kN")
    assert float(share.sum()) > 0          # the criterion governs somewhere
    assert set(work["passes"].dims) == {"candidate", "tugger", "leg", "heading", "hs", "tz"}
    # Bands contain the nominal value; the variants include the nominal plant.
    for name in ("workability_route", "workability_leg"):
        assert (work[f"{name}_min"] <= work[name] + 1e-12).all()
        assert (work[name] <= work[f"{name}_max"] + 1e-12).all()
    v = work["workability_route_variant"]
    assert sorted(v["damping_factor"].values.tolist()) == [0.5, 1.0, 2.0]
    assert sorted(v["sway_frequency_factor"].values.tolist()) == [0.97, 1.0, 1.03]
    # Hs at the upper edge of the bin never raises workability.
    assert (v.sel(hs_in_bin="upper") <= v.sel(hs_in_bin="centre") + 1e-12).all()
    # Criterion sensitivity: non-decreasing in the sway limit.
    s = work["workability_route_sensitivity"]
    assert (s.diff("trial_limit") >= -1e-12).all()
    assert float(s["trial_limit"].min()) == 2.0 and float(s["trial_limit"].max()) == 4.0
    text = _pdf_text(workdir / "reports" / "tiny.pdf")
    assert "Wire loads" in text and "Uncertainty and sensitivity" in text
    assert "safe working load 19 800 kN" in text
    page1 = pypdf.PdfReader(workdir / "reports" / "tiny.pdf").pages[0].extract_text().replace("\xa0", " ")
    # The band sentence is in the chapter "Assessment in detail"; page 1 warns only when the
    # recommendation does not hold across the band.
    assert "Uncertainty:" in text and ("holds across the band" in text or "does not hold" in text)
    holds = "the recommendation holds across the band" in " ".join(text.split())
    assert ("does not hold" in page1) == (not holds)
    assert "No leg of this route is given by an hourly hindcast" in text


def test_weather_windows_of_a_hindcast_leg(workdir):  # noqa: F811
    """With the screening on: the windows are those of the report's recommendation,
    which may be the screening's optimum (read from the assessed plant)."""
    shutil.copy(HINDCAST, workdir / "tables" / "buoy.txt")

    def change(cfg):
        cfg["screening"] = SCREENING
        cfg["routes"]["tiny"]["legs"][1] = {
            "name": "buoy", "duration_h": 24, "headings_deg": [90],
            "hindcast": {"file": "tables/buoy.txt", "hs_edges_m": [0, 1, 2, 3, 4, 6, 10],
                         "tz_edges_s": [2, 4, 5, 6, 7, 8, 9, 10, 12, 16]}}
    _edit(workdir, change)
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    win = read(workdir / "results" / "tiny" / "weather_windows.nc")
    assert win["leg"].values.tolist() == ["buoy"]          # scatter legs have no hourly record
    assert win["window_probability"].dims == ("leg", "month")
    assert win["window_probability_all"].dims == ("leg",)
    assert win["workable_hourly"].dims == ("leg", "time")
    assert win["month"].values.tolist() == list(range(1, 13))
    p = win["window_probability"].values
    assert np.all((p[np.isfinite(p)] >= 0) & (p[np.isfinite(p)] <= 1))
    # A 24-hour window needs 24 workable hours: never likelier than a workable hour.
    assert float(win["window_probability_all"].sel(leg="buoy")) <= float(win["workable_fraction"].sel(leg="buoy")) + 1e-12
    # The flag of the assessed option: winter (storms) no better than summer in the Gulf of Maine.
    flags = win["workable_hourly"].sel(leg="buoy")
    months = pd.DatetimeIndex(flags["time"].values).month
    known = flags.values >= 0
    share = {m: float((flags.values[(months == m) & known] == 1).mean()) for m in (1, 7)}
    assert share[1] <= share[7]
    # The flags agree with the per-option variables for the assessed option.
    opt = (win.attrs["option_candidate"], win.attrs["option_tugger"])
    np.testing.assert_array_equal(
        win["workable_hourly_options"].sel(candidate=opt[0], tugger=opt[1], heading=90.0).values,
        win["workable_hourly"].values)
    text = _pdf_text(workdir / "reports" / "tiny.pdf")
    assert "Weather windows" in text and "DNV-ST-N001" in text
    assert "optimised" in win["candidate"].values
    page1 = pypdf.PdfReader(workdir / "reports" / "tiny.pdf").pages[0].extract_text()
    page1 = " ".join(page1.replace("\xa0", " ").split())
    assert f"Recommendation: {opt[0]} rigging, tugger {opt[1]}" in page1
