"""Per-leg statement of how the wave headings were obtained and how much sea-state energy
lies outside the RAO frequency range (shown in the sea-state chapter)."""

from __future__ import annotations

from jls.report.contract import on_sea_grid
from jls.report.markup import sci, table
from jls.report.sections import Context

HEADING_SOURCES = {
    "default": "not given: beam seas (90°) assumed",
    "given": "given as relative headings in the configuration",
    "course_directions": "derived from the course and the wave directions",
    "direction_table": "derived from the course and the leg's direction-resolved table",
}


def energy_outside_leg(cx: Context, leg: str) -> float | None:
    """Share of the wave energy outside the RAO range, weighted by the leg's Hs-Tz
    probabilities (``energy_outside`` per Tz of response.nc); None when absent."""
    if "energy_outside" not in cx.resp:
        return None
    e = on_sea_grid(cx.resp["energy_outside"], cx.sea)
    p = cx.sea["probability"].sel(leg=leg)
    total = float(p.sum())
    return float((p * e).sum() / total) if total > 0 else None


def headings_and_coverage(cx: Context) -> str:
    rows = []
    for leg in cx.legs:
        src = str(cx.sea.attrs.get(f"heading_source_{leg}", "not recorded"))
        e = energy_outside_leg(cx, leg)
        rows.append([leg, HEADING_SOURCES.get(src, src), "n/a" if e is None else sci(e, 2)])
    policy = str(cx.resp.attrs.get("outside_rao_range", ""))
    return table("How each leg's wave headings were obtained, and the share of the sea states' "
                 "wave energy outside the RAO frequency range, weighted by the leg's Hs-Tz "
                 "probabilities" + (f" ({policy})" if policy else "") + ".",
                 ["leg", "headings", "energy outside the RAO range"], rows,
                 align="(left, left, right)")


__all__ = ["HEADING_SOURCES", "energy_outside_leg", "headings_and_coverage"]
