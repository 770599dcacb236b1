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


def test_the_spectra_leg_is_judged_hour_by_hour_on_its_measured_sway(run):
    """The spectra leg's workability and weather windows take each hour's sway over its
    measured spectrum: with the 41010 swell (ratio above 1) fewer hours pass than the
    binned JONSWAP cells say; the metocean leg keeps its binned figure; the route is the
    duration-weighted mean of the legs as before."""
    res = run / "results" / "buoy"
    work, m = read(res / "workability.nc"), read(res / "measured_response.nc")
    assert work["leg_hourly"].sel(leg="spectra_leg") and not work["leg_hourly"].sel(leg="stdmet_leg")
    hourly, binned = work["workability_leg"], work["workability_leg_binned"]
    np.testing.assert_array_equal(hourly.sel(leg="stdmet_leg").values, binned.sel(leg="stdmet_leg").values)
    assert float((binned - hourly).sel(leg="spectra_leg").max()) > 0.0
    sea = read(res / "sea_states.nc")
    np.testing.assert_allclose(work["workability_route"].values,
                               (hourly * sea["leg_weight"]).sum("leg").transpose(*work["workability_route"].dims).values)
    assert np.all(work["workability_route_min"] <= work["workability_route"] + 1e-12)
    assert np.all(work["workability_route"] <= work["workability_route_max"] + 1e-12)
    # the criteria's shares of the failing hours leave the winch's (if any) for the rest
    gov = work["governing_share"].sel(leg="spectra_leg").sum("criterion")
    assert np.all(gov <= 1.0 - hourly.sel(leg="spectra_leg") + 1e-12)
    # every hour judged once over its headings
    assert float(m["heading_weight"].sel(leg="spectra_leg").sum()) == pytest.approx(99)
    # every criterion of each hour on its own directional sea (jls.stages.hourly_seas), at
    # the headings the hour is met at; the workability judges the hours on it
    u = m["utilisation"].sel(leg="spectra_leg")
    assert set(u["criterion"].values) == set(work["criterion"].values)
    met = m["heading_weight"].sel(leg="spectra_leg") > 0
    assert bool(np.isfinite(u.where(met)).sum() == met.sum() * u.sizes["candidate"] * u.sizes["tugger"]
                * u.sizes["criterion"])
    assert "own directional sea" in work.attrs["hourly_rule"]
    assert read(res / "voyage.nc").attrs["own_sea_not_used"] == ""      # every extreme on the own seas
    win = read(res / "weather_windows.nc")
    assert win.attrs["measured_sway_legs"] == "spectra_leg"
    assert read(res / "voyage.nc").attrs["measured_sway_legs"] == "spectra_leg"
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "buoy.pdf").pages)
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    # the report's cross-check of the workability against the pass flags holds on a route
    # with a leg judged hour by hour (its cells checked against its binned figure)
    assert "the datasets are inconsistent" not in text
    assert "is judged on its own directional sea for every criterion" in text
    c, g = win.attrs["option_candidate"], win.attrs["option_tugger"]
    at = dict(candidate=c, tugger=g, leg="spectra_leg")
    assert f"{100 * float(hourly.sel(at)):.1f} {100 * float(binned.sel(at)):.1f}" in text


def test_the_hindcast_voyage_extreme_takes_the_spectra_legs_own_seas(run):
    """The long-term extreme of the recorded hours (hindcast_*) takes the spectra leg's
    hours at their own-sea levels: the stage recomputed from the run's datasets gives
    voyage.nc's numbers; on the spectra leg alone the own seas' levels move the sway's
    voyage level off the JONSWAP's (up without a tugger: the 41010 swell); the route's
    level is at least each leg's (up-crossings add)."""
    from jls.assessment.criterion_levels import criterion_statistics
    from jls.assessment.hourly import route_own_heading_utilisation
    from jls.assessment.route_hours import common_hours
    from jls.assessment.voyage import hindcast_long_term, long_term_extreme
    from jls.assessment.windows import read_route_hindcasts
    from jls.assessment.workability import criteria_array
    from jls.config.loader import load_yaml, validate
    from jls.stages.voyage import voyage
    res = run / "results" / "buoy"
    cfg = validate(load_yaml(run / "config" / "config.yaml"), base_dir=run)
    sea, response, operability = read(res / "sea_states.nc"), read(res / "response.nc"), read(res / "operability.nc")
    route, gamma = cfg["routes"]["buoy"], cfg["sea"]["gamma"]
    voy, m = read(res / "voyage.nc"), read(res / "measured_response.nc")
    again = voyage(sea, response, operability, cfg["assessment"]["criteria"], cfg["sea"]["hs_in_bin"], route,
                   base_dir=run, gamma=gamma, measured=m)
    np.testing.assert_allclose(again["hindcast_voyage_level"].values, voy["hindcast_voyage_level"].values,
                               rtol=1e-9)
    records = read_route_hindcasts(route, run, gamma=gamma)
    hours = common_hours({leg["name"]: records[leg["name"]] for leg in route["legs"]})
    st = criterion_statistics(operability, criteria_array(cfg["assessment"]["criteria"]))
    own = route_own_heading_utilisation(m, hours, sea["heading_probability"]["heading"].values)
    hp, dur = sea["heading_probability"], sea["duration_h"]
    kw = dict(mpm_unit=st["mpm"], exposure_h=float(response.attrs["exposure_h"]),
              cycles=response.attrs["mpm_cycles"])

    def level(legs, with_own):
        h = hours.sel(leg=legs)
        extra = dict(own=own.sel(leg=legs), **kw) if with_own else {}
        return hindcast_long_term(st["sigma"], st["tz_response"], h, dur.sel(leg=legs), hp.sel(leg=legs),
                                  st["limit"], **extra)["voyage_level"]
    sway = dict(criterion="relative_sway_m")
    mine, jonswap = level(["spectra_leg"], True).sel(sway), level(["spectra_leg"], False).sel(sway)
    # undamped, the swell the JONSWAP leaves out raises the sway's voyage level; damped by the
    # tugger the own directional sea may give less than the JONSWAP at the leg's headings:
    # either way the level is the own seas', not the JONSWAP's
    assert np.all(mine.sel(tugger="none").values > 1.1 * jonswap.sel(tugger="none").values)
    assert np.all(np.abs(mine.values / jonswap.values - 1.0) > 1e-3)
    whole = voy["hindcast_voyage_level"]
    assert np.all(whole.values >= level(["spectra_leg"], True).values * (1 - 1e-9))
    assert np.all(whole.values >= level(["stdmet_leg"], True).values * (1 - 1e-9))
    # the scatter cells' extreme takes the spectra leg's records on their own seas too: the
    # stage gives voyage.nc's numbers, nothing is left on JONSWAP, and against the binned
    # JONSWAP the own seas raise the undamped sway's voyage level (the 41010 swell)
    np.testing.assert_allclose(again["voyage_level"].values, voy["voyage_level"].values, rtol=1e-9)
    assert voy.attrs["own_sea_not_used"] == ""
    ratio = voy["own_sea_level_ratio"].sel(sway)
    np.testing.assert_allclose(ratio.values, (voy["voyage_level"] / voy["voyage_level_jonswap"]).sel(sway).values,
                               rtol=1e-12)
    assert np.all(ratio.values >= 0.9)
    # on the spectra leg alone: the scatter extreme with its own records is the hindcast
    # extreme of the same own-sea hours (two paths, the same hours and probabilities), and
    # undamped far above its binned JONSWAP's (the swell)
    from jls.assessment.workability import assessed_hs
    from jls.stages.voyage import own_table_seas
    one = sea.sel(leg=["spectra_leg"])
    response_crit = criterion_statistics(response, criteria_array(cfg["assessment"]["criteria"]))
    kw.pop("mpm_unit")
    rec, left = own_table_seas(m, one, st["criterion"].values.tolist(), limit=response_crit["limit"], **kw)
    assert left == {}
    args = (response_crit["sigma"], response_crit["tz_response"], one["cell_probability"],
            assessed_hs(one, cfg["sea"]["hs_in_bin"]), one["duration_h"], response_crit["limit"])
    scatter_own = long_term_extreme(*args, own=rec, shares=False)["voyage_level"].sel(sway)
    scatter_jonswap = long_term_extreme(*args, shares=False)["voyage_level"].sel(sway)
    np.testing.assert_allclose(scatter_own.values, mine.transpose(*scatter_own.dims).values, rtol=0.03)
    assert np.all(scatter_own.sel(tugger="none").values > 2.0 * scatter_jonswap.sel(tugger="none").values)
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "buoy.pdf").pages)
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    assert "takes each record (an hour, or a table" in text
    assert "enter the long-term extreme by their records" in text.replace("long- term", "long-term")
    assert "Not on their own seas" not in text

def test_page_one_warns_where_the_measured_seas_drive_more_sway(run):
    """Where the measured seas drive more sway (ratio above 1), page 1 says the voyage
    extremes of the spectra legs (JONSWAP seas) understate it, with the ratio from the
    dataset; their time-domain cells run on their own sea."""
    m = read(run / "results" / "buoy" / "measured_response.nc")
    r = m["sigma_ratio"].sel(leg="spectra_leg")
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(run / "reports" / "buoy.pdf").pages[:3])
    text = " ".join(text.replace("\xa0", " ").replace("\u2009", " ").split())
    page1 = text[:text.index("2. Assessment in detail")] if "2. Assessment in detail" in text else text
    assert float(r.min()) > 1.0                      # the 41010 swell: more sway than the JONSWAP's
    assert "unconservative by that factor" not in page1
    ratio = read(run / "results" / "buoy" / "voyage.nc")["own_sea_level_ratio"].sel(
        criterion="relative_sway_m", non_exceedance=0.5)
    assert any(f"median voyage level of the relative sway is {v:.2f} x" in page1 for v in ratio.values.ravel())
    assert "as does the long-term voyage extreme of their recorded hours" in page1.replace("long- term", "long-term")
    assert "judge every criterion on each hour's own sea" in page1.replace("\u2019", "'")
    assert any(f"spectra_leg {v:.2f} x" in page1 for v in r.values.ravel())


def test_the_spectra_legs_time_domain_cells_run_on_its_measured_sea(run):
    """The spectra leg's time-domain cells are its own (named __leg-spectra_leg), run on a
    multi-directional record of the measured spectra binned into the cell, against that
    sea's frequency-domain sigma; the metocean leg's cells stay JONSWAP cells. The leg's
    mean spectrum is stored for the report's figure, and the verification refuses the leg."""
    import json
    res = run / "results" / "buoy"
    cells = json.loads((res / "timedomain" / "cells.json").read_text())
    own = [c for c in cells if c.get("leg") == "spectra_leg"]
    assert own and all(c["name"].endswith("__leg-spectra_leg") for c in own)
    assert all("leg" not in c for c in cells if c not in own)
    for c in own:
        td = read(res / "timedomain" / f"{c['name']}.nc")
        assert td.attrs["sea_leg"] == "spectra_leg" and td.attrs["sea"].startswith("measured: ")
        err = np.abs(td["sigma"].values - td["sigma_fd"].values)
        assert np.all(err <= 4 * td["sigma_seed_std_expected"].values + 0.1 * td["sigma_fd"].values), c["name"]
    m = read(res / "measured_response.nc")
    assert float(m["spectrum_mean"].sel(leg="spectra_leg").max()) > 0
    assert read(res / "workability.nc").attrs["verification_refused_legs"].startswith("spectra_leg (measured)")
