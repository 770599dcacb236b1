"""Reader for the documented RAO CSV format (docs/vessel.md, "CSV RAO files").

One row per (frequency, heading, dof); lines starting with ``#`` and blank
lines are ignored; the first other line is the header. Columns (any order,
names case-insensitive)::

    omega_rad_s | period_s       exactly one of the two
    wave_direction_deg           direction of propagation, jls/WAMIT convention
    dof                          surge, sway, heave, roll, pitch, yaw
    amplitude, phase_deg         and/or
    re, im

Translations in m/m; rotations in rad/m, or deg/m when the file says so in a
comment line before the header, ``# rotation_units: deg/m`` (or the caller passes
``rotation_units="deg/m"``; the two must agree). Phase is a lead on the wave crest at the
reference point (``phase="lead"``, the jls/WAMIT convention); files from
programs that quote a phase lag pass ``phase="lag"``. When both polar and
re/im columns are given they must agree.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.vessel.rao import DOFS, rao_from_records

_FREQ_COLUMNS = ("omega_rad_s", "period_s")


def read_rao_csv(path, *, rotation_units: str | None = None, phase: str = "lead",
                 reference_point=(0.0, 0.0, 0.0), rtol: float = 1e-3) -> xr.Dataset:
    """Read an RAO CSV file into the jls RAO dataset (InputError on any fault)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read file: {exc}", file=path) from exc
    declared = _declared_rotation_units(text, path)
    if rotation_units is not None and declared is not None and rotation_units != declared:
        raise InputError(f"the file declares rotation_units: {declared}, the caller "
                         f"{rotation_units}", file=path, field="rotation_units", value=declared)
    rotation_units = rotation_units or declared or "rad/m"
    if rotation_units not in ("rad/m", "deg/m"):
        raise InputError("rotation_units must be 'rad/m' or 'deg/m'", file=path,
                         field="rotation_units", value=rotation_units)
    if phase not in ("lead", "lag"):
        raise InputError("phase must be 'lead' or 'lag'", file=path, field="phase",
                         value=phase)

    numbered = [(n, line) for n, line in enumerate(text.splitlines(), start=1)
                if line.strip() and not line.lstrip().startswith("#")]
    if not numbered:
        raise InputError("empty file: no header", file=path)
    header_line, header_text = numbered[0]
    header = [h.strip().lower() for h in next(csv.reader([header_text]))]
    cols = _check_header(header, path, header_line)

    freq_col = cols["freq"]
    records = {k: [] for k in ("freq", "beta", "dof", "value", "line")}
    for number, line in numbered[1:]:
        cells = [c.strip() for c in next(csv.reader([line]))]
        if len(cells) != len(header):
            raise InputError(f"expected {len(header)} columns", file=path,
                             field=f"line {number}", value=line)
        row = dict(zip(header, cells))
        dof_name = row["dof"].lower()
        if dof_name not in DOFS:
            raise InputError(f"unknown dof (one of {', '.join(DOFS)})", file=path,
                             field=f"line {number}, dof", value=row["dof"])
        num = {name: _number(row[name], path, number, name)
               for name in header if name != "dof"}
        if num[freq_col] <= 0:
            raise InputError("must be positive", file=path,
                             field=f"line {number}, {freq_col}", value=num[freq_col])
        value = _value(num, cols, path, number, rtol)
        if phase == "lag":
            value = np.conj(value)
        k = DOFS.index(dof_name)
        if k >= 3 and rotation_units == "deg/m":
            value = np.radians(1.0) * value
        records["freq"].append(num[freq_col])
        records["beta"].append(np.radians(num["wave_direction_deg"]))
        records["dof"].append(k)
        records["value"].append(value)
        records["line"].append(number)
    freq = np.array(records["freq"], float)
    omega = 2 * np.pi / freq if freq_col == "period_s" else freq
    attrs = {"csv_rotation_units": rotation_units, "csv_phase": phase}
    return rao_from_records(omega, records["beta"], records["dof"], records["value"],
                            records["line"], file=path, reference_point_m=reference_point,
                            source_format="csv", attrs=attrs, omega_label=freq_col)


def _declared_rotation_units(text, path):
    """The value of a '# rotation_units: ...' comment line before the header, if any."""
    found = None
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            break
        m = re.match(r"#\s*rotation_units\s*:\s*(\S+)\s*$", stripped, re.I)
        if m:
            if found is not None:
                raise InputError("rotation_units given twice", file=path,
                                 field=f"line {number}", value=m.group(1))
            found = m.group(1).lower()
            if found not in ("rad/m", "deg/m"):
                raise InputError("rotation_units must be 'rad/m' or 'deg/m'", file=path,
                                 field=f"line {number}", value=m.group(1))
    return found


def _check_header(header, path, line):
    known = set(_FREQ_COLUMNS) | {"wave_direction_deg", "dof", "amplitude", "phase_deg",
                                  "re", "im"}
    unknown = [h for h in header if h not in known]
    if unknown:
        raise InputError(f"unknown column(s); allowed: {sorted(known)}", file=path,
                         field=f"line {line}, header", value=unknown)
    if len(set(header)) != len(header):
        raise InputError("duplicate column in header", file=path, field=f"line {line}, header",
                         value=header)
    freq = [c for c in _FREQ_COLUMNS if c in header]
    if len(freq) != 1:
        raise InputError("give exactly one of omega_rad_s or period_s", file=path,
                         field=f"line {line}, header", value=header)
    for needed in ("wave_direction_deg", "dof"):
        if needed not in header:
            raise InputError(f"missing column {needed}", file=path,
                             field=f"line {line}, header", value=header)
    polar = {"amplitude", "phase_deg"} & set(header)
    cart = {"re", "im"} & set(header)
    if len(polar) == 1 or len(cart) == 1 or not (polar or cart):
        raise InputError("give amplitude and phase_deg, or re and im (or all four)",
                         file=path, field=f"line {line}, header", value=header)
    return {"freq": freq[0], "polar": bool(polar), "cart": bool(cart)}


def _number(text, path, line, column):
    try:
        value = float(text)
    except ValueError:
        raise InputError("not a number", file=path, field=f"line {line}, {column}",
                         value=text) from None
    if not np.isfinite(value):
        raise InputError("non-finite value", file=path, field=f"line {line}, {column}",
                         value=text)
    return value


def _value(num, cols, path, line, rtol):
    if cols["polar"]:
        amp = num["amplitude"]
        if amp < 0:
            raise InputError("negative amplitude", file=path, field=f"line {line}, amplitude",
                             value=amp)
        polar = amp * np.exp(1j * np.radians(num["phase_deg"]))
    if cols["cart"]:
        cart = num["re"] + 1j * num["im"]
        if cols["polar"] and abs(polar - cart) > rtol * max(abs(polar), abs(cart)) + 1e-12:
            raise InputError("re/im disagree with amplitude/phase_deg", file=path,
                             field=f"line {line}",
                             value={"amplitude": num["amplitude"],
                                    "phase_deg": num["phase_deg"], "re": num["re"],
                                    "im": num["im"]})
        return cart
    return polar
