"""Frequency-domain solver of the suspended jacket (sections 3.3, 4.4 and 6.7).

For each wave frequency omega and heading, the hinge moves as qb(omega) (complex
amplitude per unit wave amplitude) and the jacket responds as

    (K - omega^2 M + i omega C) q = -Kb qb

(eq. 3.10 in the frequency domain, time factor exp(i omega t)). A damping tugger is a
linear damper of slope c [kN s/m] between the fairlead and the jacket, acting along the
sway direction at the height of the CoG (section 6.3, frequency-domain form, no winch
limits): it adds i omega c to the sway-sway term and i omega c y_f to the load, with y_f
the fairlead sway. Relative motions are taken against the hinge: y - y_b, z - z_b,
phi - phi_b, psi - psi_b.

**Solve.** The tugger makes the damping non-proportional, so every 4x4 system is solved
exactly: a compiled LU with partial pivoting (:mod:`jls.response.kernels`), one
factorisation per candidate and frequency; the tugger is a rank-one change of the sway
term, so every tugger setting follows from that factorisation by the Sherman-Morrison
formula. It returns |H|^2 of the relative motions directly, which is all the statistics
need.

**Frequency grid.** One grid serves every candidate of a run, and its size does not grow
with their number. The trapezoid rule on a uniform grid integrates a resonance peak
(poles at distance d = zeta omega_n from the real axis) with a relative error of about
2 exp(-2 pi d / h), so a step h = 2 d / points_per_bandwidth suffices; the grid takes the
base step everywhere and, inside a band around each lightly damped mode of any
candidate, the finest step any candidate there needs. Work and memory are therefore
linear in the number of candidates: at most (omega_hi - omega_lo) / h_min frequencies
each, however many there are.

**Statistics** are BLAS matrix products: the moments of all candidates, tuggers,
headings and responses are ``(|H|^2) @ (weights x spectra).T`` in one call per block of
candidates, on one BLAS thread (a multi-threaded BLAS rounds differently; the solver's
threads give the same numbers for any thread count).
"""

from __future__ import annotations

import math

import numpy as np

from jls.names import ROTATIONAL
from jls.response.statistics import trapezoid_weights

#: Factor from the solver's units (m, rad) to the datasets' (m, degree) per response.
SCALE = np.where(ROTATIONAL, 180.0 / np.pi, 1.0)

POINTS_PER_BANDWIDTH = 6     # trapezoid error ~ 2 exp(-pi ppb) ~ 1e-8 on a resonance
BAND_HALF_WIDTH = 50.0       # refined band: +/- this many d = zeta omega_n ...
BAND_MIN_BASE_STEPS = 20.0   # ... and at least this many base steps


def frequency_grid(omega_lo, omega_hi, step, natural_omega=(), zeta=(),
                   points_per_bandwidth=POINTS_PER_BANDWIDTH):
    """One frequency grid over [omega_lo, omega_hi] for any number of candidates.

    natural_omega, zeta: natural frequencies [rad/s] and damping ratios of the modes to
    resolve, any shape (broadcast; non-finite or out-of-range modes are ignored). Around
    each mode the step is ``2 zeta omega_n / points_per_bandwidth`` over
    +/- max(50 zeta omega_n, 20 step); elsewhere ``step``. The result has at most
    (omega_hi - omega_lo) / min(step) + 1 points whatever the number of modes.
    """
    wn, z = np.broadcast_arrays(np.asarray(natural_omega, float), np.asarray(zeta, float))
    wn, z = wn.ravel(), z.ravel()
    ok = np.isfinite(wn) & np.isfinite(z) & (z > 0) & (wn > omega_lo) & (wn < omega_hi)
    wn, z = wn[ok], z[ok]
    need = np.minimum(2.0 * z * wn / points_per_bandwidth, step)
    half = np.maximum(BAND_HALF_WIDTH * z * wn, BAND_MIN_BASE_STEPS * step)
    # Required step on a resolution grid of the finest step (bounded size): the minimum
    # over the bands covering each cell, coarsest bands written first.
    fine = float(need.min()) if need.size else step
    n_cells = int(np.ceil((omega_hi - omega_lo) / fine))
    required = np.full(n_cells, float(step))
    order = np.argsort(-need, kind="stable")
    i0 = np.clip(((wn - half - omega_lo) / fine).astype(np.int64), 0, n_cells)[order]
    i1 = np.clip(np.ceil((wn + half - omega_lo) / fine).astype(np.int64), 0, n_cells)[order]
    for a, b, h in zip(i0, i1, need[order]):
        np.minimum(required[a:b], h, out=required[a:b])
    points = [omega_lo]
    w = omega_lo
    required = required.tolist()      # the walk is sequential: Python floats, no array calls
    while True:
        cell = min(int((w - omega_lo) / fine), n_cells - 1)
        h = required[cell]
        # never step over a finer band ahead
        h = min(required[cell:min(n_cells, cell + math.ceil(h / fine) + 1)])
        w = w + h
        if w >= omega_hi - 1e-9 * h:
            break
        points.append(w)
    points.append(omega_hi)
    return np.asarray(points)


def _solve(kernel_name, threads, M, K, C, Kb, *shared, out):
    """Run a compiled kernel over the candidates, in ``threads`` contiguous slices on
    threads (the kernels release the GIL). Each candidate is solved on its own, so the
    result is the same, bit for bit, for any number of threads."""
    from jls.response import kernels as k  # numba: imported on first solve only
    kernel = getattr(k, kernel_name)
    from jls.threads import thread_map
    n = M.shape[0]
    parts = max(1, min(int(threads or 1), n))
    edges = np.linspace(0, n, parts + 1).astype(int)
    thread_map(lambda s: kernel(M[s], K[s], C[s], Kb[s], *shared, out[s]),
               [slice(lo, hi) for lo, hi in zip(edges[:-1], edges[1:])], parts)


def _array(a, dtype):
    """C-contiguous and writable (numba compiles read-only arrays separately)."""
    return np.require(np.asarray(a, dtype), dtype, ["C", "W"])


def _prepare(M, K, Kb, C, omega, qb, fairlead_sway, c_tugger):
    M, K, Kb, C = (_array(np.asarray(a, float).reshape(-1, 4, 4), float) for a in (M, K, Kb, C))
    omega = _array(np.asarray(omega, float).ravel(), float)
    c_t = _array(np.atleast_1d(np.asarray(c_tugger, float)), float)
    qb = _array(qb, complex)
    if qb.ndim != 3 or qb.shape[1:] != (omega.size, 4):
        raise ValueError("qb must be (n_heading, n_omega, 4)")
    if fairlead_sway is None:
        if np.any(c_t != 0):
            raise ValueError("a tugger needs the fairlead sway RAO")
        yf = np.zeros(qb.shape[:2], complex)
    else:
        yf = _array(np.broadcast_to(np.asarray(fairlead_sway, complex), qb.shape[:2]), complex)
    if not (np.all(np.isfinite(omega)) and np.all(np.isfinite(qb)) and np.all(np.isfinite(yf))
            and np.all(np.isfinite(c_t))):
        raise ValueError("omega, qb, fairlead_sway and c_tugger must be finite")
    # The kernels assume finite numbers: solve a finite stand-in for a non-finite plant
    # and mark its results NaN afterwards.
    bad = ~np.all(np.isfinite(np.stack([M, K, Kb, C], axis=1)), axis=(1, 2, 3))
    if bad.any():
        M, K, Kb, C = (a.copy() for a in (M, K, Kb, C))
        for a, v in ((M, np.eye(4)), (K, np.eye(4)), (Kb, 0.0), (C, np.eye(4))):
            a[bad] = v
    return M, K, Kb, C, omega, qb, yf, c_t, bad


def relative_power(M, K, Kb, C, omega, qb, fairlead_sway=None, c_tugger=0.0, *, threads=None):
    """|H|^2 of the relative motions in m^2/m^2 and degree^2/m^2.

    M, K, Kb, C: (n_c, 4, 4) or (4, 4); omega (n_w,); qb (n_h, n_w, 4) hinge RAO;
    fairlead_sway (n_h, n_w) (needed when a tugger slope is non-zero); c_tugger (n_t,).
    Returns (n_c, n_t, n_h, 4, n_w) float64 (response order of ``RESPONSES``).
    """
    M, K, Kb, C, omega, qb, yf, c_t, bad = _prepare(M, K, Kb, C, omega, qb, fairlead_sway, c_tugger)
    out = np.empty((M.shape[0], c_t.size, qb.shape[0], 4, omega.size))
    _solve("relative_power", threads, M, K, C, Kb, c_t, omega, qb, yf, _array(SCALE, float), out=out)
    out[bad] = np.nan
    return out


def transfer_functions(M, K, Kb, C, omega, qb, fairlead_sway=None, c_tugger=0.0, *, threads=None,
                       relative=True):
    """Complex transfer functions of q and of the relative motions per unit wave amplitude.

    Shapes as :func:`relative_power`. Returns Hq, Hrel: (n_c, n_t, n_h, n_w, 4) complex in
    m/m and rad/m (a single (4, 4) plant drops the candidate axis); ``relative=False``:
    Hrel is not formed (None).
    """
    single = np.ndim(M) == 2
    M, K, Kb, C, omega, qb, yf, c_t, bad = _prepare(M, K, Kb, C, omega, qb, fairlead_sway, c_tugger)
    out = np.empty((M.shape[0], c_t.size, qb.shape[0], 4, omega.size), complex)
    _solve("absolute_transfer", threads, M, K, C, Kb, c_t, omega, qb, yf, out=out)
    out[bad] = np.nan
    Hq = np.moveaxis(out, -2, -1)
    Hrel = Hq - qb if relative else None
    return (Hq[0], None if Hrel is None else Hrel[0]) if single else (Hq, Hrel)


def moment_weights(omega, spectra):
    """(n_w, 2 n_tz) matrix W such that P @ W = [m0, m2] for rows P of |H|^2 on omega.

    spectra: (n_tz, n_w) at Hs = 1 m. The trapezoid rule on the (non-uniform) grid.
    """
    omega = np.asarray(omega, float)
    w = trapezoid_weights(omega)
    S = np.asarray(spectra, float)
    return np.ascontiguousarray(np.concatenate([S * w, S * (w * omega**2)], axis=0).T)


def spectral_moments(power, weights):
    """m0, m2 of every row of ``power`` (..., n_w) with :func:`moment_weights`: one BLAS
    matrix product, on one BLAS thread (:func:`jls.threads.single_threaded_blas`), so the
    moments are the same, bit for bit, whatever the threads of the process. Returns two
    arrays (..., n_tz)."""
    from jls.threads import single_threaded_blas
    lead = power.shape[:-1]
    with single_threaded_blas():
        m = power.reshape(-1, power.shape[-1]) @ weights
    n_tz = weights.shape[1] // 2
    return m[:, :n_tz].reshape(lead + (n_tz,)), m[:, n_tz:].reshape(lead + (n_tz,))
