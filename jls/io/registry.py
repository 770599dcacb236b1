"""One registry of dataset layouts: ``jls/schemas/datasets.yaml``.

Every dataset jls writes is described there once: its variables (dims, UDUNITS units,
long name, flag meanings), its coordinates, the global attributes it must carry and the
configuration parts it depends on. Builders call :func:`annotate`, the NetCDF writer
calls :func:`check`, the report and the tests read :func:`layout`, builders of
intermediates holding a registered quantity take its :func:`attributes`, and
:func:`config_hash` gives each dataset the hash of the configuration parts it depends
on, so the report flags a real mismatch only.
"""

from __future__ import annotations

import copy
import functools
import re
from importlib import resources

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import xarray_start  # noqa: F401  (before any dataset: see there)

#: Unit symbols jls writes (UDUNITS names); products by space, powers as m2 or s-1.
UNIT_SYMBOLS = {"1", "m", "s", "h", "t", "kN", "kW", "rad", "degree"}
_UNIT_TOKEN = re.compile(r"^([A-Za-z]+|1)(-?\d+)?$")


@functools.cache
def _registry() -> dict:
    """The parsed registry, read once per process (never handed out: see :func:`layout`)."""
    from jls.io.yamlio import loads
    text = resources.files("jls.schemas").joinpath("datasets.yaml").read_text()
    return loads(text, "jls/schemas/datasets.yaml")


def _entry(name: str) -> dict:
    try:
        return _registry()[name]
    except KeyError:
        raise KeyError(f"dataset {name!r} is not in the registry ({', '.join(names())})") from None


#: the attributes :func:`annotate` sets from the registry
ANNOTATED = ("units", "long_name", "flag_meanings", "units_note", "units_from")


@functools.cache
def _annotations(name: str) -> tuple:
    """(variable, attributes) pairs of dataset ``name``'s variables and coordinates."""
    entry = _entry(name)
    return tuple((var, {k: spec[k] for k in ANNOTATED if k in spec})
                 for group in ("variables", "coordinates") for var, spec in entry[group].items())


def attributes(name: str, var: str) -> dict:
    """The attributes :func:`annotate` gives variable or coordinate ``var`` of dataset
    ``name`` (a copy), for a builder of an intermediate that holds the same quantity."""
    found = dict(_annotations(name)).get(var)
    if found is None:
        raise KeyError(f"{var!r} is neither a variable nor a coordinate of dataset {name!r}")
    return dict(found)


def names() -> list[str]:
    return list(_registry())


def layout(name: str) -> dict:
    """The registry entry of dataset ``name`` (a copy)."""
    return copy.deepcopy(_entry(name))


def dims(name: str) -> dict[str, tuple]:
    """Variable -> dims of dataset ``name``."""
    return {v: tuple(spec["dims"]) for v, spec in _entry(name)["variables"].items()}


def valid_units(text: str) -> bool:
    """True for a UDUNITS product of the project's symbols, e.g. 'kN s m-1', 'degree m-1'."""
    tokens = str(text).split()
    if not tokens:
        return False
    for tok in tokens:
        m = _UNIT_TOKEN.match(tok)
        if not m or m.group(1) not in UNIT_SYMBOLS:
            return False
    return True


def annotate(ds: xr.Dataset, name: str) -> xr.Dataset:
    """Set units, long names and flag meanings of ``ds`` from the registry (in place)."""
    variables = ds.variables                    # the attrs of ds[var] are these variables'
    for var, attrs in _annotations(name):
        if var not in variables:
            continue
        a = variables[var].attrs
        for k in ANNOTATED:                     # stale ones carried over by arithmetic go
            a.pop(k, None)
        a.update(attrs)
    return ds


def check(ds: xr.Dataset, name: str, file=None) -> None:
    """Raise InputError unless ``ds`` follows the registry layout of ``name``: every
    required variable with its dims, no undeclared variable, units and long names set
    and parseable, and the dataset's own global attributes present."""
    entry = _entry(name)
    problems = []
    declared = entry["variables"]
    for var, spec in declared.items():
        if var not in ds.data_vars:
            if not spec.get("optional"):
                problems.append(f"missing variable {var}")
            continue
        if set(ds[var].dims) != set(spec["dims"]):
            problems.append(f"{var} has dims {tuple(ds[var].dims)}, expected {tuple(spec['dims'])}")
    undeclared = sorted(set(ds.data_vars) - set(declared))
    if undeclared:
        problems.append(f"undeclared variable(s) {', '.join(undeclared)}")
    for var in ds.variables:
        a = ds[var].attrs
        if "long_name" not in a:
            problems.append(f"{var} has no long_name")
        if "units_from" in a:
            coord = a["units_from"]
            if coord not in ds.coords:
                problems.append(f"{var} takes its units from a missing coordinate {coord}")
            elif not all(valid_units(u) for u in np.atleast_1d(ds[coord].values)):
                problems.append(f"{coord} holds units that are not UDUNITS strings")
        elif "units" in a and a["units"] != "mixed" and not valid_units(a["units"]):
            problems.append(f"{var} has units {a['units']!r}, not a UDUNITS string")
        elif a.get("units") == "mixed" and "units_note" not in a:
            problems.append(f"{var} mixes units without a units_note")
        elif var in ds.data_vars and "units" not in a and "units_from" not in a:
            problems.append(f"{var} has no units")
    missing = [k for k in entry.get("attrs", []) if k not in ds.attrs]
    if missing:
        problems.append(f"missing global attribute(s) {', '.join(missing)}")
    if problems:
        raise InputError(f"dataset '{name}' does not follow jls/schemas/datasets.yaml: "
                         + "; ".join(problems), file=file)


