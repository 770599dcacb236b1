"""End-to-end: a route whose legs are given by measured spectra and by an NDBC standard
meteorological file (the example route config/examples/spectra_route.yaml) through the
workflow to the report: binned like hindcast legs, weather windows and the route simulation
on their hourly records, the measured-spectrum response and its ratio in the report."""

import shutil

import numpy as np
import pypdf
import pytest
import yaml
from test_pipeline import ROOT, make_workdir, snakemake, tiny_config

from jls.io.netcdf import read

pytestmark = pytest.mark.slow
EXAMPLE = ROOT / "config" / "examples" / "spectra_route.yaml"


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("spectra")
    cfg = tiny_config(tmp)
    route = yaml.safe_load(EXAMPLE.read_text())["routes"]["buoy_41010"]
    cfg["routes"] = {"buoy": route}
    work = make_workdir(tmp, cfg)
    for src in ("tests/data/spectra/ndbc_41010_2019", "tests/data/metocean"):
        shutil.copytree(ROOT / src, work / src)
    r = snakemake(work)
    assert r.returncode == 0, r.stderr[-4000:]
    return work


def test_spectra_and_metocean_legs_are_assessed_like_hindcast_legs(run):
    res = run / "results" / "buoy"
    sea = read(res / "sea_states.nc")
    assert sea.attrs["leg_kind_spectra_leg"] == "spectra" and sea.attrs["leg_kind_stdmet_leg"] == "metocean"
    assert float(sea["record_total"].sel(leg="spectra_leg")) == 99
    assert float(sea["record_total"].sel(leg="stdmet_leg")) == 99
    # the spectra leg's headings come from its mean directions on the course
    assert sea.attrs["heading_source_spectra_leg"] == "direction_table"
    win = read(res / "weather_windows.nc")
    assert sorted(win["leg"].values.tolist()) == ["spectra_leg", "stdmet_leg"]
    voy = read(res / "voyage.nc")
    assert "pass_probability" in voy            # every leg hourly: the route sailed from each departure


def test_measured_response_and_its_ratio_in_the_report(run):
    res = run / "results" / "buoy"
    m = read(res / "measured_response.nc")
    assert m["leg"].values.tolist() == ["spectra_leg"]
    assert m["sigma_ratio"].dims == ("leg", "candidate", "tugger")
    assert int(m["hours"].sel(leg="spectra_leg")) == 99
    r = m["sigma_ratio"].sel(leg="spectra_leg")
    expected = m["sigma_measured"].sum("time") / m["sigma_jonswap"].sum("time")
    np.testing.assert_allclose(r.values, expected.sel(leg="spectra_leg").values)
    assert np.all(np.isfinite(r.values)) and np.all(r.values > 0)
    work = read(res / "workability.nc")
    assert set(m["candidate"].values) == set(work["candidate"].values)
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "buoy.pdf").pages)
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    assert "Wave spectra" in text and "41010w2019part.txt.gz" in text and "41010h2019part.txt" in text
    # the range over the options as the dataset holds it
    assert f"{float(r.min()):.3f} – {float(r.max()):.3f}" in text


def test_page_one_warns_where_the_measured_seas_drive_more_sway(run):
    """The verdicts of a spectra leg use the JONSWAP on each hour's (Hs, Tm02); where the
    measured seas drive more sway (ratio above 1), page 1 says the leg's workability is
    overstated, with the ratio from the dataset."""
    m = read(run / "results" / "buoy" / "measured_response.nc")
    r = m["sigma_ratio"].sel(leg="spectra_leg")
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "buoy.pdf").pages[:3])
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    page1 = text[:text.index("2. Operational basis")] if "2. Operational basis" in text else text
    assert float(r.min()) > 1.0                      # the 41010 swell: more sway than the JONSWAP's
    assert "the workability of those legs is overstated" in page1
    assert any(f"spectra_leg {v:.2f} x" in page1 for v in r.values.ravel())
