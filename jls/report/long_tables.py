"""Tables that grow with the headings: the body of the report shows the governing
heading's rows (:func:`jls.report.context.governing_heading`) and says so; the appendix
(:mod:`jls.report.appendix`) shows them all. A table is long when it has more than
:data:`MAX_BODY_ROWS` rows."""

from __future__ import annotations

import numpy as np

from jls.report.context import Context
from jls.report.contract import complex_var, negligible, reference_amplitude
from jls.report.markup import num

MAX_BODY_ROWS = 16


def peak_rows(cx: Context, headings) -> list[list[str]]:
    """Peak RAO amplitude and its period of vessel roll and hinge sway, heave and yaw at
    each of ``headings`` (an amplitude at round-off level is reported as no motion)."""
    v = cx.vessel
    hinge, rao = complex_var(v, "hinge"), complex_var(v, "rao")
    period = 2 * np.pi / v["omega"].values
    rows = []
    for h in headings:
        for name, da, scale, unit in (("vessel roll", rao.sel(vessel_dof="roll"), 180 / np.pi, "deg/m"),
                                      ("hinge sway", hinge.sel(dof="sway"), 1.0, "m/m"),
                                      ("hinge heave", hinge.sel(dof="heave"), 1.0, "m/m"),
                                      ("hinge yaw", hinge.sel(dof="yaw"), 180 / np.pi, "deg/m")):
            amp = np.abs(da.sel(heading=h).values) * scale
            if negligible(amp, reference_amplitude(v, h, unit.startswith("deg")) * scale):
                rows.append([f"{h:g}°", name, f"no {name.split()[-1]} motion at this heading", "–"])
                continue
            k = int(np.nanargmax(amp))
            rows.append([f"{h:g}°", name, f"{amp[k]:.3g} {unit}", num(period[k], 2)])
    return rows


def is_long(rows) -> bool:
    return len(rows) > MAX_BODY_ROWS


__all__ = ["MAX_BODY_ROWS", "is_long", "peak_rows"]
