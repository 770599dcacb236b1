"""The operability curves of ``workability.nc`` as the chapters draw and quote them: the
limiting Hs over Tz, per criterion too (:func:`limit_curves`), the steepness ceiling on a
fine Tz grid (:func:`ceiling_curve`) and the runs of Tz where the same thing limits Hs
(:func:`governing_runs`).
"""

from __future__ import annotations

import warnings

import numpy as np
import xarray as xr


def limit_curves(work: xr.Dataset):
    """Limiting Hs, and per criterion, over Tz: on the fine operability grid when the
    workability dataset has it, else at the scatter's Tz centres (dim 'tz' either way)."""
    if "hs_limit_curve" in work:
        return (work["hs_limit_curve"].rename(tz_curve="tz"),
                work["hs_limit_curve_criterion"].rename(tz_curve="tz"))
    return work["hs_limit"], work["hs_limit_criterion"]


def ceiling_curve(work: xr.Dataset, tz_lo: float, tz_hi: float):
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


def governing_runs(work, combo, heading) -> list[tuple[str, float, float]]:
    """Along the operability curve: runs of Tz where the same thing limits Hs.

    Returns [(label, tz_from, tz_to)], label a criterion name or 'steepness'.
    """
    fine = "hs_limit_curve" in work           # the operability grid when present
    names = (("hs_limit_curve", "hs_limit_curve_criterion", "steepness_limit_curve") if fine
             else ("hs_limit", "hs_limit_criterion", "steepness_limit"))
    hl, hc, ceiling = (work[n].rename(tz_curve="tz") if fine else work[n] for n in names)
    hl = hl.sel(candidate=combo[0], tugger=combo[1], heading=heading)
    hc = hc.sel(candidate=combo[0], tugger=combo[1], heading=heading)
    ok = np.isfinite(hl.values)
    tz = hl["tz"].values[ok]
    per_criterion = hc.transpose("tz", "criterion").values[ok]
    with warnings.catch_warnings():                     # a row of NaN: no criterion limits
        warnings.simplefilter("ignore", RuntimeWarning)
        lowest = np.nanmin(per_criterion, axis=1)
    steep = ceiling.transpose("tz").values[ok] <= lowest * (1 + 1e-9)
    names = hc["criterion"].values
    labels = ["steepness" if is_steep else str(names[int(np.nanargmin(row))])
              for is_steep, row in zip(steep, per_criterion)]
    runs = []
    for lab, t in zip(labels, tz):
        if runs and runs[-1][0] == lab:
            runs[-1][2] = float(t)
        else:
            runs.append([lab, float(t), float(t)])
    return [tuple(r) for r in runs]
