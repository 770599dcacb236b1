"""Coverage of the sea states by the vessel's RAO frequency range.

The response is integrated over the RAO's frequency range only: outside it the vessel
is taken as still. That is true only where the configuration says so, for a stated
reason (``vessel.outside_rao_range``)::

    outside_rao_range:
      zero_above_rad_s: 3.0     # the hull no longer responds to waves this short
      zero_below_rad_s: 0.1     # (rarely needed) no wave energy this long
      reason: waves shorter than 7 m against a 382 m hull

Sea-state energy outside the RAO range *and* outside the stated bands is unexplained: more
than :data:`ENERGY_OUTSIDE_LIMIT` (0.1 %) of a sea state's energy there is an error,
whatever the configuration says. The check is never skipped, so a truncated RAO file,
RAO frequencies given as periods or in Hz, or Tz given in Hz stop the run instead of
treating most of the energy as no motion. The fraction of each sea state's energy taken
as no motion is returned, and kept in the response dataset.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError
from jls.response.statistics import energy_grid, energy_outside

ENERGY_OUTSIDE_LIMIT = 1e-3
FIELD = "vessel.outside_rao_range"


def zero_bands(policy, source=None) -> tuple[float, float]:
    """(below, above) [rad/s]: the motion is taken as zero below ``below`` and above
    ``above`` (0 and inf when not stated). ``policy`` is the configuration's
    ``vessel.outside_rao_range`` mapping, or None / "error" for no stated band."""
    if policy is None or policy == "error":
        return 0.0, np.inf
    if not isinstance(policy, dict):
        raise InputError("must state the band where the motion is zero and why, e.g. "
                         "{zero_above_rad_s: 3.0, reason: ...}; 'zero' without a band is no "
                         "longer accepted", file=source, field=FIELD, value=policy)
    if not str(policy.get("reason", "")).strip():
        raise InputError("a stated zero-motion band needs a reason", file=source,
                         field=f"{FIELD}.reason")
    below = float(policy.get("zero_below_rad_s", 0.0))
    above = float(policy.get("zero_above_rad_s", np.inf))
    if "zero_below_rad_s" not in policy and "zero_above_rad_s" not in policy:
        raise InputError("state zero_above_rad_s and/or zero_below_rad_s", file=source,
                         field=FIELD, value=policy)
    if not below < above:
        raise InputError("zero_below_rad_s must be below zero_above_rad_s", file=source,
                         field=FIELD, value=[below, above])
    return below, above


def describe(policy) -> str:
    """One line for the datasets' attributes: how the RAO is continued outside its range."""
    below, above = zero_bands(policy)
    if below == 0.0 and above == np.inf:
        return (f"none: sea states with more than {100 * ENERGY_OUTSIDE_LIMIT:g} % of their "
                "energy outside the RAO range are rejected")
    parts = ([f"below {below:g} rad/s"] if below > 0 else []) + \
            ([f"above {above:g} rad/s"] if np.isfinite(above) else [])
    return f"zero motion {' and '.join(parts)}: {policy['reason'].strip()}"


def coverage(omega_lo, omega_hi, tz, gamma=3.3, policy=None, source=None):
    """(zeroed, unexplained): per Tz, the fraction of the energy outside the RAO range
    [omega_lo, omega_hi], and the part of it outside the stated zero-motion bands."""
    below, above = zero_bands(policy, source)
    tz = np.atleast_1d(np.asarray(tz, float))
    grid = energy_grid(tz, gamma)                   # the spectra once, for the three bands
    zeroed = energy_outside(omega_lo, omega_hi, tz, gamma, grid)
    in_low_band = energy_outside(min(below, omega_lo), np.inf, tz, gamma, grid) if below > 0 else 0.0
    in_high_band = energy_outside(0.0, max(above, omega_hi), tz, gamma, grid) \
        if np.isfinite(above) else 0.0
    unexplained = np.clip(zeroed - in_low_band - in_high_band, 0.0, 1.0)
    return zeroed, unexplained


def check_coverage(omega_lo, omega_hi, tz, gamma=3.3, policy=None, source=None):
    """Fraction of each sea state's energy outside [omega_lo, omega_hi] (taken as no
    motion); InputError when more than 0.1 % lies outside the stated bands too."""
    if not (np.isfinite(omega_lo) and np.isfinite(omega_hi) and 0 < omega_lo < omega_hi):
        raise InputError("RAO frequency range must be positive and increasing", file=source,
                         field="omega", value=[omega_lo, omega_hi])
    tz = np.atleast_1d(np.asarray(tz, float))
    zeroed, unexplained = coverage(omega_lo, omega_hi, tz, gamma, policy, source)
    if np.any(unexplained > ENERGY_OUTSIDE_LIMIT):
        i = int(np.argmax(unexplained))
        below, above = zero_bands(policy, source)
        stated = describe(policy).split(":")[0] if (below > 0 or np.isfinite(above)) \
            else "no zero-motion band stated"
        raise InputError(
            f"the sea state Tz = {tz[i]:g} s (gamma {gamma:g}) has {100 * unexplained[i]:.2f} % "
            f"of its energy outside the RAO range [{omega_lo:.3f}, {omega_hi:.3f}] rad/s "
            f"({stated}); extend the RAOs, check their frequency unit (rad/s, not Hz or s) "
            "and the Tz unit (s), or state the band where the vessel does not move "
            f"({FIELD}: {{zero_above_rad_s: ..., reason: ...}})",
            file=source, field=FIELD, value=float(tz[i]))
    return zeroed


def spectra_outside(efth, omega_lo, omega_hi, policy=None, source=None):
    """(zeroed, unexplained) per record of measured spectra ``efth`` (dims time, freq[,
    dir], E in m2/Hz per band of width ``numpy.gradient(freq)``, the integration rule of
    :mod:`jls.sea.measured`): the fraction of each record's energy in bands whose angular
    frequency 2 pi f lies outside the RAO range, and the part of it outside the stated
    zero-motion bands too: the rule of the parametric sea states, applied to measured and
    hindcast spectra."""
    below, above = zero_bands(policy, source)
    f = np.asarray(efth["freq"].values, float)
    w = 2.0 * np.pi * f
    if "dir" in efth.dims:                        # each direction bin stands for its width
        from jls.sea.directional import direction_widths
        e = np.einsum("tfd,d->tf", efth.transpose("time", "freq", "dir").values,
                      direction_widths(efth["dir"].values))
    else:
        e = efth.transpose("time", "freq").values
    e = e * np.gradient(f)[None, :]
    total = e.sum(axis=1)
    total = np.where(total > 0, total, np.nan)
    out = (w < omega_lo) | (w > omega_hi)
    explained = (w < min(below, omega_lo)) | (w > max(above, omega_hi))
    zeroed = e[:, out].sum(axis=1) / total
    unexplained = e[:, out & ~explained].sum(axis=1) / total
    return np.nan_to_num(zeroed), np.nan_to_num(unexplained)


def check_spectra_coverage(efth, omega_lo, omega_hi, policy=None, source=None, field=FIELD):
    """InputError when a record of measured spectra has more than 0.1 % of its energy
    outside the RAO range and the stated bands (:func:`spectra_outside`), naming the
    file, the record's time and the band; returns the zeroed fraction per record."""
    zeroed, unexplained = spectra_outside(efth, omega_lo, omega_hi, policy, source)
    bad = unexplained > ENERGY_OUTSIDE_LIMIT
    if bad.any():
        i = int(np.argmax(unexplained))
        f = np.asarray(efth["freq"].values, float)
        w = 2.0 * np.pi * f
        low = w[w < omega_lo]
        where = (f"below it (bands from {low[0]:.3f} rad/s, {f[0]:g} Hz)" if low.size
                 else f"above it (bands to {w[-1]:.3f} rad/s)")
        when = str(efth["time"].values[i])[:16]
        raise InputError(
            f"{int(bad.sum())} of the {bad.size} spectra have more than "
            f"{100 * ENERGY_OUTSIDE_LIMIT:g} % of their energy outside the RAO range "
            f"[{omega_lo:.3f}, {omega_hi:.3f}] rad/s and the stated zero-motion bands, the largest "
            f"at {when} with {100 * unexplained[i]:.2f} % {where}: as for parametric sea states, "
            "extend the RAOs or state the band where the vessel does not move "
            f"({FIELD}: {{zero_below_rad_s: ..., reason: ...}})",
            file=source, field=field, value=round(float(unexplained[i]), 6))
    return zeroed
