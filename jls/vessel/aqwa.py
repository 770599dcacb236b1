"""Reader for the motion RAO tables of an ANSYS AQWA-LINE listing (``.LIS``).

Supported: the listing of AQWA-LINE 2020 R1 (the version line ``Aqwa-Line - 2020 R1``,
:data:`SUPPORTED_VERSIONS`) of one structure, whose displacement RAO tables
"R.A.O.S-VARIATION WITH WAVE DIRECTION" read, page after page::

    * * * * H Y D R O D Y N A M I C   P A R A M E T E R S   F O R   S T R U C T U R E   1 * * * *
                          (WITH RESPECT TO STRUCTURE COG)
                 R.A.O.S-VARIATION WITH WAVE DIRECTION
     PERIOD   FREQ   DIRECTION          X         Y         Z        RX        RY        RZ
     (SECS)  (RAD/S) (DEGREES)    AMP  PHASE  AMP PHASE  AMP PHASE  AMP PHASE  AMP PHASE  AMP PHASE
      157.08   0.040   -180.00   45.2109  -89.96 ...     (period, frequency on a period's
                          0.00   45.2109   89.96 ...      first row, one row per direction)

The same listing's "VARIATION WITH WAVE PERIOD/FREQUENCY" tables (the same numbers by
direction) and the ``VEL`` and ``ACC`` R.A.O.S tables are not read. Another version,
several structures, a header or unit line other than the above (a period column in
another unit), a row of another length, a period block whose first row lacks the period
(a missing direction shows as an incomplete grid) are refused with the line number. The
listing's ``WATER DEPTH`` becomes ``water_depth_m`` (the long-wave checks use it), the
structure's ``STRUCTURE C.O.G.`` the ``reference_point_m``; a gravity other than about
9.81 m/s^2 (a listing in feet) is refused.

Conversion to the jls convention (:mod:`jls.vessel.rao`):

* frame and reference point: the RAOs are the motions of the structure's centre of
  gravity along and about AQWA's axes X, Y, Z (surge, sway, heave, roll, pitch, yaw),
  taken as x forward, y to port, z up unless ``vessel.rao_conventions.x_axis: aft``
  (a model built with x aft: the RAOs are turned, :mod:`jls.vessel.conventions`);
* direction: AQWA's wave direction is the direction the waves travel, from the X axis
  anticlockwise seen from above (0 = travelling along +X): jls's, wrapped into
  [0, 360) deg (so a route's heading of 270 deg is the listing's -90); a direction listed
  twice (-180 and 180) is read once, from the first, and the other named in
  ``aqwa_directions_dropped``;
* abscissa: each row gives the period [s] and the frequency [rad/s], both rounded; omega
  is taken from the one with the smaller relative rounding error (the frequency when
  both are exact to 1e-12) and the two must agree within their rounding, else the row
  is refused; rows whose omega collide are refused as duplicates;
* amplitude: translations m/m; rotations in degrees per metre of wave amplitude, as AQWA
  prints them (x pi/180);
* phase: AQWA's phases are lags in degrees on the wave crest at the centre of gravity
  (x(t) = |R| A cos(wt - phase); checked on the real listing of the tests: surge in
  waves travelling along +X lags the crest by a quarter period, pitch leads it), so the
  RAO is conjugated. The configuration cannot restate them otherwise.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.files import MAX_RAO_TEXT_BYTES, read_bytes
from jls.vessel.conventions import resolve_conventions, to_jls
from jls.vessel.rao import rao_from_records

SUPPORTED_VERSIONS = ("2020 R1",)
RAO_TITLE = "R.A.O.S-VARIATION WITH WAVE DIRECTION"
HEADER = ["PERIOD", "FREQ", "DIRECTION", "X", "Y", "Z", "RX", "RY", "RZ"]
UNITS = ["(SECS)", "(RAD/S)", "(DEGREES)"] + ["AMP", "PHASE"] * 6
_VERSION = re.compile(r"^\s*Aqwa-Line\s+-\s+(\S+(?:\s+R\d+)?)", re.IGNORECASE)
_STRUCTURE = re.compile(r"F\s*O\s*R\s+S\s*T\s*R\s*U\s*C\s*T\s*U\s*R\s*E\s+(\d+)")
_NUMBER = r"([-+]?\d+(?:\.\d*)?(?:[EeDd][-+]?\d+)?)"
_DEPTH = re.compile(r"WATER\s+DEPTH[\s.]*=\s*" + _NUMBER)
_GRAVITY = re.compile(r"ACCELERATION\s+DUE\s+TO\s+GRAVITY[\s.]*=\s*" + _NUMBER)
_COG = re.compile(r"STRUCTURE C\.O\.G\.\s+GX=\s*" + _NUMBER + r"\s+GY=\s*" + _NUMBER
                  + r"\s+GZ=\s*" + _NUMBER)
EXACT = 1e-12                      # relative rounding below which a column is exact


def read_aqwa_lis(path, *, conventions: dict | None = None) -> xr.Dataset:
    """Read the displacement RAO tables of an AQWA-LINE listing into the jls layout.

    conventions: the configuration's ``vessel.rao_conventions`` (only ``x_axis`` can
    add to what AQWA fixes: phases are lags, directions where the waves travel).
    """
    path = Path(path)
    raw = read_bytes(path, "AQWA listing", MAX_RAO_TEXT_BYTES)
    lines = raw.decode("latin-1").splitlines()
    version, version_line = None, 0
    for n, line in enumerate(lines, start=1):
        m = _VERSION.match(line)
        if m:
            version, version_line = " ".join(m.group(1).split()), n
            break
    if version is None:
        raise InputError("no 'Aqwa-Line - <version>' line: not an AQWA-LINE listing", file=path,
                         field="version")
    if version not in SUPPORTED_VERSIONS:
        raise InputError(f"AQWA-LINE {version} listings are not read (supported: "
                         f"{list(SUPPORTED_VERSIONS)}; their RAO tables change between "
                         "versions)", file=path, field=f"line {version_line}", value=version)
    conv = resolve_conventions(
        {"phase": "lag", "phase_source": "AQWA prints phase lags",
         "direction": "to", "direction_source": "AQWA's direction is where the waves travel"},
        conventions, file=path)
    attrs = {"aqwa_version": version, "rao_conventions": "; ".join(f"{k}: {v}" for k, v in conv.items())}
    structures, cog, depth = set(), None, None
    for n, line in enumerate(lines, start=1):
        if "H Y D R O D Y N A M I C" in line:
            m = _STRUCTURE.search(line)
            if m:
                structures.add(int(m.group(1)))
        if depth is None and (m := _DEPTH.search(line)):
            depth = _float(m.group(1), path, n)
        if (m := _GRAVITY.search(line)) and not 9.7 <= _float(m.group(1), path, n) <= 9.9:
            raise InputError("the listing's gravity is not in m/s^2: only listings in metres "
                             "are read", file=path, field=f"line {n}", value=m.group(1))
        if cog is None and (m := _COG.search(line)):
            cog = [_float(v, path, n) for v in m.groups()]
    if len(structures) > 1:
        raise InputError("the listing holds several structures; jls reads one-structure "
                         "listings", file=path, field="structure", value=sorted(structures))
    if cog is None:
        raise InputError("no 'STRUCTURE C.O.G. GX= GY= GZ=' line: the point the RAOs refer "
                         "to is unknown", file=path, field="STRUCTURE C.O.G.")
    omega, beta, values, numbers = _tables(lines, path)
    wrapped = np.round(np.mod(beta, 360.0), 6)
    first = {}
    for b, w in zip(beta, wrapped):
        first.setdefault(w, b)
    keep = np.array([first[w] == b for b, w in zip(beta, wrapped)])
    if not keep.all():
        attrs["aqwa_directions_dropped"] = (
            "; ".join(sorted({f"{b:g} deg (the direction of {first[w]:g} deg, read from its rows)"
                              for b, w in zip(beta[~keep], wrapped[~keep])})))
    omega, values, numbers = omega[keep], values[keep], numbers[keep]
    beta = np.mod(beta[keep], 360.0)
    values, beta = to_jls(values, beta, conv)
    if depth is not None:
        attrs["water_depth_m"] = float(depth)
    n = omega.size
    return rao_from_records(np.repeat(omega, 6), np.radians(np.repeat(beta, 6)),
                            np.tile(np.arange(6), n), values.reshape(-1), np.repeat(numbers, 6),
                            file=path, reference_point_m=cog, source_format="aqwa_lis",
                            attrs=attrs, omega_label="period_s")


def _float(text, path, number):
    try:
        return float(text.replace("D", "E").replace("d", "e"))
    except ValueError:
        raise InputError("not a number", file=path, field=f"line {number}", value=text) from None


def _resolution(token: str) -> float:
    """Half the last printed digit of a number: the most its rounding can be off."""
    parts = re.split(r"[EeDd]", token)
    decimals = len(parts[0].split(".")[1]) if "." in parts[0] else 0
    return 0.5 * 10.0 ** ((int(parts[1]) if len(parts) > 1 else 0) - decimals)


def _omega(t_text, w_text, path, number):
    """omega [rad/s] from a row's rounded period and frequency (module docstring)."""
    t, w = _float(t_text, path, number), _float(w_text, path, number)
    if not (t > 0 and w > 0):
        raise InputError("period and frequency must be positive", file=path,
                         field=f"line {number}", value=(t_text, w_text))
    err_t, err_w = _resolution(t_text) / t, _resolution(w_text) / w
    if abs(2 * np.pi / t - w) > w * (err_t + err_w) * 1.001 + 1e-12 * w:
        raise InputError(f"the period {t_text} s and the frequency {w_text} rad/s disagree "
                         "beyond their rounding (a period column of another kind?)", file=path,
                         field=f"line {number}", value=(t_text, w_text))
    return w if err_w <= max(err_t, EXACT) else 2 * np.pi / t


def _tables(lines, path):
    """(omega, direction [deg], values (n, 6) as AQWA prints them in jls units: rotations
    in rad/m, phases still lags, line numbers) of every displacement RAO table."""
    rot = np.array([1.0, 1.0, 1.0] + [np.pi / 180.0] * 3)
    omega, beta, values, numbers = [], [], [], []
    titles = [n for n, line in enumerate(lines) if line.strip() == RAO_TITLE]
    if not titles:
        raise InputError(f"no '{RAO_TITLE}' table (a listing without motion RAOs?)", file=path,
                         field=RAO_TITLE)
    for t in titles:
        k = _header(lines, t + 1, path)
        w, started = None, False
        while k < len(lines):
            text = lines[k].strip()
            if not text or set(text) <= {"-"}:
                k += 1
                continue
            tokens = text.split()
            if text == "1" or len(tokens) not in (13, 15) or not _numeric(tokens):
                if started and (text == "1" or not _numeric(tokens[:1])):
                    break
                raise InputError("an RAO row must hold (period, frequency,) direction and 6 "
                                 "amplitude-phase pairs", file=path, field=f"line {k + 1}",
                                 value=text)
            if len(tokens) == 15:
                w = _omega(tokens[0], tokens[1], path, k + 1)
                tokens = tokens[2:]
            elif w is None:
                raise InputError("the first row of an RAO table must give the period and the "
                                 "frequency", file=path, field=f"line {k + 1}", value=text)
            started = True
            nums = np.array([_float(v, path, k + 1) for v in tokens])
            amp, phase = nums[1::2], nums[2::2]
            if not np.all(np.isfinite(nums)) or np.any(amp < 0) or abs(nums[0]) > 360.0:
                raise InputError("a direction within +-360 deg, amplitudes finite and >= 0 and "
                                 "phases finite expected", file=path, field=f"line {k + 1}",
                                 value=text)
            omega.append(w)
            beta.append(nums[0])
            values.append(amp * rot * np.exp(1j * np.radians(phase)))
            numbers.append(k + 1)
            k += 1
        if not started:
            raise InputError("an RAO table without rows", file=path, field=f"line {t + 1}")
    return np.array(omega), np.array(beta), np.array(values), np.array(numbers)


def _numeric(tokens) -> bool:
    return all(re.fullmatch(_NUMBER, t) for t in tokens)


def _header(lines, k, path):
    """The index of the first line after a table's header, which must read as
    :data:`HEADER` and :data:`UNITS` (a period column in another unit is refused)."""
    while k < len(lines) and set(lines[k].strip()) <= {"-"} and lines[k].strip():
        k += 1
    if k >= len(lines) or lines[k].split() != HEADER:
        raise InputError(f"the RAO table's header must read {' '.join(HEADER)}", file=path,
                         field=f"line {k + 1}", value=lines[k].strip() if k < len(lines) else "")
    k += 1
    while k < len(lines) and set(lines[k].strip()) <= {"-", " "} and lines[k].strip():
        k += 1
    if k >= len(lines) or lines[k].split() != UNITS:
        raise InputError(f"the RAO table's unit line must read {' '.join(UNITS)}", file=path,
                         field=f"line {k + 1}", value=lines[k].strip() if k < len(lines) else "")
    return k + 1
