"""Names of verification cells, ``candidate__tugger__h<heading>__hs<Hs>__tz<Tz>``: light
enough for the workflow to import when it is parsed (nothing of the reference loads)."""

from __future__ import annotations

from jls.errors import InputError

SEP = "__"


def cell_name(candidate, tugger, heading, hs, tz) -> str:
    """File stem of a verification cell, e.g. ``detuned__low__h90__hs1.25__tz7.5``."""
    return (f"{candidate}{SEP}{tugger}{SEP}h{float(heading):g}{SEP}hs{float(hs):g}"
            f"{SEP}tz{float(tz):g}")


def parse_cell(name: str) -> dict:
    """Inverse of :func:`cell_name`: candidate, tugger, heading, hs, tz."""
    parts = str(name).split(SEP)
    ok = len(parts) == 5 and parts[2].startswith("h") and parts[3].startswith("hs") \
        and parts[4].startswith("tz")
    try:
        values = (float(parts[2][1:]), float(parts[3][2:]), float(parts[4][2:])) if ok else None
    except ValueError:
        values = None
    if values is None:
        raise InputError("a verification cell is named candidate__tugger__h<heading>__hs<Hs>__tz<Tz>",
                         field="cell", value=name)
    return {"candidate": parts[0], "tugger": parts[1], "heading": values[0], "hs": values[1],
            "tz": values[2]}


#: how the reason of a combination's design corner (its workable cell of the highest
#: utilisation, :func:`jls.stages.verification_cell.stressed_cells`) begins
DESIGN_CORNER = "design corner: the workable cell of the highest utilisation"


def wire_cells(cells: list[dict]) -> list[dict]:
    """Per verified combination the cell of the wire check: its design corner (the
    workable cell of the highest utilisation) where it has one, else its first cell."""
    out = {}
    for c in cells:
        key = (c["candidate"], c["tugger"])
        corner = any(r.startswith(DESIGN_CORNER) for r in c.get("reasons", []))
        if key not in out or (corner and not out[key][1]):
            out[key] = (c, corner)
    return [c for c, _ in out.values()]


__all__ = ["wire_cells", "DESIGN_CORNER", "cell_name", "parse_cell", "SEP"]
