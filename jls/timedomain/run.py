"""Time-domain runs: one sea state and tugger setting per run, statistics per run, and
the per-cell dataset a pipeline rule writes.

A run starts from rest at t = -transient, discards the start-up transient (five sway time
constants 1 / (zeta w_n) of the plant by default) and keeps the record [0, duration).
Per run: sigma of the relative sway, its most probable maximum from sigma (N = duration
/ Tz, Tz from the record's variance and velocity variance) and from the counted zero
up-crossings, the observed maximum, the fraction of time a tugger line is at its capacity,
at its floor or at either, the winch power (mean and peak, positive when the winch pays
out under tension and absorbs energy), the extreme hoist-wire tensions, the number of
slack events (a wire going from taut to slack), the shortest tugger line and the fraction
of time a line is shorter than ``min_line_length`` (its jacket end in contact with, or
past, its fairlead).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import registry
from jls.names import RELATIVE_SWAY
from jls.threads import thread_map
from jls.timedomain import dynamics as dyn
from jls.timedomain.resolution import MIN_COMPONENTS_PER_BANDWIDTH, components_per_bandwidth
from jls.timedomain.sea import realise, repeat_period, synthesise
from jls.tugger.setting import Tugger
from jls.vessel.transfer import channel_transfer

NO_TUGGER = Tugger(name="none", c=0.0)


@dataclass(frozen=True)
class Settings:
    """Integration and sea-realisation settings (``timedomain`` in the configuration):
    amplitudes "rayleigh" or "deterministic" (:mod:`jls.timedomain.sea`); min_line_length
    [m], a tugger line shorter than it counts as in contact with its fairlead."""

    dt: float
    transient_time_constants: float
    transient_s: float | None
    repeat: str
    n_components: int | None
    seed: int
    amplitudes: str
    min_line_length: float


def sway_time_constant(plant) -> float:
    """1 / (zeta w_n) of the sway mode of the plant without tugger [s]."""
    i = int(plant.modes.mode_of("sway"))
    return float(1.0 / (plant.damping_ratio[i] * plant.modes.omega[i]))


def transient_duration(plant, settings: Settings) -> float:
    if settings.transient_s is not None:
        return float(settings.transient_s)
    return settings.transient_time_constants * sway_time_constant(plant)


def record_spacing(plant, settings: Settings, duration_s, omega_range) -> float:
    """Component spacing dw [rad/s] of the record a :class:`Case` of this duration realises
    (without realising it)."""
    duration = int(round(duration_s / settings.dt)) * settings.dt
    period = repeat_period(omega_range, settings.dt / 2, duration, transient_duration(plant, settings),
                           settings.repeat, settings.n_components)
    return 2 * np.pi / period


def fairlead_positions(offset_m) -> np.ndarray:
    """Port and starboard fairleads relative to the hinge from (0, half_span, -drop)."""
    off = np.asarray(offset_m, float)
    return np.array([[off[0], off[1], off[2]], [off[0], -off[1], off[2]]])


def parameters(plant, tugger: Tugger | None, fairlead_offset_m=(0.0, 37.5, -82.5),
               min_line_length=0.0) -> np.ndarray:
    """Compiled-plant parameters of a geometric plant (:func:`jls.plant.model.build`)."""
    if plant.layout is None or plant.unstretched_length is None:
        raise InputError("the time-domain model needs the wire geometry; a plant given as "
                         "matrices has none", field="plant_matrices")
    if np.ndim(plant.M) != 2:
        raise InputError("the time-domain model runs one rigging candidate at a time",
                         field="candidates")
    L = plant.layout
    return dyn.pack(L.anchors, L.padeyes, plant.wire_stiffness, plant.unstretched_length,
                    float(L.cog_depth), plant.m_grav * plant.g, plant.M, plant.C, tugger,
                    fairlead_positions(fairlead_offset_m), min_line_length)


def initial_state(plant, tugger: Tugger | None, q=None) -> np.ndarray:
    """At rest in the static position (q = 0), or at rest at the generalised coordinates q
    (e.g. :func:`jls.timedomain.equilibrium.held_equilibrium`); tugger lines at their
    pretension."""
    x = np.zeros(dyn.N_STATE)
    if q is not None:
        x[:4] = np.asarray(q, float)
    if tugger is not None and tugger.active:
        x[8:10] = tugger.pretension
    return x


def record_statistics(y, dt, duration_s) -> dict:
    """sigma, mean, Tz (spectral and up-crossing), MPMs and observed max of a record."""
    mean = float(np.mean(y))
    r = y - mean
    sigma = float(np.std(r))
    v = np.gradient(r, dt)
    sv = float(np.std(v))
    tz_spec = 2 * np.pi * sigma / sv if sv > 0 else np.nan
    n_up = int(np.count_nonzero((r[:-1] < 0) & (r[1:] >= 0)))
    n_spec = duration_s / tz_spec if np.isfinite(tz_spec) else 1.0
    return {"mean": mean, "sigma": sigma, "tz_spectral": tz_spec,
            "tz_upcrossing": duration_s / n_up if n_up else np.nan, "n_upcrossings": n_up,
            "mpm_sigma": sigma * np.sqrt(2 * np.log(max(n_spec, 1.0))),
            "mpm_upcrossing": sigma * np.sqrt(2 * np.log(max(n_up, 1))),
            "max_observed": float(np.max(np.abs(y)))}


def integrate_run(par, x0, exc, dt, n_steps, n_skip):
    """Run the compiled integrator; returns (record, raw statistics, wall time [s])."""
    record = np.empty((n_steps + 1, 2))
    stats = np.empty(len(dyn.STATS))
    dyn.integrate(x0, exc, dt, 0, 0, par, record, stats)     # load the compiled code first
    t = time.perf_counter()
    dyn.integrate(x0, exc, dt, n_steps, n_skip, par, record, stats)
    return record, stats, time.perf_counter() - t


def run_statistics(record, raw, dt, n_skip, duration_s) -> dict:
    s = dict(zip(dyn.STATS, raw))
    out = record_statistics(record[n_skip:, 0], dt, duration_s)
    n = max(s["n"], 1.0)
    out.update({
        "limit_fraction": s["n_at_limit"] / n, "at_max_fraction": s["n_at_max"] / n,
        "at_min_fraction": s["n_at_min"] / n,
        "power_mean": s["power_sum"] / n, "power_peak": max(s["power_max"], 0.0),
        "wire_tension_min": s["wire_t_min"], "wire_tension_max": s["wire_t_max"],
        "slack_events": int(s["slack_events"]), "slack_fraction": s["n_slack_steps"] / n,
        "line_tension_min": s["line_t_min"] if np.isfinite(s["line_t_min"]) else np.nan,
        "line_tension_max": s["line_t_max"] if np.isfinite(s["line_t_max"]) else np.nan,
        "line_length_min": s["line_length_min"] if np.isfinite(s["line_length_min"]) else np.nan,
        "line_contact_fraction": s["n_line_contact"] / n,
    })
    return out


class Case:
    """One sea state at one heading, realised once and run with any tugger setting."""

    def _steps(self, plant, settings: Settings, duration_s):
        """The plant, the settings and the record's steps: the transient discarded
        (``n_skip`` steps) and ``duration_s`` recorded, at the settings' step."""
        if not settings.dt > 0:
            raise InputError("time step must be positive", field="timedomain.dt_s", value=settings.dt)
        self.plant, self.settings = plant, settings
        self.transient = transient_duration(plant, settings)
        self.dt = settings.dt
        self.n_skip = int(round(self.transient / self.dt))
        self.n_steps = self.n_skip + int(round(duration_s / self.dt))
        self.duration = (self.n_steps - self.n_skip) * self.dt

    def __init__(self, plant, motion, hs, tz, heading_deg, *, gamma, duration_s,
                 settings: Settings, seed=None):
        self._steps(plant, settings, duration_s)
        om = motion["omega"].values
        self.realisation = realise(hs, tz, gamma, (om.min(), om.max()), self.dt / 2, self.duration,
                                   self.transient, settings.seed if seed is None else seed,
                                   settings.repeat, settings.n_components, settings.amplitudes)
        self.transfer = channel_transfer(motion, heading_deg, self.realisation.omega)
        self.exc = synthesise(self.realisation, self.transfer, -self.n_skip * self.dt, self.dt / 2,
                              2 * self.n_steps + 1)
        self.fairlead_offset = motion.attrs["fairlead_offset_m"]
        self.hs, self.tz, self.heading, self.gamma = float(hs), float(tz), float(heading_deg), gamma

    def run(self, tugger: Tugger | None = None, keep_record=False) -> dict:
        tugger = tugger or NO_TUGGER
        par = parameters(self.plant, tugger, self.fairlead_offset, self.settings.min_line_length)
        record, raw, wall = integrate_run(par, initial_state(self.plant, tugger), self.exc,
                                          self.dt, self.n_steps, self.n_skip)
        out = run_statistics(record, raw, self.dt, self.n_skip, self.duration)
        out["wall_time"] = wall
        if keep_record:
            out["time"] = (np.arange(self.n_steps + 1) - self.n_skip) * self.dt
            out[RELATIVE_SWAY] = record[:, 0]
        return out


def frequency_domain_sigma(plant, motion, tuggers, hs, tz, heading_deg, gamma=3.3,
                           omega_step=0.002) -> np.ndarray:
    """sigma of the relative sway per tugger from the linear model (no winch limits),
    over the RAO's frequency range, as :mod:`jls.stages.response` computes it."""
    from jls.tugger.loads import plant_loads
    ds = plant_loads(plant, motion, tuggers, [tz], [hs], heading_deg, gamma, omega_step=omega_step)
    return ds["sigma_relative_sway"].values[:, 0, 0]


def run_cells(plant, motion, tuggers, hs, tz, heading_deg, *, gamma, duration_s,
              settings: Settings, workers=1) -> xr.Dataset:
    """Time-domain statistics per (cell, tugger) for sea-state cells (hs[i], tz[i]).

    All tuggers of a cell share one wave record (seed: settings.seed and the cell index).
    Runs go to ``workers`` threads (the compiled integrator releases the GIL). Returns the
    dataset a pipeline rule writes, with the frequency-domain sigma alongside.
    """
    hs = np.atleast_1d(np.asarray(hs, float))
    tz = np.atleast_1d(np.asarray(tz, float))
    if hs.shape != tz.shape:
        raise InputError("hs and tz must pair up cell by cell", field="cells", value=(hs.size, tz.size))
    tuggers = list(tuggers)

    def one(i):
        case = Case(plant, motion, hs[i], tz[i], heading_deg, gamma=gamma, duration_s=duration_s,
                    settings=settings, seed=(settings.seed, i))
        return [case.run(t) for t in tuggers], case

    results = thread_map(one, range(hs.size), workers)
    keys = list(results[0][0][0])
    data = {k: np.array([[r[k] for r in res] for res, _ in results]) for k in keys}
    fd = np.array([frequency_domain_sigma(plant, motion, tuggers, hs[i], tz[i], heading_deg, gamma)
                   for i in range(hs.size)])
    case = results[0][1]
    return cells_dataset(data, fd, hs, tz, tuggers, heading_deg, case, gamma)




def cells_dataset(data, fd_sigma, hs, tz, tuggers, heading_deg, case: Case, gamma) -> xr.Dataset:
    ds = xr.Dataset(coords={"cell": np.arange(hs.size), "tugger": [t.name for t in tuggers]})
    ds = ds.assign_coords(hs=("cell", hs), tz=("cell", tz),
                          c_tugger=("tugger", [t.c for t in tuggers]),
                          max_force=("tugger", [t.max_force for t in tuggers]))
    for k, v in data.items():
        ds[k] = (("cell", "tugger"), v)
    ds["sigma_fd"] = (("cell", "tugger"), fd_sigma)
    registry.annotate(ds, "sea_states")          # the cells' hs and tz
    registry.annotate(ds, "timedomain_cell")     # everything else: one source of attributes
    s = case.settings
    ds.attrs.update(
        heading_deg=float(heading_deg), gamma=float(gamma), duration_s=case.duration,
        transient_s=case.transient, dt_s=case.dt, seed=int(s.seed),
        repeat_period_s=case.realisation.repeat_period,
        n_components=int(case.realisation.omega.size), amplitudes=s.amplitudes,
        components_per_bandwidth=components_per_bandwidth(case.plant, case.realisation.d_omega),
        min_components_per_bandwidth=MIN_COMPONENTS_PER_BANDWIDTH,
        min_line_length_m=float(s.min_line_length),
        integration="classical Runge-Kutta 4, fixed step, excitation sampled at half steps",
        model="nonlinear 4-DOF: exact wire geometry with slack, tugger saturation, Rayleigh damping")
    return ds


__all__ = ["Settings", "Case", "run_cells", "frequency_domain_sigma", "record_spacing",
           "parameters", "initial_state", "record_statistics", "transient_duration",
           "sway_time_constant", "NO_TUGGER"]
