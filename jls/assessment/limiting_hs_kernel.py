"""Compiled kernel of the tip clearance's limiting Hs (numba): Newton's method for
D(H) = A entry by entry, D(H) = H (MPM_r + (F(H) - 1) MPM_eta) with Forristall's crest
factor F (:mod:`jls.assessment.tip_clearance`, its module docstring and
:func:`jls.assessment.tip_clearance.limiting_hs`).

Each entry is iterated on its own until its step is at most 1e-13 of its H (or exactly
zero, or after ``iterations``), with no array formed per iteration: ten years of hourly
sea states x options are tens of millions of entries, which the vectorised iteration
walked some twenty times through memory. The arithmetic is the vectorised iteration's,
operation for operation (F = alpha / alpha0 (ln N)^(1/beta - 1/2), dF/dH, D and dD/dH):
an entry's iterates are the same numbers; only the last step differs where the
vectorised loop went on for entries still moving elsewhere (a change below 1e-13 of H).

Imported by :mod:`jls.assessment.tip_clearance` on first use, so that jobs that never
solve for a limiting Hs do not pay numba's import; compiled code is cached on disk
(``cache=True``); ``nogil``: callers may run slices on threads.
"""

from __future__ import annotations

import math

from numba import njit


@njit(cache=True, nogil=True, error_model="numpy")
def forristall_newton(h, A, mr, me, s, log_n, log_log_n, a, b, alpha0, s1_max, tol, iterations):
    """Newton's method on every entry of the 1-D arrays (all of one length): from
    ``h`` (right of the root, overwritten by the root), allowance ``A``, MPM_r ``mr`` and
    MPM_eta ``me`` per m of Hs, steepness ``s`` per m of Hs, ln N and ln ln N; Forristall's
    slopes ``a`` (alpha) and ``b`` (beta). A step is taken where H is finite and dD/dH > 0
    (else the entry stays: a fixed point)."""
    for i in range(h.shape[0]):
        x = h[i]
        Ai, mri, mei, si, ln, lln = A[i], mr[i], me[i], s[i], log_n[i], log_log_n[i]
        for _ in range(iterations):
            s1 = si * x
            free = s1 <= s1_max
            if s1 > s1_max:                                  # np.minimum: NaN stays NaN
                s1 = s1_max
            alpha = alpha0 + a * s1
            beta = 2.0 - b * s1
            F = alpha / alpha0 * ln ** (1.0 / beta - 0.5)
            dF = si * F * (a / alpha + lln * b / beta**2) if free else 0.0
            D = x * (mri + (F - 1.0) * mei)
            dD = mri + (F - 1.0) * mei + x * dF * mei
            step = (D - Ai) / dD if (math.isfinite(x) and dD > 0) else 0.0
            x = x - step
            if not abs(step) > tol * abs(x):
                break
        h[i] = x
    return h


__all__ = ["forristall_newton"]
