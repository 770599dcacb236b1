"""Directional wave spectra: direction bins, spreading functions, the buoy's Fourier
reconstruction, and parametric partitions laid out on a direction grid.

Directions are degrees true, the direction the waves come FROM; a directional spectrum
E(f, dir) is in m^2/(Hz deg) on the bin centres ``dirs``, and each bin stands for its
width (:func:`direction_widths`), so that ``E(f) = sum_dir E(f, dir) width(dir)``.

**Fourier reconstruction** (NDBC, Longuet-Higgins et al. 1963; as wavespectra's
``read_ndbc_ascii``): from the mean and principal directions alpha1, alpha2 and the
normalised coefficients r1, r2 of each frequency band,

    D(dir) = 1/pi [1/2 + r1 cos(dir - alpha1) + r2 cos(2 (dir - alpha2))]   per radian

(times pi/180 per degree). It integrates to 1 over the circle on any uniform grid of at
least three directions, but can be negative where the spread is narrow; ``weighted=True``
applies the Longuet-Higgins weights 2/3 and 1/6 to the two harmonics, which keeps D >= 0
for consistent coefficients at the price of a broader spread.

**Parametric partitions** (wind sea, swell): long-crested (all energy in the bin nearest
the partition's direction) or spread by cos^2s((dir - from)/2), normalised on the grid.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError

__all__ = ["DEFAULT_DIRS", "direction_widths", "fourier_spreading", "cos2s_spreading",
           "long_crested", "partitions_on_grid"]

#: Default direction grid of reconstructed spectra: 24 bins of 15 deg.
DEFAULT_DIRS = np.arange(0.0, 360.0, 15.0)
D2R = np.pi / 180.0


def _dirs(dirs, field="dirs"):
    d = np.asarray(dirs, float)
    if d.ndim != 1 or d.size < 1 or not np.all(np.isfinite(d)) or np.any(d < 0) or np.any(d >= 360):
        raise InputError("directions must be a 1-D array of values in [0, 360) deg", field=field,
                         value=np.asarray(dirs).tolist())
    if d.size > 1 and len(np.unique(np.round(d, 9))) != d.size:
        raise InputError("directions must be distinct", field=field, value=d.tolist())
    return d


def direction_widths(dirs):
    """Width [deg] each direction bin stands for: half the circular distance to each
    neighbour (360 for a single direction). Sums to 360."""
    d = _dirs(dirs)
    if d.size == 1:
        return np.array([360.0])
    order = np.argsort(d)
    s = d[order]
    gaps = np.diff(np.concatenate([s, [s[0] + 360.0]]))          # to the next one
    w = 0.5 * (gaps + np.roll(gaps, 1))
    out = np.empty_like(w)
    out[order] = w
    return out


def fourier_spreading(dirs, alpha1, alpha2, r1, r2, *, weighted=False):
    """Directional distribution D [1/deg] from the buoy's coefficients, on ``dirs`` (last
    axis). alpha1, alpha2 [deg, from], r1, r2 [0-1] broadcast against each other."""
    d = _dirs(dirs)
    a1, a2, c1, c2 = (np.asarray(v, float)[..., None] for v in (alpha1, alpha2, r1, r2))
    k1, k2 = (2.0 / 3.0, 1.0 / 6.0) if weighted else (1.0, 1.0)
    D = (0.5 + k1 * c1 * np.cos(D2R * (d - a1)) + k2 * c2 * np.cos(2 * D2R * (d - a2))) / np.pi
    return D * D2R


def cos2s_spreading(dirs, from_deg, s):
    """cos^2s((dir - from)/2) spreading [1/deg] on ``dirs``, normalised so that
    sum D width = 1 on the grid (s > 0; larger s is narrower)."""
    d = _dirs(dirs)
    if not (np.isfinite(s) and s > 0):
        raise InputError("spreading exponent s must be positive", field="s", value=s)
    D = np.cos(0.5 * D2R * (d - float(from_deg))) ** (2.0 * s)
    D = np.abs(D)
    return D / np.sum(D * direction_widths(d))


def long_crested(dirs, from_deg):
    """All the energy in the bin nearest ``from_deg`` [1/deg] (sum D width = 1)."""
    d = _dirs(dirs)
    k = int(np.argmin(np.abs(np.mod(d - float(from_deg) + 180.0, 360.0) - 180.0)))
    D = np.zeros_like(d)
    D[k] = 1.0 / direction_widths(d)[k]
    return D


def partitions_on_grid(freq, dirs, partitions, *, spreading=None):
    """Directional spectrum E(f, dir) [m^2/(Hz deg)] of parametric partitions.

    freq [Hz] (n_f,); dirs [deg, from] (n_d,); partitions: objects with ``spectrum(omega)``
    [m^2 s/rad] and ``from_deg`` (:class:`jls.sea.two_peak.Partition`); spreading: None
    (long-crested) or the cos-2s exponent s, one for all or one per partition.
    Returns (n_f, n_d).
    """
    f = np.asarray(freq, float)
    d = _dirs(dirs)
    spreads = spreading if isinstance(spreading, (list, tuple)) else [spreading] * len(partitions)
    if len(spreads) != len(partitions):
        raise InputError("one spreading exponent per partition", field="spreading", value=spreading)
    E = np.zeros((f.size, d.size))
    for p, s in zip(partitions, spreads):
        if p.from_deg is None:
            raise InputError("a partition on a direction grid needs its direction", field="from_deg")
        D = long_crested(d, p.from_deg) if s is None else cos2s_spreading(d, p.from_deg, s)
        E += (2 * np.pi * p.spectrum(2 * np.pi * f))[:, None] * D[None, :]
    return E
