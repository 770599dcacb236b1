"""NDBC text files: the column layout shared by the spectral and standard meteorological
files, their times and their missing-value codes.

Layouts read (plain text, or gzip when the name ends in ``.gz``):

* **historical spectral** (``41010w2019.txt``; ``d``, ``i``, ``j``, ``k`` for alpha1,
  alpha2, r1, r2): a header ``#YY MM DD hh mm .0200 .0325 ...`` (older files ``YYYY MM DD
  hh`` without the minute, or ``YY``), then one row per record: the time and one value
  per frequency [Hz] named in the header;
* **real-time spectral** (``41010.data_spec``; ``.swdir``, ``.swdir2``, ``.swr1``,
  ``.swr2``): a header ending in ``>``; each row the time, in ``.data_spec`` the
  separation frequency, then pairs ``value (frequency)``; newest record first;
* **standard meteorological** (``41010h2019.txt``, real-time ``41010.txt``): a header
  naming the columns (``#YY MM DD hh mm WDIR ... WVHT DPD APD MWD ...``), an optional
  units row starting with ``#``, and one row per record.

Times are UTC. Records must be in strictly increasing or strictly decreasing time order
(real-time files run backwards and are reversed); anything else is an error naming the
line. Missing values are NDBC's 9-filled codes (99.00, 999, 999.0, 9999.0) or ``MM``;
what they mean is the caller's decision (a gap in standard meteorological files, an error
in spectra).
"""

from __future__ import annotations

import gzip
import hashlib
import io
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from jls.errors import InputError
from jls.io.files import MAX_TABLE_BYTES, read_bytes

__all__ = ["Table", "read_table", "is_fill", "FILL_CODES", "sibling", "stdmet_beside"]

#: NDBC's missing-value codes ("9 filled" fields), of which a column uses those of its width.
FILL_CODES = (99.0, 999.0, 9999.0)
_TIME_NAMES = ({"#yy", "yy", "yyyy", "#yyyy"}, {"mm"}, {"dd"}, {"hh"}, {"mm"})


@dataclass
class Table:
    """One NDBC text file as read: times (UTC, increasing), column names (frequencies [Hz]
    as text for spectral files), values (n_time, n_col; ``MM`` as NaN), the file's line
    number of each record (after any reversal), and provenance."""

    path: str
    times: pd.DatetimeIndex
    columns: list
    values: np.ndarray
    lines: np.ndarray
    sha256: str
    realtime: bool
    sep_freq: np.ndarray | None = None

    @property
    def name(self):
        return Path(self.path).name


def is_fill(v, codes=(999.0, 9999.0)):
    """True where v is one of the missing-value ``codes`` of its column (or NaN, i.e.
    ``MM``). NDBC fills a field with 9s to its width: 99.00 for a wave height or period,
    999 for a direction (where 99 is a valid value), 999.0 for a density or r1, r2."""
    v = np.asarray(v, float)
    return ~np.isfinite(v) | np.isin(np.round(v, 3), codes)


def _text(path, what):
    file = str(path)
    raw = read_bytes(path, what, MAX_TABLE_BYTES)      # a regular file of bounded size
    data = raw
    if file.endswith(".gz"):
        try:
            with gzip.GzipFile(fileobj=io.BytesIO(raw)) as fh:
                data = fh.read(MAX_TABLE_BYTES + 1)
        except (OSError, EOFError) as exc:
            raise InputError(f"not a readable gzip file ({exc})", file=file) from None
        if len(data) > MAX_TABLE_BYTES:
            raise InputError(f"decompresses to more than the {MAX_TABLE_BYTES >> 20} MB jls "
                             "reads; is it the right file?", file=file)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError("not a UTF-8 (ASCII) text file", file=file) from None
    return raw, text


def _number(s):
    try:
        return float(s)
    except ValueError:
        return None


def _n_time_columns(tokens):
    """How many leading header names are the time (4 or 5: with the minute)."""
    names = [t.lower() for t in tokens[:5]]
    n = 0
    for name, allowed in zip(names, _TIME_NAMES):
        if name not in allowed:
            break
        n += 1
    return n if n in (4, 5) else 0


def _times(file, rows, lines, n_time):
    a = np.array([r[:n_time] for r in rows], dtype=object)
    try:
        t = a.astype(float).astype(np.int64)
    except ValueError:
        bad = next(i for i, r in enumerate(rows) if any(_number(x) is None for x in r[:n_time]))
        raise InputError("unparsable time", file=file, field=f"line {lines[bad]}",
                         value=" ".join(rows[bad][:n_time])) from None
    year = np.where(t[:, 0] < 100, t[:, 0] + 1900, t[:, 0])
    parts = {"year": year, "month": t[:, 1], "day": t[:, 2], "hour": t[:, 3],
             "minute": t[:, 4] if n_time == 5 else 0}
    times = pd.to_datetime(pd.DataFrame(parts), errors="coerce", utc=True)
    nat = times.isna().to_numpy()
    if nat.any():
        k = int(np.flatnonzero(nat)[0])
        raise InputError("invalid date or time", file=file, field=f"line {lines[k]}",
                         value=" ".join(rows[k][:n_time]))
    return pd.DatetimeIndex(times)


def _floats(file, rows, lines, first, cols):
    """(n_row, len(cols)) floats from the row tokens at ``cols``; ``MM`` is NaN."""
    out = np.empty((len(rows), len(cols)))
    for i, r in enumerate(rows):
        for j, c in enumerate(cols):
            tok = r[c]
            if tok == "MM":
                out[i, j] = np.nan
                continue
            v = _number(tok)
            if v is None:
                raise InputError(f"unparsable number in column {first[j]}", file=file,
                                 field=f"line {lines[i]}", value=tok)
            out[i, j] = v
    return out


def read_table(path, what="NDBC file", *, spectral=False) -> Table:
    """Read an NDBC text file (layouts in the module docstring) into a :class:`Table`.

    ``spectral=True`` requires a frequency header (historical: the numbers after the time
    names; real-time: the ``(frequency)`` of each value, the same on every row). Errors
    name the file, the line and the text found.
    """
    file = str(path)
    raw, text = _text(path, what)
    numbered = [(i, ln.split()) for i, ln in enumerate(text.splitlines(), 1) if ln.strip()]
    if not numbered:
        raise InputError(f"empty {what}", file=file)
    hline, header = numbered[0]
    n_time = _n_time_columns(header)
    if not n_time:
        found = " ".join(header[:8])
        why = ("missing header: the first line must name the columns, starting "
               "'#YY MM DD hh [mm]'" + (" and then the frequencies" if spectral else ""))
        raise InputError(why, file=file, field=f"line {hline}", value=found)
    body = [(i, t) for i, t in numbered[1:] if not t[0].startswith("#")]
    if not body:
        raise InputError(f"{what} has no records", file=file)
    lines = np.array([i for i, _ in body])
    rows = [t for _, t in body]
    names = header[n_time:]
    realtime = bool(names) and (header[-1].endswith(">") or any(n.startswith("(") for n in names))
    sep = None
    if spectral and realtime:
        k0 = n_time + (1 if any(n.lower() == "sep_freq" for n in names) else 0)
        widths = {len(r) for r in rows}
        if len(widths) != 1 or (widths.pop() - k0) % 2:
            k = next(i for i, r in enumerate(rows) if len(r) != len(rows[0]) or (len(r) - k0) % 2)
            raise InputError("expected pairs 'value (frequency)' after the time, the same "
                             "number on every row", file=file, field=f"line {lines[k]}",
                             value=" ".join(rows[k][:k0 + 4]) + " ...")
        freq_text = rows[0][k0 + 1::2]
        for i, r in enumerate(rows):
            if r[k0 + 1::2] != freq_text:
                raise InputError("frequencies differ between records", file=file,
                                 field=f"line {lines[i]}", value=" ".join(r[k0 + 1:k0 + 7]))
        columns = [f.strip("()") for f in freq_text]
        if not columns or any(_number(c) is None for c in columns):
            raise InputError("missing frequency header: no '(frequency)' after the values",
                             file=file, field=f"line {lines[0]}", value=" ".join(rows[0][:k0 + 4]))
        cols = list(range(k0, len(rows[0]), 2))
        values = _floats(file, rows, lines, columns, cols)
        if k0 > n_time:
            sep = _floats(file, rows, lines, ["Sep_Freq"], [n_time])[:, 0]
    else:
        columns = names
        if spectral and (not columns or any(_number(c) is None for c in columns)):
            raise InputError("missing frequency header: the header must list the frequencies "
                             "[Hz] after the time names", file=file, field=f"line {hline}",
                             value=" ".join(header[:8]))
        bad = [i for i, r in enumerate(rows) if len(r) != n_time + len(columns)]
        if bad:
            k = bad[0]
            raise InputError(f"expected {n_time + len(columns)} fields as in the header, got "
                             f"{len(rows[k])} ({len(bad)} such lines)", file=file,
                             field=f"line {lines[k]}", value=" ".join(rows[k][:8]) + " ...")
        values = _floats(file, rows, lines, columns, list(range(n_time, n_time + len(columns))))
    times = _times(file, rows, lines, n_time)
    step = np.diff(times.asi8)
    if len(times) > 1 and (step < 0).all():
        order = slice(None, None, -1)
        times, values, lines = times[order], values[order], lines[order]
        sep = sep[order] if sep is not None else None
    elif (step <= 0).any():
        k = int(np.flatnonzero(step <= 0)[0]) + 1
        raise InputError("times not monotonic (a duplicate or out-of-order record)", file=file,
                         field=f"line {lines[k]}", value=times[k].isoformat())
    return Table(file, times, columns, values, lines, hashlib.sha256(raw).hexdigest(), realtime, sep)


def sibling(path, kind) -> Path | None:
    """The NDBC file of quantity ``kind`` ("d", "i", "j", "k": alpha1, alpha2, r1, r2)
    beside a spectral density file: historical ``<station>w<rest>`` -> ``<station><kind>
    <rest>``, real-time ``<station>.data_spec`` -> ``.swdir``, ``.swdir2``, ``.swr1``,
    ``.swr2``. None when the density file's name follows neither pattern. A historical
    direction file compressed differently from its density file (``.gz`` on one only) is
    found too."""
    p = Path(path)
    realtime = {"d": ".swdir", "i": ".swdir2", "j": ".swr1", "k": ".swr2"}
    if p.name.endswith(".data_spec"):
        return p.with_name(p.name[: -len(".data_spec")] + realtime[kind])
    m = re.match(r"^([A-Za-z0-9]{5})w(.+)$", p.name)
    if m:
        same = p.with_name(f"{m.group(1)}{kind}{m.group(2)}")
        # a density file compressed and its direction files not (or the other way round):
        # the file beside it under the other name is the one, when only that one exists
        other = same.with_name(same.name[:-3] if same.name.endswith(".gz") else same.name + ".gz")
        return other if not same.exists() and other.exists() else same
    return None


def stdmet_beside(path) -> Path | None:
    """The standard meteorological file of the same buoy and span beside a spectral
    density file, when it is there: historical ``<station>w<rest>`` -> ``<station>h<rest>``
    (either compression), real-time ``<station>.data_spec`` -> ``<station>.txt``."""
    p = Path(path)
    if p.name.endswith(".data_spec"):
        found = p.with_name(p.name[: -len(".data_spec")] + ".txt")
    else:
        found = sibling(p, "h")
    return found if found is not None and found.is_file() else None
