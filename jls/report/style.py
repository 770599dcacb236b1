"""What the report's figures share: the matplotlib style, the figure size, saving, plain
log-axis labels, the colour and line style of a combination and the frame of a
one-row-per-combination plot; and :class:`Task`, one planned figure.

Figures are drawn with matplotlib's object API (Agg/SVG, no pyplot state), sized for an
A4 text width (174 mm) so that their fonts come out at 7-8 pt in the page. Units on the
axes are the report's: m, s, degree. Each chapter module draws its own figures with
these helpers and lists them in its ``figure_plan`` (:mod:`jls.report.drawing`).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Callable, NamedTuple

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.backends.backend_svg import FigureCanvasSVG
from matplotlib.figure import Figure
from matplotlib.ticker import LogFormatterSciNotation

WIDTH_IN = 6.85
STYLE = {"font.size": 7.5, "axes.titlesize": 8, "axes.labelsize": 7.5, "legend.fontsize": 6.5,
         "xtick.labelsize": 7, "ytick.labelsize": 7, "axes.grid": True, "grid.alpha": 0.3,
         "grid.linewidth": 0.5, "lines.linewidth": 1.2, "svg.fonttype": "path",
         "svg.hashsalt": "jls", "font.family": "DejaVu Sans"}
CAND_COLOURS = ["black", "tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown"]
TUG_STYLES = ["-", "--", ":", "-."]


class Task(NamedTuple):
    """One figure of the report: ``draw(out_dir)`` writes ``<name>.svg`` there."""

    name: str                              # the file is <name>.svg
    draw: Callable[[Path], Path]           # out_dir -> the saved file
    cost: float = 1.0                      # drawing time, about 0.1 s a unit: sets the order


def file_name(name: str) -> str:
    return f"{name}.svg"


def save(fig: Figure, out_dir, name: str) -> Path:
    """``fig`` as ``<name>.svg``; the same figure gives the same bytes (ids are hashes
    salted with the style's ``svg.hashsalt``, no date).

    The layout is made once, as ``savefig`` makes it (at the SVG canvas's 72 dpi, with its
    text metrics), and the figure is then drawn once: ``savefig`` of a figure with a layout
    engine draws it twice, a first time with nothing rendered. The bytes are those of
    ``savefig``; the 19 figures of the default route draw in 12 % less CPU."""
    path = Path(out_dir) / file_name(name)
    with matplotlib.rc_context({"svg.hashsalt": STYLE["svg.hashsalt"]}):
        canvas = FigureCanvasSVG(fig)
        engine = fig.get_layout_engine()
        if engine is not None and fig.axes:
            dpi = fig.dpi
            fig.dpi = 72
            engine.execute(fig)
            fig.dpi = dpi
            fig.set_layout_engine("none")
        canvas.print_svg(path, metadata={"Date": None})
    return path


def new_figure(height_in: float, **kw) -> Figure:
    """A figure of the text width and ``height_in`` inches, constrained layout."""
    return Figure(figsize=(WIDTH_IN, height_in), layout="constrained", **kw)


class PlainLogFormatter(LogFormatterSciNotation):
    """The labels of matplotlib's log-axis formatter (10⁻², 2×10⁻¹) as plain text with
    Unicode superscripts rather than mathtext: they look the same and need no parser."""

    _MATH = re.compile(r"\$\\mathdefault\{(.*)\}\$")
    _SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")

    def __call__(self, x, pos=None):
        label = super().__call__(x, pos)
        math = self._MATH.fullmatch(label)
        if math is None:
            return label
        body = math.group(1).replace("\\times", "×")
        return re.sub(r"\^\{([^}]*)\}", lambda m: m.group(1).translate(self._SUPERSCRIPT), body)


def log_ticks(axis) -> None:
    """Plain-text labels on a log ``axis`` (``ax.yaxis``), major and minor as matplotlib
    would choose them."""
    axis.set_major_formatter(PlainLogFormatter(10.0))
    axis.set_minor_formatter(PlainLogFormatter(10.0, labelOnlyBase=False))


def legend_columns(labels) -> int:
    """Legend columns that fit the text width for labels of this length."""
    longest = max((len(s) for s in labels), default=10)
    return max(1, min(len(labels), 4 if longest <= 24 else 3 if longest <= 34 else 2))


def combo_style(dg, combo) -> dict:
    """Colour by rigging candidate, line style by tugger setting, of the figure selection."""
    c = CAND_COLOURS[dg.plot.candidates.index(combo[0]) % len(CAND_COLOURS)]
    ls = TUG_STYLES[dg.plot.tuggers.index(combo[1]) % len(TUG_STYLES)]
    return {"color": c, "linestyle": ls, "label": f"{combo[0]} / {combo[1]}"}


def percent_axis_start(work: xr.Dataset, combos) -> float:
    """Start of the workability axis [%]: the 5 % step below the lowest value shown,
    less one step of room (0 when values go that low)."""
    vals = [float(work["workability_leg"].sel(candidate=c, tugger=t).min()) for c, t in combos]
    vals += [float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
    low = 100.0 * min(vals)
    return float(max(0.0, 5.0 * np.floor(low / 5.0) - (5.0 if low % 5.0 < 1.0 else 0.0)))


#: Decades a transfer-function panel shows below its largest amplitude: the range that
#: carries the response (below it the short-period RAOs hold the BEM's numerical noise).
TRANSFER_DECADES = 3.0


def transfer_range(amplitudes, decades: float = TRANSFER_DECADES) -> tuple[float, float]:
    """The y-range of a log transfer-function panel: ``decades`` below the largest
    amplitude of ``amplitudes`` (arrays), to twice it."""
    peak = max(float(np.nanmax(a)) for a in amplitudes)
    return peak * 10.0 ** -decades, 2.0 * peak


def operability_top(curves: list) -> float:
    """Top of a limiting-Hs axis: 15 % above the highest limiting curve where a criterion,
    not the steepness ceiling, sets it (else the highest curve). ``curves``: pairs (limiting
    Hs, ceiling) on the same Tz grid. The ceiling is drawn whole and leaves the axis at its
    top, never flattened into a plateau it does not have."""
    governed = [np.where(c < 0.999 * cl, c, np.nan) for c, cl in curves]
    peak = max((np.nanmax(g) for g in governed if np.isfinite(g).any()), default=np.nan)
    if not np.isfinite(peak):
        peak = max((np.nanmax(c) for c, _ in curves if np.isfinite(c).any()), default=1.0)
    return float(max(1.15 * peak, 0.5))


def combination_rows(ax, combos, dg, start: float, xlabel: str) -> None:
    """The frame of a one-row-per-combination percent plot: rows labelled candidate /
    tugger, the best and the bare-baseline rows shaded, the x-axis from ``start`` to 100 %."""
    y = np.arange(len(combos))[::-1]
    for yy, ct in zip(y, combos):
        if ct in (dg.best, (dg.baseline, dg.no_tugger)):
            ax.axhspan(yy - 0.45, yy + 0.45, color="0.9", zorder=0)
    ax.set_yticks(y, [f"{c} / {t}" for c, t in combos])
    ax.set_ylim(-0.7, len(combos) - 0.3)
    ax.set_xlim(start, 100.0)
    ax.set_xlabel(f"{xlabel} [%] (axis starts at {start:g} %)")
    ax.grid(False, axis="y")


__all__ = ["CAND_COLOURS", "STYLE", "TUG_STYLES", "WIDTH_IN", "PlainLogFormatter", "Task",
           "combination_rows", "combo_style", "file_name", "legend_columns", "log_ticks",
           "new_figure", "operability_top", "percent_axis_start", "save", "TRANSFER_DECADES",
           "transfer_range"]
