"""Independent pieces of work on threads: the compiled kernels (solver, time-domain
integrator) release the GIL, so threads run them side by side in one process."""

from __future__ import annotations


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


__all__ = ["thread_map"]
