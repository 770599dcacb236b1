"""The hours of the legs given by their own seas (measured spectra, partitions,
Torsethaugen) as cells of the hindcast long-term voyage extreme
(:func:`jls.assessment.voyage.hindcast_long_term`): each such hour's level is its
utilisation on its own directional sea (``measured_response.nc`` ``utilisation``) times
the criterion's limit, as the route simulation takes it.

The voyage formula needs each hour's sigma and response zero-crossing period; the own
sea's utilisation is an MPM over the exposure, sigma sqrt(2 ln N). The hour's sigma is
the JONSWAP's on its (Hs, Tz) moved by the factor level / MPM_JONSWAP (exactly the route
simulation's rule), and its up-crossing period is the JONSWAP's response period
(``measured_response.nc`` does not hold the own sea's): for the relative sway, narrow-banded
about the pendulum period, the spectrum's shape hardly moves it; for the other criteria it
is an assumption, stated in ``voyage.nc`` (attribute ``own_sea_not_used``). An hour whose
JONSWAP MPM is 0 takes sigma = level / sqrt(2 ln N), N the exposure's cycles at that period
(or the study's fixed N, ``assessment.mpm_cycles``). An hour met at no heading (its
utilisation NaN) keeps the JONSWAP, as in the route simulation.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.hourly import at_hours
from jls.response.statistics import FIXED_CYCLES_STUDY

__all__ = ["own_cells"]


def _moved(u, s_j, m_j, t_j, lim, exposure_s, cycles):
    """The own-sea sigma of hours of utilisation ``u`` (rows, hours) from the JONSWAP's
    sigma, MPM and response period at the hours (module docstring); NaN u keeps s_j."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        level = u * lim[:, None]
        n_c = exposure_s / t_j if cycles == "response" else np.full_like(t_j, FIXED_CYCLES_STUDY)
        k_n = np.sqrt(2.0 * np.log(np.maximum(np.nan_to_num(n_c, nan=1.0), 1.0)))
        bare = np.where(level == 0, 0.0, level / k_n)
        moved = np.where(m_j > 0, s_j * (level / np.where(m_j > 0, m_j, 1.0)), bare)
    return np.where(np.isnan(u), s_j, moved)


def own_cells(own, hours, known, parts, ih, hp, stats, options, n_grid, exposure, rows=64):
    """The hindcast cells of :func:`hindcast_long_term` with the hours of the legs given by
    their own seas moved to columns of their own: (sigma, tz_response with those columns
    appended, the cells). ``parts``: the JONSWAP cells in the order (leg, heading met).
    Memory: the appended columns (options x own hours x headings), filled ``rows`` options
    at a time."""
    sig, tzr, mpm, lim = stats
    dims, shape, coords = options
    n = sig.shape[0]
    exposure_s, cycles = exposure[0] * 3600.0, exposure[1]
    o = own.reindex(leg=hours["leg"].values, time=hours["time"].values)
    if "criterion" in dims:
        o = o.reindex(criterion=coords["criterion"].values)
    o = o.sel({d: coords[d] for d in dims if d in o.dims and d != "criterion" and d in coords})
    template = xr.DataArray(np.zeros(shape), dims=dims, coords=coords)
    mine = o.notnull().any([d for d in o.dims if d != "leg"]).values
    todo, p = [], 0                                  # (part index, leg, heading index a, heading)
    for k in range(known.shape[0]):
        for a, heading, prob in zip(ih, hp["heading"].values, hp.values[k]):
            if prob > 0:
                if mine[k]:
                    todo.append((p, k, a, heading))
                p += 1
    total = sum(parts[q][0].size for q, *_ in todo)
    if not total:
        return sig, tzr, parts
    col = sig.shape[1]
    sig = np.concatenate([sig, np.empty((n, total))], axis=1)
    tzr = np.concatenate([tzr, np.empty((n, total))], axis=1)
    out = list(parts)
    for q, k, a, heading in todo:
        part = parts[q]
        ok_k = o.isel(leg=k)
        if "heading" in ok_k.dims:
            ok_k = ok_k.sel(heading=float(heading))
        u = ok_k.broadcast_like(template).transpose(*dims, "time").values.reshape(n, -1)[:, known[k]]
        f = part[2]
        w = (part[0] - a * n_grid, part[1] - a * n_grid, 1.0 - f, f)
        block, m = slice(a * n_grid, (a + 1) * n_grid), part[0].size
        idx = np.arange(col, col + m)
        for r0 in range(0, n, rows):
            r = slice(r0, min(r0 + rows, n))
            t_j = at_hours(tzr[r, block], w)
            sig[r, col:col + m] = _moved(u[r], at_hours(sig[r, block], w) * part[3],
                                         at_hours(mpm[r, block], w) * part[3], t_j, lim[r], exposure_s, cycles)
            tzr[r, col:col + m] = t_j
        col += m
        out[q] = (idx, idx, np.zeros(m), np.ones(m), part[4])
    return sig, tzr, out
