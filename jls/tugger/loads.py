"""Tugger loads in the fast frequency-domain path: per candidate, tugger setting, heading
and Tz, the pay-out velocity and net force of the pair at Hs = 1 m (section 6.4).

Each line pays out at u = i w (y - y_f), the jacket's CoG sway against the fairlead sway
(eq. 6.3; the port line's is -u), and the pair pushes with F = -c u while no line is at a
limit. Their spectral moments come from the same machinery as the relative motions
(:func:`jls.response.solver.moment_weights`, :func:`jls.response.solver.spectral_moments`):
one BLAS product per block of candidates, so the cost is linear in the candidates. The
solve is the response solver's own (:func:`jls.response.solver.transfer_functions`: one
4x4 factorisation per candidate and frequency, every tugger by Sherman-Morrison).

Since F = c u exactly, sigma_F = c sigma_u and MPM_F = c MPM_u (same zero-crossing period);
the mean power absorbed by the pair is c sigma_u^2 and the power at the MPM pay-out velocity
c MPM_u^2. The model is linear: sigma and MPM scale with Hs, power with Hs^2, which is what
the per-m and per-m2 units of the dataset state.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.response.solver import moment_weights, spectral_moments, transfer_functions
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, unit_spectra

#: Candidates per solve block (complex transfer functions are kept for a block only).
LOAD_BLOCK = 16
#: Variables added to the response dataset, name -> (statistic, kind)
LOAD_VARIABLES = ("tugger_sigma_force", "tugger_mpm_force", "tugger_sigma_payout_velocity",
                  "tugger_mpm_payout_velocity", "tugger_power_mean", "tugger_power_peak")


def payout_moments(M, K, Kb, C, omega, qb, fairlead_sway, c_tugger, tz, gamma=3.3, threads=None):
    """m0, m2 of the pay-out velocity at Hs = 1 m, (n_c, n_t, n_h, n_tz) each.

    Shapes as :func:`jls.response.solver.transfer_functions` (M, K, Kb, C: (n_c, 4, 4);
    qb (n_h, n_w, 4); fairlead_sway (n_h, n_w); c_tugger (n_t,)).
    """
    M, K, Kb, C = (np.asarray(a, float).reshape(-1, 4, 4) for a in (M, K, Kb, C))
    omega = np.asarray(omega, float)
    c_t = np.atleast_1d(np.asarray(c_tugger, float))
    tz = np.atleast_1d(np.asarray(tz, float))
    W = moment_weights(omega, unit_spectra(omega, tz, gamma))
    yf = np.asarray(fairlead_sway, complex)
    n_c, n_h = M.shape[0], qb.shape[0]
    m0 = np.empty((n_c, c_t.size, n_h, tz.size))
    m2 = np.empty_like(m0)
    for lo in range(0, n_c, LOAD_BLOCK):
        hi = min(lo + LOAD_BLOCK, n_c)
        Hq, _ = transfer_functions(M[lo:hi], K[lo:hi], Kb[lo:hi], C[lo:hi], omega, qb, yf, c_t,
                                   threads=threads)
        rel = Hq[..., 0] - yf                                     # (b, n_t, n_h, n_w)
        P = (omega**2) * (rel.real**2 + rel.imag**2)              # |i w (y - y_f)|^2
        m0[lo:hi], m2[lo:hi] = spectral_moments(np.ascontiguousarray(P), W)
    return m0, m2


def load_statistics(m0, m2, c_tugger, exposure_s=3 * 3600.0, cycles="response") -> dict:
    """Unit-Hs statistics of the pair from the pay-out moments (n_c, n_t, n_h, n_tz):
    sigma and MPM of force [kN per m of Hs] and pay-out velocity [m/s per m], mean and peak
    power [kW per m^2 of Hs]."""
    n = "response" if cycles == "response" else FIXED_CYCLES_STUDY
    st = from_moments(m0, m2, exposure_s, n)
    c = np.asarray(c_tugger, float)[None, :, None, None]
    return {"tugger_sigma_force": c * st["sigma"], "tugger_mpm_force": c * st["mpm"],
            "tugger_sigma_payout_velocity": st["sigma"], "tugger_mpm_payout_velocity": st["mpm"],
            "tugger_power_mean": c * st["sigma"] ** 2, "tugger_power_peak": c * st["mpm"] ** 2}


def add_tugger_loads(ds: xr.Dataset, plant: xr.Dataset, exc, tuggers: dict, *, gamma=3.3,
                     exposure_h=3.0, cycles="response", threads=None) -> xr.Dataset:
    """The response dataset ``ds`` with the tugger loads of :func:`load_statistics` on its
    (candidate, tugger, heading, tz), from the plant and the solver's excitation
    (:func:`jls.response.moments.excitation`)."""
    from jls.io import registry
    sub = plant.sel(candidate=ds["candidate"].values)
    c_t = np.array([float(tuggers[n]) for n in ds["tugger"].values])
    heads = [int(np.flatnonzero(np.isclose(exc.headings, h))[0]) for h in ds["heading"].values]
    m0, m2 = payout_moments(sub["M"].values, sub["K"].values, sub["Kb"].values, sub["C"].values,
                            exc.omega, exc.qb[heads], exc.fairlead_sway[heads], c_t,
                            ds["tz"].values, gamma, threads)
    stats = load_statistics(m0, m2, c_t, exposure_h * 3600.0, cycles)
    dims = ("candidate", "tugger", "heading", "tz")
    for k, v in stats.items():
        ds[k] = (dims, v)
    registry.annotate(ds, "response")
    return ds


__all__ = ["payout_moments", "load_statistics", "add_tugger_loads", "LOAD_VARIABLES"]
