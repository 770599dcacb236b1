"""Integrated-parameter files (jls.sea.metocean): NDBC standard meteorological text,
ERA5 single-level and WAVEWATCH III point output written by the tests."""

import numpy as np
import pytest
import sea_fixtures as fx

from jls.errors import InputError
from jls.sea import metocean
from jls.sea.hindcast import hindcast_gaps

STDMET = """\
#YY  MM DD hh mm WDIR WSPD GST  WVHT   DPD   APD MWD   PRES  ATMP  WTMP  DEWP  VIS  TIDE
#yr  mo dy hr mn degT m/s  m/s     m   sec   sec degT   hPa  degC  degC  degC   mi    ft
2019 02 06 00 50 350  7.0  9.0  1.90  9.09  6.98  99 1021.1  19.0  23.9  14.1 99.0 99.00
2019 02 06 01 50 340  7.2  9.1  1.99  9.09  7.10 105 1021.3  19.1  23.9  14.0 99.0 99.00
2019 02 06 02 50 999 99.0 99.0 99.00 99.00 99.00 999 1021.5  19.1  23.9  14.0 99.0 99.00
2019 02 06 04 50 330  6.1  8.0  1.55 99.00  6.78 999 1021.9  19.0  23.8  14.2 99.0 99.00
"""
REALTIME = """\
#YY  MM DD hh mm WDIR WSPD GST  WVHT   DPD   APD MWD   PRES  ATMP  WTMP  DEWP  VIS PTDY  TIDE
#yr  mo dy hr mn degT m/s  m/s     m   sec   sec degT   hPa  degC  degC  degC  nmi  hPa    ft
2020 06 08 03 40 160  5.0  6.0   1.1   5.6   4.9 196 1015.0  27.0  28.1  23.0   MM   MM    MM
2020 06 08 02 40 150  5.0  6.0    MM    MM    MM  MM 1015.1  27.0  28.1  23.0   MM   MM    MM
2020 06 08 01 40 140  6.0  7.0   1.1   7.1   4.9 144 1015.2  27.1  28.1  23.1   MM   MM    MM
"""


def test_ndbc_stdmet_fill_values_are_gaps(tmp_path):
    p = tmp_path / "41010h2019.txt"
    p.write_text(STDMET)
    df = metocean.read_ndbc_stdmet(p)
    assert list(df.columns) == ["hs", "tp", "tz", "direction"]
    assert df.index[0].isoformat() == "2019-02-06T00:50:00+00:00"
    np.testing.assert_array_equal(df["hs"].to_numpy(), [1.90, 1.99, np.nan, 1.55])
    np.testing.assert_array_equal(df["tp"].isna().to_numpy(), [False, False, True, True])
    assert df["direction"].iloc[0] == 99.0                   # a direction of 99 deg is a value
    assert np.isnan(df["direction"].iloc[3])
    assert df.attrs["gaps"] == 1 and df.attrs["format"] == "ndbc_stdmet"
    series = metocean.hindcast_series(df, "tz")
    assert len(series) == 3 and series.attrs["n_gap_records"] == 1
    # one record without a direction: the column stays, and a table binned by direction
    # leaves that hour out (input checks, round three: one hour, not the column)
    assert np.isnan(series["direction"].iloc[2]) and series["direction"].notna().sum() == 2
    from jls.sea.hindcast import bin_hindcast
    table = bin_hindcast(series, [0, 5], [0, 20], [0, 180, 360])
    assert int(table["count"].sum()) == 2 and table.attrs["n_missing_direction"] == 1
    assert "1 record(s) without a wave direction" in table.attrs["warnings"]
    assert hindcast_gaps(series, step="1h").n_records == 3
    counts = bin_hindcast(series, [0, 1, 2, 3], [5, 6, 7, 8])
    assert int(counts["count"].sum()) == 3
    rt = tmp_path / "41010.txt"
    rt.write_text(REALTIME)
    df = metocean.read_ndbc_stdmet(rt)
    assert df.index.is_monotonic_increasing and len(df) == 3
    assert np.isnan(df["hs"].iloc[1]) and df["hs"].iloc[2] == 1.1


def test_ndbc_stdmet_malformed(tmp_path):
    p = tmp_path / "x.txt"
    p.write_text(STDMET.replace("2019 02 06 01 50", "2019 02 05 01 50"))
    with pytest.raises(InputError, match=r"x.txt: line 4: times not monotonic"):
        metocean.read_ndbc_stdmet(p)
    p.write_text(STDMET.replace("WVHT", "WAVE"))
    with pytest.raises(InputError, match="no WVHT column"):
        metocean.read_ndbc_stdmet(p)
    p.write_text("\n".join(STDMET.splitlines()[2:]))
    with pytest.raises(InputError, match=r"line 1: missing header"):
        metocean.read_ndbc_stdmet(p)
    p.write_text(STDMET.replace("1.99", "45.0"))
    with pytest.raises(InputError, match=r"hs at 2019-02-06T01:50:00\+00:00: hs outside 0-30 m"):
        metocean.read_ndbc_stdmet(p)


ERA5 = {"swh": [1.8, 2.4, 2.1], "pp1d": [13.5, 14.0, 14.2], "mwp": [9.1, 9.6, 9.8], "mwd": [80.0, 85.0, 90.0],
        "shww": [1.1, 1.6, 1.2], "mpww": [5.1, 5.9, 5.5], "mdww": [20.0, 25.0, 30.0],
        "shts": [1.4, 1.8, 1.7], "mpts": [12.1, 12.6, 12.9], "mdts": [95.0, 95.0, 100.0]}


def test_era5_single_level_with_partitions(tmp_path):
    df = metocean.read_era5_parameters(fx.era5_parameters(tmp_path / "era5.nc", ERA5))
    assert list(df.columns) == ["hs", "tp", "te", "direction", "wind_hs", "wind_te", "wind_direction",
                                "swell_hs", "swell_te", "swell_direction"]
    np.testing.assert_array_equal(df["swell_te"].to_numpy(), ERA5["mpts"])
    assert df.index.tz is not None and df.index[0].isoformat() == "2019-02-06T00:00:00+00:00"
    # found by standard name whatever the variable is called; by the short name without one
    renamed = fx.era5_parameters(tmp_path / "renamed.nc", ERA5, names={"swh": "VHM0", "mwd": "VMDR"})
    np.testing.assert_array_equal(metocean.read_era5_parameters(renamed)["hs"].to_numpy(), ERA5["swh"])
    bare = fx.era5_parameters(tmp_path / "bare.nc", ERA5, standard_names=False, time="time")
    np.testing.assert_array_equal(metocean.read_era5_parameters(bare)["direction"].to_numpy(), ERA5["mwd"])


def test_era5_wrong_units_and_unknown_names(tmp_path):
    p = fx.era5_parameters(tmp_path / "cm.nc", ERA5, units={"swh": "cm"})
    with pytest.raises(InputError, match=r"cm.nc: swh: units of hs must be m \(got 'cm'\)"):
        metocean.read_era5_parameters(p)
    p = fx.era5_parameters(tmp_path / "rad.nc", ERA5, units={"mwd": "radian"})
    with pytest.raises(InputError, match=r"mwd: units of direction must be degree"):
        metocean.read_era5_parameters(p)
    p = fx.era5_parameters(tmp_path / "odd.nc", {"swh": [1.0, 2.0]}, names={"swh": "wave_height"},
                           standard_names=False)
    with pytest.raises(InputError, match=r"odd.nc: hs: no significant wave height: none of the "
                                         r"variables wave_height is swh"):
        metocean.read_era5_parameters(p)


def test_era5_nonmonotonic_times(tmp_path):
    p = fx.era5_parameters(tmp_path / "t.nc", ERA5)
    import xarray as xr
    with xr.open_dataset(p) as ds:
        ds = ds.load()
    ds = ds.isel(valid_time=[0, 2, 1])
    p2 = tmp_path / "t2.nc"
    ds.to_netcdf(p2)
    with pytest.raises(InputError, match=r"t2.nc: time: times not strictly increasing"):
        metocean.read_era5_parameters(p2)


WW3 = {"hs": [1.5, 2.0], "fp": [0.08, 0.0625], "t02": [5.5, 6.1], "t0m1": [7.0, 7.9], "dir": [60.0, 70.0],
       "phs0": [0.9, 1.0], "ptp0": [5.0, 5.5], "pdir0": [30.0, 35.0],
       "phs1": [1.2, 1.7], "ptp1": [12.5, 16.0], "pdir1": [100.0, 95.0]}


def test_ww3_point_output(tmp_path):
    df = metocean.read_metocean(fx.ww3_parameters(tmp_path / "ww3.nc", WW3), "ww3")
    np.testing.assert_allclose(df["tp"].to_numpy(), [12.5, 16.0])          # 1 / fp
    np.testing.assert_array_equal(df["tz"].to_numpy(), WW3["t02"])
    np.testing.assert_array_equal(df["p1_tp"].to_numpy(), WW3["ptp1"])
    assert {"p0_hs", "p0_direction", "p1_hs", "p1_direction"} <= set(df.columns)
    two = fx.ww3_parameters(tmp_path / "two.nc", WW3, n_station=2)
    with pytest.raises(InputError, match=r"two.nc: station: the file holds 2 values along station"):
        metocean.read_ww3_parameters(two)
    assert len(metocean.read_ww3_parameters(two, station=1)) == 2
    with pytest.raises(InputError, match="unknown metocean format"):
        metocean.read_metocean(two, "grib")


def test_direction_stated_going_to_is_refused(tmp_path):
    """A direction variable found by its name (mwd) whose CF standard_name states "going
    to": read as "coming from" it would be 180 deg off (docs/inputs.md, class d)."""
    import xarray as xr
    bare = fx.era5_parameters(tmp_path / "bare.nc", ERA5, standard_names=False, time="time")
    with xr.open_dataset(bare) as ds:
        ds = ds.load()
    ds["mwd"].attrs["standard_name"] = "sea_surface_wave_to_direction"
    ds.to_netcdf(tmp_path / "to.nc")
    with pytest.raises(InputError) as exc:
        metocean.read_era5_parameters(tmp_path / "to.nc")
    text = str(exc.value)
    assert text.startswith(f"{tmp_path / 'to.nc'}: mwd: the file states that mwd is the direction the "
                           "waves travel TO")
    assert "standard_name sea_surface_wave_from_direction" in text
    assert "(got 'sea_surface_wave_to_direction')" in text
    # the same file stating "coming from" is read, its directions as written
    ds["mwd"].attrs["standard_name"] = "sea_surface_wave_from_direction"
    ds.to_netcdf(tmp_path / "from.nc")
    df = metocean.read_era5_parameters(tmp_path / "from.nc")
    np.testing.assert_array_equal(df["direction"].to_numpy(), ERA5["mwd"])
