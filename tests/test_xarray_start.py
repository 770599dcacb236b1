"""jls.io.xarray_start: a job that makes datasets does not import dask.array, and dask
arrays are still recognised as such once dask.array is imported."""

import subprocess
import sys

import pytest

pytest.importorskip("dask")

CODE = """
import sys
import numpy as np
import xarray as xr
import jls.io.netcdf
from jls.io.xarray_start import install
ds = xr.Dataset({"a": (("x",), np.arange(3.0))})
ds["b"] = ds["a"] * 2
print("dask.array" in sys.modules, install())
import dask.array as da
from xarray.namedarray.pycompat import is_chunked_array
lazy = xr.DataArray(da.ones(4, chunks=2), dims="x")
print(is_chunked_array(lazy.variable._data), float((lazy * 2).sum().compute()))
"""


def test_no_dask_import_for_datasets_and_dask_arrays_still_work():
    out = subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True, check=True)
    first, second = out.stdout.split("\n")[:2]
    assert first == "False True"          # datasets made, dask.array not imported, stand-in in place
    assert second == "True 8.0"           # a dask array is one, and computes
