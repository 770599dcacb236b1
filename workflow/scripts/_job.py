"""Imported by every workflow script before numpy, xarray or jls.

A job is one short process whose modules and datasets live until it ends, so the cyclic
garbage collector is told from the start to run seldom: its youngest generation after
20 000 allocations instead of Python's 700 (the report's own threshold,
:data:`jls.report.document.GC_THRESHOLD`). At the defaults the report job's imports ran
328 collections (0.10-0.12 s of CPU), 10 after; every job imports much the same
(numpy, pandas, xarray, netCDF4, numba). :func:`jls.io.provenance.workflow_step` then
freezes what exists when the step starts.
"""

import gc

gc.set_threshold(20_000, 50, 100)
