"""What a scatter table says about itself, honoured or refused (:mod:`jls.sea.scatter`).

A table's header lines (``# key: value``) and its matrix corner label are metadata: a
reader that ignores them may read a peak-period table as Tz, a percent table with a
stated record count that does not match, or a unit it does not know. Here:

* the corner label of a matrix (``hs\\tz``): when it names the axes, rows must be Hs and
  columns the zero-up-crossing period Tz; a label naming another period (``hs\\tp``,
  ``Te``, ``Tm01``) or the axes the other way round (``tz\\hs``) is refused;
* stated totals: ``records`` (or ``total``, ``n_records``, ``count``) must equal the sum
  of a counts table's cells; ``first_record``, ``last_record`` and ``missing_hours`` of an
  hourly source must add up to the hours spanned;
* header keys jls cannot honour are refused: units other than m and s (``hs_units: ft``),
  a period other than Tz (``period: tp``), a direction convention other than "from", and
  any key naming a unit, scale or convention jls does not read. Descriptive keys (source,
  buoy, years, description, ...) are kept as attributes;
* a probability table summing to neither 1 nor 100 is renormalised with a warning.
"""

from __future__ import annotations

import re

import numpy as np
import pandas as pd

from jls.errors import InputError

HS_NAMES = {"hs", "hm0", "swh", "hsig", "h_s", "h13"}
TZ_NAMES = {"tz", "tm02", "t02", "tm2", "t_z", "tzero"}
OTHER_PERIODS = {"tp": "the peak period Tp", "tpeak": "the peak period Tp", "t_p": "the peak period Tp",
                 "te": "the energy period Te", "tm01": "the mean period Tm01", "t01": "the mean period Tm01",
                 "tm10": "the energy period Tm-10", "tm": "a mean period", "tmean": "a mean period",
                 "t1": "the mean period Tm01", "tpk": "the peak period Tp"}
TOTAL_KEYS = ("records", "n_records", "total", "count", "counts", "record_count")
#: header keys whose value jls honours, with the values it accepts
HONOURED = {"hs_units": {"m"}, "hs_unit": {"m"}, "tz_units": {"s"}, "tz_unit": {"s"},
            "period": {"tz", "tm02", "t02", "zero-up-crossing", "zero-crossing"},
            "direction_convention": {"from", "coming from", "from, true", "from true"},
            "direction_units": {"deg", "degree", "degrees"}}
#: words that make an unknown header key a statement jls would have to honour
_SEMANTIC = ("unit", "period", "convention", "scale", "factor", "percent", "multiplier",
             "offset", "datum")


def _tokens(text: str) -> list[str]:
    return re.findall(r"[a-z][a-z0-9_]*", text.lower().replace("tm-10", "tm10").replace("m-1", "m1"))


def check_corner(label: str, file, where: str, period: str = "tz") -> None:
    """Refuse a matrix corner label that names a period other than Tz (other than Tp for a
    table declared in Hs-Tp, ``period="tp"``), or the axes the wrong way round; a label
    naming neither axis is a free label."""
    tokens = _tokens(label)
    for t in tokens:
        if period == "tp" and (t in TZ_NAMES or (t in OTHER_PERIODS and "Tp" not in OTHER_PERIODS[t])):
            raise InputError(f"the corner label says the columns are "
                             f"{OTHER_PERIODS.get(t, 'the zero-up-crossing period Tz')}, but the leg "
                             "declares a table in Hs-Tp (period: tp)", file=file, field=where, value=label)
        if period == "tp" and t in OTHER_PERIODS:
            continue
        if t in OTHER_PERIODS:
            raise InputError(f"the corner label says the columns are {OTHER_PERIODS[t]}, not the "
                             "zero-up-crossing period Tz jls assesses: convert the periods to Tz "
                             "(JONSWAP gamma 3.3: Tz = Tp / 1.286) and label the corner hs\\tz",
                             file=file, field=where, value=label)
    hs = [i for i, t in enumerate(tokens) if t in HS_NAMES]
    tz = [i for i, t in enumerate(tokens) if t in TZ_NAMES]
    if hs and tz and tz[0] < hs[0]:
        raise InputError("the corner label puts Tz first (rows Tz, columns Hs); jls reads rows "
                         "as Hs and columns as Tz: transpose the table and label it hs\\tz",
                         file=file, field=where, value=label)


def check_header_keys(header: dict, file) -> None:
    """Refuse header keys that state something jls does not honour."""
    for key, value in header.items():
        text = str(value).strip().lower()
        if key in HONOURED:
            if text not in HONOURED[key]:
                raise InputError(f"header key '{key}' states {value!r}; jls reads only "
                                 f"{sorted(HONOURED[key])}: convert the table", file=file,
                                 field=f"header key {key}", value=value)
        elif any(word in key for word in _SEMANTIC):
            raise InputError(f"header key '{key}' states something jls does not read (units m "
                             "and s, Tz, directions the waves come from, in degrees true): "
                             "convert the table and remove the line, or rename the key if it is "
                             "a description", file=file, field=f"header key {key}", value=value)


def _count(text, key, file):
    try:
        v = float(str(text).replace(",", "").replace("_", "").strip())
    except ValueError:
        raise InputError("a stated count must be a number", file=file,
                         field=f"header key {key}", value=text) from None
    return v


def check_stated_totals(header: dict, values: np.ndarray, values_kind: str, file) -> None:
    """Stated record counts against the cells, and a stated span against its records."""
    total = float(np.asarray(values, float).sum())
    for key in TOTAL_KEYS:
        if key not in header:
            continue
        stated = _count(header[key], key, file)
        if values_kind == "counts" and abs(stated - total) > 0.5:
            raise InputError(f"the header states {key}: {header[key]} but the cells sum to "
                             f"{total:.0f} ({100 * (total - stated) / stated:+.1f} %): a truncated "
                             "or edited table, or another table's header?", file=file,
                             field=f"header key {key}", value=header[key])
    if {"first_record", "last_record", "missing_hours"} <= set(header) and "records" in header:
        try:
            first = pd.Timestamp(str(header["first_record"]).replace("UTC", "").strip())
            last = pd.Timestamp(str(header["last_record"]).replace("UTC", "").strip())
        except ValueError:
            raise InputError("first_record and last_record must be times (YYYY-MM-DD HH:MM)",
                             file=file, field="header key first_record",
                             value=header["first_record"]) from None
        spanned = (last - first) / pd.Timedelta("1h") + 1
        stated = _count(header["records"], "records", file) + _count(
            header["missing_hours"], "missing_hours", file)
        if abs(spanned - stated) > 0.5:
            raise InputError(f"the header's records ({header['records']}) and missing_hours "
                             f"({header['missing_hours']}) make {stated:.0f} hours, but "
                             f"first_record to last_record spans {spanned:.0f}: the header does "
                             "not describe this table", file=file, field="header key missing_hours",
                             value=header["missing_hours"])


def table_warnings(header: dict, values: np.ndarray, values_kind: str, source: str) -> list[str]:
    """Warnings for a report's first page: a probability table whose values sum to neither
    1 nor 100 (it is renormalised: cells missing, or another total?)."""
    total = float(np.asarray(values, float).sum())
    if values_kind == "probability" and not (abs(total - 1) <= 0.01 or abs(total - 100) <= 1):
        return [f"scatter table {source}: its probabilities sum to {total:.4g}, neither 1 nor 100; "
                "they were renormalised to 1"]
    return []
