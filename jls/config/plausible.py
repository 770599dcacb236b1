"""Plausibility checks that catch unit slips the schema's bounds cannot see.

Each check looks at one input as a whole (a configuration, a sea-state table, an RAO
dataset) and raises :class:`jls.errors.InputError` naming the file, the key and the value
with the likely slip: Hs in cm, Hs and Tz swapped, Tz in Hz, RAO frequencies given as
periods or in Hz, rotations in degrees, the hinge's height with the wrong sign, grids
that would take hours or exhaust the memory.
"""

from __future__ import annotations

import math

from jls.errors import InputError

MAX_CANDIDATES = 20_000        # the response solves them in blocks of 64, memory bounded
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
    w = vessel.get("bem", {}).get("omega_rad_s")
    if w is not None and not w["min"] < w["max"]:
        raise InputError("min must be below max", file=source, field="vessel.bem.omega_rad_s",
                         value=[w["min"], w["max"]])


def check_hinge_sign(vessel: dict, source="config") -> None:
    """The hinge above the RAO reference point (z up): a flipped sign is named as such."""
    hinge = vessel.get("hinge_m")
    ref = vessel["rao_reference_point_m"] if hinge is not None else None
    if hinge is not None and not hinge[2] > ref[2]:
        raise InputError("the hinge must be above the RAO reference point "
                         f"(rao_reference_point_m z = {ref[2]:g} m; z up, the hinge sits on the "
                         "crane tops, far above the vessel's CoG and waterline); is the sign "
                         "of z flipped?", file=source, field="vessel.hinge_m[2]", value=hinge[2])


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


