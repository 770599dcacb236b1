"""The chapter "The reference study beside this assessment": the study's numbers in
jls.report.study_values equal the published ones (read back from the study's text), and
the chapter prints them beside ours, ours equal to the datasets'."""

import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import report_fixtures as rf
from test_report_checks import context

from jls.assessment.recommendation import Reason
from jls.names import RELATIVE_SWAY
from jls.report import study
from jls.report import study_values as sv

STUDY = Path("/work/shared/reference/thesis-suspended-jacket-motion-control.txt")


@pytest.fixture(scope="module")
def lines():
    if not STUDY.exists():
        pytest.skip(f"the study's text is not at {STUDY}")
    return STUDY.read_text(encoding="utf-8").splitlines()


def numbers(fields):
    out = []
    for f in fields:
        m = re.fullmatch(r"\s*([+-]?\d+(?:\.\d+)?)\s*%?\*?\s*", f)
        out.append(float(m.group(1)) if m else f.strip())
    return out


def table_rows(lines, caption, after=True):
    """The tab-separated rows next to the study's caption ``caption`` ("Table 4.4:"): the
    block after it (or before it), header included, blank lines skipped."""
    i = next(k for k, line in enumerate(lines) if line.startswith(caption))
    step = 1 if after else -1
    k, out = i + step, []
    while 0 <= k < len(lines) and (not lines[k].strip() or "\t" in lines[k] or not out):
        if "\t" in lines[k]:
            out.append(numbers(lines[k].split("\t")))
        k += step
    return out if after else out[::-1]


def by_first(rows):
    return {r[0]: r[1:] for r in rows}


def test_table_3_1_and_5_2(lines):
    modes = {r[-1].lower(): r[1] for r in table_rows(lines, "Table 3.1:", after=False)[1:]}
    assert modes == sv.TABLE_3_1_PERIOD_S
    t52 = by_first(table_rows(lines, "Table 5.2:"))
    base, opt = sv.TABLE_5_2["baseline"], sv.TABLE_5_2["optimised"]
    assert t52["Top spread, S_{top} [m]"] == [base["top_spread_m"], opt["top_spread_m"]]
    assert t52["Drop height, h_{drop} [m]"] == [base["drop_height_m"], opt["drop_height_m"]]
    assert t52["Sway period, T_{sway} [s]"] == [base["sway_period_s"], opt["sway_period_s"]]


def test_table_4_4_and_its_sea_states(lines):
    t44 = by_first(table_rows(lines, "Table 4.4:"))
    for name, (rom, orca, sigma, top) in sv.TABLE_4_4.items():
        r = t44[name]
        assert [r[0], r[1], r[3], r[4]] == [rom, orca, sigma, top]
    assert len(t44) == 1 + len(sv.TABLE_4_4)                      # header and five sea states
    text = "\n".join(lines)
    for name in ("V1", "V2", "S1"):
        hs, tz = sv.VALIDATION_SEA_STATES[name]
        assert f"**{name}** ($H_s = {hs:.2f}$ m, $T_z = {tz:.2f}$ s)" in text
    for name in ("V3", "V4"):                      # carried at the beam-sea height, 2.40 m
        assert f"**{name}** ($T_z = {sv.VALIDATION_SEA_STATES[name][1]:.2f}$ s)" in text
        assert sv.VALIDATION_SEA_STATES[name][0] == sv.VALIDATION_SEA_STATES["V1"][0]


def test_tables_6_3_and_6_5(lines):
    t63 = by_first(table_rows(lines, "Table 6.3:"))
    for name, values in sv.TABLE_6_3.items():
        assert tuple(t63[name.capitalize()]) == values
    assert "capped at 980, 980 and 1980 kN respectively" in "\n".join(lines)
    assert list(sv.SECTION_6_4_NET_FORCE_KN.values()) == [980.0, 980.0, 1980.0]
    t65 = table_rows(lines, "Table 6.5:")[1:]
    assert {(r[0], r[1]): tuple(r[2:]) for r in t65} == sv.TABLE_6_5


def test_tables_6_7_to_6_9(lines):
    t67 = by_first(table_rows(lines, "Table 6.7:"))
    for label, key in (("No tugger", "none"), ("Low (300 kN·s/m)", "low"),
                       ("Reference (1000 kN·s/m)", "reference"), ("High (2000 kN·s/m)", "high")):
        assert t67[label][0] == sv.TABLE_6_7_TO_TZ_S[key]
        if key != "none":
            assert t67[label][1] == sv.TABLE_6_7_GAIN_S[key]
    t68 = by_first(table_rows(lines, "Table 6.8:"))
    for label, key in (("As rigged", "as rigged"), ("Tugger only", "tugger only"),
                       ("Rigging changed", "rigging changed"), ("Both", "both")):
        assert t68[label][0] == sv.TABLE_6_8_TO_TZ_S[key]
        if key != "as rigged":
            assert t68[label][1] == sv.TABLE_6_8_GAIN_S[key]
    t69 = table_rows(lines, "Table 6.9:")[1:]
    assert {r[0]: tuple(r[1:]) for r in t69} == sv.TABLE_6_9


# -- the chapter ------------------------------------------------------------------------
@pytest.fixture(scope="module")
def cx():
    return context(rf.datasets())


def test_our_sway_mpm_equals_the_response_dataset(cx):
    # Hs x limit / Hs_lim,sway on the operability grid is Hs x the unit MPM of response.nc
    combo = (cx.dg.baseline, cx.dg.no_tugger)
    for tz in (6.0, 7.5, 8.5):
        used, mpm = study.sway_mpm(cx, combo, 2.4, tz)
        unit = float(cx.resp["mpm"].sel(candidate=combo[0], tugger=combo[1], heading=90.0,
                                        response=RELATIVE_SWAY, tz=tz))
        assert used == tz
        assert mpm == pytest.approx(2.4 * unit, rel=1e-12)


def test_chapter_prints_the_study_beside_ours(cx):
    text = study.chapter(cx)
    assert text.startswith("= The reference study beside this assessment")
    for published in ("15.700", "3.543", "18.39", "13.05", "66.46", "22.86", "6.63", "+0.53",
                      "+0.15", "+0.60", "7.15", "2.68", "3.77", "10.11"):
        assert published in text, published
    # ours: the rigging change's sway period from the plant, the window from the curves
    assert f"{study._period(cx, 'detuned', 'sway'):,.2f}" in text
    assert f"{study.window_to(cx, (cx.dg.baseline, cx.dg.no_tugger)):,.2f}" in text
    assert study.change_rigging(cx) == "detuned"


def fake(gains_high_beats: bool, excluded: bool):
    dg = SimpleNamespace(baseline="baseline", best=("detuned", "none"), tuggers=["none", "high", "reference"],
                         excluded={("baseline", "high"): Reason("winches saturate in 4 % of the route",
                                                                "winch 4.0 %")} if excluded else {})
    return SimpleNamespace(dg=dg, c_tugger=lambda tg: {"none": 0.0, "high": 2000.0, "reference": 1000.0}[tg])


def test_the_rule_is_stated_where_the_high_tugger_beats_the_rigging_change():
    ours = {"as rigged": 0.0, "tugger reference only": 0.22, "tugger high only": 0.54, "rigging changed": 0.35}
    text = study._finding(fake(True, True), ours)
    assert "the tugger high alone gains more than the rigging change here" in text
    assert "still excludes baseline rigging, tugger high" in text and "winches saturate" in text
    text = study._finding(fake(True, False), ours)
    assert "prefers detuned rigging, tugger none" in text
    # the study's ranking: said so, no exclusion argued
    ours["tugger high only"] = 0.30
    assert "The ranking is the study's" in study._finding(fake(False, True), ours)


def test_absent_without_the_sway_criterion(cx):
    other = SimpleNamespace(dg=SimpleNamespace(criteria=["relative_yaw_deg"]), work=cx.work)
    assert not study.present(other)
    assert np.isfinite(study.hs_limit(cx, (cx.dg.baseline, cx.dg.no_tugger), 7.0))
