"""Unit-Hs spectral moments and statistics of a set of candidates on one frequency grid.

The vessel's six RAOs are interpolated per DOF (amplitude and unwrapped phase) onto one
grid refined around the lightly damped modes of every candidate and then carried to the
hinge and the fairleads (:func:`jls.vessel.transfer.motion_on_grid`, the one transfer) (:func:`jls.response.solver.frequency_grid`, bounded in size
whatever the number of candidates) and driven through the plant of every candidate,
in blocks of ``BLOCK`` candidates (bounded memory); spectral moments of each sea state
can be kept in a :class:`jls.io.sea_state_cache.SeaStateCache` so that only sea states
not seen before are evaluated.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.io import registry
from jls.names import RESPONSES
from jls.response.coverage import describe
from jls.response.solver import (
    frequency_grid,
    moment_weights,
    relative_power,
    spectral_moments,
    transfer_functions,
)
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, unit_spectra
from jls.vessel.transfer import motion_on_grid

#: UDUNITS of each relative motion per m of Hs (statistics) or of wave amplitude (transfer)
RESPONSE_UNITS = ("m m-1", "m m-1", "degree m-1", "degree m-1")


#: Candidates per solver block. Blocks are aligned to multiples of BLOCK in the global
#: candidate index and always BLOCK rows deep (padded), so every candidate's numbers are
#: computed by identical operations whatever the chunk it belongs to.
BLOCK = 64


@dataclass(frozen=True)
class Excitation:
    """The solver's inputs that do not depend on the candidate: frequency grid, hinge
    RAO qb (n_h, n_w, 4) and fairlead sway (n_h, n_w) per heading [deg]."""

    omega: np.ndarray
    headings: np.ndarray
    qb: np.ndarray
    fairlead_sway: np.ndarray


def excitation(plant: xr.Dataset, motion: xr.Dataset, headings_deg, omega_step=0.002) -> Excitation:
    """The grid refined around every candidate's modes, and the hinge and fairlead RAOs on
    it: the vessel's RAOs interpolated per DOF onto the grid, then transferred
    (:func:`jls.vessel.transfer.motion_on_grid`)."""
    omega_rao = motion["omega"].values
    lo, hi = float(omega_rao.min()), float(omega_rao.max())
    wn = 2 * np.pi / plant["natural_period"].values
    omega = frequency_grid(lo, hi, omega_step, wn, plant["damping_ratio"].values)
    gm = motion_on_grid(motion, headings_deg, omega)
    return Excitation(omega, gm.headings, gm.hinge, gm.fairlead_sway)


def _matrices(plant: xr.Dataset, index: slice):
    return tuple(plant[k].values[index] for k in ("M", "K", "Kb", "C"))


def unit_moments(plant: xr.Dataset, exc: Excitation, tz, c_tugger, gamma=3.3, *,
                 candidates=slice(None), cache=None, threads=None):
    """Spectral moments m0, m2 at Hs = 1 m, (n_c, n_t, n_h, 4, n_tz) each, of the
    candidates ``candidates`` (a slice of the plant's candidate axis).

    ``cache``: a directory; sea states (Tz, heading, gamma) already there are read, the
    others evaluated and stored. Returns (m0, m2, evaluated) with ``evaluated`` the
    number of (Tz, heading) sea states computed here.
    """
    from jls.io.sea_state_cache import SeaStateCache

    tz = np.atleast_1d(np.asarray(tz, float))
    c_t = np.atleast_1d(np.asarray(c_tugger, float))
    n_all = plant.sizes["candidate"]
    start, stop, _ = candidates.indices(n_all)
    n_c, n_t, n_h = stop - start, c_t.size, exc.headings.size
    m0 = np.full((n_c, n_t, n_h, 4, tz.size), np.nan)
    m2 = np.full_like(m0, np.nan)
    missing = np.ones((n_h, tz.size), bool)
    store = keys = None
    if cache is not None:
        store = SeaStateCache(cache, _matrices(plant, slice(start, stop)), exc.omega, c_t)
        keys = [store.heading_key(h, exc.qb[i], exc.fairlead_sway[i])
                for i, h in enumerate(exc.headings)]
        for i in range(n_h):
            for j, t in enumerate(tz):
                hit = store.load(keys[i], t, gamma)
                if hit is not None and hit[0].shape == (n_c, n_t, 4):
                    m0[:, :, i, :, j], m2[:, :, i, :, j] = hit
                    missing[i, j] = False
    heads = np.flatnonzero(missing.any(axis=1))
    cols = np.flatnonzero(missing.any(axis=0))
    if heads.size:
        W = moment_weights(exc.omega, unit_spectra(exc.omega, tz[cols], gamma))
        M, K, Kb, C = _matrices(plant, slice(None))
        qb, yf = exc.qb[heads], exc.fairlead_sway[heads]
        # Blocks aligned to multiples of BLOCK, always BLOCK deep: the zero rows of a
        # padded block do not touch the other rows' results.
        for b0 in range(start - start % BLOCK, stop, BLOCK):
            lo, hi = max(b0, start), min(b0 + BLOCK, stop)
            P = np.zeros((BLOCK, n_t, heads.size, 4, exc.omega.size))
            P[lo - b0:hi - b0] = relative_power(M[lo:hi], K[lo:hi], Kb[lo:hi], C[lo:hi], exc.omega,
                                                qb, yf, c_t, threads=threads)
            a0, a2 = spectral_moments(P, W)
            sel = np.ix_(np.arange(lo - start, hi - start), np.arange(n_t), heads, np.arange(4), cols)
            m0[sel], m2[sel] = a0[lo - b0:hi - b0], a2[lo - b0:hi - b0]
    evaluated = int(missing.sum())
    if store is not None:
        for i in heads:
            for j in np.flatnonzero(missing[i]):
                store.save(keys[i], tz[j], gamma, m0[:, :, i, :, j], m2[:, :, i, :, j])
    return m0, m2, evaluated


def moments_dataset(m0, m2, *, candidates, tuggers, headings, tz) -> xr.Dataset:
    """Unit-Hs spectral moments of a chunk of candidates as its chunk file holds them
    (response and screening chunk jobs): m0, m2 over candidate, tugger, heading,
    response, tz."""
    dims = ("candidate", "tugger", "heading", "response", "tz")
    ds = xr.Dataset({"m0": (dims, m0), "m2": (dims, m2)},
                    coords={"candidate": list(candidates), "tugger": list(tuggers),
                            "heading": np.asarray(headings, float), "tz": np.asarray(tz, float)})
    ds["m0"].attrs.update(long_name="zeroth spectral moment at Hs = 1 m", units="m^2 or degree^2")
    ds["m2"].attrs.update(long_name="second spectral moment at Hs = 1 m", units="m^2/s^2 or degree^2/s^2")
    return ds


def statistics_dataset(m0, m2, *, candidates, tuggers: dict, headings, tz, gamma=3.3,
                       exposure_h=3.0, cycles="response", energy_outside_fraction=None,
                       outside_policy="error") -> xr.Dataset:
    """sigma, tz_response, n_cycles, mpm (candidate, tugger, heading, tz, response) from
    the moments of :func:`unit_moments`, with the attributes of docs/reference/outputs.md."""
    n_cycles = "response" if cycles == "response" else FIXED_CYCLES_STUDY
    stats = from_moments(m0, m2, exposure_h * 3600.0, n_cycles)
    names = list(tuggers)
    dims = ("candidate", "tugger", "heading", "response", "tz")
    ds = xr.Dataset({k: (dims, v) for k, v in stats.items()},
                    coords={"candidate": list(candidates), "tugger": names,
                            "c_tugger": ("tugger", [float(tuggers[n]) for n in names]),
                            "heading": np.asarray(headings, float), "response": list(RESPONSES),
                            "tz": np.asarray(tz, float)})
    ds = ds.assign_coords(response_units=("response", list(RESPONSE_UNITS)),
                          transfer_units=("response", list(RESPONSE_UNITS)))
    if energy_outside_fraction is not None:
        ds["energy_outside"] = ("tz", np.asarray(energy_outside_fraction, float))
    registry.annotate(ds, "response")
    ds.attrs.update(
        exposure_h=float(exposure_h),
        mpm_cycles=("response: N = exposure / Tz_response" if cycles == "response"
                    else f"fixed: N = {FIXED_CYCLES_STUDY}"),
        gamma=float(gamma), spectrum="JONSWAP, sigma_a 0.07, sigma_b 0.09, Tp from Tz (DNV-RP-C205)",
        outside_rao_range=describe(outside_policy))
    return ds


def shown_transfer(plant: xr.Dataset, exc: Excitation, shown, tuggers: dict, threads=None) -> xr.DataArray:
    """Relative-motion transfer functions (shown_candidate, tugger, heading, response,
    omega) of the candidates named in ``shown`` (those the report draws), rotations in
    degrees."""
    shown = [c for c in plant["candidate"].values.tolist() if c in set(shown)]
    sub = plant.sel(candidate=shown)
    c_t = [float(tuggers[n]) for n in tuggers]
    _, Hrel = transfer_functions(sub["M"].values, sub["K"].values, sub["Kb"].values,
                                 sub["C"].values, exc.omega, exc.qb, exc.fairlead_sway, c_t,
                                 threads=threads)
    H = np.moveaxis(Hrel, -1, -2) * np.where([False, False, True, True], 180.0 / np.pi, 1.0)[:, None]
    da = xr.DataArray(H, dims=("shown_candidate", "tugger", "heading", "response", "omega"),
                      coords={"shown_candidate": shown, "tugger": list(tuggers),
                              "heading": exc.headings, "response": list(RESPONSES),
                              "omega": exc.omega})
    return da


