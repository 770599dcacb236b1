"""The report's figures, drawn with matplotlib (object API, Agg/SVG, no pyplot state).

Each function takes datasets of the README (section Outputs) and the :class:`~jls.report.contract.Digest`
and writes one SVG into ``out_dir``, sized for an A4 text width (174 mm) so that its
fonts come out at 7-8 pt in the page. Units on the axes are the report's: m, s, degree.
"""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.collections import PatchCollection
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle
from matplotlib.ticker import LogFormatterSciNotation

from jls.report.contract import (
    complex_var,
    criterion_label,
    flag,
    limit_text,
    negligible,
    on_sea_grid,
    reference_amplitude,
)

WIDTH_IN = 6.85
STYLE = {"font.size": 7.5, "axes.titlesize": 8, "axes.labelsize": 7.5, "legend.fontsize": 6.5,
         "xtick.labelsize": 7, "ytick.labelsize": 7, "axes.grid": True, "grid.alpha": 0.3,
         "grid.linewidth": 0.5, "lines.linewidth": 1.2, "svg.fonttype": "path",
         "svg.hashsalt": "jls", "font.family": "DejaVu Sans"}
CAND_COLOURS = ["black", "tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown"]
TUG_STYLES = ["-", "--", ":", "-."]
HATCHES = [None, "///", "...", "xxx"]
PASS, FAIL, PARTIAL = "#7cc47f", "#e57373", "#ffcc80"


def _save(fig: Figure, out_dir, name: str) -> Path:
    """``fig`` as ``<name>.svg``; the same figure gives the same bytes (ids are hashes
    salted with the style's ``svg.hashsalt``, no date)."""
    path = Path(out_dir) / f"{name}.svg"
    with matplotlib.rc_context({"svg.hashsalt": STYLE["svg.hashsalt"]}):
        fig.savefig(path, format="svg", metadata={"Date": None})
    return path


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


def _figure(height_in: float, **kw) -> Figure:
    return Figure(figsize=(WIDTH_IN, height_in), layout="constrained", **kw)


def _ncol(labels) -> int:
    """Legend columns that fit the text width for labels of this length."""
    longest = max((len(s) for s in labels), default=10)
    return max(1, min(len(labels), 4 if longest <= 24 else 3 if longest <= 34 else 2))


def combo_style(dg, combo) -> dict:
    c = CAND_COLOURS[dg.plot.candidates.index(combo[0]) % len(CAND_COLOURS)]
    ls = TUG_STYLES[dg.plot.tuggers.index(combo[1]) % len(TUG_STYLES)]
    return {"color": c, "linestyle": ls, "label": f"{combo[0]} / {combo[1]}"}


# -- plant ----------------------------------------------------------------------------
def rigging(plant: xr.Dataset, dg, out_dir) -> Path:
    """The wires of the shown candidates in the transverse (Y-Z) and longitudinal
    (X-Z) planes: hinge at the origin, anchors, padeyes, CoG and the jacket top."""
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.5)
        axes = fig.subplots(1, 2)
        for (ax, (h, name)) in zip(axes, ((1, "transverse view (Y-Z), looking forward"),
                                          (0, "longitudinal view (X-Z), looking to port"))):
            for i, cand in enumerate(dg.plot.candidates):
                p = plant.sel(candidate=cand)
                colour = CAND_COLOURS[i % len(CAND_COLOURS)]
                ls = "-" if i == 0 else ("--", "-.", ":", (0, (5, 1, 1, 1)), (0, (3, 1)))[(i - 1) % 5]
                anchor, pad_rel = p["anchor"].values, p["padeye"].values
                depth = float(p["cog_depth"])
                pad = pad_rel + np.array([0.0, 0.0, -depth])
                for a, b in zip(anchor, pad):
                    ax.plot([a[h], b[h]], [a[2], b[2]], color=colour, ls=ls, lw=1.0)
                ax.plot(anchor[:, h], anchor[:, 2], "v", color=colour, ms=4)
                ax.plot(pad[:, h], pad[:, 2], "o", color=colour, ms=3, mfc="white")
                ax.plot([0], [-depth], "+", color=colour, ms=9, mew=1.5)
                lo, hi = pad[:, h].min(), pad[:, h].max()
                top = pad[:, 2].mean()
                ax.add_patch(Rectangle((lo, -depth), hi - lo, top + depth, fill=False,
                                       ec=colour, ls=ls, lw=0.7, alpha=0.7))
                ax.plot([], [], color=colour, ls=ls, label=cand)
            ax.plot([0], [0], "s", color="red", ms=5, label="hinge (origin)")
            ax.axhline(0.0, color="grey", lw=0.6, ls=":")
            ax.set_title(name)
            ax.set_xlabel("y to port [m]" if h == 1 else "x forward [m]")
            ax.set_ylabel("z up from the hinge [m]")
            ax.set_aspect("equal", adjustable="datalim")
        handles, labels = axes[0].get_legend_handles_labels()
        wide = max(len(s) for s in labels) > 24
        fig.legend(handles, labels, loc="outside lower center", ncol=min(len(labels), 2 if wide else 4))
        return _save(fig, out_dir, "rigging")


# -- vessel ---------------------------------------------------------------------------
def hinge_raos(vessel: xr.Dataset, plant: xr.Dataset, dg, out_dir) -> Path:
    """Hinge excitation amplitudes and the vessel roll RAO against wave period."""
    hinge = complex_var(vessel, "hinge")
    rao = complex_var(vessel, "rao")
    period = 2 * np.pi / vessel["omega"].values
    t_sway = float(plant["natural_period"].sel(candidate=dg.baseline).isel(mode=0))
    panels = [("hinge sway $y_b$ [m/m]", hinge.sel(dof="sway"), 1.0, "sway"),
              ("hinge heave $z_b$ [m/m]", hinge.sel(dof="heave"), 1.0, "heave"),
              ("hinge roll $\\varphi_b$ [deg/m]", hinge.sel(dof="roll"), 180 / np.pi, "roll"),
              ("hinge yaw $\\psi_b$ [deg/m]", hinge.sel(dof="yaw"), 180 / np.pi, "yaw"),
              ("vessel roll [deg/m]", rao.sel(vessel_dof="roll"), 180 / np.pi, "roll"),
              ("vessel sway [m/m]", rao.sel(vessel_dof="sway"), 1.0, "sway")]
    with matplotlib.rc_context(STYLE):
        fig = _figure(4.4)
        axes = fig.subplots(2, 3, sharex=True).ravel()
        for ax, (title, da, scale, motion) in zip(axes, panels):
            quiet = []
            for j, h in enumerate(vessel["heading"].values):
                amp = np.abs(da.sel(heading=h).values) * scale
                if negligible(amp / scale, reference_amplitude(vessel, h, rotation=scale != 1.0)):
                    amp = np.zeros_like(amp)                 # round-off, not motion
                    quiet.append(f"{h:g}°")
                ax.plot(period, amp, color=f"C{j}", label=f"heading {h:g}°")
            if quiet:
                where = "this heading" if len(quiet) == 1 else "headings " + ", ".join(quiet)
                ax.text(0.5, 0.55, f"no {motion} motion at {where}", transform=ax.transAxes,
                        ha="center", va="center", fontsize=7, color="0.3")
                ax.set_ylim(0, 1)
                ax.set_yticklabels([])
            ax.axvline(t_sway, color="k", ls=":", lw=0.8)
            ax.set_title(title)
            ax.set_xlim(max(period.min(), 3.0), min(period.max(), 30.0))
            if not quiet:
                ax.set_ylim(bottom=0)
        for ax in axes[3:]:
            ax.set_xlabel("wave period [s]")
        axes[0].legend(loc="upper left")
        axes[1].annotate(f"baseline sway period {t_sway:.2f} s", (t_sway, 0), xytext=(3, 3),
                         textcoords="offset points", fontsize=6, rotation=90, va="bottom")
        return _save(fig, out_dir, "hinge_raos")


def relative_transfer(resp: xr.Dataset, plant: xr.Dataset, dg, out_dir) -> Path:
    """Relative sway and yaw per unit wave amplitude for the shown combinations."""
    H = complex_var(resp, "transfer").rename(shown_candidate="candidate")
    stored = set(H["candidate"].values.tolist())      # the baseline and named candidates
    period = 2 * np.pi / resp["omega"].values
    heads = resp["heading"].values
    with matplotlib.rc_context(STYLE):
        fig = _figure(2.9 + 1.6 * (len(heads) - 1))
        axes = np.atleast_2d(fig.subplots(len(heads), 2, sharex=True, squeeze=False))
        for k, h in enumerate(heads):
            rot = [x for x in ("relative_roll", "relative_yaw") if x in H["response"].values]
            scale_rot = float(np.nanmax(np.abs(H.sel(heading=h, response=rot).values))) if rot else 0.0
            for ax, r, unit in ((axes[k, 0], "relative_sway", "m/m"), (axes[k, 1], "relative_yaw", "deg/m")):
                amps = {combo: np.abs(H.sel(candidate=combo[0], tugger=combo[1], heading=h, response=r).values)
                        for combo in dg.plot.combos if combo[0] in stored}
                ref = scale_rot if r == "relative_yaw" else float(np.nanmax(np.abs(H.sel(heading=h).values)))
                if negligible(np.array(list(amps.values())), ref):
                    ax.text(0.5, 0.5, f"no {r.split('_')[1]} motion at this heading", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="0.3")
                    for combo in amps:
                        ax.plot([], [], lw=0.9, **combo_style(dg, combo))
                else:
                    for combo, amp in amps.items():
                        ax.semilogy(period, amp, lw=0.9, **combo_style(dg, combo))
                    log_ticks(ax.yaxis)
                for i, cand in enumerate(dg.plot.candidates):
                    ax.axvline(float(plant["natural_period"].sel(candidate=cand).isel(mode=0)),
                               color=CAND_COLOURS[i % len(CAND_COLOURS)], ls=":", lw=0.7)
                ax.set_title(f"{r.replace('_', ' ')} [{unit}], heading {h:g}°")
                ax.set_xlim(3.0, min(period.max(), 25.0))
        for ax in axes[-1]:
            ax.set_xlabel("wave period [s]")
        handles, labels = axes[0, 0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "relative_transfer")


# -- sea states -----------------------------------------------------------------------
def _limit_curves(work: xr.Dataset):
    """Limiting Hs, per criterion, over Tz: on the fine operability grid when the
    workability dataset has it, else at the scatter's Tz centres (dim 'tz' either way)."""
    if "hs_limit_curve" in work:
        return (work["hs_limit_curve"].rename(tz_curve="tz"),
                work["hs_limit_curve_criterion"].rename(tz_curve="tz"))
    return work["hs_limit"], work["hs_limit_criterion"]


def _ceiling_curve(work: xr.Dataset, tz_lo: float, tz_hi: float):
    """The steepness ceiling on a fine Tz grid, power-law interpolated (exact for the
    study rule, Hs ~ Tz^2) between and beyond the tabulated points."""
    s = work["steepness_limit"].dropna("tz")
    x, y = np.log(s["tz"].values), np.log(s.values)
    tz = np.linspace(tz_lo, tz_hi, 200)
    lx = np.log(tz)
    if x.size == 1:
        return tz, np.exp(y[0] + 2 * (lx - x[0]))
    slope_lo, slope_hi = (y[1] - y[0]) / (x[1] - x[0]), (y[-1] - y[-2]) / (x[-1] - x[-2])
    ly = np.interp(lx, x, y)
    ly = np.where(lx < x[0], y[0] + slope_lo * (lx - x[0]), ly)
    ly = np.where(lx > x[-1], y[-1] + slope_hi * (lx - x[-1]), ly)
    return tz, np.exp(ly)


def scatter(sea: xr.Dataset, work: xr.Dataset, dg, leg: str, out_dir) -> Path:
    """One leg's Hs-Tz table: probability per cell, pass/fail of the baseline without
    tugger, steep cells hatched, cells outside the linear range marked, the baseline's
    limiting Hs and the steepness ceiling."""
    s = sea.sel(leg=leg)
    combo = (dg.baseline, dg.no_tugger)
    passes = flag(on_sea_grid(work["passes"].sel(candidate=combo[0], tugger=combo[1], leg=leg), sea))
    hp = s["heading_probability"]
    pass_frac = ((passes * hp).sum("heading") / max(float(hp.sum()), 1e-12)).transpose("hs", "tz")
    outside = dg.linear[combo]["mask"].sel(leg=leg).any("heading").transpose("hs", "tz").values
    prob = s["probability"].transpose("hs", "tz").values
    steep = flag(s["steep"]).transpose("hs", "tz").values
    live = prob > 0
    rows_live = np.flatnonzero(live.any(axis=1))
    cols_live = np.flatnonzero(live.any(axis=0))
    n_rows = rows_live[-1] + 1 if rows_live.size else s.sizes["hs"]
    small = n_rows > 10 or (cols_live.size and cols_live[-1] - cols_live[0] > 10)
    with matplotlib.rc_context({**STYLE, "hatch.color": "0.4", "hatch.linewidth": 0.5}):
        fig = _figure(float(np.clip(1.4 + 0.3 * n_rows, 3.0, 6.2)))
        ax = fig.subplots()
        hs_lo, hs_up = s["hs_lower"].values, s["hs_upper"].values
        tz_lo, tz_up = s["tz_lower"].values, s["tz_upper"].values
        frac = pass_frac.values
        cells = {False: [], True: []}                  # hatched (steep) or not -> cell rectangles
        for i in range(s.sizes["hs"]):
            for j in range(s.sizes["tz"]):
                h0, h1 = float(hs_lo[i]), float(hs_up[i])
                t0, t1 = float(tz_lo[j]), float(tz_up[j])
                if not np.all(np.isfinite([h0, h1, t0, t1])):
                    continue
                p = prob[i, j]
                f = float(frac[i, j])
                colour = "white" if p <= 0 else PASS if f >= 1 - 1e-9 else FAIL if f <= 1e-9 else PARTIAL
                cells[bool(steep[i, j] and p > 0)].append(
                    Rectangle((t0, h0), t1 - t0, h1 - h0, fc=colour, ec="0.6", lw=0.4))
                if p > 0:
                    txt = f"{100 * p:.1f}" if p >= 0.0005 else "<0.1"
                    ax.text((t0 + t1) / 2, (h0 + h1) / 2, txt, ha="center", va="center",
                            fontsize=5 if small else 6,
                            weight="bold" if bool(outside[i, j]) else "normal",
                            bbox={"fc": "white", "ec": "none", "alpha": 0.7, "pad": 0.4},
                            in_layout=False)      # inside its cell, inside the axes
                    if bool(outside[i, j]):
                        ax.plot(t1 - 0.08 * (t1 - t0), h1 - 0.14 * (h1 - h0), marker="^",
                                color="k", ms=2 if small else 3)
        for hatched, rects in cells.items():          # one artist per kind: same look, drawn faster
            if rects:
                ax.add_collection(PatchCollection(rects, match_original=True, zorder=1,
                                                  hatch="///" if hatched else None),
                                  autolim=False)
        if cols_live.size:
            t_lo, t_hi = float(tz_lo[cols_live[0]]), float(tz_up[cols_live[-1]])
            h_hi = float(s["hs_upper"].values[rows_live[-1]])
        else:
            t_lo, t_hi = float(np.nanmin(tz_lo)), float(np.nanmax(tz_up))
            h_hi = float(np.nanmax(s["hs_upper"]))
        tz, ceil = _ceiling_curve(work, t_lo, t_hi)
        ax.plot(tz, ceil, color="0.35", ls="--", lw=1.0, label="steepness ceiling")
        curve, _ = _limit_curves(work)
        for k, h in enumerate(work["heading"].values):
            hl = curve.sel(candidate=combo[0], tugger=combo[1], heading=h).dropna("tz")
            ax.plot(hl["tz"], hl, color="navy", lw=1.2, ls=TUG_STYLES[k % 4],
                    label=f"limiting Hs, {h:g}°")
        ax.set_xlim(t_lo, t_hi)
        ax.set_ylim(0, h_hi)
        ax.set_xlabel("zero-crossing period Tz [s]")
        ax.set_ylabel("significant wave height Hs [m]")
        ax.set_title(f"leg {leg}: probability per cell [%]; {combo[0]} rigging, tugger {combo[1]}")
        handles = ax.get_legend_handles_labels()[0] + [
            Patch(fc=PASS, ec="0.6", label="passes"), Patch(fc=FAIL, ec="0.6", label="fails"),
            Patch(fc=PARTIAL, ec="0.6", label="passes at some headings"),
            Patch(fc="white", ec="0.6", hatch="///", label="above steepness ceiling"),
            matplotlib.lines.Line2D([], [], marker="^", color="k", ls="", ms=3,
                                    label="outside linear range")]
        fig.legend(handles=handles, loc="outside right upper", fontsize=6)
        ax.grid(False)
        return _save(fig, out_dir, f"scatter_{leg}")


# -- operability and workability ------------------------------------------------------
TUG_COLOURS = ["black", "tab:blue", "tab:orange", "tab:green"]


def operability_top(curves: list) -> float:
    """Top of the operability y-axis: 15 % above the highest limiting curve where a
    criterion, not the steepness ceiling, sets it (else the highest curve)."""
    governed = [np.where(c < 0.999 * cl, c, np.nan) for c, cl in curves]
    peak = max((np.nanmax(g) for g in governed if np.isfinite(g).any()), default=np.nan)
    if not np.isfinite(peak):
        peak = max((np.nanmax(c) for c, _ in curves if np.isfinite(c).any()), default=1.0)
    return float(max(1.15 * peak, 0.5))


def operability(work: xr.Dataset, sea: xr.Dataset, dg, out_dir) -> Path:
    """Limiting Hs against Tz (the study's figure 6.7), one panel per shown candidate and
    heading, one line per shown tugger, the baseline without tugger as a grey reference;
    the y-range covers the limiting curves and the steepness ceiling is clipped."""
    heads = work["heading"].values
    curve, per_criterion = _limit_curves(work)
    ceiling = (work["steepness_limit_curve"].rename(tz_curve="tz") if "steepness_limit_curve" in work
               else work["steepness_limit"])
    tz_all = curve["tz"].values
    panels = [(h, c) for h in heads for c in dg.plot.candidates]
    n_col = 1 if len(panels) == 1 else 2
    n_row = int(np.ceil(len(panels) / n_col))
    with matplotlib.rc_context(STYLE):
        fig = _figure(0.9 + 2.3 * n_row)
        axes = np.atleast_1d(fig.subplots(n_row, n_col, squeeze=False, sharex=True).ravel())
        base = (dg.baseline, dg.no_tugger)
        for ax, (h, cand) in zip(axes, panels):
            sel = dict(heading=h)
            cl = ceiling.sel(tz=curve["tz"]).values if "tz" in ceiling.dims else ceiling.values
            lines = [(curve.sel(candidate=cand, tugger=tg, **sel).values, cl) for tg in dg.plot.tuggers]
            lines.append((curve.sel(candidate=base[0], tugger=base[1], **sel).values, cl))
            top = operability_top(lines)
            tz_f, ceil_f = _ceiling_curve(work, float(np.nanmin(tz_all)), float(np.nanmax(tz_all)))
            ax.plot(tz_f, np.minimum(ceil_f, top), color="0.5", ls="--", lw=1.1, label="steepness ceiling")
            clipped = ceil_f > top
            if clipped.any():
                i = int(np.argmax(clipped))
                ax.annotate("ceiling continues above", (tz_f[i], top), xytext=(5, -8),
                            textcoords="offset points", ha="left", fontsize=6, color="0.4")
                ax.plot(tz_f[clipped], np.full(clipped.sum(), top), color="0.5", lw=2.5, alpha=0.35,
                        solid_capstyle="butt", label="ceiling clipped at the axis top")
            if cand != base[0]:
                ax.plot(tz_all, lines[-1][0], color="0.75", lw=2.0, label=f"{base[0]} / {base[1]}")
            for k, tg in enumerate(dg.plot.tuggers):
                ax.plot(tz_all, lines[k][0], color=TUG_COLOURS[k % len(TUG_COLOURS)],
                        ls=TUG_STYLES[k % len(TUG_STYLES)], label=f"tugger {tg}")
            if len(dg.criteria) > 1:
                pc = per_criterion.sel(candidate=cand, tugger=dg.plot.tuggers[0], heading=h)
                for k, c in enumerate(dg.criteria):
                    ax.plot(pc["tz"], pc.sel(criterion=c), color="0.55", lw=0.6, ls=(0, (1, 1 + k)),
                            label=f"{criterion_label(c)} alone (tugger {dg.plot.tuggers[0]})")
            ax.set_ylim(0, top)
            ax.set_xlim(float(np.nanmin(tz_all)), float(np.nanmax(tz_all)))
            ax.set_ylabel("limiting Hs [m]")
            ax.set_title(f"{cand} rigging" + (f", heading {h:g}°" if len(heads) > 1 else ""))
        for ax in axes[len(panels):]:
            ax.set_visible(False)
        for ax in axes[max(0, len(panels) - n_col):len(panels)]:
            ax.set_xlabel("zero-crossing period Tz [s]")
        crit = ", ".join(f"{criterion_label(c)} {limit_text(dg, c)}" for c in dg.criteria)
        fig.suptitle(f"Largest workable Hs ({crit}, {dg.exposure_h:g} h MPM)", fontsize=8)
        seen = {}
        for ax in axes[:len(panels)]:
            for hd, lb in zip(*ax.get_legend_handles_labels()):
                seen.setdefault(lb, hd)
        fig.legend(list(seen.values()), list(seen), loc="outside lower center", ncol=_ncol(list(seen)))
        return _save(fig, out_dir, "operability")


def percent_axis_start(work: xr.Dataset, combos) -> float:
    """Start of the workability axis [%]: the 5 % step below the lowest value shown,
    less one step of room (0 when values go that low)."""
    vals = [float(work["workability_leg"].sel(candidate=c, tugger=t).min()) for c, t in combos]
    vals += [float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
    low = 100.0 * min(vals)
    return float(max(0.0, 5.0 * np.floor(low / 5.0) - (5.0 if low % 5.0 < 1.0 else 0.0)))


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


def workability_bars(work: xr.Dataset, dg, out_dir) -> Path:
    """Workability per leg and for the route as a dot plot: one row per combination, a
    marker per leg and a filled diamond for the route, on an axis that starts where the
    values do (the start is stated in the caption; a dot plot does not imply a zero)."""
    legs = [str(v) for v in work["leg"].values]
    combos = dg.dots.combos
    start = percent_axis_start(work, combos)
    markers = ["o", "s", "^", "v", "<", ">", "p", "h"]
    with matplotlib.rc_context(STYLE):
        fig = _figure(1.2 + 0.22 * len(combos))
        ax = fig.subplots()
        y = np.arange(len(combos))[::-1]
        for k, leg in enumerate(legs):
            vals = [100 * float(work["workability_leg"].sel(candidate=c, tugger=t, leg=leg)) for c, t in combos]
            ax.plot(vals, y, ls="", marker=markers[k % len(markers)], mfc="white", mec=f"C{k}",
                    ms=4.5, mew=1.0, label=f"leg {leg}")
        route = [100 * float(work["workability_route"].sel(candidate=c, tugger=t)) for c, t in combos]
        ax.plot(route, y, ls="", marker="D", color="black", ms=4.5, label="route")
        combination_rows(ax, combos, dg, start, "workable fraction")
        ax.grid(True, axis="x")
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "workability")
