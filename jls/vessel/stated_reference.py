"""What an RAO file states about itself checked against the configuration: the point its
RAOs refer to and the g it was computed with (Capytaine and jls NetCDF files).

A file that states the point its RAOs refer to (a Capytaine file's
``rotation_center``, or the ``reference_point_m`` of a file jls computed with Capytaine,
``source_format`` capytaine-bem), in the frame of its model with z = 0 at the still
waterline, states that point's height above the water; the
configuration states it too (``vessel.rao_reference_point_height_m``, or derived from
``rigging.limits.hinge_height_m``). :func:`check_stated_reference` refuses a disagreement
of more than :data:`REFERENCE_TOLERANCE_M`, naming both sources: the hinge's lever arm
from the reference point, and so its motion, would be wrong by the difference. A file's
``g`` (Capytaine) is compared with ``g_m_per_s2`` likewise.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jls.errors import InputError

#: The largest disagreement between the reference height stated by the file and by the
#: configuration [m].
REFERENCE_TOLERANCE_M = 0.05
#: The largest relative disagreement between a file's g and the configuration's.
G_TOLERANCE = 0.005


def stated_reference_height(rao) -> float | None:
    """The height above the still waterline of the point the file says its RAOs refer to,
    or None when the file does not state it."""
    fmt = str(rao.attrs.get("source_format", ""))
    source = str(rao.attrs.get("reference_point_source", ""))
    # stated: a Capytaine file's rotation_center, or a file jls computed with Capytaine
    # (vessel.bem, scripts/make_default_vessel.py: the hull's CoG in the mesh frame, z = 0
    # at the waterline). A reader's default origin (WAMIT, CSV, a file without
    # rotation_center) states nothing.
    if not (source.startswith("rotation_center") or fmt == "capytaine-bem"):
        return None
    if "reference_point_m" not in rao.attrs:
        return None
    return float(np.asarray(rao.attrs["reference_point_m"], float)[2])


def check_stated_reference(rao, vessel: dict, file=None, config_source: str = "config",
                           g: float | None = None, g_source: str = "config") -> None:
    """The file's stated reference point (height above the waterline) and g against the
    configuration's; InputError naming both sources."""
    name = Path(str(file)).name if file else "the RAO file"
    stated = stated_reference_height(rao)
    if stated is not None and "rao_reference_point_height_m" in vessel:
        conf = float(vessel["rao_reference_point_height_m"])
        if abs(stated - conf) > REFERENCE_TOLERANCE_M:
            where = ("rotation_center" if rao.attrs.get("reference_point_source", "").startswith(
                "rotation_center") else "reference_point_m")
            raise InputError(f"{name} states that its RAOs refer to a point at z = {stated:g} m "
                             f"({where}, in its model's frame: z = 0 at the waterline), and "
                             f"{config_source} puts the RAO reference point {conf:g} m above the "
                             f"waterline (vessel.rao_reference_point_height_m): the hinge's lever arm "
                             f"from it would be {abs(stated - conf):.2f} m off. Give the file's height, "
                             "or RAOs about the configured point (jls.vessel.transfer."
                             "shift_reference_point)", file=file,
                             field="vessel.rao_reference_point_height_m", value=conf)
    if g is not None and "capytaine_g" in rao.attrs:
        fg = float(rao.attrs["capytaine_g"])
        if abs(fg - g) > G_TOLERANCE * g:
            raise InputError(f"{name} was computed with g = {fg:g} m/s2 and {g_source} gives "
                             f"g_m_per_s2 = {g:g}: the wave numbers of the two disagree", file=file,
                             field="g_m_per_s2", value=g)


__all__ = ["check_stated_reference", "stated_reference_height", "REFERENCE_TOLERANCE_M"]
