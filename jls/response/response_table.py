"""Every criterion's spectral moments of many hours of parametric wave systems from one
table per gamma: what ten years of hourly partitions cost.

Each criterion is a linear response to the wave elevation: the relative motions, the
tip's motion relative to the wave under it (r = eta - z_t) and the dynamic wire tensions
(:mod:`jls.response.sea_state`, :mod:`jls.response.sea_state_tip_tension`). The wave
systems of an hour are independent, so their cross-spectra have zero mean and the hour's
variance of each response is the sum of its systems' variances. A JONSWAP (or PM) system
of Hs, Tp, gamma, mean direction theta0 and spreading D met on course c gives::

    m_n = Hs^2 sum_h A_h(theta0 - c, D) M_n(h, Tp)     M_n: the unit-Hs long-crested moment
                                                       at RAO heading h (the table)

with A_h the share of the system's directions met at RAO heading h after the linear
interpolation of |H|^2 in heading (exactly as the exact path weights them). The table is
solved once per gamma on a geometric Tp grid of ratio :data:`TP_RATIO` spanning the hours'
Tp (one solve of every candidate at the RAO headings, then one matrix product per block),
and each hour costs a sparse product of its weights with the table
(:func:`jls.response.system_table.hourly_moments`). Tp is interpolated linearly between
the grid's points: the only difference from the exact path. At the ratio 1.01 it is below
0.5 % on sigma of every criterion (``tests/test_response_table.py`` asserts the bound on
random hours against :func:`jls.response.sea_state.heading_moments` and
:func:`jls.response.sea_state_tip_tension.tip_tension_moments`). The wave elevation's
moments (its tail above the RAO range included), the energy outside the RAO range and the
mean period T1 are tabulated or formed per system the same way.

Rule (:func:`use_table`): the table is used for :data:`TABLE_HOURS` sea states or more
whose systems are all JONSWAP or PM; measured spectra (not parametric), Torsethaugen
systems and fewer hours take the exact path.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.errors import InputError
from jls.response.coverage import ENERGY_OUTSIDE_LIMIT, FIELD, zero_bands
from jls.response.solver import moment_weights
from jls.response.statistics import trapezoid_weights
from jls.response.system_table import SystemTable, hourly_moments, system_table
from jls.sea.sea_state import DIRECTIONS, WaveSystem
from jls.sea.spectra import jonswap, t1_from_tp

__all__ = ["TABLE_HOURS", "TP_RATIO", "ResponseTable", "use_table", "tp_grid", "response_table", "table_moments"]

#: sea states from which the table is used (below it the exact path is cheaper: the table
#: costs about as much as as many hours as it has Tp points)
TABLE_HOURS = 1000
#: ratio of neighbouring Tp grid points (sets the interpolation error, module docstring)
TP_RATIO = 1.01
PARAMETRIC = ("jonswap", "pm")


@dataclass(frozen=True)
class ResponseTable:
    """Unit-Hs moments of a JONSWAP of ``gamma`` at each Tp of ``tp`` met long-crested at
    each RAO heading: ``table`` (a :class:`SystemTable`: m0, m2 (n_tp, n_h, c, t, 4 + k),
    the four relative motions then the k outputs of ``parts`` [(name, n)]: the tip points
    and the wires), ``static`` (tip names, heights, static tensions),
    ``wave`` (n_tp, 2) the elevation's m0, m2 in the RAO range, ``tail`` (n_tp, 2) above
    it, ``below`` (n_tp,) the energy below the RAO range."""

    tp: np.ndarray
    gamma: float
    table: SystemTable
    parts: list
    static: dict
    wave: np.ndarray
    tail: np.ndarray
    below: np.ndarray


def _gamma(system: WaveSystem) -> float:
    return 1.0 if system.shape == "pm" else float(system.gamma)


def use_table(states) -> bool:
    """The rule of the module docstring."""
    states = list(states)
    return len(states) >= TABLE_HOURS and all(s.shape in PARAMETRIC for st in states for s in st.systems)


def tp_grid(tp) -> np.ndarray:
    """A geometric grid of ratio :data:`TP_RATIO` spanning ``tp`` [s] (at least 2 points)."""
    tp = np.asarray(tp, float)
    lo, hi = float(tp.min()) / TP_RATIO, float(tp.max()) * TP_RATIO
    n = max(int(np.ceil(np.log(hi / lo) / np.log(TP_RATIO))) + 1, 2)
    return np.geomspace(lo, hi, n)


def response_table(tr, tp, gamma, *, tip=None, hinge_xy=(0.0, 0.0), g=9.81, tensions=False,
                   threads=None) -> ResponseTable:
    """The :class:`ResponseTable` of a :class:`jls.response.sea_state.SeaStateTransfer` on the
    Tp grid ``tp`` for JONSWAP systems of ``gamma``; ``tip``, ``hinge_xy``, ``g``,
    ``tensions`` as :func:`jls.response.sea_state_tip_tension.tip_tension_moments`."""
    from jls.response.sea_state_tip_tension import BLOCK, power_rows, system_tail_moments
    from jls.sea.sea_state import SeaState, Spreading
    tp = np.asarray(tp, float)
    motions = system_table(tr, tp, gamma, threads=threads)
    omega = tr.exc.omega
    S = np.asarray(jonswap(omega[None, :], 1.0, tp[:, None], float(gamma)), float)       # (n_tp, n_w)
    W = moment_weights(omega, S)                                                         # (n_w, 2 n_tp)
    tw = trapezoid_weights(omega)
    wave = np.stack([S @ tw, S @ (tw * omega**2)], axis=1)
    unit = [SeaState((WaveSystem("jonswap", 1.0, float(t), 0.0, Spreading("long-crested"), "wind",
                                 float(gamma)),)) for t in tp]
    tail = np.array([system_tail_moments(s, omega[-1]) for s in unit])
    low = np.linspace(0.0, float(omega[0]), 4001)
    below = np.trapezoid(np.asarray(jonswap(low[None, :], 1.0, tp[:, None], float(gamma)), float), low, axis=1)
    # the blocks of candidates on the threads given, each solved on one (a block's numbers
    # are its own: the same whatever the threads)
    parts, static, block_rows = power_rows(tr, tip=tip, hinge_xy=hinge_xy, g=g, tensions=tensions, threads=1)
    table = motions
    if parts:
        from jls.threads import thread_map
        n_c, n_t, n_h, n_w = tr.plant.sizes["candidate"], len(tr.tuggers), tr.exc.headings.size, omega.size
        k = sum(n for _, n in parts)
        m = np.empty((2, tp.size, n_h, n_c, n_t, k))

        def block(b):
            sl = slice(b, min(b + BLOCK, n_c))
            nb, rows = block_rows(sl)
            at = 0
            for _, n, r in rows:
                x = (r.reshape(-1, n_w) @ W).reshape(nb, n_t, n, n_h, 2, tp.size)
                m[:, :, :, sl, :, at:at + n] = np.transpose(x, (4, 5, 3, 0, 1, 2))
                at += n

        thread_map(block, range(0, n_c, BLOCK), threads)
        table = SystemTable(tp, motions.headings, float(gamma), tr.symmetric,
                            np.concatenate([motions.m0, m[0]], axis=-1), np.concatenate([motions.m2, m[1]], axis=-1))
    return ResponseTable(tp, float(gamma), table, parts, static, wave, tail, below)


def _slots(states):
    """{gamma: [(hour index array, [(hs, tp, from) per hour], spreading)]}: the hours'
    systems grouped by gamma and spreading, one slot per occurrence within an hour."""
    groups = {}
    for i, st in enumerate(states):
        seen = {}
        for s in st.systems:
            key = (_gamma(s), s.spreading)
            j = seen.get(key, 0)
            seen[key] = j + 1
            slots = groups.setdefault(key, [])
            if j == len(slots):
                slots.append({})
            slots[j][i] = (s.hs, s.tp, s.from_deg)
    out = {}
    for (gamma, spread), slots in groups.items():
        for slot in slots:
            out.setdefault(gamma, []).append((slot, spread))
    return out


def table_moments(tables: dict, states, course, *, tr=None, n_dirs=DIRECTIONS, source=None) -> dict:
    """Moments of each sea state (all systems JONSWAP or PM) met on ``course`` [deg true]
    (one per state) from ``tables`` {gamma: :class:`ResponseTable`}: ``m0``, ``m2`` (n, c,
    t, 4) of the relative motions and the dict of
    :func:`jls.response.sea_state_tip_tension.tip_tension_moments` (when the tables have
    tip or tension outputs), and ``energy_outside`` (n,), checked as
    :func:`jls.response.sea_state.energy_outside` (``tr``: its ``outside_policy`` and grid)."""
    states = list(states)
    n = len(states)
    course = np.broadcast_to(np.asarray(course, float), (n,))
    first = next(iter(tables.values()))
    out = {"m0": 0.0, "m2": 0.0}
    out.update(first.static)
    e = np.zeros((4, n))        # variance; the wave m0 in the RAO range, below it; the wave m2 in it
    m1 = np.zeros(n)
    tail = np.zeros((2, n))
    for gamma, slots in _slots(states).items():
        tab = tables[gamma]
        for slot, spread in slots:
            hs, tp, d = (np.full(n, np.nan) for _ in range(3))
            idx = np.fromiter(slot.keys(), int)
            vals = np.array(list(slot.values()), float).reshape(-1, 3)
            hs[idx], tp[idx], d[idx] = vals.T
            sys = [(hs, tp, d, spread)]
            a0, a2 = hourly_moments(tab.table, sys, course, n_dirs=n_dirs)
            if isinstance(out["m0"], np.ndarray):             # the systems' moments add (in place)
                out["m0"] += a0
                out["m2"] += a2
            else:
                out["m0"], out["m2"] = a0, a2
            ok = np.isfinite(hs) & (hs > 0)
            h2 = np.where(ok, hs, 0.0) ** 2
            t = np.where(ok, tp, tab.tp[0])
            v = h2 / 16.0
            e[0] += v
            e[1] += h2 * np.interp(t, tab.tp, tab.wave[:, 0])
            e[2] += h2 * np.interp(t, tab.tp, tab.below)
            e[3] += h2 * np.interp(t, tab.tp, tab.wave[:, 1])
            tail[0] += h2 * np.interp(t, tab.tp, tab.tail[:, 0])
            tail[1] += h2 * np.interp(t, tab.tp, tab.tail[:, 1])
            m1 += np.where(ok, v * 2.0 * np.pi / np.asarray(t1_from_tp(t, gamma), float), 0.0)
    out["hs"] = 4.0 * np.sqrt(e[0])
    with np.errstate(divide="ignore", invalid="ignore"):
        out["wave_t1"] = np.where(m1 > 0, 2.0 * np.pi * e[0] / m1, np.nan)
        outside = np.where(e[0] > 0, (e[2] + np.maximum(e[0] - e[2] - e[1], 0.0)) / e[0], 0.0)
    out["wave_m0"], out["wave_m2"] = e[1] + tail[0], e[3] + tail[1]
    m0, m2 = out["m0"], out["m2"]
    out["m0"], out["m2"] = m0[..., :4], m2[..., :4]
    at = 4
    for name, k in first.parts:
        out[f"{name}_m0"], out[f"{name}_m2"] = m0[..., at:at + k], m2[..., at:at + k]
        at += k
    if first.parts:
        if "tip_m0" in out:
            out["tip_m0"] = out["tip_m0"] + tail[0][:, None, None, None]
            out["tip_m2"] = out["tip_m2"] + tail[1][:, None, None, None]
    if tr is not None:
        omega = tr.exc.omega
        lo, hi = float(omega[0]), float(omega[-1])
        below, above = zero_bands(tr.outside_policy, source)
        high = np.maximum(e[0] - e[2] - e[1], 0.0)
        explained = (e[2] if below >= lo else 0.0) + (high if np.isfinite(above) and above <= hi else 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            bad = np.flatnonzero((e[0] > 0) & (outside - explained / np.where(e[0] > 0, e[0], 1.0)
                                               > ENERGY_OUTSIDE_LIMIT))
        if bad.size:
            s = states[int(bad[0])]
            raise InputError(f"the sea state ({s.describe()}) has {100 * outside[bad[0]]:.2f} % of its energy "
                             f"outside the RAO range [{lo:.3f}, {hi:.3f}] rad/s and the stated "
                             "zero-motion bands; extend the RAOs or state the band where the vessel "
                             "does not move", file=source, field=FIELD, value=round(100 * float(outside[bad[0]]), 3))
    out["energy_outside"] = outside
    return out
