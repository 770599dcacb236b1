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


# --- (c) geometry that cannot be; (g) preconditions of the jobs at parse time ------------

def _check(tmp_path, monkeypatch, overlay: str):
    """``jls check`` of the shipped configuration with ``overlay`` as a --configfile, in a
    copy of the project: the InputError it raises."""
    import shutil

    from jls.config.workflow_inputs import check_run
    monkeypatch.chdir(tmp_path)
    shutil.copytree(ROOT / "config", tmp_path / "config")
    (tmp_path / "my.yaml").write_text(overlay)
    with pytest.raises(InputError) as exc:
        check_run([Path("config/config.yaml"), Path("my.yaml")])
    text = str(exc.value)
    assert "\n" not in text
    assert not (tmp_path / "results").exists()
    return text


def test_fairleads_below_the_waterline(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "vessel:\n  fairlead_drop_m: 150\n")
    assert text.startswith("my.yaml: vessel.fairlead_drop_m:")
    assert "30.54 m below the waterline" in text and "119.46 m above it" in text
    assert "(got 150)" in text


def test_tip_point_outside_the_jacket(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch,
                  "assessment:\n  tip_clearance:\n    tip_offsets_m: [[-7.5, 24.4], [500, 0]]\n")
    assert text.startswith("my.yaml: assessment.tip_clearance.tip_offsets_m[1]:")
    # padeyes 17.0 m fore-aft and 22.5 m athwart from the CoG: twice that is the envelope
    assert "500.0 m from the CoG" in text and "+-34.0 m" in text and "+-45.0 m" in text
    assert "(got [500, 0])" in text


def test_tip_point_inside_a_stated_envelope_is_accepted(tmp_path, monkeypatch):
    import shutil

    from jls.config.workflow_inputs import check_run
    monkeypatch.chdir(tmp_path)
    shutil.copytree(ROOT / "config", tmp_path / "config")
    (tmp_path / "my.yaml").write_text("jacket:\n  envelope_half_m: [40, 50]\nassessment:\n"
                                      "  tip_clearance:\n    tip_offsets_m: [[-38, 48]]\n")
    check_run([Path("config/config.yaml"), Path("my.yaml")])
    (tmp_path / "my.yaml").write_text("jacket:\n  envelope_half_m: [40, 50]\nassessment:\n"
                                      "  tip_clearance:\n    tip_offsets_m: [[-41, 48]]\n")
    with pytest.raises(InputError, match=r"\+-40.0 m .*jacket.envelope_half_m"):
        check_run([Path("config/config.yaml"), Path("my.yaml")])


def test_splash_clearance_above_the_tip(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "rigging:\n  limits:\n    splash_clearance_m: 15\n")
    # tip: 119.46 - 60.091 - 48 = 11.37 m above the water
    assert text.startswith("my.yaml: rigging.limits.splash_clearance_m:")
    assert "15 m" in text and "11.37 m" in text and "(got 15)" in text


def test_padeye_below_the_waterline(tmp_path, monkeypatch):
    # a candidate's drop of 130 m puts the padeyes 119.46 - 130 = -10.54 m
    text = _check(tmp_path, monkeypatch, "rigging:\n  design_space:\n    drop_height_m: [50, 140]\n"
                  "candidates:\n  - {name: deep, drop_height_m: 130}\n")
    assert "my.yaml: candidates[0].drop_height_m:" in text and "10.54 m below the waterline" in text


def test_tugger_capacity_equal_to_its_floor(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "tuggers:\n  - {name: none, c_kN_s_per_m: 0}\n"
                  "  - {name: tight, c_kN_s_per_m: 300, max_force_kN: 20, min_force_kN: 20}\n")
    assert text.startswith("my.yaml: tuggers[1].max_force_kN:")
    assert "capacity 20 kN must exceed the no-slack floor 20 kN" in text


def test_slope_sweep_heading_the_rao_lacks(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "timedomain:\n  slope_sweep:\n    heading_deg: 37\n")
    assert "timedomain.slope_sweep.heading_deg" in text and "heading 37" in text
    assert "representative_hlv.nc" in text and "set in my.yaml" in text


def test_empty_file_name(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "vessel:\n  rao_file: ''\n")
    assert "my.yaml: vessel.rao_file: an empty file name names no file" in text


def test_shipped_geometry_passes():
    from jls.config.geometry_checks import check_geometry
    from jls.config.loader import load
    check_geometry(load(ROOT / "config" / "config.yaml"))


def test_a_deleted_dataset_sets_the_report_aside(tmp_path):
    """A dataset deleted by hand while the report exists: Snakemake alone would say
    "Nothing to be done"; the parse names it and the report is set aside, so the dataset
    and everything after it are rebuilt (tests/test_rerun.py runs it end to end)."""
    from jls.config.intermediates import REPORT_DATASETS, missing
    base = tmp_path / "results" / "r"
    (base / "timedomain").mkdir(parents=True)
    for name in REPORT_DATASETS + ("screening.nc", "plant_assessed.nc"):
        (base / name).write_text("x")
    (base / "timedomain" / "cells.json").write_text('[{"name": "baseline__h90__hs1.25__tz8.5"}]')
    (base / "timedomain" / "baseline__h90__hs1.25__tz8.5.nc").write_text("x")
    report = tmp_path / "reports" / "r.pdf"
    kw = dict(screening=True, windows=False, measured=False, verification=False)
    assert missing(tmp_path / "results", "r", report, **kw) == []      # no report: a first run
    report.parent.mkdir()
    report.write_text("%PDF")
    assert missing(tmp_path / "results", "r", report, **kw) == []
    (base / "response.nc").unlink()
    (base / "timedomain" / "baseline__h90__hs1.25__tz8.5.nc").unlink()
    assert missing(tmp_path / "results", "r", report, **kw) == [
        str(base / "response.nc"), str(base / "timedomain" / "baseline__h90__hs1.25__tz8.5.nc")]
    assert str(base / "weather_windows.nc") in missing(tmp_path / "results", "r", report,
                                                       **{**kw, "windows": True})


def test_configured_sea_state_steeper_than_breaking(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "timedomain:\n  cells:\n    - {hs_m: 25, tz_s: 3}\n")
    assert text.startswith("my.yaml: timedomain.cells[0].hs_m: Hs 25 m at Tz 3 s is steeper than breaking")
    assert "(got 25)" in text


def test_design_corner_heading_the_route_lacks(tmp_path, monkeypatch):
    text = _check(tmp_path, monkeypatch, "verification:\n  design_corner: {enabled: true, heading_deg: 45}\n")
    assert text.startswith("my.yaml: verification.design_corner.heading_deg: not a relative heading of "
                           "route 'default' (90 deg)") and "(got 45)" in text
