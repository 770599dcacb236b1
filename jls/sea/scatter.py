"""Hs-Tz(-direction) scatter tables: reader, writer and the common Dataset layout.

Dataset layout (units in every variable's attrs):

* dims ``("hs", "tz")`` or ``("hs", "tz", "direction")``
* coords ``hs`` [m], ``tz`` [s] (bin centres), ``hs_lower``/``hs_upper`` (dim hs, m),
  ``tz_lower``/``tz_upper`` (dim tz, s), ``direction`` [deg] if present
* ``probability`` [1] sums to 1; ``count`` [1] (int64) only when the source held counts;
  ``steep`` (bool, dims hs, tz): cell centre above the study's steepness ceiling
  (flagged, never dropped; see :mod:`jls.sea.steepness`)
* attrs: ``source`` (file name), ``sha256`` (of the file), ``total`` (sum of the raw
  values as read), ``values_kind`` ("counts" / "probability"), ``layout``, ``hs_bins``,
  ``tz_bins``, the steepness summary, and any other ``# key: value`` header lines.

File layouts (comma separated; ``#`` lines before the data are ``key: value`` header lines;
see docs/sea.md):

* ``matrix``: first row = Tz bin labels (first cell is a free corner label), first
  column = Hs bin labels, cells = values.  Header keys ``hs_bins``, ``tz_bins``
  (``centres`` | ``edges``) and ``values`` (``counts`` | ``probability``) are required.
* ``long``: a column-name row ``hs,tz[,direction],probability`` (or ``count``), one row
  per cell; missing cells are zero.  Header keys ``hs_bins`` and ``tz_bins`` required.

Bin labels: ``edges`` labels are ``lower-upper`` (e.g. ``0.5-1.0``), lower inclusive;
bins must not overlap (gaps are allowed).  ``centres`` labels are numbers; edges are the
midpoints between neighbouring centres and the end bins are mirrored (first lower edge =
c0 - (c1 - c0)/2, clipped at 0), so at least two bins are needed.
"""

from __future__ import annotations

import csv
import gzip
import hashlib
import math
import re
from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import registry
from jls.io.files import MAX_TABLE_BYTES, read_bytes
from jls.sea.steepness import flag_steep
from jls.sea.table_metadata import check_corner, check_header_keys, check_stated_totals, table_warnings

__all__ = ["read_scatter", "write_scatter", "scatter_dataset"]

#: the bin centres and edges are the sea-state dataset's quantities: their attributes are
#: the registry's (``sea_states``); the table's own variables have these (a directional
#: table's probability is joint over direction, unlike the sea-state dataset's)
REGISTERED = ("hs", "tz", "hs_lower", "hs_upper", "tz_lower", "tz_upper")
OWN_ATTRS = {
    "direction": {"units": "deg", "long_name": "wave direction, sector centre (convention of the source)"},
    "probability": {"units": "1", "long_name": "probability of occurrence (sums to 1)"},
    "count": {"units": "1", "long_name": "number of occurrences"},
}
_RESERVED = {"source", "sha256", "total", "values_kind", "layout", "hs_bins", "tz_bins", "values", "warnings",
             "steepness_rule", "steep_cells_with_data", "steep_probability"}
_NUM = r"(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)"
_EDGE_RE = re.compile(rf"^\s*{_NUM}\s*-\s*{_NUM}\s*$")
_KINDS = {"centres": "centres", "centers": "centres", "edges": "edges"}
_VALUES = {"counts": "counts", "count": "counts", "probability": "probability"}


def _fmt(x: float) -> str:
    """Short decimal text for a bin edge (at least one decimal)."""
    s = f"{x:.6f}".rstrip("0")
    return s + "0" if s.endswith(".") else s


def _number(text, file, where, *, what="value"):
    """Parse one finite, non-negative number or raise InputError at `where`."""
    try:
        v = float(text)
    except ValueError:
        raise InputError(f"unparsable number in {what}", file=file, field=where, value=text) from None
    if not math.isfinite(v):
        raise InputError(f"non-finite {what}", file=file, field=where, value=text)
    if v < 0:
        raise InputError(f"negative {what}", file=file, field=where, value=text)
    return v


def _label(text, kind, file, where):
    """Parse a bin label: a centre (float) or an edge pair (lower, upper)."""
    if kind == "centres":
        if _EDGE_RE.match(text):
            raise InputError("the bins are declared as centres (header or bins=) but the label "
                             "is a pair of edges; declare '# hs_bins: edges' / '# tz_bins: edges'",
                             file=file,
                             field=where, value=text)
        return _number(text, file, where, what="bin centre")
    m = _EDGE_RE.match(text)
    if not m and re.fullmatch(_NUM, text.strip()):
        raise InputError("the bins are declared as edges (header or bins=) but the label is a "
                         "single number; "
                         "declare '# hs_bins: centres' / '# tz_bins: centres', or give "
                         "'lower-upper' labels", file=file, field=where, value=text)
    if not m:
        raise InputError("unparsable bin label; expected 'lower-upper' (e.g. 0.5-1.0) "
                         "with non-negative numbers", file=file, field=where, value=text)
    lo, hi = float(m.group(1)), float(m.group(2))
    if not lo < hi:
        raise InputError("bin lower edge must be below its upper edge", file=file, field=where, value=text)
    return (lo, hi)


def _bins(parsed, wheres, texts, kind, axis, file):
    """Validate parsed labels in table order; return (centre, lower, upper) arrays."""
    seen = {}
    for p, w, t in zip(parsed, wheres, texts):
        if p in seen:
            raise InputError(f"duplicated {axis} bin (also at {seen[p]})", file=file, field=w, value=t)
        seen[p] = w
    for i in range(1, len(parsed)):
        prev, cur = parsed[i - 1], parsed[i]
        ok = cur > prev if kind == "centres" else cur[0] >= prev[1] - 1e-9 * max(1.0, prev[1])
        if not ok:
            raise InputError(f"{axis} bins not increasing (or overlapping) after "
                             f"{texts[i - 1]!r} at {wheres[i - 1]}", file=file, field=wheres[i], value=texts[i])
    if kind == "edges":
        lower = np.array([p[0] for p in parsed])
        upper = np.array([p[1] for p in parsed])
        return 0.5 * (lower + upper), lower, upper
    c = np.array(parsed, dtype=float)
    if c.size and c[0] == 0.0:
        # no sea state has Hs or Tz 0: a first label of 0 is the first bin's lower edge
        # (0.0, 0.5, 1.0 ... m), and read as centres every bin would sit half a bin low
        step = f"{c[1] - c[0]:g}" if c.size > 1 else "w"
        raise InputError(f"the bins are declared as centres (header or bins=) but the first {axis} "
                         f"label is 0, which no bin is centred on: the labels look like the bins' "
                         f"lower edges ({', '.join(texts[:3])}, ...). Declare '# {axis}_bins: edges' "
                         f"and label each bin 'lower-upper' (0-{step}, ...), or give the centres",
                         file=file, field=wheres[0], value=texts[0])
    if c.size < 2:
        raise InputError(f"a single {axis} bin centre gives no bin width; give edges instead",
                         file=file, field=wheres[0], value=texts[0])
    mid = 0.5 * (c[1:] + c[:-1])
    lower = np.concatenate([[max(c[0] - (mid[0] - c[0]), 0.0)], mid])
    upper = np.concatenate([mid, [c[-1] + (c[-1] - mid[-1])]])
    return c, lower, upper


def read_utf8(path, what):
    """(raw bytes, text) of a UTF-8 file (gzip-compressed when its name ends in ``.gz``);
    unreadable or non-UTF-8 files, and paths that are not regular files of bounded size
    (a named pipe, /dev/zero), are an InputError."""
    file = str(path)
    raw = read_bytes(path, what, MAX_TABLE_BYTES)
    data = raw
    if file.endswith(".gz"):                 # a compressed record (the default route's)
        try:
            data = gzip.decompress(raw)
        except (OSError, EOFError) as exc:
            raise InputError(f"not a readable gzip file ({exc})", file=file) from None
        if len(data) > MAX_TABLE_BYTES:
            raise InputError(f"{what} is larger than the {MAX_TABLE_BYTES // 2 ** 20} MB jls reads "
                             "once decompressed", file=file)
    try:
        return raw, data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError("not a UTF-8 text file", file=file) from None


def _read_text(path):
    """Split a scatter file into (raw bytes, header dict, [(line number, cells)])."""
    file = str(path)
    raw, text = read_utf8(path, "scatter table")
    header, rows = {}, []
    for lineno, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        if not s:
            continue
        if s.startswith("#"):
            m = re.match(r"#\s*([A-Za-z_]\w*)\s*:\s*(.*)$", s)
            if m and not rows:
                key = m.group(1).lower()
                if key in header:
                    raise InputError("header key given twice", file=file, field=f"line {lineno}", value=key)
                header[key] = m.group(2).strip()
            continue
        rows.append((lineno, [c.strip() for c in next(csv.reader([s]))]))
    return raw, header, rows


def _option(name, override, header, table, file, *, required=True):
    """Resolve one option from the keyword override or the header."""
    text = override if override is not None else header.get(name)
    if text is None:
        if not required:
            return None
        raise InputError(f"missing header key '# {name}: ...' (one of {sorted(set(table.values()))})",
                         file=file, field=f"header key {name}")
    key = str(text).strip().lower()
    if key not in table:
        raise InputError(f"unknown {name}; expected one of {sorted(set(table.values()))}",
                         file=file, field=f"header key {name}", value=text)
    return table[key]


def _parse_matrix(rows, kinds, vkind, file, period="tz"):
    if len(rows) < 2 or len(rows[0][1]) < 2:
        raise InputError("empty table: need a Tz label row and at least one Hs row", file=file,
                         field="table", value=f"{len(rows)} data lines")
    line0, head = rows[0]
    check_corner(head[0], file, f"line {line0}, column 1", period)
    ncol = len(head)
    tz_w = [f"line {line0}, column {j + 1}" for j in range(1, ncol)]
    tz = _bins([_label(t, kinds["tz"], file, w) for t, w in zip(head[1:], tz_w)],
               tz_w, head[1:], kinds["tz"], "tz", file)
    hs_t, hs_w = [], []
    for ln, cells in rows[1:]:
        if len(cells) != ncol:
            raise InputError(f"row has {len(cells)} cells, the Tz label row (line {line0}) has {ncol}",
                             file=file, field=f"line {ln}", value=",".join(cells))
        hs_t.append(cells[0])
        hs_w.append(f"line {ln}, column 1")
    hs = _bins([_label(t, kinds["hs"], file, w) for t, w in zip(hs_t, hs_w)],
               hs_w, hs_t, kinds["hs"], "hs", file)
    vals = np.array([[_value(c, vkind, file, f"line {ln}, column {j + 2} (hs {cells[0]}, tz {head[j + 1]})")
                      for j, c in enumerate(cells[1:])] for ln, cells in rows[1:]])
    return vals, hs, tz, None


def _value(text, vkind, file, where):
    v = _number(text, file, where)
    if vkind == "counts" and not v.is_integer():
        raise InputError("count must be a whole number (use '# values: probability' for "
                         "fractional tables)", file=file, field=where, value=text)
    return v


def _parse_long(rows, kinds, vkind, file):
    if not rows:
        raise InputError("empty table: no column-name row", file=file, field="table", value="0 data lines")
    line0, names = rows[0]
    names = [n.lower() for n in names]
    allowed = {"hs", "tz", "direction", "probability", "count", "counts"}
    for j, n in enumerate(names):
        if n not in allowed:
            raise InputError(f"unknown column; expected {sorted(allowed)}", file=file,
                             field=f"line {line0}, column {j + 1}", value=n)
        if names.count(n) > 1:
            raise InputError("duplicated column", file=file, field=f"line {line0}, column {j + 1}", value=n)
    vcols = [n for n in names if n in ("probability", "count", "counts")]
    if "hs" not in names or "tz" not in names or len(vcols) != 1:
        raise InputError("long layout needs columns hs, tz, optional direction and exactly one of "
                         "probability / count", file=file, field=f"line {line0}", value=",".join(names))
    col_kind = _VALUES[vcols[0]]
    if vkind is not None and vkind != col_kind:
        raise InputError(f"header says values: {vkind} but the value column is {vcols[0]!r}",
                         file=file, field=f"line {line0}", value=vcols[0])
    vkind = col_kind
    ih, it, iv = names.index("hs"), names.index("tz"), names.index(vcols[0])
    idir = names.index("direction") if "direction" in names else None
    if len(rows) < 2:
        raise InputError("empty table: no data rows", file=file, field=f"line {line0}", value=",".join(names))
    cells_of, first = {}, {"hs": {}, "tz": {}}
    for ln, cells in rows[1:]:
        if len(cells) != len(names):
            raise InputError(f"row has {len(cells)} cells, expected {len(names)}", file=file,
                             field=f"line {ln}", value=",".join(cells))
        w = lambda j: f"line {ln}, column {j + 1}"  # noqa: E731
        h = _label(cells[ih], kinds["hs"], file, w(ih))
        t = _label(cells[it], kinds["tz"], file, w(it))
        first["hs"].setdefault(h, (w(ih), cells[ih]))
        first["tz"].setdefault(t, (w(it), cells[it]))
        d = None
        if idir is not None:
            d = _number(cells[idir], file, w(idir), what="direction")
            if d > 360:
                raise InputError("direction must be within 0-360 deg", file=file, field=w(idir), value=cells[idir])
            d = d % 360.0
        key = (h, t, d)
        if key in cells_of:
            raise InputError(f"duplicated bin (same hs, tz, direction as {cells_of[key][0]})",
                             file=file, field=f"line {ln}", value=",".join(cells))
        cells_of[key] = (f"line {ln}", _value(cells[iv], vkind, file, w(iv)))
    axes = {}
    for axis in ("hs", "tz"):
        keys = sorted(first[axis])
        axes[axis] = _bins(keys, [first[axis][k][0] for k in keys], [first[axis][k][1] for k in keys],
                           kinds[axis], axis, file)
        axes[axis + "_index"] = {k: i for i, k in enumerate(keys)}
    dirs = sorted({k[2] for k in cells_of}) if idir is not None else None
    shape = (len(axes["hs"][0]), len(axes["tz"][0])) + ((len(dirs),) if dirs else ())
    vals = np.zeros(shape)
    dix = {d: i for i, d in enumerate(dirs)} if dirs else {}
    for (h, t, d), (_, v) in cells_of.items():
        idx = (axes["hs_index"][h], axes["tz_index"][t]) + ((dix[d],) if dirs else ())
        vals[idx] = v
    return vals, axes["hs"], axes["tz"], (np.array(dirs) if dirs else None), vkind


def scatter_dataset(values, *, hs_lower, hs_upper, tz_lower, tz_upper, hs=None, tz=None,
                    direction=None, values_kind="counts", attrs=None, file=None) -> xr.Dataset:
    """Build the scatter Dataset from a value array of shape (hs, tz[, direction]).

    values: counts (whole numbers) or probabilities (any positive total; normalised).
    hs/tz default to the bin mid-points.  Raises InputError for negative, non-finite or
    all-zero values.  The ``steep`` flag uses the study's rule.
    """
    v = np.asarray(values, dtype=float)
    if values_kind not in ("counts", "probability"):
        raise InputError("values_kind must be 'counts' or 'probability'", file=file,
                         field="values_kind", value=values_kind)
    bad = ~np.isfinite(v) | (v < 0)
    if bad.any():
        raise InputError("negative or non-finite value", file=file, field="values", value=float(v[bad][0]))
    total = float(v.sum())
    if not total > 0:
        raise InputError("table is empty or all zero", file=file, field="values", value=total)
    hs_lower, hs_upper, tz_lower, tz_upper = (np.asarray(a, dtype=float) for a in
                                              (hs_lower, hs_upper, tz_lower, tz_upper))
    hs = 0.5 * (hs_lower + hs_upper) if hs is None else np.asarray(hs, dtype=float)
    tz = 0.5 * (tz_lower + tz_upper) if tz is None else np.asarray(tz, dtype=float)
    dims = ("hs", "tz") + (("direction",) if direction is not None else ())
    coords = {"hs": ("hs", hs), "tz": ("tz", tz), "hs_lower": ("hs", hs_lower),
              "hs_upper": ("hs", hs_upper), "tz_lower": ("tz", tz_lower), "tz_upper": ("tz", tz_upper)}
    if direction is not None:
        coords["direction"] = ("direction", np.asarray(direction, dtype=float))
    data = {"probability": (dims, v / total)}
    if values_kind == "counts":
        if not np.all(v == np.round(v)):
            raise InputError("counts must be whole numbers", file=file, field="values")
        data["count"] = (dims, v.astype(np.int64))
        total = int(round(total))
    ds = xr.Dataset(data, coords=coords)
    for name in list(ds.variables):
        ds[name].attrs.update(registry.attributes("sea_states", name) if name in REGISTERED else OWN_ATTRS[name])
    ds.attrs.update(attrs or {})
    ds.attrs["total"] = total
    ds.attrs["values_kind"] = values_kind
    return flag_steep(ds, "study")


def read_scatter(path, *, layout=None, bins=None, values=None, period="tz") -> xr.Dataset:
    """Read a scatter table (matrix or long CSV) into the scatter Dataset (see module doc).

    layout: "matrix" | "long" overrides the ``layout`` header key; without either, a
    first row starting with column name ``hs`` means long, anything else matrix.
    bins: "centres" | "edges" for both axes, or {"hs": ..., "tz": ...}; overrides the
    ``hs_bins`` / ``tz_bins`` header keys.  values: "counts" | "probability" overrides
    the ``values`` header key.  ``period``: "tp" for a matrix table in Hs-Tp (its corner
    may say tp, not tz; the axis is still named ``tz`` here, :func:`jls.sea.legs.tp_table_as_tz`).
    Every bad cell raises InputError naming file, line, column and value; nothing is
    returned partially.
    """
    file = str(path)
    raw, header, rows = _read_text(path)
    if not rows and not header:
        raise InputError("empty file: no header lines and no table" if raw.strip() == b""
                         else "no table: only comment lines", file=file)
    if not rows:
        raise InputError("empty table: no rows after the header lines", file=file, field="table")
    for sep, name in ((";", "semicolons"), ("\t", "tabs")):
        if len(rows[0][1]) == 1 and sep in rows[0][1][0]:
            raise InputError(f"the table is separated by {name}; scatter tables are "
                             "comma-separated (CSV)", file=file, field=f"line {rows[0][0]}",
                             value=rows[0][1][0][:60])
    if layout is None:
        layout = header.get("layout")
    if layout is None:
        first = [c.lower() for c in rows[0][1]] if rows else []
        layout = "long" if first[:1] == ["hs"] and "tz" in first else "matrix"
    layout = str(layout).strip().lower()
    if layout not in ("matrix", "long"):
        raise InputError("layout must be 'matrix' or 'long'", file=file, field="layout", value=layout)
    over = bins if isinstance(bins, dict) else {"hs": bins, "tz": bins}
    kinds = {a: _option(f"{a}_bins", over.get(a), header, _KINDS, file) for a in ("hs", "tz")}
    vkind = _option("values", values, header, _VALUES, file, required=(layout == "matrix"))
    if layout == "matrix":
        vals, hs, tz, direction = _parse_matrix(rows, kinds, vkind, file, period)
    else:
        vals, hs, tz, direction, vkind = _parse_long(rows, kinds, vkind, file)
    check_header_keys(header, file)
    check_stated_totals(header, vals, vkind, file)
    if not vals.sum() > 0:
        raise InputError("table is all zero", file=file, field=f"values, lines {rows[1][0]}-{rows[-1][0]}",
                         value=0)
    attrs = {(k if k not in _RESERVED else f"header_{k}"): v for k, v in header.items()}
    attrs.update(source=Path(path).name, sha256=hashlib.sha256(raw).hexdigest(), layout=layout,
                 hs_bins=kinds["hs"], tz_bins=kinds["tz"],
                 warnings="\n".join(table_warnings(header, vals, vkind, Path(path).name)))
    return scatter_dataset(vals, hs=hs[0], hs_lower=hs[1], hs_upper=hs[2], tz=tz[0], tz_lower=tz[1],
                           tz_upper=tz[2], direction=direction, values_kind=vkind, attrs=attrs, file=file)


def write_scatter(ds: xr.Dataset, path, header: dict | None = None) -> Path:
    """Write a (hs, tz) scatter Dataset as a matrix CSV with edge labels.

    Writes ``count`` when present, else ``probability``.  `header` entries become
    ``# key: value`` lines after the layout keys (values must be single-line).
    A Dataset with a direction dimension must be summed over it first.
    """
    if "direction" in ds.dims:
        raise InputError("matrix layout holds (hs, tz) only; sum over direction first",
                         file=str(path), field="direction")
    kind = "counts" if "count" in ds else "probability"
    vals = ds["count"].values if kind == "counts" else ds["probability"].values
    lines = ["# layout: matrix", "# hs_bins: edges", "# tz_bins: edges", f"# values: {kind}"]
    for k, v in (header or {}).items():
        text = str(v)
        if "\n" in text or not re.fullmatch(r"[A-Za-z_]\w*", str(k)) or k.lower() in _RESERVED:
            raise InputError("header entries need a plain key and a single-line value", field=str(k), value=text)
        lines.append(f"# {k}: {text}")
    lab = lambda lo, hi: f"{_fmt(lo)}-{_fmt(hi)}"  # noqa: E731
    lines.append(",".join(["hs\\tz"] + [lab(a, b) for a, b in zip(ds["tz_lower"].values, ds["tz_upper"].values)]))
    for i, (a, b) in enumerate(zip(ds["hs_lower"].values, ds["hs_upper"].values)):
        cells = [str(int(x)) if kind == "counts" else repr(float(x)) for x in vals[i]]
        lines.append(",".join([lab(a, b)] + cells))
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
