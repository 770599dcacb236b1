"""Plausibility checks that catch unit slips the schema's bounds cannot see.

Each check looks at one input as a whole (a configuration, a sea-state table, an RAO
dataset) and raises :class:`jls.errors.InputError` naming the file, the key and the value
with the likely slip: Hs in cm, Hs and Tz swapped, Tz in Hz, RAO frequencies given as
periods or in Hz, rotations in degrees, the hinge's height with the wrong sign, grids
that would take hours or exhaust the memory.
"""

from __future__ import annotations

import math

import numpy as np

from jls.errors import InputError

TZ_RANGE_S = (1.0, 25.0)
HS_MAX_M = 25.0
OMEGA_RANGE_RAD_S = (0.01, 10.0)
ROTATION_RAO_MAX = 0.5          # rad/m: above it the file is in degrees
BREAKING_STEEPNESS = 1.0 / 7.0  # Hs / L of the steepest possible sea
MAX_CANDIDATES = 20_000        # the response solves them in blocks of 64, memory bounded
SOLVER_BLOCK = 64
MAX_OPERABILITY_TZ = 2500
MAX_TRANSFER_VALUES = 50_000_000
G = 9.81


def check_config(cfg: dict, source="config") -> None:
    """Consistency of a schema-valid configuration: hinge height sign, grid sizes."""
    vessel = cfg.get("vessel", {})
    hinge = vessel.get("hinge_m")
    ref = vessel["rao_reference_point_m"] if hinge is not None else None
    if hinge is not None and not hinge[2] > ref[2]:
        raise InputError("the hinge must be above the RAO reference point "
                         f"(rao_reference_point_m z = {ref[2]:g} m; z up, the hinge sits on the "
                         "crane tops, far above the vessel's CoG and waterline); is the sign "
                         "of z flipped?", file=source, field="vessel.hinge_m[2]", value=hinge[2])
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


def check_sea_table(ds, file=None, field="scatter") -> None:
    """Hs and Tz of a scatter dataset within the plausible ranges, and no sea state
    steeper than breaking waves (the signature of Hs and Tz swapped)."""
    p = ds["probability"].values
    if p.ndim > 2:
        p = p.sum(axis=tuple(range(2, p.ndim)))
    used_hs = p.sum(axis=1) > 0
    used_tz = p.sum(axis=0) > 0
    tz = ds["tz"].values[used_tz]
    hs = ds["hs"].values[used_hs]
    lo, hi = TZ_RANGE_S
    bad = tz[(tz < lo) | (tz > hi)]
    if bad.size:
        raise InputError(f"Tz outside {lo:g}-{hi:g} s: periods in s expected (Hz, or Hs and Tz "
                         "swapped?)", file=file, field=f"{field}: tz", value=float(bad[0]))
    bad = hs[hs > HS_MAX_M]
    if bad.size:
        raise InputError(f"Hs above {HS_MAX_M:g} m: heights in m expected (cm, or Hs and Tz "
                         "swapped?)", file=file, field=f"{field}: hs", value=float(bad[0]))
    length = G * ds["tz"].values ** 2 / (2 * np.pi)
    steep = ds["hs"].values[:, None] / length[None, :] > BREAKING_STEEPNESS
    share = float((p * steep).sum())
    if share > 0.01:
        i, j = np.argwhere(steep & (p > 0))[0]
        raise InputError(f"{100 * share:.0f} % of the probability lies in sea states steeper "
                         "than breaking waves (Hs > L/7): are Hs and Tz swapped?", file=file,
                         field=f"{field}: hs {ds['hs'].values[i]:g} m, tz {ds['tz'].values[j]:g} s",
                         value=float(p[i, j]))


def check_rao(ds, file=None) -> None:
    """RAO frequencies within 0.01-10 rad/s and rotations plausible in rad/m."""
    omega = ds["omega"].values
    lo, hi = OMEGA_RANGE_RAD_S
    if omega[0] < lo or omega[-1] > hi:
        raise InputError(f"RAO frequencies {omega[0]:.4g}-{omega[-1]:.4g} rad/s lie outside "
                         f"{lo:g}-{hi:g} rad/s: periods or Hz given as rad/s?", file=file,
                         field="omega", value=float(omega[0] if omega[0] < lo else omega[-1]))
    amp = np.abs(ds["rao"].values[..., 3:])
    peak = amp.max(axis=(0, 1))
    k = int(np.argmax(peak))
    if peak[k] > ROTATION_RAO_MAX:
        name = ("roll", "pitch", "yaw")[k]
        raise InputError(f"{name} RAO peaks at {peak[k]:.3g} rad/m ({np.degrees(peak[k]):.3g} "
                         f"deg/m), more than {ROTATION_RAO_MAX} rad/m: the file looks like deg/m "
                         "(declare it: '# rotation_units: deg/m' in a CSV file, ULEN for WAMIT)",
                         file=file, field=f"rao[{name}]", value=float(peak[k]))
