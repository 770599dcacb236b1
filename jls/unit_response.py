"""Unit-Hs response dataset: transfer functions and statistics per candidate, tugger,
heading and Tz (the README (section Outputs), ``response.nc``).

The vessel RAOs are interpolated (amplitude and phase) onto a response grid that is
refined around the lightly damped sway and yaw modes, transferred to the hinge and the
fairleads, and driven through the plant of every candidate. The grid never leaves the
RAO's frequency range: the energy of each sea state outside it is measured, and more
than 0.1 % is an error unless the configuration states that the vessel is still there.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.coverage import ENERGY_OUTSIDE_LIMIT, check_coverage, describe  # noqa: F401
from jls.motion import select
from jls.response import RESPONSES, ROTATIONAL, response_grid, transfer_functions
from jls.statistics import FIXED_CYCLES_STUDY, unit_statistics
from jls.vessel import fairlead_motion, hinge_excitation, interp_rao, make_rao_dataset

def response_dataset(plant: xr.Dataset, motion: xr.Dataset, tz, headings_deg, tuggers: dict,
                     *, gamma=3.3, exposure_h=3.0, cycles="response", omega_step=0.002,
                     outside_policy="error", source=None) -> xr.Dataset:
    """Transfer functions and unit-Hs statistics (see module docstring).

    plant, motion: datasets of the README (section Outputs) (complex merged); tz: Tz values [s];
    headings_deg: headings to evaluate; tuggers: name -> damping slope [kN s/m];
    cycles: "response" or "fixed" (N = 1000, as the study).
    """
    tz = np.asarray(sorted(set(float(t) for t in tz)))
    omega_rao = motion["omega"].values
    lo, hi = float(omega_rao.min()), float(omega_rao.max())
    frac = check_coverage(lo, hi, tz, gamma, outside_policy, source)

    # Refine around the sway and yaw modes (the two longest periods) of every candidate.
    wn = 2 * np.pi / plant["natural_period"].isel(mode=slice(0, 2)).values
    zeta = float(np.nanmin(plant["damping_ratio"].values))
    omega = response_grid(lo, hi, omega_step, wn, zeta=zeta, points_per_bandwidth=8)

    motion = select(motion, headings_deg)
    rao = make_rao_dataset(omega_rao, np.radians(motion["heading"].values),
                           motion["rao"].transpose("omega", "heading", "vessel_dof").values,
                           reference_point_m=motion.attrs.get("reference_point_m", (0, 0, 0)))
    rao = interp_rao(rao, omega)
    hinge_m = tuple(motion.attrs["hinge_m"])
    off = motion.attrs["fairlead_offset_m"]
    qb = hinge_excitation(rao, hinge_m).transpose("wave_direction", "omega", ...).values
    fl = fairlead_motion(rao, hinge_m, drop=-off[2], half_span=off[1])
    fl_sway = fl.sel(axis="y").mean("side").transpose("wave_direction", "omega").values

    names = list(tuggers)
    c_t = np.array([float(tuggers[n]) for n in names])
    _, Hrel = transfer_functions(plant["M"].values, plant["K"].values, plant["Kb"].values,
                                 plant["C"].values, omega, qb, fl_sway, c_t)
    Hrel = Hrel * np.where(ROTATIONAL, 180.0 / np.pi, 1.0)          # rotations in degrees
    H = np.moveaxis(Hrel, -1, -2)                                    # (cand, t, h, resp, w)
    n_cycles = "response" if cycles == "response" else FIXED_CYCLES_STUDY
    stats = unit_statistics(omega, H, tz, gamma, exposure_h * 3600.0, n_cycles)

    dims = ("candidate", "tugger", "heading", "response", "tz")
    coords = {"candidate": plant["candidate"].values, "tugger": names,
              "c_tugger": ("tugger", c_t), "heading": motion["heading"].values,
              "response": list(RESPONSES), "tz": tz, "omega": omega}
    ds = xr.Dataset({k: (dims, v) for k, v in stats.items()}, coords=coords)
    ds["transfer"] = (("candidate", "tugger", "heading", "response", "omega"), H)
    ds["energy_outside"] = ("tz", frac)
    per = "m or degree per m of Hs (per response)"
    for name, long_name, unit in [
        ("sigma", "standard deviation at Hs = 1 m", per),
        ("tz_response", "response zero-crossing period", "s"),
        ("n_cycles", "response cycles in the exposure", "1"),
        ("mpm", "most probable maximum at Hs = 1 m", per),
        ("transfer", "relative motion per unit wave amplitude", "m/m or degree/m (per response)"),
        ("energy_outside", "sea-state energy outside the RAO frequency range", "1"),
    ]:
        ds[name].attrs.update(long_name=long_name, units=unit)
    ds["omega"].attrs.update(long_name="wave angular frequency", units="rad/s")
    ds["tz"].attrs.update(long_name="zero-up-crossing period", units="s")
    ds["heading"].attrs.update(long_name="relative wave heading", units="degree")
    ds["c_tugger"].attrs.update(long_name="tugger damping slope", units="kN s/m")
    ds.attrs.update(
        exposure_h=float(exposure_h),
        mpm_cycles=("response: N = exposure / Tz_response" if cycles == "response"
                    else f"fixed: N = {FIXED_CYCLES_STUDY}"),
        gamma=float(gamma), spectrum="JONSWAP, sigma_a 0.07, sigma_b 0.09, Tp from Tz (DNV-RP-C205)",
        outside_rao_range=describe(outside_policy))
    return ds
