"""Content-addressed cache of unit-Hs spectral moments, one file per sea state.

The response of a set of candidates to one sea state (Tz, heading, gamma) is the pair
of spectral moments m0, m2 per candidate, tugger and response. It depends only on the
plant matrices of those candidates, the tugger slopes, the frequency grid, the hinge and
fairlead RAOs at that heading, the sea state, and the solver. The cache keys a file by a
hash of exactly these, so:

* adding a Tz column to a leg evaluates that sea state alone;
* legs and routes that share sea states (and plant and vessel) reuse them;
* a change of plant, vessel, tuggers or grid misses the cache and recomputes.

The thread count is not in the key: the moments are the same, bit for bit, for any
number of threads (the solver's threads solve each candidate alone, and the moments'
matrix product runs on one BLAS thread; tests/test_determinism.py), so a cache filled by
jobs of any size serves every other.

Files are ``<root>/<set key>/<heading key>/tz<Tz>_g<gamma>.npy`` holding an array
(2, n_candidate, n_tugger, 4): m0 and m2. They are written atomically (temporary file,
then rename), so concurrent jobs may share a cache directory.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from jls import __version__
from jls.io.atomic import write_atomically

#: Bump when the numbers the solver produces for the same inputs change. (2: the moments'
#: matrix product on one BLAS thread; before, its rounding followed the job's threads.)
SOLVER_VERSION = "fd-lu4-sherman-morrison-2"


def _digest(*arrays, text: str = "") -> str:
    h = hashlib.sha256(text.encode())
    for a in arrays:
        a = np.ascontiguousarray(a)
        h.update(str((a.dtype.str, a.shape)).encode())
        h.update(a.tobytes())
    return h.hexdigest()[:16]


class SeaStateCache:
    """Spectral moments of one candidate set per sea state, on disk under ``root``.

    ``plant``: (M, K, Kb, C) arrays of the candidates; ``omega``: the frequency grid;
    ``c_tugger``: tugger slopes.
    """

    def __init__(self, root, plant, omega, c_tugger):
        self.root = Path(root)
        self.set_key = _digest(*plant, omega, np.asarray(c_tugger, float),
                               text=f"{SOLVER_VERSION} jls {__version__}")

    def _path(self, heading_key: str, tz: float, gamma: float) -> Path:
        return self.root / self.set_key / heading_key / f"tz{float(tz)!r}_g{float(gamma)!r}.npy"

    @staticmethod
    def heading_key(heading_deg: float, qb, fairlead_sway) -> str:
        """Key of one heading's excitation (hinge and fairlead RAOs on the grid)."""
        return _digest(np.asarray(qb, complex), np.asarray(fairlead_sway, complex),
                       text=f"heading {float(heading_deg)!r}")

    def load(self, heading_key: str, tz: float, gamma: float):
        """(m0, m2) or None when the sea state is not cached."""
        path = self._path(heading_key, tz, gamma)
        try:
            m = np.load(path)
        except (FileNotFoundError, ValueError, EOFError, OSError):
            return None
        return m[0], m[1]

    def save(self, heading_key: str, tz: float, gamma: float, m0, m2) -> None:
        def write(tmp):
            with open(tmp, "wb") as f:
                np.save(f, np.stack([m0, m2]))
        write_atomically(self._path(heading_key, tz, gamma), write, suffix=".npy.tmp")
