"""Writers of a jls RAO dataset as the files engineers exchange: an OrcaFlex vessel type
(text data, YAML) and the RAO tables of an AQWA-LINE 2020 R1 listing.

Both are read back by :func:`jls.vessel.orcaflex.read_orcaflex_vessel_type` and
:func:`jls.vessel.aqwa.read_aqwa_lis` to the dataset written, to rounding (every number
is written with 17 significant digits), which is what the round-trip tests check. The
listing holds the RAO tables only (what the reader reads), under a banner saying jls
wrote it.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.io.atomic import write_atomically
from jls.vessel.orcaflex import COLUMNS
from jls.vessel.rao import validate_rao


def _num(x: float) -> str:
    return repr(float(x))


def orcaflex_text(ds: xr.Dataset, *, vessel_type: str, draught: str) -> str:
    """The dataset as an OrcaFlex text data file holding one vessel type and draught: its
    own conventions stated (frequency in rad/s, rotations in degrees per unit amplitude,
    phases lags in degrees on the crest at the RAO origin, OrcaFlex's axes)."""
    validate_rao(ds)
    rao = ds["rao"].transpose("omega", "wave_direction", "dof").values
    omega = ds["omega"].values
    ref = [float(v) for v in ds.attrs["reference_point_m"]]
    out = ["%YAML 1.1", "# Type: Model",
           f"# Written by jls (scripts/export_vessel.py) from {ds.attrs.get('source', '')}",
           "---", "General:", "  UnitsSystem: SI", "VesselTypes:",
           f"  - Name: {vessel_type}",
           "    RAOResponseUnits: degrees", "    RAOWaveUnit: amplitude",
           "    WavesReferredToBy: frequency (rad/s)", "    RAOPhaseConvention: lags",
           "    RAOPhaseUnitsConvention: degrees", "    RAOPhaseRelativeToConvention: crest",
           "    SurgePositive: forward", "    SwayPositive: port", "    HeavePositive: up",
           "    RollPositiveStarboard: down", "    PitchPositiveBow: down",
           "    YawPositiveBow: port", "    Symmetry: None", "    Draughts:",
           f"      - Name: {draught}", "        DisplacementRAOs:",
           f"          RAOOrigin: [{', '.join(_num(v) for v in ref)}]",
           "          PhaseOrigin: [~, ~, ~]", "          RAOs:"]
    scale = np.array([1.0, 1.0, 1.0] + [180.0 / np.pi] * 3)
    for j, beta in enumerate(np.degrees(ds["wave_direction"].values)):
        out.append(f"            - RAODirection: {_num(beta)}")
        out.append(f"              {', '.join(COLUMNS)}:")
        for i, w in enumerate(omega):
            z = rao[i, j]
            row = [w]
            for d in range(6):
                row += [abs(z[d]) * scale[d], -np.degrees(np.angle(z[d]))]
            out.append(f"                - [{', '.join(_num(v) for v in row)}]")
    return "\n".join(out) + "\n"


AQWA_HEADER = (" PERIOD   FREQ   DIRECTION          X                 Y                 Z"
               "                RX                RY                RZ")
AQWA_UNITS = (" (SECS)  (RAD/S) (DEGREES)" + "    AMP      PHASE" * 6)


def aqwa_text(ds: xr.Dataset) -> str:
    """The dataset as the RAO tables of an AQWA-LINE 2020 R1 listing ("R.A.O.S-VARIATION
    WITH WAVE DIRECTION": per period, one row per direction; rotations in degrees per
    metre, phases lags in degrees), with the structure's C.O.G. line (the reference point)
    and the water depth when the dataset states one."""
    validate_rao(ds)
    rao = ds["rao"].transpose("omega", "wave_direction", "dof").values
    omega = ds["omega"].values
    beta = np.degrees(ds["wave_direction"].values)
    ref = [float(v) for v in ds.attrs["reference_point_m"]]
    scale = np.array([1.0, 1.0, 1.0] + [180.0 / np.pi] * 3)
    out = [" " + "*" * 80,
           f" * RAO tables written by jls (scripts/export_vessel.py) from "
           f"{ds.attrs.get('source', '')}",
           " * in the layout of an AQWA-LINE 2020 R1 listing; not the output of an AQWA run.",
           " " + "*" * 80, "", " Aqwa-Line    - 2020 R1                64BIT VERSION 2020 R1", ""]
    depth = float(ds.attrs.get("water_depth_m", np.inf))
    if np.isfinite(depth):
        out.append(f"                                WATER  DEPTH  . . . . . . . . . . . . . "
                   f". . . . =  {_num(depth)}")
    out += ["                                ACCELERATION  DUE  TO GRAVITY . . . . . . . . "
            "=       9.807", "",
            f"                                STRUCTURE C.O.G.            GX=  {_num(ref[0])}"
            f"  GY=  {_num(ref[1])}  GZ=  {_num(ref[2])}", ""]
    title = "R.A.O.S-VARIATION WITH WAVE DIRECTION"
    for i in range(omega.size):                    # ascending frequency: longest period first
        out += ["1", "              * * * * H Y D R O D Y N A M I C   P A R A M E T E R S   "
                "F O R   S T R U C T U R E   1 * * * *", "",
                "                                          (WITH RESPECT TO STRUCTURE COG)", "",
                " " * 36 + title, " " * 36 + "-" * len(title), AQWA_HEADER,
                " ------   -----  --------- " + "-" * 107, AQWA_UNITS, " " + "-" * 133, ""]
        w = omega[i]
        for j, b in enumerate(beta):
            z = rao[i, j]
            cells = []
            for d in range(6):
                cells += [_num(abs(z[d]) * scale[d]), _num(-np.degrees(np.angle(z[d])))]
            lead = f"  {2 * np.pi / w:.16e}  {w:.16e}" if j == 0 else " " * 18
            out.append(f"{lead}  {_num(b)}  " + "  ".join(cells))
    return "\n".join(out) + "\n1\n"


def write_text(text: str, path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    return write_atomically(path, lambda tmp: Path(tmp).write_text(text), suffix=".tmp")
