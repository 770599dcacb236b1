"""Go or no-go on a forecast: from which hour a leg may be started so that every hour of
it, its contingency included, stays inside the forecast limits.

An hour's *utilisation* is the largest, over the criteria, of the hour's 3-h MPM over its
limit, divided by the forecast-uncertainty factor alpha of the hour (DNV-ST-N001:
OP_WF = alpha OP_LIM, so a response at utilisation u against OP_LIM is u / alpha against
OP_WF). A start at hour s is a **go** when every hour of ``[s, s + L)`` has utilisation
at most 1, with ``L`` the leg's planned duration plus its contingency in whole hours.
An hour the forecast does not cover (after its last hour, or beyond the lead times of
the alpha table) is never inside the limits: a window that reaches it is a no-go with
that reason, never a go.

Alpha per lead time and Hs (:class:`LeadTimeAlpha`) is configured with its source; the
lead-time values are the upper ends of the table's classes (an hour at 13 h lead time
takes the row of the first lead time >= 13 h), linear in Hs between the table's values
and held at its ends (never extrapolated). Without a table alpha is 1, and the answer
says so.

The scan is O(hours) per option: a running count of the hours outside the limits.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.errors import InputError

__all__ = ["LeadTimeAlpha", "Decision", "alpha_factors", "window_hours", "decide"]

FIELD = "forecast.alpha_factors"


@dataclass(frozen=True)
class LeadTimeAlpha:
    """Forecast-uncertainty factors: ``lead_time_h`` (n_l,) upper ends of the lead-time
    classes [h], ``hs_m`` (n_h,) Hs [m], ``alpha`` (n_l, n_h) in (0, 1], with ``source``."""

    source: str
    lead_time_h: np.ndarray
    hs_m: np.ndarray
    alpha: np.ndarray

    def __post_init__(self):
        lead, hs, a = (np.asarray(x, float) for x in (self.lead_time_h, self.hs_m, self.alpha))
        if not str(self.source).strip():
            raise InputError("an alpha table needs its source", field=f"{FIELD}.source", value=self.source)
        if a.ndim != 2 or a.shape != (lead.size, hs.size):
            raise InputError(f"alpha must be {lead.size} lead times x {hs.size} Hs values",
                             field=f"{FIELD}.alpha", value=a.tolist())
        for name, x in (("lead_time_h", lead), ("hs_m", hs)):
            if x.size < 1 or np.any(np.diff(x) <= 0) or np.any(x <= 0):
                raise InputError("must be positive and increase strictly", field=f"{FIELD}.{name}",
                                 value=x.tolist())
        if np.any(~np.isfinite(a) | (a <= 0) | (a > 1)):
            raise InputError("alpha factors lie in (0, 1]", field=f"{FIELD}.alpha", value=a.tolist())
        object.__setattr__(self, "lead_time_h", lead)
        object.__setattr__(self, "hs_m", hs)
        object.__setattr__(self, "alpha", a)

    def __call__(self, lead_h, hs) -> np.ndarray:
        """alpha at each (lead time [h], Hs [m]); NaN beyond the table's last lead time."""
        lead = np.asarray(lead_h, float)
        hs = np.broadcast_to(np.asarray(hs, float), lead.shape)
        row = np.searchsorted(self.lead_time_h, lead, side="left")        # first class >= lead
        out = np.full(lead.shape, np.nan)
        inside = (row < self.lead_time_h.size) & (lead >= 0)
        for r in np.unique(row[inside]):
            k = inside & (row == r)
            out[k] = np.interp(hs[k], self.hs_m, self.alpha[r])
        return out


def alpha_factors(table: LeadTimeAlpha | None, lead_h, hs) -> np.ndarray:
    """alpha per hour: the table's, or 1 without a table."""
    lead = np.asarray(lead_h, float)
    return np.ones(lead.shape) if table is None else table(lead, hs)


def window_hours(duration_h: float, contingency_h: float) -> int:
    """Hours a start must find inside the limits: the leg's duration plus contingency,
    rounded up to whole hours."""
    total = float(duration_h) + float(contingency_h)
    if not (np.isfinite(total) and total > 0):
        raise InputError("a leg's duration plus contingency must be positive", field="duration_h",
                         value=total)
    return int(np.ceil(total - 1e-9))


@dataclass(frozen=True)
class Decision:
    """One option's answer. ``first_start``: index of the first hour >= the requested start
    from which the leg stays inside (None: no such hour in the forecast); ``go``: that hour
    is the requested start; ``governing``: (criterion, hour index) of the largest
    utilisation of the window from the requested start (None where it is not covered);
    ``margin``: 1 minus that utilisation; ``reason``: why not, for a no-go."""

    go: bool
    first_start: int | None
    governing: tuple | None
    margin: float | None
    reason: str


def decide(utilisation: np.ndarray, criterion_utilisation: np.ndarray, criteria, start: int,
           hours: int, uncovered_reason: str = "the forecast ends before the leg does",
           strict=None) -> list[Decision]:
    """Decisions for every option from ``utilisation`` (options, n_hours), the per-hour
    largest over the criteria divided by alpha (NaN: hour not covered), and
    ``criterion_utilisation`` (options, n_hours, criteria) to name the governing criterion;
    the leg starts at hour index ``start`` at the earliest and needs ``hours`` hours.
    ``strict`` (criteria,) bool: criteria that must stay strictly below 1 (the tension
    floors: a wire at its floor has gone as low as allowed), an hour at 1 on them is out."""
    u = np.asarray(utilisation, float)
    n_opt, n = u.shape
    if not 0 <= start < n:
        raise InputError(f"the start lies outside the forecast's {n} hours", field="start", value=start)
    bad = ~(u <= 1.0)                                      # NaN (not covered) is never inside
    if strict is not None and np.any(strict):
        bad |= np.any(np.asarray(criterion_utilisation)[..., np.asarray(strict, bool)] >= 1.0, axis=-1)
    counts = np.zeros((n_opt, n + 1), int)
    np.cumsum(bad, axis=1, out=counts[:, 1:])
    starts = np.arange(start, n - hours + 1)
    out = []
    for i in range(n_opt):
        inside = counts[i, starts + hours] - counts[i, starts] == 0 if starts.size else np.zeros(0, bool)
        first = int(starts[np.argmax(inside)]) if inside.any() else None
        window = u[i, start:start + hours]
        covered = start + hours <= n and np.all(np.isfinite(window))
        governing = margin = None
        if covered:
            k = int(np.argmax(window))
            c = int(np.argmax(criterion_utilisation[i, start + k]))
            governing, margin = (str(criteria[c]), start + k), float(1.0 - window[k])
        go = first == start
        if go:
            reason = ""
        elif not covered:
            reason = uncovered_reason
        else:
            k = int(np.flatnonzero(bad[i, start:start + hours])[0])
            reason = (f"utilisation {window[k]:.2f} > 1 at hour {k} of the leg" if window[k] > 1.0 else
                      f"utilisation 1 on a strict limit at hour {k} of the leg")
        out.append(Decision(go, first, governing, margin, reason))
    return out
