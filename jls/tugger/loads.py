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

from jls.io import registry
from jls.response.solver import moment_weights, spectral_moments, transfer_functions
from jls.response.statistics import (
    FIXED_CYCLES_STUDY,
    from_moments,
    transfer_moments,
    unit_spectra,
    unit_statistics,
)

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


def load_statistics(m0, m2, c_tugger, exposure_s=3 * 3600.0, cycles="response",
                    tugger_axis=1) -> dict:
    """Unit-Hs statistics of the pair from the pay-out velocity's moments, e.g.
    (n_c, n_t, n_h, n_tz) with the tugger settings on axis ``tugger_axis``: sigma and MPM
    of force [kN per m of Hs] and pay-out velocity [m/s per m], mean and peak power
    [kW per m^2 of Hs]. The one place these statistics are made (the pipeline's response
    and :func:`frequency_domain_loads`)."""
    n = "response" if cycles == "response" else FIXED_CYCLES_STUDY
    st = from_moments(m0, m2, exposure_s, n)
    shape = [1] * np.ndim(m0)
    shape[tugger_axis] = -1
    c = np.asarray(c_tugger, float).reshape(shape)
    return {"tugger_sigma_force": c * st["sigma"], "tugger_mpm_force": c * st["mpm"],
            "tugger_sigma_payout_velocity": st["sigma"], "tugger_mpm_payout_velocity": st["mpm"],
            "tugger_power_mean": c * st["sigma"] ** 2, "tugger_power_peak": c * st["mpm"] ** 2}


def add_tugger_loads(ds: xr.Dataset, plant: xr.Dataset, exc, tuggers: dict, *, gamma=3.3,
                     exposure_h=3.0, cycles="response", threads=None) -> xr.Dataset:
    """The response dataset ``ds`` with the tugger loads of :func:`load_statistics` on its
    (candidate, tugger, heading, tz), from the plant and the solver's excitation
    (:func:`jls.response.moments.excitation`)."""
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
    st = load_statistics(*transfer_moments(omega, u, tz, gamma), c, exposure_s, tugger_axis=0)
    scale = hs[None, :, None]
    sig_u = st["tugger_sigma_payout_velocity"][:, None, :] * scale
    mpm_u = st["tugger_mpm_payout_velocity"][:, None, :] * scale
    sig_f = st["tugger_sigma_force"][:, None, :] * scale
    mpm_f = st["tugger_mpm_force"][:, None, :] * scale
    # Dissipated power c v^2 with v the relative velocity: mean c sigma_v^2, peak c MPM_v^2.
    p_mean = st["tugger_power_mean"][:, None, :] * scale**2
    p_peak = st["tugger_power_peak"][:, None, :] * scale**2
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
    ds["tz"].attrs.update(registry.attributes("response", "tz"))
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


__all__ = ["payout_moments", "load_statistics", "add_tugger_loads", "LOAD_VARIABLES",
           "load_transfer", "frequency_domain_loads", "plant_loads", "fixed_line_force"]
