"""Response moments integrated directly over directional wave spectra, record by record.

The pipeline's transfer functions give |H(omega, beta)|^2 of every response option (rigging
candidate x tugger setting x relative motion) at relative headings beta; measured or
hindcast spectra give E(t, f, dir) per record (an hour), with dir the direction the waves
come FROM. A wave component from dir meets a vessel on course c at the relative heading
``beta = (c - dir + 180) mod 360`` (:func:`jls.sea.headings.relative_heading`, the WAMIT
convention of the RAOs), so the spreading of the sea is integrated as it is, with no
parametric fit. The response moments of all records and options are ONE matrix product::

    m_n(t, o) = sum_(f, dir) E(t, f, dir) G_n[(f, dir), o]            (n_t x n_f n_d) @ (n_f n_d x n_o)
    G_n[(i, j), o] = width_j int phi_i(f) (2 pi f)^n |H_o(2 pi f, beta_j)|^2 df

phi_i is the interpolation function of band i: the spectrum is taken as linear between
the band centres and constant over the outer halves of the end bands
(:mod:`jls.sea.measured`), so G_0 with |H| = 1 returns the spectrum's m0 exactly.
|H|^2 is linear between its frequencies (the trapezoid rule of the solver's grid), and
the product of the two is integrated on the union of both grids, so a resonance narrower
than a spectral band (the sway mode: 1 % damping at 15.5 s, a half-power width of
0.0013 Hz against NDBC's 0.005 Hz bands) is integrated on the solver's refined grid.
Outside the transfer functions' frequency range the response is taken as zero and the
share of each record's energy there is returned (``energy_outside``) for the caller's
coverage policy. Between the given headings |H|^2 is interpolated linearly (circularly);
``symmetric=True`` mirrors headings above 180 deg (a port/starboard-symmetric hull).

Memory is bounded: records are processed in chunks (``chunk`` rows at a time, float32
or float64), and G has (n_f n_d) x 2 n_o entries whatever the number of records.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.sea.directional import direction_widths
from jls.sea.headings import relative_heading

__all__ = ["ResponseMatrix", "band_interpolation", "heading_weights", "response_matrix",
           "response_moments", "directional_moments"]


def _nodes(freq):
    """Band centres f_i and the outer ends of the end bands [Hz]."""
    f = np.asarray(freq, float)
    w = np.gradient(f) if f.size > 1 else np.array([1.0])
    return f, f[0] - 0.5 * w[0], f[-1] + 0.5 * w[-1]


def band_interpolation(freq, f):
    """phi_i(f) (n_f, len(f)): the interpolation functions of the bands ``freq`` [Hz]
    evaluated at ``f`` [Hz] (hat functions; flat over the outer half of each end band;
    zero beyond)."""
    centres, lo, hi = _nodes(freq)
    f = np.asarray(f, float)
    phi = np.zeros((centres.size, f.size))
    tol = 1e-13 * (hi - lo)
    inside = (f >= lo - tol) & (f <= hi + tol)
    idx = np.clip(np.searchsorted(centres, f, side="right") - 1, 0, centres.size - 1)
    below, above = f < centres[0], f >= centres[-1]
    mid = inside & ~below & ~above
    i = idx[mid]
    t = (f[mid] - centres[i]) / (centres[i + 1] - centres[i])
    cols = np.flatnonzero(mid)
    phi[i, cols] = 1.0 - t
    phi[i + 1, cols] = t
    phi[0, np.flatnonzero(inside & below)] = 1.0
    phi[-1, np.flatnonzero(inside & above)] = 1.0
    return phi


def _trapezoid_weights(x):
    d = np.diff(x)
    w = np.zeros_like(x)
    w[:-1] += d / 2
    w[1:] += d / 2
    return w


def _frequency_weights(freq, omega, orders=(0, 2)):
    """A_n (n_f, n_w) with int phi_i(f) omega^n g(omega) df = A_n @ g for g linear between
    the samples on ``omega`` [rad/s] (zero outside), and each band's share inside the
    range of omega."""
    omega = np.asarray(omega, float)
    if omega.ndim != 1 or omega.size < 2 or np.any(np.diff(omega) <= 0) or omega[0] < 0:
        raise InputError("omega must be >= 0 and strictly increasing", field="omega",
                         value=np.asarray(omega).tolist()[:5])
    centres, lo, hi = _nodes(freq)
    eps = 1e-11 * (hi - lo)         # the band functions drop to zero just outside lo and hi
    knots = 2 * np.pi * np.concatenate([[lo - eps, lo], centres, [hi, hi + eps]])
    knots = knots[(knots > omega[0]) & (knots < omega[-1])]
    grid = np.union1d(omega, knots)
    # linear interpolation matrix from omega to grid: two entries per row
    k = np.clip(np.searchsorted(omega, grid, side="right") - 1, 0, omega.size - 2)
    t = (grid - omega[k]) / (omega[k + 1] - omega[k])
    phi = band_interpolation(freq, grid / (2 * np.pi))              # (n_f, n_g)
    tw = _trapezoid_weights(grid) / (2 * np.pi)                     # d omega -> d f
    out = []
    for n in orders:
        a = phi * (tw * grid**n)                                    # (n_f, n_g)
        A = np.zeros((phi.shape[0], omega.size))
        np.add.at(A.T, k, (a * (1 - t)).T)
        np.add.at(A.T, k + 1, (a * t).T)
        out.append(A)
    # each band's area is its width (np.gradient); the part within omega's range is A_0 @ 1
    share = out[0].sum(axis=1) / (np.gradient(centres) if centres.size > 1 else np.ones(1))
    return out, np.clip(share, 0.0, 1.0)


def _heading_weights(headings, wanted, symmetric):
    """For each wanted relative heading [deg], the two given headings around it and their
    weights (|H|^2 linear in heading, circular): (i0, i1, w1) arrays, i0 == i1 where a
    given heading matches."""
    h = np.mod(np.asarray(headings, float), 360.0)
    want = np.mod(np.asarray(wanted, float), 360.0)
    if symmetric:
        want = np.where(want > 180.0, 360.0 - want, want)
    d = np.abs(np.mod(want[:, None] - h[None, :] + 180.0, 360.0) - 180.0)
    exact = d.min(axis=1) < 1e-6
    if h.size == 1:
        if not exact.all():
            raise InputError("transfer functions at one heading cannot serve other headings",
                             field="headings", value=[float(h[0])])
        z = np.zeros(want.size, int)
        return z, z, np.zeros(want.size)
    order = np.argsort(h)
    hs = h[order]
    ext = np.concatenate([hs, [hs[0] + 360.0]])
    j = np.clip(np.searchsorted(ext, want, side="right") - 1, 0, hs.size - 1)
    w1 = (want - ext[j]) / (ext[j + 1] - ext[j])
    i0, i1 = order[j], order[(j + 1) % hs.size]
    near = d.argmin(axis=1)
    return np.where(exact, near, i0), np.where(exact, near, i1), np.where(exact, 0.0, w1)


def heading_weights(headings, wanted, symmetric=False):
    """(i0, i1, w1): |H|^2 at each ``wanted`` relative heading is (1 - w1) |H[i0]|^2 +
    w1 |H[i1]|^2 of the given ``headings`` (linear, circular), as in the matrix G."""
    return _heading_weights(headings, wanted, symmetric)


@dataclass(frozen=True)
class ResponseMatrix:
    """G of one course: ``G`` (n_f n_d, 2 n_o) with the m0 block then the m2 block; the
    spectra's ``freq`` [Hz] and ``dirs`` [deg], the ``course_deg``, the relative heading
    of each direction bin, and each band's share inside the transfer functions' range."""

    G: np.ndarray
    freq: np.ndarray
    dirs: np.ndarray
    course_deg: float
    headings_deg: np.ndarray
    band_inside: np.ndarray

    @property
    def n_options(self):
        return self.G.shape[1] // 2


def response_matrix(power, omega, headings_deg, freq, dirs, course_deg, *, symmetric=False,
                    dtype=np.float64) -> ResponseMatrix:
    """The matrix G of :func:`response_moments` for spectra on (freq [Hz], dirs [deg, from])
    and a vessel on ``course_deg`` [deg true].

    power: |H|^2 per unit wave amplitude, (n_o, n_h, n_w) or (n_h, n_w) for one option
    [unit^2 m^-2]; omega [rad/s] (n_w,); headings_deg (n_h,) relative (WAMIT convention).
    """
    P = np.asarray(power)
    P = P.astype(float) if P.dtype not in (np.float32, np.float64) else P
    P = P[None] if P.ndim == 2 else P
    omega = np.asarray(omega, float)
    if P.ndim != 3 or P.shape[1:] != (np.size(headings_deg), omega.size):
        raise InputError("power must be (options, headings, omega)", field="power", value=list(P.shape))
    if not np.all(np.isfinite(P)) or np.any(P < 0):
        raise InputError("|H|^2 must be finite and non-negative", field="power")
    d = np.asarray(dirs, float)
    width = direction_widths(d)
    beta = relative_heading(float(course_deg), d)
    (A0, A2), inside = _frequency_weights(freq, omega)
    A = np.concatenate([A0, A2]).astype(P.dtype)                   # (2 n_f, n_w)
    i0, i1, w1 = _heading_weights(headings_deg, beta, symmetric)
    n_f, n_d, n_o = A0.shape[0], d.size, P.shape[0]
    G = np.empty((n_f, n_d, 2, n_o), dtype=dtype)
    for j in range(n_d):
        Pj = P[:, i0[j], :] if w1[j] == 0 else (1 - w1[j]) * P[:, i0[j], :] + w1[j] * P[:, i1[j], :]
        g = (A @ Pj.T) * width[j]                                   # (2 n_f, n_o)
        G[:, j, 0, :], G[:, j, 1, :] = g[:n_f], g[n_f:]
    return ResponseMatrix(G.reshape(n_f * n_d, 2 * n_o), np.asarray(freq, float), d,
                          float(course_deg), beta, inside)


def response_moments(spectra, matrix: ResponseMatrix, *, chunk=4096, dtype=None):
    """m0, m2 (n_t, n_o) of records ``spectra`` (n_t, n_f, n_d) [m2 Hz-1 degree-1] on the
    matrix's grid, and each record's share of energy outside the transfer functions'
    frequency range (n_t,). One matrix product per ``chunk`` records."""
    E = spectra.values if isinstance(spectra, xr.DataArray) else np.asarray(spectra)
    n_f, n_d = matrix.freq.size, matrix.dirs.size
    if E.ndim != 3 or E.shape[1:] != (n_f, n_d):
        raise InputError(f"spectra must be (records, {n_f} frequencies, {n_d} directions)",
                         field="spectra", value=list(E.shape))
    dtype = dtype or matrix.G.dtype
    G = matrix.G.astype(dtype, copy=False)
    n_t, n_o = E.shape[0], matrix.n_options
    m = np.empty((n_t, 2 * n_o), dtype=dtype)
    df = np.gradient(matrix.freq) if n_f > 1 else np.ones(1)
    w = np.outer(df, direction_widths(matrix.dirs)).ravel()
    w_in = np.outer(df * matrix.band_inside, direction_widths(matrix.dirs)).ravel()
    outside = np.empty(n_t)
    for a in range(0, n_t, chunk):
        b = min(a + chunk, n_t)
        X = np.ascontiguousarray(E[a:b].reshape(b - a, n_f * n_d), dtype=dtype)
        np.matmul(X, G, out=m[a:b])
        m0 = X @ w.astype(dtype)
        with np.errstate(divide="ignore", invalid="ignore"):
            outside[a:b] = np.where(m0 > 0, 1.0 - (X @ w_in.astype(dtype)) / m0, 0.0)
    return m[:, :n_o], m[:, n_o:], np.clip(outside, 0.0, 1.0)


def directional_moments(efth: xr.DataArray, power: xr.DataArray, course_deg, *, symmetric=False,
                        chunk=4096, dtype=np.float64) -> xr.Dataset:
    """Response statistics per record of directional spectra ``efth`` (time, freq, dir)
    (:mod:`jls.sea.measured`) and transfer functions ``power`` (..., heading, omega) |H|^2
    (any leading dims are the options, e.g. candidate, tugger, response; coords
    ``heading`` [deg, relative] and ``omega`` [rad/s]).

    course_deg: the course [deg true], one for all records or one per record (records
    sharing a course share one matrix). Returns a Dataset with ``m0``, ``m2``, ``sigma``
    (sqrt m0), ``tz`` (2 pi sqrt(m0/m2)) over (time, *options) and ``energy_outside``.
    """
    if "dir" not in efth.dims:
        raise InputError("the response over a spectrum needs directions: a 1-D spectrum has "
                         "none (give it a dir dimension of one bin to make it long-crested)",
                         field="dir")
    opt_dims = [d for d in power.dims if d not in ("heading", "omega")]
    P = power.transpose(*opt_dims, "heading", "omega")
    lead = P.shape[:-2]
    Pv = P.values.reshape((-1,) + P.shape[-2:])
    course = np.broadcast_to(np.asarray(course_deg, float), (efth.sizes["time"],))
    E = efth.transpose("time", "freq", "dir").values
    n_o = Pv.shape[0]
    m0 = np.empty((E.shape[0], n_o), dtype)
    m2 = np.empty_like(m0)
    outside = np.empty(E.shape[0])
    for c in np.unique(np.round(course, 6)):
        rows = np.flatnonzero(np.round(course, 6) == c)
        G = response_matrix(Pv, P["omega"].values, P["heading"].values, efth["freq"].values,
                            efth["dir"].values, c, symmetric=symmetric, dtype=dtype)
        m0[rows], m2[rows], outside[rows] = response_moments(E[rows], G, chunk=chunk, dtype=dtype)
    dims = ["time"] + opt_dims
    coords = {"time": efth["time"].values, **{d: P[d].values for d in opt_dims if d in P.coords}}
    shape = (E.shape[0],) + lead
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = np.where(m2 > 0, 2 * np.pi * np.sqrt(m0 / m2), np.nan)
    ds = xr.Dataset({"m0": (dims, m0.reshape(shape)), "m2": (dims, m2.reshape(shape)),
                     "sigma": (dims, np.sqrt(np.maximum(m0, 0)).reshape(shape)),
                     "tz": (dims, tz.reshape(shape)), "energy_outside": ("time", outside)},
                    coords=coords)
    ds["course_deg"] = ("time", course.copy())
    ds.attrs.update({k: efth.attrs[k] for k in ("source", "sha256", "format") if k in efth.attrs})
    return ds
