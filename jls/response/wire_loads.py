"""Wire-tension statistics of every candidate for the response dataset.

The dynamic wire tension is a linear output of the plant (:mod:`jls.response.tension`): its
transfer function follows from the complex response of q and of the hinge on the same
frequency grid the motion statistics use (:func:`jls.response.moments.excitation`).
Candidates are solved in blocks of :data:`jls.response.moments.BLOCK`, so the memory is
bounded and the cost linear in candidates; the spectral moments of the tension power are
one matrix product per block (:func:`jls.response.solver.spectral_moments`, as for the
motions); the statistics are kept, the complex transfer functions are not. The result is merged into ``response.nc`` and
``operability.nc`` (variables ``tension_*`` over candidate, tugger, heading, tz, wire).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.response.solver import moment_weights, spectral_moments, transfer_functions
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, unit_spectra
from jls.response.tension import plant_gradients, tension_transfer

TENSION_STATS = ("tension_sigma", "tension_tz_response", "tension_n_cycles", "tension_mpm")
#: UDUNITS of the tension variables (per m of Hs for the statistics linear in Hs)
TENSION_UNITS = {"tension_static": "kN", "tension_sigma": "kN m-1", "tension_tz_response": "s",
                 "tension_n_cycles": "1", "tension_mpm": "kN m-1"}


def has_geometry(plant: xr.Dataset) -> bool:
    """True when the plant carries the wire geometry the tensions need."""
    return all(v in plant for v in ("anchor", "padeye", "cog_depth", "wire_stiffness", "tension"))


def tension_response(plant: xr.Dataset, exc, tz, tuggers: dict, *, gamma=3.3, exposure_h=3.0,
                     cycles="response", block=None, threads=None, candidates=None) -> xr.Dataset:
    """Unit-Hs wire-tension statistics (candidate, tugger, heading, tz, wire) and the static
    tension (candidate, wire) of every candidate; with ``candidates`` (names), the
    statistics of those only (NaN for the others: no tension criterion needs them).

    plant: the plant dataset (geometric); exc: :class:`jls.response.moments.Excitation`;
    tz: Tz values [s]; tuggers: name -> damping slope [kN s/m]; cycles: "response" or
    "fixed" (N = 1000).
    """
    from jls.response.moments import BLOCK, _matrices

    block = int(block or BLOCK)
    tz = np.atleast_1d(np.asarray(tz, float))
    c_t = [float(tuggers[n]) for n in tuggers]
    grad_q, grad_qb, k = plant_gradients(plant)
    M, K, Kb, C = _matrices(plant, slice(None))
    n_c = M.shape[0]
    names = plant["candidate"].values
    index = (np.arange(n_c) if candidates is None
             else np.flatnonzero(np.isin(names.astype(str), [str(c) for c in candidates])))
    shape = (n_c, len(c_t), exc.headings.size, tz.size, k.shape[-1])
    out = {name: np.full(shape, np.nan) for name in TENSION_STATS}
    n_cycles = FIXED_CYCLES_STUDY if cycles == "fixed" else "response"
    W = moment_weights(exc.omega, unit_spectra(exc.omega, tz, gamma))     # one matrix product per block
    for lo in range(0, index.size, block):
        sel = index[lo:lo + block]
        Hq, _ = transfer_functions(M[sel], K[sel], Kb[sel], C[sel], exc.omega, exc.qb,
                                   exc.fairlead_sway, c_t, threads=threads)
        HT = tension_transfer(Hq, exc.qb, grad_q[sel], grad_qb[sel], k[sel])  # (c, t, h, w, wire)
        P = np.ascontiguousarray(np.moveaxis(HT.real**2 + HT.imag**2, -1, -2))   # (c, t, h, wire, w)
        m0, m2 = spectral_moments(P, W)
        stats = from_moments(m0, m2, exposure_h * 3600.0, n_cycles)             # (..., wire, tz)
        for name in TENSION_STATS:
            out[name][sel] = np.moveaxis(stats[name.removeprefix("tension_")], -1, -2)
    dims = ("candidate", "tugger", "heading", "tz", "wire")
    ds = xr.Dataset({name: (dims, v) for name, v in out.items()},
                    coords={"candidate": plant["candidate"].values, "tugger": list(tuggers),
                            "heading": np.asarray(exc.headings, float), "tz": tz,
                            "wire": plant["wire"].values})
    ds["tension_static"] = plant["tension"].transpose("candidate", "wire").drop_vars(
        [c for c in plant["tension"].coords if c not in ("candidate", "wire")])
    return ds


__all__ = ["TENSION_STATS", "TENSION_UNITS", "has_geometry", "tension_response"]
