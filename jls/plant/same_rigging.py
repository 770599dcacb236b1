"""One option per rigging: candidates whose geometry agrees within a tolerance are one.

Two candidates are the same rigging when every anchor and padeye coordinate and the CoG
depth agree within ``tolerance_m`` (the largest difference, Chebyshev distance over the
25 numbers): a spread set to 4 mm off another is not another rigging, and the
screening's optimum landing on a configured candidate is that candidate. Candidates
chain into one group when each is within the tolerance of another of the group.

The neighbours are found with a k-d tree (:class:`scipy.spatial.cKDTree`, pairs within
the tolerance), so a 10 000-candidate grid costs about N log N, not N^2.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy.spatial import cKDTree

from jls.errors import InputError

GEOMETRY = ("anchor", "padeye", "cog_depth")


def geometry_matrix(plant: xr.Dataset, names) -> np.ndarray:
    """(n, 25) anchors, padeyes [m] and CoG depth [m] of the candidates ``names``."""
    missing = [v for v in GEOMETRY if v not in plant]
    if missing:
        raise InputError(f"the plant dataset has no {', '.join(missing)}: riggings cannot be "
                         "compared", field="candidate")
    sel = plant[list(GEOMETRY)].sel(candidate=list(names))
    parts = [sel["anchor"].transpose("candidate", "wire", "axis").values.reshape(len(names), -1),
             sel["padeye"].transpose("candidate", "wire", "axis").values.reshape(len(names), -1),
             sel["cog_depth"].values.reshape(len(names), 1)]
    return np.concatenate(parts, axis=1).astype(float)


def groups(plant: xr.Dataset, names, tolerance_m: float) -> list[list[str]]:
    """The candidates ``names`` grouped by rigging, each group in the order of ``names``
    and the groups in the order of their first member."""
    names = [str(n) for n in names]
    if not tolerance_m >= 0:
        raise InputError("the tolerance of the same rigging must be non-negative",
                         field="recommendation.same_rigging_tolerance_m", value=tolerance_m)
    x = geometry_matrix(plant, names)
    parent = list(range(len(names)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    finite = np.all(np.isfinite(x), axis=1)
    idx = np.flatnonzero(finite)
    if idx.size > 1:
        pairs = cKDTree(x[idx]).query_pairs(r=float(tolerance_m) * (1 + 1e-9), p=np.inf,
                                            output_type="ndarray")
        for a, b in pairs:
            ra, rb = root(int(idx[a])), root(int(idx[b]))
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)          # the earlier name roots the group
    out: dict[int, list[str]] = {}
    for i, n in enumerate(names):
        out.setdefault(root(i), []).append(n)
    return list(out.values())


def merge(ds: xr.Dataset, plant: xr.Dataset, tolerance_m: float) -> xr.Dataset:
    """``ds`` with one candidate per rigging: the first name of each group kept (the
    baseline, then the configured candidates in their order, then the screening's
    ``optimised``), the others dropped; coordinate ``candidate_names`` lists every name of
    each option, attribute ``same_rigging`` says which were merged (empty: none) and
    ``same_rigging_tolerance_m`` the tolerance."""
    names = [str(c) for c in ds["candidate"].values]
    found = groups(plant, names, tolerance_m)
    keep = [g[0] for g in found]
    listed = {g[0]: ", ".join(g) for g in found}
    out = ds.sel(candidate=keep) if len(keep) < len(names) else ds
    out = out.assign_coords(candidate_names=("candidate", [listed[k] for k in keep]))
    out["candidate_names"].attrs["long_name"] = ("every name of the option: candidates of the same "
                                                 "rigging geometry within same_rigging_tolerance_m")
    merged = [g for g in found if len(g) > 1]
    out.attrs["same_rigging"] = "; ".join(
        f"{', '.join(g[1:])} {'is' if len(g) == 2 else 'are'} the same rigging as {g[0]}" for g in merged)
    out.attrs["same_rigging_tolerance_m"] = float(tolerance_m)
    return out


def alias(ds: xr.Dataset, name: str) -> str | None:
    """The option of ``ds`` that carries the candidate ``name`` (itself, or the candidate it
    was merged into); None when no option does."""
    cands = [str(c) for c in ds["candidate"].values]
    if name in cands:
        return name
    if "candidate_names" not in ds.coords:
        return None
    for c, listed in zip(cands, ds["candidate_names"].values.tolist()):
        if name in [s.strip() for s in str(listed).split(",")]:
            return c
    return None


__all__ = ["GEOMETRY", "alias", "geometry_matrix", "groups", "merge"]
