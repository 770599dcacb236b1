"""The report's fixes of issues 20 and 21 on the synthetic route (tests/report_fixtures.py):
the operational basis (unrestricted and weather-restricted, with and without alpha), the
voyage extremes (curve, table, page-1 line, months of a hindcast route), references that
Typst numbers, the failure split, the four cases, and the figures' axes from the data.
tests/test_report_default.py checks the same on the default route's report."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import numpy as np
import pypdf
import pytest
import report_fixtures as rf
import xarray as xr

from jls.assessment.operation import AlphaTable, classify, forecast_limits
from jls.assessment.winch_limits import apply_winch_limits
from jls.assessment.workability import assessed_hs
from jls.report import rigging_compare, tuggers, vessel, voyage
from jls.report.context import Context
from jls.report.contract import digest, on_sea_grid
from jls.report.document import render_report
from jls.report.markup import num, plural, signed
from jls.report.style import operability_top
from jls.report.workability import failure_split
from jls.tugger.setting import Tugger

REPORT = Path(__file__).resolve().parents[1] / "jls" / "report"
MONTHS = ("Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec")


def pdf_text(path) -> str:
    """The PDF's text with plain spaces and apostrophes (Typst sets typographic ones)."""
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(path).pages)
    return (text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", "")
            .replace("\u2019", "'"))


def flat(text: str) -> str:
    return re.sub(r"\s+", " ", text)


def headings(text: str) -> dict:
    """Chapter title -> its number, as the PDF prints them."""
    return {m.group(2).strip(): int(m.group(1)) for m in re.finditer(r"^(\d+)\. (\S[^\n]*)$", text, re.M)}


def chapter(text: str, title: str) -> str:
    nums = headings(text)
    k = nums[title]
    start = re.search(rf"^{k}\. {re.escape(title)}$", text, re.M).end()
    nxt = re.search(rf"^{k + 1}\. \S", text[start:], re.M)
    return text[start:start + nxt.start()] if nxt else text[start:]


def context(data, voy=None, **kw) -> Context:
    dg = digest("r", *(data[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                         "workability")), rf.provenance())
    return Context(sea=data["sea_states"], vessel=data["vessel_motion"], plant=data["plant"],
                   resp=data["response"], work=data["workability"], prov=rf.provenance(), dg=dg,
                   figs={}, voyage=voy, **kw)


def captured(monkeypatch, module):
    """Figures ``module`` saves, kept instead of written."""
    figs = []
    monkeypatch.setattr(module, "save", lambda fig, out_dir, name: figs.append(fig) or Path(out_dir) / name)
    return figs


@pytest.fixture(scope="module")
def data():
    return rf.datasets()


def with_hindcast_months(voy: xr.Dataset) -> xr.Dataset:
    """The fixture's voyage.nc with the route simulation's monthly results of a hindcast
    route (values constructed, layout the registry's)."""
    v = voy.copy()
    shape = (v.sizes["candidate"], v.sizes["tugger"])
    months = np.arange(1, 13)
    p = np.clip(0.55 - 0.4 * np.cos(2 * np.pi * (months - 1) / 12)[None, None, :]
                + 0.05 * np.arange(shape[1])[None, :, None] - 0.1 * np.arange(shape[0])[:, None, None], 0, 1)
    v["pass_probability_month"] = (("candidate", "tugger", "month"), p)
    v["pass_probability"] = (("candidate", "tugger"), p.mean(-1))
    v["best_month"] = (("candidate", "tugger"), np.full(shape, 7, np.int64))
    v["worst_month"] = (("candidate", "tugger"), np.full(shape, 1, np.int64))
    v["departures_month"] = ("month", np.full(12, 700, np.int64))
    v["judged_month"] = ("month", np.full(12, 690, np.int64))
    return v.assign_coords(month=months)


@pytest.fixture(scope="module")
def rendered(data, tmp_path_factory):
    voy = with_hindcast_months(rf.voyage(data))
    out = render_report(tmp_path_factory.mktemp("checks") / "r.pdf", route="r", voyage=voy,
                        provenance=dict(rf.provenance(), route_description="North Sea to Biscay, two legs"),
                        **data)
    return pdf_text(out), voy


# -- numbers and references ---------------------------------------------------------------
def test_a_value_that_rounds_to_zero_has_no_sign():
    assert num(-0.001, 2) == "0.00" and num(-0.4, 0) == "0" and num(-1.5, 1) == "-1.5"
    assert signed(-0.001, 2) == "0.00" and signed(1.234, 2) == "+1.23" and signed(-0.4, 1) == "-0.4"
    assert plural(1, "leg") == "1 leg" and plural(2, "leg") == "2 legs"


def _literals(tree):
    docstrings = {id(n.body[0].value) for n in ast.walk(tree)
                  if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef)) and n.body
                  and isinstance(n.body[0], ast.Expr) and isinstance(n.body[0].value, ast.Constant)}
    for n in ast.walk(tree):
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings:
            yield n.lineno, n.value


def test_no_chapter_writes_a_section_table_or_figure_number_by_hand():
    """References to the report's own sections, tables and figures are Typst labels; a
    number after 'section', 'table' or 'figure' in a string is the study's, and says so."""
    pattern = re.compile(r"(?<!study's )(?<!study )\b(sections?|tables?|figures?)\s+\d", re.I)
    found = [f"{p.name}:{line}: {s!r}" for p in sorted(REPORT.glob("*.py"))
             for line, s in _literals(ast.parse(p.read_text())) if pattern.search(s)]
    assert not found, "\n".join(found)


def test_references_carry_the_numbers_of_the_compiled_headings(rendered):
    text = rendered[0]
    nums = headings(text)
    sea = flat(chapter(text, "Sea states"))
    assert f"outside the linear range (section {nums['Assumptions and validity']})" in sea
    assert "(section 8)" not in sea
    tug = flat(chapter(text, "Damping tuggers"))
    assert f"(sections {nums['Operability']} and {nums['Workability']})" in tug
    summary = flat(chapter(text, "Summary"))
    assert f"section {nums['Voyage extremes']}" in summary


def test_no_configuration_advice_and_no_raw_optimiser_text(rendered):
    text = flat(rendered[0])
    for phrase in ("configure ", "Set assessment.", "give a leg", "to obtain its band",
                   "name it as a candidate", "screening.constraints", "trust-region", "-0.00"):
        assert phrase not in text, phrase
    assert not re.search(r"\b1 (legs|cells|variants|combinations)\b", text)


# -- operational basis ------------------------------------------------------------------
def test_unrestricted_operation_points_to_the_voyage_extremes(rendered, data):
    text = rendered[0]
    nums = headings(text)
    page1 = flat(chapter(text, "Assessment in detail"))          # page 1 stated in full
    work = data["workability"]
    assert work.attrs["operation_class"] == "unrestricted"
    assert "Operational basis: unrestricted operation (DNV-ST-N001; " in page1
    assert f"the voyage extremes (section {nums['Voyage extremes']})" in page1
    basis = flat(chapter(text, "Operational basis"))
    assert f"planned operation period T_POP {num(work.attrs['planned_period_h'], 0)} h" in basis
    assert "contingency time T_C not stated" in basis
    assert "Design basis:" in basis and "no forecast limit OP_WF" in basis
    assert "Limiting sea states for the master" not in text


def restricted(data, alpha: bool):
    work = data["workability"].copy()
    basis = classify(48.0, 12.0)
    table = AlphaTable("DNV-ST-N001 table 2-1, forecast level B (example)", [12.0, 72.0],
                       [1.0, 6.0], [[0.9, 0.95], [0.7, 0.8]]) if alpha else None
    lim = forecast_limits(work["hs_limit"], basis, table)
    for name in ("alpha_factor", "hs_opwf"):
        if name in lim:
            work[name] = lim[name]
    work.attrs.update(operation_class=basis.operation_class, operation_reason=basis.reason,
                      planned_period_h=48.0, reference_period_h=60.0, contingency_h=12.0)
    if table:
        work.attrs["alpha_source"] = table.source
    return dict(data, workability=work)


@pytest.mark.parametrize("alpha", [True, False])
def test_weather_restricted_operation_gives_the_master_a_table(data, tmp_path, alpha):
    d = restricted(data, alpha)
    text = pdf_text(render_report(tmp_path / "r.pdf", route="r", provenance=rf.provenance(), **d))
    page1 = flat(chapter(text, "Assessment in detail"))
    assert "Operational basis: weather-restricted operation" in page1
    master = flat(chapter(text, "Operational basis"))
    assert "Limiting sea states for the master" in master
    dg = digest("r", *(d[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                      "workability")), rf.provenance())
    op = d["workability"]["hs_limit"].sel(candidate=dg.best[0], tugger=dg.best[1], heading=90.0)
    rows = {}
    for z in op.dropna("tz")["tz"].values:
        m = re.search(rf"(?m)^{z:.2f} (.*)$", text[text.index("Limiting Hs for the master"):])
        rows[z] = m.group(1).split()
        assert rows[z][0] == f"{float(op.sel(tz=z)):.2f}"                       # OP_LIM
    if alpha:
        wf = d["workability"]["hs_opwf"].sel(candidate=dg.best[0], tugger=dg.best[1], heading=90.0)
        for z, cells in rows.items():
            assert cells[2] == f"{float(wf.sel(tz=z)):.2f}"                      # OP_WF
        assert "DNV-ST-N001 table 2-1, forecast level B (example)" in master
    else:
        assert "Alpha was not applied" in master and "OP_WF" not in " ".join(" ".join(r) for r in rows.values())


# -- voyage extremes -------------------------------------------------------------------
def test_voyage_chapter_and_page_1_line_equal_the_dataset(rendered, data):
    text, voy = rendered
    cx = context(data, voy)
    best = cx.dg.best
    inside = 1 - float(voy["exceedance_probability_any"].sel(candidate=best[0], tugger=best[1]))
    page1 = flat(chapter(text, "Assessment in detail"))
    assert (f"the probability that the voyage of {best[0]} rigging, tugger {best[1]} stays inside "
            f"every limit from departure to arrival is {100 * inside:.1f} %") in page1
    ch = flat(chapter(text, "Voyage extremes"))
    assert "conservative" in ch and "over-estimate the exceedance probability" in ch
    for c, tg in cx.dg.table.combos:
        p = float(voy["exceedance_probability"].sel(candidate=c, tugger=tg, criterion="relative_sway_m"))
        lv = voy["voyage_level"].sel(candidate=c, tugger=tg, criterion="relative_sway_m")
        # a level beyond the linear model's range (2 x the 3-m limit) is never printed as a figure
        shown = [f"{x:.1f} m" if x <= 6.0 else "beyond the model"
                 for x in (float(lv.sel(non_exceedance=q)) for q in (0.5, 0.9))]
        assert re.search(rf"{c} {tg} {100 * p:.1f} % {shown[0]} {shown[1]}", ch), (c, tg)
    assert "Share of the month's judged departures whose voyage stays inside every limit" in ch
    assert "best month Jul, worst month Jan" in ch


def test_voyage_levels_beyond_the_linear_range_are_said_so():
    lv = xr.DataArray([[[[24.0, 33.0]]]], dims=("candidate", "tugger", "criterion", "non_exceedance"),
                      coords={"candidate": ["a"], "tugger": ["n"], "criterion": ["relative_sway_m"],
                              "non_exceedance": [0.5, 0.9]})
    v = xr.Dataset({"voyage_level": lv, "limit": ("criterion", [3.0])}).assign_coords(
        level_units=("criterion", ["m"]))
    assert voyage.beyond_linear(v, ("a", "n")) == [("relative_sway_m", 24.0, 6.0,
                                                    "the linear range stated, 2 × the limit")]
    assert voyage.beyond_linear(v.assign(voyage_level=lv / 10), ("a", "n")) == []


def test_exceedance_curve_axes_and_marks_from_the_data(data, rendered, monkeypatch, tmp_path):
    voy = rendered[1]
    cx = context(data, voy)
    figs = captured(monkeypatch, voyage)
    voyage.exceedance_figure(voy, cx.dg, tmp_path)
    ax = figs[0].axes[0]
    lim = float(voy["limit"].sel(criterion="relative_sway_m"))
    long = [ln for ln in ax.get_lines() if len(ln.get_xdata()) > 2]
    curves = [ln for ln in long if not ln.get_label().startswith("_")]
    greyed = [ln for ln in long if ln.get_label().startswith("_")]
    assert len(curves) == len(cx.dg.plot.combos)
    c0 = voy["exceedance_curve"].sel(candidate=cx.dg.plot.combos[0][0], tugger=cx.dg.plot.combos[0][1],
                                     criterion="relative_sway_m")
    x = c0["level"].values * lim
    # coloured up to the model's range (2 x the limit), greyed beyond it (issue 31, item 5)
    np.testing.assert_allclose(curves[0].get_xdata(), np.where(x <= 2 * lim, x, np.nan))
    np.testing.assert_allclose(curves[0].get_ydata(), c0.values)
    if x.max() > 2 * lim:
        assert greyed and np.nanmin(np.asarray(greyed[0].get_xdata(), float)) >= 2 * lim
        assert all(ln.get_color() == "0.6" for ln in greyed)
    assert any(np.allclose(ln.get_xdata(), lim) for ln in ax.get_lines() if len(ln.get_xdata()) == 2)
    assert ax.get_xlim()[0] == pytest.approx(0.5 * lim)
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    voyage.month_figure(voy, cx.dg, tmp_path)
    line = figs[1].axes[0].get_lines()[0]
    np.testing.assert_allclose(line.get_ydata(), 100 * voy["pass_probability_month"].sel(
        candidate=cx.dg.plot.combos[0][0], tugger=cx.dg.plot.combos[0][1]).values)


# -- figures ------------------------------------------------------------------------------
def test_hinge_figure_draws_roll_once_and_no_empty_panel(data, monkeypatch, tmp_path):
    cx = context(data)
    figs = captured(monkeypatch, vessel)
    vessel.hinge_raos(cx.vessel, cx.plant, cx.dg, tmp_path)
    titles = [ax.get_title() for ax in figs[0].axes if ax.get_visible()]
    assert sum("roll" in s for s in titles) == 1
    assert not any("yaw" in s for s in titles)          # round-off at every heading here
    assert all(len(ax.get_lines()) > 0 for ax in figs[0].axes if ax.get_visible())


def test_transfer_functions_show_three_decades_below_the_peak(data, monkeypatch, tmp_path):
    cx = context(data)
    figs = captured(monkeypatch, vessel)
    vessel.relative_transfer(cx.resp, cx.plant, cx.dg, tmp_path)
    ax = figs[0].axes[0]
    peak = max(np.nanmax(ln.get_ydata()) for ln in ax.get_lines() if len(ln.get_ydata()) > 2)
    assert ax.get_ylim()[0] == pytest.approx(1e-3 * peak)


def test_recommended_operability_draws_the_ceiling_whole_and_colours_cells(data, monkeypatch, tmp_path):
    cx = context(data)
    figs = captured(monkeypatch, rigging_compare)
    rigging_compare.recommended_operability(cx.work, cx.sea, cx.dg.best, 2.4, tmp_path)
    ax = figs[0].axes[0]
    ceiling = next(ln for ln in ax.get_lines() if ln.get_label() == "steepness ceiling")
    assert np.nanmax(ceiling.get_ydata()) > ax.get_ylim()[1]            # leaves the axis, no plateau
    assert np.sum(np.isclose(ceiling.get_ydata(), ax.get_ylim()[1])) <= 1
    colours = np.concatenate([c.get_facecolors()[:, :3] for c in ax.collections if len(c.get_offsets())])
    fail = np.array(matplotlib_rgb(rigging_compare.FAIL))
    passes = on_sea_grid(cx.work["passes"].sel(candidate=cx.dg.best[0], tugger=cx.dg.best[1]), cx.sea)
    live = cx.sea["probability"] > 0
    n_fail = int(((passes.fillna(0) < 0.5).all("heading") & live).sum())
    assert n_fail > 0 and int(np.isclose(colours, fail, atol=1e-3).all(1).sum()) == n_fail


def matplotlib_rgb(colour):
    from matplotlib.colors import to_rgb
    return to_rgb(colour)


def test_four_cases_axis_follows_the_limiting_curves(data, monkeypatch, tmp_path):
    cx = context(data)
    figs = captured(monkeypatch, tuggers)
    tuggers.four_cases_figure(cx, tmp_path)
    ax = figs[0].axes[0]
    ceiling = cx.work["steepness_limit_curve"].values
    lines = [cx.work["hs_limit_curve"].min("heading").sel(candidate=c, tugger=tg).values
             for _, (c, tg) in tuggers.four_cases(cx)]
    assert ax.get_ylim()[1] == pytest.approx(operability_top([(y, ceiling) for y in lines]))
    assert ax.get_ylim()[1] < np.nanmax(ceiling)


# -- failures, four cases -------------------------------------------------------------------
@pytest.fixture(scope="module")
def three_tuggers():
    d = rf.datasets(tuggers={"none": 0.0, "low": 300.0, "reference": 1000.0})
    sea, resp = d["sea_states"], d["response"]
    tugs = {"none": Tugger("none", 0.0), "low": Tugger("low", 300.0, max_force=1.0e5),
            "reference": Tugger("reference", 1000.0, max_force=60.0)}
    work = apply_winch_limits(d["workability"].copy(), resp, sea, tugs, assessed_hs(sea), "fail")
    work.attrs["tugger_min_gain"] = 0.0
    return dict(d, workability=work)


def test_failure_split_adds_up_to_the_non_workable_probability(three_tuggers):
    cx = context(three_tuggers)
    work = three_tuggers["workability"]
    saw_winch = False
    for combo in cx.dg.combos:
        split = failure_split(cx, combo)
        total = sum(split.values())
        w = work["workability_leg"].sel(candidate=combo[0], tugger=combo[1])
        np.testing.assert_allclose(total.transpose("leg").values, 1 - w.transpose("leg").values, atol=1e-12)
        saw_winch |= float(split["winch"].sum()) > 0
    assert saw_winch


def test_four_cases_take_the_tugger_page_1_excludes_least(three_tuggers):
    cx = context(three_tuggers)
    assert any(ct[1] == "reference" and cx.dg.excluded[ct].short.startswith("winch")
               for ct in cx.dg.excluded)
    cases = dict(tuggers.four_cases(cx))
    assert cases["tugger only"][1] == "low"
    text = flat(tuggers.chapter(cx))
    assert "page 1" in text
