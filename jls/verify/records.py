"""The ROM driven by a user's own motion record, against a reference response record.

Record files are CSV: optional ``#`` comment lines, one header line of column names,
then one row of numbers per sample. Units are in the column names; rotations may be
given in degrees (``_deg``) or radians (``_rad``).

Motion record, one of two kinds (a column of the other kind, or any column not listed,
is an error):

* vessel: ``time_s`` and any of ``surge_m``, ``sway_m``, ``heave_m``, ``roll_deg``,
  ``pitch_deg``, ``yaw_deg`` (or ``_rad``): the vessel's motion at the point its motions
  refer to (the RAO reference point), x forward, y to port, z up; a DOF not given is
  zero (a measured record often has the rotations only, as the study's section 4.6);
* hinge: ``time_s`` and any of ``y_b_m``, ``z_b_m``, ``phi_b_deg``, ``psi_b_deg`` (or
  ``_rad``): the ROM's input q_b directly.

Response record: ``time_s`` and any of ``relative_sway_m``, ``relative_heave_m``,
``relative_roll_deg``, ``relative_yaw_deg`` (or ``_rad``): y - y_b etc. of the jacket.

Time must increase strictly; every value must be a finite number. A record sampled
unevenly (steps differing by more than 1e-6 of the median) is resampled linearly onto
its median step, and the result says so. Before the ROM sees it, each motion column is
high-pass filtered (section 4.6: 0.02 Hz, to remove the slow heading and offset drift;
a zero-phase fourth-order Butterworth filter, so the timing is kept); the ROM starts
from rest and the start-up transient (five sway time constants, section 4.6) is left
out of every statistic and comparison. A reference response record is filtered alike
and compared over the samples both records hold after the transient. A malformed file
stops with :class:`jls.errors.InputError` naming the file, the column and the value,
before anything is computed or written. Units m, s, rad inside.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.signal import butter, sosfiltfilt

from jls.errors import InputError

VESSEL = ("surge", "sway", "heave", "roll", "pitch", "yaw")
HINGE = ("y_b", "z_b", "phi_b", "psi_b")
RESPONSE = ("relative_sway", "relative_heave", "relative_roll", "relative_yaw")
ROTATIONS = {"roll", "pitch", "yaw", "phi_b", "psi_b", "relative_roll", "relative_yaw"}
MIN_ROWS = 10


@dataclass(frozen=True)
class MotionRecord:
    """A motion record: kind ('vessel' or 'hinge'), time (n,) [s] on a uniform step,
    data (n, 6 or 4) [m, rad] in the order of :data:`VESSEL` or :data:`HINGE`, the
    columns the file gave, the file, whether it was resampled."""

    kind: str
    time: np.ndarray
    data: np.ndarray
    columns: tuple
    file: str
    resampled: bool

    @property
    def dt(self) -> float:
        return float(self.time[1] - self.time[0])


@dataclass(frozen=True)
class ResponseRecord:
    """A response record: time (n,) [s], data (n, 4) [m, rad] in the order of
    :data:`RESPONSE` (NaN where the file has no column), the columns given, the file."""

    time: np.ndarray
    data: np.ndarray
    columns: tuple
    file: str
    resampled: bool


def _column(name: str, allowed, file):
    """(quantity, factor to m or rad) of a column name, or InputError."""
    for suffix, factor in (("_m", 1.0), ("_rad", 1.0), ("_deg", np.pi / 180.0)):
        if name.endswith(suffix):
            q = name[: -len(suffix)]
            if q in allowed and ((suffix == "_m") == (q not in ROTATIONS)):
                return q, factor
    units = ", ".join(f"{q}_{'deg|rad' if q in ROTATIONS else 'm'}" for q in allowed)
    raise InputError(f"unknown column (known: time_s, {units})", file=file, field=name, value=name)


def _read_table(path, what):
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"{what} not found", file=path) from None
    except UnicodeDecodeError:
        raise InputError(f"{what} is not UTF-8 text", file=path) from None
    lines = [(i + 1, ln) for i, ln in enumerate(text.splitlines())
             if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InputError(f"{what} is empty", file=path)
    header = [h.strip() for h in next(csv.reader([lines[0][1]]))]
    if "time_s" not in header:
        raise InputError("no time_s column", file=path, field="header", value=header)
    if len(set(header)) != len(header):
        dup = next(h for h in header if header.count(h) > 1)
        raise InputError("column given twice", file=path, field=dup, value=dup)
    rows = []
    for lineno, ln in lines[1:]:
        cells = next(csv.reader([ln]))
        if len(cells) != len(header):
            raise InputError(f"line {lineno} has {len(cells)} values for {len(header)} columns",
                             file=path, field=f"line {lineno}", value=ln)
        row = []
        for name, cell in zip(header, cells):
            try:
                v = float(cell)
            except ValueError:
                raise InputError(f"not a number on line {lineno}", file=path, field=name,
                                 value=cell.strip()) from None
            if not np.isfinite(v):
                raise InputError(f"not a finite number on line {lineno}", file=path, field=name,
                                 value=cell.strip())
            row.append(v)
        rows.append((lineno, row))
    if len(rows) < MIN_ROWS:
        raise InputError(f"{what} needs at least {MIN_ROWS} samples", file=path, value=len(rows))
    values = np.array([r for _, r in rows])
    t = values[:, header.index("time_s")]
    bad = np.flatnonzero(np.diff(t) <= 0)
    if bad.size:
        i = int(bad[0]) + 1
        raise InputError(f"time does not increase on line {rows[i][0]} "
                         f"({t[i - 1]:g} s before it)", file=path, field="time_s", value=float(t[i]))
    return path, header, t, values


def _uniform(t, values):
    """The samples on a uniform step (the median), linearly resampled if needed."""
    steps = np.diff(t)
    h = float(np.median(steps))
    if np.max(np.abs(steps - h)) <= 1e-6 * h:
        return t, values, False
    n = int(np.floor((t[-1] - t[0]) / h)) + 1
    tu = t[0] + h * np.arange(n)
    return tu, np.stack([np.interp(tu, t, v) for v in values.T], -1), True


def read_motion_record(path) -> MotionRecord:
    """Read a vessel or hinge motion record (module docstring)."""
    path, header, t, values = _read_table(path, "motion record")
    names = [h for h in header if h != "time_s"]
    if not names:
        raise InputError("no motion column", file=path, field="header", value=header)
    quantity = [n.rsplit("_", 1)[0] for n in names]
    for n, q in zip(names, quantity):
        if q not in VESSEL and q not in HINGE:
            _column(n, VESSEL + HINGE, path)                 # raises: unknown column
    kind = "hinge" if quantity[0] in HINGE else "vessel"
    allowed = VESSEL if kind == "vessel" else HINGE
    for n, q in zip(names, quantity):
        if q not in allowed:
            raise InputError(f"a {kind} record (from column {names[0]}) cannot have this column: "
                             "give the vessel's motion or the hinge's, not both", file=path,
                             field=n, value=n)
    data = np.zeros((t.size, len(allowed)))
    for n in names:
        q, f = _column(n, allowed, path)
        data[:, allowed.index(q)] = values[:, header.index(n)] * f
    tu, du, resampled = _uniform(t, data)
    return MotionRecord(kind=kind, time=tu, data=du, columns=tuple(names), file=str(path),
                        resampled=resampled)


def read_response_record(path) -> ResponseRecord:
    """Read a reference response record (module docstring)."""
    path, header, t, values = _read_table(path, "response record")
    names = [h for h in header if h != "time_s"]
    if not names:
        raise InputError("no response column", file=path, field="header", value=header)
    data = np.full((t.size, 4), np.nan)
    for n in names:
        q, f = _column(n, RESPONSE, path)
        data[:, RESPONSE.index(q)] = values[:, header.index(n)] * f
    tu, du, resampled = _uniform(t, data)
    return ResponseRecord(time=tu, data=du, columns=tuple(names), file=str(path), resampled=resampled)


def highpass(y, dt, cutoff_hz=0.02, order=4):
    """Zero-phase Butterworth high-pass of the columns of y (axis 0)."""
    if cutoff_hz is None or cutoff_hz <= 0:
        return np.asarray(y, float)
    nyq = 0.5 / dt
    if cutoff_hz >= nyq:
        raise InputError(f"high-pass cut-off {cutoff_hz:g} Hz is at or above the record's Nyquist "
                         f"frequency {nyq:g} Hz", field="highpass_hz", value=cutoff_hz)
    sos = butter(order, cutoff_hz / nyq, btype="highpass", output="sos")
    return sosfiltfilt(sos, np.asarray(y, float), axis=0)


def rom_from_record(plant, record: MotionRecord, response: ResponseRecord | None = None, *,
                    highpass_hz=0.02, transient=None, exposure_s=3 * 3600.0,
                    vessel_lever_m=(-215.263, 1.0, 99.998), fairlead_offset_m=(0.0, 37.5, -82.5),
                    c_tugger=0.0, filter_response=True) -> dict:
    """The ROM driven by a motion record, and compared with a response record if given.

    Returns the ROM's relative-sway statistics (sigma, Tz, MPM over ``exposure_s``) after
    the transient, those of the other relative motions, and with a response record its
    statistics and the ROM's agreement with it (r, R^2, RMS error; sway, and each other
    motion both records hold). ``transient`` [s] defaults to five sway time constants.
    """
    from jls.verify import identify, rom
    from jls.verify.chapter4 import transient_s
    from jls.verify.excitation import Excitation
    tr = transient_s(plant) if transient is None else float(transient)
    dt = record.dt
    if record.time[-1] - record.time[0] <= tr + 10 * dt:
        raise InputError(f"the record ({record.time[-1] - record.time[0]:g} s) is not longer than "
                         f"the start-up transient left out ({tr:g} s)", file=record.file,
                         field="time_s", value=float(record.time[-1]))
    data = highpass(record.data, dt, highpass_hz)
    exc = Excitation(record.kind, data, dt, t0=float(record.time[0]), kinematics="linear")
    qb, y_f = exc.rom_input(vessel_lever_m, fairlead_offset_m)
    state = rom.simulate(plant, dt, qb, fairlead_sway=y_f, c_tugger=c_tugger)
    rel = rom.relative(state, qb)
    keep = record.time >= record.time[0] + tr - 1e-9
    t = record.time[keep]
    out = {"file": record.file, "kind": record.kind, "columns": list(record.columns),
           "resampled": record.resampled, "dt_s": dt, "highpass_hz": highpass_hz,
           "transient_s": tr, "duration_s": float(t[-1] - t[0]),
           "rom": identify.statistics(rel[keep, 0], dt, exposure_s),
           "rom_sigma_other": {"heave_m": float(rel[keep, 1].std()),
                               "roll_deg": float(np.degrees(rel[keep, 2].std())),
                               "yaw_deg": float(np.degrees(rel[keep, 3].std()))}}
    if response is None:
        return out
    lo, hi = max(t[0], response.time[0]), min(t[-1], response.time[-1])
    win = (t >= lo - 1e-9) & (t <= hi + 1e-9)
    if np.count_nonzero(win) < MIN_ROWS:
        raise InputError("the response record does not overlap the motion record after the "
                         "transient", file=response.file, field="time_s",
                         value=[float(response.time[0]), float(response.time[-1])])
    resp = response.data
    if filter_response:
        resp = np.where(np.isnan(resp), np.nan,
                        highpass(np.nan_to_num(resp), float(response.time[1] - response.time[0]), highpass_hz))
    tw = t[win]
    given = {}
    for k, q in enumerate(RESPONSE):
        if np.all(np.isnan(resp[:, k])):
            continue
        ref_k = np.interp(tw, response.time, resp[:, k])
        given[q] = {"comparison": identify.compare(rel[keep][win, k], ref_k),
                    "reference": identify.statistics(ref_k, dt, exposure_s),
                    "rom": identify.statistics(rel[keep][win, k], dt, exposure_s)}
    out["response_file"] = response.file
    out["compared_s"] = [float(tw[0]), float(tw[-1])]
    out["against_response"] = given
    return out


__all__ = ["MotionRecord", "ResponseRecord", "read_motion_record", "read_response_record",
           "highpass", "rom_from_record", "VESSEL", "HINGE", "RESPONSE"]
