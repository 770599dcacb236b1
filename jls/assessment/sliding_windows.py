"""Running reductions over every window of consecutive hours: the maximum and the sum
over each window of ``n`` values along the last axis, in O(m) whatever ``n`` (the van
Herk / Gil-Werman block method: two block-wise running reductions, one combination).
The route simulation sails every departure with them."""

from __future__ import annotations

import numpy as np

__all__ = ["sliding_max", "sliding_sum"]


def _blocks(a, n, fill):
    """a (..., m) padded to whole blocks of n: (..., m_blocks, n)."""
    m = a.shape[-1]
    pad = (-m) % n
    if pad:
        a = np.concatenate([a, np.full(a.shape[:-1] + (pad,), fill, a.dtype)], axis=-1)
    return a.reshape(a.shape[:-1] + (-1, n)), m


def sliding_max(a, n: int):
    """Maximum over every window of ``n`` consecutive values along the last axis:
    out[..., i] = max(a[..., i:i + n]), length m - n + 1 (van Herk / Gil-Werman: a
    running maximum forward within blocks of n and one backward, O(m) whatever n).
    NaN propagates to exactly the windows that hold it."""
    a = np.asarray(a)
    m = a.shape[-1]
    if not 1 <= n <= m:
        raise ValueError(f"window {n} must lie in 1..{m}")
    fill = -np.inf if a.dtype.kind == "f" else np.iinfo(a.dtype).min
    blk, _ = _blocks(a, n, fill)
    fwd = np.maximum.accumulate(blk, axis=-1).reshape(a.shape[:-1] + (-1,))
    bwd = np.maximum.accumulate(blk[..., ::-1], axis=-1)[..., ::-1].reshape(a.shape[:-1] + (-1,))
    return np.maximum(bwd[..., : m - n + 1], fwd[..., n - 1: m])


def sliding_sum(a, n: int):
    """Sum over every window of ``n`` consecutive values along the last axis (length
    m - n + 1), from block-wise running sums, so that a window's rounding error stays
    that of its own values (no long cumulative sum)."""
    a = np.asarray(a)
    m = a.shape[-1]
    if not 1 <= n <= m:
        raise ValueError(f"window {n} must lie in 1..{m}")
    blk, _ = _blocks(a, n, 0)
    fwd = np.cumsum(blk, axis=-1).reshape(a.shape[:-1] + (-1,))
    bwd = np.cumsum(blk[..., ::-1], axis=-1)[..., ::-1].reshape(a.shape[:-1] + (-1,))
    whole = np.arange(m - n + 1) % n == 0    # the window is one whole block
    return bwd[..., : m - n + 1] + np.where(whole, 0, fwd[..., n - 1: m])
