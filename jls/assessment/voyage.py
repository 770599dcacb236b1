"""Voyage extremes: the distribution of the largest response over a whole voyage.

A transit cannot pause, so besides the share of sea states inside a limit (workability)
the question is how large the largest response of the voyage gets. From the legs'
scatter tables (the long-term, "all sea states" approach):

    Lambda(x) = sum_legs sum_cells p(cell) D_leg 3600 / Tz_r(cell) exp(-x^2 / (2 sigma(cell)^2))
    P(voyage max <= x) = exp(-Lambda(x))

``Lambda`` is the expected number of up-crossings of level x in the voyage: in a sea state
the response is a zero-mean stationary Gaussian process (the model is linear) whose
up-crossings of x occur at Rice's rate exp(-x^2 / (2 sigma^2)) / Tz_r, one for each
Rayleigh-distributed peak above x of a narrow-band response. ``p(cell)`` is the joint
probability of (heading, Hs, Tz) of the leg's table (``cell_probability``), D_leg the leg
duration [h], ``sigma = Hs sigma(Hs = 1 m)`` with Hs the assessed Hs of the bin (its
centre or upper edge, ``sea.hs_in_bin``; sigma scales linearly with Hs) and Tz_r =
2 pi sqrt(m0/m2) the response's zero-crossing period [s] (Tz_r does not depend on Hs).

Units: levels in the criterion's level units (m or degree for a relative motion; for a
wire-tension criterion the dynamic utilisation of the worst wire, see
:func:`jls.assessment.criterion_levels.criterion_statistics`), sigma per metre of Hs, Hs
in m, durations in h, periods in s.

Assumptions, and the side they err on:

* **Independent sea states.** Consecutive sea states are taken as independent and the
  voyage as meeting each cell for p D hours. Real sea states persist: a storm lasts
  hours to days, so a voyage that meets one meets many hours of it, and most voyages
  meet none. For the same expected number of up-crossings E[Lambda], clustering them in
  fewer voyages lowers the probability that a voyage has any:
  1 - exp(-E[Lambda]) >= E[1 - exp(-Lambda)] (Jensen; 1 - exp(-L) is concave). The
  independence assumption therefore over-estimates the exceedance probability: it is
  conservative. :mod:`jls.assessment.route_simulation` measures the difference on a hindcast
  (:func:`hindcast_long_term` against the departures' own probabilities).
* **Poisson up-crossings.** High-level up-crossings of a narrow-band response come in
  wave groups; counting each as an independent event also over-estimates the
  exceedance probability (conservative). The formula describes the upper tail: at levels
  of the order of sigma it is an approximation.
* **Dynamic part.** For a criterion on a response about a static mean (a wire tension),
  the formula applies to the dynamic part against the dynamic allowance (limit minus
  static value); the relative motions have zero mean.

A one-cell table of duration equal to the exposure gives exactly the short-term
distribution of the maximum, exp(-N exp(-x^2 / (2 sigma^2))) with N = exposure / Tz_r,
whose level at probability exp(-1) (the mode of x^2 / (2 sigma^2), a Gumbel variable) is
the MPM sigma sqrt(2 ln N) of :mod:`jls.response.statistics`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import xarray as xr

from jls.assessment.hourly import tz_weights
from jls.errors import InputError
from jls.io import registry

NON_EXCEEDANCE = (0.5, 0.9)
CELL_DIMS = ("leg", "heading", "hs", "tz")
BLOCK = 2 ** 18          # options x cells per block: bounded memory, mostly in cache
MAX_ITER = 100
RTOL = 1e-13             # on x^2


class Cells(NamedTuple):
    """Cells as rows of the options' statistics columns: a cell's unit statistics are
    interpolated between columns ``lo`` and ``hi`` (``frac``; None: at ``lo``) and
    scaled by ``hs`` [m]; ``log_weight`` is log(p D 3600) [log s]."""

    lo: np.ndarray
    hi: np.ndarray
    frac: np.ndarray | None
    hs: np.ndarray
    log_weight: np.ndarray


def _terms(sig, tzr, cells: Cells):
    """b = 1 / (2 sigma^2) and log(expected cycles) per (option, cell). A cell without
    response drops out (b 0, log cycles -inf); infinite sigma (a limit broken at rest)
    gives b 0 and finite log cycles; NaN stays NaN."""
    s, t = sig[:, cells.lo], tzr[:, cells.lo]
    if cells.frac is not None:
        moved = cells.frac > 0             # a cell at its lower column keeps it (even inf)
        with np.errstate(invalid="ignore"):
            s = np.where(moved, s + cells.frac * (sig[:, cells.hi] - s), s)
            t = np.where(moved, t + cells.frac * (tzr[:, cells.hi] - t), t)
    s = s * cells.hs
    with np.errstate(divide="ignore", invalid="ignore"):
        b = 0.5 / (s * s)
        logc = cells.log_weight - np.log(t)
    dead = s == 0
    b[dead], logc[dead] = 0.0, -np.inf
    return b, logc


def _group_bound(b, w, lt, n_groups=16):
    """A lower bound of the root y of Lambda(y) = exp(lt) from groups of cells: for the
    cells S with b below a threshold, Lambda(y) >= W_S exp(-mean_S(b) y) (Jensen; W_S
    their cycles, mean_S weighted by them), so y >= (log W_S - lt) / mean_S(b). The
    thresholds are n_groups steps of log b; many small cells (hindcast hours) that the
    single-cell bound misses are caught this way. w: the cells' cycles exp(logc)."""
    alive = (w > 0) & (b > 0)
    if not alive.any():
        return np.zeros(b.shape[0])
    lb = np.log(np.where(alive, b, 1.0))
    lo, hi = lb[alive].min(), lb[alive].max()
    g = np.clip(((lb - lo) / max(hi - lo, 1e-12) * n_groups).astype(int), 0, n_groups - 1)
    idx = (np.arange(b.shape[0])[:, None] * n_groups + g).ravel()
    size = b.shape[0] * n_groups
    W = np.cumsum(np.bincount(idx, w.ravel(), size).reshape(-1, n_groups), -1)
    WB = np.cumsum(np.bincount(idx, (w * b).ravel(), size).reshape(-1, n_groups), -1)
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = np.where(W > 0, (np.log(W) - lt) / (WB / np.where(W > 0, W, 1.0)), -np.inf)
    return np.maximum(np.nan_to_num(bound, nan=-np.inf).max(-1), 0.0)


def _newton(b, logc, log_t):
    """y = x^2 with Lambda(y) = t for each target (n, k).

    log Lambda(y) = logsumexp(logc - b y) is convex and decreasing in y, so Newton's
    iterates started left of the root rise monotonically to it (a convex function lies
    above its tangents). The start is the higher of two lower bounds of the root: the
    largest single-cell root (Lambda is at least each of its terms) and the group bound
    of :func:`_group_bound`; each target starts from the previous root. Cells whose term
    is below exp(-50) of the smallest target at the start are dropped: their terms only
    fall as y rises.
    """
    out = np.zeros((b.shape[0], log_t.size))
    w = np.exp(logc)
    with np.errstate(divide="ignore"):
        log_total = np.log(w.sum(-1))                            # log Lambda(0)
    rows = np.flatnonzero(log_total > log_t.min())               # the others' levels are 0
    b, logc = b[rows], logc[rows]
    y = _group_bound(b, w[rows], log_t.max())
    for n, j in enumerate(np.argsort(-log_t)):                   # rising levels
        lt = log_t[j]
        with np.errstate(divide="ignore", invalid="ignore"):
            lower = np.where(b > 0, (logc - lt) / np.where(b > 0, b, 1.0), -np.inf).max(-1)
        y = np.maximum(y, np.maximum(lower, 0.0))
        if n == 0:
            keep = (logc - b * y[:, None] > log_t.min() - 50.0).any(0)
            b, logc = b[:, keep], logc[:, keep]
        for _ in range(MAX_ITER):
            e = np.exp(logc - b * y[:, None])
            s0, s1 = e.sum(-1), np.einsum("ij,ij->i", b, e)
            step = np.maximum((np.log(s0) - lt) * s0 / s1, 0.0)
            y = y + step
            if (step <= RTOL * y).all():
                break
        out[rows, j] = np.where(log_total[rows] > lt, y, 0.0)
    return out


def _crossings(b, logc, limit):
    """Each cell's expected up-crossings of ``limit`` (n,) scaled by the largest, and the
    log of that scale (n, 1): Lambda = e.sum(-1) exp(top) without underflow."""
    with np.errstate(invalid="ignore"):
        t = logc - b * np.square(limit)[:, None]                 # log up-crossings per cell
    top = np.max(t, -1, keepdims=True, initial=-np.inf)
    with np.errstate(invalid="ignore"):
        e = np.exp(t - np.where(np.isfinite(top), top, 0.0))
    return e, top


def _in_blocks(block, n: int, m: int, threads=1) -> None:
    """Run ``block(rows)`` over slices of the n options (BLOCK options x m cells per
    slice: bounded memory), side by side on ``threads`` threads."""
    step = max(1, BLOCK // max(m, 1))
    blocks = [slice(r0, min(r0 + step, n)) for r0 in range(0, n, step)]
    if threads > 1 and len(blocks) > 1:
        from concurrent.futures import ThreadPoolExecutor
        with ThreadPoolExecutor(max_workers=int(threads)) as pool:
            list(pool.map(block, blocks))
    else:
        for rows in blocks:
            block(rows)


def _solve(sig, tzr, cells: Cells, limit, non_exceedance, *, share=None, keep=None, groups=None,
           threads=1):
    """Expected up-crossings of ``limit`` (n,) and levels (n, k) of n options with
    statistics (n, n_columns); each cell's share of the up-crossings at the limit is
    written to ``share[:, keep]`` (n, M) when given, and summed by ``groups`` (m,) int
    (returned (n, n_groups), else None). Blocks of options run on ``threads`` threads."""
    n, m = sig.shape[0], cells.hs.size
    log_t = np.log(-np.log(np.asarray(non_exceedance, float)))
    lam = np.full(n, np.nan)
    level = np.full((n, log_t.size), np.nan)
    onehot = None if groups is None else (groups[:, None] == np.arange(groups.max() + 1)).astype(float)
    by_group = None if groups is None else np.full((n, onehot.shape[1]), np.nan)

    def block(rows):
        b, logc = _terms(sig[rows], tzr[rows], cells)
        e, top = _crossings(b, logc, limit[rows])
        broken = ((b == 0) & np.isfinite(logc)).any(-1)
        bad = np.isnan(b).any(-1) | np.isnan(logc).any(-1)
        lam[rows] = np.where(broken, np.inf, e.sum(-1) * np.exp(top[:, 0]))
        ok = ~bad & ~broken
        y = np.full((b.shape[0], log_t.size), np.nan)
        if log_t.size:
            y[ok] = _newton(b[ok], logc[ok], log_t)
        y[broken & ~bad] = np.inf
        level[rows] = np.sqrt(y)
        if share is not None or onehot is not None:
            if broken.any():
                e[broken] = ((b[broken] == 0) & np.isfinite(logc[broken]))
            with np.errstate(invalid="ignore", divide="ignore"):
                sh = np.nan_to_num(e / e.sum(-1, keepdims=True), nan=0.0)
            sh[bad] = np.nan
            if share is not None and np.unique(keep).size == keep.size:
                share[rows][:, keep] = sh
            elif share is not None:                # cells credited to one table cell: summed
                from scipy.sparse import csr_matrix
                credit = csr_matrix((np.ones(keep.size), (np.arange(keep.size), keep)),
                                    shape=(keep.size, share.shape[1]))
                share[rows] = np.asarray((credit.T @ sh.T).T)
            if onehot is not None:
                by_group[rows] = sh @ onehot

    _in_blocks(block, n, m, threads)
    return lam, level, by_group


def _options(sigma_unit, tz_response, limit, columns):
    """The option dims (those of the statistics besides ``columns``, and the limit's),
    the statistics (n_options, n_columns) and the limits (n_options,)."""
    lim = xr.DataArray(limit)
    if set(lim.dims) - set(sigma_unit.dims):
        sigma_unit = xr.broadcast(sigma_unit, lim)[0]
    dims = [d for d in sigma_unit.dims if d not in columns]
    sigma_unit = sigma_unit.transpose(*dims, *columns)
    tz_response = tz_response.broadcast_like(sigma_unit).transpose(*dims, *columns)
    shape = [sigma_unit.sizes[d] for d in dims]
    n = int(np.prod(shape))
    lim = lim.broadcast_like(sigma_unit.isel({c: 0 for c in columns}, drop=True)).transpose(*dims)
    coords = {d: sigma_unit[d] for d in dims if d in sigma_unit.coords}
    return dims, shape, coords, sigma_unit.values.reshape(n, -1).astype(float), \
        tz_response.values.reshape(n, -1).astype(float), lim.values.reshape(-1).astype(float)


def _result(lam, level, dims, shape, coords, non_exceedance):
    ne = xr.DataArray(list(non_exceedance), dims="non_exceedance")
    ds = xr.Dataset({
        "expected_exceedances": (dims, lam.reshape(shape)),
        "exceedance_probability": (dims, -np.expm1(-lam).reshape(shape)),
        "voyage_level": ((*dims, "non_exceedance"), level.reshape(*shape, -1)),
    }, coords={**coords, "non_exceedance": ne})
    return ds


def _index(labels, values, field):
    idx = np.asarray(labels.to_index().get_indexer(values))
    if (idx < 0).any():
        raise InputError("no response statistics at the sea states' value", field=field,
                         value=float(np.asarray(values)[idx < 0][0]))
    return idx


def _table_cells(sigma_unit, cell_probability, hs, duration_h):
    """The scatter tables' cells with cycles: (weight (leg, heading, hs, tz) [s], its
    values flat, the kept flat indices, their (leg, heading, hs, tz) indices, Cells)."""
    weight = (cell_probability * duration_h * 3600.0).transpose(*CELL_DIMS)
    hs_cell = xr.DataArray(hs).broadcast_like(weight).transpose(*CELL_DIMS)
    w, h = weight.values.reshape(-1), hs_cell.values.reshape(-1)
    keep = np.flatnonzero((w > 0) & np.isfinite(h) & (h > 0))
    grid = np.stack(np.meshgrid(*(np.arange(weight.sizes[d]) for d in CELL_DIMS), indexing="ij"),
                    axis=-1).reshape(-1, 4)[keep]
    ih = _index(sigma_unit["heading"], weight["heading"].values[grid[:, 1]], "heading")
    it = _index(sigma_unit["tz"], weight["tz"].values[grid[:, 3]], "tz")
    col = ih * sigma_unit.sizes["tz"] + it
    return weight, w, keep, grid, Cells(col, col, None, h[keep], np.log(w[keep]))


def _with_own(own, weight, keep, grid, cells: Cells, sig, tzr, options, duration_h):
    """The scatter cells with the legs of ``own`` replaced by their own-sea cells
    (:func:`jls.assessment.voyage_own_seas.table_own_cells`): (sig, tzr, cells, flat index
    of each cell in the (leg, heading, hs, tz) grid, leg index of each cell)."""
    if own is None:
        return sig, tzr, cells, keep, grid[:, 0]
    from jls.assessment.voyage_own_seas import table_own_cells
    replaced, o_sig, o_tz, o_logw, o_flat = table_own_cells(own, weight, duration_h, options)
    if not replaced:
        return sig, tzr, cells, keep, grid[:, 0]
    stay = ~np.isin(grid[:, 0], replaced)
    col = np.arange(sig.shape[1], sig.shape[1] + o_logw.size)
    cells = Cells(np.concatenate([cells.lo[stay], col]), np.concatenate([cells.hi[stay], col]), None,
                  np.concatenate([cells.hs[stay], np.ones(col.size)]),
                  np.concatenate([cells.log_weight[stay], o_logw]))
    flat = np.concatenate([keep[stay], o_flat])
    return np.concatenate([sig, o_sig], 1), np.concatenate([tzr, o_tz], 1), cells, flat, \
        np.unravel_index(flat, weight.shape)[0]


def exceedance_at_levels(sigma_unit: xr.DataArray, tz_response: xr.DataArray,
                         cell_probability: xr.DataArray, hs: xr.DataArray, duration_h: xr.DataArray,
                         limit, levels, threads=1, *, own: xr.Dataset | None = None) -> xr.DataArray:
    """P(voyage max > x limit) at each of ``levels`` (dim ``level``) over the option dims:
    :func:`long_term_extreme`'s exceedance probability with the limit swept, each option's
    cell terms formed once for all the levels (the curve costs one exponential per
    option, cell and level, not a long-term solve per level). ``own``: as
    :func:`long_term_extreme`'s."""
    weight, _, keep, grid, cells = _table_cells(sigma_unit, cell_probability, hs, duration_h)
    dims, shape, coords, sig, tzr, lim = _options(sigma_unit, tz_response, limit, ("heading", "tz"))
    sig, tzr, cells, _, _ = _with_own(own, weight, keep, grid, cells, sig, tzr, (dims, shape, coords),
                                      duration_h)
    x = np.asarray(levels, float)
    n, m = sig.shape[0], cells.hs.size
    lam = np.full((n, x.size), np.nan)

    def block(rows):
        b, logc = _terms(sig[rows], tzr[rows], cells)
        broken = ((b == 0) & np.isfinite(logc)).any(-1)
        bad = np.isnan(b).any(-1) | np.isnan(logc).any(-1)
        out = np.empty((b.shape[0], x.size))
        for k, xk in enumerate(x):
            e, top = _crossings(b, logc, xk * lim[rows])
            out[:, k] = e.sum(-1) * np.exp(top[:, 0])
        out[broken] = np.inf
        out[bad] = np.nan
        lam[rows] = out

    _in_blocks(block, n, m, threads)
    return xr.DataArray(-np.expm1(-lam).reshape(*shape, x.size), dims=(*dims, "level"),
                        coords={**coords, "level": x})


def long_term_extreme(sigma_unit: xr.DataArray, tz_response: xr.DataArray,
                      cell_probability: xr.DataArray, hs: xr.DataArray, duration_h: xr.DataArray,
                      limit, non_exceedance=NON_EXCEEDANCE, shares=True, threads=1, *,
                      own: xr.Dataset | None = None) -> xr.Dataset:
    """The voyage extreme of the module docstring from the legs' scatter tables.

    sigma_unit: standard deviation at Hs = 1 m [level units per m], dims ``heading``,
    ``tz`` and any option dims (e.g. candidate, tugger, criterion); tz_response: the
    response zero-crossing period [s], the same dims; cell_probability: (leg, heading,
    hs, tz) joint probability within each leg (``sea_states.nc``); hs: assessed Hs of
    each bin (leg, hs) or (hs) [m]; duration_h: (leg) [h]; limit: the level whose
    exceedance is wanted [level units], broadcastable to the option dims (e.g. over
    ``criterion``); non_exceedance: probabilities of the wanted levels.

    Returns over the option dims: ``expected_exceedances`` (Lambda at the limit),
    ``exceedance_probability`` 1 - exp(-Lambda), ``voyage_level`` (..., non_exceedance);
    with ``shares``: ``crossing_share`` (..., leg, heading, hs, tz), each cell's share of
    the expected up-crossings at the limit (0 for empty cells; sums to 1), and
    ``crossing_share_leg`` (..., leg). threads: blocks of options run side by side.

    ``own``: the legs given by their own seas (measured spectra, partitions, a
    Torsethaugen table), whose table cells are replaced by their records' own-sea cells
    (:func:`jls.assessment.voyage_own_seas.table_own_cells`: each record at each heading
    with its probability, own sigma and own up-crossing period); a record's crossing share
    is credited to the table cell it is binned in (``hs_cell``, ``tz_cell``).
    """
    weight, w, keep, grid, cells = _table_cells(sigma_unit, cell_probability, hs, duration_h)
    dims, shape, coords, sig, tzr, lim = _options(sigma_unit, tz_response, limit, ("heading", "tz"))
    sig, tzr, cells, keep, legs_of = _with_own(own, weight, keep, grid, cells, sig, tzr,
                                               (dims, shape, coords), duration_h)
    full = np.zeros((sig.shape[0], w.size), np.float32) if shares else None
    lam, level, by_leg = _solve(sig, tzr, cells, lim, non_exceedance, share=full, keep=keep,
                                groups=legs_of if shares else None, threads=threads)
    ds = _result(lam, level, dims, shape, coords, non_exceedance)
    if shares:
        cell_coords = {d: weight[d] for d in CELL_DIMS}
        ds["crossing_share"] = xr.DataArray(full.reshape(*shape, *weight.shape),
                                            dims=(*dims, *CELL_DIMS), coords=cell_coords)
        legs = np.zeros((sig.shape[0], weight.sizes["leg"]))
        legs[:, : by_leg.shape[1]] = by_leg
        ds["crossing_share_leg"] = xr.DataArray(legs.reshape(*shape, -1), dims=(*dims, "leg"),
                                                coords={"leg": weight["leg"]})
    return ds


def hindcast_long_term(sigma_unit: xr.DataArray, tz_response: xr.DataArray, hours: xr.Dataset,
                       duration_h: xr.DataArray, heading_probability: xr.DataArray, limit,
                       non_exceedance=NON_EXCEEDANCE, threads=1, *, own: xr.DataArray | None = None,
                       mpm_unit: xr.DataArray | None = None, exposure_h: float | None = None,
                       cycles="response") -> xr.Dataset:
    """The same formula with every recorded hour of a leg's hindcast as a cell of
    probability heading_probability / (recorded hours of the leg), at its own Hs and Tz.

    sigma_unit, tz_response: as :func:`long_term_extreme`, on a Tz grid (interpolated
    linearly in Tz, held at the grid's ends); hours: (leg, time) ``hs`` [m] and ``tz``
    [s], NaN where the leg has no record (:func:`jls.assessment.route_hours.common_hours`);
    heading_probability: (leg, heading). Returns ``expected_exceedances``,
    ``exceedance_probability`` and ``voyage_level`` over the option dims.

    ``own``: the hours' utilisation on their own seas (leg, time, criterion, option dims,
    optionally heading; :func:`jls.assessment.hourly.route_own_heading_utilisation`), NaN
    where an hour keeps the JONSWAP: those hours' cells are their own seas'
    (:mod:`jls.assessment.voyage_own_seas`); a Dataset with ``utilisation`` and the own
    sea's ``sigma`` and ``tz_response`` (:func:`jls.assessment.hourly.route_own_heading_utilisation`),
    or the utilisation alone (an older dataset: the JONSWAP's sigma moved by level / MPM,
    ``mpm_unit`` the unit-Hs MPM on the grid; ``exposure_h`` and ``cycles`` as
    ``assessment.mpm_cycles``, kept for the callers).
    """
    hs, tz = hours["hs"].transpose("leg", "time").values, hours["tz"].transpose("leg", "time").values
    known = np.isfinite(hs) & np.isfinite(tz)
    n_known = known.sum(-1)
    grid = sigma_unit["tz"].values.astype(float)
    order = np.argsort(grid)
    sigma_unit, tz_response = sigma_unit.isel(tz=order), tz_response.isel(tz=order)
    grid = grid[order]
    hp = heading_probability.transpose("leg", "heading").sel(leg=hours["leg"])
    hp = hp.where(hp > 0, drop=True).fillna(0.0)           # the headings the legs meet
    ih = _index(sigma_unit["heading"], hp["heading"].values, "heading")
    parts = []
    for k in range(hs.shape[0]):
        i, j, _, f, _ = tz_weights(tz[k, known[k]], grid)        # the hourly verdicts' interpolation
        dur = float(duration_h.sel(leg=hours["leg"][k]))
        for a, p in zip(ih, hp.values[k]):
            if p > 0:
                base = a * grid.size
                parts.append((base + i, base + j, f, hs[k, known[k]],
                              np.full(i.size, np.log(p * dur * 3600.0 / n_known[k]))))
    dims, shape, coords, sig, tzr, lim = _options(sigma_unit, tz_response, limit, ("heading", "tz"))
    if own is not None:
        if mpm_unit is None or exposure_h is None:
            raise ValueError("own needs mpm_unit and exposure_h")
        mpm = _options(mpm_unit.isel(tz=order), tz_response, limit, ("heading", "tz"))[3]
        from jls.assessment.voyage_own_seas import own_cells
        sig, tzr, parts = own_cells(own, hours, known, parts, ih, hp, (sig, tzr, mpm, lim),
                                     (dims, shape, coords), grid.size, (float(exposure_h), cycles))
    cells = Cells(*(np.concatenate(x) for x in zip(*parts)))
    lam, level, _ = _solve(sig, tzr, cells, lim, non_exceedance, threads=threads)
    return _result(lam, level, dims, shape, coords, non_exceedance)


def voyage_dataset(long_term: xr.Dataset, limit: xr.DataArray, *, route: xr.Dataset | None = None,
                   hindcast: xr.Dataset | None = None, attrs: dict | None = None) -> xr.Dataset:
    """The ``voyage.nc`` layout from :func:`long_term_extreme` (scatter tables, over
    candidate, tugger, criterion), the criteria's ``limit`` with ``level_units``
    (:func:`jls.assessment.criterion_levels.criterion_statistics`) and, for a route with
    hourly hindcasts, the route simulation
    (:func:`jls.assessment.route_simulation.route_simulation`) and the same hours'
    long-term extreme (:func:`hindcast_long_term`, variables prefixed ``hindcast_``).
    ``attrs``: global attributes (route, hs_in_bin, ...).
    """
    ds = long_term.copy()
    ds["limit"] = limit
    ds["exceedance_probability_any"] = np.minimum(ds["exceedance_probability"].sum("criterion"), 1.0)
    def bare(d):      # the criteria's auxiliary coordinates (response, strict, ...) are the limit's
        return d.drop_vars([c for c in d.coords if c not in d.dims])
    if route is not None:
        ds = ds.merge(bare(route), join="exact", compat="no_conflicts", combine_attrs="drop_conflicts")
    if hindcast is not None:
        hindcast = bare(hindcast)
        ds = ds.merge(hindcast.rename({v: f"hindcast_{v}" for v in hindcast.data_vars}), join="exact",
                      compat="no_conflicts")
    ds = ds.assign_coords(level_units=limit["level_units"])
    registry.annotate(ds, "voyage")
    ds.attrs.update(attrs or {})
    ds.attrs.setdefault("independence", "consecutive sea states independent (conservative: "
                                        "over-estimates the exceedance probability)")
    return ds
