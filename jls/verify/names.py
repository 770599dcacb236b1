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


#: the study comparison's parts (:func:`jls.verify.study.study_part`), each a job of its
#: own that runs beside the others: the study's sea states of table 4.4 in two groups,
#: and the linear range's steps in two (the first two, then the rest until the range is
#: left), two or three records each
STUDY_PARTS = {"table-1": ("V1", "V2", "V3"), "table-2": ("V4", "S1"), "range-1": (0, 2), "range-2": (2, None)}


__all__ = ["STUDY_PARTS", "wire_cells", "DESIGN_CORNER", "cell_name", "parse_cell", "SEP"]
