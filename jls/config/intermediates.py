"""The intermediate datasets a workflow run would read, checked when it is parsed.

Snakemake decides what to rebuild from modification times, parameters and code; it never
looks inside a file. A truncated ``response.nc`` (a full disk, a copy cut short), a file
that is not NetCDF, or a dataset copied in from another configuration would be taken as
up to date and every reader would then fail on it, or worse, use it. Before the DAG is
built, every existing dataset of the routes is checked (:func:`jls.io.netcdf.problem`):
it opens, it follows its layout in the registry, it carries the provenance attributes,
and its ``config_sha256`` is the hash of the configuration parts it depends on
(:func:`jls.config.dataset_hash.config_hash`). A bad one is named and set aside
(:func:`set_aside`: renamed ``<file>.rejected``, never deleted) together with the route's
report, which every dataset of the route feeds: Snakemake, finding the report missing,
rebuilds the set-aside dataset and everything between it and the report (a missing
intermediate alone would not make it rerun anything whose outputs look up to date).

The screening's chunk files record the screening's hash but depend on less (editing a
criterion reruns no chunk job), so only their opening and provenance are checked.

Outputs must be regular files and directories: a symbolic link among the run's outputs
(results/<route>/..., reports/, logs/, benchmarks/out/) is refused, since a log or an
output written through it would land wherever the link points. The roots themselves
(``results`` ...) may be links, e.g. to a scratch file system.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from jls.config.dataset_hash import config_hash
from jls.io.netcdf import problem


def route_datasets(results, route: str, *, screening: bool, n_screening_chunks: int,
                   n_response_chunks: int, windows: bool) -> list[tuple[Path, str | None]]:
    """(path, configuration-hash name) of the datasets the route's jobs read, when they
    exist; the hash name is None where only opening and provenance are checked."""
    base = Path(results) / route
    items = [("sea_states.nc", "sea_states"), ("vessel_motion.nc", "vessel_motion"),
             ("response.nc", "response"), ("operability.nc", "operability"),
             ("response_variants.nc", "response_variants"), ("workability.nc", "workability"),
             ("tugger_studies.nc", "tugger_studies"), ("measured_response.nc", "measured_response"),
             ("voyage.nc", "voyage"), ("voyage_plan.nc", "voyage_plan"),
             ("verification_study.nc", "verification_study")]
    if screening:
        items += [("screening.nc", "screening"), ("plant_assessed.nc", "plant")]
        items += [(f"screening/chunk-{i}.nc", None) for i in range(n_screening_chunks)]
    else:
        items.append(("plant.nc", "plant"))
    if n_response_chunks > 1:
        items += [(f"response/chunk-{i}.nc", "response") for i in range(n_response_chunks)]
    if windows:
        items.append(("weather_windows.nc", "weather_windows"))
    return [(base / name, h) for name, h in items if (base / name).exists()]


def cells_problem(path) -> tuple[list[str], str | None]:
    """(cell names, problem) of a route's ``timedomain/cells.json``."""
    from jls.timedomain.cells import parse_cell
    try:
        with open(path) as fh:
            cells = json.load(fh)
        names = [str(c["name"]) for c in cells]
        for name in names:
            parse_cell(name)
    except (OSError, ValueError, TypeError, KeyError) as exc:
        return [], f"not the list of time-domain cells jls writes ({type(exc).__name__})"
    return names, None


def problems(cfg: dict, results, routes, *, windows_routes=(), **layout) -> list[tuple[str, str, str]]:
    """(route, file, why it is rebuilt) of every bad dataset of the routes (module docstring);
    ``layout``: the other keywords of :func:`route_datasets`; ``windows_routes``: the routes
    with weather windows (a hindcast leg)."""
    out = []
    for route in routes:
        hashes = {}
        for path, name in route_datasets(results, route, windows=route in windows_routes, **layout):
            expected = None
            if name is not None:
                if name not in hashes:
                    hashes[name] = config_hash(cfg, name, route)
                expected = hashes[name]
            why = problem(path, config_sha256=expected)
            if why:
                out.append((route, str(path), why))
        listing = Path(results) / route / "timedomain" / "cells.json"
        if listing.exists():
            names, why = cells_problem(listing)
            if why:
                out.append((route, str(listing), why))
            expected = config_hash(cfg, "timedomain_cell", route)
            for name in names:
                path = listing.parent / f"{name}.nc"
                if path.exists():
                    why = problem(path, config_sha256=expected)
                    if why:
                        out.append((route, str(path), why))
    return out


#: The datasets every route's report is built from (beside those its configuration adds).
REPORT_DATASETS = ("sea_states.nc", "vessel_motion.nc", "response.nc", "operability.nc",
                   "response_variants.nc", "workability.nc", "voyage.nc", "tugger_studies.nc",
                   "timedomain/cells.json")


def _listed(listing: Path) -> list[Path]:
    """The cell files a ``cells.json`` lists (none when it cannot be read: it is then
    named by :func:`problems` and rebuilt)."""
    try:
        with open(listing) as fh:
            return [listing.parent / f"{c['name']}.nc" for c in json.load(fh)]
    except (OSError, ValueError, TypeError, KeyError):
        return []


def missing(results, route: str, report, *, screening: bool, windows: bool, measured: bool,
            verification: bool) -> list[str]:
    """The datasets of a route that are missing while its report exists (a dataset
    deleted by hand): Snakemake, finding the report up to date, would rebuild nothing
    ("Nothing to be done"); the caller sets the report aside so that the missing dataset
    and everything between it and the report are rebuilt. Nothing is missing for a route
    without a report (a first run, or one that stopped: Snakemake builds what is missing)."""
    if not Path(report).exists():
        return []
    base = Path(results) / route
    names = list(REPORT_DATASETS)
    names += ["screening.nc", "plant_assessed.nc"] if screening else ["plant.nc"]
    names += ["weather_windows.nc"] if windows else []
    names += ["measured_response.nc"] if measured else []
    names += ["verification/cells.json"] if verification else []
    paths = [base / n for n in names]
    for listing in ("timedomain/cells.json",) + (("verification/cells.json",) if verification else ()):
        paths += _listed(base / listing)
    return [str(p) for p in paths if not p.exists()]


def symlinks(roots, inner=()) -> list[str]:
    """Symbolic links below the output directories ``roots`` (the roots themselves may be
    links) and at or below the directories ``inner`` (each route's results folder)."""
    found = [str(p) for p in map(Path, inner) if p.is_symlink()]
    for root in list(roots) + [p for p in inner if not Path(p).is_symlink()]:
        root = Path(root)
        if not root.is_dir():
            continue
        for dirpath, dirnames, filenames in os.walk(root):
            for name in dirnames + filenames:
                p = Path(dirpath) / name
                if p.is_symlink():
                    found.append(str(p))
            dirnames[:] = [d for d in dirnames if not (Path(dirpath) / d).is_symlink()]
    return sorted(set(found))


def set_aside(path) -> str:
    """Rename a rejected dataset to ``<file>.rejected`` (replacing an older one) so that the
    workflow rebuilds it; returns the new name."""
    path = Path(path)
    target = path.with_name(path.name + ".rejected")
    os.replace(path, target)
    return str(target)
