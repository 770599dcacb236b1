"""Damping-slope sweep in the time domain (section 6.5.1, table 6.6).

The winch capacity is held fixed while the slope of the pair varies; every slope and
the bare plant run on the same wave record per wave period, so the reductions are
directly comparable. Critical damping of the sway mode is 2 M w_n (the study's
6178 kN s/m for 7719 t at 15.70 s; the shipped plant's 6281 kN s/m at 15.44 s). With
``end_at_critical`` the sweep ends at the plant's own critical slope
(:func:`critical_slope`): it is appended as the last slope, and listed slopes from 95 % of
it up are left out (the study's 6178 is its critical slope, replaced by the plant's); the
dataset says which (``critical_slope_kN_s_per_m``, ``sweep_ends_at_critical``,
``slopes_left_out_kN_s_per_m``).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.timedomain.run import Settings, run_cells
from jls.tugger.setting import Tugger


def critical_slope(plant) -> float:
    """2 M_sway w_n of the sway mode [kN s/m]."""
    i = int(plant.modes.mode_of("sway"))
    return float(2.0 * plant.M[0, 0] * plant.modes.omega[i])


#: Listed slopes from this fraction of the critical slope up are replaced by it.
CRITICAL_REPLACES = 0.95


def sweep_slopes(plant, slopes, end_at_critical) -> tuple[np.ndarray, np.ndarray]:
    """(slopes swept, listed slopes left out): with end_at_critical, the listed slopes
    below 95 % of :func:`critical_slope` and then the critical slope itself."""
    slopes = np.atleast_1d(np.asarray(slopes, float))
    if not end_at_critical:
        return slopes, np.zeros(0)
    crit = critical_slope(plant)
    keep = slopes < CRITICAL_REPLACES * crit
    return np.append(slopes[keep], crit), slopes[~keep]


def slope_sweep(plant, motion, slopes, tz, hs, heading_deg, *, capacity_kN, floor_kN, gamma,
                duration_s, settings: Settings, end_at_critical=False, workers=1) -> xr.Dataset:
    """MPM of the relative sway, fraction of time at capacity and sigma reduction per
    (tz, slope) at one wave height; dims (tz, slope). ``end_at_critical``: see the module
    docstring."""
    slopes, left_out = sweep_slopes(plant, slopes, end_at_critical)
    tz = np.atleast_1d(np.asarray(tz, float))
    tuggers = [Tugger("none", 0.0)] + [Tugger(f"c{s:g}", float(s), capacity_kN, floor_kN)
                                        for s in slopes]
    ds = run_cells(plant, motion, tuggers, np.full(tz.shape, float(hs)), tz, heading_deg,
                   gamma=gamma, duration_s=duration_s, settings=settings, workers=workers)
    bare = ds.isel(tugger=0)
    sw = ds.isel(tugger=slice(1, None))
    out = xr.Dataset(coords={"tz": tz, "slope": slopes})
    def grid(da):
        return (("tz", "slope"), da.values)
    out["mpm"] = grid(sw["mpm_upcrossing"])
    out["mpm"].attrs.update(units="m", long_name="3-h most probable maximum relative sway")
    out["at_capacity_fraction"] = grid(sw["at_max_fraction"])
    out["at_capacity_fraction"].attrs.update(units="1", long_name="fraction of time a line is at the winch capacity")
    out["sigma"] = grid(sw["sigma"])
    out["sigma"].attrs.update(units="m", long_name="standard deviation of the relative sway")
    out["sigma_reduction"] = (("tz", "slope"), 1.0 - sw["sigma"].values / bare["sigma"].values[:, None])
    out["sigma_reduction"].attrs.update(units="1", long_name="reduction of sigma against no tugger")
    out["mpm_no_tugger"] = ("tz", bare["mpm_upcrossing"].values, {"units": "m", "long_name": "MPM without tugger"})
    out["tz"].attrs.update(units="s", long_name="zero-up-crossing period")
    out["slope"].attrs.update(units="kN s/m", long_name="damping slope of the pair")
    out.attrs.update(ds.attrs, hs_m=float(hs), capacity_kN=float(capacity_kN),
                     critical_slope_kN_s_per_m=critical_slope(plant),
                     sweep_ends_at_critical=int(bool(end_at_critical)),
                     slopes_left_out_kN_s_per_m=[float(v) for v in left_out])
    return out


__all__ = ["slope_sweep", "critical_slope", "sweep_slopes"]
