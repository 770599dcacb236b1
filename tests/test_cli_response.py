"""``jls response``: the contract's three forms print candidates.<name>.<tugger>.<criterion>
{sigma, tz_response, mpm}; the numbers are the library's; --vessel-heading turns true
directions into relative headings; bad options are one-line errors."""

import json
import math

import numpy as np
import pytest

from jls.cli import main
from jls.commands.response import transfer_from_config
from jls.response.sea_state import sea_state_statistics
from jls.sea.sea_state import WaveSystem, parse_spreading, torsethaugen_systems


def _run(capsys, *argv):
    assert main(["response", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def tr(cfg):
    return transfer_from_config(cfg, ".")


def _check_shape(out, cfg):
    names = ["baseline", *[c["name"] for c in cfg.get("candidates", [])]]
    assert list(out["candidates"]) == names
    tuggers = [t["name"] for t in cfg["tuggers"]]
    for per in out["candidates"].values():
        assert list(per) == tuggers
        for crit in per.values():
            sway = crit["relative_sway_m"]
            assert set(sway) == {"sigma", "tz_response", "mpm"}
            assert sway["mpm"] > 3 * sway["sigma"] > 0 and 5 < sway["tz_response"] < 30


def test_torsethaugen_at_a_heading_is_the_librarys_two_systems(capsys, cfg, tr):
    out = _run(capsys, "--hs", "2", "--tp", "12", "--spectrum", "torsethaugen", "--heading", "90")
    _check_shape(out, cfg)
    systems = torsethaugen_systems(2.0, "tp", 12.0, from_deg=90.0, spreading=cfg["sea"]["spreading"])
    assert [s["kind"] for s in out["sea_state"]["systems"]] == ["swell", "wind"]
    assert out["sea_state"]["hs_m"] == pytest.approx(2.0, rel=1e-12)
    ds = sea_state_statistics(tr, [systems], 0.0, exposure_h=cfg["assessment"]["exposure_h"])
    got = out["candidates"]["baseline"]["none"]["relative_sway_m"]
    assert got["sigma"] == pytest.approx(float(ds["sigma"].sel(candidate="baseline", tugger="none",
                                                               criterion="relative_sway_m")[0]), rel=1e-12)
    # the 3-h MPM of the response's own cycle count
    assert got["mpm"] == pytest.approx(got["sigma"] * math.sqrt(2 * math.log(3 * 3600 / got["tz_response"])))


def test_jonswap_spread_and_two_systems_with_a_vessel_heading(capsys, cfg, tr):
    spread = _run(capsys, "--hs", "2", "--tp", "12", "--spectrum", "jonswap", "--gamma", "3.3",
                  "--spreading", "cos2s:10", "--heading", "90")
    _check_shape(spread, cfg)
    long = _run(capsys, "--hs", "2", "--tp", "12", "--spectrum", "jonswap", "--gamma", "3.3",
                "--spreading", "long-crested", "--heading", "90")
    s, lc = (o["candidates"]["baseline"]["none"]["relative_sway_m"]["sigma"] for o in (spread, long))
    assert s < lc                                   # spreading takes energy off the beam
    # two systems with true directions: the vessel heading 200 meets them at 130 and 80 deg
    two = _run(capsys, "--system", "1.5,7,250,3.3,cos2s:4", "--system", "1,16,300,5,cos2s:13",
               "--vessel-heading", "200")
    _check_shape(two, cfg)
    rel = [x["relative_heading_deg"] for x in two["sea_state"]["systems"]]
    assert rel == pytest.approx([130.0, 80.0]) and two["sea_state"]["vessel_heading_deg"] == 200.0
    systems = [WaveSystem("jonswap", 1.5, 7.0, 250.0, parse_spreading("cos2s:4"), "wind", 3.3),
               WaveSystem("jonswap", 1.0, 16.0, 300.0, parse_spreading("cos2s:13"), "swell", 5.0)]
    ds = sea_state_statistics(tr, [systems], 200.0)
    np.testing.assert_allclose([two["candidates"][c][t]["relative_yaw_deg"]["sigma"]
                                for c in ds["candidate"].values for t in ds["tugger"].values],
                               ds["sigma"].sel(criterion="relative_yaw_deg").values[0].ravel(), rtol=1e-12)
    # the same sea turned with the vessel: the same answer
    turned = _run(capsys, "--system", "1.5,7,10,3.3,cos2s:4", "--system", "1,16,60,5,cos2s:13",
                  "--vessel-heading", "320")
    np.testing.assert_allclose(_flat(turned), _flat(two), rtol=1e-9)


def _flat(out):
    return [v for per in out["candidates"].values() for crit in per.values()
            for stats in crit.values() for v in stats.values()]


@pytest.mark.parametrize("argv, text", [
    (["--hs", "2"], "--tp or --tz"),
    (["--tp", "9"], "give --hs"),
    (["--system", "1,8,90,3.3"], "five fields"),
    (["--system", "1,8,1.57,3.3,cos2s:x"], "exponent"),
    (["--system", "1,8,400,3.3,long"], "DIR_FROM"),
    (["--hs", "2", "--tp", "9", "--spectrum", "torsethaugen", "--gamma", "2"], "own gammas"),
    (["--hs", "2", "--tp", "9", "--heading", "400"], "--heading"),
])
def test_bad_options_are_one_line_errors(capsys, argv, text):
    assert main(["response", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith("jls: error:") and text in err and err.count("\n") == 1


SPECTRA = "tests/data/spectra/ndbc_41010_2019/41010w2019part.txt.gz"


def test_a_measured_directional_record_is_its_direction_bins_as_the_measured_machinery_integrates_it(capsys, tr):
    """--spectra: the NDBC 41010 record of 2019-02-06 00:40 on course 200, each direction bin
    a long-crested measured system, against jls.response.directional on the same record (which
    takes the spectrum flat over the outer halves of its end bands: within 1 %)."""
    import xarray as xr

    from jls.response.directional import directional_moments
    from jls.response.solver import relative_power
    from jls.sea.measured import read_spectra
    out = _run(capsys, "--spectra", SPECTRA, "--format", "ndbc", "--time", "2019-02-06T00:40Z",
               "--vessel-heading", "200")
    assert len(out["sea_state"]["systems"]) == 24 and out["sea_state"]["hs_m"] == pytest.approx(1.902, abs=1e-3)
    efth = read_spectra(SPECTRA, "ndbc").isel(time=[0])
    p = tr.plant
    P = relative_power(p["M"].values, p["K"].values, p["Kb"].values, p["C"].values, tr.exc.omega,
                       tr.exc.qb, tr.exc.fairlead_sway, list(tr.tuggers.values()))[:, :, :, 0]
    power = xr.DataArray(P, dims=("candidate", "tugger", "heading", "omega"),
                         coords={"heading": tr.exc.headings, "omega": tr.exc.omega})
    ref = directional_moments(efth, power, 200.0)["sigma"].values[0]
    got = np.array([[out["candidates"][c][t]["relative_sway_m"]["sigma"] for t in tr.tuggers]
                    for c in tr.candidates])
    np.testing.assert_allclose(got, ref, rtol=1e-2)
    assert main(["response", "--spectra", SPECTRA, "--format", "ndbc", "--time", "2020-01-01T00:00"]) == 2
    assert "no record within 30 min" in capsys.readouterr().err
