"""The PDF assessment report rendered from small synthetic datasets (tests/report_fixtures.py)."""

from __future__ import annotations

import os
import re

import numpy as np
import pypdf
import pytest
import report_fixtures as rf
import xarray as xr

from jls.errors import InputError
from jls.io.netcdf import merge_complex, split_complex
from jls.report import document
from jls.report.contract import check, digest
from jls.report.document import ReportError, render_report
from jls.report.markup import cell, t, table

HEADINGS = ["Summary", "Assessment in detail", "Operational basis", "Inputs and provenance", "Plant", "Vessel and hinge motion",
            "Sea states", "Wave spectra", "Operability", "Workability", "Damping tuggers",
            "The reference study beside this assessment", "Wire loads",
            "Weather windows", "Voyage extremes", "Uncertainty and sensitivity",
            "Verification against a nonlinear reference",
            "Assumptions and validity"]


@pytest.fixture(scope="module")
def data():
    return rf.datasets()


@pytest.fixture(scope="module")
def rendered(data, tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "test_route.pdf"
    path = render_report(out, route="test_route", provenance=rf.provenance(), voyage=rf.voyage(data),
                         **data)
    reader = pypdf.PdfReader(path)
    text = "\n".join(page.extract_text() for page in reader.pages)
    text = text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", "")
    return path, reader, text


def section(text, name):
    """Text of one numbered section (from its heading to the next)."""
    k = HEADINGS.index(name)
    start = re.search(rf"^{k + 1}\. {name}$", text, re.M).end()
    if k + 1 == len(HEADINGS):
        return text[start:]
    return text[start:re.search(rf"^{k + 2}\. {HEADINGS[k + 1]}$", text, re.M).start()]


def page_one_and_detail(text):
    """Page 1's summary and the chapter "Assessment in detail" that states it in full."""
    return section(text, "Summary") + "\n" + section(text, "Assessment in detail")


def test_pdf_is_a4_and_has_every_section_in_order(rendered):
    path, reader, text = rendered
    assert path.exists() and path.stat().st_size > 10_000
    w, h = (float(x) for x in reader.pages[0].mediabox[2:])
    assert (round(w), round(h)) == (595, 842)
    positions = []
    for k, name in enumerate(HEADINGS):
        m = re.search(rf"^{k + 1}\. {name}$", text, re.M)
        assert m, f"heading {name!r} missing"
        positions.append(m.start())
    assert positions == sorted(positions)


def test_headline_numbers_equal_workability_dataset(rendered, data):
    text = page_one_and_detail(rendered[2])
    wr = data["workability"]["workability_route"]
    base = 100 * float(wr.sel(candidate="baseline", tugger="none"))
    m = re.search(r"Route workability, baseline rigging, no tugger\s+(\d+\.\d) %", text)
    assert m and m.group(1) == f"{base:.1f}"
    # the best combination is the recommendation (exclusion rules applied), no better
    # than the best feasible combination
    from jls.assessment.recommendation import recommend
    cands = [str(c) for c in wr["candidate"].values]
    tugs = [str(t) for t in wr["tugger"].values]
    c_tug = {t: float(data["response"]["c_tugger"].sel(tugger=t)) for t in tugs}
    (bc, bt), _, _ = recommend({"plant": data["plant"], "response": data["response"],
                                "workability": data["workability"], "sea_states": data["sea_states"]},
                               cands, tugs, c_tug)
    best = float(wr.sel(candidate=bc, tugger=bt))
    feasible = data["plant"]["feasible"].astype(bool)
    assert best <= float(wr.where(feasible).max())
    m = re.search(r"Route workability, best combination\s+(\d+\.\d) %", text)
    assert m and m.group(1) == f"{100 * best:.1f}"
    # the summary table carries every candidate x tugger, legs and route
    for c in wr["candidate"].values:
        for tg in wr["tugger"].values:
            assert f"{100 * float(wr.sel(candidate=c, tugger=tg)):.1f} %" in text
            for leg in data["sea_states"]["leg"].values:
                w = data["workability"]["workability_leg"].sel(candidate=c, tugger=tg, leg=leg)
                assert f"{100 * float(w):.1f} %" in text
    assert "Governing criterion: relative sway" in text


def test_provenance_hashes_and_vessel_source_appear(rendered):
    text = section(rendered[2], "Inputs and provenance")
    prov = rf.provenance()
    assert prov["config_sha256"] in text
    for item in prov["inputs"].values():
        assert item["sha256"] in text
    assert "synthetic_beam_sea.nc" in text
    assert "representative" in text.lower()
    assert rf.OUTSIDE_REASON in " ".join(text.split())
    for name, version in prov["packages"].items():
        assert name in text and version in text


def test_plant_sea_operability_and_validity_content(rendered, data):
    text = rendered[2]
    plant = section(text, "Plant")
    for c in ("baseline", "detuned"):
        t1 = float(data["plant"]["natural_period"].sel(candidate=c).isel(mode=0))
        assert f"{t1:.3f}" in plant
    assert "19 534" in plant                                   # baseline forward wire tension
    sea = section(text, "Sea states")
    for leg in ("north_sea", "biscay"):
        steep = float(data["sea_states"]["steep_probability"].sel(leg=leg))
        assert f"{100 * steep:.1f} %" in sea
    oper = section(text, "Operability")
    assert "steepness ceiling" in oper and "relative sway" in oper
    valid = section(text, "Assumptions and validity")
    for phrase in ("Linear frequency-domain model", "Rayleigh", "without winch limits",
                   "Not assessed", "no structural check", "Verify before sailing", "in air",
                   "16.8 %", "33.4 %", "centre"):
        assert phrase in valid


def test_linear_range_flags_match_an_independent_count(rendered, data):
    sea, resp, work = data["sea_states"], data["response"], data["workability"]
    dg = digest("test_route", sea, data["vessel_motion"], data["plant"], resp, work, rf.provenance())
    unit = resp["mpm"].sel(candidate="baseline", tugger="none", heading=90.0).sel(tz=sea["tz"])
    hs = sea["hs"].broadcast_like(sea["hs_upper"])
    big = ((hs * unit.sel(response="relative_sway") > 6.0)
           | (hs * unit.sel(response="relative_yaw") > 5.0)
           | (hs * unit.sel(response="relative_roll") > 5.0))
    live = sea["probability"] > 0
    lin = dg.linear[("baseline", "none")]
    assert lin["cells"] == int((big & live).sum()) > 0
    prob = float(((sea["probability"] * (big & live)).sum(("hs", "tz")) * sea["leg_weight"]).sum())
    assert lin["route_probability"] == pytest.approx(prob)
    valid = section(rendered[2], "Assumptions and validity")
    assert f"{lin['cells']} cells carrying {100 * prob:.1f} %" in valid


def test_missing_variable_is_a_clear_error_and_leaves_no_pdf(data, tmp_path):
    broken = dict(data, workability=data["workability"].drop_vars("hs_limit"))
    out = tmp_path / "report.pdf"
    with pytest.raises(InputError, match=r"workability: missing variable\(s\) hs_limit"):
        render_report(out, route="r", provenance=rf.provenance(), **broken)
    assert list(tmp_path.iterdir()) == []


def test_wrong_dimensions_are_named(data):
    work = data["workability"].copy()
    work["workability_route"] = work["workability_route"].expand_dims(extra=[0])
    with pytest.raises(InputError, match="workability: wrong dimensions workability_route"):
        check(dict(data, workability=work))


def test_typesetting_failure_is_a_report_error_without_partial_file(data, tmp_path, monkeypatch):
    from jls.report import operability, plant, sea_states, vessel, workability
    monkeypatch.setattr(plant, "rigging", lambda *a, **k: tmp_path / "rigging.svg")
    for module, name in ((vessel, "hinge_raos"), (vessel, "relative_transfer"),
                         (operability, "operability"), (workability, "workability_bars"),
                         (sea_states, "scatter")):
        monkeypatch.setattr(module, name, lambda *a, **k: tmp_path / "x.svg")
    monkeypatch.setattr(document, "source", lambda cx: "#let x = (\n")
    out = tmp_path / "sub" / "report.pdf"
    with pytest.raises(ReportError, match="typesetting the report failed"):
        render_report(out, route="r", provenance=rf.provenance(), **data)
    assert list((tmp_path / "sub").iterdir()) == []


def test_provenance_must_carry_the_config_hash(data, tmp_path):
    prov = rf.provenance()
    del prov["config_sha256"]
    with pytest.raises(InputError, match="provenance lacks config_sha256"):
        render_report(tmp_path / "r.pdf", route="r", provenance=prov, **data)


def test_complex_variables_whole_or_split(data):
    whole = {k: merge_complex(v) for k, v in data.items()}
    split = {k: split_complex(v) for k, v in data.items()}
    assert "rao_re" in split["vessel_motion"] and "rao" in whole["vessel_motion"]
    check(whole)                                     # no error either way
    check(split)


def test_fixture_is_self_consistent(data):
    sea, work = data["sea_states"], data["workability"]
    np.testing.assert_allclose(sea["probability"].sum(("hs", "tz")), 1.0)
    passes = work["passes"].sel(tz=sea["tz"]).fillna(0) > 0.5
    leg = (sea["probability"] * sea["heading_probability"] * passes).sum(("heading", "hs", "tz"))
    xr.testing.assert_allclose(leg.transpose(*work["workability_leg"].dims), work["workability_leg"])
    assert 0.5 < float(work["workability_route"].min()) < float(work["workability_route"].max()) < 1.0
    assert bool(data["plant"]["feasible"].all())


def test_markup_escapes_data_text():
    assert t("a_b #c *d* $e$ [f] <g> @h") == r"a\_b \#c \*d\* \$e\$ \[f\] \<g\> \@h"
    assert t("x_y=1", wrap=True) == "x\\_\u200by\\=\u200b1"
    src = table("cap_tion", ["a", cell("*b*", raw=True)], [["1_2", cell("z")]])
    assert "cap\\_tion" in src and "[1\\_\u200b2]" in src and "[*b*]" in src


def test_report_is_readable_like_other_outputs(rendered):
    mask = os.umask(0)
    os.umask(mask)
    assert rendered[0].stat().st_mode & 0o777 == 0o666 & ~mask


# -- what is shown, ties, limits, round-off ---------------------------------------------
def pdf_text(path_or_stream):
    reader = pypdf.PdfReader(path_or_stream)
    text = "\n".join(page.extract_text() for page in reader.pages)
    return text.replace("\xa0", " ").replace("\u2009", " ").replace("\u200b", "")


@pytest.fixture(scope="module")
def data_3x4():
    return rf.datasets(candidates={**rf.CANDIDATES, "narrow": {"top_spread_y": 42.0, "drop_height": 63.0}},
                       tuggers={"none": 0.0, "low": 500.0, "reference": 1000.0, "high": 2000.0})


def test_every_combination_of_3_candidates_and_4_tuggers_is_reported(data_3x4, tmp_path):
    out = render_report(tmp_path / "r.pdf", route="r", provenance=rf.provenance(), **data_3x4)
    text = pdf_text(out)
    work = section(text, "Workability")
    # one route row per combination in the breakdown table, all 12 in the dot plot
    assert len(re.findall(r"^route \d+\.\d %", work, re.M)) == 12
    assert "All 12 combinations are shown." in work
    oper = section(text, "Operability")
    assert "All 12 combinations are shown." in oper
    assert "part 1 of 2" in oper and "part 2 of 2" in oper      # the limiting-Hs table, split
    valid = section(text, "Assumptions and validity")
    dg = digest("r", *(data_3x4[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                              "workability")), rf.provenance())
    assert len(dg.linear) == 12
    live = dg.linear[("baseline", "none")]["live_cells"]
    assert valid.count(f" of {live}") == 12                      # one row per combination


def test_a_figure_that_cannot_show_everything_states_its_selection():
    from jls.report.choices import plot_selection
    cands = ["baseline"] + [f"c{i}" for i in range(8)]
    tugs = ["none", "a", "b", "c", "d"]
    wr = xr.DataArray(np.linspace(0.5, 0.9, len(cands) * len(tugs)).reshape(len(cands), len(tugs)),
                      dims=("candidate", "tugger"), coords={"candidate": cands, "tugger": tugs})
    sel = plot_selection(xr.Dataset({"workability_route": wr}), cands, tugs, "baseline", "none",
                         ("c7", "d"), n_headings=1)
    assert len(sel.candidates) == 6 and len(sel.tuggers) == 4
    assert "baseline" in sel.candidates and "c7" in sel.candidates      # baseline and best
    assert "none" in sel.tuggers and "d" in sel.tuggers
    assert sel.caption().startswith(f"Shown: 24 of {len(cands) * len(tugs)} combinations")
    assert "highest route workability" in sel.caption()


DOCUMENT = {"number": "JLS-RPT-0042", "revision": "C", "prepared": "A. Preparer",
            "checked": "B. Checker", "approved": "C. Approver", "client": "Client Ltd",
            "project": "Transit 7", "title": "Transit rigging assessment"}


@pytest.fixture(scope="module")
def tied(data, tmp_path_factory):
    """Datasets where the two passive combinations share the top route workability and the
    tugger settings add nothing to it, rendered with a document-control section and a known
    commit."""
    work = data["workability"].copy(deep=True)
    for c, tg in (("baseline", "none"), ("baseline", "reference"), ("detuned", "none"),
                  ("detuned", "reference")):
        work["workability_route"].loc[dict(candidate=c, tugger=tg)] = 0.95
    tied = dict(data, workability=work)
    prov = dict(rf.provenance(), document=DOCUMENT, git_commit="f" * 40)
    out = render_report(tmp_path_factory.mktemp("tied") / "r.pdf", route="r", provenance=prov, **tied)
    return tied, pypdf.PdfReader(out)


def test_a_tie_for_best_is_disclosed_with_its_rule(tied):
    data, reader = tied
    dg = digest("r", *(data[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                         "workability")), rf.provenance())
    # the tuggers add nothing over the best passive option: excluded; of the two passive
    # riggings the larger smallest margin wins (the detuned rigging sits on its splash
    # clearance, the baseline has metres to spare)
    assert ("baseline", "reference") in dg.excluded and ("detuned", "reference") in dg.excluded
    assert dg.margins["baseline"] > dg.margins["detuned"]
    assert dg.best == ("baseline", "none")
    assert dg.ties == [("detuned", "none")]
    text = " ".join(page_one_and_detail(pdf_text(reader.stream)).split())
    assert "best combination 95.0 %" in text
    assert "tied with 1 other" in text
    assert "Tie. detuned rigging, tugger none reaches the same route workability" in text
    assert "the larger smallest safety margin first" in text and "then fewer changes" in text
    assert "a tugger only where it adds more than 1.0 percentage points" in text


def test_tie_break_prefers_the_bare_baseline_at_equal_margins():
    from jls.assessment.recommendation import best_with_ties
    cands, tugs = ["baseline", "alt"], ["none", "t"]
    wr = xr.DataArray([[0.9, 0.9], [0.9, 0.8]], dims=("candidate", "tugger"),
                      coords={"candidate": cands, "tugger": tugs})
    combos = [(c, t) for c in cands for t in tugs]
    work = xr.Dataset({"workability_route": wr}, attrs={"tie_tolerance": 1e-9})
    best, ties = best_with_ties(work, combos, "baseline", {"none": 0.0, "t": 500.0},
                                {"baseline": 0.3, "alt": 0.3})
    assert best == ("baseline", "none")         # no active component
    assert ties == [("alt", "none"), ("baseline", "t")]   # one each: the lower slope first


def test_a_margin_on_its_budget_is_flagged_at_limit(rendered, data):
    assert float(data["plant"]["splash_clearance_margin"].sel(candidate="detuned")) == pytest.approx(0.75, abs=1e-9)
    # the page furniture (running header and footer) left out: a sentence may break over a page
    body = "\n".join(line for line in section(rendered[2], "Plant").splitlines()
                     if not line.startswith(("Document number not assigned rev.", "Rigging assessment, route")))
    plant = " ".join(body.split())
    assert "yes, at limit: splash clearance margin" in plant
    assert "0.75 m, its whole tolerance budget" in plant
    assert "lengths 0.01 m" in plant                              # the resolution, stated
    assert "inside its tolerance budget (splash clearance 0.75 m, lead angles 0.50°) is infeasible" in plant
    assert ("splash clearance 0.75 m (wire length and creep 0.30 m, hinge height 0.10 m, draught and "
            "trim change 0.30 m, tip fabrication 0.05 m)") in plant          # the budget's components
    summary = page_one_and_detail(rendered[2])
    assert re.search(r"^detuned none 0 at limit", summary, re.M)
    assert re.search(r"^baseline none 0 yes", summary, re.M)


def test_at_limit_and_infeasible_reason_from_the_plant_dataset_are_used(data):
    from jls.report.contract import constraint_flags
    plant = data["plant"].copy()
    plant["at_limit"] = ("candidate", np.array(["side lead angle", ""], dtype=object))
    plant["infeasible_reason"] = ("candidate", np.array(["", "drop height above its bound"], dtype=object))
    plant["feasible"] = ("candidate", np.array([1, 0], np.int8))
    at, why = constraint_flags(plant)
    assert at == {"baseline": "side lead angle", "detuned": ""}
    assert why == {"baseline": "", "detuned": "drop height above its bound"}


def test_round_off_motion_is_no_motion(rendered, data):
    hinge_yaw = np.abs(merge_complex(data["vessel_motion"])["hinge"].sel(dof="yaw")).max()
    assert 0 < float(hinge_yaw) < 1e-15                        # the fixture's round-off
    vessel = " ".join(section(rendered[2], "Vessel and hinge motion").split())
    assert "hinge yaw no yaw motion at this heading" in vessel
    assert not re.search(r"e-1[0-9] deg/m", vessel)


def test_negligible_is_relative_to_the_scale():
    from jls.report.contract import ROUNDOFF_RELATIVE, negligible
    assert negligible([1e-17, -3e-17], 0.05)
    assert negligible([0.0], 0.0)
    assert not negligible([1e-6], 0.05)
    assert not negligible([0.1 * ROUNDOFF_RELATIVE], 1e-11)    # small, but not against its scale


def test_paths_do_not_hyphenate_and_break_after_slashes():
    from jls.report.markup import path
    p = path("config/vessel/representative_hlv.nc")
    assert p.startswith("#text(hyphenate: false)[") and p.count("/\u200b") == 2


def test_input_table_keeps_path_and_checksum_apart(rendered):
    text = section(rendered[2], "Inputs and provenance")
    prov = rf.provenance()
    # each checksum whole, on the line under its path; the path never hyphenated
    for name, item in prov["inputs"].items():
        assert re.search(rf"^{name} {re.escape(item['path'])}\n{item['sha256']}$", text, re.M), name
    assert "synthe-" not in text and "represen-" not in text


def test_workability_axis_starts_where_the_values_do(rendered, data):
    from jls.report.style import percent_axis_start
    work = data["workability"]
    combos = [(c, tg) for c in ("baseline", "detuned") for tg in ("none", "reference")]
    start = percent_axis_start(work, combos)
    low = 100 * float(work["workability_leg"].min())
    assert 0 < start <= low - 1.0 and start % 5 == 0
    assert start > low - 10
    text = " ".join(section(rendered[2], "Workability").split())
    assert f"The axis starts at {start:g} %" in text
    # the README's default-route values (93-98.5 %) get an axis from 90 %
    wr = xr.DataArray([[0.948, 0.985]], dims=("candidate", "tugger"),
                      coords={"candidate": ["b"], "tugger": ["n", "t"]})
    wl = xr.DataArray([[[0.93, 0.958], [0.983, 0.986]]], dims=("candidate", "tugger", "leg"),
                      coords={"candidate": ["b"], "tugger": ["n", "t"], "leg": ["a", "c"]})
    assert percent_axis_start(xr.Dataset({"workability_route": wr, "workability_leg": wl}),
                              [("b", "n"), ("b", "t")]) == 90.0


def test_operability_range_shows_the_curves_not_the_ceiling(data):
    from jls.report.operability import operability_top
    work = data["workability"]
    curve = work["hs_limit_curve"].sel(candidate="baseline", heading=90.0)
    ceiling = work["steepness_limit_curve"].values
    top = operability_top([(curve.sel(tugger=tg).values, ceiling) for tg in ("none", "reference")])
    governed = curve.where(curve < 0.999 * ceiling).max()
    assert float(governed) < top <= 1.2 * float(governed)
    assert top < 0.5 * float(np.nanmax(ceiling))               # the ceiling is clipped


# -- document control, configuration check, reproducibility ---------------------------
def test_document_control_on_page_one_and_in_the_footer(tied):
    reader = tied[1]
    page1 = reader.pages[0].extract_text().replace("\xa0", " ")
    for item in ("Transit rigging assessment", "JLS-RPT-0042", "A. Preparer", "B. Checker",
                 "C. Approver", "Client Ltd", "Transit 7", "f" * 40, "jls version"):
        assert item in page1, item
    assert re.search(r"revision\s+C", page1)
    for page in reader.pages:
        assert "JLS-RPT-0042 rev. C · jls 0.1.0 · commit ffffffffffff" in page.extract_text().replace("\xa0", " ")


def test_source_commit_of_a_checkout_and_of_a_plain_directory(tmp_path):
    import subprocess

    from jls.report import control
    (tmp_path / "jls").mkdir()
    assert control.source_commit(tmp_path / "jls") == control.NOT_GIT
    import jls
    head = subprocess.run(["git", "-C", os.path.dirname(jls.__file__), "rev-parse", "HEAD"],
                          capture_output=True, text=True)
    if head.returncode != 0:
        pytest.skip("jls is not running from a git checkout")
    assert control.source_commit().split(" ")[0] == head.stdout.strip()


def test_document_section_is_validated():
    from jls.config.loader import load_yaml, validate
    cfg = load_yaml(rf.ROOT / "config" / "config.yaml")
    validate(dict(cfg, document={"number": "X-1", "revision": 0, "prepared": "A"}))
    with pytest.raises(InputError, match="document"):
        validate(dict(cfg, document={"numbr": "X-1"}))


def _with_hashes(data, hashes):
    out = {}
    for name, ds in data.items():
        ds = ds.copy()
        ds.attrs = dict(ds.attrs, config_sha256=hashes[name])
        out[name] = ds
    return out


def test_config_mismatch_is_judged_per_dataset(data):
    per = dict(rf.SECTION_HASHES)
    stale = _with_hashes(data, dict(per, plant="0" * 64))
    prov = dict(rf.provenance(), config_sha256_datasets=per)     # whole-config hash differs from all
    dg = digest("r", *(stale[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                          "workability")), prov)
    assert dg.hash_mismatch == ["plant (000000000000)"]
    assert dg.same_config == {"sea_states": True, "vessel_motion": True, "plant": False,
                              "response": True, "workability": True}
    fresh = _with_hashes(data, per)
    dg = digest("r", *(fresh[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                          "workability")), prov)
    assert dg.hash_mismatch == []


def test_config_mismatch_falls_back_to_the_whole_configuration(data):
    mixed = _with_hashes(data, dict({k: rf.CONFIG_SHA for k in data}, response="1" * 64))
    dg = digest("r", *(mixed[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                          "workability")), rf.provenance())
    assert dg.hash_mismatch == ["response (111111111111)"]
    assert dg.hash_basis == "the whole configuration"


def test_source_date_epoch_makes_the_pdf_reproducible(data, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")        # 2023-11-14T22:13:20Z
    a = render_report(tmp_path / "a.pdf", route="r", provenance=dict(
        rf.provenance(), created="2026-01-01T00:00:00+00:00"), **data)
    b = render_report(tmp_path / "b.pdf", route="r", provenance=dict(
        rf.provenance(), created="2026-06-30T12:00:00+00:00"), **data)
    assert a.read_bytes() == b.read_bytes()
    reader = pypdf.PdfReader(a)
    assert "2023-11-14T22:13:20+00:00" in reader.pages[0].extract_text()
    assert str(reader.metadata.get("/CreationDate", "")).startswith("D:20231114221320")


def test_a_malformed_source_date_epoch_is_named(monkeypatch):
    from jls.report import control
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "yesterday")
    with pytest.raises(InputError, match="SOURCE_DATE_EPOCH"):
        control.created(rf.provenance())
    monkeypatch.delenv("SOURCE_DATE_EPOCH")
    assert control.created(rf.provenance()) == rf.provenance()["created"]


def test_fixture_statistics_and_workability_are_the_librarys(data):
    from jls.assessment.workability import assess
    from jls.response.statistics import unit_statistics
    resp = merge_complex(data["response"])
    H = resp["transfer"].rename(shown_candidate="candidate").transpose(
        "candidate", "tugger", "heading", "response", "omega")
    stats = unit_statistics(resp["omega"].values, H.values, resp["tz"].values, resp.attrs["gamma"],
                            3600 * resp.attrs["exposure_h"], "response")
    mpm = resp["mpm"].sel(candidate=H["candidate"]).transpose(
        "candidate", "tugger", "heading", "response", "tz").values
    np.testing.assert_allclose(stats["mpm"], mpm, rtol=1e-9)
    work = assess(resp, data["sea_states"], rf.CRITERIA, curve=resp)
    xr.testing.assert_allclose(work["workability_route"], data["workability"]["workability_route"])


@pytest.mark.slow
def test_long_tables_of_many_combinations_continue_on_the_next_page(tmp_path):
    cands = {**rf.CANDIDATES, **{f"c{i}": {"top_spread_y": 38.0 + 2 * i, "drop_height": 58.0 + i}
                                 for i in range(6)}}
    tugs = {"none": 0.0, "a": 250.0, "b": 500.0, "reference": 1000.0, "high": 2000.0}
    out = render_report(tmp_path / "r.pdf", route="r", provenance=rf.provenance(),
                        **rf.datasets(candidates=cands, tuggers=tugs))
    for page in pypdf.PdfReader(out).pages:
        placed = []
        page.extract_text(visitor_text=lambda text, cm, tm, *_: placed.append((tm[5] * cm[3] + cm[5], text))
                          if text.strip() else None)
        footer = min(y for y, text in placed if re.search(r"\d+ / \d+", text))
        body = [y for y, text in placed if y > footer + 1e-6 or y < footer - 1e-6]
        assert min(body) > footer + 10.0      # no table row runs into or past the footer


def test_many_candidates_tables_list_a_stated_selection():
    """Per-combination tables stay readable (and the report fast) with a grid of candidates:
    they list a stated selection, always with the baseline and the recommendation."""
    from jls.report.choices import MAX_TABLE_COMBOS, table_selection
    cands = ["baseline"] + [f"c{i}" for i in range(40)]
    tugs = ["none", "reference"]
    wr = xr.DataArray(np.linspace(0.5, 0.99, len(cands) * 2).reshape(len(cands), 2),
                      dims=("candidate", "tugger"), coords={"candidate": cands, "tugger": tugs})
    combos = [(c, t) for c in cands for t in tugs]
    sel = table_selection(xr.Dataset({"workability_route": wr}), combos, "baseline", ("c3", "none"), [])
    assert len(sel.combos) == MAX_TABLE_COMBOS and sel.total == len(combos)
    assert {("baseline", "none"), ("baseline", "reference"), ("c3", "none"), ("c39", "reference")} <= set(sel.combos)
    assert "Listed: 24 of 82 combinations" in sel.table_caption()
    small = table_selection(xr.Dataset({"workability_route": wr}), combos[:10], "baseline", combos[0], [])
    assert small.rule is None and small.table_caption() == ""


def _many_options():
    """Datasets and digest of more combinations than a table holds (8 riggings x 5 tuggers)."""
    cands = {**rf.CANDIDATES, **{f"c{i}": {"top_spread_y": 38.0 + 2 * i, "drop_height": 58.0 + i}
                                 for i in range(6)}}
    tugs = {"none": 0.0, "a": 250.0, "b": 500.0, "reference": 1000.0, "high": 2000.0}
    data = rf.datasets(candidates=cands, tuggers=tugs)
    return data, digest("r", *(data[k] for k in ("sea_states", "vessel_motion", "plant", "response",
                                                  "workability")), rf.provenance())


def test_table_1_lists_the_recommendation_however_many_options_rank_above_it():
    """With more combinations than a table holds, table 1 lists the digest's table
    selection: the baseline, the recommendation and its ties, then the highest route
    workability, so the recommended row is there even when excluded options outrank it."""
    from dataclasses import replace

    from jls.report.choices import MAX_TABLE_COMBOS, table_selection
    from jls.report.context import Context
    from jls.report.summary import workability_table
    data, dg = _many_options()
    wr = data["workability"]["workability_route"]
    low = min((ct for ct in dg.combos if ct[0] != dg.baseline),
              key=lambda ct: float(wr.sel(candidate=ct[0], tugger=ct[1])))
    dg = replace(dg, best=low, table=table_selection(data["workability"], dg.combos, dg.baseline, low, []))
    cx = Context(sea=data["sea_states"], vessel=data["vessel_motion"], plant=data["plant"],
                 resp=data["response"], work=data["workability"], prov=rf.provenance(), dg=dg, figs={})
    text = workability_table(cx)
    assert len(dg.combos) > MAX_TABLE_COMBOS
    assert text.count("\n  ") == 1 + MAX_TABLE_COMBOS             # the header, one line per row
    assert f"*{t(low[0])}*" in text and f"*{t(low[1])}*" in text   # the recommendation, in bold
    assert f"Listed: {MAX_TABLE_COMBOS} of {len(dg.combos)} combinations" in text


def test_the_linear_range_table_lists_the_tables_selection_of_many_options():
    """A 10 000-candidate grid listed 40 000 rows here (a 55 MB PDF): the table lists the
    digest's table selection and says so in its caption."""
    from jls.report.choices import MAX_TABLE_COMBOS
    from jls.report.context import Context
    from jls.report.validity import chapter
    data, dg = _many_options()
    cx = Context(sea=data["sea_states"], vessel=data["vessel_motion"], plant=data["plant"],
                 resp=data["response"], work=data["workability"], prov=rf.provenance(), dg=dg, figs={})
    text = chapter(cx).split("outside the linear range (relative sway")[1]
    assert len(dg.combos) > MAX_TABLE_COMBOS and len(dg.linear) == len(dg.combos)
    assert text.count("\n  [") == MAX_TABLE_COMBOS                # one line per listed row
    assert f"Listed: {MAX_TABLE_COMBOS} of {len(dg.combos)} combinations" in text


def test_page_one_states_the_vessel_data_and_the_hinge_geometry(rendered, data):
    """Issue 18, items 2 and 4: page 1 says whether the vessel data are the vessel's own
    or representative (with how the hull's sway compares with the study's), from
    vessel_motion.nc, and where the hinge stands: height above the waterline and lever arm
    (the hinge geometry in the chapter "Assessment in detail" right after it)."""
    text = " ".join(page_one_and_detail(rendered[2]).split())
    assert " ".join(str(data["vessel_motion"].attrs["vessel_statement"]).split()).rstrip(".") in \
        " ".join(section(rendered[2], "Summary").split()).replace("’", "'")
    attrs = data["vessel_motion"].attrs
    statement = " ".join(str(attrs["vessel_statement"]).split())
    assert statement.rstrip(".") in text.replace("’", "'")
    height = float(attrs["hinge_height_above_water_m"])
    assert f"The hinge stands {height:.2f} m above the waterline" in text
    lever = [float(x) for x in attrs["hinge_lever_arm_m"]]
    assert f"{lever[0]:.1f}, {lever[1]:.1f}, {lever[2]:.1f} m (forward, port, up)".replace("-", "−") in text \
        or f"{lever[0]:.1f}, {lever[1]:.1f}, {lever[2]:.1f} m (forward, port, up)" in text
