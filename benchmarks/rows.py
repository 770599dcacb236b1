"""A benchmark result row and how its ratio is read, shared by the benchmark scripts.

A row is (figure, target, measured, ratio): ``ratio >= 1`` meets the target (target
over measured for a time or a memory limit, measured over target for a rate).
"""

from __future__ import annotations

from typing import NamedTuple


class Row(NamedTuple):
    figure: str
    target: str
    measured: str
    ratio: float


def within(figure: str, limit: float, measured: float, unit: str = "s") -> Row:
    """A figure that must stay under ``limit`` (a time or a memory)."""
    return Row(figure, f"< {limit:g} {unit}", f"{measured:.3g} {unit}",
               limit / measured if measured > 0 else float("inf"))


def at_least(figure: str, floor: float, measured: float, unit: str) -> Row:
    """A rate that must reach ``floor``."""
    return Row(figure, f">= {floor:g} {unit}", f"{measured:.3g} {unit}", measured / floor)
