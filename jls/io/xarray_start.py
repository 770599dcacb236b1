"""xarray without dask's import at a job's first dataset.

xarray asks, when it makes its first variable, whether the data is a dask array, and to
know dask's array type it imports ``dask.array`` whenever dask is installed: 0.25 s of
every job's start-up (dask, scipy.sparse, jinja2 and 300 more modules), though jls never
makes a dask array. Importing this module (done by :mod:`jls.io.netcdf` and
:mod:`jls.io.registry`, before any dataset is made) puts a stand-in for dask into
xarray's cache of duck-array modules: it answers "no dask array type" until
``dask.array`` has been imported by anyone (no object can be a dask array before that),
and from then on, and for anything else xarray asks of it (module, version,
availability), it is xarray's own entry. Nothing changes but when dask is imported. Where
xarray's internals differ (another version), nothing is installed.
"""

from __future__ import annotations

import sys


class _DaskOnDemand:
    """xarray's ``DuckArrayModule("dask")``, made on first need (module docstring)."""

    def __init__(self, make):
        self._make = make
        self._real = None

    def _load(self):
        if self._real is None:
            self._real = self._make("dask")
        return self._real

    @property
    def type(self):
        if self._real is None and "dask.array" not in sys.modules:
            return ()
        return self._load().type

    @property
    def module(self):
        return self._load().module

    @property
    def version(self):
        return self._load().version

    @property
    def available(self):
        return self._load().available


def install() -> bool:
    """Put the stand-in into xarray's cache unless dask's entry is already there; True when
    the cache holds the stand-in."""
    try:
        from xarray.namedarray import pycompat
        cache, make = pycompat._cached_duck_array_modules, pycompat.DuckArrayModule
    except (ImportError, AttributeError):
        return False
    if not isinstance(cache, dict):
        return False
    return isinstance(cache.setdefault("dask", _DaskOnDemand(make)), _DaskOnDemand)


install()
