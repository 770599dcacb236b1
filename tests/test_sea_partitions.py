"""Hourly partitions (jls.sea.partitions) and the per-leg sea model (jls.sea.records.sea_model):
the CSV read as written; a missing partition, directions in radians and a period column of
another kind refused with the file, the column and the value; the partitions laid out as
E(t, f, dir) carry each hour's Hs and the systems' directions; the declarations checked."""

import math

import numpy as np
import pandas as pd
import pytest

from jls.errors import InputError
from jls.sea.measured import integrated_parameters
from jls.sea.partitions import directional_spectra, partition_frame, read_partitions, sea_states
from jls.sea.records import leg_series, sea_model
from jls.sea.spectra import te_from_tp

HEADER = "time, hs_wind, tp_wind, dir_wind, hs_swell, tp_swell, dir_swell"
SPREAD = {"wind": "cos2s:4", "swell": "cos2s:13"}


def _write(tmp_path, header=HEADER, rows=None, n=30, name="p.csv"):
    if rows is None:
        rows = [f"2021-03-01T{h % 24:02d}:00Z, 1.2, 6.5, {40 + h}, 0.8, 14.0, {100 + h}" for h in range(min(n, 24))]
    p = tmp_path / name
    p.write_text("\n".join([header, *rows]) + "\n")
    return p


def test_a_partitions_csv_is_read_as_written_and_laid_out_with_its_hs(tmp_path):
    df = read_partitions(_write(tmp_path))
    assert list(df.columns) == ["hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell"]
    assert len(df) == 24 and df.index.tz is not None and df["dir_swell"].iloc[3] == 103.0
    states, kept = sea_states(df, gamma=3.3, spreading=SPREAD)
    assert kept.all() and [s.kind for s in states[0].systems] == ["wind", "swell"]
    assert states[0].hs == pytest.approx(math.hypot(1.2, 0.8))
    efth = directional_spectra(states[:2], df.index[:2])
    hs = integrated_parameters(efth)["hs"].values
    np.testing.assert_allclose(hs, math.hypot(1.2, 0.8), rtol=2e-3)        # the grid ends at 1 Hz
    # the energy of the swell bins lies around its direction
    e = efth.isel(time=0).sel(freq=slice(0.06, 0.09)).sum("freq")
    assert abs(float(e["dir"].values[int(np.argmax(e.values))]) - 100.0) <= 10.0


@pytest.mark.parametrize("header, column, value", [
    ("time, hs_wind, tp_wind, dir_wind, hs_swell, tp_swell", "dir_swell", None),
    ("time, hs_wind, tp_wind, dir_wind, hs_swell, te_swell, dir_swell", "te_swell", "te_swell"),
    ("time, hs_wind, tz_wind, dir_wind, hs_swell, tp_swell, dir_swell", "tz_wind", "tz_wind"),
    ("time, hs_wind, tp_wind, dir_wind (rad), hs_swell, tp_swell, dir_swell", "dir_wind", "rad"),
])
def test_a_missing_partition_radians_or_another_period_is_refused(tmp_path, header, column, value):
    n_fields = len(header.split(","))
    rows = [", ".join(["2021-03-01T00:00Z", "1.2", "6.5", "40", "0.8", "14.0", "100"][:n_fields])]
    p = _write(tmp_path, header, rows)
    with pytest.raises(InputError) as e:
        read_partitions(p)
    assert e.value.file == str(p) and e.value.field == column
    if value is not None:
        assert e.value.value == value


def test_directions_in_radians_without_a_unit_are_refused(tmp_path):
    rows = [f"2021-03-01T{h:02d}:00Z, 1.2, 6.5, {0.25 * h:.2f}, 0.8, 14.0, 1.7" for h in range(24)]
    p = _write(tmp_path, rows=rows)
    with pytest.raises(InputError, match="radians") as e:
        read_partitions(p)
    assert e.value.field == "dir_wind" and e.value.value == pytest.approx(5.75) and e.value.file == str(p)
    # a partition with Hs but no direction: refused on its line
    rows = ["2021-03-01T00:00Z, 1.2, 6.5, , 0.8, 14.0, 100"]
    with pytest.raises(InputError, match="direction") as e:
        read_partitions(_write(tmp_path, rows=rows, name="q.csv"))
    assert e.value.field == "dir_wind, line 2"


def test_era5_partitions_turn_te_into_tp_and_a_missing_one_is_refused():
    idx = pd.date_range("2021-03-01", periods=2, freq="h", tz="UTC")
    df = pd.DataFrame({"hs": [1.0, 1.0], "wind_hs": [1.0, 0.5], "wind_te": [5.0, 5.0],
                       "wind_direction": [10.0, 20.0], "swell_hs": [0.5, 0.5],
                       "swell_te": [12.0 * float(te_from_tp(1.0, 3.3))] * 2, "swell_direction": [90.0, 90.0]},
                      index=idx)
    out = partition_frame(df, "era5", 3.3, file="x.nc")
    np.testing.assert_allclose(out["tp_swell"], 12.0, rtol=1e-9)
    with pytest.raises(InputError, match="swell partition is missing") as e:
        partition_frame(df.drop(columns="swell_te"), "era5", 3.3, file="x.nc")
    assert e.value.file == "x.nc" and e.value.field == "swell_te"


def test_the_sea_model_is_declared_and_checked(tmp_path):
    p = _write(tmp_path)
    leg = {"name": "p", "metocean": {"file": p.name, "format": "partitions", "period": "tp"}}
    assert sea_model(leg) == "partitions"
    s = leg_series(leg, tmp_path, gamma=3.3)                 # total Hs and the sum's Tz
    assert s["hs"].iloc[0] == pytest.approx(math.hypot(1.2, 0.8))
    assert 5.0 < s["tz"].iloc[0] < 9.0 and 40.0 < s["direction"].iloc[0] < 100.0
    for bad, text in (({**leg, "spectrum": "jonswap"}, "partitions file"),
                      ({**leg, "metocean": {**leg["metocean"], "period": "tz"}}, "period: tp"),
                      ({"name": "t", "scatter": "a.csv", "spectrum": "torsethaugen"}, "Hs-Tp"),
                      ({"name": "t", "scatter": "a.csv", "spectrum": "measured"}, "spectra leg"),
                      ({"name": "m", "metocean": {"file": "a", "format": "ndbc_stdmet", "period": "tz"},
                        "spectrum": "partitions"}, "partitions")):
        with pytest.raises(InputError, match=text):
            sea_model(bad)
    assert sea_model({"name": "t", "scatter": "a.csv", "spectrum": "torsethaugen", "period": "tp"}) == "torsethaugen"


def test_ww3_partitions_are_the_wind_sea_and_the_swells(tmp_path):
    import sea_fixtures as fx

    from jls.sea.metocean import read_metocean
    values = {"hs": [1.5, 2.0], "fp": [0.08, 0.0625], "t02": [5.5, 6.1], "t0m1": [7.0, 7.9], "dir": [60.0, 70.0],
              "phs0": [0.9, 1.0], "ptp0": [5.0, 5.5], "pdir0": [30.0, 35.0],
              "phs1": [1.2, 1.7], "ptp1": [12.5, 16.0], "pdir1": [100.0, 95.0]}
    path = fx.ww3_parameters(tmp_path / "ww3.nc", values)
    out = partition_frame(read_metocean(path, "ww3"), "ww3", 3.3, file=path)
    assert list(out.columns) == ["hs_wind", "tp_wind", "dir_wind", "hs_swell", "tp_swell", "dir_swell"]
    np.testing.assert_allclose(out["tp_swell"], [12.5, 16.0])
    states, kept = sea_states(out, gamma=3.3, spreading=SPREAD)
    assert [s.kind for s in states[1].systems] == ["wind", "swell"] and states[1].systems[1].from_deg == 95.0
    only_wind = {k: v for k, v in values.items() if not k.endswith("1")}
    with pytest.raises(InputError, match="swell") as e:
        partition_frame(read_metocean(fx.ww3_parameters(tmp_path / "w.nc", only_wind), "ww3"), "ww3", 3.3)
    assert e.value.field == "phs1"
