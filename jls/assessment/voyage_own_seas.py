"""The legs given by their own seas (measured spectra, partitions, Torsethaugen) as
cells of the voyage extremes (:mod:`jls.assessment.voyage`):

* **The scatter-table extreme** (:func:`table_own_cells`, used by
  :func:`jls.assessment.voyage.long_term_extreme` and ``exceedance_at_levels``): such a
  leg's binned JONSWAP cells are replaced by its records (each hour, or a table's cell) at
  each relative heading, with the record's probability at the heading
  (``measured_response.nc`` ``probability``) and its own sea's up-crossing period
  (``tz_response_own``: the functions of ``jls response``) with the sigma whose MPM there
  is the record's level (:func:`jls.assessment.hourly.own_sigma`). A record's
  share of the up-crossings is credited to the scatter cell it is binned in.
* **The hindcast extreme** (:func:`own_cells`, used by
  :func:`jls.assessment.voyage.hindcast_long_term`): each own-sea hour's level is its
  utilisation times the criterion's limit, as the route simulation takes it, and its sigma
  and period are its own sea's (:func:`jls.assessment.hourly.own_hour_statistics`, the one
  rule of both; an older ``measured_response.nc`` without them: the JONSWAP's sigma moved
  by level / MPM at the JONSWAP's period). An hour met at no heading (its utilisation NaN)
  keeps the JONSWAP, as in the route simulation.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.hourly import at_hours, own_hour_statistics

__all__ = ["own_cells", "table_own_cells", "own_criteria_missing"]


def own_cells(own, hours, known, parts, ih, hp, stats, options, n_grid, exposure, rows=64):
    """The hindcast cells of :func:`hindcast_long_term` with the hours of the legs given by
    their own seas moved to columns of their own: (sigma, tz_response with those columns
    appended, the cells). ``parts``: the JONSWAP cells in the order (leg, heading met).
    Memory: the appended columns (options x own hours x headings), filled ``rows`` options
    at a time."""
    sig, tzr, mpm, lim = stats
    dims, shape, coords = options
    n = sig.shape[0]
    own = own if isinstance(own, xr.Dataset) else own.to_dataset(name="utilisation")
    o = own.reindex(leg=hours["leg"].values, time=hours["time"].values)
    if "criterion" in dims:
        o = o.reindex(criterion=coords["criterion"].values)
    o = o.sel({d: coords[d] for d in dims if d in o.dims and d != "criterion" and d in coords})
    template = xr.DataArray(np.zeros(shape), dims=dims, coords=coords)
    mine = o["utilisation"].notnull().any([d for d in o["utilisation"].dims if d != "leg"]).values
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
        at = {v: ok_k[v].broadcast_like(template).transpose(*dims, "time").values.reshape(n, -1)[:, known[k]]
              for v in ok_k.data_vars}
        f = part[2]
        w = (part[0] - a * n_grid, part[1] - a * n_grid, 1.0 - f, f)
        block, m = slice(a * n_grid, (a + 1) * n_grid), part[0].size
        idx = np.arange(col, col + m)
        for r0 in range(0, n, rows):
            r = slice(r0, min(r0 + rows, n))
            with np.errstate(invalid="ignore", over="ignore"):
                level = at["utilisation"][r] * lim[r, None]
            s, t = own_hour_statistics(level, at_hours(sig[r, block], w) * part[3],
                                       at_hours(mpm[r, block], w) * part[3], at_hours(tzr[r, block], w),
                                       at["tz_response"][r] if "tz_response" in at else None, *exposure)
            sig[r, col:col + m], tzr[r, col:col + m] = s, t
        col += m
        out[q] = (idx, idx, np.zeros(m), np.ones(m), part[4])
    return sig, tzr, out


def own_criteria_missing(own: xr.Dataset, criteria) -> list:
    """The ``criteria`` ``own`` (:func:`table_own_cells`) has no statistics of: a leg
    whose own sea lacks any of them keeps its JONSWAP cells."""
    have = set(own["criterion"].values.tolist()) if "criterion" in own.coords else set()
    return [c for c in criteria if c not in have]


def table_own_cells(own: xr.Dataset, weight: xr.DataArray, duration_h: xr.DataArray, options):
    """The own-sea cells of the legs of ``own`` for :func:`jls.assessment.voyage.long_term_extreme`:
    (legs replaced (indices into ``weight``'s legs), sigma (n, m) [level units],
    tz_response (n, m) [s], log weight (m,) log(p D 3600), flat index of each cell in
    ``weight`` (leg, heading, hs, tz) for its crossing share (m,)).

    ``own``: per leg, every record (an hour, or a table's cell; dim ``time``) at the leg's
    relative headings: ``sigma`` and ``tz_response`` (leg, time, heading, option dims),
    ``probability`` (leg, time, heading) within the leg and the scatter cell each record
    is credited to, ``hs_cell`` and ``tz_cell`` (leg, time: indices into ``weight``'s
    ``hs`` and ``tz``); ``options``: (dims, shape, coords) of the options. Each record at each heading of positive probability is one cell
    of weight p D 3600 with its own sigma (not scaled by Hs) and period. Memory: options x
    the records' cells."""
    legs = [str(x) for x in weight["leg"].values]
    idx_h = weight["heading"].to_index()
    dims, shape, coords = options
    n = int(np.prod(shape))
    replaced, sig, tzr, logw, flat = [], [], [], [], []
    template = xr.DataArray(np.zeros(shape), dims=dims, coords=coords)
    for leg in own["leg"].values:
        if str(leg) not in legs:
            continue
        k = legs.index(str(leg))
        o = own.sel(leg=leg, drop=True)
        prob = o["probability"].transpose("time", "heading").values
        t_i, h_i = np.nonzero(np.nan_to_num(prob) > 0)
        if not t_i.size:
            continue
        heads = idx_h.get_indexer(o["heading"].values)
        if (heads[np.unique(h_i)] < 0).any():
            continue                              # a heading the route's cells have not: keep the table's
        o = o.sel({d: coords[d] for d in dims if d in o.dims and d in coords})

        def flat_of(v):
            a = o[v].broadcast_like(template).transpose(*dims, "time", "heading").values
            return a.reshape(n, *prob.shape)[:, t_i, h_i]
        replaced.append(k)
        sig.append(flat_of("sigma"))
        tzr.append(flat_of("tz_response"))
        logw.append(np.log(prob[t_i, h_i] * float(duration_h.sel(leg=leg)) * 3600.0))
        hs_c, tz_c = o["hs_cell"].values[t_i].astype(int), o["tz_cell"].values[t_i].astype(int)
        flat.append(np.ravel_multi_index((np.full(t_i.size, k), heads[h_i], hs_c, tz_c), weight.shape))
    if not replaced:
        return [], None, None, None, None
    return replaced, np.concatenate(sig, 1), np.concatenate(tzr, 1), np.concatenate(logw), np.concatenate(flat)
