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
