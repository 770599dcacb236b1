"""The report's verification chapter and page-1 sentence (jls.report.verification) on
small constructed verification-cell datasets in the registry's layout."""

import shutil
from importlib import resources
from types import SimpleNamespace

import numpy as np
import pytest
import typst
import xarray as xr

from jls.io import registry
from jls.report import verification as ver
from jls.verify.cell import add_verdict, cell_name, unavailable_cell

REC, BASE = ("detuned", "low"), ("baseline", "none")
ROM_PERIODS = {"sway": 15.44, "yaw": 9.1, "roll": 4.2, "heave": 1.3}
REF_PERIODS = {"surge": 19.2, "sway": 15.45, "yaw": 9.11, "roll": 4.21, "pitch": 1.77, "heave": 1.31}


def cell(candidate, tugger, sigma_ratio, *, hs=1.25, tz=7.5, tolerance=0.10, mpm_ratio=None,
         reasons="nearest the workability boundary", damping_off=0.0):
    """A verified cell whose ROM's relative sway is ``sigma_ratio`` times the reference's."""
    mpm_ratio = sigma_ratio if mpm_ratio is None else mpm_ratio
    sig_ref, mpm_ref = 0.8, 2.9
    n = 50
    time = np.arange(n) * 0.1
    ref_trace = np.sin(time)
    ds = xr.Dataset(coords={"model": ["rom", "reference"], "wire": ["w1", "w2", "w3", "w4"],
                            "mode": np.arange(1, 7), "rom_mode": np.arange(1, 5),
                            "response": ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"],
                            "response_units": ("response", ["m", "m", "degree", "degree"]),
                            "axis": ["x", "y", "z"], "trace_time": time,
                            "period": [13.9, 17.0], "amplitude": [0.05]})
    ds = ds.assign_coords(dominant_dof=("mode", list(REF_PERIODS)),
                          rom_dominant_dof=("rom_mode", list(ROM_PERIODS)))
    ds["sigma"] = (("model", "response"), [[sigma_ratio * sig_ref, 0.1, 0.2, 0.05], [sig_ref, 0.1, 0.2, 0.05]])
    ds["mpm"] = ("model", [mpm_ratio * mpm_ref, mpm_ref])
    ds["tz_response"] = ("model", [12.0, 12.0])
    ds["max_observed"] = ("model", [2.0, 2.0])
    ds["sigma_ratio"] = ((), sigma_ratio)
    ds["mpm_ratio"] = ((), mpm_ratio)
    ds["sigma_fd"] = ((), sigma_ratio * sig_ref)
    for k, v in {"r": 0.9998, "r2": 0.9995, "rms_error": 0.02, "rms_error_relative": 0.03,
                 "wire_tension_min": 17000.0, "wire_tension_max": 21800.0, "slack_fraction": 0.0,
                 "wall_time_reference": 2.0, "wall_time": 3.0}.items():
        ds[k] = ((), v)
    ds["tension_static"] = (("model", "wire"), [[21357.8, 17416.5] * 2, [21245.8, 17322.6] * 2])
    ds["pose_offset"] = ("axis", [0.0, 0.0, 0.001])
    ds["pose_angle"] = ("axis", [0.0, 0.0, 0.0])
    ds["natural_period_reference"] = ("mode", list(REF_PERIODS.values()))
    ds["period_decay_reference"] = ("mode", [p * 1.001 for p in REF_PERIODS.values()])
    ds["damping_ratio_decay_reference"] = ("mode", [0.0098] * 6)
    ds["damping_ratio_target"] = ("mode", [0.0098] * 6)
    ds["damping_ratio_achieved"] = ("mode", [0.0098 * (1 + damping_off)] * 6)
    ds["variance_share"] = ("mode", [0.0, 0.98, 0.02, 0.0, 0.0, 0.0])
    ds["natural_period_rom"] = ("rom_mode", list(ROM_PERIODS.values()))
    ds["damping_ratio_rom"] = ("rom_mode", [0.0098] * 4)
    ds["decay_period"] = ("model", [15.443, 15.445])
    ds["decay_damping_ratio"] = ("model", [0.0098, 0.0099])
    ds["decay_fit_r2"] = ("model", [1.0, 0.99999])
    ds["harmonic_gain"] = (("model", "period", "amplitude"), [[[2.5], [3.1]], [[2.5], [3.0]]])
    ds["harmonic_phase"] = (("model", "period", "amplitude"), [[[-10.0], [-170.0]], [[-10.0], [-169.0]]])
    ds["trace_relative_sway"] = (("model", "trace_time"), [sigma_ratio * ref_trace, ref_trace])
    if tugger != "none":
        ds["tugger_limit_fraction"] = ((), 0.0)
    add_verdict(ds, tolerance)
    registry.annotate(ds, "verification_cell")
    ds.attrs.update(cell=cell_name(candidate, tugger, 90, hs, tz), status="verified", reason="",
                    candidate=candidate, tugger=tugger, hs_m=hs, tz_s=tz, heading_deg=90.0,
                    duration_s=1200.0, transient_s=1254.0, dt_s=0.05, seed="(1, 2)",
                    kinematics="rigid", release_m=0.54, reference="MoorDyn-C 2.7 (test)",
                    damping="dashpots (test)", reasons=reasons)
    return ds


def plain(markup: str) -> str:
    """Markup with the escapes and break opportunities of jls.report.markup.t removed."""
    return markup.replace("\\", "").replace("\u200b", "")


def context(cells, best=REC, figs=None):
    dg = SimpleNamespace(best=best, baseline="baseline", no_tugger="none")
    return SimpleNamespace(dg=dg, verification=list(cells), figs=figs or {})


def compiles(tmp_path, body):
    """The markup typesets with the report's template."""
    tpl = resources.files("jls.report").joinpath("template.typ")
    with resources.as_file(tpl) as p:
        shutil.copyfile(p, tmp_path / "template.typ")
    (tmp_path / "main.typ").write_text('#import "template.typ": *\n'
                                       '#show: report.with(title: [t], subtitle: [s], footer-left: [f])\n'
                                       + body, encoding="utf-8")
    typst.compile(str(tmp_path / "main.typ"), output=str(tmp_path / "main.pdf"),
                  root=str(tmp_path), ignore_system_fonts=True)
    return True


def test_constructed_cells_follow_the_registry():
    registry.check(cell(*REC, 1.03), "verification_cell")
    u = unavailable_cell("MoorDyn cannot be imported", candidate="detuned", tugger="low", hs=1.0,
                         tz=7.0, heading_deg=90.0, duration_s=1200.0, dt=0.05, seed=1,
                         kinematics="rigid", tolerance=0.1)
    registry.check(u, "verification_cell")
    assert not bool(u["verified"]) and np.isnan(float(u["mpm_ratio"]))


@pytest.mark.parametrize("ratio, within, conservative", [(1.03, True, True), (0.98, True, False),
                                                          (1.15, False, True), (0.88, False, False)])
def test_verdict_of_a_cell(ratio, within, conservative):
    ds = cell(*REC, ratio)
    assert bool(ds["within_tolerance"]) is within and bool(ds["conservative"]) is conservative
    text = ver.verdict_text(ds)
    assert ("within" if within else "outside") in text
    assert ("not conservative" in text) is (not conservative)
    assert f"{'over' if ratio > 1 else 'under'}-predicts the MPM by {abs(100 * (ratio - 1)):.1f} %" in text


def test_page_one_confirmed_says_by_how_much():
    s = plain(ver.page_one_sentence(context([cell(*REC, 1.031), cell(*BASE, 0.95)])))
    assert "is confirmed" in s and "over-predicts the relative-sway MPM by 3.1 %" in s
    assert "MPM ratio 1.031" in s and "1 verified cell " in s


def test_page_one_under_prediction_within_tolerance_is_confirmed():
    s = plain(ver.page_one_sentence(context([cell(*REC, 0.981), cell(*REC, 1.02, hs=0.75)])))
    assert "is confirmed" in s and "under-predicts the relative-sway MPM by 1.9 %" in s
    assert "2 verified cells" in s and "MPM ratios 0.981-1.020" in s


def test_page_one_under_prediction_beyond_tolerance_is_not_confirmed():
    s = plain(ver.page_one_sentence(context([cell(*REC, 0.87)])))
    assert "is not confirmed" in s and "under-predicts the relative-sway MPM by 13.0 %" in s
    assert "overstated" in s and "Hs 1.25 m, Tz 7.5 s" in s


def test_page_one_unverified_with_the_reason():
    u = unavailable_cell("MoorDyn cannot be imported (ImportError)", candidate="detuned", tugger="low",
                         hs=1.0, tz=7.0, heading_deg=90.0, duration_s=1200.0, dt=0.05, seed=1,
                         kinematics="rigid", tolerance=0.1)
    s = ver.page_one_sentence(context([u]))
    assert "is unverified" in s and "MoorDyn cannot be imported" in s
    s = ver.page_one_sentence(context([cell(*BASE, 1.0)]))        # no cell of the recommendation
    assert "is unverified" in s and "verification.combinations" in s


def test_chapter_shows_ratios_decay_transfer_function_periods_and_verdicts(tmp_path):
    cx = context([cell(*BASE, 1.003), cell(*REC, 0.98, hs=0.75, tz=9.5)])
    for name, draw, _ in ver.figure_plan(cx):
        assert draw(tmp_path).name == f"{name}.svg"
        cx.figs[name] = f"{name}.svg"
    markup = ver.verification(cx)
    assert compiles(tmp_path, markup)
    text = plain(markup)
    assert text.startswith("= Verification against a nonlinear reference")
    assert text.index("detuned / low") < text.index("baseline / none")      # recommendation first
    assert "0.980" in text and "1.003" in text                                # the ratios
    assert "recommendation" in text and "baseline" in text
    assert "under-predicts the MPM by 2.0 %" in text and "over-predicts the MPM by 0.3 %" in text
    assert "within the 10 % tolerance, not conservative" in text
    assert text.count("not carried") == 4                                     # surge and pitch, two combinations
    assert "19.200" in text and "1.770" in text                               # the reference's own modes
    assert "gain ratio 13.9 s" in text and "1.033" in text                    # 3.1 / 3.0 at 17 s
    assert "15.443" in text and "15.445" in text                              # decay periods
    assert "verification_traces.svg" in text


def test_chapter_without_the_reference_says_so(tmp_path):
    u = unavailable_cell("the nonlinear reference needs MoorDyn", candidate="detuned", tugger="low",
                         hs=1.0, tz=7.0, heading_deg=90.0, duration_s=1200.0, dt=0.05, seed=1,
                         kinematics="rigid", tolerance=0.1)
    cx = context([u])
    assert ver.figure_plan(cx) == []
    text = ver.verification(cx)
    assert "could not run" in text and "needs MoorDyn" in text and "unverified" in text
    assert compiles(tmp_path, text)
    text = ver.verification(context([]))
    assert "No cell was verified" in text and compiles(tmp_path, text)


def test_chapter_states_the_legs_left_out_with_their_reason(tmp_path):
    """Legs whose sea is their own are refused by the verification (the reference runs a
    JONSWAP): the chapter says which and why, from the workability's attribute."""
    import xarray as xr

    from jls.stages.verification_cell import refused_legs
    cx = context([])
    cx.work = xr.Dataset(attrs={"verification_refused_legs": refused_legs({"swell_leg": "partitions"})})
    text = ver.verification(cx)
    assert "Legs left out of the verification" in text and "swell" in text and "JONSWAP" in plain(text)
    assert "No cell was verified" in text and compiles(tmp_path, text)
    cx.work = xr.Dataset(attrs={"verification_refused_legs": ""})
    assert "left out" not in ver.verification(cx)
