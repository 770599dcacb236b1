"""The report's figures drawn by worker processes: the same bytes as drawn serially."""

from __future__ import annotations

import matplotlib
import pytest
import report_fixtures as rf
from matplotlib.ticker import LogFormatterSciNotation

from jls.report import control, document, drawing, operability, style
from jls.report.chapters import CHAPTERS
from jls.report.context import Context
from jls.report.contract import digest
from jls.report.document import render_report

needs_fork = pytest.mark.skipif(not drawing.can_fork(), reason="no fork start method")


@pytest.fixture(scope="module")
def data():
    return rf.datasets()


def context(data) -> Context:
    prov = dict(rf.provenance())
    prov["created"] = control.created(prov)
    dg = digest("r", data["sea_states"], data["vessel_motion"], data["plant"], data["response"],
                data["workability"], prov)
    return Context(sea=data["sea_states"], vessel=data["vessel_motion"],
                            plant=data["plant"], resp=data["response"], work=data["workability"],
                            prov=prov, dg=dg, figs={})


@needs_fork
def test_figures_with_one_and_two_workers_are_byte_identical(data, tmp_path):
    cx = context(data)
    one, two = tmp_path / "one", tmp_path / "two"
    one.mkdir()
    two.mkdir()
    names = document.draw_figures(cx, one, workers=1)
    assert document.draw_figures(cx, two, workers=2) == names
    assert sorted(p.name for p in one.iterdir()) == sorted(names.values())
    assert len(names) >= 6
    for name in names.values():
        assert (one / name).read_bytes() == (two / name).read_bytes(), name


@needs_fork
def test_the_pdf_is_the_same_with_two_workers(data, tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    a = render_report(tmp_path / "a.pdf", route="r", provenance=rf.provenance(), **data)
    b = render_report(tmp_path / "b.pdf", route="r", provenance=rf.provenance(), workers=2, **data)
    assert a.read_bytes() == b.read_bytes()


@pytest.mark.parametrize("workers", [1, pytest.param(2, marks=needs_fork)])
def test_a_failing_figure_fails_the_report_and_keeps_the_previous(data, tmp_path, monkeypatch,
                                                                   workers):
    """Drawn in this process or in a worker, a figure that fails stops the report and
    leaves the previous PDF in place, and nothing else."""
    out = tmp_path / "report.pdf"
    out.write_bytes(b"previous report")

    def broken(*args, **kwargs):
        raise RuntimeError("figure failed")
    monkeypatch.setattr(operability, "operability", broken)
    with pytest.raises(RuntimeError, match="figure failed"):
        render_report(out, route="r", provenance=rf.provenance(), workers=workers, **data)
    assert out.read_bytes() == b"previous report"
    assert [p.name for p in tmp_path.iterdir()] == ["report.pdf"]      # nothing left behind
    assert [p.name for p in tmp_path.iterdir()] == ["report.pdf"]


def test_the_plan_names_every_figure_once_in_the_report_order(data):
    cx = context(data)
    tasks = drawing.plan(cx)
    names = [t.name for t in tasks]
    assert len(set(names)) == len(names)
    scatter = [f"scatter_{leg}" for leg in map(str, data["sea_states"]["leg"].values)]
    expected = ["rigging", "hinge_raos", "relative_transfer", *scatter, "spectra_transfer", "operability",
                "workability"]
    assert names[:len(expected)] == expected
    assert drawing.names(tasks) == {n: f"{n}.svg" for n in names}
    # Planned chapter by chapter: the figures come in the order the text shows them.
    cx.figs = drawing.names(tasks)
    text = document.source(cx)
    where = [text.index(f'image("{cx.figs[n]}"') for n in names]
    assert where == sorted(where)
    assert {n for m in CHAPTERS if hasattr(m, "figure_plan") for n in
            (t.name for t in m.figure_plan(cx))} == set(names)


@pytest.mark.parametrize("minor", [False, True])
def test_plain_log_labels_say_what_the_mathtext_labels_say(minor):
    plain = style.PlainLogFormatter(10.0, labelOnlyBase=not minor)
    math = LogFormatterSciNotation(10.0, labelOnlyBase=not minor)
    values = [1e-4, 1e-3, 0.01, 0.1, 1.0, 10.0, 100.0, 0.2, 0.03, 20.0, 5e-4]
    expect = {1e-4: "10⁻⁴", 1e-3: "10⁻³", 0.01: "10⁻²", 0.1: "10⁻¹", 1.0: "10⁰", 10.0: "10¹",
              100.0: "10²", 0.2: "2×10⁻¹", 0.03: "3×10⁻²", 20.0: "2×10¹", 5e-4: "5×10⁻⁴"}
    for x in values:
        label = plain(x)
        assert "$" not in label
        if math(x) == "":
            assert label == ""
        else:
            assert label == expect[x]


def test_log_axes_carry_no_mathtext(tmp_path):
    with matplotlib.rc_context(style.STYLE):
        fig = style.new_figure(2.0)
        ax = fig.subplots()
        ax.semilogy([1, 2, 3], [1e-3, 1.0, 50.0])
        style.log_ticks(ax.yaxis)
        style.save(fig, tmp_path, "log")
    labels = [t.get_text() for t in ax.yaxis.get_ticklabels(which="both")]
    assert "10⁻³" in labels and "10¹" in labels
    assert not any("$" in s for s in labels)
