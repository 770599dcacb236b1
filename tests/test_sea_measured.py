"""Measured and hindcast spectra (jls.sea.measured, jls.sea.ndbc, jls.sea.directional):
the committed NDBC 41010 files, real-time files made from them, WW3 and ERA5 fixtures."""

import numpy as np
import pandas as pd
import pytest
import sea_fixtures as fx

from jls.errors import InputError
from jls.sea import directional, measured, spectra


@pytest.fixture(scope="module")
def ndbc():
    return measured.read_ndbc_spectra(fx.NDBC_DENSITY)


def test_historical_files_read_as_directional_spectra(ndbc):
    assert ndbc.dims == ("time", "freq", "dir")
    assert ndbc.shape == (99, 47, 24)
    assert str(ndbc["time"].values[0])[:16] == "2019-02-06T00:40"
    assert str(ndbc["time"].values[-1])[:16] == "2019-02-10T10:40"
    assert np.all(np.diff(ndbc["time"].values) > np.timedelta64(0))
    assert ndbc["freq"].values[[0, 1, -1]].tolist() == pytest.approx([0.02, 0.0325, 0.485])
    assert ndbc.attrs["r1_scale"] == 100.0 and ndbc.attrs["r2_scale"] == 100.0
    assert ndbc.attrs["layout"] == "historical" and ndbc.attrs["alpha1_file"] == "41010d2019part.txt.gz"
    # the directions redistribute each band's energy: summed over the bins it is the file's C11
    header, rows = fx.historical_rows("w")
    c11 = np.array([[float(v) for v in r[5:]] for r in rows])
    np.testing.assert_allclose(measured.frequency_spectrum(ndbc).values, c11, rtol=1e-12, atol=1e-12)
    one_d = measured.read_ndbc_spectra(fx.NDBC_DENSITY, directional=False)
    assert one_d.dims == ("time", "freq")


def test_hs_and_tm02_from_the_file_by_hand_and_as_wavespectra_computes_them(ndbc):
    p = measured.integrated_parameters(ndbc)
    header, rows = fx.historical_rows("w")
    f = np.array([float(x) for x in header[5:]])
    s = np.array([float(v) for v in rows[0][5:]])
    df = np.gradient(f)
    assert float(p["hs"][0]) == pytest.approx(4 * np.sqrt(np.sum(s * df)), rel=1e-12)
    assert float(p["tm02"][0]) == pytest.approx(np.sqrt(np.sum(s * df) / np.sum(f**2 * s * df)), rel=1e-12)
    assert float(p["hs"][0]) == pytest.approx(1.902, abs=5e-4)
    wavespectra = pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    ws = wavespectra.read_ndbc_ascii(str(fx.NDBC_DENSITY))
    # wavespectra holds frequencies in float32: agreement to its rounding
    np.testing.assert_allclose(p["hs"].values, ws.spec.hs(tail=False).values, atol=1e-6)
    np.testing.assert_allclose(p["tm02"].values, ws.spec.tm02().values, atol=1e-6)
    tp_ws = ws.spec.tp(smooth=False).values
    e1 = measured.frequency_spectrum(ndbc).values
    flat = np.sort(e1, axis=1)[:, -1] == np.sort(e1, axis=1)[:, -2]     # two bands share the maximum
    np.testing.assert_allclose(p["tp"].values[~flat], tp_ws[~flat], rtol=1e-6)
    assert flat.sum() <= 2


def test_fourier_reconstruction_is_wavespectras_with_r_in_hundredths(ndbc):
    """The standard reconstruction, as wavespectra's construct_spectra, once the historical
    r1, r2 (hundredths) are scaled to 0-1; its mean direction per band is alpha1."""
    vals = {k: np.array([[float(v) for v in r[5:]] for r in fx.historical_rows(k)[1]]) for k in "wdijk"}
    dirs = directional.DEFAULT_DIRS
    D = directional.fourier_spreading(dirs, vals["d"], vals["i"], vals["j"] / 100, vals["k"] / 100)
    np.testing.assert_allclose(ndbc.values, vals["w"][..., None] * D, rtol=1e-12)
    pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    from wavespectra.input.ndbc_ascii import construct_spectra
    shape = vals["w"].shape + (1,)
    ref = construct_spectra(vals["w"].reshape(shape), vals["d"].reshape(shape), vals["i"].reshape(shape),
                            vals["j"].reshape(shape) / 100, vals["k"].reshape(shape) / 100, dirs)
    np.testing.assert_allclose(ndbc.values, ref, rtol=1e-12, atol=1e-15)
    # first circular moment of D points to alpha1 wherever r1 > 0
    th = np.radians(dirs)
    mean = np.degrees(np.arctan2((D * np.sin(th)).sum(-1), (D * np.cos(th)).sum(-1))) % 360
    ok = vals["j"] > 0
    err = np.abs((mean - vals["d"] + 180) % 360 - 180)[ok]
    assert err.max() < 1e-9


def test_realtime_files_give_the_same_spectra(tmp_path, ndbc):
    path = fx.write_realtime(tmp_path)
    rt = measured.read_ndbc_spectra(path)
    assert rt.attrs["layout"] == "real-time" and rt.attrs["r1_scale"] == 1.0
    np.testing.assert_array_equal(rt["time"].values, ndbc["time"].values)   # reversed to increasing
    np.testing.assert_allclose(rt.values, ndbc.values, rtol=1e-12, atol=1e-15)
    # without its direction files, the density file reads as a 1-D spectrum
    for suffix in (".swdir", ".swdir2", ".swr1", ".swr2"):
        (tmp_path / f"41010{suffix}").unlink()
    assert measured.read_ndbc_spectra(path).dims == ("time", "freq")


def _sub(tmp_path, name):
    d = tmp_path / name
    d.mkdir()
    return d


def test_direction_files_all_or_none(tmp_path):
    path = fx.write_historical(tmp_path, kinds="wdi")
    with pytest.raises(InputError, match=r"direction files are missing.*r1 \(41010j2019part.txt\)"):
        measured.read_ndbc_spectra(path)
    assert measured.read_ndbc_spectra(path, directional=False).dims == ("time", "freq")
    with pytest.raises(InputError, match="need the four direction files"):
        measured.read_ndbc_spectra(fx.write_historical(_sub(tmp_path, "alone"), kinds="w"), directional=True)


def _edit_value(kind_to_edit, row, col, value):
    def edit(kind, header, rows):
        if kind == kind_to_edit:
            rows[row][5 + col] = value
        return header, rows
    return edit


def test_malformed_ndbc_files_stop_with_a_named_error(tmp_path):
    # missing frequency header: the time names only
    def no_freq(kind, header, rows):
        return (header[:5], [r[:5] for r in rows]) if kind == "w" else (header, rows)
    p = fx.write_historical(_sub(tmp_path, "a"), no_freq, kinds="w")
    with pytest.raises(InputError, match=r"41010w2019part.txt: line 1: missing frequency header"):
        measured.read_ndbc_spectra(p)
    # no header at all: the first line is a record
    def no_header(kind, header, rows):
        return rows[0], rows[1:]
    p = fx.write_historical(_sub(tmp_path, "b"), no_header, kinds="w")
    with pytest.raises(InputError, match=r"line 1: missing header.*\(got '2019 02 06 00 40"):
        measured.read_ndbc_spectra(p)
    # a 999 fill value in the density drops that record, one hour (input checks, round
    # three): the line is named in the attributes and a report's warning
    p = fx.write_historical(_sub(tmp_path, "c"), _edit_value("w", 4, 15, "999.00"), kinds="w")
    one = measured.read_ndbc_spectra(p)
    full = measured.read_ndbc_spectra(fx.NDBC_DENSITY, directional=False)
    assert one.sizes["time"] == 98 and one.attrs["n_fill_records"] == 1
    assert "density file lines 6" in one.attrs["fill_records"]
    assert full["time"].values[4] not in one["time"].values
    np.testing.assert_array_equal(one.values, np.delete(full.values, 4, axis=0))
    # non-monotonic times: record 10 moved before record 9
    def swap(kind, header, rows):
        rows[8], rows[9] = rows[9], rows[8]
        return header, rows
    p = fx.write_historical(_sub(tmp_path, "d"), swap, kinds="w")
    with pytest.raises(InputError, match=r"line 11: times not monotonic.*2019-02-06T09:40"):
        measured.read_ndbc_spectra(p)
    # a 999 direction in a band that holds energy drops that record (in one without energy
    # it is harmless); a file mostly so is an error naming the first
    p = fx.write_historical(_sub(tmp_path, "e"), _edit_value("d", 2, 15, "999"))
    one = measured.read_ndbc_spectra(p)
    assert one.shape == (98, 47, 24) and "density file lines 4" in one.attrs["fill_records"]
    def mostly(kind, header, rows):
        if kind == "d":
            for r in rows[:60]:
                r[5 + 15] = "999"
        return header, rows
    p = fx.write_historical(_sub(tmp_path, "e2"), mostly)
    with pytest.raises(InputError, match=r"41010d2019part.txt: line 2, frequency .1100 Hz: missing-value "
                                         r"code in the alpha1 of a band that holds energy of 60 of the 99"):
        measured.read_ndbc_spectra(p)
    p = fx.write_historical(_sub(tmp_path, "f"), _edit_value("d", 2, 0, "999"))
    assert measured.read_ndbc_spectra(p).shape == (99, 47, 24)        # 0.02 Hz holds no energy
    # r1 beyond 100 hundredths; a direction file with other records than the density's
    p = fx.write_historical(_sub(tmp_path, "g"), _edit_value("j", 3, 20, "150"))
    with pytest.raises(InputError, match=r"41010j2019part.txt: line 5, frequency .1600 Hz: r1 outside"):
        measured.read_ndbc_spectra(p)
    def drop_in_k(kind, header, rows):
        return header, (rows[:50] + rows[51:]) if kind == "k" else rows
    p = fx.write_historical(_sub(tmp_path, "h"), drop_in_k)
    with pytest.raises(InputError, match=r"41010k2019part.txt: time: records differ from the density file"):
        measured.read_ndbc_spectra(p)
    # a ragged row and an unparsable number
    p = fx.write_historical(_sub(tmp_path, "i"), lambda k, h, r: (h, r[:3] + [r[3][:-2]] + r[4:]), kinds="w")
    with pytest.raises(InputError, match=r"line 5: expected 52 fields"):
        measured.read_ndbc_spectra(p)
    p = fx.write_historical(_sub(tmp_path, "j"), _edit_value("w", 0, 3, "1.2.3"), kinds="w")
    with pytest.raises(InputError, match=r"line 2: unparsable number in column .0425 \(got '1.2.3'\)"):
        measured.read_ndbc_spectra(p)
    with pytest.raises(InputError, match="unknown spectra format"):
        measured.read_spectra(fx.NDBC_DENSITY, "swan")


def test_realtime_with_changing_frequencies_is_an_error(tmp_path):
    path = fx.write_realtime(tmp_path, n=5)
    lines = path.read_text().splitlines()
    lines[3] = lines[3].replace("(0.033)", "(0.034)")
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(InputError, match=r"41010.data_spec: line 4: frequencies differ between records"):
        measured.read_ndbc_spectra(path)


ERA5_FREQ = 0.03453 * 1.1 ** np.arange(30)


def _jonswap_directional(freq, dirs_from, hs=2.0, tp=12.0, from_deg=45.0, s=10.0):
    """E(f, dir) [m2 Hz-1 degree-1] of a JONSWAP spread cos-2s about ``from_deg``."""
    S = spectra.jonswap(2 * np.pi * freq, hs, tp) * 2 * np.pi
    return S[:, None] * directional.cos2s_spreading(dirs_from, from_deg, s)[None, :]


def test_ww3_spectra_through_wavespectra(tmp_path):
    pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    freq = ERA5_FREQ
    dirs_to = np.arange(0.0, 360.0, 15.0)
    E = _jonswap_directional(freq, (dirs_to + 180) % 360)               # on the from-directions
    efth_rad = np.repeat((E * 180 / np.pi)[None], 3, axis=0)           # m2 s rad-1
    path = fx.ww3_spectra(tmp_path / "ww3.nc", freq, dirs_to, efth_rad)
    got = measured.read_spectra(path, "ww3")
    assert got.dims == ("time", "freq", "dir") and got.shape == (3, 30, 24)
    p = measured.integrated_parameters(got)
    hs_band = 4 * np.sqrt(np.sum(E.sum(1) * 15.0 * np.gradient(freq)))
    np.testing.assert_allclose(p["hs"].values, hs_band, rtol=1e-6)
    # going-to 225 deg is coming from 45 deg
    assert float(got["dir"][int(got.isel(time=0).sum("freq").argmax("dir"))]) == 45.0
    bad = fx.ww3_spectra(tmp_path / "deg.nc", freq, dirs_to, efth_rad, units="m2 s degree-1")
    with pytest.raises(InputError, match=r"deg.nc: efth: unexpected units.*m2 s degree-1"):
        measured.read_ww3_spectra(bad)
    with pytest.raises(InputError, match=r"not WW3 spectral output: variable\(s\) efth, frequency, direction, time not found"):
        measured.read_ww3_spectra(fx.era5_parameters(tmp_path / "p.nc", {"swh": [1.0, 2.0]}))


def test_era5_spectra_through_wavespectra(tmp_path):
    pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    dd = 15.0
    dirs_to = np.arange(0.0, 360.0, dd) + dd / 2          # ERA5 direction bins (going to)
    E = _jonswap_directional(ERA5_FREQ, (dirs_to + 180) % 360, hs=3.0, tp=10.0, from_deg=97.5)
    d2fd = np.log10(np.maximum(E.T * 180 / np.pi, 1e-30))  # (direction, frequency), per radian
    path = fx.era5_spectra(tmp_path / "era5.nc", np.repeat(d2fd[None], 2, axis=0))
    got = measured.read_spectra(path, "era5")
    assert got.shape == (2, 30, 24)
    hs_band = 4 * np.sqrt(np.sum(E.sum(1) * dd * np.gradient(ERA5_FREQ)))
    np.testing.assert_allclose(measured.integrated_parameters(got)["hs"].values, hs_band, rtol=1e-5)
    assert float(got["dir"][int(got.isel(time=0).sum("freq").argmax("dir"))]) == 97.5
    with pytest.raises(InputError, match="not ERA5 2-D wave spectra"):
        measured.read_era5_spectra(fx.era5_parameters(tmp_path / "p.nc", {"swh": [1.0]}))


def test_spectra_array_checks_its_input():
    t = pd.date_range("2020-01-01", periods=2, freq="h")
    with pytest.raises(InputError, match="frequencies must be"):
        measured.spectra_array(np.zeros((2, 3)), t, [0.1, 0.3, 0.2])
    with pytest.raises(InputError, match="frequencies must be"):
        measured.spectra_array(np.zeros((2, 3)), t, [2.0, 3.0, 4.0])          # rad/s, not Hz
    with pytest.raises(InputError, match="times not strictly increasing"):
        measured.spectra_array(np.zeros((2, 2)), t[::-1], [0.1, 0.2])
    with pytest.raises(InputError, match="negative spectral density"):
        measured.spectra_array(-np.ones((2, 2)), t, [0.1, 0.2])


def test_without_the_spectra_extra_the_error_names_it(tmp_path, monkeypatch):
    """wavespectra is the optional extra [spectra]: without it (an import that fails, as
    where it is not installed), WW3 and ERA5 spectra stop with one error naming the extra;
    NDBC files are read without it."""
    monkeypatch.setitem(__import__("sys").modules, "wavespectra", None)
    freq, dirs_to = ERA5_FREQ, np.arange(0.0, 360.0, 15.0)
    efth = np.repeat((_jonswap_directional(freq, (dirs_to + 180) % 360) * 180 / np.pi)[None], 2, axis=0)
    path = fx.ww3_spectra(tmp_path / "ww3.nc", freq, dirs_to, efth)
    with pytest.raises(InputError, match=r"ww3.nc: reading WAVEWATCH III spectra needs wavespectra, "
                                         r"the optional extra \[spectra\].*pip install -e '\.\[spectra\]'"):
        measured.read_spectra(path, "ww3")
    d2fd = np.log10(np.maximum(_jonswap_directional(freq, (dirs_to + 180) % 360).T * 180 / np.pi, 1e-30))
    era5 = fx.era5_spectra(tmp_path / "era5.nc", np.repeat(d2fd[None], 2, axis=0))
    with pytest.raises(InputError, match=r"ERA5 spectra needs wavespectra, the optional extra \[spectra\]"):
        measured.read_spectra(era5, "era5")
    assert measured.read_spectra(fx.NDBC_DENSITY, "ndbc").sizes["time"] > 0
