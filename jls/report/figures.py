"""The report's figures, drawn with matplotlib (object API, Agg/SVG, no pyplot state).

Each function takes datasets of the README (section Outputs) and the :class:`~jls.report.contract.Digest`
and writes one SVG into ``out_dir``, sized for an A4 text width (174 mm) so that its
fonts come out at 7-8 pt in the page. Units on the axes are the report's: m, s, degree.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle

from jls.report.contract import complex_var, criterion_label, flag, limit_text, on_sea_grid

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
    path = Path(out_dir) / f"{name}.svg"
    fig.savefig(path, format="svg", metadata={"Date": None})
    return path


def _figure(height_in: float, **kw) -> Figure:
    return Figure(figsize=(WIDTH_IN, height_in), layout="constrained", **kw)


def _ncol(labels) -> int:
    """Legend columns that fit the text width for labels of this length."""
    longest = max((len(s) for s in labels), default=10)
    return max(1, min(len(labels), 4 if longest <= 24 else 3 if longest <= 34 else 2))


def combo_style(dg, combo) -> dict:
    c = CAND_COLOURS[dg.candidates.index(combo[0]) % len(CAND_COLOURS)]
    ls = TUG_STYLES[dg.tuggers.index(combo[1]) % len(TUG_STYLES)]
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
            for i, cand in enumerate(dg.candidates):
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
    panels = [("hinge sway $y_b$ [m/m]", hinge.sel(dof="sway"), 1.0),
              ("hinge heave $z_b$ [m/m]", hinge.sel(dof="heave"), 1.0),
              ("hinge roll $\\varphi_b$ [deg/m]", hinge.sel(dof="roll"), 180 / np.pi),
              ("hinge yaw $\\psi_b$ [deg/m]", hinge.sel(dof="yaw"), 180 / np.pi),
              ("vessel roll [deg/m]", rao.sel(vessel_dof="roll"), 180 / np.pi),
              ("vessel sway [m/m]", rao.sel(vessel_dof="sway"), 1.0)]
    with matplotlib.rc_context(STYLE):
        fig = _figure(4.4)
        axes = fig.subplots(2, 3, sharex=True).ravel()
        for ax, (title, da, scale) in zip(axes, panels):
            for j, h in enumerate(vessel["heading"].values):
                amp = np.abs(da.sel(heading=h).values) * scale
                ax.plot(period, amp, color=f"C{j}", label=f"heading {h:g}°")
            ax.axvline(t_sway, color="k", ls=":", lw=0.8)
            ax.set_title(title)
            ax.set_xlim(max(period.min(), 3.0), min(period.max(), 30.0))
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
            for ax, r, unit in ((axes[k, 0], "relative_sway", "m/m"), (axes[k, 1], "relative_yaw", "deg/m")):
                for combo in (c for c in dg.combos if c[0] in stored):
                    amp = np.abs(H.sel(candidate=combo[0], tugger=combo[1], heading=h, response=r).values)
                    ax.semilogy(period, amp, lw=0.9, **combo_style(dg, combo))
                for i, cand in enumerate(dg.candidates):
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
        for i in range(s.sizes["hs"]):
            for j in range(s.sizes["tz"]):
                h0, h1 = float(s["hs_lower"][i]), float(s["hs_upper"][i])
                t0, t1 = float(s["tz_lower"][j]), float(s["tz_upper"][j])
                if not np.all(np.isfinite([h0, h1, t0, t1])):
                    continue
                p = prob[i, j]
                f = float(pass_frac[i, j])
                colour = "white" if p <= 0 else PASS if f >= 1 - 1e-9 else FAIL if f <= 1e-9 else PARTIAL
                ax.add_patch(Rectangle((t0, h0), t1 - t0, h1 - h0, fc=colour, ec="0.6", lw=0.4,
                                       hatch="///" if steep[i, j] and p > 0 else None))
                if p > 0:
                    txt = f"{100 * p:.1f}" if p >= 0.0005 else "<0.1"
                    ax.text((t0 + t1) / 2, (h0 + h1) / 2, txt, ha="center", va="center",
                            fontsize=5 if small else 6,
                            weight="bold" if bool(outside[i, j]) else "normal",
                            bbox={"fc": "white", "ec": "none", "alpha": 0.7, "pad": 0.4})
                    if bool(outside[i, j]):
                        ax.plot(t1 - 0.08 * (t1 - t0), h1 - 0.14 * (h1 - h0), marker="^",
                                color="k", ms=2 if small else 3)
        tz_lo, tz_up = s["tz_lower"].values, s["tz_upper"].values
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
def operability(work: xr.Dataset, sea: xr.Dataset, dg, out_dir) -> Path:
    """Limiting Hs against Tz for the shown combinations, per heading, with the
    steepness ceiling (the study's figure 6.7)."""
    heads = work["heading"].values
    curve, per_criterion = _limit_curves(work)
    tz_all = curve["tz"].values
    with matplotlib.rc_context(STYLE):
        fig = _figure(1.0 + 3.0 * len(heads))
        axes = np.atleast_1d(fig.subplots(len(heads), 1, squeeze=False).ravel())
        for ax, h in zip(axes, heads):
            tz, ceil = _ceiling_curve(work, float(np.nanmin(tz_all)), float(np.nanmax(tz_all)))
            ax.plot(tz, ceil, color="0.5", ls="--", lw=1.2, label="steepness ceiling")
            for combo in dg.combos:
                hl = curve.sel(candidate=combo[0], tugger=combo[1], heading=h).dropna("tz")
                ax.plot(hl["tz"], hl, **combo_style(dg, combo))
            if len(dg.criteria) > 1:
                base = per_criterion.sel(candidate=dg.baseline, tugger=dg.no_tugger,
                                                      heading=h)
                for k, c in enumerate(dg.criteria):
                    ax.plot(base["tz"], base.sel(criterion=c), color="0.6", lw=0.6,
                            ls=(0, (1, 1 + k)), label=f"{criterion_label(c)} alone (baseline)")
            top = max(float(np.nanmax(sea["hs_upper"])), 1.0)
            ax.set_ylim(0, top)
            ax.set_xlim(float(np.nanmin(tz_all)), float(np.nanmax(tz_all)))
            ax.set_xlabel("zero-crossing period Tz [s]")
            ax.set_ylabel("limiting Hs [m]")
            crit = ", ".join(f"{criterion_label(c)} {limit_text(dg, c)}" for c in dg.criteria)
            ax.set_title(f"heading {h:g}°: largest workable Hs ({crit}, {dg.exposure_h:g} h MPM)")
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "operability")


def workability_bars(work: xr.Dataset, dg, out_dir) -> Path:
    """Workability per leg and for the route, one bar per shown combination."""
    legs = [str(v) for v in work["leg"].values]
    groups = legs + ["route"]
    n = len(dg.combos)
    width = 0.8 / max(n, 1)
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.0)
        ax = fig.subplots()
        for k, combo in enumerate(dg.combos):
            sel = dict(candidate=combo[0], tugger=combo[1])
            vals = [float(work["workability_leg"].sel(leg=leg, **sel)) for leg in legs]
            vals.append(float(work["workability_route"].sel(**sel)))
            st = combo_style(dg, combo)
            x = np.arange(len(groups)) - 0.4 + width * (k + 0.5)
            ax.bar(x, 100 * np.array(vals), width * 0.9, color=st["color"], alpha=0.85,
                   hatch=HATCHES[dg.tuggers.index(combo[1]) % len(HATCHES)], ec="white", lw=0.3,
                   label=st["label"])
        ax.set_xticks(np.arange(len(groups)), groups)
        ax.set_ylabel("workable fraction [%]")
        ax.set_ylim(0, 100)
        handles, labels = ax.get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=_ncol(labels))
        return _save(fig, out_dir, "workability")
