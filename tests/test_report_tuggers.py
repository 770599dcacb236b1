"""The report with winch limits and time-domain cells: page 1 states what the
recommendation excludes and why; the chapter "Damping tuggers" renders the time-domain
cells, the decay tests, the slope sweep and the four cases (synthetic route of
tests/report_fixtures.py)."""

import copy
import re

import pypdf
import pytest
import report_fixtures as rf

from jls.assessment.winch_limits import apply_timedomain, apply_winch_limits
from jls.assessment.workability import assessed_hs
from jls.config.loader import load
from jls.report.contract import digest
from jls.report.document import render_report
from jls.stages.timedomain_cell import cell_dataset
from jls.stages.tugger_studies import tugger_studies
from jls.tugger.setting import Tugger


def _text(path):
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(path).pages)
    return text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", "")


@pytest.fixture(scope="module")
def data():
    return rf.datasets()


def limited(data, capacity_kN, policy="fail", fraction=0.01, cells=()):
    """The fixture's workability with a reference winch of the given per-line capacity."""
    d = copy.copy(data)
    sea, resp = d["sea_states"], d["response"]
    tuggers = {"none": Tugger("none", 0.0), "reference": Tugger("reference", 1000.0, max_force=capacity_kN)}
    hs = assessed_hs(sea)
    work = apply_winch_limits(d["workability"].copy(), resp, sea, tuggers, hs, policy)
    work = apply_timedomain(work, sea, list(cells), hs)
    work.attrs["max_saturation_fraction"] = fraction
    work.attrs["tugger_min_gain"] = 0.0       # the winch rule alone: any gain earns a place here
    d["workability"] = work
    return d


def test_recommendation_excludes_a_saturating_setting_and_says_why(tmp_path):
    # The baseline alone: its tugger earns its place unless the winch saturates (the
    # fixture's detuned rigging, on its tolerance budget, does as well without a tugger).
    data = rf.datasets(candidates={"baseline": {}})
    free = limited(data, 1.0e5)                       # a winch that never saturates
    dg_free = digest("test_route", *(free[k] for k in ("sea_states", "vessel_motion", "plant",
                                                        "response", "workability")), rf.provenance())
    assert dg_free.best[1] == "reference" and dg_free.best not in dg_free.excluded
    assert all(r.short.startswith("tugger") for r in dg_free.excluded.values())   # gain rule only
    small = limited(data, 60.0)                        # 2 (60 - 40) = 40 kN for damping
    share = float(small["workability"]["saturation_share_route"].sel(candidate=dg_free.best[0],
                                                                      tugger="reference"))
    assert share > 0.01
    dg = digest("test_route", *(small[k] for k in ("sea_states", "vessel_motion", "plant",
                                                    "response", "workability")), rf.provenance())
    assert dg.best[1] == "none"
    assert all(tg == "reference" for _, tg in dg.excluded)
    out = render_report(tmp_path / "r.pdf", route="test_route", provenance=rf.provenance(), **small)
    # the selection rule and table 1, stated in full in the chapter after page 1
    pages = pypdf.PdfReader(out).pages
    page1 = re.sub(r"\s+", " ", " ".join(pages[k].extract_text() for k in range(3)).replace("\xa0", " "))
    page1 = page1[page1.index("2. Assessment in detail"):page1.index("3. Operational basis")]
    assert "Excluded: " in page1
    label = f"winch {100 * share:.1f} %"                 # the sentence and table 1's column
    assert page1.count(label) >= 2
    assert dg.excluded[(dg_free.best[0], "reference")].short.startswith(label.replace(" %", "\u00a0%"))
    assert "winches saturate in the frequency domain in sea states carrying x % of the route" in page1


def test_chapter_shows_cells_decay_sweep_and_four_cases(data, tmp_path):
    cfg = load(rf.ROOT / "config" / "config.yaml")
    cfg["timedomain"].update(duration_h=0.5, trace_s=60,
                             slope_sweep={**cfg["timedomain"]["slope_sweep"], "slopes_kN_s_per_m": [1000],
                                          "tz_s": [6.6], "duration_h": 0.5})
    cfg["tuggers"] = [t for t in cfg["tuggers"] if t["name"] in ("none", "reference")]
    motion = data["vessel_motion"]
    cell = {"candidate": "baseline", "heading": 90.0, "hs": 2.5, "tz": 7.5, "reasons": ["configured"]}
    td = cell_dataset(cfg, motion, cell)
    assert td.sizes["time"] == int(round(60 / cfg["timedomain"]["dt_s"]))
    # The tugger settings' runs on two threads give the same dataset, bit for bit (but
    # for the measured run times).
    two = cell_dataset(cfg, motion, cell, workers=2)
    assert two.drop_vars("wall_time").identical(td.drop_vars("wall_time"))
    studies = tugger_studies(cfg, motion)
    # A decay with the tugger is faster than without.
    t10 = studies["decay_time_to_10pct"]
    assert float(t10.sel(tugger="reference")) < float(t10.sel(tugger="none"))
    d = limited(data, 1000.0, cells=[td])
    out = render_report(tmp_path / "r.pdf", route="test_route", provenance=rf.provenance(), **d,
                        timedomain=[td], timedomain_cells=[{"name": td.attrs["cell"], "reasons": ["configured"]}],
                        tugger_studies=studies)
    text = _text(out)
    chapter = text[text.index("Damping tuggers\n"):text.index("Assumptions and validity\n")]
    flat = re.sub(r"\s+", " ", chapter)
    for title in ("Time-domain cells", "Decay tests", "Damping-slope sweep",
                  "Rigging change and tugger side by side"):
        assert title in chapter
    assert "as rigged baseline / none" in flat and "both detuned / reference" in flat
    assert f"{float(td['sigma'].sel(tugger='none')):.3f}" in chapter
    n_td = int((d["workability"]["verdict_source"] == 3).sum())
    assert n_td > 0 and f"{n_td} from the time domain" in flat
    # the cell named in words on its own row, the winch capacity per line, the critical
    # damping of the dataset
    assert td.attrs["cell"] not in flat and "baseline rigging, heading 90°, Hs 2.5 m, Tz 7.5 s" in flat
    assert "capacity per line [kN]" in flat and re.search(r"reference 1 000 1 000 ", flat)
    crit = f"{float(studies.attrs['critical_slope_kN_s_per_m']):,.0f}".replace(",", " ")
    assert re.search(rf"critical damping of this plant.s sway mode is {crit} kN s/m", flat)
