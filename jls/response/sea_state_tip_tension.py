"""Tip clearance and hoist-wire tensions in sea states of wave systems: the statistics the
criteria ``tip_air_gap_m`` and the wire-tension criteria need, for sea states met at the
vessel's heading (a forecast hour's systems with their spreading), every candidate and
tugger at once.

Both are linear outputs of the plant whose transfer function is known per RAO heading:
the dynamic wire tensions (:func:`jls.response.tension.tension_transfer`) and the tip's
downward motion relative to the wave surface under it, r = eta - z_t
(:func:`jls.response.tip.relative_transfer`). So, as for the relative motions
(:func:`jls.response.sea_state.heading_moments`), their variance in a directional sea is
the power |H|^2 at the RAO headings weighted by the spectrum met at each heading
A_h(omega) (:func:`jls.response.sea_state._heading_spectra`, the same linear interpolation
of |H|^2 in heading): one solve of the absolute transfer functions per candidate and
tugger, whatever the number of sea states, and one matrix product per block of
candidates. Linear in candidates and sea states.

As in :mod:`jls.response.tip`, the spectrum's energy above the RAO range (where hull and
jacket are still but the waves are not) is added to the relative motion and to the wave
elevation: per system on a geometric grid over three decades plus the analytic omega^-5
tail beyond (:func:`jls.response.tip.tail_moments`, here per system of any shape). The
wave elevation's moments are those of the whole spectrum in the RAO range plus that tail;
its mean period T1 = 2 pi m0 / m1 combines the systems' m1 (a JONSWAP or PM system's T1
from its Tp and gamma by DNV-RP-C205, as the workflow's tip statistics; any other
system's by the trapezoid rule on its spectrum).
"""

from __future__ import annotations

import numpy as np

from jls.response.moments import _matrices
from jls.response.sea_state import (
    DIRECTIONS,
    HEADING_GROUP,
    SeaStateTransfer,
    _states,
    group_products,
    heading_products,
    hold_powers,
)
from jls.response.solver import transfer_functions
from jls.response.tension import plant_gradients
from jls.response.tip import TipSettings, _Elevation, relative_transfer, still_water_height, tip_points
from jls.response.wire_loads import has_geometry
from jls.sea.spectra import t1_from_tp
from jls.threads import single_threaded_blas

__all__ = ["BLOCK", "system_tail_moments", "mean_period_t1", "power_rows", "tip_tension_moments"]

BLOCK = 4             # candidates per solve (complex transfer functions: bounded memory)


def system_tail_moments(state, omega_hi, decades=3.0, points=4000):
    """(m0, m2) of a sea state's spectrum above ``omega_hi`` [rad/s], summed over its
    systems: :func:`jls.response.tip.tail_moments`'s grid and omega^-5 tail, any shape."""
    w = np.geomspace(float(omega_hi), float(omega_hi) * 10.0**decades, points)
    m0 = m2 = 0.0
    for sys in state.systems:
        S = sys.spectrum(w)
        m0 += float(np.trapezoid(S, w) + S[-1] * w[-1] / 4.0)
        m2 += float(np.trapezoid(S * w**2, w) + S[-1] * w[-1] ** 3 / 2.0)
    return m0, m2


def mean_period_t1(state) -> float:
    """T1 = 2 pi m0 / m1 [s] of a sea state, from its systems' m0 and m1 (module docstring)."""
    m0 = m1 = 0.0
    for sys in state.systems:
        v = sys.m0()
        if v <= 0:
            continue
        if sys.shape in ("jonswap", "pm"):
            m1 += v * 2.0 * np.pi / float(t1_from_tp(sys.tp, 1.0 if sys.shape == "pm" else sys.gamma))
        else:
            w = sys.omega if sys.shape == "measured" else np.linspace(1e-3, 60 * 2 * np.pi / sys.tp, 20000)
            S = sys.spectrum(w)
            v = float(np.trapezoid(S, w))
            m1 += float(np.trapezoid(S * w, w))
        m0 += v
    return 2.0 * np.pi * m0 / m1 if m1 > 0 else np.nan


def _tension_power(Hq, qb_re, qb_im, grad_q, grad_qb, k):
    """|H|^2 (c, t, wire, h, w) [kN^2/m^2] of the dynamic wire tensions: the transfer function
    of :func:`jls.response.tension.tension_transfer`, k (dL/dq Hq + dL/dqb qb), formed in
    real arithmetic as matrix products over the DOFs (its real and imaginary parts apart);
    Hq (c, t, h, w, 4), qb_re and qb_im (h, 4, w)."""
    g = grad_q[:, None, None]                                    # (c, 1, 1, wire, 4)
    gb = grad_qb[:, None, None]
    kk = k[:, None, None, :, None]
    power = 0.0
    for part, b in ((Hq.real, qb_re), (Hq.imag, qb_im)):
        x = kk * (np.matmul(g, np.ascontiguousarray(np.moveaxis(part, -1, -2))) + np.matmul(gb, b))
        power = power + x * x                                    # (c, t, h, wire, w)
    return np.ascontiguousarray(np.moveaxis(power, 3, 2))


def power_rows(tr: SeaStateTransfer, *, tip: TipSettings | None, hinge_xy=(0.0, 0.0), g=9.81, tensions=True,
               threads=None):
    """(parts, static, block_rows) of :func:`tip_tension_moments`: ``parts`` [(name, n)] of
    the outputs ("tip": one per tip point, "tension": one per wire), ``static`` the arrays
    that do not depend on the sea (``tip``, ``tip_height``, ``tension_static``) and
    ``block_rows(sl)`` -> (nb, [(name, n, |H|^2 rows (nb t n, n_h n_w))]) of a block of
    candidates ``sl``: the power at the RAO headings on the solver's grid."""
    exc, plant = tr.exc, tr.plant
    omega = exc.omega
    n_w, n_h = omega.size, exc.headings.size
    M, K, Kb, C = _matrices(plant, slice(None))
    c_t = [float(v) for v in tr.tuggers.values()]
    parts, static = [], {}
    if tip is not None:
        names, tx, ty = tip_points(plant, tip)
        eta = _Elevation(omega, exc.headings, float(hinge_xy[0]) + tx, float(hinge_xy[1]) + ty, g)
        parts.append(("tip", len(names)))
        static["tip"] = names
        static["tip_height"] = still_water_height(tip, plant["drop_height"].values)
    if tensions:
        if not has_geometry(plant):
            raise ValueError("wire tensions need the geometric plant, not one given as matrices")
        grad_q, grad_qb, k = plant_gradients(plant)
        parts.append(("tension", k.shape[-1]))
        static["tension_static"] = plant["tension"].transpose("candidate", "wire").values
        qb_re, qb_im = (np.ascontiguousarray(np.moveaxis(x, -1, -2)) for x in (exc.qb.real, exc.qb.imag))

    def block_rows(sl):
        """[(name, n, |H|^2 rows (nb t n, n_h n_w))] of a block of candidates."""
        Hq, _ = transfer_functions(M[sl], K[sl], Kb[sl], C[sl], omega, exc.qb, exc.fairlead_sway, c_t,
                                   threads=threads, relative=False)         # (nb, t, h, w, 4)
        rows = []
        for name, n in parts:
            if name == "tip":
                H = relative_transfer(Hq, eta[sl], ty[sl])                   # (nb, t, tip, h, w)
                rows.append((name, n, (H.real**2 + H.imag**2).reshape(-1, n_h * n_w)))
            else:
                rows.append((name, n, _tension_power(Hq, qb_re, qb_im, grad_q[sl], grad_qb[sl],
                                                     k[sl]).reshape(-1, n_h * n_w)))
        return Hq.shape[0], rows

    return parts, static, block_rows


def tip_tension_moments(tr: SeaStateTransfer, sea_states, vessel_heading_deg, *, tip: TipSettings | None,
                        hinge_xy=(0.0, 0.0), g=9.81, tensions=True, n_dirs=DIRECTIONS, threads=None,
                        products=None) -> dict:
    """Spectral moments of the tip's relative motion and of the wire tensions of each sea
    state met on ``vessel_heading_deg`` [deg true] (one, or one per sea state).

    tip: the tip settings (None: no tip statistics); hinge_xy: the hinge's horizontal
    lever arm from the RAO reference point [m]; g [m/s^2]; tensions: compute the wire
    tensions (the plant must carry its wire geometry, :func:`has_geometry`); products:
    :func:`jls.response.sea_state.heading_products` of these sea states when the caller
    has them (shared with the relative motions).

    Returns a dict: ``wave_m0``, ``wave_m2`` (n_s,) [m^2, m^2/s^2] with the tail above the
    RAO range, ``wave_t1`` (n_s,) [s], ``hs`` (n_s,) [m]; with ``tip``: ``tip_m0``,
    ``tip_m2`` (n_s, c, t, tip) with the tail, ``tip_height`` (c,) [m] (the still-water
    height the criterion takes), ``tip`` (names); with ``tensions``: ``tension_m0``,
    ``tension_m2`` (n_s, c, t, wire) [kN^2, kN^2/s^2] and ``tension_static`` (c, wire) [kN].
    """
    states = _states(sea_states)
    course = np.broadcast_to(np.asarray(vessel_heading_deg, float), (len(states),))
    omega = tr.exc.omega
    n_s = len(states)
    n_c, n_t = tr.plant.sizes["candidate"], len(tr.tuggers)
    tails = np.array([system_tail_moments(s, omega[-1]) for s in states]).reshape(n_s, 2)
    out = {"hs": np.array([4.0 * np.sqrt(sum(x.m0() for x in s.systems)) for s in states]),
           "wave_t1": np.array([mean_period_t1(s) for s in states])}
    parts, static, block_rows = power_rows(tr, tip=tip, hinge_xy=hinge_xy, g=g, tensions=tensions, threads=threads)
    out.update(static)
    for name, n in parts:
        for q in (0, 2):
            out[f"{name}_m{q}"] = np.zeros((n_s, n_c, n_t, n))

    def products_into(gr, an, sl, nb, rows):
        with single_threaded_blas():
            for name, n, r in rows:
                for q, key in ((0, f"{name}_m0"), (1, f"{name}_m2")):
                    out[key][gr, sl] = (r @ an[q]).reshape(nb, n_t, n, -1).transpose(3, 0, 1, 2)

    blocks = [slice(b, min(b + BLOCK, n_c)) for b in range(0, n_c, BLOCK)]
    wave = np.zeros((2, n_s))
    if hold_powers(tr, n_s, products):     # every candidate's powers held, each group's products dropped
        held = [(sl, *block_rows(sl)) for sl in blocks] if parts else []
        for a in range(0, n_s, HEADING_GROUP):
            gr = slice(a, min(a + HEADING_GROUP, n_s))
            an = group_products(tr, states[gr], course[gr], n_dirs)
            wave[0, gr], wave[1, gr] = an[0].sum(axis=0), an[1].sum(axis=0)
            for sl, nb, rows in held:
                products_into(gr, an, sl, nb, rows)
    else:
        groups, An = heading_products(tr, states, course, n_dirs) if products is None else products
        for gr, an in zip(groups, An):
            wave[0, gr], wave[1, gr] = an[0].sum(axis=0), an[1].sum(axis=0)
        for sl in blocks if parts else []:
            nb, rows = block_rows(sl)
            for gr, an in zip(groups, An):
                products_into(gr, an, sl, nb, rows)
    out["wave_m0"], out["wave_m2"] = wave[0] + tails[:, 0], wave[1] + tails[:, 1]
    if not parts:
        return out
    if tip is not None:
        out["tip_m0"] += tails[:, 0, None, None, None]
        out["tip_m2"] += tails[:, 1, None, None, None]
    return out
