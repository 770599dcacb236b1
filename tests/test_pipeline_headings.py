"""End-to-end: a leg on a course with a direction-resolved table through the workflow."""

import numpy as np
import pytest
import yaml
from test_pipeline import snakemake, workdir  # noqa: F401 - the fixture is used by name

from jls.io.netcdf import read

pytestmark = pytest.mark.slow

# From the north (beam seas from starboard heading west) and from the east (following
# seas heading west).
LEG_DIR = """# hs_bins: centres
# tz_bins: centres
hs,tz,direction,probability
0.5,5.5,0,0.4
1.5,6.5,0,0.3
2.5,7.5,90,0.2
3.5,7.5,90,0.1
"""


def test_a_course_leg_with_a_direction_table_runs_end_to_end(workdir):  # noqa: F811
    (workdir / "tables" / "dir.csv").write_text(LEG_DIR)
    path = workdir / "config" / "config.yaml"
    cfg = yaml.safe_load(path.read_text())
    cfg["routes"]["tiny"]["legs"][0] = {"name": "north", "scatter": "tables/dir.csv",
                                        "layout": "long", "duration_h": 30, "course_deg": 270}
    path.write_text(yaml.safe_dump(cfg))
    r = snakemake(workdir)
    assert r.returncode == 0, r.stderr[-3000:]
    res = workdir / "results" / "tiny"
    sea = read(res / "sea_states.nc")
    assert sea.attrs["heading_source_north"] == "direction_table"
    assert sea.attrs["heading_source_south"] == "given"
    north = sea["cell_probability"].sel(leg="north")
    assert float(north.sel(heading=90.0, hs=0.5, tz=5.5)) == pytest.approx(0.4)
    assert float(north.sel(heading=0.0, hs=2.5, tz=7.5)) == pytest.approx(0.2)
    assert float(north.sel(heading=0.0).sum()) == pytest.approx(0.3)
    np.testing.assert_allclose(sea["cell_probability"].sum(("heading", "hs", "tz")), [1.0, 1.0])
    # The response of leg north covers both derived headings; workability weights each
    # cell by its joint probability.
    work = read(res / "workability.nc")
    expected = (sea["cell_probability"] * work["passes"]).sum(("heading", "hs", "tz"))
    np.testing.assert_allclose(work["workability_leg"].values,
                               expected.transpose(*work["workability_leg"].dims).values)
    assert sorted(work["heading"].values.tolist()) == [0.0, 90.0]
    assert (workdir / "reports" / "tiny.pdf").stat().st_size > 0
