"""The default route's report, built by the workflow in a temporary copy of the repository,
checked item by item against issue 20 (the loose ends an engineer trips over, what was
not assessed, what to verify before sailing) and issue 21 (voyage extremes): text present
or absent, table columns and values from the datasets, and the figures' axes drawn from
the same datasets by the report's own figure functions."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from test_report_checks import captured, chapter, flat, headings, pdf_text

from jls.io.netcdf import read
from jls.names import SATURATED_FAIL, TIME_DOMAIN
from jls.report import rigging_compare, tuggers, vessel
from jls.report.chapters import present_chapters
from jls.report.context import Context
from jls.report.contract import complex_var, digest, on_sea_grid
from jls.report.markup import num as _num
from jls.report.style import operability_top

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.slow


def num(x, nd=2) -> str:
    """A number as the PDF's text shows it (spaces for the thin and non-breaking ones)."""
    return _num(x, nd).replace("\u2009", " ").replace("\u00a0", " ")


@pytest.fixture(scope="module")
def default(default_run):
    """(PDF text, datasets, Context) of the default route, from a clean workflow run (the
    session's ``default_run``, which this module only reads)."""
    work = default_run
    res = work / "results" / "default"
    data = {"sea_states": read(res / "sea_states.nc"), "vessel_motion": read(res / "vessel_motion.nc"),
            "plant": read(res / "plant_assessed.nc"), "response": read(res / "response.nc"),
            "workability": read(res / "workability.nc")}
    extra = {"screening": read(res / "screening.nc"), "voyage": read(res / "voyage.nc"),
             "plan": read(res / "voyage_plan.nc"),
             "studies": read(res / "tugger_studies.nc"),
             "td": [read(p) for p in sorted((res / "timedomain").glob("*.nc"))]}
    prov = {"jls_version": "?", "config_sha256": "", "created": "", "inputs": {},
            "pdf": str(work / "reports" / "default.pdf")}
    dg = digest("default", *(data[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                               "workability")), prov)
    cx = Context(sea=data["sea_states"], vessel=data["vessel_motion"], plant=data["plant"],
                 resp=data["response"], work=data["workability"], prov=prov, dg=dg, figs={},
                 screening=extra["screening"], td=extra["td"], studies=extra["studies"],
                 voyage=extra["voyage"], plan=extra["plan"],
                 td_cells=json.loads((res / "timedomain" / "cells.json").read_text()))
    cx.sections = present_chapters(cx)
    return pdf_text(work / "reports" / "default.pdf"), data, cx


def test_every_chapter_in_order(default):
    text = default[0]
    nums = headings(text)
    for title in ("Summary", "Operational basis", "Rigging", "Damping tuggers", "Voyage extremes",
                  "Assumptions and validity"):
        assert title in nums, title
    assert sorted(nums.values()) == list(range(1, len(nums) + 1))


def test_page_1_carries_the_voyage_line_and_the_operational_basis(default):
    text, data, cx = default
    v = cx.voyage
    best = cx.dg.best
    inside = 1 - float(v["exceedance_probability_any"].sel(candidate=best[0], tugger=best[1]))
    page1 = flat(chapter(text, "Assessment in detail"))          # page 1 stated in full
    nums = headings(text)
    assert (f"stays inside every limit from departure to arrival is {100 * inside:.1f} % "
            f"(independent sea states, conservative; section {nums['Voyage extremes']})") in page1
    assert f"Operational basis: {data['workability'].attrs['operation_class']} operation" in page1
    assert "Gulf of Maine to off Cape Canaveral" in page1        # the route described


def test_page_1_is_one_page_and_names_what_binds_the_recommendation(default):
    """Issue 34, Build item 1: the summary ends on page 1 (its text holds chapter 2's
    heading) and names every criterion that binds the recommendation with its figure."""
    import pypdf
    text, data, cx = default
    page = flat(pypdf.PdfReader(cx.prov["pdf"]).pages[0].extract_text().replace("\xa0", " ")
                .replace("\u2009", " ").replace("\u200b", ""))
    assert "2. Assessment in detail" in page
    summary = page.split("2. Assessment in detail")[0]
    assert summary.strip().split("1. Summary")[1].strip().startswith(("Acceptable", "Not acceptable"))
    work, best, v = data["workability"], cx.dg.best, cx.voyage
    share = (work["governing_share"] * data["sea_states"]["leg_weight"]).sum("leg").sel(
        candidate=best[0], tugger=best[1])
    tip_binds = float(share.sel(criterion="tip_air_gap_m")) > 0 or (
        float(v["voyage_level"].sel(candidate=best[0], tugger=best[1], criterion="tip_air_gap_m")
              .sel(non_exceedance=0.5, method="nearest")) > float(v["limit"].sel(criterion="tip_air_gap_m")))
    daf = float(work["dynamic_amplification"].sel(candidate=best[0], tugger=best[1]))
    tension_binds = float(share.sel(criterion="wire_tension")) > 0 or daf > float(work.attrs["daf_limit"])
    assert tip_binds and tension_binds             # the default route: both bind its recommendation
    assert "tip air gap fails" in summary and "tension" in summary
    assert not re.search(r"\([^()]*\(", summary)                    # no nested parentheses
    assert f"{daf:.2f}, above the design value" in summary
    for leg in cx.legs:
        assert f"{leg} {100 * cx.w_leg(best, leg):.1f} %" in summary.replace("\u200b", "")


def test_page_1_opens_with_the_verdict_of_the_voyage_as_sailed(default):
    text, _, cx = default
    p, best = cx.plan, cx.dg.best
    page1 = flat(chapter(text, "Summary"))
    first = page1.strip()
    # the default route: 125 h without a hold point, unrestricted; its 10-year design sea
    # states break the limits, and its 75-h second leg must be split to be weather-restricted
    assert first.startswith("Not acceptable as an unrestricted transit")
    assert "Not acceptable as a weather-restricted transit either" in page1
    assert "leg cape_canaveral (75 h) is longer than 72 h" in page1
    exc = float(p["plan_exceedance_probability"].sel(candidate=best[0], tugger=best[1]))
    assert f"exceeds a limit {exc:.2f}" in page1
    assert "Forecast limits for the master" in page1
    assert "Voyage plan" in headings(text)
    # the master's table equals voyage_plan.nc, over the whole Tp range of the legs' seas
    tp = p["tp"].values
    assert tp[0] <= float(p["leg_tp_min"].min()) and tp[-1] >= float(p["leg_tp_max"].max())
    wf = p["master_hs_opwf"].sel(candidate=best[0], tugger=best[1])
    for leg in (str(x) for x in p["leg"].values):
        cells = ["–" if np.isnan(x) else "no limit" if np.isinf(x) else f"{x:.2f}"
                 for x in wf.sel(leg=leg).values]
        assert f"{leg}: OP_WF [m] {' '.join(cells)}" in page1


def test_voyage_chapter_says_the_levels_are_beyond_the_linear_model(default):
    text, _, cx = default
    ch = flat(chapter(text, "Voyage extremes"))
    lv = float(cx.voyage["voyage_level"].sel(candidate=cx.dg.best[0], tugger=cx.dg.best[1],
                                             criterion="relative_sway_m", non_exceedance=0.5))
    assert lv > 10.0                                  # the default route: tens of metres
    assert "The voyage levels lie outside the linear model's validity" in ch
    # never printed as a figure the linear model cannot give (issue 31, item 5)
    assert "beyond the model" in ch and f"{lv:.1f} m" not in ch
    assert "conservative" in ch and "Independence, and the side it errs on" in ch


def test_hinge_figure_and_transfer_functions(default, monkeypatch, tmp_path):
    _, _, cx = default
    figs = captured(monkeypatch, vessel)
    vessel.hinge_raos(cx.vessel, cx.plant, cx.dg, tmp_path)
    titles = [ax.get_title() for ax in figs[0].axes if ax.get_visible()]
    assert sum("roll" in s for s in titles) == 1
    # a panel for the yaw exactly when the hinge yaws: the default twin hull's bow slot
    # makes it yaw in beam seas (a box would not)
    hinge_yaw = np.abs(complex_var(cx.vessel, "hinge").sel(dof="yaw"))
    yaws = float(hinge_yaw.max()) * 215.0 > 0.05            # m/m at the tip of a 215 m lever
    assert any("yaw" in s for s in titles) == yaws == vessel._moves(cx.vessel, "hinge yaw")
    vessel.relative_transfer(cx.resp, cx.plant, cx.dg, tmp_path)
    for ax in figs[1].axes[:2]:
        peak = max(np.nanmax(ln.get_ydata()) for ln in ax.get_lines() if len(ln.get_ydata()) > 2)
        assert ax.get_ylim()[0] == pytest.approx(1e-3 * peak)


def test_captions_refer_to_the_compiled_section_numbers(default):
    text = default[0]
    nums = headings(text)
    sea = flat(chapter(text, "Sea states"))
    assert sea.count(f"outside the linear range (section {nums['Assumptions and validity']})") == 2
    assert "(section 8)" not in sea


def test_no_raw_optimiser_text_signed_zero_advice_or_singular_plural(default):
    text = flat(default[0])
    for phrase in ("trust-region", "-0.00", "+0.00", "configure ", "screening.constraints",
                   "Set assessment.", "give a leg", "name it as a candidate", "gain stops"):
        assert phrase not in text, phrase
    assert not re.search(r"\b1 (legs|cells|variants|combinations)\b", text)
    rig = flat(chapter(default[0], "Rigging"))
    assert "converged" in rig and "evaluations" in rig


def test_workability_table_has_the_winch_column_and_adds_up(default):
    text, data, cx = default
    ch = chapter(text, "Workability")
    assert "winch saturates" in ch
    work, sea = data["workability"], data["sea_states"]
    # the winch share of the baseline with the reference tugger, counted independently
    sel = dict(candidate="baseline", tugger="reference")
    util = on_sea_grid(work["utilisation"].sel(sel), sea)
    winch = ((on_sea_grid(work["verdict_source"].sel(sel), sea) == SATURATED_FAIL)
             & (util <= 1).all("criterion") & (sea["cell_probability"] > 0))
    share = float(((sea["cell_probability"] * winch).sum(("heading", "hs", "tz")) * sea["leg_weight"]).sum())
    assert share > 0
    rows = re.findall(r"(?m)^route ((?:\d+\.\d % ?)+)$", ch)
    assert len(rows) == len(cx.dg.table.combos)
    for row in rows:
        w, fails, *split, steep = (float(x) for x in row.replace("%", " ").split())
        assert abs(w + fails - 100.0) <= 0.11 and abs(sum(split) - fails) <= 0.05 * (len(split) + 1)
    assert f"{100 * share:.1f} %" in ch


def test_rigging_chapter_has_no_duplicate_of_table_1_and_lists_every_option(default):
    text, _, cx = default
    rig = flat(chapter(text, "Rigging"))
    assert "Workability per leg and for the route, baseline and optimised rigging" not in rig
    window = rig[rig.index("Workable Tz window"):]
    for c, tg in cx.dg.table.combos:
        assert f"{c} / {tg} " in window, (c, tg)


def test_recommendation_keeps_its_budget_and_the_rigging_chapter_prices_margin(default):
    # Issue 20, item 1: the recommendation has its tolerance budget to spare, not zero, and
    # the rigging chapter's margin table is screening.nc's sweep of the recommended family.
    text, data, cx = default
    cand, tug = cx.dg.best
    budget = float(data["plant"].attrs["splash_clearance_budget_m"])
    assert budget > 0
    assert float(data["plant"]["splash_clearance_margin"].sel(candidate=cand)) >= budget - 0.01
    page1 = flat(chapter(text, "Summary"))
    assert "splash clearance 0.00 m" not in page1 and "no room for fabrication" not in page1
    rig = flat(chapter(text, "Rigging"))
    assert "What margin costs." in rig
    s = cx.screening
    w = 100 * s["margin_route_workability"].sel(margin_family=cand, tugger=tug)
    for m, x in zip(s["splash_margin"].values, w.values):
        assert f" {num(m)} " in rig and f" {num(x)} " in rig, (m, x)
    j = int(np.argmin(np.abs(s["splash_margin"].values - budget)))
    assert (f"keeping the {num(budget)} m tolerance budget costs {num(float(w[0] - w[j]))} percentage "
            "points") in rig


def test_time_domain_cells_include_the_recommendation(default):
    # Issue 20, item 3: the recommended rigging's boundary cells ran in the time domain
    # beside the baseline's, and their verdicts are in the workability.
    _, data, cx = default
    cand = cx.dg.best[0]
    ran = {str(d.attrs["candidate"]) for d in cx.td}
    assert {cand, "baseline"} <= ran
    mine = [c for c in cx.td_cells if c["candidate"] == cand]
    assert mine and all(any("boundary" in r for r in c["reasons"]) for c in mine)
    src = data["workability"]["verdict_source"].sel(candidate=cand)
    assert int((src == TIME_DOMAIN).sum()) + int(data["workability"]["timedomain_marginal"]
                                                   .sel(candidate=cand).sum()) > 0


def test_recommended_operability_ceiling_and_colours(default, monkeypatch, tmp_path):
    _, _, cx = default
    figs = captured(monkeypatch, rigging_compare)
    rigging_compare.recommended_operability(cx.work, cx.sea, cx.dg.best,
                                            float(cx.screening.attrs["design_hs_m"]), tmp_path)
    ax = figs[0].axes[0]
    ceiling = next(ln for ln in ax.get_lines() if ln.get_label() == "steepness ceiling")
    assert np.nanmax(ceiling.get_ydata()) > ax.get_ylim()[1]
    assert np.sum(np.isclose(ceiling.get_ydata(), ax.get_ylim()[1])) <= 1       # no plateau
    colours = {tuple(np.round(c, 3)) for coll in ax.collections if len(coll.get_offsets())
               for c in coll.get_facecolors()[:, :3]}
    assert len(colours) >= 2                                                    # passes and fails


def test_tugger_chapter_items(default, monkeypatch, tmp_path):
    text, _, cx = default
    ch = flat(chapter(text, "Damping tuggers"))
    # winch capacity per line, from the time-domain cells
    assert "capacity per line [kN]" in ch
    for tg in ("low", "high"):
        cap = float(cx.td[0]["max_force"].sel(tugger=tg))
        assert re.search(rf"{tg} \d[\d ]* {re.escape(num(cap, 0))} ", ch)
    # the time-domain cell named in words, not by its file name
    a = cx.td[0].attrs
    assert f"{a['candidate']} rigging, heading {float(a['heading_deg']):g}°, Hs {float(a['hs_m']):g} m" in ch
    assert str(a["cell"]) not in ch
    # the critical damping is the dataset's
    crit = float(cx.studies.attrs["critical_slope_kN_s_per_m"])
    assert f"critical damping of this plant's sway mode is {num(crit, 0)} kN s/m" in ch
    last = float(cx.studies["slope"].values[-1])
    if abs(last - crit) > 0.005 * crit:
        assert f"The sweep's last slope, {num(last, 0)} kN s/m, is" in ch and "not this plant's" in ch
    mpm = cx.studies["sweep_mpm"].values
    if (np.diff(mpm, axis=-1) < 0).all() or (np.diff(mpm, axis=0) < 0).all():
        assert "does not stop within the sweep" in ch
    # four cases: the tugger page 1 excludes least, and what page 1 says of each
    cases = dict(tuggers.four_cases(cx))
    tug = cases["tugger only"][1]

    def hard(tg):
        return sum(tuggers.hard_exclusion(cx.dg.excluded[ct]) for ct in
                   ((cx.dg.baseline, tg), (cases["rigging changed"][0], tg)) if ct in cx.dg.excluded)
    active = [tg for tg in cx.dg.tuggers if cx.c_tugger(tg) > 0]
    assert hard(tug) == min(hard(tg) for tg in active)
    assert "page 1" in ch and "recommended" in ch
    figs = captured(monkeypatch, tuggers)
    tuggers.four_cases_figure(cx, tmp_path)
    ax = figs[0].axes[0]
    ceiling = cx.work["steepness_limit_curve"].values
    lines = [cx.work["hs_limit_curve"].min("heading").sel(candidate=c, tugger=g).values
             for c, g in cases.values()]
    assert ax.get_ylim()[1] == pytest.approx(operability_top([(y, ceiling) for y in lines]))
    assert ax.get_ylim()[1] < 10.0 < np.nanmax(ceiling)               # not the ceiling's 20 m


def test_plant_chapter_prints_the_jacket_and_defines_the_candidates(default):
    text, data, _ = default
    ch = flat(chapter(text, "Plant"))
    p = data["plant"]
    M = p["M"].sel(candidate="baseline")
    assert f"Gravitational (dry) mass {num(p.attrs['m_grav_t'], 0)} t" in ch
    assert f"inertial mass {num(M.sel(dof='sway', dof_col='sway'), 0)} t" in ch
    assert f"roll inertia {num(M.sel(dof='roll', dof_col='roll') / 1e6, 3)} × 10⁶ t m²" in ch
    assert "A detuned rigging is one whose sway natural period" in ch
    assert "detuned: a candidate of the configuration" in ch
    sea = flat(chapter(text, "Sea states"))
    assert "The wave-steepness rule." in sea and "1/15" in sea


def test_assumptions_list_what_was_not_assessed_and_what_to_verify(default):
    text, data, cx = default
    ch = flat(chapter(text, "Assumptions and validity"))
    nums = headings(text)
    assert "dynamic tensions, DAF and slack margin (section " + str(nums["Wire loads"]) + ") are assessed" in ch
    assert "dynamic tensions and lift-point capacities are not assessed" not in ch
    for item in ("Wind:", "The block connection system:", "Winch speed and power against a rating:",
                 "Lift-point capacity:", "Fairlead feasibility:"):
        assert item in ch, item
    rig = cx.dg.best[0]
    period = float(data["plant"]["natural_period"].sel(candidate=rig).isel(mode=0))
    f = np.asarray(data["workability"].attrs["sway_frequency_factors"], float)
    assert (f"the sway period within ±{num(100 * np.max(np.abs(f - 1)), 0)} % of the assessed "
            f"{num(period, 2)} s ({num(period / f.max(), 2)}-{num(period / f.min(), 2)} s)") in ch
    tip = float(data["plant"].attrs["splash_clearance_m"]) + float(
        data["plant"]["splash_clearance_margin"].sel(candidate=rig))
    assert f"Tip height after pay-out: the jacket's lowest point measured at least {num(tip, 2)} m" in ch
    assert "Draught and trim" in ch and "Sway monitoring" in ch and "action levels" in ch


def test_page_one_says_why_the_highest_workability_is_not_the_recommendation(default):
    """The combination of the highest route workability, where the recommendation is
    another, is named on page 1 and, in the chapter after it, with its actual reason: on the shipped route a tugger setting the
    winch rule excludes, on a feasible rigging, so never "not feasible"."""
    text, _, cx = default
    dg = cx.dg
    page1 = flat(chapter(text, "Summary"))
    detail = flat(chapter(text, "Assessment in detail"))          # page 1 in short, then in full
    assert dg.best_any != dg.best and cx.feasible(dg.best_any[0]) and dg.best_any in dg.excluded
    assert "which a rule excludes" in page1
    assert "which the recommendation passes over" in detail
    assert "but that rigging candidate is not feasible" not in page1 + detail


def test_issue_34_contract_on_the_default_route(default):
    # workability.nc holds the wire-tension criterion; no two options share a rigging
    # geometry within 1 cm; dataset file names and configuration keys appear only in the
    # provenance chapter and the appendix (at most 3 pages, never page 1).
    from test_report_cleanliness import names_outside

    from jls.plant import same_rigging
    text, data, cx = default
    work = data["workability"]
    assert "wire_tension" in [str(c) for c in work["criterion"].values]
    assert "dynamic_amplification" in work and "daf_limit" in work.attrs
    x = same_rigging.geometry_matrix(data["plant"], work["candidate"].values)
    d = np.abs(x[:, None, :] - x[None, :, :]).max(axis=-1)
    assert (d[~np.eye(len(x), dtype=bool)] > 0.01).all()
    assert "optimised" in str(work["candidate_names"].values) or "optimised" in work["candidate"].values
    # the chapters split the text, whatever the pages: the whole text as one page
    assert names_outside([text]) == {}
    appendix = text[text.index("Appendix: every heading"):]
    assert len(re.findall(r"\d+ / \d+", appendix)) <= 3        # page footers: at most 3 pages
    study = flat(chapter(text, "The reference study beside this assessment"))
    assert "+0.53" in study and "15.700" in study
