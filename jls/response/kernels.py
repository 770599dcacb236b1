"""Compiled kernels of the frequency-domain solver (numba): a batched 4x4 complex solve.

For every candidate c, tugger t and frequency w the system

    A_t q = b_t,   A_t = A0 + i w c_t e e^T,   A0 = K - w^2 M + i w C,
    b_t = -Kb qb + i w c_t y_f e                 (e = e_sway)

is solved exactly. The tugger makes the damping non-proportional, so no modal shortcut
is taken; but it changes A0 by rank one, so A0 is factored once per candidate and
frequency (LU with partial pivoting, rows swapped whole, as LAPACK's getrf), u = A0^-1 e
and v = A0^-1 (-Kb qb) per heading are substituted, and each tugger setting follows by
the Sherman-Morrison formula: z = v + i w c_t y_f u, q = z - i w c_t z_0 u / (1 + i w c_t u_0).

The 4x4 factorisation and substitutions are written out on scalar locals (entries
``a<row><col>``, pivot rows ``p<k>``, reciprocal pivots ``d<k>``) so that they stay in
registers; a loop over a 4x4 array is about twice as slow. The two kernels differ only in
what they store. Both are generated from one template by
``scripts/make_frequency_domain_kernels.py``: edit the template there and rerun it.

Imported only by :mod:`jls.response.solver`, on first use, so that jobs that never
solve do not pay numba's import. Compiled code is cached on disk (``cache=True``). The
kernels release the GIL (``nogil``): :mod:`jls.response.solver` runs slices of the
candidates on threads (a serial kernel compiles in half the time of a numba-parallel one).
Fast math assumes finite numbers (twice as fast as IEEE complex arithmetic): the caller
passes finite plants only and marks the others NaN (:mod:`jls.response.solver`).
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, fastmath=True, nogil=True)
def relative_power(M, K, C, Kb, c_t, omega, qb, yf, scale, out):
    """out[c, t, h, r, w] = |scale_r (q_r - qb_r)|^2, the squared relative-motion transfer
    function. Shapes: M, K, C, Kb (n_c, 4, 4); c_t (n_t,); omega (n_w,); qb (n_h, n_w, 4);
    yf (n_h, n_w); scale (4,); out (n_c, n_t, n_h, 4, n_w) float64."""
    n_h = qb.shape[0]
    n_t = c_t.shape[0]
    for c in range(M.shape[0]):
        load = np.empty((n_h, 4), np.complex128)
        for w in range(omega.shape[0]):
            om = omega[w]
            om2 = om * om
            for h in range(n_h):
                for i in range(4):
                    s = 0j
                    for j in range(4):
                        s -= Kb[c, i, j] * qb[h, w, j]
                    load[h, i] = s
            a00 = complex(K[c, 0, 0] - om2 * M[c, 0, 0], om * C[c, 0, 0])
            a01 = complex(K[c, 0, 1] - om2 * M[c, 0, 1], om * C[c, 0, 1])
            a02 = complex(K[c, 0, 2] - om2 * M[c, 0, 2], om * C[c, 0, 2])
            a03 = complex(K[c, 0, 3] - om2 * M[c, 0, 3], om * C[c, 0, 3])
            a10 = complex(K[c, 1, 0] - om2 * M[c, 1, 0], om * C[c, 1, 0])
            a11 = complex(K[c, 1, 1] - om2 * M[c, 1, 1], om * C[c, 1, 1])
            a12 = complex(K[c, 1, 2] - om2 * M[c, 1, 2], om * C[c, 1, 2])
            a13 = complex(K[c, 1, 3] - om2 * M[c, 1, 3], om * C[c, 1, 3])
            a20 = complex(K[c, 2, 0] - om2 * M[c, 2, 0], om * C[c, 2, 0])
            a21 = complex(K[c, 2, 1] - om2 * M[c, 2, 1], om * C[c, 2, 1])
            a22 = complex(K[c, 2, 2] - om2 * M[c, 2, 2], om * C[c, 2, 2])
            a23 = complex(K[c, 2, 3] - om2 * M[c, 2, 3], om * C[c, 2, 3])
            a30 = complex(K[c, 3, 0] - om2 * M[c, 3, 0], om * C[c, 3, 0])
            a31 = complex(K[c, 3, 1] - om2 * M[c, 3, 1], om * C[c, 3, 1])
            a32 = complex(K[c, 3, 2] - om2 * M[c, 3, 2], om * C[c, 3, 2])
            a33 = complex(K[c, 3, 3] - om2 * M[c, 3, 3], om * C[c, 3, 3])
            best = a00.real * a00.real + a00.imag * a00.imag
            p0 = 0
            v = a10.real * a10.real + a10.imag * a10.imag
            if v > best:
                best = v
                p0 = 1
            v = a20.real * a20.real + a20.imag * a20.imag
            if v > best:
                best = v
                p0 = 2
            v = a30.real * a30.real + a30.imag * a30.imag
            if v > best:
                best = v
                p0 = 3
            if p0 == 1:
                a00, a01, a02, a03, a10, a11, a12, a13 = a10, a11, a12, a13, a00, a01, a02, a03
            elif p0 == 2:
                a00, a01, a02, a03, a20, a21, a22, a23 = a20, a21, a22, a23, a00, a01, a02, a03
            elif p0 == 3:
                a00, a01, a02, a03, a30, a31, a32, a33 = a30, a31, a32, a33, a00, a01, a02, a03
            r = 1.0 / (a00.real * a00.real + a00.imag * a00.imag)
            d0 = complex(a00.real * r, -a00.imag * r)
            a10 = a10 * d0
            a11 = a11 - a10 * a01
            a12 = a12 - a10 * a02
            a13 = a13 - a10 * a03
            a20 = a20 * d0
            a21 = a21 - a20 * a01
            a22 = a22 - a20 * a02
            a23 = a23 - a20 * a03
            a30 = a30 * d0
            a31 = a31 - a30 * a01
            a32 = a32 - a30 * a02
            a33 = a33 - a30 * a03
            best = a11.real * a11.real + a11.imag * a11.imag
            p1 = 1
            v = a21.real * a21.real + a21.imag * a21.imag
            if v > best:
                best = v
                p1 = 2
            v = a31.real * a31.real + a31.imag * a31.imag
            if v > best:
                best = v
                p1 = 3
            if p1 == 2:
                a10, a11, a12, a13, a20, a21, a22, a23 = a20, a21, a22, a23, a10, a11, a12, a13
            elif p1 == 3:
                a10, a11, a12, a13, a30, a31, a32, a33 = a30, a31, a32, a33, a10, a11, a12, a13
            r = 1.0 / (a11.real * a11.real + a11.imag * a11.imag)
            d1 = complex(a11.real * r, -a11.imag * r)
            a21 = a21 * d1
            a22 = a22 - a21 * a12
            a23 = a23 - a21 * a13
            a31 = a31 * d1
            a32 = a32 - a31 * a12
            a33 = a33 - a31 * a13
            best = a22.real * a22.real + a22.imag * a22.imag
            p2 = 2
            v = a32.real * a32.real + a32.imag * a32.imag
            if v > best:
                best = v
                p2 = 3
            if p2 == 3:
                a20, a21, a22, a23, a30, a31, a32, a33 = a30, a31, a32, a33, a20, a21, a22, a23
            r = 1.0 / (a22.real * a22.real + a22.imag * a22.imag)
            d2 = complex(a22.real * r, -a22.imag * r)
            a32 = a32 * d2
            a33 = a33 - a32 * a23
            r = 1.0 / (a33.real * a33.real + a33.imag * a33.imag)
            d3 = complex(a33.real * r, -a33.imag * r)
            # u = A0^-1 e_sway: the tugger's column
            u0, u1, u2, u3 = 1.0 + 0j, 0j, 0j, 0j
            if p0 == 1:
                u0, u1 = u1, u0
            elif p0 == 2:
                u0, u2 = u2, u0
            elif p0 == 3:
                u0, u3 = u3, u0
            if p1 == 2:
                u1, u2 = u2, u1
            elif p1 == 3:
                u1, u3 = u3, u1
            if p2 == 3:
                u2, u3 = u3, u2
            u1 = u1 - a10 * u0
            u2 = u2 - a20 * u0
            u3 = u3 - a30 * u0
            u2 = u2 - a21 * u1
            u3 = u3 - a31 * u1
            u3 = u3 - a32 * u2
            u3 = (u3) * d3
            u2 = (u2 - a23 * u3) * d2
            u1 = (u1 - a12 * u2 - a13 * u3) * d1
            u0 = (u0 - a01 * u1 - a02 * u2 - a03 * u3) * d0
            for h in range(n_h):
                b0 = load[h, 0]
                b1 = load[h, 1]
                b2 = load[h, 2]
                b3 = load[h, 3]
                if p0 == 1:
                    b0, b1 = b1, b0
                elif p0 == 2:
                    b0, b2 = b2, b0
                elif p0 == 3:
                    b0, b3 = b3, b0
                if p1 == 2:
                    b1, b2 = b2, b1
                elif p1 == 3:
                    b1, b3 = b3, b1
                if p2 == 3:
                    b2, b3 = b3, b2
                b1 = b1 - a10 * b0
                b2 = b2 - a20 * b0
                b3 = b3 - a30 * b0
                b2 = b2 - a21 * b1
                b3 = b3 - a31 * b1
                b3 = b3 - a32 * b2
                b3 = (b3) * d3
                b2 = (b2 - a23 * b3) * d2
                b1 = (b1 - a12 * b2 - a13 * b3) * d1
                b0 = (b0 - a01 * b1 - a02 * b2 - a03 * b3) * d0
                for t in range(n_t):
                    s = complex(0.0, om * c_t[t])
                    sy = s * yf[h, w]
                    z0 = b0 + sy * u0
                    z1 = b1 + sy * u1
                    z2 = b2 + sy * u2
                    z3 = b3 + sy * u3
                    f = s * z0 / (1.0 + s * u0)
                    x = z0 - f * u0
                    x = (x - qb[h, w, 0]) * scale[0]
                    out[c, t, h, 0, w] = x.real * x.real + x.imag * x.imag
                    x = z1 - f * u1
                    x = (x - qb[h, w, 1]) * scale[1]
                    out[c, t, h, 1, w] = x.real * x.real + x.imag * x.imag
                    x = z2 - f * u2
                    x = (x - qb[h, w, 2]) * scale[2]
                    out[c, t, h, 2, w] = x.real * x.real + x.imag * x.imag
                    x = z3 - f * u3
                    x = (x - qb[h, w, 3]) * scale[3]
                    out[c, t, h, 3, w] = x.real * x.real + x.imag * x.imag



@njit(cache=True, fastmath=True, nogil=True)
def absolute_transfer(M, K, C, Kb, c_t, omega, qb, yf, out):
    """out[c, t, h, r, w] = q_r, the complex transfer function of the CoG motion (shapes as
    relative_power, out complex128)."""
    n_h = qb.shape[0]
    n_t = c_t.shape[0]
    for c in range(M.shape[0]):
        load = np.empty((n_h, 4), np.complex128)
        for w in range(omega.shape[0]):
            om = omega[w]
            om2 = om * om
            for h in range(n_h):
                for i in range(4):
                    s = 0j
                    for j in range(4):
                        s -= Kb[c, i, j] * qb[h, w, j]
                    load[h, i] = s
            a00 = complex(K[c, 0, 0] - om2 * M[c, 0, 0], om * C[c, 0, 0])
            a01 = complex(K[c, 0, 1] - om2 * M[c, 0, 1], om * C[c, 0, 1])
            a02 = complex(K[c, 0, 2] - om2 * M[c, 0, 2], om * C[c, 0, 2])
            a03 = complex(K[c, 0, 3] - om2 * M[c, 0, 3], om * C[c, 0, 3])
            a10 = complex(K[c, 1, 0] - om2 * M[c, 1, 0], om * C[c, 1, 0])
            a11 = complex(K[c, 1, 1] - om2 * M[c, 1, 1], om * C[c, 1, 1])
            a12 = complex(K[c, 1, 2] - om2 * M[c, 1, 2], om * C[c, 1, 2])
            a13 = complex(K[c, 1, 3] - om2 * M[c, 1, 3], om * C[c, 1, 3])
            a20 = complex(K[c, 2, 0] - om2 * M[c, 2, 0], om * C[c, 2, 0])
            a21 = complex(K[c, 2, 1] - om2 * M[c, 2, 1], om * C[c, 2, 1])
            a22 = complex(K[c, 2, 2] - om2 * M[c, 2, 2], om * C[c, 2, 2])
            a23 = complex(K[c, 2, 3] - om2 * M[c, 2, 3], om * C[c, 2, 3])
            a30 = complex(K[c, 3, 0] - om2 * M[c, 3, 0], om * C[c, 3, 0])
            a31 = complex(K[c, 3, 1] - om2 * M[c, 3, 1], om * C[c, 3, 1])
            a32 = complex(K[c, 3, 2] - om2 * M[c, 3, 2], om * C[c, 3, 2])
            a33 = complex(K[c, 3, 3] - om2 * M[c, 3, 3], om * C[c, 3, 3])
            best = a00.real * a00.real + a00.imag * a00.imag
            p0 = 0
            v = a10.real * a10.real + a10.imag * a10.imag
            if v > best:
                best = v
                p0 = 1
            v = a20.real * a20.real + a20.imag * a20.imag
            if v > best:
                best = v
                p0 = 2
            v = a30.real * a30.real + a30.imag * a30.imag
            if v > best:
                best = v
                p0 = 3
            if p0 == 1:
                a00, a01, a02, a03, a10, a11, a12, a13 = a10, a11, a12, a13, a00, a01, a02, a03
            elif p0 == 2:
                a00, a01, a02, a03, a20, a21, a22, a23 = a20, a21, a22, a23, a00, a01, a02, a03
            elif p0 == 3:
                a00, a01, a02, a03, a30, a31, a32, a33 = a30, a31, a32, a33, a00, a01, a02, a03
            r = 1.0 / (a00.real * a00.real + a00.imag * a00.imag)
            d0 = complex(a00.real * r, -a00.imag * r)
            a10 = a10 * d0
            a11 = a11 - a10 * a01
            a12 = a12 - a10 * a02
            a13 = a13 - a10 * a03
            a20 = a20 * d0
            a21 = a21 - a20 * a01
            a22 = a22 - a20 * a02
            a23 = a23 - a20 * a03
            a30 = a30 * d0
            a31 = a31 - a30 * a01
            a32 = a32 - a30 * a02
            a33 = a33 - a30 * a03
            best = a11.real * a11.real + a11.imag * a11.imag
            p1 = 1
            v = a21.real * a21.real + a21.imag * a21.imag
            if v > best:
                best = v
                p1 = 2
            v = a31.real * a31.real + a31.imag * a31.imag
            if v > best:
                best = v
                p1 = 3
            if p1 == 2:
                a10, a11, a12, a13, a20, a21, a22, a23 = a20, a21, a22, a23, a10, a11, a12, a13
            elif p1 == 3:
                a10, a11, a12, a13, a30, a31, a32, a33 = a30, a31, a32, a33, a10, a11, a12, a13
            r = 1.0 / (a11.real * a11.real + a11.imag * a11.imag)
            d1 = complex(a11.real * r, -a11.imag * r)
            a21 = a21 * d1
            a22 = a22 - a21 * a12
            a23 = a23 - a21 * a13
            a31 = a31 * d1
            a32 = a32 - a31 * a12
            a33 = a33 - a31 * a13
            best = a22.real * a22.real + a22.imag * a22.imag
            p2 = 2
            v = a32.real * a32.real + a32.imag * a32.imag
            if v > best:
                best = v
                p2 = 3
            if p2 == 3:
                a20, a21, a22, a23, a30, a31, a32, a33 = a30, a31, a32, a33, a20, a21, a22, a23
            r = 1.0 / (a22.real * a22.real + a22.imag * a22.imag)
            d2 = complex(a22.real * r, -a22.imag * r)
            a32 = a32 * d2
            a33 = a33 - a32 * a23
            r = 1.0 / (a33.real * a33.real + a33.imag * a33.imag)
            d3 = complex(a33.real * r, -a33.imag * r)
            # u = A0^-1 e_sway: the tugger's column
            u0, u1, u2, u3 = 1.0 + 0j, 0j, 0j, 0j
            if p0 == 1:
                u0, u1 = u1, u0
            elif p0 == 2:
                u0, u2 = u2, u0
            elif p0 == 3:
                u0, u3 = u3, u0
            if p1 == 2:
                u1, u2 = u2, u1
            elif p1 == 3:
                u1, u3 = u3, u1
            if p2 == 3:
                u2, u3 = u3, u2
            u1 = u1 - a10 * u0
            u2 = u2 - a20 * u0
            u3 = u3 - a30 * u0
            u2 = u2 - a21 * u1
            u3 = u3 - a31 * u1
            u3 = u3 - a32 * u2
            u3 = (u3) * d3
            u2 = (u2 - a23 * u3) * d2
            u1 = (u1 - a12 * u2 - a13 * u3) * d1
            u0 = (u0 - a01 * u1 - a02 * u2 - a03 * u3) * d0
            for h in range(n_h):
                b0 = load[h, 0]
                b1 = load[h, 1]
                b2 = load[h, 2]
                b3 = load[h, 3]
                if p0 == 1:
                    b0, b1 = b1, b0
                elif p0 == 2:
                    b0, b2 = b2, b0
                elif p0 == 3:
                    b0, b3 = b3, b0
                if p1 == 2:
                    b1, b2 = b2, b1
                elif p1 == 3:
                    b1, b3 = b3, b1
                if p2 == 3:
                    b2, b3 = b3, b2
                b1 = b1 - a10 * b0
                b2 = b2 - a20 * b0
                b3 = b3 - a30 * b0
                b2 = b2 - a21 * b1
                b3 = b3 - a31 * b1
                b3 = b3 - a32 * b2
                b3 = (b3) * d3
                b2 = (b2 - a23 * b3) * d2
                b1 = (b1 - a12 * b2 - a13 * b3) * d1
                b0 = (b0 - a01 * b1 - a02 * b2 - a03 * b3) * d0
                for t in range(n_t):
                    s = complex(0.0, om * c_t[t])
                    sy = s * yf[h, w]
                    z0 = b0 + sy * u0
                    z1 = b1 + sy * u1
                    z2 = b2 + sy * u2
                    z3 = b3 + sy * u3
                    f = s * z0 / (1.0 + s * u0)
                    x = z0 - f * u0
                    out[c, t, h, 0, w] = x
                    x = z1 - f * u1
                    out[c, t, h, 1, w] = x
                    x = z2 - f * u2
                    out[c, t, h, 2, w] = x
                    x = z3 - f * u3
                    out[c, t, h, 3, w] = x
