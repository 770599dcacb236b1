"""Central finite differences for the tests that check a stiffness against its potential."""

import numpy as np


def hessian(V, n: int, eps: float = 1e-4) -> np.ndarray:
    """The n x n Hessian of V at the origin by central differences of step ``eps``."""
    H = np.zeros((n, n))
    for i in range(n):
        for j in range(n):
            def f(a, b):
                x = np.zeros(n)
                x[i] += a
                x[j] += b
                return V(x)
            H[i, j] = (f(eps, eps) - f(eps, -eps) - f(-eps, eps) + f(-eps, -eps)) / (4 * eps**2)
    return H
