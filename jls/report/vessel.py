"""The report's chapter "Vessel and hinge motion": the hinge's rigid-body motion with the
hull, peak RAO amplitudes (round-off reported as no motion), and the figures of the hinge
excitation and of the jacket's relative motion per unit wave amplitude.

The hinge turns with the hull, so its roll is the vessel's roll: the figure draws it once.
A motion that is round-off at every assessed heading (hinge yaw in beam seas) gets no
panel; the table says so. The relative transfer functions are drawn over
:data:`DECADES` decades below their largest amplitude, the range that carries the
response (below it the short-period RAOs hold only the BEM's numerical noise)."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.names import RELATIVE_ROLL, RELATIVE_SWAY, RELATIVE_YAW
from jls.report import long_tables
from jls.report.context import Context, governing_heading, heading
from jls.report.contract import ROUNDOFF_RELATIVE, complex_var, negligible, reference_amplitude
from jls.report.markup import figure, ref, t, table
from jls.report.style import (
    CAND_COLOURS,
    STYLE,
    TRANSFER_DECADES,
    Task,
    combo_style,
    legend_columns,
    log_ticks,
    new_figure,
    save,
    transfer_range,
)

DECADES = TRANSFER_DECADES


def figure_plan(cx: Context) -> list[Task]:
    n_head = cx.resp.sizes.get("heading", 1)
    return [Task("hinge_raos", lambda d: hinge_raos(cx.vessel, cx.plant, cx.dg, d), 3.0),
            Task("relative_transfer", lambda d: relative_transfer(cx.resp, cx.plant, cx.dg, d),
                 4.0 * n_head)]


def chapter(cx: Context) -> str:
    v, dg = cx.vessel, cx.dg
    out = [heading("vessel", "Vessel and hinge motion")]
    out.append(f"The hinge of the lift beams at {t(_vec(v.attrs.get('hinge_m')))} m from the RAO "
               f"reference point {t(_vec(v.attrs.get('reference_point_m')))} moves with the hull as a "
               "rigid body: $y_b = y + psi x_B - phi z_B$, $z_b = z + phi y_B - theta x_B$ "
               "(eq. 3.1); its rotations are the vessel's. The long lever arm to the hinge turns "
               "vessel roll into hinge sway, which drives the pendulum.\n")
    rows = long_tables.peak_rows(cx, v["heading"].values)
    shown = ""
    if long_tables.is_long(rows):
        gov = governing_heading(cx)
        rows = long_tables.peak_rows(cx, [gov])
        shown = (f" Shown: the governing heading, {gov:g}° (where the baseline rigging without "
                 "tugger has the lowest limiting Hs); every heading is in the appendix.")
    out.append(table("Peak RAO amplitudes in the RAO range; an amplitude below "
                     f"{ROUNDOFF_RELATIVE:g} of the largest of its kind (translation or rotation) "
                     "at the heading is round-off and reported as no motion. The hinge's roll is "
                     "the vessel's." + shown, ["heading", "motion", "peak", "at period [s]"],
                     rows, align="(left, left, right, right)", label="tab-peak-rao"))
    quiet = [name for name, *_ in hinge_panels(v) if name.startswith("hinge") and not _moves(v, name)]
    cap = ("Hinge excitation amplitudes against wave period at the assessed headings: hinge sway, "
           "heave and roll (the hinge turns with the hull, so its roll is the vessel's roll), and "
           "the vessel's sway at the RAO reference point; dotted: baseline sway period.")
    if quiet:
        cap = t(cap + f" Not drawn: {', '.join(quiet)}, round-off at every assessed heading (") \
            + ref("tab-peak-rao", "table") + ")."
    out.append(figure(cx.figs["hinge_raos"], cap, caption_raw=bool(quiet)))
    out.append(figure(cx.figs["relative_transfer"], "Relative sway and relative yaw of the jacket "
                      "against the hinge per unit wave amplitude (colour: rigging candidate, line "
                      f"style: tugger setting), over {DECADES:g} decades below the largest amplitude "
                      "of each panel; dotted: sway periods. " + dg.plot.caption()))
    return "\n".join(out)


def hinge_panels(vessel: xr.Dataset) -> list:
    """(name, title, amplitude, scale, rotation) of the hinge-excitation panels: hinge sway,
    heave, roll and yaw, and the vessel's sway at its RAO reference point."""
    hinge = complex_var(vessel, "hinge")
    rao = complex_var(vessel, "rao")
    return [("hinge sway", "hinge sway $y_b$ [m/m]", hinge.sel(dof="sway"), 1.0, False),
            ("hinge heave", "hinge heave $z_b$ [m/m]", hinge.sel(dof="heave"), 1.0, False),
            ("hinge roll", "hinge roll $\\varphi_b$ = vessel roll [deg/m]", hinge.sel(dof="roll"),
             180 / np.pi, True),
            ("hinge yaw", "hinge yaw $\\psi_b$ [deg/m]", hinge.sel(dof="yaw"), 180 / np.pi, True),
            ("vessel sway", "vessel sway [m/m]", rao.sel(vessel_dof="sway"), 1.0, False)]


def _moves(vessel: xr.Dataset, name: str) -> bool:
    """Whether the panel's motion is more than round-off at some assessed heading."""
    _, _, da, _, rot = next(p for p in hinge_panels(vessel) if p[0] == name)
    return any(not negligible(np.abs(da.sel(heading=h).values), reference_amplitude(vessel, h, rot))
               for h in vessel["heading"].values)


def _vec(x) -> str:
    try:
        return "(" + ", ".join(f"{float(a):.3f}" for a in x) + ")"
    except TypeError:
        return "(not stated)"


def hinge_raos(vessel: xr.Dataset, plant: xr.Dataset, dg, out_dir) -> Path:
    """Hinge excitation amplitudes against wave period (:func:`hinge_panels`, those with
    motion at some heading), one line per heading."""
    period = 2 * np.pi / vessel["omega"].values
    t_sway = float(plant["natural_period"].sel(candidate=dg.baseline).isel(mode=0))
    panels = [p for p in hinge_panels(vessel) if _moves(vessel, p[0])]
    n_col = 2 if len(panels) <= 4 else 3
    n_row = int(np.ceil(len(panels) / n_col))
    with matplotlib.rc_context(STYLE):
        fig = new_figure(0.6 + 1.9 * n_row)
        axes = np.atleast_1d(fig.subplots(n_row, n_col, sharex=True, squeeze=False).ravel())
        for ax, (_, title, da, scale, rot) in zip(axes, panels):
            for j, h in enumerate(vessel["heading"].values):
                amp = np.abs(da.sel(heading=h).values)
                if negligible(amp, reference_amplitude(vessel, h, rot)):
                    amp = np.zeros_like(amp)                 # round-off, not motion
                ax.plot(period, amp * scale, color=f"C{j}", label=f"heading {h:g}°")
            ax.axvline(t_sway, color="k", ls=":", lw=0.8)
            ax.set_title(title)
            ax.set_xlim(max(period.min(), 3.0), min(period.max(), 30.0))
            ax.set_ylim(bottom=0)
        for ax in axes[len(panels):]:
            ax.set_visible(False)
        for ax in axes[max(0, len(panels) - n_col):len(panels)]:
            ax.set_xlabel("wave period [s]")
        axes[0].legend(loc="upper left")
        axes[min(1, len(panels) - 1)].annotate(f"baseline sway period {t_sway:.2f} s", (t_sway, 0),
                                               xytext=(3, 3), textcoords="offset points", fontsize=6,
                                               rotation=90, va="bottom")
        return save(fig, out_dir, "hinge_raos")


def relative_transfer(resp: xr.Dataset, plant: xr.Dataset, dg, out_dir) -> Path:
    """Relative sway and yaw per unit wave amplitude for the shown combinations."""
    H = complex_var(resp, "transfer").rename(shown_candidate="candidate")
    stored = set(H["candidate"].values.tolist())      # the baseline and named candidates
    period = 2 * np.pi / resp["omega"].values
    heads = resp["heading"].values
    with matplotlib.rc_context(STYLE):
        fig = new_figure(2.9 + 1.6 * (len(heads) - 1))
        axes = np.atleast_2d(fig.subplots(len(heads), 2, sharex=True, squeeze=False))
        for k, h in enumerate(heads):
            rot = [x for x in (RELATIVE_ROLL, RELATIVE_YAW) if x in H["response"].values]
            scale_rot = float(np.nanmax(np.abs(H.sel(heading=h, response=rot).values))) if rot else 0.0
            for ax, r, unit in ((axes[k, 0], RELATIVE_SWAY, "m/m"), (axes[k, 1], RELATIVE_YAW, "deg/m")):
                amps = {combo: np.abs(H.sel(candidate=combo[0], tugger=combo[1], heading=h, response=r).values)
                        for combo in dg.plot.combos if combo[0] in stored}
                ref = scale_rot if r == RELATIVE_YAW else float(np.nanmax(np.abs(H.sel(heading=h).values)))
                if negligible(np.array(list(amps.values())), ref):
                    ax.text(0.5, 0.5, f"no {r.split('_')[1]} motion at this heading", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="0.3")
                    for combo in amps:
                        ax.plot([], [], lw=0.9, **combo_style(dg, combo))
                else:
                    for combo, amp in amps.items():
                        ax.semilogy(period, amp, lw=0.9, **combo_style(dg, combo))
                    ax.set_ylim(*transfer_range(amps.values()))
                    log_ticks(ax.yaxis)
                for i, cand in enumerate(dg.plot.candidates):
                    ax.axvline(float(plant["natural_period"].sel(candidate=cand).isel(mode=0)),
                               color=CAND_COLOURS[i % len(CAND_COLOURS)], ls=":", lw=0.7)
                ax.set_title(f"{r.replace('_', ' ')} [{unit}], heading {h:g}°")
                ax.set_xlim(3.0, min(period.max(), 25.0))
        for ax in axes[-1]:
            ax.set_xlabel("wave period [s]")
        handles, labels = axes[0, 0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncol=legend_columns(labels))
        return save(fig, out_dir, "relative_transfer")


__all__ = ["DECADES", "chapter", "figure_plan", "hinge_panels", "hinge_raos", "relative_transfer",
           "transfer_range"]
