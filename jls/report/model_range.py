"""The linear model's range: whether a reported response level of a criterion for an
option lies beyond it, and why (:meth:`ModelRange.beyond`), for every place that prints
or draws a level (voyage levels, the design check, the exceedance curves, page 1).

A level is beyond the model when it passes the smallest of

* *the stated linear range*: a relative motion in metres beyond ``LINEAR_SWAY_FACTOR`` x
  its limit, an angle beyond ``LINEAR_ANGLE_DEG`` (:func:`jls.report.basis.model_threshold`);
* *the linear range the time domain measured* (relative sway only): the relative-sway MPM
  up to which the 6-DOF nonlinear reference stays within the verification's tolerance of
  the linear model, ``linear_range_mpm_inside_m`` of ``verification_study.nc``;
* *the linear range the time domain measured on the rigging* (relative sway only): the
  smallest linear relative-sway MPM of the rigging's verification cells (``verification/``)
  that ran and left the tolerance of the nonlinear reference (:func:`measured_cells`);
* *the clearance to the lift beams* is the relative-sway limit itself (the study's 3.0 m
  clearance budget): a level beyond it fails the criterion; ``side_lead_max_deg`` is a
  static rigging design limit (the study's table 5.1), not a dynamic clearance, and is not
  used as one (on the detuned rigging it would end the model's range at 0.6 m of sway,
  where its verification cells agree with the nonlinear reference at 2.3 m and 3.0 m);
* *a slack hoist wire* (the tension criteria, whose level is the governing wire's dynamic
  utilisation MPM / A with the allowance A): wire i goes slack when its dynamic MPM
  reaches its static tension T_s,i, i.e. at the utilisation T_s,i / A_i; the smallest
  over the wires is taken (with the floor f governing the allowance, 1 / (1 - f) for
  every wire). A level of any criterion computed where the option's tension level at the
  same point (the same quantile of the voyage, the same leg of the design check) lies
  beyond slack is beyond the model too: the linear model holds only with taut wires.

Every threshold comes from the datasets; nothing here computes a response.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from jls.names import MAX_TENSION_KN, MIN_TENSION_KN, SWAY_M, TENSION_SENSE, WIRE_TENSION_CRITERION
from jls.report.basis import model_threshold
from jls.report.contract import LINEAR_ANGLE_DEG, LINEAR_SWAY_FACTOR, criterion_label

SLACK = "a hoist wire goes slack"
MEASURED = "the linear range the time domain measured"
MEASURED_CELL = "the linear range the time domain measured on this rigging"
STATED_SWAY = f"the linear range stated, {LINEAR_SWAY_FACTOR:g} × the limit"
STATED_ANGLE = f"the linear range of the angles, {LINEAR_ANGLE_DEG:g}°"


@dataclass(frozen=True)
class Beyond:
    """Why a level is beyond the model: the threshold it passes (level units of the
    criterion, for slack the tension criterion's utilisation) and the reason."""

    threshold: float
    reason: str
    criterion: str


@dataclass(frozen=True)
class ModelRange:
    """The thresholds of the linear model's range per criterion (and candidate)."""

    units: dict                      # criterion -> level units (m, degree, 1)
    limits: dict                     # criterion -> limit on its level
    measured_sway_m: float | None = None
    slack_level: dict = field(default_factory=dict)        # (candidate, criterion) -> utilisation
    measured_cells_m: dict = field(default_factory=dict)   # candidate -> sway [m]

    def thresholds(self, c: str, candidate: str) -> list[Beyond]:
        """Every threshold of the level of ``c`` for the rigging ``candidate``."""
        out = []
        thr = model_threshold(self.units.get(c, ""), self.limits.get(c, np.nan))
        if thr is not None and np.isfinite(thr):
            out.append(Beyond(thr, STATED_ANGLE if self.units.get(c) in ("degree", "°") else STATED_SWAY, c))
        if c == SWAY_M:
            if self.measured_sway_m is not None and np.isfinite(self.measured_sway_m):
                out.append(Beyond(self.measured_sway_m, MEASURED, c))
            s = self.measured_cells_m.get(str(candidate))
            if s is not None and np.isfinite(s):
                out.append(Beyond(s, MEASURED_CELL, c))
        s = self.slack_level.get((str(candidate), c))
        if s is not None and np.isfinite(s):
            out.append(Beyond(s, SLACK, c))
        return out

    def threshold(self, c: str, candidate: str) -> Beyond | None:
        """The smallest threshold of ``c`` (the one that applies), None when it has none."""
        th = self.thresholds(c, candidate)
        return min(th, key=lambda b: b.threshold) if th else None

    def beyond(self, c: str, combo, x: float, levels: dict | None = None) -> Beyond | None:
        """Is the level ``x`` of criterion ``c`` for the option ``combo`` (candidate,
        tugger) beyond the linear model, and why: its own smallest threshold it passes,
        else a tension criterion of the same option whose level at the same point
        (``levels``: criterion -> level) lies beyond slack. None: inside the model."""
        cand = str(combo[0])
        own = [b for b in self.thresholds(c, cand) if x > b.threshold]
        if own:
            return min(own, key=lambda b: b.threshold)
        for k, y in (levels or {}).items():
            s = self.slack_level.get((cand, str(k)))
            if k != c and s is not None and np.isfinite(s) and y > s:
                return Beyond(s, SLACK, str(k))
        return None


def slack_levels(work: xr.Dataset | None, plant: xr.Dataset | None, criteria) -> dict:
    """(candidate, tension criterion) -> the utilisation at which a hoist wire goes slack,
    min_i T_s,i / A_i with the criterion's allowance A_i (see the module docstring)."""
    if work is None or plant is None or "tension" not in plant:
        return {}
    static = plant["tension"]
    out = {}
    for c in criteria:
        if (c not in TENSION_SENSE and c != WIRE_TENSION_CRITERION) or c not in work["limit"]["criterion"].values:
            continue
        lim = float(work["limit"].sel(criterion=c))
        if c == WIRE_TENSION_CRITERION:
            a = static * (1.0 - lim)
            lim_c = work["limit"].coords.get("tension_ceiling_kN")
            ceiling = float(lim_c.sel(criterion=c)) if lim_c is not None else np.nan
            if np.isfinite(ceiling):
                a = np.minimum(a, ceiling - static)
        elif c == MIN_TENSION_KN:
            a = static - lim
        else:                                   # MAX_TENSION_KN: the rise to the limit
            assert c == MAX_TENSION_KN
            a = lim - static
        ratio = (static / a.where(a > 0)).min("wire")
        for cand, r in zip(static["candidate"].values, np.atleast_1d(ratio.values)):
            out[(str(cand), c)] = float(r) if np.isfinite(r) else 0.0   # slack or failing at rest
    return out


def measured_cells(cells) -> dict:
    """candidate -> the smallest linear (ROM) relative-sway MPM [m] of its verification
    cells that ran and left the tolerance of the nonlinear reference: the time domain
    measured the linear range of that rigging to end at or below it. Riggings whose every
    cell stayed within tolerance have none."""
    out: dict = {}
    for ds in cells or []:
        if not {"verified", "within_tolerance", "mpm"} <= set(ds) or not bool(ds["verified"]) \
                or bool(ds["within_tolerance"]):
            continue
        cand = str(ds.attrs.get("candidate", ""))
        m = float(ds["mpm"].sel(model="rom")) if "model" in ds["mpm"].dims else float(ds["mpm"])
        if cand and np.isfinite(m):
            out[cand] = min(out.get(cand, np.inf), m)
    return out


def model_range(levels: xr.Dataset, *, work=None, plant=None, study=None, cells=None) -> ModelRange:
    """The model's range for a dataset of levels (``voyage.nc`` or ``voyage_plan.nc``: a
    ``limit`` per criterion with the coordinate ``level_units``); ``work``
    (``workability.nc``: the tension criteria's configured limits), ``plant``
    (``plant.nc``: static tensions, lead angles, drop height) and ``study``
    (``verification_study.nc``: the measured linear range) where available."""
    crit = [str(c) for c in levels["criterion"].values]
    units = ({c: str(levels["level_units"].sel(criterion=c).values) for c in crit}
             if "level_units" in levels.coords else {c: "" for c in crit})
    limits = {c: float(levels["limit"].sel(criterion=c)) for c in crit}
    measured = None
    if study is not None and "reason" not in study.attrs:
        m = float(study.attrs.get("linear_range_mpm_inside_m", np.nan))
        hs_out = float(study.attrs.get("linear_range_hs_leaves_m", np.nan))
        measured = m if np.isfinite(m) and np.isfinite(hs_out) else None
    return ModelRange(units, limits, measured, slack_levels(work, plant, crit),
                      measured_cells(cells))


def statement(rng: ModelRange, candidates) -> str:
    """What the model's range is, per rigging (plain text, one paragraph): the thresholds
    of the relative sway (which applies) and the tension level at which a wire goes slack."""
    parts = []
    for cand in (str(c) for c in candidates):
        bits = []
        if SWAY_M in rng.units:
            th = rng.thresholds(SWAY_M, cand)
            b = min(th, key=lambda x: x.threshold)
            short = {STATED_SWAY: "stated", MEASURED: "measured",
                     MEASURED_CELL: "measured on this rigging"}
            listed = ", ".join(f"{short.get(x.reason, x.reason)} {x.threshold:.1f} m" for x in th)
            bits.append(f"relative sway {b.threshold:.1f} m, set by {b.reason} ({listed})")
        for (c, k), s in sorted(rng.slack_level.items()):
            if c == cand:
                bits.append(f"{criterion_label(k)} level {s:.2f} (a hoist wire goes slack)")
        if bits:
            parts.append(f"{cand}: " + "; ".join(bits))
    return "; ".join(parts)


def of(cx, levels: xr.Dataset) -> ModelRange:
    """The model's range of the report's context ``cx`` for ``levels`` (cached per dataset)."""
    cache = cx.__dict__.setdefault("_model_range", {})
    key = id(levels)
    if key not in cache:
        cache[key] = model_range(levels, work=getattr(cx, "work", None), plant=getattr(cx, "plant", None),
                                 study=getattr(cx, "verification_study", None),
                                 cells=getattr(cx, "verification", None))
    return cache[key]


__all__ = ["MEASURED", "MEASURED_CELL", "measured_cells", "SLACK", "STATED_ANGLE", "STATED_SWAY", "Beyond", "ModelRange",
           "model_range", "of", "slack_levels", "statement"]
