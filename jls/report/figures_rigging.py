"""Figures of the rigging screening (chapter 5), from the screening dataset.

Each function takes ``screening.nc`` (:func:`jls.design.screening.screening_dataset`) and
returns a matplotlib Figure (object API, no pyplot state) in the style of
:mod:`jls.report.figures`, sized for an A4 text width: the caller saves it.

* :func:`sensitivity` - natural periods against each design variable (figure 5.3);
* :func:`screening_surface` - the score over the screened grid with sway-period
  contours, the infeasible region hatched, baseline and optimum marked (figure 5.4);
* :func:`geometry` - baseline and optimised rigging in two projections with the
  waterline, the jacket tip and the splash clearance (figure 5.5).
"""

from __future__ import annotations

import matplotlib
import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.patches import Patch, Rectangle

from jls.plant.linearise import DOF
from jls.plant.rigging import DESIGN_VARIABLES
from jls.report.figures import STYLE, WIDTH_IN, log_ticks

LABELS = {"top_spread_y": "top spread Y [m]", "bottom_spread_y": "bottom spread Y [m]",
          "bottom_spread_x": "bottom spread X [m]", "drop_height": "drop height [m]"}
DOF_COLOURS = {"sway": "tab:blue", "yaw": "tab:orange", "roll": "tab:green", "heave": "tab:purple"}
SCORES = {"route_workability": ("route workability [%]", 100.0, "viridis"),
          "screening_sigma": ("worst relative-sway sigma over the envelope [m]", 1.0, "viridis_r"),
          "workability_surrogate": ("route workability, bin-smoothed [%]", 100.0, "viridis")}


def _figure(height_in: float) -> Figure:
    return Figure(figsize=(WIDTH_IN, height_in), layout="constrained")


def period_by_dof(periods: np.ndarray, dominant: np.ndarray, dof: str) -> np.ndarray:
    """Period of the mode dominated by ``dof`` (NaN where no mode or several are)."""
    mask = np.asarray(dominant) == DOF.index(dof)
    one = mask.sum(-1) == 1
    return np.where(one, np.where(mask, periods, 0.0).sum(-1), np.nan)


def sensitivity(screening: xr.Dataset) -> Figure:
    """Natural periods against each design variable, one at a time about the baseline
    (dashed), the feasible range about the baseline shaded (figure 5.3)."""
    with matplotlib.rc_context(STYLE):
        fig = _figure(4.6)
        axes = fig.subplots(2, 2, sharey=True).ravel()
        for ax, var in zip(axes, DESIGN_VARIABLES):
            s = screening.sel(variable=var)
            x = s["sensitivity_value"].values
            for dof in ("sway", "yaw", "roll", "heave"):
                t = period_by_dof(s["sensitivity_period"].values, s["sensitivity_dominant_dof"].values, dof)
                ax.semilogy(x, t, color=DOF_COLOURS[dof], label=f"{dof} mode")
            lo, hi = float(s["feasible_lower"]), float(s["feasible_upper"])
            if np.isfinite(lo) and np.isfinite(hi):
                ax.axvspan(lo, hi, color="tab:green", alpha=0.10, lw=0, label="feasible range")
            bad = ~s["sensitivity_feasible"].values.astype(bool)
            if bad.any():
                ax.plot(x[bad], np.full(bad.sum(), 0.9), "x", color="tab:red", ms=3,
                        label="infeasible", transform=ax.get_xaxis_transform())
            ax.axvline(float(s["baseline_value"]), color="k", ls="--", lw=0.8, label="baseline")
            ax.set_xlabel(LABELS[var])
            ax.set_xlim(x.min(), x.max())
        for ax in axes[::2]:
            ax.set_ylabel("natural period [s]")
        axes[0].set_ylim(0.8, 40.0)
        log_ticks(axes[0].yaxis)                     # shared by the four panels
        handles, labels = axes[0].get_legend_handles_labels()
        for ax in axes[1:]:
            for h, lab in zip(*ax.get_legend_handles_labels()):
                if lab not in labels:
                    handles.append(h)
                    labels.append(lab)
        fig.legend(handles, labels, loc="outside lower center", ncol=4)
        return fig


def _grid_slice(screening: xr.Dataset):
    """Grid candidates on the plane of the first two screened variables, through the
    optimum (or the baseline) in the others: (x var, y var, x, y, index array)."""
    variables = screening.attrs["grid_variables"].split()
    grid = screening["kind"].values == "grid"
    ref = screening.attrs["optimum_candidate"] or "baseline"
    keep = grid.copy()
    for var in variables[2:]:
        vals = screening[var].values
        target = float(screening[var].sel(candidate=ref))
        nearest = vals[grid][np.argmin(np.abs(vals[grid] - target))]
        keep &= np.isclose(vals, nearest)
    xv = variables[0]
    yv = variables[1] if len(variables) > 1 else None
    x = np.unique(screening[xv].values[keep])
    y = np.unique(screening[yv].values[keep]) if yv else np.array([0.0])
    index = np.full((y.size, x.size), -1)
    for i in np.flatnonzero(keep):
        ix = np.argmin(np.abs(x - screening[xv].values[i]))
        iy = np.argmin(np.abs(y - screening[yv].values[i])) if yv else 0
        index[iy, ix] = i
    return xv, yv, x, y, index


def _edges(centres: np.ndarray) -> np.ndarray:
    """Cell edges around grid centres (midpoints, ends mirrored)."""
    c = np.asarray(centres, float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[2 * c[0] - mid[0]], mid, [2 * c[-1] - mid[-1]]])


def screening_surface(screening: xr.Dataset, score: str | None = None, tugger: str | None = None) -> Figure:
    """The score over the screened grid (figure 5.4): sway-period contours, infeasible
    region hatched, baseline (white) and optimum (red) marked."""
    score = score or screening.attrs["objective"]
    tugger = tugger or screening.attrs["objective_tugger"]
    label, scale, cmap = SCORES[score]
    xv, yv, x, y, index = _grid_slice(screening)
    values = screening[score].sel(tugger=tugger).values * scale
    sway = period_by_dof(screening["natural_period"].values, screening["dominant_dof"].values, "sway")
    feasible = screening["feasible"].values.astype(bool)
    Z = np.where(index >= 0, values[index], np.nan)
    T = np.where(index >= 0, sway[index], np.nan)
    bad = np.where(index >= 0, ~feasible[index], True)
    points = {"baseline": ("o", "white"), screening.attrs["optimum_candidate"]: ("*", "red")}
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.8)
        ax = fig.subplots()
        if yv is None:
            ax.plot(x, Z[0], color="k")
            ax.fill_between(x, 0, 1, where=bad[0], transform=ax.get_xaxis_transform(),
                            facecolor="none", hatch="///", edgecolor="grey", lw=0)
            ax.set_ylabel(label)
            for name, (marker, colour) in points.items():
                if name in screening["candidate"].values:
                    c = screening.sel(candidate=name)
                    ax.plot(float(c[xv]), float(c[score].sel(tugger=tugger)) * scale, marker,
                            mfc=colour, mec="k", ms=8, label=name)
        else:
            mesh = ax.pcolormesh(x, y, np.ma.masked_invalid(Z), cmap=cmap, shading="nearest")
            fig.colorbar(mesh, ax=ax, label=f"{label}, tugger {tugger}")
            if np.isfinite(T).sum() > 3:
                cs = ax.contour(x, y, np.ma.masked_invalid(T), colors="k", linewidths=0.6,
                                levels=np.arange(np.floor(np.nanmin(T)), np.ceil(np.nanmax(T)) + 0.5, 0.5))
                ax.clabel(cs, fmt="%.1f s", fontsize=6)
            xe, ye = _edges(x), _edges(y)
            for iy, ix in zip(*np.nonzero(bad)):
                ax.add_patch(Rectangle((xe[ix], ye[iy]), xe[ix + 1] - xe[ix], ye[iy + 1] - ye[iy],
                                       facecolor="none", edgecolor="grey", hatch="////", lw=0.0))
            for name, (marker, colour) in points.items():
                if name in screening["candidate"].values:
                    c = screening.sel(candidate=name)
                    ax.plot(float(c[xv]), float(c[yv]), marker, mfc=colour, mec="k", ms=9 if marker == "*" else 6,
                            label=f"{name}: T_sway {float(sway[list(screening['candidate'].values).index(name)]):.2f} s")
            ax.set_ylabel(LABELS[yv])
        ax.set_xlabel(LABELS[xv])
        handles, labels = ax.get_legend_handles_labels()
        handles.append(Patch(facecolor="none", edgecolor="grey", hatch="////"))
        labels.append("infeasible")
        ax.legend(handles, labels, loc="lower left")
        ax.set_title("screening: sway-period contours [s]" if yv else "screening")
        return fig


def geometry(screening: xr.Dataset) -> Figure:
    """Baseline and optimised rigging in the transverse (Y-Z) and longitudinal (X-Z)
    planes: hinge at the origin, wires, jacket outline to its tip, the waterline and
    the splash-clearance line, with each design's clearance."""
    hinge_h = float(screening.attrs["hinge_height_m"])
    tip_below = float(screening.attrs["padeye_to_tip_m"])
    clearance = float(screening.attrs["splash_clearance_m"])
    shown = [("baseline", "black", "-")]
    opt = screening.attrs["optimum_candidate"]
    if opt:
        shown.append((opt, "tab:red", "--"))
    with matplotlib.rc_context(STYLE):
        fig = _figure(3.9)
        axes = fig.subplots(1, 2, sharey=True)
        for ax, (h, title) in zip(axes, ((1, "transverse view (Y-Z), looking forward"),
                                         (0, "longitudinal view (X-Z), looking to port"))):
            for name, colour, ls in shown:
                c = screening.sel(candidate=name)
                depth = float(c["cog_depth"])
                anchor = c["anchor"].values
                pad = c["padeye"].values + np.array([0.0, 0.0, -depth])
                for a, b in zip(anchor, pad):
                    ax.plot([a[h], b[h]], [a[2], b[2]], color=colour, ls=ls, lw=1.0)
                ax.plot(anchor[:, h], anchor[:, 2], "v", color=colour, ms=4)
                ax.plot(pad[:, h], pad[:, 2], "o", color=colour, ms=3, mfc="white")
                top = pad[:, 2].mean()
                tip = top - tip_below
                lo, hi = pad[:, h].min(), pad[:, h].max()
                ax.add_patch(Rectangle((lo, tip), hi - lo, top - tip, fill=False, ec=colour, ls=ls, lw=0.7))
                margin = tip - (-hinge_h + clearance)
                label = "optimised" if name == opt else name
                ax.plot([], [], color=colour, ls=ls,
                        label=f"{label}: drop {float(c['drop_height']):.2f} m, tip {tip + hinge_h:.2f} m "
                              f"above water (margin {margin:.2f} m)")
            ax.axhline(-hinge_h, color="tab:blue", lw=1.0, label="waterline")
            ax.axhline(-hinge_h + clearance, color="tab:blue", lw=0.7, ls=":",
                       label=f"splash clearance {clearance:g} m")
            ax.plot([0], [0], "s", color="red", ms=5, label="hinge (origin)")
            ax.set_title(title)
            ax.set_xlabel("y to port [m]" if h == 1 else "x forward [m]")
            ax.set_aspect("equal", adjustable="datalim")
        axes[0].set_ylabel("z up from the hinge [m]")
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=2)
        return fig
