"""Plausibility checks that catch unit slips the schema's bounds cannot see.

Each check looks at one input as a whole (a configuration, a sea-state table, an RAO
dataset) and raises :class:`jls.errors.InputError` naming the file, the key and the value
with the likely slip: Hs in cm, Hs and Tz swapped, Tz in Hz, RAO frequencies given as
periods or in Hz, rotations in degrees, the hinge's height with the wrong sign, grids
that would take hours or exhaust the memory.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from jls.errors import InputError
from jls.vessel.phase_checks import HEAVE_LONG_WAVE, LONG_WAVE_PERIOD_S

MAX_CANDIDATES = 20_000        # the response solves them in blocks of 64, memory bounded
MAX_SCREENING_CANDIDATES = 100_000   # four variables of 17 points; 10 000 screen in ~13 s
MAX_JOBS = 10_000                    # Snakemake builds a DAG of that size in seconds
SOLVER_BLOCK = 64
MAX_OPERABILITY_TZ = 2500
MAX_TRANSFER_VALUES = 50_000_000


def check_config(cfg: dict, source="config") -> None:
    """Consistency of a schema-valid configuration: hinge height sign, grid sizes."""
    vessel = cfg.get("vessel", {})
    check_hinge_sign(vessel, source)
    grid = cfg["assessment"]["operability_tz_s"]
    if not grid["min"] < grid["max"]:
        raise InputError("min must be below max", file=source,
                         field="assessment.operability_tz_s", value=[grid["min"], grid["max"]])
    n = math.floor((grid["max"] - grid["min"]) / grid["step"] + 1e-9) + 1
    if n > MAX_OPERABILITY_TZ:
        raise InputError(f"the grid has {n} Tz values, more than {MAX_OPERABILITY_TZ}; "
                         "take a larger step", file=source,
                         field="assessment.operability_tz_s.step", value=grid["step"])
    n_cand = candidate_count(cfg)
    if n_cand > MAX_CANDIDATES:
        raise InputError(f"{n_cand} rigging candidates, more than {MAX_CANDIDATES}; screen with "
                         "a coarser candidate_grid", file=source, field="candidate_grid",
                         value={k: len(v) for k, v in cfg.get("candidate_grid", {}).items()})
    scr = cfg["screening"]
    if scr["enabled"]:
        n_scr = screening_count(cfg)
        if n_scr > MAX_SCREENING_CANDIDATES:
            raise InputError(f"the screening grid makes {n_scr:.4g} candidates, more than "
                             f"{MAX_SCREENING_CANDIDATES}; take fewer grid points or free "
                             "variables", file=source, field="screening.grid_points",
                             value=dict(scr["grid_points"]))
    jobs = job_count(cfg)
    if jobs > MAX_JOBS:
        raise InputError(f"the run would hold about {jobs:.4g} jobs, more than {MAX_JOBS} (chunks "
                         "of the screening and the response, time-domain cells, per route): take "
                         "larger chunks (screening.chunk_candidates, response.chunk_candidates), "
                         "fewer cells or routes", file=source, field="response.chunk_candidates"
                         if cfg["response"].get("chunk_candidates") else "routes",
                         value=jobs)
    td = cfg["timedomain"]
    for route, spec in cfg["routes"].items():
        n = boundary_cell_count(cfg, len(spec["legs"]))
        if n > int(td["max_cells"]):
            raise InputError(f"route '{route}' would send up to {n} boundary cells to the time domain "
                             f"(legs x boundary candidates x boundary_cells_per_leg), more than "
                             f"timedomain.max_cells ({int(td['max_cells'])}): list the candidates "
                             "(timedomain.boundary_candidates) or raise max_cells", file=source,
                             field="timedomain.boundary_candidates", value=td["boundary_candidates"])
    w = vessel.get("bem", {}).get("omega_rad_s")
    if w is not None and not w["min"] < w["max"]:
        raise InputError("min must be below max", file=source, field="vessel.bem.omega_rad_s",
                         value=[w["min"], w["max"]])


def screening_count(cfg: dict) -> int:
    """Candidates of the rigging screening: the baseline and the grid."""
    return 1 + math.prod(int(v) for v in cfg["screening"]["grid_points"].values())


#: jobs a route's DAG holds besides its chunks and cells: sea states, vessel motion, plant
#: or screening, response, variants, time-domain choice, tugger studies, workability,
#: weather windows, report
FIXED_JOBS_PER_ROUTE = 10


def job_count(cfg: dict) -> int:
    """An upper estimate of the workflow's jobs, known before the DAG is built: per route
    the fixed jobs, the screening's and the response's chunks and the time-domain cells
    (the configured ones and the boundary cells; under winch_saturation 'timedomain' the
    most a route may send, timedomain.max_cells). ``cfg``: validated."""
    scr, td = cfg["screening"], cfg["timedomain"]
    n_cand = candidate_count(cfg) + (1 if scr["enabled"] else 0)
    chunk = cfg["response"].get("chunk_candidates")          # optional: one job for all
    response_chunks = -(-n_cand // int(chunk)) if chunk else 0
    screening_chunks = -(-screening_count(cfg) // int(scr["chunk_candidates"])) if scr["enabled"] else 0
    total = 0
    for spec in cfg["routes"].values():
        cells = len(td["cells"]) + boundary_cell_count(cfg, len(spec["legs"]))
        if cfg["assessment"]["winch_saturation"] == "timedomain":
            cells = int(td["max_cells"])
        total += FIXED_JOBS_PER_ROUTE + screening_chunks + response_chunks + min(cells, int(td["max_cells"]))
    return total


def check_hinge_sign(vessel: dict, source="config") -> None:
    """The hinge above the RAO reference point (z up): a flipped sign is named as such."""
    hinge = vessel.get("hinge_m")
    ref = vessel["rao_reference_point_m"] if hinge is not None else None
    if hinge is not None and not hinge[2] > ref[2]:
        raise InputError("the hinge must be above the RAO reference point "
                         f"(rao_reference_point_m z = {ref[2]:g} m; z up, the hinge sits on the "
                         "crane tops, far above the vessel's CoG and waterline); is the sign "
                         "of z flipped?", file=source, field="vessel.hinge_m[2]", value=hinge[2])


def boundary_cell_count(cfg: dict, n_legs: int) -> int:
    """The most boundary cells a route of ``n_legs`` legs sends to the time domain: per
    leg and boundary candidate (``timedomain.boundary_candidates``; ``assessed``: every
    assessed candidate, the screening's optimum included, but of a candidate grid only its
    ``grid_boundary_candidates`` best) ``boundary_cells_per_leg``."""
    from jls.config.builders import boundary_candidates, grid_boundary_count
    n = len(boundary_candidates(cfg)) + grid_boundary_count(cfg)
    return n_legs * n * int(cfg["timedomain"]["boundary_cells_per_leg"])


def candidate_count(cfg: dict) -> int:
    """Baseline, listed candidates and the full-factorial grid."""
    grid = cfg.get("candidate_grid") or {}
    return 1 + len(cfg.get("candidates", [])) + (math.prod(len(v) for v in grid.values())
                                                 if grid else 0)


def check_problem_size(cfg: dict, n_headings: int, omega_range, source="config") -> None:
    """The response arrays a route holds at once must fit in memory: the transfer functions
    of the candidates the report shows (baseline, named candidates, the optimum) and one
    solver block of the others, x tuggers x headings x responses x frequencies, at most
    :data:`MAX_TRANSFER_VALUES` complex values (grid candidates keep statistics only)."""
    step = cfg["response"]["omega_step_rad_s"]
    n_omega = int((omega_range[1] - omega_range[0]) / step) + 1
    n_tug = len(cfg["tuggers"])
    held = 2 + len(cfg.get("candidates", [])) + SOLVER_BLOCK
    n = held * n_tug * n_headings * 4 * n_omega
    if n > MAX_TRANSFER_VALUES:
        raise InputError(f"{held} candidates at once x {n_tug} tuggers x {n_headings} "
                         f"headings x {n_omega} frequencies make {n:.3g} transfer-function "
                         f"values, more than {MAX_TRANSFER_VALUES:.0e} (about "
                         f"{16 * MAX_TRANSFER_VALUES / 1e9:.1f} GB); take fewer candidates or "
                         "headings, or a larger step", file=source,
                         field="response.omega_step_rad_s", value=step)


# The long-wave regime (LONG_WAVE_PERIOD_S, HEAVE_LONG_WAVE: the longest period at which a
# hull follows the waves whatever its size, and the heave RAO there) is defined once, in
# jls.vessel.phase_checks, whose checks use it too.
TILT_RATIO = (1 / 3, 3.0)         # rotation RAO over the wave slope w^2/g at long periods
HEAD_SEAS_DEG = 20.0               # headings this close to 0 or 180 deg judge pitch alone


def check_rao_magnitudes(rao, vessel: dict, file=None, g: float = 9.81) -> list[str]:
    """The RAO's long-wave limit: in waves much longer than the hull, heave tends to 1 m/m
    and the hull tilts with the wave slope, the wave number k (w^2 / g in deep water, the
    dispersion relation at the file's ``water_depth_m`` when it states one). At the longest
    period T0 (lowest frequency w0):

    * T0 >= 25 s (waves of 975 m and more): the heave RAO (median over headings) must lie
      within 0.7-1.4 m/m, else the heave is in the wrong unit or column;
    * when the heave there is within those bounds (the long-wave regime is reached): the
      largest tilt sqrt(roll^2 + pitch^2) over the headings must be at least k / 3, and
      the pitch in head or following seas (within 20 deg) at most 3 k / |cos beta| (roll
      resonance may raise the tilt in beam seas, never lower it). A wrong WAMIT ULEN (or
      rotations in deg/m, or per a length) scales every rotation and shows here: the check
      catches a factor of 3 either way.

    Returns the warnings (the check could not be made: the file stops short of long
    waves); raises InputError naming ``vessel.wamit_ulen_m`` (WAMIT) or the file."""
    omega = np.asarray(rao["omega"].values, float)
    w0 = float(omega[0])
    t0 = 2 * np.pi / w0
    values = rao["rao"].transpose("omega", "wave_direction", "dof").values[0]
    beta = np.degrees(np.asarray(rao["wave_direction"].values, float))
    heave = float(np.median(np.abs(values[:, 2])))
    lo, hi = HEAVE_LONG_WAVE
    field = "vessel.wamit_ulen_m" if "wamit_ulen_m" in rao.attrs else "vessel.rao_file"
    if t0 >= LONG_WAVE_PERIOD_S and not lo <= heave <= hi:
        raise InputError(f"the heave RAO at the file's longest period, {t0:.3g} s, is {heave:.3g} m/m; "
                         f"in waves that long a hull rises and falls with the water (heave tends to "
                         f"1 m/m, {lo:g}-{hi:g} expected): heave in another unit, another column as "
                         "heave, or periods and frequencies mixed up?", file=file,
                         field="rao[heave]", value=round(heave, 6))
    if not lo <= heave <= hi:
        return [f"{Path(str(file)).name if file else 'RAO file'}: the RAO's longest period, "
                f"{t0:.3g} s, is too short for the long-wave checks of heave (-> 1 m/m) and of the "
                f"rotations against the wave slope (heave there {heave:.3g} m/m); the rotation "
                "units (WAMIT ULEN) were checked only against the 0.5 rad/m bound"]
    k = wavenumber(w0, float(rao.attrs.get("water_depth_m", np.inf)), g)
    tilt = np.hypot(np.abs(values[:, 3]), np.abs(values[:, 4])) / k
    ulen = rao.attrs.get("wamit_ulen_m")

    def slip(factor):
        if ulen is not None:
            return (f"with ULEN {ulen:g} m as declared in vessel.wamit_ulen_m; the file's own "
                    f"ULEN would be about {ulen * factor:.4g} m")
        return "rotations per a length scale, or in another unit?"

    tlo, thi = TILT_RATIO
    if tilt.max() < tlo:
        r = float(tilt.max())
        raise InputError(f"at the file's longest period, {t0:.3g} s, the hull tilts by at most "
                         f"{r:.3g} x the wave slope k = {k:.3g} rad/m; in long waves it tilts "
                         f"with the slope (about 1 x): every rotation too small by a factor "
                         f"{1 / r:.3g} ({slip(r)})", file=file, field=field,
                         value=ulen if ulen is not None else round(r, 6))
    ahead = np.abs(np.cos(np.radians(beta))) >= np.cos(np.radians(HEAD_SEAS_DEG))
    if ahead.any():
        pitch = np.abs(values[ahead, 4]) / (k * np.abs(np.cos(np.radians(beta[ahead]))))
        r = float(pitch.max())
        if r > thi:
            raise InputError(f"at the file's longest period, {t0:.3g} s, the pitch in head or "
                             f"following seas is {r:.3g} x the wave slope k = {k:.3g} rad/m; in "
                             f"long waves a hull pitches with the slope (about 1 x): rotations too "
                             f"large by a factor {r:.3g} ({slip(r)})",
                             file=file, field=field, value=ulen if ulen is not None else round(r, 6))
    return []


def wavenumber(omega: float, depth: float = np.inf, g: float = 9.81) -> float:
    """Wave number [rad/m] of the dispersion relation w^2 = g k tanh(k h) (deep water: w^2/g)."""
    k = omega ** 2 / g
    if not np.isfinite(depth):
        return k
    k = max(k, omega / np.sqrt(g * depth))
    for _ in range(50):                                   # Newton on f(k) = g k tanh(kh) - w^2
        t = np.tanh(k * depth)
        f = g * k * t - omega ** 2
        k_new = k - f / (g * t + g * k * depth * (1 - t * t))
        if abs(k_new - k) < 1e-12 * k:
            return float(k_new)
        k = k_new
    return float(k)
