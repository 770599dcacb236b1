"""Figure of the chapter "Wave spectra": per leg, where the energy meets the resonance: the
leg's typical wave spectra against the relative-sway transfer function (per unit wave
amplitude) of the recommended rigging and tugger at the leg's most probable heading.

The leg's typical spectra:

* a leg whose sea is partitions or measured spectra: the probability-weighted mean
  frequency spectrum of its hours (``spectrum_mean`` of ``measured_response.nc``);
* a JONSWAP or Torsethaugen leg: the spectra of its :data:`TOP_CELLS` most probable cells
  (``cell_probability`` of ``sea_states.nc`` summed over the headings), each the sea model
  the assessment integrates on the cell's assessed Hs and period: the JONSWAP of the
  response's gamma on (Hs, Tz), or the Torsethaugen sum of wind sea and swell on (Hs, Tp).

The transfer function is ``transfer`` of ``response.nc`` (stored for the baseline and the
named candidates; a recommendation without one is said so on its panel), the sway period
the plant dataset's. Every number drawn is read from those datasets.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np

from jls.assessment.workability import assessed_hs
from jls.names import RELATIVE_SWAY
from jls.report.contract import complex_var
from jls.report.style import STYLE, new_figure, save
from jls.sea.sea_state import torsethaugen_systems
from jls.sea.spectra import jonswap, tp_from_tz

__all__ = ["NAME", "TOP_CELLS", "leg_spectra", "leg_heading", "sea_transfer"]

NAME = "spectra_transfer"
TOP_CELLS = 3
PERIOD_RANGE_S = (3.0, 25.0)
LONG = {"wind": "long-crested", "swell": "long-crested"}     # 1-D spectra: directions do not enter


def leg_heading(cx, leg) -> float:
    """The leg's most probable relative heading (sea_states.nc)."""
    p = cx.sea["cell_probability"].sel(leg=leg).sum(("hs", "tz"))
    return float(p["heading"].values[int(np.argmax(p.values))])


def leg_spectra(cx, leg, model: str, omega) -> list[tuple[str, np.ndarray]]:
    """[(label, S(omega) [m^2 s/rad])] of the leg's typical spectra (module docstring)."""
    m = cx.measured
    if model in ("partitions", "measured") and m is not None and "spectrum_mean" in m:
        S = m["spectrum_mean"].sel(leg=leg)
        S = np.interp(omega, m["omega"].values, S.values, left=0.0, right=0.0)
        hours = int(m["hours"].sel(leg=leg))
        return [(f"mean of {hours} hours ({model})", S)]
    gamma = float(cx.resp.attrs.get("gamma", 3.3))
    p = cx.sea["cell_probability"].sel(leg=leg).sum("heading").transpose("hs", "tz")
    hs = assessed_hs(cx.sea, str(cx.work.attrs.get("hs_in_bin", "centre"))).sel(leg=leg).values
    total = float(p.sum())
    order = np.argsort(-p.values, axis=None, kind="stable")[:TOP_CELLS]
    out = []
    for k in order:
        i, j = np.unravel_index(k, p.shape)
        if p.values[i, j] <= 0:
            break
        h, per = float(hs[i]), float(p["tz"].values[j])
        share = 100 * float(p.values[i, j]) / total
        if model == "torsethaugen":
            S = sum(s.spectrum(omega) for s in torsethaugen_systems(h, "tp", per, from_deg=0.0, spreading=LONG))
            out.append((f"Hs {h:g} m, Tp {per:.3g} s ({share:.0f} %)", np.asarray(S, float)))
        else:
            S = jonswap(omega, h, float(tp_from_tz(per, gamma)), gamma)
            out.append((f"Hs {h:g} m, Tz {per:.3g} s ({share:.0f} %)", np.asarray(S, float)))
    return out


def sea_transfer(cx, leg_models: dict, out_dir) -> Path:
    """The figure (module docstring); ``leg_models``: leg -> sea model ("jonswap" or the
    leg's declared one)."""
    best = cx.dg.best
    resp = cx.resp
    omega = resp["omega"].values
    period = 2 * np.pi / omega
    H = complex_var(resp, "transfer")
    H = H.rename(shown_candidate="candidate") if H is not None else None
    stored = set(H["candidate"].values.tolist()) if H is not None else set()
    t_sway = (float(cx.plant["natural_period"].sel(candidate=best[0]).isel(mode=0))
              if best[0] in cx.plant["candidate"].values else None)
    legs = list(leg_models)
    n_col = 2 if len(legs) > 3 else 1
    n_row = -(-len(legs) // n_col)
    with matplotlib.rc_context(STYLE):
        fig = new_figure(0.6 + 1.9 * n_row)
        axes = np.atleast_1d(fig.subplots(n_row, n_col, squeeze=False).ravel())
        for ax, leg in zip(axes, legs):
            model = leg_models[leg]
            head = leg_heading(cx, leg)
            for k, (label, S) in enumerate(leg_spectra(cx, leg, model, omega)):
                ax.plot(period, S, color=f"C{k}", lw=1.0, label=label)
            ax.set_ylabel("S [m² s/rad]")
            ax.set_ylim(bottom=0)
            ax.set_xlim(*PERIOD_RANGE_S)
            ax.set_title(f"{leg} ({model}), heading {head:g}°")
            ax2 = ax.twinx()
            if best[0] in stored:
                amp = np.abs(H.sel(candidate=best[0], tugger=best[1], heading=head, response=RELATIVE_SWAY).values)
                ax2.plot(period, amp, color="k", ls="--", lw=0.9, label="|H| relative sway")
                ax2.set_ylim(bottom=0)
            else:
                ax2.text(0.5, 0.9, f"no stored transfer function of {best[0]}", transform=ax.transAxes,
                         ha="center", fontsize=6, color="0.3")
            ax2.set_ylabel("|H| [m/m]")
            if t_sway is not None:
                ax.axvline(t_sway, color="k", ls=":", lw=0.7)
            h1, l1 = ax.get_legend_handles_labels()
            h2, l2 = ax2.get_legend_handles_labels()
            ax.legend(h1 + h2, l1 + l2, loc="upper left", fontsize=5.5)
        for ax in axes[len(legs):]:
            ax.set_visible(False)
        for ax in axes[max(0, len(legs) - n_col):len(legs)]:
            ax.set_xlabel("wave period [s]")
        return save(fig, out_dir, NAME)
