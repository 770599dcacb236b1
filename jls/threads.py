"""Independent pieces of work on threads: the compiled kernels (solver, time-domain
integrator) release the GIL, so threads run them side by side in one process. Matrix
products (BLAS) stay on one thread, so that no number depends on the threads a process
was given."""

from __future__ import annotations

from contextlib import contextmanager


def thread_map(fn, items, workers=1) -> list:
    """``[fn(x) for x in items]``, on up to ``workers`` threads (in order; serial for one
    worker or one item)."""
    items = list(items)
    workers = min(int(workers or 1), len(items))
    if workers <= 1:
        return [fn(x) for x in items]
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(fn, items))


@contextmanager
def single_threaded_blas():
    """BLAS (numpy's matrix products) on one thread inside the block.

    A multi-threaded BLAS splits a matrix product differently from a single-threaded one
    and rounds differently (measured: OpenBLAS, 1 thread against 2, 5e-16 relative on the
    spectral moments), and Snakemake sets a job's BLAS threads (OPENBLAS_NUM_THREADS,
    OMP_NUM_THREADS) to the job's threads: without this, a response job's numbers would
    depend on the threads it was given, and the sea-state cache would mix both. jls's own
    kernels take the threads (each candidate solved alone, so bit for bit the same); the
    products after them run on one.
    """
    from threadpoolctl import threadpool_limits
    with threadpool_limits(limits=1, user_api="blas"):
        yield


__all__ = ["single_threaded_blas", "thread_map"]
