"""Round three of the input checks (docs/inputs.md): the round-two classes that were still
quiet, geometry that cannot be, files that contradict the configuration, conventions
checked by physics, too little data and every job's precondition at parse time. Each
error names the file of origin, the key or line and the value."""

from pathlib import Path

import pytest

from jls.errors import InputError
from jls.sea.scatter import read_scatter

ROOT = Path(__file__).resolve().parents[1]


# --- (b) round-two classes still quiet -------------------------------------------------

def _lower_edge_table(path, header_tz="centres"):
    path.write_text("# layout: matrix\n# hs_bins: centres\n# tz_bins: " + header_tz + "\n"
                    "# values: counts\nhs\\tz,2,3,4,5\n0.0,1,2,0,0\n0.5,3,9,4,1\n1.0,0,5,8,2\n"
                    "1.5,0,1,4,3\n")
    return path


def test_scatter_lower_edges_declared_centres(tmp_path):
    path = _lower_edge_table(tmp_path / "leg.csv")
    with pytest.raises(InputError) as exc:
        read_scatter(path)
    text = str(exc.value)
    assert "leg.csv: line 6, column 1:" in text and "first hs label is 0" in text
    assert "lower edges (0.0, 0.5, 1.0, ...)" in text and "(got '0.0')" in text


def test_scatter_tz_lower_edge_zero_named(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text("# hs_bins: edges\n# tz_bins: centres\n# values: counts\n"
                    "hs\\tz,0,1,2\n0.5-1.0,1,2,3\n")
    with pytest.raises(InputError, match=r"t.csv: line 4, column 2: .*first tz label is 0"):
        read_scatter(path)


def test_scatter_true_centres_accepted(tmp_path):
    path = tmp_path / "c.csv"
    path.write_text("# hs_bins: centres\n# tz_bins: centres\n# values: counts\n"
                    "hs\\tz,2.5,3.5,4.5\n0.25,1,2,0\n0.75,3,9,4\n")
    ds = read_scatter(path)
    assert ds["hs_lower"].values[0] == 0.0 and ds["hs"].values[0] == 0.25
