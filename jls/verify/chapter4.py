"""The study's chapter-4 tests of the ROM against the nonlinear reference, for any
rigging candidate and sea state.

* :func:`reference_modes`: the reference's periods and damping from small free decays
  along each of its six linearised mode shapes (surge and pitch included), beside the
  linearisation's periods;
* :func:`free_decay` (section 4.1): release from a sway offset (the other DOFs in
  static equilibrium with it) on a still vessel, period and damping of both models by
  log decrement;
* :func:`harmonic` (section 4.2): steady-state amplitude and phase of the relative
  sway under a harmonic hinge sway, against the ROM's transfer function;
* :func:`irregular_sea` (sections 4.4 and 4.5): both models on the same vessel-motion
  record of one sea state: sigma and MPM of each, and r, R^2 and RMS error of the ROM's
  relative sway against the reference's at identical excitation.

Units t, kN, m, s, rad (results in m, s, and degrees where named so).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.verify import excitation as exc_mod
from jls.verify import identify, rom, simulate, statics

DT = 0.02
#: the winch-law slope [kN s/m] of a tugger held at its pretension: active (its lines
#: exist), a force change under 1e-9 kN at any speed the jacket reaches
HELD_SLOPE = 1e-12


def _sway_mode(plant):
    i = int(np.argmax(plant.modes.energy_fraction[..., 0]))
    return float(plant.modes.omega[i]), float(plant.damping_ratio[i])


def transient_s(plant, time_constants=5.0, c_tugger=0.0) -> float:
    """Start-up transient excluded from statistics: ``time_constants`` sway time
    constants 1 / (zeta w_n) of the ROM (section 4.6: five). With a tugger of slope
    ``c_tugger`` [kN s/m] (a linear damper on the sway, as the ROM has it) the time
    constant of the slowest-decaying mode of the damped ROM, 1 / min(-Re lambda): the
    tugger damps the sway, and the start-up then ends with the slowest other mode."""
    if not c_tugger:
        w, z = _sway_mode(plant)
        return time_constants / (z * w)
    M, K, C = (np.asarray(a, float) for a in (plant.M, plant.K, plant.C))
    C = C.copy()
    C[0, 0] += float(c_tugger)
    n = M.shape[0]
    Mi = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Mi @ K, -Mi @ C]])
    return time_constants / float(np.min(-np.linalg.eigvals(A).real))


def held_tugger(ref):
    """The reference with its tugger lines held at their pretension (a winch law of no
    slope): the modes and the geometry stay those of the tugger's lines, the damping is
    the dashpots' alone. The tugger's own damping is modelled alike in both models (its
    winch law in the reference, its linear damper in the ROM) and compared by the sway
    free decay (:func:`free_decay`)."""
    if ref.tugger is None:
        return ref
    return dataclasses.replace(ref, tugger=dataclasses.replace(ref.tugger, c=HELD_SLOPE))


def reference_modes(ref, *, cycles=8, amplitude_m=0.05, dt=DT) -> xr.Dataset:
    """Periods and damping ratios of the reference: of its linearisation, and measured
    by log decrement on small free decays along each mode shape (the modal coordinate
    phi^T M6 (x - x_static) of the MoorDyn run), the tugger lines held at their
    pretension (:func:`held_tugger`): what the dashpots achieve against their targets.
    ``amplitude_m``: the release's largest translation (or rotation times the CoG depth)."""
    ref = held_tugger(ref)
    md = ref.modes
    rows = []
    for j in range(6):
        phi = md.shapes[:, j]
        scale = np.max(np.abs(phi * np.array([1, 1, 1, ref.lever, ref.lever, ref.lever])))
        d = phi * amplitude_m / scale
        pose0 = ref.pose.copy()
        pose0[:3] += d[:3]
        pose0[3:] = statics.euler_from_matrix(statics.rodrigues(d[3:]) @ statics.rotation(*ref.pose[3:]))
        run = simulate.run(ref, exc_mod.still(dt, cycles * md.period[j]), pose=pose0)
        x = run.pose - ref.pose
        eta = x @ (ref.M6 @ phi)
        fit = identify.log_decrement(run.time, eta)
        rows.append((fit.period_undamped, fit.zeta, fit.r2, fit.n_peaks))
    rows = np.array(rows)
    ds = xr.Dataset(coords={"mode": np.arange(1, 7), "dominant_dof": ("mode", list(md.dominant))})
    ds["period_linearised"] = ("mode", md.period, {"units": "s", "long_name": "undamped period of the linearised reference"})
    ds["period_decay"] = ("mode", rows[:, 0], {"units": "s", "long_name": "undamped period from a small free decay (log decrement)"})
    ds["damping_ratio_decay"] = ("mode", rows[:, 1], {"units": "1", "long_name": "damping ratio from the free decay"})
    ds["damping_ratio_target"] = ("mode", ref.dashpots.target_ratio, {"units": "1", "long_name": "damping ratio the dashpots were sized for (the ROM's)"})
    ds["damping_ratio_linearised"] = ("mode", ref.dashpots.achieved_ratio, {"units": "1", "long_name": "damping ratio the dashpots give the linearised reference"})
    ds["decay_fit_r2"] = ("mode", rows[:, 2], {"units": "1", "long_name": "R^2 of ln(peak) against cycle"})
    ds["decay_peaks"] = ("mode", rows[:, 3].astype(int), {"units": "1", "long_name": "peaks used"})
    return ds


@dataclass(frozen=True)
class DecayComparison:
    """Free decay of both models: fits, the ROM's modal period and damping, release
    [m], time [s], relative sway of the reference and the ROM [m], wall time [s]."""

    reference: identify.DecayFit
    rom: identify.DecayFit
    rom_period: float
    rom_zeta: float
    release_m: float
    time: np.ndarray
    sway_reference: np.ndarray
    sway_rom: np.ndarray
    wall_time: float

    def as_dict(self) -> dict:
        return {"release_m": self.release_m, "reference": self.reference.as_dict(),
                "rom": self.rom.as_dict(), "rom_modal_period_s": self.rom_period,
                "rom_modal_zeta": self.rom_zeta,
                "period_ratio_rom_to_reference": self.rom.period_undamped / self.reference.period_undamped,
                "zeta_ratio_rom_to_reference": self.rom.zeta / self.reference.zeta,
                "wall_time_s": self.wall_time}


def free_decay(ref, plant, *, release_m=0.54, cycles=12, dt=DT) -> DecayComparison:
    """Release both models from a sway offset on a still vessel (section 4.1; the
    study's release gave 0.54 m) and identify period and damping by log decrement. With a
    tugger on the reference the ROM carries it too (its linear damper on the still
    vessel's fairleads); ``rom_period`` and ``rom_zeta`` stay the plant's modal values."""
    w, z = _sway_mode(plant)
    duration = cycles * 2 * np.pi / w
    pose0 = statics.solve_pose(ref, ref.pose, fixed={1: ref.pose[1] + release_m})
    run = simulate.run(ref, exc_mod.still(dt, duration), pose=pose0)
    y_ref = run.relative()[:, 0]
    n = run.time.size
    c_t = ref.tugger.c if ref.tugger is not None else 0.0       # the ROM carries the same damper
    x = rom.simulate(plant, dt, np.zeros((n, 4)), x0=rom.condensed_release(plant, release_m),
                     c_tugger=c_t)
    return DecayComparison(reference=identify.log_decrement(run.time, y_ref),
                           rom=identify.log_decrement(run.time, x[:, 0]),
                           rom_period=2 * np.pi / w, rom_zeta=z, release_m=float(release_m),
                           time=run.time, sway_reference=y_ref, sway_rom=x[:, 0],
                           wall_time=run.wall_time)


def harmonic(ref, plant, periods_s=(12.0, 13.9, 17.0, 19.0), amplitudes_m=(0.05, 0.5), *,
             settle_cycles=6, fit_cycles=10, dt=DT) -> xr.Dataset:
    """Steady-state relative sway under a hinge sway y_b = A sin(w t) (section 4.2).

    Both models start in the ROM's steady state at the instant the sway velocity is
    zero, so little transient is left; the reference runs ``settle_cycles`` and its
    complex amplitude is fitted over the next ``fit_cycles`` together with its sway
    mode's decaying free oscillation. Returns amplitude ratio |y_rel / y_b| and phase
    [deg] of both, and the ROM's over the reference's amplitude, per (period, amplitude).
    """
    periods = np.atleast_1d(np.asarray(periods_s, float))
    amps = np.atleast_1d(np.asarray(amplitudes_m, float))
    c_t = ref.tugger.c if ref.tugger is not None else 0.0
    H = rom.transfer(plant, 2 * np.pi / periods, c_t)
    j_sway = ref.modes.index("sway")
    w_mode, z_mode = ref.modes.omega[j_sway], ref.dashpots.achieved_ratio[j_sway]
    shape = (periods.size, amps.size)
    ref_tf, wall = np.empty(shape, complex), np.empty(shape)
    for i, T in enumerate(periods):
        w = 2 * np.pi / T
        q_unit = H[i, :, 0] * (-1j)                     # response to sin(w t)
        phase0 = -np.angle(q_unit[0])                   # sway velocity zero at t = 0
        for k, A in enumerate(amps):
            q0 = q_unit * A * np.exp(1j * phase0)
            pose0 = ref.pose.copy()
            pose0[[1, 2, 3, 5]] += q0.real
            exc = exc_mod.harmonic_hinge(A, T, dt, (settle_cycles + fit_cycles) * T, phase=phase0)
            run = simulate.run(ref, exc, pose=pose0)
            sel = run.time >= settle_cycles * T - 1e-9
            t = run.time[sel]
            Y, _, _ = identify.harmonic_fit(t, run.relative()[sel, 0], w, mode_omega=w_mode, mode_zeta=z_mode)
            X, _, _ = identify.harmonic_fit(t, exc.data[sel, 0], w)
            ref_tf[i, k] = Y / X
            wall[i, k] = run.wall_time
    rom_tf = np.broadcast_to((H[:, 0, 0] - 1.0)[:, None], shape)
    ds = xr.Dataset(coords={"period": periods, "amplitude": amps})
    ds["period"].attrs.update(units="s", long_name="hinge sway period")
    ds["amplitude"].attrs.update(units="m", long_name="hinge sway amplitude")
    for name, tf, who in (("reference", ref_tf, "reference"), ("rom", rom_tf, "ROM")):
        ds[f"gain_{name}"] = (("period", "amplitude"), np.abs(tf), {"units": "1", "long_name": f"|y - y_b| / |y_b|, {who}"})
        ds[f"phase_{name}"] = (("period", "amplitude"), np.degrees(np.angle(tf)), {"units": "degree", "long_name": f"phase of y - y_b to y_b, {who}"})
    ds["gain_ratio"] = (("period", "amplitude"), np.abs(rom_tf) / np.abs(ref_tf), {"units": "1", "long_name": "ROM gain over the reference's"})
    ds["wall_time"] = (("period", "amplitude"), wall, {"units": "s", "long_name": "reference wall time"})
    return ds


def irregular_sea(ref, plant, motion, hs, tz, heading_deg, *, gamma=3.3, duration_s=3 * 3600.0,
                  transient=None, dt=DT, seed=1, kinematics="rigid", exposure_s=3 * 3600.0,
                  keep_records=False, frequency_domain=True, settle=None) -> dict:
    """Both models on the same vessel-motion record of one sea state (sections 4.4, 4.5).

    The record is jls's sea realisation (:func:`jls.verify.excitation.vessel_record`);
    the reference moves its tips rigidly with the six DOFs, the ROM takes the hinge by
    eq. 3.1 from the same record, both with the reference's tugger setting (the ROM's
    linear, the reference's with winch limits). Statistics after ``transient`` [s]
    (default: five time constants, :func:`transient_s` with the tugger). Returns per model sigma, Tz, MPM over
    ``exposure_s`` and the observed maximum of the relative sway [m], the sigma of
    the other relative motions, the ROM's against the reference's (r, R^2, RMS error),
    the ROM's frequency-domain sigma on the continuous spectrum, the reference's wire
    tension extremes and slack time, and wall times. ``frequency_domain=False`` leaves out
    the ROM's frequency-domain sigma (NaN; a caller that does not read it saves its
    0.1-0.15 s per record).

    ``settle`` [s]: None, the reference runs the whole record from rest as the ROM does;
    else it starts ``settle`` before the statistics (at most ``transient`` before) from
    the ROM's state at that instant (:func:`linear_start`), the ROM's record being the
    same: what is left to settle is the reference's own nonlinear difference from the
    ROM, not the whole start-up from rest (docs/verification.md, "The reference's
    start").
    """
    c_ref = ref.tugger.c if ref.tugger is not None else 0.0
    tr = transient_s(plant, c_tugger=c_ref) if transient is None else float(transient)
    exc = exc_mod.vessel_record(motion, hs, tz, heading_deg, gamma=gamma, duration_s=duration_s,
                                transient_s=tr, dt=dt, seed=seed, kinematics=kinematics)
    keep_all = exc.time >= -1e-9
    qb, y_f = exc.rom_input(ref.vessel_lever, ref.fairleads[0])
    c_t = ref.tugger.c if ref.tugger is not None else 0.0
    import time as _time
    t0 = _time.perf_counter()
    state = rom.simulate(plant, dt, qb, fairlead_sway=y_f, c_tugger=c_t)
    rom_wall = _time.perf_counter() - t0
    rel_rom = rom.relative(state, qb)[keep_all]
    if settle is None:
        run = simulate.run(ref, exc)
        keep = keep_all
    else:
        i0 = max(0, int(np.flatnonzero(keep_all)[0]) - int(round(float(settle) / dt)))
        pose0, vel0 = linear_start(ref, state[i0])
        part = exc_mod.Excitation(exc.kind, exc.data[i0:], exc.dt, t0=float(exc.time[i0]),
                                  kinematics=exc.kinematics)
        run = simulate.run(ref, part, pose=pose0, velocity=vel0)
        keep = keep_all[i0:]
    rel_ref = run.relative()[keep]
    out = {"hs_m": float(hs), "tz_s": float(tz), "heading_deg": float(heading_deg),
           "gamma": float(gamma), "duration_s": float(duration_s), "transient_s": tr,
           "dt_s": dt, "seed": seed, "kinematics": kinematics,
           "reference": identify.statistics(rel_ref[:, 0], dt, exposure_s),
           "rom": identify.statistics(rel_rom[:, 0], dt, exposure_s),
           "comparison": identify.compare(rel_rom[:, 0], rel_ref[:, 0]),
           "sigma_other_reference": dict(zip(("heave_m", "roll_deg", "yaw_deg"),
                                             _sig(rel_ref[:, 1:]))),
           "sigma_other_rom": dict(zip(("heave_m", "roll_deg", "yaw_deg"), _sig(rel_rom[:, 1:]))),
           "wire_tension_min_kN": float(run.tension[keep].min()),
           "wire_tension_max_kN": float(run.tension[keep].max()),
           "slack_fraction": float(np.mean(np.any(run.tension[keep] <= 0.0, axis=1))),
           "reference_wall_time_s": run.wall_time, "rom_wall_time_s": rom_wall}
    if ref.tugger is not None:
        tt = run.tugger_command[keep]
        out["tugger_limit_fraction"] = float(np.mean(np.any((tt >= ref.tugger.max_force) | (tt <= ref.tugger.min_force), axis=1)))
    out["rom_sigma_frequency_domain"] = (_fd_sigma(plant, motion, ref.tugger, hs, tz, heading_deg, gamma)
                                         if frequency_domain else float("nan"))
    out["sigma_ratio_rom_to_reference"] = out["rom"]["sigma"] / out["reference"]["sigma"]
    out["mpm_ratio_rom_to_reference"] = out["rom"]["mpm"] / out["reference"]["mpm"]
    if keep_records:
        out["records"] = {"time": exc.time[keep_all], "relative_reference": rel_ref, "relative_rom": rel_rom,
                          "tension": run.tension[keep], "pose_reference": run.pose[keep] - ref.pose}
    return out


def linear_start(ref, x):
    """The reference's pose (6,) and velocity (6,) in the ROM's state ``x`` = [q, q'] (8,):
    the static pose moved by the ROM's sway, heave, roll and yaw (small angles: the
    rotation rates as the angular velocity), surge and pitch at rest."""
    x = np.asarray(x, float)
    pose, vel = np.array(ref.pose, float), np.zeros(6)
    for k, dof in enumerate((1, 2, 3, 5)):
        pose[dof] += x[k]
        vel[dof] = x[4 + k]
    return pose, vel


def _sig(rel):
    s = rel.std(0)
    return [float(s[0]), float(np.degrees(s[1])), float(np.degrees(s[2]))]


def _fd_sigma(plant, motion, tugger, hs, tz, heading_deg, gamma):
    """The ROM's relative-sway sigma on the continuous spectrum (jls's frequency domain)."""
    from jls.timedomain.run import NO_TUGGER, frequency_domain_sigma
    return float(frequency_domain_sigma(plant, motion, [tugger or NO_TUGGER], hs, tz, heading_deg, gamma)[0])


def linear_range(ref, plant, motion, tz, heading_deg, *, hs_start, hs_step, hs_max, tolerance,
                 gamma=3.3, duration_s=1200.0, transient=None, dt=DT, seed=1,
                 kinematics="rigid", exposure_s=3 * 3600.0) -> dict:
    """The linear range measured: both models on one sea state's record (Tz, heading,
    seed fixed) with Hs stepped up from ``hs_start`` by ``hs_step`` until the ROM over the
    reference's relative-sway MPM leaves ``tolerance`` of 1 or Hs passes ``hs_max``.
    Returns the steps' Hs, sigma and MPM ratios and the reference's MPM [m], the last Hs
    inside (``hs_inside``, NaN if none) with the reference's MPM there, and the first
    outside (``hs_leaves``, NaN if none up to ``hs_max``)."""
    hs_list, sig, mpm, mref = [], [], [], []
    for hs in range_steps(hs_start, hs_step, hs_max):
        out = irregular_sea(ref, plant, motion, hs, tz, heading_deg, gamma=gamma, duration_s=duration_s,
                            transient=transient, dt=dt, seed=seed, kinematics=kinematics,
                            exposure_s=exposure_s)
        hs_list.append(hs)
        sig.append(out["sigma_ratio_rom_to_reference"])
        mpm.append(out["mpm_ratio_rom_to_reference"])
        mref.append(out["reference"]["mpm"])
        if abs(mpm[-1] - 1) > tolerance:
            break
    return range_summary(hs_list, sig, mpm, mref, tolerance)


def range_steps(hs_start, hs_step, hs_max) -> list[float]:
    """The Hs of :func:`linear_range`'s steps up to ``hs_max``, summed step by step as it
    does (so that a range run in parts steps through the same values)."""
    out, hs = [], float(hs_start)
    while hs <= hs_max + 1e-9:
        out.append(hs)
        hs += float(hs_step)
    return out


def range_summary(hs_list, sig, mpm, mref, tolerance) -> dict:
    """:func:`linear_range`'s answer from its steps (Hs, sigma and MPM ratios, the
    reference's MPM), the last of them outside ``tolerance`` if the range was left."""
    hs_list, mref = [float(h) for h in hs_list], [float(m) for m in mref]
    ratio = np.array(mpm, float)
    inside = np.flatnonzero(np.abs(ratio - 1) <= tolerance)
    left = np.abs(ratio[-1] - 1) > tolerance
    return {"hs": np.array(hs_list), "sigma_ratio": np.array(sig, float), "mpm_ratio": ratio,
            "mpm_reference": np.array(mref), "tolerance": float(tolerance),
            "hs_inside": float(hs_list[inside[-1]]) if inside.size else float("nan"),
            "mpm_reference_inside": float(mref[inside[-1]]) if inside.size else float("nan"),
            "hs_leaves": float(hs_list[-1]) if left else float("nan")}


def variance_share(ref, pose) -> np.ndarray:
    """Share of each reference mode in the variance of the jacket's sway (6,): the
    motion about the static pose ``pose`` (n, 6) split into the modes, x = sum phi_j
    eta_j with eta = Phi^T M6 x, and var(phi_yj eta_j) over their sum (the relative
    sway's modal part: the hinge's sway is no mode's)."""
    phi = ref.modes.shapes
    eta = np.asarray(pose, float) @ (ref.M6 @ phi)
    v = np.var(eta * phi[1], axis=0)
    total = float(v.sum())
    return v / total if total > 0 else np.full(6, np.nan)


__all__ = ["linear_start", "reference_modes", "held_tugger", "variance_share", "linear_range", "range_steps", "range_summary", "HELD_SLOPE", "free_decay", "DecayComparison", "harmonic", "irregular_sea",
           "transient_s", "DT"]
