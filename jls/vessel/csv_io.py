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
programs that quote a phase lag declare ``# phase: lag`` (or the caller passes
``phase="lag"``); phases in radians declare ``# phase_units: rad``. When both polar and
re/im columns are given they must agree. Other declarations of units, conventions or
reference points are refused (jls would otherwise ignore them).
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_RAO_TEXT_BYTES, read_bytes
from jls.vessel.rao import DOFS, rao_from_records

_FREQ_COLUMNS = ("omega_rad_s", "period_s")


def read_rao_csv(path, *, rotation_units: str | None = None, phase: str | None = None,
                 reference_point=(0.0, 0.0, 0.0), rtol: float = 1e-3) -> xr.Dataset:
    """Read an RAO CSV file into the jls RAO dataset (InputError on any fault).

    The file's ``# key: value`` lines before the header are honoured or refused
    (:func:`_declarations`): ``rotation_units`` (rad/m, deg/m), ``phase`` (lead, lag),
    ``phase_units`` (deg, rad), ``translation_units`` (m/m); a caller's argument must agree
    with the file's declaration. Without ``phase_units``, phases that all lie within
    +-pi (and are not all small) are refused as radians in the ``phase_deg`` column."""
    path = Path(path)
    raw = read_bytes(path, "RAO file", MAX_RAO_TEXT_BYTES)
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"cannot read file: {exc}", file=path) from None
    declared = _declarations(text, path)
    rotation_units = _agree("rotation_units", rotation_units, declared, path) or "rad/m"
    phase = _agree("phase", phase, declared, path) or "lead"
    phase_units = declared.get("phase_units", (None, None))[1]
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
    records = {k: [] for k in ("freq", "beta", "dof", "value", "line", "phase")}
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
        if phase_units == "rad" and "phase_deg" in num:
            num["phase_deg"] = float(np.degrees(num["phase_deg"]))
        value = _value(num, cols, path, number, rtol)
        if cols["polar"]:
            records["phase"].append((num["phase_deg"], num["amplitude"], number))
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
    if cols["polar"] and not cols["cart"] and phase_units is None:
        _check_phase_units(records["phase"], path)
    freq = np.array(records["freq"], float)
    omega = 2 * np.pi / freq if freq_col == "period_s" else freq
    attrs = {"csv_rotation_units": rotation_units, "csv_phase": phase,
             "csv_phase_units": phase_units or "deg"}
    return rao_from_records(omega, records["beta"], records["dof"], records["value"],
                            records["line"], file=path, reference_point_m=reference_point,
                            source_format="csv", attrs=attrs, omega_label=freq_col)


#: declarations a CSV RAO file may make, and the values jls honours
_HONOURED = {"rotation_units": ("rad/m", "deg/m"), "phase": ("lead", "lag"),
             "phase_units": ("deg", "rad"), "translation_units": ("m/m",)}
#: words that make another declaration one jls would have to honour
_SEMANTIC = ("unit", "phase", "convention", "reference", "heading", "direction", "frequency",
             "period", "scale", "ulen", "length", "sign", "time")


def _declarations(text, path) -> dict:
    """``# key: value`` lines before the header: key -> (line, value). A declaration jls
    honours must have a value it reads; one stating a unit, phase, convention or reference
    jls does not read is refused; other keys (source, vessel, note) are descriptions."""
    found = {}
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            break
        m = re.match(r"#\s*([A-Za-z_]\w*)\s*:\s*(\S.*?)\s*$", stripped)
        if not m:
            continue
        key, value = m.group(1).lower(), m.group(2)
        if key in _HONOURED:
            if key in found:
                raise InputError(f"{key} given twice", file=path, field=f"line {number}",
                                 value=value)
            if value.lower() not in _HONOURED[key]:
                raise InputError(f"{key} must be " + " or ".join(f"'{v}'" for v in _HONOURED[key]),
                                 file=path, field=f"line {number}", value=value)
            found[key] = (number, value.lower())
        elif any(word in key for word in _SEMANTIC):
            raise InputError(f"the file declares '{key}', which jls does not read (it reads "
                             f"{', '.join(_HONOURED)}): convert the file and remove the line, or "
                             "state it in the configuration's vessel block", file=path,
                             field=f"line {number}", value=value)
    return found


def _agree(key, given, declared, path):
    """The caller's value of a declaration, the file's, or None; they must agree."""
    if key not in declared:
        return given
    line, value = declared[key]
    if given is not None and given != value:
        raise InputError(f"the file declares {key}: {value}, the caller {given}", file=path,
                         field=key, value=value)
    return value


#: phases within +-pi with at least one beyond this many degrees look like radians
_RADIAN_PHASE_MIN = 1.0


def _check_phase_units(phases, path) -> None:
    """Phases in degrees spread over +-180 deg across six motions, frequencies and headings;
    a file whose every phase of a moving dof lies within +-pi, not all near zero, holds
    radians in its phase_deg column."""
    if not phases:
        return
    peak = max(a for _, a, _ in phases)
    moving = [(ph, line) for ph, a, line in phases if a > 1e-3 * peak]
    if len(moving) < 12:
        return
    values = np.array([ph for ph, _ in moving])
    if np.all(np.abs(values) <= np.pi + 1e-9) and np.abs(values).max() > _RADIAN_PHASE_MIN:
        i = int(np.argmax(np.abs(values)))
        raise InputError(f"every phase lies within +-pi ({values.min():.3g} to {values.max():.3g}): "
                         "radians in the phase_deg column? Declare '# phase_units: rad' (or "
                         "'# phase_units: deg' if they are degrees)", file=path,
                         field=f"line {moving[i][1]}, phase_deg", value=float(values[i]))


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
