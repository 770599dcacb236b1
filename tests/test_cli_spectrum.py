"""``jls spectrum FILE --format NAME --json``: the contract of issue 22."""

import json
import subprocess
import sys

import numpy as np
import pytest
import sea_fixtures as fx

from jls.cli import main
from jls.sea import measured


def _run(capsys, *args):
    assert main(["spectrum", *map(str, args)]) == 0
    return json.loads(capsys.readouterr().out)


def test_ndbc_historical_json_contract(capsys):
    out = _run(capsys, fx.NDBC_DENSITY, "--format", "ndbc", "--json")
    for key in ("time", "hs_m", "tm02_s", "tp_s"):
        assert len(out[key]) == 99, key
    assert out["directional"] is True and out["n_directions"] == 24 and out["n_frequencies"] == 47
    assert out["time"][0] == "2019-02-06T00:40:00Z" and out["time"][-1] == "2019-02-10T10:40:00Z"
    # 4 sqrt(m0), sqrt(m0/m2) and the peak band of the file itself
    header, rows = fx.historical_rows("w")
    f = np.array([float(x) for x in header[5:]])
    s = np.array([[float(v) for v in r[5:]] for r in rows])
    df = np.gradient(f)
    m0, m2 = s @ df, s @ (f**2 * df)
    np.testing.assert_allclose(out["hs_m"], 4 * np.sqrt(m0), rtol=1e-12)
    np.testing.assert_allclose(out["tm02_s"], np.sqrt(m0 / m2), rtol=1e-12)
    np.testing.assert_allclose(out["tp_s"], 1 / f[s.argmax(axis=1)], rtol=1e-12)
    assert 0.5 < min(out["hs_m"]) and max(out["hs_m"]) < 5.0       # a February front: 0.6-4.7 m


def test_ndbc_realtime_and_one_dimensional(capsys, tmp_path):
    hist = _run(capsys, fx.NDBC_DENSITY, "--format", "ndbc", "--json")
    rt = _run(capsys, fx.write_realtime(tmp_path), "--format", "ndbc", "--json")
    assert rt["time"] == hist["time"]
    # real-time files print the frequencies to three decimals (0.033 for the 0.0325 Hz
    # band), which moves the band widths: Hs and Tm02 within 0.5 %
    np.testing.assert_allclose(rt["hs_m"], hist["hs_m"], rtol=5e-3)
    np.testing.assert_allclose(rt["tm02_s"], hist["tm02_s"], rtol=5e-3)
    one = _run(capsys, fx.write_historical(tmp_path, kinds="w"), "--format", "ndbc", "--json")
    assert one["directional"] is False and one["n_directions"] == 0
    np.testing.assert_allclose(one["hs_m"], hist["hs_m"], rtol=1e-12)
    assert main(["spectrum", str(fx.NDBC_DENSITY), "--format", "ndbc"]) == 0
    text = capsys.readouterr().out
    assert "99 records, 47 frequencies, directional, 24 directions" in text
    assert "2019-02-06T00:40:00Z" in text


def test_ww3_format(capsys, tmp_path):
    pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    freq = 0.04 * 1.1 ** np.arange(25)
    dirs_to = np.arange(0.0, 360.0, 15.0)
    efth = np.full((2, freq.size, dirs_to.size), 0.01)
    out = _run(capsys, fx.ww3_spectra(tmp_path / "ww3.nc", freq, dirs_to, efth), "--format", "ww3", "--json")
    expected = measured.integrated_parameters(measured.read_ww3_spectra(tmp_path / "ww3.nc"))
    np.testing.assert_allclose(out["hs_m"], expected["hs"].values)
    assert out["time"] == ["2019-02-06T00:00:00Z", "2019-02-06T01:00:00Z"]


def test_errors_are_one_line(tmp_path):
    from jls import cli
    assert cli.SPECTRA_FORMATS == measured.FORMATS
    bad = fx.write_historical(tmp_path, lambda k, h, r: (h[:5], [x[:5] for x in r]), kinds="w")
    r = subprocess.run([sys.executable, "-m", "jls.cli", "spectrum", str(bad), "--format", "ndbc", "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert "41010w2019part.txt: line 1: missing frequency header" in r.stderr
    r = subprocess.run([sys.executable, "-m", "jls.cli", "spectrum", str(bad), "--format", "swan"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "invalid choice: 'swan'" in r.stderr
