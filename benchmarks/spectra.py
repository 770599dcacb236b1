"""Benchmark: response moments over ten years of hourly directional spectra of one leg.

Target: 87 600 spectra x 40 frequencies x 24 directions against 100 candidates x 4
tugger settings (x 4 relative motions) in under 60 s on 2 cores and under 4 GB: the
transfer functions are per candidate, the spectra per hour, and the moments one matrix
product (jls.response.directional). Synthetic inputs: JONSWAP wind seas and swells with
cos-2s spreading and random directions per hour; |H|^2 of a base-excited oscillator per
candidate (sway period 14-17 s, damping raised by each tugger setting) with a heading
factor per relative motion, on a solver-like grid refined around every candidate's mode.

Run: python benchmarks/spectra.py [--float64] [--responses 1]
"""

from __future__ import annotations

import argparse
import resource
import time

import numpy as np
from rows import within

from jls.response.directional import response_matrix, response_moments
from jls.response.solver import frequency_grid
from jls.sea.directional import DEFAULT_DIRS
from jls.sea.spectra import jonswap

HOURS = 87_600
FREQ = np.linspace(0.03, 0.40, 40)          # Hz, 40 bands
CHUNK = 8_760                               # hours per matrix product (one year)


def synthetic_spectra(rng, n, dtype):
    """(n, 40, 24) [m2 Hz-1 degree-1]: a wind sea and a swell per hour, each spread cos-2s."""
    out = np.empty((n, FREQ.size, DEFAULT_DIRS.size), dtype)
    th = np.radians(DEFAULT_DIRS)
    for a in range(0, n, CHUNK):
        b = min(a + CHUNK, n)
        k = b - a
        e = np.zeros((k, FREQ.size, DEFAULT_DIRS.size))
        for hs, tp, s in ((rng.uniform(0.3, 4.0, k), rng.uniform(4.0, 10.0, k), 4.0),
                          (rng.uniform(0.1, 2.0, k), rng.uniform(10.0, 18.0, k), 12.0)):
            S = jonswap(2 * np.pi * FREQ[None, :], hs[:, None], tp[:, None]) * 2 * np.pi   # (k, 40)
            d0 = np.radians(rng.uniform(0.0, 360.0, k))[:, None]
            D = np.abs(np.cos(0.5 * (th[None, :] - d0))) ** (2 * s)
            D /= D.sum(axis=1, keepdims=True) * 15.0
            e += S[:, :, None] * D[:, None, :]
        out[a:b] = e
    return out


def synthetic_power(n_cand, n_tug, n_resp, dtype):
    """|H|^2 (n_cand * n_tug * n_resp, 24 headings, n_w) and the grid omega [rad/s]."""
    rng = np.random.default_rng(1)
    t_n = rng.uniform(14.0, 17.0, n_cand)
    zeta = np.array([0.0098, 0.03, 0.06, 0.12])[:n_tug]
    omega = frequency_grid(0.15, 2.6, 0.002, 2 * np.pi / t_n, np.full(n_cand, zeta[0]))
    heads = np.radians(DEFAULT_DIRS)
    factors = [np.sin(heads) ** 2 + 0.05, np.cos(heads) ** 2 + 0.1, np.abs(np.sin(heads)) + 0.02,
               np.abs(np.sin(2 * heads)) + 0.02][:n_resp]
    P = np.empty((n_cand, n_tug, n_resp, heads.size, omega.size), dtype)
    for c in range(n_cand):
        r = omega * t_n[c] / (2 * np.pi)
        for t, z in enumerate(zeta):
            h2 = (r**4 / ((1 - r**2) ** 2 + (2 * z * r) ** 2)).astype(dtype)
            for q, f in enumerate(factors):
                P[c, t, q] = f[:, None].astype(dtype) * h2[None, :]
    return P.reshape(-1, heads.size, omega.size), omega


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--float64", action="store_true", help="double precision (default float32)")
    ap.add_argument("--responses", type=int, default=4, choices=(1, 2, 3, 4),
                    help="relative motions per candidate and tugger (default 4)")
    ap.add_argument("--candidates", type=int, default=100)
    ap.add_argument("--tuggers", type=int, default=4, choices=(1, 2, 3, 4))
    args = ap.parse_args()
    dtype = np.float64 if args.float64 else np.float32
    rng = np.random.default_rng(0)

    t0 = time.perf_counter()
    E = synthetic_spectra(rng, HOURS, dtype)
    P, omega = synthetic_power(args.candidates, args.tuggers, args.responses, dtype)
    t_inputs = time.perf_counter() - t0

    t1 = time.perf_counter()
    G = response_matrix(P, omega, DEFAULT_DIRS, FREQ, DEFAULT_DIRS, course_deg=35.0, dtype=dtype)
    t_matrix = time.perf_counter() - t1
    del P
    t2 = time.perf_counter()
    m0, m2, outside = response_moments(E, G, chunk=CHUNK)
    t_product = time.perf_counter() - t2
    sigma = np.sqrt(m0)
    peak_gb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
    n_opt = G.n_options
    flops = 2.0 * HOURS * FREQ.size * DEFAULT_DIRS.size * 2 * n_opt
    print(f"spectra: {HOURS} hours x {FREQ.size} frequencies x {DEFAULT_DIRS.size} directions, "
          f"{np.dtype(dtype).name}; options: {args.candidates} candidates x {args.tuggers} tuggers x "
          f"{args.responses} responses = {n_opt}; transfer grid {omega.size} frequencies")
    print(f"  synthetic inputs          {t_inputs:7.2f} s (not part of the figure)")
    print(f"  response matrix G         {t_matrix:7.2f} s  ({G.G.shape[0]} x {G.G.shape[1]})")
    print(f"  moments, one product/year {t_product:7.2f} s  ({flops / t_product / 1e9:.0f} GFLOP/s)")
    print(f"  total (matrix + moments)  {t_matrix + t_product:7.2f} s   target < 60 s")
    print(f"  peak memory               {peak_gb:7.2f} GB  target < 4 GB")
    print(f"  sigma range {float(sigma.min()):.3g}-{float(sigma.max()):.3g}, energy outside the "
          f"transfer range <= {float(outside.max()):.2g}")
    for row in (within("directional spectra: matrix + moments, 10 years x 1600 options", 60.0,
                       t_matrix + t_product),
                within("directional spectra: peak memory", 4.0, peak_gb, "GB")):
        print("  " + " | ".join(map(str, row)))


if __name__ == "__main__":
    main()
