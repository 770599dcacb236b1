"""Time-domain cells: their names, their seeds and the cells nearest the workability
boundary.

A cell is (rigging candidate, relative heading, Hs, Tz); its file stem is
``candidate__h<heading>__hs<Hs>__tz<Tz>`` and the seed of its wave record follows from
the configured seed and the cell itself, so a cell's numbers do not depend on which other
cells run.
"""

from __future__ import annotations

import zlib

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import SWAY_M

SEP = "__"


LEG = "leg-"


def cell_name(candidate, heading, hs, tz, leg=None) -> str:
    """File stem of a cell, e.g. ``baseline__h90__hs2.25__tz7.5``; a cell whose sea is its
    leg's own (``leg``: a leg of spectrum partitions, measured or torsethaugen,
    :mod:`jls.timedomain.cell_sea`) ends in ``__leg-<leg>``."""
    stem = f"{candidate}{SEP}h{float(heading):g}{SEP}hs{float(hs):g}{SEP}tz{float(tz):g}"
    return stem if leg is None else f"{stem}{SEP}{LEG}{leg}"


def parse_cell(name: str) -> dict:
    """Inverse of :func:`cell_name` (``leg`` only when the name carries one)."""
    parts = str(name).split(SEP, 4)
    if len(parts) not in (4, 5) or not (parts[1].startswith("h") and parts[2].startswith("hs")
                                        and parts[3].startswith("tz")) \
            or (len(parts) == 5 and not (parts[4].startswith(LEG) and len(parts[4]) > len(LEG))):
        raise InputError("a time-domain cell is named candidate__h<heading>__hs<Hs>__tz<Tz>[__leg-<leg>]",
                         field="cell", value=name)
    out = {"candidate": parts[0], "heading": float(parts[1][1:]), "hs": float(parts[2][2:]),
           "tz": float(parts[3][2:])}
    if len(parts) == 5:
        out["leg"] = parts[4][len(LEG):]
    return out


def boundary_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, candidates,
                   per_leg=1) -> list[dict]:
    """Per leg and candidate, the ``per_leg`` live cells whose relative-sway utilisation
    is nearest 1 (smallest |ln u| over the tugger settings)."""
    if per_leg <= 0 or SWAY_M not in work["criterion"].values:
        return []
    u = work["utilisation"].sel(criterion=SWAY_M, drop=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        dist = np.abs(np.log(u)).min("tugger")
    live = sea["cell_probability"] > 0
    out = []
    for cand in candidates:
        if cand not in work["candidate"].values:
            continue
        for leg in work["leg"].values:
            d = dist.sel(candidate=cand, leg=leg).where(live.sel(leg=leg)).transpose("heading", "hs", "tz")
            flat = d.values.ravel()
            order = [i for i in np.argsort(np.where(np.isfinite(flat), flat, np.inf), kind="stable")
                     if np.isfinite(flat[i])][:per_leg]
            for i in order:
                ih, ihs, itz = np.unravel_index(i, d.shape)
                out.append({"candidate": str(cand), "heading": float(d["heading"].values[ih]),
                            "hs": float(hs.sel(leg=leg).values[ihs]), "tz": float(d["tz"].values[itz]),
                            "leg": str(leg), "reason": f"nearest the workability boundary, leg {leg}"})
    return out


def cell_seed(seed: int, cell: dict) -> tuple:
    """Seed of a cell's wave record: the configured seed and a checksum of the cell."""
    return (int(seed), zlib.crc32(cell_name(cell["candidate"], cell["heading"], cell["hs"],
                                            cell["tz"], cell.get("leg")).encode()))


