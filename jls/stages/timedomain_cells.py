"""Time-domain cells of a route: which sea-state cells the pipeline runs in the nonlinear
time domain, and the dataset of one cell (``results/<route>/timedomain/<cell>.nc``).

A cell is (rigging candidate, relative heading, Hs, Tz) at the Hs the workability assesses
(bin centre or upper edge); one run per tugger setting, all on one wave record whose
seed follows from the configured seed and the cell itself, so a cell's numbers do not
depend on which other cells run. Cells are chosen (:func:`choose_cells`):

* per leg and time-domain candidate (``timedomain.boundary_candidates``), the
  ``timedomain.boundary_cells_per_leg`` cells nearest the workability boundary: the
  relative-sway utilisation nearest 1 (|ln u| smallest over the tugger settings) among
  the cells with non-zero probability;
* under ``assessment.winch_saturation: timedomain``, every cell with non-zero
  probability whose winch saturates in the frequency domain (:mod:`jls.stages.winch_limits`);
* the cells listed in ``timedomain.cells``.
"""

from __future__ import annotations

import zlib

import numpy as np
import xarray as xr

from jls import registry
from jls.errors import InputError
from jls.stages.winch_limits import saturated_cells
from jls.threads import thread_map

SEP = "__"


def cell_name(candidate, heading, hs, tz) -> str:
    """File stem of a cell, e.g. ``baseline__h90__hs2.25__tz7.5``."""
    return f"{candidate}{SEP}h{float(heading):g}{SEP}hs{float(hs):g}{SEP}tz{float(tz):g}"


def parse_cell(name: str) -> dict:
    """Inverse of :func:`cell_name`."""
    parts = str(name).split(SEP)
    if len(parts) != 4 or not (parts[1].startswith("h") and parts[2].startswith("hs")
                               and parts[3].startswith("tz")):
        raise InputError("a time-domain cell is named candidate__h<heading>__hs<Hs>__tz<Tz>",
                         field="cell", value=name)
    return {"candidate": parts[0], "heading": float(parts[1][1:]), "hs": float(parts[2][2:]),
            "tz": float(parts[3][2:])}


def boundary_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, candidates,
                   per_leg=1) -> list[dict]:
    """Per leg and candidate, the ``per_leg`` live cells whose relative-sway utilisation
    is nearest 1 (smallest |ln u| over the tugger settings)."""
    if per_leg <= 0 or "relative_sway_m" not in work["criterion"].values:
        return []
    u = work["utilisation"].sel(criterion="relative_sway_m", drop=True)
    with np.errstate(divide="ignore", invalid="ignore"):
        dist = np.abs(np.log(u)).min("tugger")
    live = sea["cell_probability"] > 0
    out = []
    for cand in candidates:
        if cand not in work["candidate"].values:
            continue
        for leg in work["leg"].values:
            d = dist.sel(candidate=cand, leg=leg).where(live.sel(leg=leg)).transpose("heading", "hs", "tz")
            flat = d.values.ravel()
            order = [i for i in np.argsort(np.where(np.isfinite(flat), flat, np.inf), kind="stable")
                     if np.isfinite(flat[i])][:per_leg]
            for i in order:
                ih, ihs, itz = np.unravel_index(i, d.shape)
                out.append({"candidate": str(cand), "heading": float(d["heading"].values[ih]),
                            "hs": float(hs.sel(leg=leg).values[ihs]), "tz": float(d["tz"].values[itz]),
                            "reason": f"nearest the workability boundary, leg {leg}"})
    return out


def choose_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, cfg) -> list[dict]:
    """Every time-domain cell of the route (see module docstring), named and deduplicated
    in a stable order; each carries the reasons it was chosen."""
    td, policy = cfg["timedomain"], cfg["assessment"]["winch_saturation"]
    chosen = boundary_cells(work, sea, hs, td["boundary_candidates"], td["boundary_cells_per_leg"])
    if policy == "timedomain" and "winch_saturates" in work:
        hs_of = {(str(leg), float(b)): float(v) for leg in sea["leg"].values
                 for b, v in zip(sea["hs"].values, hs.sel(leg=leg).values)}
        for c in saturated_cells(work, sea):
            for leg in work["leg"].values:
                chosen.append({"candidate": c["candidate"], "heading": c["heading"],
                               "hs": hs_of[(str(leg), c["hs_bin"])], "tz": c["tz"],
                               "reason": "winch saturates in the frequency domain"})
    for c in td["cells"]:
        chosen.append({"candidate": c["candidate"], "heading": float(c["heading_deg"]),
                       "hs": float(c["hs_m"]), "tz": float(c["tz_s"]), "reason": "configured"})
    out = {}
    for c in chosen:
        name = cell_name(c["candidate"], c["heading"], c["hs"], c["tz"])
        if name in out:
            if c["reason"] not in out[name]["reasons"]:
                out[name]["reasons"].append(c["reason"])
        else:
            out[name] = {"name": name, **{k: c[k] for k in ("candidate", "heading", "hs", "tz")},
                         "reasons": [c["reason"]]}
    limit = td["max_cells"]
    if len(out) > int(limit):
        raise InputError(f"{len(out)} time-domain cells chosen, more than timedomain.max_cells "
                         f"({int(limit)}); raise it, list fewer cells or candidates, or use "
                         "assessment.winch_saturation: fail", field="timedomain.max_cells",
                         value=len(out))
    return list(out.values())


def candidate_plant(cfg, name: str, source="config"):
    """The geometric plant (:func:`jls.plant.build`) of one rigging candidate."""
    from jls import modes as modes_mod, plant as plant_mod
    from jls.assembly import rigging_from_config
    from jls.rigging import apply_design
    from jls.stages.plant import SUFFIX, candidate_values
    if cfg.get("plant_matrices"):
        raise InputError("the time-domain model needs the wire geometry; a plant given as "
                         "matrices has none", file=source, field="plant_matrices")
    values = candidate_values(cfg)
    if name not in values:
        raise InputError(f"no such rigging candidate (configured: {', '.join(values)})",
                         file=source, field="timedomain.boundary_candidates", value=name)
    rig = rigging_from_config(cfg)
    layout = apply_design(rig.layout, rig.jacket.z_p, **{k.removesuffix(SUFFIX): float(v)
                                                         for k, v in values[name].items()})
    p = plant_mod.build(layout, rig.jacket, rig.wire_stiffness, g=rig.g, zeta=rig.zeta,
                        anchor_modes=rig.anchor_modes)
    plant_mod.require_taut(p, rig.wire_names, source)
    modes_mod.require_stable(p.modes)
    return p


def cell_seed(seed: int, cell: dict) -> tuple:
    """Seed of a cell's wave record: the configured seed and a checksum of the cell."""
    return (int(seed), zlib.crc32(cell_name(cell["candidate"], cell["heading"], cell["hs"],
                                            cell["tz"]).encode()))


def cell_dataset(cfg, motion: xr.Dataset, cell: dict, source="config", workers=1) -> xr.Dataset:
    """Time-domain statistics of one cell for every configured tugger setting, with the
    frequency-domain sigma alongside and a ``trace_s`` window of the relative sway from the
    middle of each record (layout ``timedomain_cell`` of the registry). The tugger
    settings' runs go to ``workers`` threads (the compiled integrator releases the GIL);
    the result does not depend on their number."""
    from jls.timedomain.run import Case, cells_dataset, frequency_domain_sigma, settings_from_config
    from jls.tugger import tuggers_from_config
    td = cfg["timedomain"]
    settings = settings_from_config(cfg)
    plant = candidate_plant(cfg, cell["candidate"], source)
    tuggers = list(tuggers_from_config(cfg, source).values())
    duration_h = td.get("duration_h") or cfg["assessment"]["exposure_h"]
    gamma = cfg["sea"]["gamma"]
    case = Case(plant, motion, cell["hs"], cell["tz"], cell["heading"], gamma, duration_h * 3600.0,
                settings, seed=cell_seed(settings.seed, cell))
    runs = thread_map(lambda t: case.run(t, keep_record=True), tuggers, workers)
    keys = [k for k in runs[0] if k not in ("time", "relative_sway")]
    data = {k: np.array([[r[k] for r in runs]]) for k in keys}
    fd = frequency_domain_sigma(plant, motion, tuggers, cell["hs"], cell["tz"], cell["heading"], gamma)
    ds = cells_dataset(data, fd[None, :], np.array([cell["hs"]]), np.array([cell["tz"]]),
                       tuggers, cell["heading"], case, gamma).isel(cell=0, drop=True)
    ds = ds.drop_vars(["hs", "tz"], errors="ignore")
    t = runs[0]["time"]
    n = int(round(float(td["trace_s"]) / case.dt))
    keep = t >= 0
    mid = int(np.flatnonzero(keep)[0] + max(keep.sum() - n, 0) // 2)
    window = slice(mid, mid + n)
    ds = ds.assign_coords(time=t[window] - t[window][0] if n else np.zeros(0))
    ds["trace_relative_sway"] = (("tugger", "time"), np.array([r["relative_sway"][window] for r in runs]))
    registry.annotate(ds, "timedomain_cell")
    ds.attrs.update(cell=cell_name(cell["candidate"], cell["heading"], cell["hs"], cell["tz"]),
                    candidate=cell["candidate"], hs_m=float(cell["hs"]), tz_s=float(cell["tz"]),
                    trace_start_s=float(t[mid]))
    return ds


__all__ = ["cell_name", "parse_cell", "boundary_cells", "choose_cells", "candidate_plant",
           "cell_dataset", "cell_seed"]
