"""Hourly hindcasts, gap summary, binning, and the default route tables (jls.sea.hindcast)."""

import hashlib
import importlib.util
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from jls.errors import InputError
from jls.sea.hindcast import bin_hindcast, hindcast_gaps, read_hindcast
from jls.sea.scatter import read_scatter

HERE = Path(__file__).parent
DATA = HERE / "data" / "sea"
REPO = HERE.parent
ROUTE = REPO / "config" / "routes" / "default"
# One year (1996) of each buoy's hourly record, committed with the tests (NDBC, public
# domain); the default route's tables were made from the full 1996-2005 records, which
# scripts/make_default_route.py reads from the folder given on its command line.
EXCERPT = HERE / "data" / "metocean"
LEGS = {"leg1_gulf_of_maine.csv": "ndbc44007_hourly_hs_tz_1996.txt",
        "leg2_cape_canaveral.csv": "ndbc41009_hourly_hs_tz_1996.txt"}
ATTRIBUTION = ("NDBC, public domain U.S. government data, via the OMAE 2019 "
               "environmental-contour benchmark datasets A and B")


def test_read_valid_hindcast():
    path = DATA / "hindcast_valid.txt"
    df = read_hindcast(path)
    assert list(df.columns) == ["hs", "tz"] and len(df) == 8
    assert df.index.name == "time" and str(df.index.tz) == "UTC"
    assert df.index[0] == pd.Timestamp("2000-01-01 00:00", tz="UTC")
    assert df["hs"].iloc[6] == 2.30 and df["tz"].iloc[-1] == 7.00
    assert df.attrs["sha256"] == hashlib.sha256(path.read_bytes()).hexdigest()
    assert df.attrs["units"] == {"hs": "m", "tz": "s"}


def test_gap_summary():
    df = read_hindcast(DATA / "hindcast_valid.txt")  # hours 0,1,2,4,5,9,10,11
    g = hindcast_gaps(df)
    assert (g.missing_hours, g.n_gaps, g.longest_gap_hours) == (4, 2, 3)
    assert g.longest_gap_start == pd.Timestamp("2000-01-01 06:00", tz="UTC")
    assert g.coverage == pytest.approx(8 / 12)
    # an explicit window counts leading / trailing missing hours too
    g2 = hindcast_gaps(df, start="1999-12-31 22:00", end="2000-01-01 12:00")
    assert (g2.missing_hours, g2.n_gaps) == (7, 4)
    assert g2.coverage == pytest.approx(8 / 15)
    assert g2.as_dict()["start"] == "1999-12-31T22:00:00+00:00"
    full = hindcast_gaps(df.iloc[:3])
    assert (full.missing_hours, full.n_gaps, full.coverage, full.longest_gap_start) == (0, 0, 1.0, None)


def test_bin_hindcast_counts_and_closed_last_bin():
    df = read_hindcast(DATA / "hindcast_valid.txt")
    ds = bin_hindcast(df, [0, 1, 2, 3], [4, 5, 6, 7])
    # (hs, tz): (0.4,4.2) (0.8,4.6) (1.2,5.1) (1.4,5.5) (1.1,5.4) (0.9,6.3) (2.3,6.8) (2.0,7.0)
    # 7.0 s sits on the last edge: the last bin is closed; 2.0 m goes to [2, 3)
    np.testing.assert_array_equal(ds["count"], [[2, 0, 1], [0, 3, 0], [0, 0, 2]])
    assert ds.attrs["total"] == 8 and ds.attrs["n_outside"] == 0
    assert ds.attrs["values_kind"] == "counts" and ds.attrs["source"] == "hindcast_valid.txt"
    assert float(ds["probability"].sum()) == pytest.approx(1.0)
    assert ds["steep"].dims == ("hs", "tz")


def test_bin_hindcast_outside_records_error_or_reported():
    df = read_hindcast(DATA / "hindcast_valid.txt")
    with pytest.raises(InputError, match="1 records lie outside") as e:
        bin_hindcast(df, [0, 1, 2], [4, 5, 6, 7])
    assert e.value.value == {"hs": 2.3, "tz": 6.8}
    ds = bin_hindcast(df, [0, 1, 2], [4, 5, 6, 7], outside="report")
    assert ds.attrs["n_outside"] == 1 and ds.attrs["n_records"] == 8 and ds.attrs["total"] == 7
    assert int(ds["count"].sum()) + ds.attrs["n_outside"] == len(df)
    with pytest.raises(InputError, match="strictly increasing"):
        bin_hindcast(df, [0, 2, 1], [4, 5])


def test_direction_column_and_sector_binning():
    df = read_hindcast(DATA / "hindcast_direction.txt")
    assert list(df.columns) == ["hs", "tz", "direction"]
    ds = bin_hindcast(df, [0, 1, 2], [4, 5, 6], dir_edges=[-45, 45, 135, 225, 315])
    assert ds["count"].dims == ("hs", "tz", "direction")
    np.testing.assert_array_equal(ds["direction"], [0, 90, 180, 270])
    # 10, 350 and 360 deg all fall in the north sector centred on 0
    np.testing.assert_array_equal(ds["count"].sum(("hs", "tz")), [3, 1, 1, 0])
    assert ds["steep"].dims == ("hs", "tz")
    with pytest.raises(InputError, match="no direction"):
        bin_hindcast(read_hindcast(DATA / "hindcast_valid.txt"), [0, 3], [4, 8], dir_edges=[0, 180, 360])


BAD = [
    ("hindcast_bad_unparsable.txt", "unparsable number", "line 3", "0,80"),
    ("hindcast_bad_negative.txt", "Hs must be", "line 4", "-1.20"),
    ("hindcast_bad_nonfinite.txt", "Tz must be finite", "line 3", "NaN"),
    ("hindcast_bad_sentinel.txt", "< 30 m", "line 3", "99.00"),
    ("hindcast_bad_time.txt", "unparsable time", "line 3", "2000-01-01-25"),
    ("hindcast_bad_order.txt", "not strictly increasing", "line 4", "2000-01-01-02"),
    ("hindcast_bad_fields.txt", "expected 3 fields", "line 4", "2000-01-01-01; 0.80"),
]


@pytest.mark.parametrize("name,message,line,value", BAD, ids=[b[0] for b in BAD])
def test_bad_rows_name_file_and_line(name, message, line, value):
    with pytest.raises(InputError) as e:
        read_hindcast(DATA / name)
    assert message in str(e.value)
    assert e.value.file.endswith(name) and e.value.field == line and e.value.value == value


def test_header_required(tmp_path):
    f = tmp_path / "h.txt"
    f.write_text("2000-01-01-00; 0.4; 4.2\n")
    with pytest.raises(InputError, match="column-name row") as e:
        read_hindcast(f)
    assert e.value.field == "line 1"


# --- the shipped default route ------------------------------------------------------

@pytest.mark.parametrize("table", sorted(LEGS))
def test_default_route_tables_read_back(table):
    ds = read_scatter(ROUTE / table)
    assert ds.attrs["values_kind"] == "counts" and ds.attrs["layout"] == "matrix"
    assert ds.attrs["total"] == int(ds.attrs["records"]) > 80000
    assert ds.attrs["attribution"] == ATTRIBUTION
    assert ds.attrs["source_file"] == LEGS[table].replace("1996", "1996-2005") and ds.attrs["years"] == "1996-2005"
    np.testing.assert_allclose(np.diff(ds["hs_lower"]), 0.5)
    np.testing.assert_allclose(np.diff(ds["tz_lower"]), 1.0)
    assert ds["hs_lower"][0] == 0 and float(ds["tz_lower"][0]).is_integer()
    # both legs share the same bins
    other = read_scatter(ROUTE / sorted(set(LEGS) - {table})[0])
    np.testing.assert_array_equal(ds["hs"], other["hs"])
    np.testing.assert_array_equal(ds["tz"], other["tz"])


@pytest.fixture(scope="module")
def raw_series():
    return {t: read_hindcast(EXCERPT / raw) for t, raw in LEGS.items()}


@pytest.fixture(scope="module")
def made_route(tmp_path_factory, raw_series):
    """The default-route script run on the committed excerpts (renamed as it expects)."""
    spec = importlib.util.spec_from_file_location("make_default_route", REPO / "scripts" / "make_default_route.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    src, out = tmp_path_factory.mktemp("metocean"), tmp_path_factory.mktemp("route")
    for leg in mod.LEGS:
        (src / leg["raw"]).write_bytes((EXCERPT / LEGS[leg["table"]]).read_bytes())
    return {p.name: p for p in mod.make_route(src, out)}


@pytest.mark.parametrize("table", sorted(LEGS))
def test_route_script_bins_every_record(table, raw_series, made_route):
    series = raw_series[table]
    ds = read_scatter(made_route[table])
    assert ds.attrs["total"] == len(series)  # every valid record counted
    assert ds.attrs["source_sha256"] == series.attrs["sha256"]
    edges_hs = np.append(ds["hs_lower"].values, ds["hs_upper"].values[-1])
    edges_tz = np.append(ds["tz_lower"].values, ds["tz_upper"].values[-1])
    binned = bin_hindcast(series, edges_hs, edges_tz)
    np.testing.assert_array_equal(binned["count"], ds["count"])
    gaps = hindcast_gaps(series)
    assert int(ds.attrs["missing_hours"]) == gaps.missing_hours
    assert int(ds.attrs["gaps"]) == gaps.n_gaps
    assert int(ds.attrs["longest_gap_hours"]) == gaps.longest_gap_hours
    # the data's range sets the bins: no empty outer row or column of the route
    assert (series["hs"] <= edges_hs[-1]).all() and (series["tz"] >= edges_tz[0]).all()


def test_iso_times_and_offsets_are_read_as_utc(tmp_path):
    f = tmp_path / "iso.txt"
    f.write_text("time; hs; tz\n2000-01-01-00; 1; 5\n2000-01-01T01:00Z; 1; 5\n"
                 "2000-01-01T03:00+01:00; 1; 5\n2000-01-01 04:00; 1; 5\n")
    df = read_hindcast(f)
    assert list(df.index.hour) == [0, 1, 2, 4]
    assert hindcast_gaps(df).missing_hours == 1
