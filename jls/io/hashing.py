"""Hashes that identify inputs: a file's SHA-256 and a configuration mapping's.
"""

from __future__ import annotations

import hashlib
import json

import numpy as np


def config_hash(cfg) -> str:
    """Stable SHA-256 of a configuration mapping (sorted JSON)."""
    text = json.dumps(cfg, sort_keys=True, default=lambda o: np.asarray(o).tolist())
    return hashlib.sha256(text.encode()).hexdigest()


def file_sha256(path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


