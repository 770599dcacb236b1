"""Reader for WAMIT motion RAO files (``.4``, option 4 output).

Each line holds seven numbers::

    PER  BETA  I  |Xi|  phase  Re(Xi)  Im(Xi)

PER is the wave period in s (or the angular frequency in rad/s when WAMIT
ran with IPEROUT=2: pass ``abscissa="omega"``), BETA the wave heading in
degrees (direction of propagation relative to +x, the jls convention), I
the mode 1..6 (surge, sway, heave, roll, pitch, yaw) and phase in degrees.

WAMIT non-dimensionalises the RAOs with the length scale ULEN: translations
by the wave amplitude A (m/m, independent of ULEN), rotations by A/ULEN.
Rotations in rad/m are therefore the file values divided by ULEN (ULEN = 1
gives rad/m directly).

WAMIT's time convention is Re{Xi exp(+i omega t)} with the phase a lead on
the incident wave at the body-coordinate origin, which is the jls convention,
so values map directly. The reader checks that the Re/Im columns agree with
|Xi| and phase line by line, which pins the convention down.

The RAOs refer to the origin of the WAMIT body coordinate system (XBODY),
not necessarily the CoG: say where that origin is with ``reference_point``
and use :func:`jls.vessel.transfer.shift_reference_point` to move the
reference point to the CoG.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_RAO_TEXT_BYTES, read_bytes
from jls.vessel.rao import rao_from_records

#: WAMIT special periods: -1 zero frequency, 0 infinite frequency (no motion RAO).
_LIMIT_PERIODS = (-1.0, 0.0)


def read_wamit4(path, *, ulen: float = 1.0, abscissa: str = "period",
                reference_point=(0.0, 0.0, 0.0), rtol: float = 1e-3) -> xr.Dataset:
    """Read a WAMIT ``.4`` RAO file into the jls RAO dataset.

    ulen: WAMIT length scale ULEN in m (rotations are divided by it).
    abscissa: "period" (s, default) or "omega" (rad/s) for the first column.
    reference_point: position of the WAMIT body origin in the source model
        coordinates (stored as ``reference_point_m``).
    rtol: tolerance of the check Re + i Im == |Xi| exp(i phase).
    """
    path = Path(path)
    if not np.isfinite(ulen) or ulen <= 0:
        raise InputError("ULEN must be a positive length in m", file=path, field="ulen",
                         value=ulen)
    if abscissa not in ("period", "omega"):
        raise InputError("abscissa must be 'period' or 'omega'", file=path,
                         field="abscissa", value=abscissa)
    raw = read_bytes(path, "RAO file", MAX_RAO_TEXT_BYTES)      # a regular file, bounded
    try:
        text = raw.decode()
    except UnicodeDecodeError as exc:
        raise InputError(f"cannot read file: {exc}", file=path) from None

    rows, lines, skipped = [], [], 0
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        row = _parse_line(line, number, path)
        if abscissa == "period" and row[0] in _LIMIT_PERIODS:
            skipped += 1
            continue
        rows.append(row)
        lines.append(number)
    if not rows:
        raise InputError("no data lines", file=path)
    data = np.array(rows)
    lines = np.array(lines)
    first, beta, mode, amp, phase_deg, re, im = data.T

    def fail(message, column, index):
        raise InputError(message, file=path, field=f"line {lines[index]}, {column}",
                         value=float(data[index, _COLUMNS.index(column)]))

    bad = np.nonzero(first <= 0)[0]
    if bad.size:
        fail(f"{abscissa} must be positive", "period", bad[0])
    bad = np.nonzero((mode != np.round(mode)) | (mode < 1) | (mode > 6))[0]
    if bad.size:
        fail("dof (mode) must be an integer 1..6 (single body)", "dof", bad[0])
    bad = np.nonzero(amp < 0)[0]
    if bad.size:
        fail("negative |RAO|", "amplitude", bad[0])

    polar = amp * np.exp(1j * np.radians(phase_deg))
    cart = re + 1j * im
    scale = np.maximum(np.abs(polar), np.abs(cart))
    floor = 1e-6 * max(float(np.max(amp)), 1e-30)
    bad = np.nonzero(np.abs(polar - cart) > rtol * scale + floor)[0]
    if bad.size:
        i = bad[0]
        raise InputError("Re/Im columns disagree with |RAO| and phase", file=path,
                         field=f"line {lines[i]}",
                         value={"amplitude": amp[i], "phase_deg": phase_deg[i],
                                "re": re[i], "im": im[i]})

    dof = mode.astype(int) - 1
    values = cart.copy()
    values[dof >= 3] /= ulen
    omega = 2 * np.pi / first if abscissa == "period" else first
    attrs = {"wamit_ulen_m": float(ulen),
             "wamit_abscissa": abscissa,
             "wamit_limit_rows_skipped": int(skipped),
             "source_note": "WAMIT .4 motion RAOs; rotations divided by ULEN to rad/m"}
    return rao_from_records(omega, np.radians(beta), dof, values, lines, file=path,
                            reference_point_m=reference_point, source_format="wamit4",
                            attrs=attrs,
                            omega_label="period_s" if abscissa == "period" else "omega")


_COLUMNS = ("period", "heading", "dof", "amplitude", "phase", "re", "im")


def _parse_line(line: str, number: int, path: Path) -> list[float]:
    parts = line.split()
    if len(parts) != 7:
        raise InputError("expected 7 columns: period, heading, dof, |RAO|, phase, Re, Im",
                         file=path, field=f"line {number}", value=line.strip())
    values = []
    for column, part in zip(_COLUMNS, parts):
        try:
            value = float(part.replace("D", "E").replace("d", "e"))
        except ValueError:
            raise InputError("not a number", file=path, field=f"line {number}, {column}",
                             value=part) from None
        if not np.isfinite(value):
            raise InputError("non-finite value", file=path,
                             field=f"line {number}, {column}", value=part)
        values.append(value)
    return values
