"""The study's own comparison beside the project's (jls.verify.study, the report's
study section) and the report's words on cells whose reference is not damped as stated."""

import numpy as np
import pytest
from test_verification_report import BASE, REC, cell, compiles, context, plain

from jls.io import registry
from jls.report import verification as ver
from jls.verify import reference_available, study

OK, WHY = reference_available()


def filled():
    """The study dataset with the project's columns as the default plant gave them."""
    ds = study.unavailable("x", tolerance=0.1)
    del ds.attrs["reason"]
    ds["sigma_rom"][:] = [0.0509, 0.6369, 1.9371, 5.0422, 8.0379]
    ds["sigma_reference"][:] = [0.0509, 0.6370, 1.9239, 4.6849, 6.8542]
    ds["sigma_ratio"][:] = ds["sigma_rom"] / ds["sigma_reference"]
    ds["mpm_ratio"][:] = ds["sigma_ratio"]
    ds.attrs.update(duration_s=1200.0, linear_range_tz_s=9.0, linear_range_hs_inside_m=1.5,
                    linear_range_hs_leaves_m=2.0, linear_range_mpm_inside_m=15.2)
    return ds


def test_table_4_4_is_the_studys():
    ds = study.unavailable("no MoorDyn", tolerance=0.1)
    registry.check(ds, study.LAYOUT)
    assert list(ds["sea_state"].values) == ["V1", "V2", "V3", "V4", "S1"]
    # the published errors are the published RMS values' ratio, to their rounding
    calc = ds["study_sigma_rom"] / ds["study_sigma_full"] - 1
    np.testing.assert_allclose(calc, ds["study_error"], atol=0.006)


def test_study_section_prints_the_study_beside_ours_and_what_the_reference_sees(tmp_path):
    text = ver.study_section(filled())
    assert compiles(tmp_path, text)
    p = plain(text)
    assert "+16.8 %" in p and "+33.4 %" in p and "3.047" in p and "5.383" in p      # the study's
    assert "+7.6 %" in p and "+17.3 %" in p                                         # ours, V4 and S1
    assert "shares with the ROM" in p and "it lacks damping that grows with the amplitude" in p
    assert "block connection system" in p and "surge and pitch" in p
    assert "leaves the 10 % tolerance at Hs 2.00 m" in p and "15.2 m" in p
    p = plain(ver.study_section(study.unavailable("the nonlinear reference needs MoorDyn", tolerance=0.1)))
    assert "could not run" in p and "needs MoorDyn" in p


def test_a_reference_not_damped_as_stated_confirms_nothing():
    bad = cell(*REC, 1.0, damping_off=0.05)
    assert bad.attrs["verdict"] == "not comparable"
    assert ver.verdict_text(bad).startswith("not comparable: the reference is not damped as the ROM")
    s = plain(ver.page_one_sentence(context([bad, cell(*BASE, 1.0)])))
    assert "is unverified" in s and "not damped as the ROM" in s
    # beside a comparable cell of the recommendation, only that one counts
    s = plain(ver.page_one_sentence(context([bad, cell(*REC, 1.02, hs=0.75)])))
    assert "is confirmed" in s and "1 verified cell" in s


def test_page_one_says_what_was_verified_and_where_the_range_ends():
    cx = context([cell(*REC, 1.02), cell(*BASE, 0.99), cell(*BASE, 1.14, hs=3.25)])
    cx.verification_study = filled()
    s = plain(ver.page_one_what_was_verified(cx))
    assert "2 of 3 cells within 10 %" in s and "MPM 0.990-1.140" in s
    assert "from a relative-sway MPM of about 15 m" in s
    assert ver.page_one_what_was_verified(context([])) == ""


@pytest.mark.slow
@pytest.mark.skipif(not OK, reason=WHY)
def test_study_comparison_on_the_default_plant():
    from jls.config.builders import candidate_plant
    from jls.config.loader import load
    from jls.stages.vessel_motion import vessel_motion
    cfg = load("config/config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=".")
    ds = study.study_comparison(candidate_plant(cfg, "baseline"), motion, duration_s=600.0,
                                transient_time_constants=2.0)
    registry.check(ds, study.LAYOUT)
    r = ds["mpm_ratio"]
    assert np.all(np.abs(r.sel(sea_state=["V1", "V2"]) - 1) < 0.005)      # linear inside the design cell
    assert float(r.sel(sea_state="S1")) > float(r.sel(sea_state="V4")) > 1.03
    assert ds.attrs["linear_range_hs_leaves_m"] <= 2.7                   # S1 is outside


def test_wire_cells_take_each_combinations_design_corner():
    from jls.verify.names import wire_cells
    cells = [{"name": "a", "candidate": "d", "tugger": "none", "reasons": ["nearest the workability boundary"]},
             {"name": "b", "candidate": "d", "tugger": "none",
              "reasons": ["design corner: the workable cell of the highest utilisation (0.99, leg x)"]},
             {"name": "c", "candidate": "b", "tugger": "none", "reasons": ["nearest the workability boundary"]},
             {"name": "e", "candidate": "b", "tugger": "none", "reasons": ["design corner"]}]   # the configured sea state
    assert [c["name"] for c in wire_cells(cells)] == ["b", "c"]


@pytest.mark.skipif(not OK, reason=WHY)
def test_wires_as_wires_hold_the_roms_static_tensions_and_agree_with_one_segment(tmp_path):
    from jls.config.builders import candidate_plant
    from jls.config.loader import load
    from jls.stages.vessel_motion import vessel_motion
    from jls.verify.wires import unavailable, wire_check
    cfg = load("config/config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=".")
    ds = wire_check(candidate_plant(cfg, "baseline"), motion, 3.25, 6.5, 90.0, segments=4,
                    wire_mass_t_per_m=0.1, axial_damping_ratio=0.8, duration_s=40.0, transient_s=20.0,
                    tolerance=0.1, cell="baseline__none__h90__hs3.25__tz6.5")
    registry.check(ds, "verification_wires")
    # padeye tensions of the wires as wires, held still in MoorDyn: the ROM's within 0.1 %
    # (the padeye node carries an eighth of its wire's weight, about 0.04 %)
    assert float(ds["tension_ratio_max"]) < 1e-3
    assert float(ds["sigma_ratio_segments"]) == pytest.approx(1.0, abs=0.02)
    assert float(ds["r_segments"]) > 0.999 and bool(ds["within_tolerance"])
    assert float(ds["wall_time_segments"]) > float(ds["wall_time_one_segment"])
    text = plain(ver.wires_text([ds]))
    assert compiles(tmp_path, ver.wires_text([ds])) and "stands as the fast default" in text
    bad = ds.copy()
    bad["sigma_ratio_segments"] = ((), 1.2)
    bad["within_tolerance"] = ((), False)
    assert "does not stand" in plain(ver.wires_text([ds, bad]))
    u = unavailable("no MoorDyn", "x")
    registry.check(u, "verification_wires")


def test_without_moordyn_the_study_and_wire_datasets_say_so(monkeypatch):
    import sys

    from jls.config.loader import load
    from jls.stages.verification_cell import study_dataset, wires_dataset
    from jls.stages.vessel_motion import vessel_motion
    monkeypatch.setitem(sys.modules, "moordyn", None)          # import moordyn now fails
    cfg = load("config/config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=".")
    s = study_dataset(cfg, motion)
    registry.check(s, study.LAYOUT)
    assert "pip install moordyn" in s.attrs["reason"] and np.isnan(s["sigma_ratio"]).all()
    assert float(s["study_error"].sel(sea_state="S1")) == pytest.approx(0.334)
    w = wires_dataset(cfg, motion, {"candidate": "baseline", "tugger": "none", "heading": 90.0,
                                    "hs": 3.25, "tz": 6.5})
    registry.check(w, "verification_wires")
    assert "pip install moordyn" in w.attrs["reason"] and not bool(w["within_tolerance"])


def test_validity_chapter_gives_the_measured_linear_range_beside_its_flag():
    from jls.report.validity import linear_range_measured
    cx = context([])
    assert linear_range_measured(cx) == ""
    cx.verification_study = filled()
    s = plain(linear_range_measured(cx))
    assert "relative-sway MPM of about 15 m (Hs 2.00 m at Tz 9.0 s" in s
    cx.verification_study = study.unavailable("no MoorDyn", tolerance=0.1)
    assert linear_range_measured(cx) == ""
