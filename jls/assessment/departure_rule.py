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

**Cost.** Per option and stretch: one sliding maximum per leg over its forecast window
and one over its sailed window (van Herk / Gil-Werman, O(n) whatever the window,
:func:`jls.assessment.route_simulation.sliding_max`), the next allowed hour of every hour
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

from jls.assessment.route_simulation import sliding_max

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


def _window_max(u, start, n, length):
    """max(u[..., t + start : t + start + n]) for t in 0..length-1 (n >= 1)."""
    return sliding_max(u[..., start: start + length + n - 1], n)


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
    fmax = np.full((rows, n_start), -np.inf)
    for k, s, n in win:
        np.fmax(fmax, _window_max(np.where(np.isnan(forecast[:, k]), np.inf, forecast[:, k]), s, n, n_start),
                out=fmax)
    gap = np.zeros((rows, n_start), bool)
    for k, s, n in win:
        gap |= _window_max(np.isnan(forecast[:, k]).astype(np.int8), s, n, n_start) > 0
    amax = np.full((rows, n_start), -np.inf)
    for k, s, n in sail:
        w = _window_max(util[:, k], s, n, n_start)            # NaN where an hour is unknown
        amax = np.where(np.isnan(w) | np.isnan(amax), np.nan, np.maximum(amax, w))
    return fmax <= 1.0, amax > 1.0, np.isfinite(amax), gap


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
    util = np.asarray(util, float)
    forecast = np.asarray(forecast, float)
    rows, _, m = util.shape
    dep = np.asarray(departures, int)
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
    r_idx = np.arange(rows)[:, None]
    for s, st in enumerate(stretch_list):
        allowed, exc, known, gap = stretch_arrays(util, forecast, st, horizon_h)
        n_start = allowed.shape[-1]
        counted = np.concatenate([np.zeros((rows, 1), int), np.cumsum(gap, axis=-1)], axis=-1)
        nxt = next_allowed(allowed)
        live = status == SAILED
        inside = live & (ready < n_start)
        at = np.where(inside, ready, 0)
        start = np.where(inside, nxt[r_idx, at] if n_start else 0, n_start)
        w = start - ready
        found = inside & (start < n_start)
        over = live & ((found & (w > max_wait_h)) | (~found & (ready + max_wait_h < n_start)))
        lost = live & ~found & ~over                    # the answer lies beyond the record
        # a wait through an unrecorded hour's forecast is no answer either
        end = np.clip(np.where(found & ~over, start, ready + max_wait_h + 1), 0, n_start)
        lost |= (live & inside & ~lost) & (counted[r_idx, end] - counted[r_idx, at] > 0)
        over &= ~lost
        ok = found & ~over & ~lost
        if s == 0:                   # an hour whose forecast window lacks a record is not judged
            unknown_at = inside & (~(w == 0)) & (gap[r_idx, at] if n_start else True)
            immediate = np.where(inside & ~unknown_at, (w == 0).astype(np.int8), -1).astype(np.int8)
        status[over] = NOT_SAILED
        status[lost] = NOT_JUDGED
        wait[:, s] = np.where(ok, w, np.nan)
        go = np.where(ok, start, 0)
        if n_start:
            exceeds |= ok & exc[r_idx, go]
            unknown |= ok & ~known[r_idx, go]
            # the reference: departing at once, no rule
            ref_in = ref_known & (ref_at < n_start)
            ra = np.where(ref_in, ref_at, 0)
            ref |= ref_in & exc[r_idx, ra]
            ref_known &= ref_in & known[r_idx, ra]
        else:
            ref_known[:] = False
        ready = np.where(ok, start + st.sail_h, ready)
        ref_at = ref_at + st.sail_h
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


def summarise(d: Departures, months, quantiles=QUANTILES) -> dict:
    """Per option row (and per departure month, ``months`` (departure,) 1-12): the
    shares and quantiles of the plan (numpy arrays; the stage labels them).

    ``exceedance_probability``: exceeding voyages over sailed (judged) voyages;
    ``departure_fraction``: departures the first hold point allows at once, over those
    judged there; ``not_sailed_fraction``: not sailed over judged (sailed + not sailed);
    ``wait_h``: total wait of the sailed voyages (quantiles); ``wait_cdf`` (rows, step):
    the share of them waiting at most each of :data:`WAIT_STEPS_H`; ``wait_hold_h`` (rows,
    stretch, quantile); ``transit_h``: leaving the first hold point to arrival;
    ``reference_exceedance_probability``: departing at any hour, no rule."""
    q = list(quantiles)
    sailed, exc = d.status == SAILED, d.exceeds
    judged = d.status != NOT_JUDGED
    total = np.where(sailed, np.nansum(d.wait_h, axis=1), np.nan)

    def block(sel):
        s = sailed & sel
        j = judged & sel
        im = (d.immediate >= 0) & sel
        rk = (d.reference_exceeds >= 0) & sel
        w = np.where(s, total, np.nan)
        return {
            "exceedance_probability": _share((exc & s).sum(-1), s.sum(-1)),
            "departure_fraction": _share(((d.immediate == 1) & sel).sum(-1), im.sum(-1)),
            "not_sailed_fraction": _share((j & ~s).sum(-1), j.sum(-1)),
            "wait_h": _quantiles(w, q),
            "transit_h": _quantiles(np.where(s, d.transit_h, np.nan), q),
            "reference_exceedance_probability": _share(((d.reference_exceeds == 1) & sel).sum(-1), rk.sum(-1)),
            "sailed": s.sum(-1), "judged": j.sum(-1),
        }

    every = np.ones(d.status.shape[-1], bool)
    out = block(every)
    steps = np.asarray(WAIT_STEPS_H, float)
    n_s = sailed.sum(-1)
    out["wait_cdf"] = np.stack([_share((sailed & (total <= x)).sum(-1), n_s) for x in steps], axis=-1)
    out["wait_hold_h"] = np.stack([_quantiles(np.where(sailed, d.wait_h[:, s], np.nan), q)
                                   for s in range(d.wait_h.shape[1])], axis=1)
    months = np.asarray(months, int)
    per = [block(months == mo) for mo in range(1, 13)]
    for key in ("exceedance_probability", "departure_fraction", "not_sailed_fraction",
                "wait_h", "transit_h", "reference_exceedance_probability", "sailed", "judged"):
        out[key + "_month"] = np.stack([p[key] for p in per], axis=1)
    return out
