"""Scatter-table reader/writer and steepness flags (jls.sea.scatter, jls.sea.steepness)."""

import hashlib
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jls.errors import InputError
from jls.sea.scatter import read_scatter, scatter_dataset, write_scatter
from jls.sea.steepness import flag_steep, steepness_limit_hs

DATA = Path(__file__).parent / "data" / "sea"


def _all_have_units(ds):
    for name in ds.variables:
        assert "units" in ds[name].attrs and "long_name" in ds[name].attrs, name


def test_matrix_counts_with_edges():
    path = DATA / "matrix_counts_edges.csv"
    ds = read_scatter(path)
    assert ds["probability"].dims == ("hs", "tz")
    np.testing.assert_array_equal(ds["hs_lower"], [0, 1, 2])
    np.testing.assert_array_equal(ds["hs_upper"], [1, 2, 3])
    np.testing.assert_array_equal(ds["tz_lower"], [4, 5, 6])
    np.testing.assert_array_equal(ds["hs"], [0.5, 1.5, 2.5])
    np.testing.assert_array_equal(ds["tz"], [4.5, 5.5, 6.5])
    counts = np.array([[10, 20, 5], [3, 40, 12], [0, 6, 4]])
    np.testing.assert_array_equal(ds["count"], counts)
    assert ds["count"].dtype == np.int64
    np.testing.assert_allclose(ds["probability"], counts / 100)
    assert ds.attrs["total"] == 100 and ds.attrs["values_kind"] == "counts"
    assert ds.attrs["source"] == "matrix_counts_edges.csv"
    assert ds.attrs["sha256"] == hashlib.sha256(path.read_bytes()).hexdigest()
    assert ds.attrs["layout"] == "matrix" and ds.attrs["buoy"] == "test"
    assert ds["hs"].attrs["units"] == "m" and ds["tz_upper"].attrs["units"] == "s"
    _all_have_units(ds)


def test_steep_flag_is_study_ceiling_at_cell_centres_and_nothing_dropped():
    ds = read_scatter(DATA / "matrix_counts_edges.csv")
    expected = ds["hs"].values[:, None] > steepness_limit_hs(ds["tz"].values)[None, :]
    np.testing.assert_array_equal(ds["steep"], expected)
    assert ds["steep"].values[2, 0]  # Hs 2.5 m at Tz 4.5 s: ceiling 2.11 m
    assert ds["steep"].attrs["rule"] == "study" and ds.attrs["steepness_rule"] == "study"
    assert ds.attrs["steep_cells_with_data"] == 0  # that steep cell holds no records
    assert int(ds["count"].sum()) == ds.attrs["total"]  # flagged, not removed


def test_flag_steep_dnv_rule_flags_fewer_cells_and_reports_probability():
    ds = read_scatter(DATA / "matrix_probability_centres.csv")
    study, dnv = flag_steep(ds, "study"), flag_steep(ds, "dnv", gamma=3.3)
    assert dnv["steep"].sum() < study["steep"].sum()
    assert dnv.attrs["steepness_rule"] == "dnv" and dnv["steep"].attrs["gamma"] == 3.3
    p = float(study["probability"].where(study["steep"], 0).sum())
    assert study.attrs["steep_probability"] == pytest.approx(p)
    assert p == pytest.approx(0.025)  # Hs 3.5 m at Tz 5.5 s (ceiling 3.15 m): reported, kept
    assert dnv.attrs["steep_probability"] == 0.0


def test_matrix_probability_centres_derived_edges():
    ds = read_scatter(DATA / "matrix_probability_centres.csv")
    assert "count" not in ds and ds.attrs["values_kind"] == "probability"
    assert ds.attrs["total"] == pytest.approx(100.0)  # percent as read
    assert float(ds["probability"].sum()) == pytest.approx(1.0)
    np.testing.assert_allclose(ds["hs_lower"], [0, 1, 2, 3])
    np.testing.assert_allclose(ds["hs_upper"], [1, 2, 3, 4])
    np.testing.assert_allclose(ds["tz_lower"], [5, 6, 7, 8])
    np.testing.assert_allclose(ds["tz_upper"], [6, 7, 8, 9])
    assert float(ds["probability"].sel(hs=1.5, tz=6.5)) == pytest.approx(0.25)


def test_centres_nonuniform_mirror_and_clip(tmp_path):
    f = tmp_path / "c.csv"
    f.write_text("# hs_bins: centres\n# tz_bins: centres\n# values: counts\nx,4,5,7\n0.2,1,1,1\n1.0,1,1,1\n")
    ds = read_scatter(f)
    np.testing.assert_allclose(ds["hs_lower"], [0.0, 0.6])  # 0.2 - 0.4 clipped at 0
    np.testing.assert_allclose(ds["hs_upper"], [0.6, 1.4])
    np.testing.assert_allclose(ds["tz_lower"], [3.5, 4.5, 6.0])
    np.testing.assert_allclose(ds["tz_upper"], [4.5, 6.0, 8.0])
    np.testing.assert_allclose(ds["tz"], [4, 5, 7])  # centres kept as given


def test_long_layout_with_direction():
    ds = read_scatter(DATA / "long_probability_direction.csv")
    assert ds["probability"].dims == ("hs", "tz", "direction")
    assert ds["steep"].dims == ("hs", "tz")
    np.testing.assert_array_equal(ds["direction"], [0, 90, 180, 270])
    assert ds["direction"].attrs["units"] == "deg"
    assert float(ds["probability"].sum()) == pytest.approx(1.0)
    assert float(ds["probability"].sel(hs=1.5, tz=6.5, direction=90)) == pytest.approx(0.30)
    assert float(ds["probability"].sel(hs=0.5, tz=7.5).sum()) == 0.0  # missing cells are zero
    assert ds.attrs["layout"] == "long" and ds.attrs["values_kind"] == "probability"
    _all_have_units(ds)


def test_long_counts_with_edges_any_row_order():
    ds = read_scatter(DATA / "long_counts_edges.csv")
    np.testing.assert_array_equal(ds["hs_lower"], [0, 1])
    np.testing.assert_array_equal(ds["tz_lower"], [4, 5])
    np.testing.assert_array_equal(ds["count"], [[3, 11], [0, 7]])
    assert ds.attrs["total"] == 21


def test_keyword_overrides(tmp_path):
    path = DATA / "matrix_no_header.csv"
    with pytest.raises(InputError, match="missing header key") as e:
        read_scatter(path)
    assert "hs_bins" in e.value.field
    ds = read_scatter(path, bins="centres", values="counts")
    np.testing.assert_array_equal(ds["count"], [[1, 2], [3, 4]])
    ds2 = read_scatter(path, bins={"hs": "centres", "tz": "centres"}, values="probability", layout="matrix")
    assert "count" not in ds2
    xr.testing.assert_allclose(ds["probability"], ds2["probability"])
    # bins= overrides the header: the edge-labelled file read as centres fails on '0.0-1.0'
    with pytest.raises(InputError, match="declared as centres .* is a pair of edges"):
        read_scatter(DATA / "matrix_counts_edges.csv", bins="centres")


MALFORMED = [
    # file, message fragment, location fragment, offending value
    ("bad_negative.csv", "negative", "line 6, column 3", "-4"),
    ("bad_nonfinite.csv", "non-finite", "line 5, column 3", "nan"),
    ("bad_inf.csv", "non-finite", "line 5, column 3", "inf"),
    ("bad_unparsable.csv", "unparsable number", "line 5, column 3", "2O"),
    ("bad_bin_label.csv", "unparsable bin label", "line 6, column 1", "1.0 to 2.0"),
    ("bad_duplicate_bins.csv", "duplicated tz bin", "line 4, column 4", "5.5"),
    ("bad_duplicate_long.csv", "duplicated bin", "line 6", "0.50,4.5,4"),
    ("bad_nonmonotonic.csv", "not increasing", "line 7, column 1", "1.0-2.0"),
    ("bad_overlap_edges.csv", "overlapping", "line 4, column 3", "4.5-6.0"),
    ("bad_ragged.csv", "row has 2 cells", "line 6", "1.0-2.0,3"),
    ("bad_fractional_counts.csv", "whole number", "line 5, column 3", "2.5"),
    ("bad_allzero.csv", "all zero", "lines 5-6", 0),
    ("bad_empty.csv", "empty table", "table", None),
    ("bad_missing_key.csv", "missing header key", "values", None),
    ("bad_duplicate_key.csv", "header key given twice", "line 4", "values"),
]


@pytest.mark.parametrize("name,message,where,value", MALFORMED, ids=[m[0] for m in MALFORMED])
def test_malformed_tables_raise_input_error_naming_file_location_value(name, message, where, value):
    with pytest.raises(InputError) as e:
        read_scatter(DATA / name)
    err = e.value
    assert message in str(err)
    assert err.file.endswith(name)
    assert where in err.field
    if value is not None:
        assert err.value == value
    assert name in str(err)  # the printed line names the file too


def test_missing_file_is_input_error(tmp_path):
    with pytest.raises(InputError, match="scatter table not found"):
        read_scatter(tmp_path / "nope.csv")


def test_write_read_round_trip(tmp_path):
    ds = read_scatter(DATA / "matrix_counts_edges.csv")
    out = write_scatter(ds, tmp_path / "t.csv", header={"note": "round trip"})
    back = read_scatter(out)
    for v in ("count", "probability", "steep", "hs_lower", "hs_upper", "tz_lower", "tz_upper"):
        np.testing.assert_array_equal(back[v], ds[v])
    assert back.attrs["note"] == "round trip" and back.attrs["total"] == 100
    # probability tables are written as probabilities
    p = read_scatter(DATA / "matrix_probability_centres.csv")
    back = read_scatter(write_scatter(p, tmp_path / "p.csv"))
    np.testing.assert_allclose(back["probability"], p["probability"], rtol=1e-12)
    # direction-resolved tables do not fit the matrix layout
    with pytest.raises(InputError, match="direction"):
        write_scatter(read_scatter(DATA / "long_probability_direction.csv"), tmp_path / "d.csv")


def test_scatter_dataset_checks_values():
    kw = dict(hs_lower=[0, 1], hs_upper=[1, 2], tz_lower=[4], tz_upper=[5])
    with pytest.raises(InputError, match="all zero"):
        scatter_dataset(np.zeros((2, 1)), **kw)
    with pytest.raises(InputError, match="negative"):
        scatter_dataset(np.array([[1.0], [-1.0]]), **kw)
    ds = scatter_dataset(np.array([[1.0], [3.0]]), values_kind="probability", **kw)
    np.testing.assert_allclose(ds["probability"][:, 0], [0.25, 0.75])


def test_leg_steepness_flag_uses_the_configured_rule_and_g():
    from jls.sea.legs import read_leg
    leg = {"name": "a", "scatter": str(DATA / "matrix_probability_centres.csv")}
    study = read_leg(leg, ".", "study", 3.3, 9.81)
    low_g = read_leg(leg, ".", "study", 3.3, 9.0)
    dnv = read_leg(leg, ".", "dnv", 3.3, 9.81)
    assert study.attrs["steepness_rule"] == "study" and dnv.attrs["steepness_rule"] == "dnv"
    hs, tz = low_g["hs"].values[:, None], low_g["tz"].values[None, :]
    np.testing.assert_array_equal(low_g["steep"], hs > 9.0 * tz**2 / (2 * np.pi * 15) + 1e-9)
    np.testing.assert_array_equal(study["steep"], hs > 9.81 * tz**2 / (2 * np.pi * 15) + 1e-9)
    assert float(low_g["steep"].attrs["g"]) == 9.0
