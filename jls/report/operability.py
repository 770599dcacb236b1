"""The report's chapter "Operability": the limiting Hs against Tz (the study's eq. 2.7) per
rigging candidate, heading and tugger setting, what limits it along the curve, and the
table of limiting Hs per Tz."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import xarray as xr

from jls.report.context import Context, heading
from jls.report.contract import criterion_label, limit_text
from jls.report.curves import ceiling_curve, governing_runs, limit_curves
from jls.report.markup import cell, figure, num, t, table
from jls.report.style import STYLE, TUG_STYLES, Task, legend_columns, new_figure, operability_top, save

MAX_TZ_ROWS = 40
MAX_LIMIT_COLUMNS = 8


def figure_plan(cx: Context) -> list[Task]:
    n_head = cx.resp.sizes.get("heading", 1)
    return [Task("operability", lambda d: operability(cx.work, cx.sea, cx.dg, d),
                 1.0 + n_head * len(cx.dg.plot.candidates))]


def chapter(cx: Context) -> str:
    dg, work = cx.dg, cx.work
    out = [heading("operability", "Operability")]
    out.append("The largest workable significant wave height at each zero-crossing period follows "
               "from the unit-Hs response because the model is linear (eq. 2.7):\n"
               "$ H_(s,lim)(T_z) = min(min_k X_(max,k) / X_k (H_s = 1 \"m\", T_z), "
               "H_(s,\"steep\")(T_z)) $\n"
               "with $X_k$ the most probable maximum of criterion $k$ and the wave-steepness "
               "ceiling as the upper bound, as in the study's figure 6.7.\n")
    out.append(figure(cx.figs["operability"], "Limiting Hs against Tz, one panel per rigging "
                      "candidate (and heading), one line per tugger setting; thin grey: the "
                      f"{dg.baseline} rigging without tugger for comparison; dashed grey: the "
                      "steepness ceiling, which leaves the top of a panel where it no longer "
                      "limits (the y-range shows the limiting curves). " + dg.plot.caption()))
    groups: dict[str, list[str]] = {}
    heads = work["heading"].values
    for combo in dg.table.combos:
        for h in heads:
            runs = governing_runs(work, combo, h)
            txt = "; ".join(f"{'steepness ceiling' if lab == 'steepness' else criterion_label(lab)} "
                            f"{a:g}-{b:g} s" for lab, a, b in runs)
            groups.setdefault(txt, []).append(f"{combo[0]} / {combo[1]}"
                                              + (f" at {h:g}°" if len(heads) > 1 else ""))
    n_all = len(dg.table.combos) * len(heads)
    rows = [["all" if len(who) == n_all else "; ".join(who), txt] for txt, who in groups.items()]
    out.append(table("What limits Hs along the operability curve, by Tz range (candidate / tugger)."
                     + dg.table.table_caption(),
                     ["combinations", "governing (Tz range)"], rows,
                     columns="(1fr, 1fr)", align="(left, left)"))
    hl = work["hs_limit"]
    tz = hl.dropna("tz", how="all")["tz"].values
    step = max(1, int(np.ceil(tz.size / MAX_TZ_ROWS)))
    tz = tz[::step]
    shown = dg.table.combos
    chunks = [shown[i:i + MAX_LIMIT_COLUMNS] for i in range(0, len(shown), MAX_LIMIT_COLUMNS)]
    for h in heads:
        for k, cols in enumerate(chunks):
            header = ["Tz [s]", "ceiling [m]"] + [cell(f"{t(c[0], wrap=True)} \\ {t(c[1])}", raw=True)
                                                  for c in cols]
            rows = [[num(z, 2), num(work["steepness_limit"].sel(tz=z), 2),
                     *[num(hl.sel(candidate=c[0], tugger=c[1], heading=h, tz=z), 2) for c in cols]]
                    for z in tz]
            part = f", part {k + 1} of {len(chunks)}" if len(chunks) > 1 else ""
            out.append(table(f"Limiting Hs [m] per Tz at heading {h:g}°{part}"
                             + (f" (every {step}th period)" if step > 1 else "") + "."
                             + dg.table.table_caption(),
                             header, rows, size="8pt" if len(header) <= 7 else "7pt",
                             columns="(auto, auto" + ", 1fr" * len(cols) + ")"))
    return "\n".join(out)


# -- figure ---------------------------------------------------------------------------
TUG_COLOURS = ["black", "tab:blue", "tab:orange", "tab:green"]


def operability(work: xr.Dataset, sea: xr.Dataset, dg, out_dir) -> Path:
    """Limiting Hs against Tz (the study's figure 6.7), one panel per shown candidate and
    heading, one line per shown tugger, the baseline without tugger as a grey reference;
    the y-range covers the limiting curves and the steepness ceiling is clipped."""
    heads = work["heading"].values
    curve, per_criterion = limit_curves(work)
    ceiling = (work["steepness_limit_curve"].rename(tz_curve="tz") if "steepness_limit_curve" in work
               else work["steepness_limit"])
    tz_all = curve["tz"].values
    panels = [(h, c) for h in heads for c in dg.plot.candidates]
    n_col = 1 if len(panels) == 1 else 2
    n_row = int(np.ceil(len(panels) / n_col))
    with matplotlib.rc_context(STYLE):
        fig = new_figure(0.9 + 2.3 * n_row)
        axes = np.atleast_1d(fig.subplots(n_row, n_col, squeeze=False, sharex=True).ravel())
        base = (dg.baseline, dg.no_tugger)
        for ax, (h, cand) in zip(axes, panels):
            sel = dict(heading=h)
            cl = ceiling.sel(tz=curve["tz"]).values if "tz" in ceiling.dims else ceiling.values
            lines = [(curve.sel(candidate=cand, tugger=tg, **sel).values, cl) for tg in dg.plot.tuggers]
            lines.append((curve.sel(candidate=base[0], tugger=base[1], **sel).values, cl))
            top = operability_top(lines)
            tz_f, ceil_f = ceiling_curve(work, float(np.nanmin(tz_all)), float(np.nanmax(tz_all)))
            ax.plot(tz_f, ceil_f, color="0.5", ls="--", lw=1.1, label="steepness ceiling")
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
        fig.legend(list(seen.values()), list(seen), loc="outside lower center", ncol=legend_columns(list(seen)))
        return save(fig, out_dir, "operability")


__all__ = ["chapter", "figure_plan", "operability", "operability_top"]
