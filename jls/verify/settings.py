"""What a pipeline verification runs (:class:`Settings`, one cell's run) and which cells
it runs (:class:`Choice`), built from the configuration's ``verification`` block by
:func:`jls.config.builders.verification_settings_from_config` and
:func:`jls.config.builders.verification_choice_from_config`."""

from __future__ import annotations

from dataclasses import dataclass

#: the named combinations of ``verification.combinations``
RECOMMENDATION, BASELINE = "recommendation", "baseline"


@dataclass(frozen=True)
class Settings:
    """One cell's run: the irregular record's length ``duration_s`` [s] after the
    start-up transient of ``transient_time_constants`` ROM sway time constants; the
    verdict's ``tolerance``; the wave phases' ``seed``; the RK4 step ``dt`` [s] and
    ``kinematics`` of both models; the reference's ``pitch_inertia_t_m2`` (None: the
    roll inertia), ``wire_mass_t_per_m`` and ``segments``; the free decay's
    ``release_m``; the harmonic tests' ``harmonic_periods_s`` and
    ``harmonic_amplitude_m``; the kept relative-sway window ``trace_s`` [s]; the
    reference's start ``reference_start_time_constants`` ROM sway time constants before
    the statistics, in the ROM's state (None: from rest with the ROM)."""

    duration_s: float
    transient_time_constants: float
    tolerance: float
    seed: int
    dt: float
    kinematics: str
    pitch_inertia_t_m2: float | None
    wire_mass_t_per_m: float
    segments: int
    release_m: float
    harmonic_periods_s: tuple
    harmonic_amplitude_m: float
    trace_s: float
    reference_start_time_constants: float | None


@dataclass(frozen=True)
class Choice:
    """Which cells a route verifies: ``combinations`` (:data:`RECOMMENDATION`,
    :data:`BASELINE` or (candidate, tugger) pairs), per combination the
    ``boundary_cells`` live cells nearest the workability boundary and, when
    ``design_corner`` is (Hs [m], Tz [s], heading [deg]), that sea state; with
    ``stressed_cells`` the workable cell of the highest utilisation and the largest
    workable sea state of the heaviest leg; at most ``max_cells`` cells; nothing when
    not ``enabled``."""

    enabled: bool
    combinations: tuple
    boundary_cells: int
    design_corner: tuple | None
    max_cells: int
    stressed_cells: bool


__all__ = ["Settings", "Choice", "RECOMMENDATION", "BASELINE"]
