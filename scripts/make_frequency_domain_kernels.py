"""Write the compiled kernels of jls/frequency_domain_kernels.py from one template.

The 4x4 LU with partial pivoting and the substitutions are written out on scalar
locals (a<row><col>, pivot rows p<k>, reciprocal pivots d<k>) so that numba keeps them in
registers. The tugger adds i w c to A[0, 0], a rank-one change: A0 = K - w^2 M + i w C is
factored once per candidate and frequency and every tugger setting follows exactly by
the Sherman-Morrison formula with u = A0^-1 e_sway. This script expands that template into the two kernels (relative |H|^2 and
complex transfer) and replaces everything below the module's imports.

Run: python scripts/make_frequency_domain_kernels.py
"""

from pathlib import Path

MODULE = Path(__file__).resolve().parents[1] / "jls" / "frequency_domain_kernels.py"

N = 4


def A(i, j):
    return f"a{i}{j}"


def emit_solve(e, v, J):
    """Substitutions with the factors for the vector v0..v3 (in place)."""
    for k in range(N - 1):       # P v: every row swap first (L holds the swapped rows)
        for i in range(k + 1, N):
            e(f"{'if' if i == k + 1 else 'elif'} p{k} == {i}:", J)
            e(f"{v}{k}, {v}{i} = {v}{i}, {v}{k}", J + 4)
    for k in range(N - 1):
        for i in range(k + 1, N):
            e(f"{v}{i} = {v}{i} - {A(i, k)} * {v}{k}", J)
    for k in range(N - 1, -1, -1):
        terms = "".join(f" - {A(k, j)} * {v}{j}" for j in range(k + 1, N))
        e(f"{v}{k} = ({v}{k}{terms}) * d{k}", J)


def body(indent, mode):
    I = " " * indent
    L = []

    def e(s, d=0):
        L.append(I + " " * d + s)

    for i in range(N):
        for j in range(N):
            e(f"{A(i, j)} = complex(K[c, {i}, {j}] - om2 * M[c, {i}, {j}], om * C[c, {i}, {j}])")
    for k in range(N - 1):
        e(f"best = {A(k, k)}.real * {A(k, k)}.real + {A(k, k)}.imag * {A(k, k)}.imag")
        e(f"p{k} = {k}")
        for i in range(k + 1, N):
            e(f"v = {A(i, k)}.real * {A(i, k)}.real + {A(i, k)}.imag * {A(i, k)}.imag")
            e("if v > best:")
            e("best = v", 4)
            e(f"p{k} = {i}", 4)
        for i in range(k + 1, N):
            e(f"{'if' if i == k + 1 else 'elif'} p{k} == {i}:")
            lhs = ", ".join([A(k, j) for j in range(N)] + [A(i, j) for j in range(N)])
            rhs = ", ".join([A(i, j) for j in range(N)] + [A(k, j) for j in range(N)])
            e(f"{lhs} = {rhs}", 4)
        e(f"r = 1.0 / ({A(k, k)}.real * {A(k, k)}.real + {A(k, k)}.imag * {A(k, k)}.imag)")
        e(f"d{k} = complex({A(k, k)}.real * r, -{A(k, k)}.imag * r)")
        for i in range(k + 1, N):
            e(f"{A(i, k)} = {A(i, k)} * d{k}")
            for j in range(k + 1, N):
                e(f"{A(i, j)} = {A(i, j)} - {A(i, k)} * {A(k, j)}")
    k = N - 1
    e(f"r = 1.0 / ({A(k, k)}.real * {A(k, k)}.real + {A(k, k)}.imag * {A(k, k)}.imag)")
    e(f"d{k} = complex({A(k, k)}.real * r, -{A(k, k)}.imag * r)")
    e("# u = A0^-1 e_sway: the tugger's column")
    e("u0, u1, u2, u3 = 1.0 + 0j, 0j, 0j, 0j")
    emit_solve(e, "u", 0)
    e("for h in range(n_h):")
    J = 4
    for i in range(N):
        e(f"b{i} = load[h, {i}]", J)
    emit_solve(e, "b", J)
    e("for t in range(n_t):", J)
    T = J + 4
    e("s = complex(0.0, om * c_t[t])", T)
    e("sy = s * yf[h, w]", T)
    for i in range(N):
        e(f"z{i} = b{i} + sy * u{i}", T)
    e("f = s * z0 / (1.0 + s * u0)", T)
    for i in range(N):
        e(f"x = z{i} - f * u{i}", T)
        if mode == "power":
            e(f"x = (x - qb[h, w, {i}]) * scale[{i}]", T)
            e(f"out[c, t, h, {i}, w] = x.real * x.real + x.imag * x.imag", T)
        else:
            e(f"out[c, t, h, {i}, w] = x", T)
    return "\n".join(L)


def kernel(name, mode, doc, sig):
    head = f'''

@njit(cache=True, fastmath=True, nogil=True)
def {name}({sig}):
    """{doc}"""
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
'''
    return head + body(12, mode) + "\n"


def main():
    text = MODULE.read_text()
    head = text[:text.index("\n\n\n@njit(")] + "\n"
    body = kernel("relative_power", "power",
                  "out[c, t, h, r, w] = |scale_r (q_r - qb_r)|^2, the squared relative-motion "
                  "transfer\n    function. Shapes: M, K, C, Kb (n_c, 4, 4); c_t (n_t,); omega (n_w,); "
                  "qb (n_h, n_w, 4);\n    yf (n_h, n_w); scale (4,); out (n_c, n_t, n_h, 4, n_w) float64.",
                  "M, K, C, Kb, c_t, omega, qb, yf, scale, out")
    body += "\n" + kernel("absolute_transfer", "complex",
                          "out[c, t, h, r, w] = q_r, the complex transfer function of the CoG "
                          "motion (shapes as\n    relative_power, out complex128).",
                          "M, K, C, Kb, c_t, omega, qb, yf, out")
    MODULE.write_text(head + body)


if __name__ == "__main__":
    main()
