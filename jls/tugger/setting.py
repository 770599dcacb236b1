"""Damping tuggers: settings, setpoint law and loads in the frequency domain (chapter 6).

A damping tugger is a pair of opposing lines from fairleads on the vessel to the jacket
at CoG height (section 6.3.2: fairleads 82.5 m below the hinge and 37.5 m either side,
jacket half-width 22.5 m, free length 15 m). Each line follows the maximum-force setpoint
(eq. 6.2)

    T = sat[T_min, T_max](T0 + c/n u),    T0 = (T_min + T_max) / 2,

with u the pay-out velocity of that line (eq. 6.3), so that the net force of the pair is
c u while neither line is at a limit. In the frequency domain the pair is a linear damper
of slope c between the fairlead sway and the jacket sway (:mod:`jls.response.solver`); this
module turns that closed-loop response into the loads on the winch, and flags where the
linear picture breaks down because the winch would saturate.

Winch settings (table 6.3): Low 300 kN s/m on 1000 kN, Reference 1000 / 1000, High
2000 / 2000; floor T_min = 20 kN; two lines. A setting given without a capacity gets the
1000 kN winch the study holds fixed in its slope sweep (section 6.5.1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.response.statistics import unit_statistics

T_MIN_KN = 20.0
DEFAULT_CAPACITY_KN = 1000.0
N_LINES = 2
JACKET_HALF_WIDTH_M = 22.5
#: Table 6.3 of the study: name -> (slope kN s/m, capacity kN).
STUDY_SETTINGS = {"low": (300.0, 1000.0), "reference": (1000.0, 1000.0), "high": (2000.0, 2000.0)}


@dataclass(frozen=True)
class Tugger:
    """One tugger setting: slope c of the pair [kN s/m], per-line force limits [kN],
    first-order actuator lag [s] (0: ideal force source), number of lines, jacket
    half-width at the attachment [m]."""

    name: str
    c: float
    max_force: float = DEFAULT_CAPACITY_KN
    min_force: float = T_MIN_KN
    lag: float = 0.0
    n_lines: int = N_LINES
    half_width: float = JACKET_HALF_WIDTH_M

    @property
    def active(self) -> bool:
        return self.c > 0

    @property
    def pretension(self) -> float:
        """T0, midway between the floor and the capacity (section 6.3.2)."""
        return 0.5 * (self.max_force + self.min_force)

    @property
    def net_force_limit(self) -> float:
        """Largest net force of the pair available for damping: T_max - T_min [kN]."""
        return self.max_force - self.min_force

    @property
    def saturation_velocity(self) -> float:
        """Pay-out speed at which a line reaches a limit, (T_max - T0) n / c [m/s]."""
        return np.inf if self.c <= 0 else (self.max_force - self.pretension) * self.n_lines / self.c


def tension(tugger: Tugger, u):
    """Per-line tension [kN] of the setpoint law (eq. 6.2) at pay-out velocity u [m/s]."""
    return np.clip(tugger.pretension + tugger.c / tugger.n_lines * np.asarray(u, float),
                   tugger.min_force, tugger.max_force)


def settings_table(tuggers) -> xr.Dataset:
    """Table 6.3 for the given settings: slope, capacity, floor, pretension, saturation
    speed and net force limit, per tugger."""
    tuggers = list(tuggers)
    ds = xr.Dataset(
        {"c": ("tugger", [t.c for t in tuggers], {"units": "kN s/m", "long_name": "damping slope of the pair"}),
         "max_force": ("tugger", [t.max_force for t in tuggers], {"units": "kN", "long_name": "winch capacity per line"}),
         "min_force": ("tugger", [t.min_force for t in tuggers], {"units": "kN", "long_name": "no-slack floor per line"}),
         "pretension": ("tugger", [t.pretension for t in tuggers], {"units": "kN", "long_name": "pretension per line"}),
         "saturation_velocity": ("tugger", [t.saturation_velocity for t in tuggers],
                                 {"units": "m/s", "long_name": "pay-out speed at which a line reaches a limit"}),
         "net_force_limit": ("tugger", [t.net_force_limit for t in tuggers],
                             {"units": "kN", "long_name": "largest net force of the pair"})},
        coords={"tugger": [t.name for t in tuggers]})
    return ds


def load_transfer(omega, jacket_sway, fairlead_sway, c):
    """Transfer functions of the tugger loads per unit wave amplitude.

    jacket_sway: (..., n_w) complex closed-loop CoG sway with the tugger of slope c;
    fairlead_sway: broadcastable (..., n_w) complex fairlead sway; c: broadcastable to
    the leading axes [kN s/m]. Returns (payout_velocity, net_force), each (..., n_w):
    the pay-out velocity of the starboard line (m/s per m; the port line's is its
    negative; eq. 6.3 with the fairlead's own motion) and the net sway force of the pair
    on the jacket (kN per m), F = -c i w (y - y_f).
    """
    iw = 1j * np.asarray(omega, float)
    rel = np.asarray(jacket_sway, complex) - np.asarray(fairlead_sway, complex)
    u = iw * rel
    c = np.asarray(c, float)[..., None]
    return u, -c * u


def frequency_domain_loads(omega, jacket_sway, fairlead_sway, tuggers, tz, hs=1.0,
                           gamma=3.3, exposure_s=3 * 3600.0) -> xr.Dataset:
    """Tugger loads in irregular seas: sigma and 3-h MPM of force and pay-out velocity,
    mean and peak power, and the saturation flag, per (tugger, hs, tz).

    jacket_sway: (n_tugger, n_w) closed-loop CoG sway transfer function per tugger
    (:func:`jls.response.solver.transfer_functions`), fairlead_sway: (n_w,) fairlead sway RAO,
    tuggers: sequence of :class:`Tugger` in the same order. The model is linear: sigma
    and MPM scale with Hs, power with Hs^2. A cell is flagged where the MPM net force
    exceeds what the winch can deliver (T_max - T_min): there the frequency domain is
    unreliable because the winch saturates.
    """
    tuggers = list(tuggers)
    c = np.array([t.c for t in tuggers])
    hs = np.atleast_1d(np.asarray(hs, float))
    tz = np.atleast_1d(np.asarray(tz, float))
    u, force = load_transfer(omega, jacket_sway, fairlead_sway, c)
    st_u = unit_statistics(omega, u, tz, gamma, exposure_s)
    st_f = unit_statistics(omega, force, tz, gamma, exposure_s)
    scale = hs[None, :, None]
    sig_u, mpm_u = st_u["sigma"][:, None, :] * scale, st_u["mpm"][:, None, :] * scale
    sig_f, mpm_f = st_f["sigma"][:, None, :] * scale, st_f["mpm"][:, None, :] * scale
    # Dissipated power c v^2 with v the relative velocity: mean c sigma_v^2, peak c MPM_v^2.
    p_mean = c[:, None, None] * sig_u**2
    p_peak = c[:, None, None] * mpm_u**2
    limit = np.array([t.net_force_limit for t in tuggers])[:, None, None]
    saturates = (mpm_f > limit) & (c[:, None, None] > 0)
    dims = ("tugger", "hs", "tz")
    ds = xr.Dataset(coords={"tugger": [t.name for t in tuggers], "hs": hs, "tz": tz,
                            "omega": np.asarray(omega, float)})
    for name, val, unit, ln in [
        ("sigma_force", sig_f, "kN", "standard deviation of the net tugger force on the jacket"),
        ("mpm_force", mpm_f, "kN", "3-h most probable maximum net tugger force"),
        ("sigma_payout_velocity", sig_u, "m/s", "standard deviation of the line pay-out velocity"),
        ("mpm_payout_velocity", mpm_u, "m/s", "3-h most probable maximum pay-out velocity"),
        ("power_mean", p_mean, "kW", "mean power absorbed by the pair"),
        ("power_peak", p_peak, "kW", "power absorbed at the MPM pay-out velocity"),
    ]:
        ds[name] = (dims, val, {"units": unit, "long_name": ln})
    ds["force_available"] = ("tugger", limit[:, 0, 0],
                             {"units": "kN", "long_name": "net force available for damping, T_max - T_min"})
    ds["saturates"] = (dims, saturates.astype(np.int8), {
        "units": "1", "flag_values": [0, 1],
        "flag_meanings": "linear frequency_domain_unreliable_winch_saturates",
        "long_name": "MPM net force exceeds the force available: frequency domain unreliable, winch saturates"})
    ds["payout_velocity_re"] = (("tugger", "omega"), u.real, {"units": "m/s per m", "long_name": "pay-out velocity RAO (starboard line), real part"})
    ds["payout_velocity_im"] = (("tugger", "omega"), u.imag, {"units": "m/s per m", "long_name": "pay-out velocity RAO (starboard line), imaginary part"})
    ds["force_re"] = (("tugger", "omega"), force.real, {"units": "kN/m", "long_name": "net tugger force RAO, real part"})
    ds["force_im"] = (("tugger", "omega"), force.imag, {"units": "kN/m", "long_name": "net tugger force RAO, imaginary part"})
    ds["hs"].attrs.update(units="m", long_name="significant wave height")
    ds["tz"].attrs.update(units="s", long_name="zero-up-crossing period")
    ds["omega"].attrs.update(units="rad/s", long_name="wave angular frequency")
    ds.attrs.update(gamma=float(gamma), exposure_h=exposure_s / 3600.0)
    return ds


def plant_loads(plant, motion, tuggers, tz, hs=1.0, heading_deg=90.0, gamma=3.3,
                exposure_s=3 * 3600.0, omega_step=0.002) -> xr.Dataset:
    """:func:`frequency_domain_loads` of one plant (:class:`jls.plant.model.Plant`) in the
    vessel-motion dataset of :func:`jls.stages.vessel_motion.vessel_motion` at one heading, on a grid
    over the RAO's range refined around the plant's modes; adds ``sigma_relative_sway``
    (tugger, hs, tz) [m], the linear response the loads belong to."""
    from jls.response.solver import frequency_grid, transfer_functions
    from jls.vessel.transfer import channel_transfer
    tuggers = list(tuggers)
    om = motion["omega"].values
    grid = frequency_grid(om.min(), om.max(), omega_step, plant.modes.omega, plant.damping_ratio)
    tr = channel_transfer(motion, heading_deg, grid)
    fl_sway = 0.5 * (tr[5] + tr[8])                                  # port and starboard
    Hq, Hrel = transfer_functions(plant.M, plant.K, plant.Kb, plant.C, grid,
                                  tr[None, :4].transpose(0, 2, 1), fl_sway[None],
                                  [t.c for t in tuggers])
    ds = frequency_domain_loads(grid, Hq[:, 0, :, 0], fl_sway, tuggers, tz, hs, gamma, exposure_s)
    sig = unit_statistics(grid, Hrel[:, 0, :, 0], np.atleast_1d(tz), gamma, exposure_s)["sigma"]
    ds["sigma_relative_sway"] = (("tugger", "hs", "tz"), sig[:, None, :] * ds["hs"].values[None, :, None],
                                 {"units": "m", "long_name": "standard deviation of the relative sway (linear)"})
    ds.attrs["heading_deg"] = float(heading_deg)
    return ds


def fixed_line_force(inertial_mass_t, period_s, amplitude_m, g=9.81) -> xr.DataArray:
    """Force a fixed-line pair must deliver to make the jacket follow a fairlead sway of
    amplitude X at period T, F = M_i w^2 X (eq. 6.1, table 6.1), in kN; dims (period,
    amplitude). Divide by ``g`` (kept as attr) for the table's tonnes-force."""
    T = np.atleast_1d(np.asarray(period_s, float))
    X = np.atleast_1d(np.asarray(amplitude_m, float))
    F = inertial_mass_t * (2 * np.pi / T[:, None]) ** 2 * X[None, :]
    da = xr.DataArray(F, dims=("period", "amplitude"), coords={"period": T, "amplitude": X},
                      name="fixed_line_force",
                      attrs={"units": "kN", "long_name": "force of a fixed-line pair, M_i w^2 X",
                             "g_m_per_s2": g})
    da["period"].attrs.update(units="s", long_name="excitation period")
    da["amplitude"].attrs.update(units="m", long_name="fairlead sway amplitude")
    return da


__all__ = ["Tugger", "tension", "settings_table", "load_transfer",
           "frequency_domain_loads", "plant_loads", "fixed_line_force", "STUDY_SETTINGS", "T_MIN_KN"]
