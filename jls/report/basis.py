"""What page 1 and the chapters "Operational basis" and "Voyage extremes" share: the
operational basis as ``workability.nc`` records it (DNV-ST-N001 class, reason, periods,
alpha), and the voyage's probability of staying inside every limit from ``voyage.nc``.

Every number comes from the datasets' attributes and variables; nothing here computes a
result of its own.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.assessment.operation import RESTRICTED, RESTRICTED_MAX_POP_H, RESTRICTED_MAX_REFERENCE_H
from jls.report.contract import LINEAR_ANGLE_DEG, LINEAR_SWAY_FACTOR
from jls.report.markup import t

__all__ = ["BEYOND_MODEL", "RESTRICTED", "RESTRICTED_MAX_POP_H", "RESTRICTED_MAX_REFERENCE_H", "Basis",
           "model_threshold", "operation_basis", "summary_sentence", "voyage_inside", "voyage_level"]

#: what a response level beyond the linear model's range is printed as (never its figure)
BEYOND_MODEL = "beyond the model"


def model_threshold(units: str, limit: float) -> float | None:
    """The level beyond which the linear model is out of its range (the validity
    chapter's thresholds: a relative motion in metres beyond LINEAR_SWAY_FACTOR x its
    limit, an angle beyond LINEAR_ANGLE_DEG); None for a utilisation (no threshold).
    ``units``: the level's UDUNITS string (m, degree, 1)."""
    u = str(units).strip()
    if u == "m":
        return LINEAR_SWAY_FACTOR * float(limit)
    if u in ("degree", "°"):
        return LINEAR_ANGLE_DEG
    return None


@dataclass(frozen=True)
class Basis:
    """The operational basis of ``workability.nc``: class, the reason (as the library
    states it), planned and reference periods [h], the contingency (None: not stated),
    the alpha table's source (None: alpha not applied) and whether OP_WF is stored."""

    operation_class: str
    reason: str
    planned_h: float
    reference_h: float
    contingency_h: float | None
    alpha_source: str | None
    has_opwf: bool

    @property
    def restricted(self) -> bool:
        return self.operation_class == RESTRICTED


def operation_basis(work: xr.Dataset) -> Basis | None:
    """The operational basis recorded in ``work``'s attributes; None when it has none."""
    a = work.attrs
    if "operation_class" not in a:
        return None
    cont = a.get("contingency_h")
    src = a.get("alpha_source")
    return Basis(str(a["operation_class"]), str(a.get("operation_reason", "")),
                 float(a.get("planned_period_h", np.nan)), float(a.get("reference_period_h", np.nan)),
                 None if cont is None else float(cont), None if src in (None, "") else str(src),
                 "hs_opwf" in work)


def voyage_inside(voyage: xr.Dataset | None, combo) -> float | None:
    """Probability that the option's voyage stays inside every limit,
    1 - ``exceedance_probability_any`` (a lower bound: the sum over criteria bounds the
    probability of exceeding any); None without a voyage dataset or the option."""
    if voyage is None or combo[0] not in voyage["candidate"].values \
            or combo[1] not in voyage["tugger"].values:
        return None
    return 1.0 - float(voyage["exceedance_probability_any"].sel(candidate=combo[0], tugger=combo[1]))


def voyage_level(voyage: xr.Dataset, combo, criterion: str, q: float) -> float:
    """The level the option's voyage maximum of ``criterion`` stays below with probability
    ``q`` (``voyage_level``), in the criterion's level units."""
    return float(voyage["voyage_level"].sel(candidate=combo[0], tugger=combo[1], criterion=criterion)
                 .sel(non_exceedance=q, method="nearest"))


def summary_sentence(cx) -> str:
    """Page 1: the operation class and what follows from it (markup, one paragraph)."""
    b = operation_basis(cx.work)
    if b is None:
        return ("*Operational basis:* the workability dataset does not record the operation class "
                f"(DNV-ST-N001); {cx.sec('operation')} says what that leaves open.\n")
    head = f"*Operational basis:* {t(b.operation_class)} operation (DNV-ST-N001; {t(b.reason)}). "
    if b.restricted:
        alpha = (f"OP_WF = α OP_LIM with α from {t(b.alpha_source)}" if b.has_opwf
                 else "alpha was not applied (no alpha table), so the table gives OP_LIM only")
        return (head + "It sails on a favourable forecast: the master's limiting-Hs table per Tz "
                f"and heading is in {cx.sec('operation')} ({alpha}).\n")
    return (head + "A voyage this long cannot rely on one forecast; it is designed on the route's "
            f"statistics, the voyage extremes ({cx.sec('voyage')}), and the workability above is "
            "a planning figure.\n")
