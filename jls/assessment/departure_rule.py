"""The voyage as it will be sailed: a departure rule at hold points, simulated through
hourly records from every departure hour of the season.

The route's legs are grouped into *stretches* by their hold points (a hold point is the
start of a leg where the voyage can wait or make safe; the first leg's start always is
one): a stretch is the legs from one hold point up to the next. The rule, at a hold
point at hour t (the voyage is ready there):

* the stretch is started when every hour of ``[t, t + min(D + C, H))`` has a *forecast
  utilisation* at most alpha: ``D`` the stretch's hours (its legs' ``ceil`` durations),
  ``C`` its contingency hours, ``H`` the forecast horizon. An hour of the stretch is
  judged on the leg the voyage sails in it; the contingency hours on the stretch's last
  leg. With the forecast ``perfect`` the forecast is the record itself;
* else the voyage waits one hour and asks again, up to ``W`` hours (the maximum wait):
  a voyage that would wait longer at any hold point is *not sailed*;
* a sailed stretch takes its D hours; the voyage is then ready at the next hold point.

The *utilisation* of an hour is the largest over the criteria of the hour's 3-h MPM over
its limit (the route simulation's hourly statistics,
:func:`jls.assessment.route_simulation.hourly_statistics`); a strict criterion (the
level must stay below the limit) at exactly its limit counts as beyond it. alpha may vary
by hour (an alpha table is a function of the limiting Hs, hence of the hour's Tz and
option): the rule compares utilisation over alpha with 1. A *sailed voyage exceeds*
when any hour it actually sails has utilisation above 1; hours beyond the forecast
horizon are sailed unforecast, which is where a perfect forecast's risk comes from.

**Cost.** Per option and stretch: one running count per leg of the hours that decide
the forecast and the sailed windows, each window's verdict a difference of two counts
(O(n) whatever the window, compiled: :mod:`jls.assessment.departure_kernels`; equal to
the comparisons of the windows' maxima), the next allowed hour of every hour
by one backward running minimum (O(n)), and the departures composed stretch by stretch
by indexing (O(n)). Nothing is quadratic in the record or the wait.

**Ends and gaps.** An hour without a record has no forecast (the voyage does not start
into it) and no known actual utilisation. A departure whose answer depends on hours
beyond the record's end, whose wait is decided by an unrecorded hour's forecast, or
whose sailed hours include an unrecorded one, is *not judged*: it is counted, and left
out of every share.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: status of a departure
NOT_JUDGED, NOT_SAILED, SAILED = -1, 0, 1
STATUS_FLAGS = "not_judged not_sailed sailed"
QUANTILES = (0.5, 0.9)
#: waits [h] at which the waiting-time distribution (share of sailed voyages waiting at
#: most that long in all) is given
WAIT_STEPS_H = (0, 6, 12, 24, 48, 72, 120, 168, 240, 336, 504, 720)


@dataclass(frozen=True)
class Stretch:
    """Consecutive legs from a hold point up to the next: ``legs`` their indices,
    ``hours`` each leg's hours (ceil of its duration), ``contingency_h`` the stretch's
    contingency hours (whole hours, ceil)."""

    legs: tuple
    hours: tuple
    contingency_h: int

    @property
    def sail_h(self) -> int:
        return int(sum(self.hours))

    def windows(self, horizon_h: int):
        """Per leg (leg index, first hour, length) of the forecast window: the stretch's
        hours and its contingency (on the last leg), cut at the horizon."""
        span = min(self.sail_h + self.contingency_h, int(horizon_h))
        out, start = [], 0
        for i, (k, h) in enumerate(zip(self.legs, self.hours)):
            end = start + h + (self.contingency_h if i == len(self.legs) - 1 else 0)
            n = min(end, span) - start
            if n > 0:
                out.append((k, start, n))
            start += h
        return out

    def sailed(self):
        """Per leg (leg index, first hour, length) of the hours actually sailed."""
        off = np.concatenate([[0], np.cumsum(self.hours)[:-1]]).astype(int)
        return [(k, int(o), int(h)) for k, o, h in zip(self.legs, off, self.hours)]


def stretches(hold_point, duration_h, contingency_h=None) -> list[Stretch]:
    """The stretches of a route: ``hold_point`` per leg (the first leg's start is always
    one), ``duration_h`` per leg [h], ``contingency_h`` per leg [h] (None or NaN: none);
    a stretch's contingency is the sum over its legs, rounded up to whole hours."""
    n = len(duration_h)
    hold = [True] + [bool(h) for h in list(hold_point)[1:]]
    cont = [0.0 if contingency_h is None or c is None or not np.isfinite(c) else float(c)
            for c in (contingency_h if contingency_h is not None else [None] * n)]
    hours = [math.ceil(float(d) - 1e-9) for d in duration_h]
    starts = [k for k in range(n) if hold[k]] + [n]
    return [Stretch(tuple(range(a, b)), tuple(hours[a:b]), math.ceil(sum(cont[a:b]) - 1e-9))
            for a, b in zip(starts[:-1], starts[1:])]


def next_allowed(allowed):
    """For every hour t the first hour t' >= t with ``allowed[..., t']`` (the last axis),
    or its length when there is none: one backward running minimum, O(n)."""
    allowed = np.asarray(allowed, bool)
    m = allowed.shape[-1]
    idx = np.where(allowed, np.arange(m), m)
    return np.minimum.accumulate(idx[..., ::-1], axis=-1)[..., ::-1]


def stretch_arrays(util, forecast, stretch: Stretch, horizon_h: int):
    """(allowed, exceeds, known, gap) of every start hour of ``stretch`` (rows,
    n_start): the forecast over its window stays at most 1 (``forecast``: utilisation
    over alpha; an unrecorded hour never allows), its sailed hours' actual utilisation
    (``util``) goes beyond 1, they are all recorded, and the forecast window holds an
    unrecorded hour. util, forecast: (rows, legs, time)."""
    m = util.shape[-1]
    win, sail = stretch.windows(horizon_h), stretch.sailed()
    need = max([s + n for _, s, n in win] + [s + n for _, s, n in sail])
    n_start = m - need + 1
    rows = util.shape[0]
    if n_start < 1:
        empty = np.zeros((rows, 0), bool)
        return empty, empty, empty, empty
    from jls.assessment.departure_kernels import window_verdicts  # numba: imported where used
    spec = [np.asarray(w, np.int64).reshape(-1, 3) for w in (win, sail)]
    u = np.ascontiguousarray(util, float)
    f = u if forecast is util else np.ascontiguousarray(forecast, float)
    return window_verdicts(u, f, spec[0], spec[1], n_start, f is u)


@dataclass
class Departures:
    """Per option row and departure: ``status`` (:data:`NOT_JUDGED`, :data:`NOT_SAILED`,
    :data:`SAILED`), ``exceeds`` (a sailed voyage's actual utilisation beyond 1 in some
    hour), ``wait_h`` (rows, stretch, departure) the wait at each hold point, ``transit_h``
    from leaving the first hold point to arrival (sailing and the later waits),
    ``immediate`` (the first hold point allows departure at the hour; -1 not judged: the
    hour's forecast window lacks a record, or the hour lies beyond the records),
    ``reference_exceeds`` (the voyage departing at the hour with no rule exceeds; -1 not
    judged). Waits and transit are NaN where the voyage is not sailed or not judged."""

    status: np.ndarray
    exceeds: np.ndarray
    wait_h: np.ndarray
    transit_h: np.ndarray
    immediate: np.ndarray
    reference_exceeds: np.ndarray


def simulate_departures(util, forecast, stretch_list: list[Stretch], departures, *, horizon_h: int,
                        max_wait_h: int) -> Departures:
    """Sail every departure hour with the rule (module docstring).

    util: (rows, legs, time) actual utilisation per option row, leg and hour (NaN:
    unrecorded); forecast: the same over alpha (with a perfect forecast, util / alpha);
    departures: indices of the departure hours on the time axis (the season's hours)."""
    from jls.assessment.departure_kernels import compose_stretch
    util = np.asarray(util, float)
    forecast = np.asarray(forecast, float)
    rows, _, m = util.shape
    dep = np.asarray(departures, np.int64)
    nd = dep.size
    ready = np.broadcast_to(dep, (rows, nd)).copy()
    status = np.full((rows, nd), SAILED, np.int8)
    exceeds = np.zeros((rows, nd), bool)
    unknown = np.zeros((rows, nd), bool)
    wait = np.full((rows, len(stretch_list), nd), np.nan)
    immediate = np.full((rows, nd), -1, np.int8)
    ref = np.zeros((rows, nd), bool)
    ref_known = np.ones((rows, nd), bool)
    ref_at = ready.copy()
    for s, st in enumerate(stretch_list):
        allowed, exc, known, gap = stretch_arrays(util, forecast, st, horizon_h)
        compose_stretch(allowed, exc, known, gap, s == 0, int(max_wait_h), int(st.sail_h), ready, status, exceeds,
                        unknown, wait[:, s], immediate, ref, ref_known, ref_at)
    status[(status == SAILED) & unknown] = NOT_JUDGED
    sailed = status == SAILED
    first = wait[:, 0]
    transit = np.where(sailed, ready - (dep[None, :] + np.nan_to_num(first)), np.nan)
    wait[~np.broadcast_to(sailed[:, None, :], wait.shape)] = np.nan
    ref_flag = np.where(ref_known, ref.astype(np.int8), -1).astype(np.int8)
    return Departures(status, exceeds & sailed, wait, transit, immediate, ref_flag)


def _share(num, den):
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(den > 0, num / np.where(den > 0, den, 1), np.nan)


def _quantiles(x, q):
    """(rows, len(q)) quantiles of x (rows, n) over its finite values (inverted CDF: a
    value that occurred); NaN for a row without one."""
    out = np.full((x.shape[0], len(q)), np.nan)
    ok = np.isfinite(x).any(-1)
    if ok.any():
        out[ok] = np.nanquantile(x[ok], q, axis=-1, method="inverted_cdf").T
    return out


#: the largest histogram (rows x groups x values) :func:`_whole_hours` counts in
HISTOGRAM_CELLS = 20_000_000


def _whole_hours(x, group, n_group):
    """Counts (rows, n_group, values) of the finite values of x (rows, n) per group
    (``group`` (n,) in 0..n_group-1) and the smallest value, when they are whole hours
    within a range the histogram holds (every wait and transit of the rule is); else None."""
    from jls.assessment.departure_kernels import group_histogram, whole_range
    x = np.ascontiguousarray(x, float)
    seen, lo, hi, whole = whole_range(x)
    if not seen:
        return np.zeros((x.shape[0], n_group, 1), np.int64), 0.0
    if x.shape[0] * n_group * (hi - lo + 1) > HISTOGRAM_CELLS or not whole:
        return None
    return group_histogram(x, np.asarray(group, np.int64), n_group, lo, int(hi - lo) + 1), lo


def _counted_quantiles(counts, lo, q):
    """(rows, groups, len(q)) inverted-CDF quantiles from :func:`_whole_hours`' counts:
    the rank numpy's ``nanquantile(method="inverted_cdf")`` takes, found on the running
    count; NaN for a group without a value."""
    cum = np.cumsum(counts, axis=-1)
    n = cum[..., -1]
    out = np.full((*n.shape, len(q)), np.nan)
    for i, qi in enumerate(q):
        index = n * float(qi) - 1                   # numpy's virtual index of the method
        prev = np.floor(index)
        rank = np.maximum(np.where(index - prev == 0, prev, prev + 1), 0).astype(np.int64)
        at = np.argmax(cum > rank[..., None], axis=-1)
        out[..., i] = np.where(n > 0, lo + at, np.nan)
    return out


def _quantiles_by_month(x, months, q):
    """(every (rows, len(q)), per month (rows, 12, len(q))) quantiles of x (rows, n) over its
    finite values (:func:`_quantiles`), by counting whole hours when the values are, and
    then the counts (rows, values) of every departure and the smallest value (else None)."""
    h = _whole_hours(x, months - 1, 12) if ((months >= 1) & (months <= 12)).all() else None
    if h is None:
        return _quantiles(x, q), np.stack([_quantiles(np.where(months == mo, x, np.nan), q)
                                           for mo in range(1, 13)], axis=1), None
    counts, lo = h
    every = counts.sum(axis=1, keepdims=True)
    return _counted_quantiles(every, lo, q)[:, 0], _counted_quantiles(counts, lo, q), (every[:, 0], lo)


def summarise(d: Departures, months, quantiles=QUANTILES) -> dict:
    """Per option row (and per departure month, ``months`` (departure,) 1-12): the
    shares and quantiles of the plan (numpy arrays; the stage labels them).

    ``exceedance_probability``: exceeding voyages over sailed (judged) voyages;
    ``departure_fraction``: departures the first hold point allows at once, over those
    judged there; ``not_sailed_fraction``: not sailed over judged (sailed + not sailed);
    ``wait_h``: total wait of the sailed voyages (quantiles); ``wait_cdf`` (rows, step):
    the share of them waiting at most each of :data:`WAIT_STEPS_H`; ``wait_hold_h`` (rows,
    stretch, quantile); ``transit_h``: leaving the first hold point to arrival;
    ``reference_exceedance_probability``: departing at any hour, no rule.

    The counts per month and the quantiles of whole hours are counted in one compiled
    pass over the departures (no per-row or per-month pass)."""
    from jls.assessment.departure_kernels import group_counts
    q = list(quantiles)
    months = np.asarray(months, int)
    sailed, exc = d.status == SAILED, d.exceeds
    judged = d.status != NOT_JUDGED
    total = np.where(sailed, np.nansum(d.wait_h, axis=1), np.nan)
    counts = {"exc": exc & sailed, "sailed": sailed, "immediate": d.immediate == 1, "im": d.immediate >= 0,
              "not_sailed": judged & ~sailed, "judged": judged, "ref": d.reference_exceeds == 1,
              "rk": d.reference_exceeds >= 0}
    every = {k: m.sum(-1) for k, m in counts.items()}
    in_year = (months >= 1) & (months <= 12)
    masks = np.stack(list(counts.values()))
    per = group_counts(masks if in_year.all() else masks[..., in_year], months[in_year] - 1, 12)
    month = dict(zip(counts, per))
    out = {}
    for c, tag in ((every, ""), (month, "_month")):
        out["exceedance_probability" + tag] = _share(c["exc"], c["sailed"])
        out["departure_fraction" + tag] = _share(c["immediate"], c["im"])
        out["not_sailed_fraction" + tag] = _share(c["not_sailed"], c["judged"])
        out["reference_exceedance_probability" + tag] = _share(c["ref"], c["rk"])
        out["sailed" + tag], out["judged" + tag] = c["sailed"], c["judged"]
    out["wait_h"], out["wait_h_month"], waits = _quantiles_by_month(total, months, q)
    transit = np.where(sailed, d.transit_h, np.nan)
    out["transit_h"], out["transit_h_month"], _ = _quantiles_by_month(transit, months, q)
    steps = np.asarray(WAIT_STEPS_H, float)
    n_s = sailed.sum(-1)
    if waits is None:
        out["wait_cdf"] = np.stack([_share((sailed & (total <= x)).sum(-1), n_s) for x in steps], axis=-1)
    else:                               # sailed voyages waiting at most x: the running count at x
        cum, lo = np.cumsum(waits[0], axis=-1), waits[1]
        at = np.clip(np.floor(steps - lo).astype(np.int64), -1, cum.shape[-1] - 1)
        below = np.where(at >= 0, cum[:, np.maximum(at, 0)], 0)
        out["wait_cdf"] = _share(below, n_s[:, None])
    out["wait_hold_h"] = np.stack([_quantiles_by_month(np.where(sailed, d.wait_h[:, s], np.nan), months, q)[0]
                                   for s in range(d.wait_h.shape[1])], axis=1)
    return out
