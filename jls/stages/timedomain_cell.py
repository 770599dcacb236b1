"""Time-domain cells of a route: which sea-state cells the pipeline runs in the nonlinear
time domain, and the dataset of one cell (``results/<route>/timedomain/<cell>.nc``).

A cell is (rigging candidate, relative heading, Hs, Tz) at the Hs the workability assesses
(bin centre or upper edge); one run per tugger setting, all on one wave record whose
seed follows from the configured seed and the cell itself, so a cell's numbers do not
depend on which other cells run. Cells are chosen (:func:`choose_cells`):

* per leg and time-domain candidate (``timedomain.boundary_candidates``: by default every
  assessed candidate, so the recommendation, chosen among them afterwards, is one; of a
  ``candidate_grid`` the ``timedomain.grid_boundary_candidates`` of highest
  frequency-domain route workability, the grid's others being excluded from the
  recommendation, so that the cells do not grow with the grid), the
  ``timedomain.boundary_cells_per_leg`` cells nearest the workability boundary: the
  relative-sway utilisation nearest 1 (|ln u| smallest over the tugger settings) among
  the cells with non-zero probability;
* under ``assessment.winch_saturation: timedomain``, every cell with non-zero
  probability whose winch saturates in the frequency domain (:mod:`jls.assessment.winch_limits`);
* the cells listed in ``timedomain.cells``.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.winch_limits import apply_winch_limits, saturated_cells
from jls.assessment.workability import assess, assessed_hs
from jls.config.builders import (
    assessed_candidate_plant,
    boundary_candidates,
    candidate_plant,
    candidate_values,
    tuggers_from_config,
)
from jls.errors import InputError
from jls.io import registry
from jls.names import RELATIVE_SWAY
from jls.timedomain.cells import boundary_cells, cell_name, cell_seed
from jls.timedomain.directional import DirectionalCase


def route_cells(sea: xr.Dataset, response: xr.Dataset, cfg, model_legs=()) -> list[dict]:
    """The route's time-domain cells (:func:`choose_cells`) from its sea states and
    frequency-domain statistics: the frequency-domain workability with the winch limits,
    then the choice. ``cfg``: ``assessment`` (criteria, winch_saturation), ``sea``,
    ``tuggers`` and ``timedomain`` (cells, boundary_candidates as names,
    boundary_cells_per_leg, max_cells, ``grid_best``: how many of the other candidates, a
    candidate grid's, join the boundary candidates, the best by route workability). The
    boundary cells are chosen per candidate from that candidate's own utilisation, so
    only the boundary candidates are assessed (a large grid's others would cost their
    whole assessment for no cell) unless a grid's best are ranked or every candidate's
    saturating cells run in the time domain (``winch_saturation: timedomain``)."""
    a, s, td = cfg["assessment"], cfg["sea"], cfg["timedomain"]
    named = boundary_candidates(cfg)
    if a["winch_saturation"] != "timedomain" and not td["grid_best"]:
        response = response.sel(candidate=[c for c in response["candidate"].values if c in set(named)])
    work = assess(response, sea, a["criteria"], hs_in_bin=s["hs_in_bin"],
                  steepness_rule=s["steepness_rule"], gamma=s["gamma"])
    hs = assessed_hs(sea, s["hs_in_bin"])
    work = apply_winch_limits(work, response, sea, tuggers_from_config(cfg), hs, a["winch_saturation"])
    if td["grid_best"]:
        best = best_grid_candidates(work, named, int(td["grid_best"]))
        cfg = {**cfg, "timedomain": {**td, "boundary_candidates": list(named) + best}}
    return choose_cells(work, sea, hs, cfg, model_legs)


def best_grid_candidates(work: xr.Dataset, named, n: int) -> list[str]:
    """The ``n`` candidates not in ``named`` (a candidate grid's) of highest route
    workability over the tugger settings, best first (ties in the dataset's order)."""
    score = work["workability_route"].max("tugger")
    others = [(i, str(c)) for i, c in enumerate(work["candidate"].values) if str(c) not in set(named)]
    ranked = sorted(others, key=lambda ic: (-float(score.values[ic[0]]), ic[0]))
    return [c for _, c in ranked[:n]]


def choose_cells(work: xr.Dataset, sea: xr.Dataset, hs: xr.DataArray, cfg, model_legs=()) -> list[dict]:
    """Every time-domain cell of the route (see module docstring), named and deduplicated
    in a stable order; each carries the reasons it was chosen. A cell chosen for a leg of
    ``model_legs`` (names of the legs of spectrum partitions, measured or torsethaugen) is
    that leg's own (``leg``, its name ending ``__leg-<leg>``): its record is synthesised
    from the leg's sea in the cell (:mod:`jls.timedomain.cell_sea`), not from a JONSWAP."""
    td, policy = cfg["timedomain"], cfg["assessment"]["winch_saturation"]
    chosen = boundary_cells(work, sea, hs, boundary_candidates(cfg), td["boundary_cells_per_leg"])
    if policy == "timedomain" and "winch_saturates" in work:
        hs_of = {(str(leg), float(b)): float(v) for leg in sea["leg"].values
                 for b, v in zip(sea["hs"].values, hs.sel(leg=leg).values)}
        own = {str(x) for x in model_legs}
        for c in saturated_cells(work, sea):
            for leg in work["leg"].values:
                if str(leg) in own and not float(sea["cell_probability"].sel(
                        leg=leg, heading=c["heading"], hs=c["hs_bin"], tz=c["tz"])) > 0:
                    continue                   # a leg's own cell only where the leg has the cell
                chosen.append({"candidate": c["candidate"], "heading": c["heading"],
                               "hs": hs_of[(str(leg), c["hs_bin"])], "tz": c["tz"], "leg": str(leg),
                               "reason": "winch saturates in the frequency domain"})
    for c in td["cells"]:
        chosen.append({"candidate": c["candidate"], "heading": float(c["heading_deg"]),
                       "hs": float(c["hs_m"]), "tz": float(c["tz_s"]), "reason": "configured"})
    out = {}
    own = {str(x) for x in model_legs}
    for c in chosen:
        leg = c.get("leg") if c.get("leg") in own else None
        name = cell_name(c["candidate"], c["heading"], c["hs"], c["tz"], leg)
        if name in out:
            if c["reason"] not in out[name]["reasons"]:
                out[name]["reasons"].append(c["reason"])
        else:
            out[name] = {"name": name, **{k: c[k] for k in ("candidate", "heading", "hs", "tz")},
                         **({"leg": leg} if leg else {}), "reasons": [c["reason"]]}
    limit = td["max_cells"]
    if len(out) > int(limit):
        raise InputError(f"{len(out)} time-domain cells chosen, more than timedomain.max_cells "
                         f"({int(limit)}); raise it, list fewer cells or candidates, or use "
                         "assessment.winch_saturation: fail", field="timedomain.max_cells",
                         value=len(out))
    return list(out.values())


def cell_dataset(cfg, motion: xr.Dataset, cell: dict, source="config", workers=1,
                 plant_ds: xr.Dataset | None = None, leg: dict | None = None, base_dir=".") -> xr.Dataset:
    """Time-domain statistics of one cell for every configured tugger setting on
    ``timedomain.seeds_per_cell`` wave records (layout ``timedomain_cell`` of the registry):
    per tugger the statistics pooled over the records (:func:`jls.timedomain.seeds.pool`),
    per tugger and seed sigma and MPM with their mean and spread, the spread random
    amplitudes should give, the frequency-domain sigma and the bias of the record's
    component grid (:mod:`jls.timedomain.resolution`), and a ``trace_s`` window of the
    relative sway from the middle of the first record. A record too coarse for the sway
    resonance is an InputError naming the key that set its length. The tugger settings'
    runs go to ``workers`` threads (the compiled integrator releases the GIL); the result
    does not depend on their number. ``plant_ds``: the assessed plant (``plant_assessed.nc``),
    for a candidate no configuration lists (the screening's ``optimised``). A cell of a leg
    whose sea is its own (``cell["leg"]``; ``leg``: that leg's configuration, its files
    under ``base_dir``) runs on the multi-directional record of the leg's sea in the cell
    (:mod:`jls.timedomain.cell_sea`, :class:`jls.timedomain.directional.DirectionalCase`),
    its ``sigma_fd`` that sea's frequency-domain sigma
    (:func:`jls.response.sea_state.sea_state_statistics`, the same spreading)."""
    from jls.config.builders import settings_from_config, tuggers_from_config
    from jls.timedomain.resolution import linear_grid, require_resolution
    from jls.timedomain.run import Case, cells_dataset, frequency_domain_sigma, record_spacing
    from jls.timedomain.seeds import pool, record_seed, run_seeds, spread
    td = cfg["timedomain"]
    settings = settings_from_config(cfg)
    plant = (candidate_plant(cfg, cell["candidate"], source)
             if plant_ds is None or cell["candidate"] in candidate_values(cfg)
             else assessed_candidate_plant(cfg, plant_ds, cell["candidate"], source))
    tuggers = list(tuggers_from_config(cfg, source).values())
    duration_h = td.get("duration_h") or cfg["assessment"]["exposure_h"]
    field = ("timedomain.n_components" if settings.n_components else
             "timedomain.duration_h" if td.get("duration_h") else "assessment.exposure_h")
    om = motion["omega"].values
    require_resolution(plant, record_spacing(plant, settings, duration_h * 3600.0, (om.min(), om.max())),
                       field=field, value=settings.n_components or duration_h, source=source)
    gamma = cfg["sea"]["gamma"]
    base = cell_seed(settings.seed, cell)
    own = _own_sea(cfg, cell, leg, base_dir)

    def make(j):
        if own is not None:
            return DirectionalCase(plant, motion, own[0], own[1], duration_s=duration_h * 3600.0,
                                   settings=settings, seed=record_seed(base, j))
        return Case(plant, motion, cell["hs"], cell["tz"], cell["heading"], gamma=gamma,
                    duration_s=duration_h * 3600.0, settings=settings, seed=record_seed(base, j))

    n_seeds = int(td["seeds_per_cell"])
    runs, case = run_seeds(make, tuggers, n_seeds, workers, keep_first=True)
    pooled = [pool([seed[i] for seed in runs], case.duration) for i in range(len(tuggers))]
    data = {k: np.array([[p[k] for p in pooled]]) for k in pooled[0]}
    if own is None:
        fd = frequency_domain_sigma(plant, motion, tuggers, cell["hs"], cell["tz"], cell["heading"], gamma)
    else:
        fd = directional_sigma(cfg, cell["candidate"], plant_ds, motion, tuggers, own[0], own[1])
    ds = cells_dataset(data, fd[None, :], np.array([cell["hs"]]), np.array([cell["tz"]]),
                       tuggers, cell["heading"], case, gamma).isel(cell=0, drop=True)
    ds = ds.drop_vars(["hs", "tz"], errors="ignore")
    real = case.realisation
    if own is None:
        lin = linear_grid(plant, motion, tuggers, real.omega, real.d_omega, cell["hs"], cell["tz"],
                          cell["heading"], gamma)
    else:
        lin = directional_grid(plant, motion, tuggers, case)
    ds["sigma_grid_bias"] = ("tugger", lin["sigma"] / fd - 1.0)
    ds["n_independent_components"] = ("tugger", lin["n_eff"])
    expected = lin["sigma"] / (2.0 * np.sqrt(lin["n_eff"])) if settings.amplitudes == "rayleigh" \
        else np.zeros(len(tuggers))
    if "draw_std" in lin:            # a multi-directional record: its direction draws scatter too
        expected = np.sqrt(expected**2 + lin["draw_std"] ** 2)
    ds["sigma_seed_std_expected"] = ("tugger", expected)
    ds = ds.assign_coords(seed=np.arange(n_seeds))
    for k, v in spread(runs).items():
        ds[k] = (("tugger", "seed") if v.ndim == 2 else ("tugger",), v)
    first = runs[0]
    t = first[0]["time"]
    n = int(round(float(td["trace_s"]) / case.dt))
    keep = t >= 0
    mid = int(np.flatnonzero(keep)[0] + max(keep.sum() - n, 0) // 2)
    window = slice(mid, mid + n)
    ds = ds.assign_coords(time=t[window] - t[window][0] if n else np.zeros(0))
    ds["trace_relative_sway"] = (("tugger", "time"), np.array([r[RELATIVE_SWAY][window] for r in first]))
    registry.annotate(ds, "timedomain_cell")
    ds.attrs.update(sea=own[2] if own is not None else
                    f"JONSWAP (gamma {float(gamma):g}) on Hs {float(cell['hs']):g} m, Tz {float(cell['tz']):g} s, "
                    f"long-crested at {float(cell['heading']):g} deg",
                    sea_leg=cell.get("leg", ""))
    ds.attrs.update(cell=cell_name(cell["candidate"], cell["heading"], cell["hs"], cell["tz"], cell.get("leg")),
                    candidate=cell["candidate"], hs_m=float(cell["hs"]), tz_s=float(cell["tz"]),
                    trace_start_s=float(t[mid]), seeds_per_cell=n_seeds,
                    statistics=f"per tugger pooled over {n_seeds} records of {case.duration:g} s "
                               "(sigma from the mean variance, MPMs for one record's duration, "
                               "counts summed, fractions averaged, extremes over all)",
                    record_warning=record_warning(ds),
                    # the sway mode, for the standard error of the MPM (winch_limits)
                    sway_damping_ratio=float(np.ravel(plant.damping_ratio)[0]),
                    sway_natural_period_s=float(np.ravel(plant.modes.period)[0]))
    return ds


def _own_sea(cfg, cell, leg, base_dir):
    """(systems, course, description) of a cell of a leg whose sea is its own, else None."""
    if not cell.get("leg"):
        return None
    from jls.timedomain.cell_sea import cell_systems
    if leg is None or leg.get("name") != cell["leg"]:
        raise InputError("the cell is a leg's own: its leg's configuration is needed", field="cell",
                         value=cell_name(cell["candidate"], cell["heading"], cell["hs"], cell["tz"], cell["leg"]))
    return cell_systems(leg, cell, sea=cfg["sea"], gamma=float(cfg["sea"]["gamma"]), base_dir=base_dir)


def directional_sigma(cfg, candidate, plant_ds, motion, tuggers, systems, course) -> np.ndarray:
    """sigma of the relative sway per tugger of the sea of ``systems`` met on ``course``, from
    the frequency-domain response of a sea of several spread systems
    (:func:`jls.response.sea_state.sea_state_statistics`, no winch limits)."""
    from jls.config.builders import rigging_from_config
    from jls.names import SWAY_M
    from jls.plant.candidates import plant_dataset
    from jls.response.sea_state import sea_state_statistics, sea_state_transfer
    from jls.sea.sea_state import SeaState
    if plant_ds is not None and candidate in [str(c) for c in plant_ds["candidate"].values]:
        pds = plant_ds.sel(candidate=[candidate])
    else:
        pds, _ = plant_dataset(rigging_from_config(cfg), {candidate: candidate_values(cfg)[candidate]})
    tr = sea_state_transfer(pds, motion, {t.name: float(t.c) for t in tuggers},
                            cfg["response"]["omega_step_rad_s"], cfg["vessel"]["outside_rao_range"])
    st = sea_state_statistics(tr, [SeaState(tuple(systems))], float(course))
    return st["sigma"].sel(criterion=SWAY_M).values[0, 0, :]


def directional_grid(plant, motion, tuggers, case) -> dict:
    """The linear model on a multi-directional record's components and draws, per tugger:
    ``sigma`` (its expected value over the direction draws, on the component grid) and
    ``n_eff`` (the independent components of the relative sway) and ``draw_std`` (the
    standard deviation of a record's sigma over independent direction draws,
    :func:`jls.timedomain.directional.direction_spread`; an upper bound for the stratified
    draws)."""
    from jls.response.solver import relative_power
    from jls.timedomain.directional import heading_shares
    from jls.timedomain.sea import independent_components
    from jls.vessel.transfer import motion_on_grid
    real = case.realisation
    gm = motion_on_grid(motion, case.headings, real.omega)
    P = relative_power(plant.M, plant.K, plant.Kb, plant.C, real.omega, gm.hinge, gm.fairlead_sway,
                       [t.c for t in tuggers])[0, :, :, 0, :]                    # (tugger, n_h, n_w)
    A = heading_shares(case.systems, case.course, case.headings, real.omega,
                       symmetric=bool(case.headings.max() <= 180.0 + 1e-9))      # (n_w, n_h)
    a2 = 0.5 * real.amplitude**2
    v = np.einsum("wh,thw->tw", A, P) * a2                                       # (tugger, n_w)
    v2 = np.einsum("wh,thw->tw", A, P**2) * a2**2
    sigma = np.sqrt(v.sum(axis=1))
    draws = np.sqrt(np.maximum(v2 - v**2, 0.0).sum(axis=1))                      # std of sigma^2
    return {"sigma": sigma, "n_eff": np.array([independent_components(r) for r in v]),
            "draw_std": np.where(sigma > 0, draws / (2.0 * np.where(sigma > 0, sigma, 1.0)), 0.0)}


def record_warning(ds: xr.Dataset, bias_limit=0.01) -> str:
    """A page-1 sentence when the record's component grid biases sigma by more than
    ``bias_limit`` for some setting, or a line touches its fairlead; empty otherwise."""
    out = []
    bias = ds["sigma_grid_bias"].values
    if np.nanmax(np.abs(bias)) > bias_limit:
        i = int(np.nanargmax(np.abs(bias)))
        out.append(f"the wave record's component grid ({ds.attrs['components_per_bandwidth']:.2f} per "
                   f"sway half-power bandwidth) biases sigma by {100 * bias[i]:+.1f} % "
                   f"(tugger {ds['tugger'].values[i]})")
    contact = ds["line_contact_fraction"].values
    if np.nanmax(contact) > 0:
        i = int(np.nanargmax(contact))
        out.append(f"a tugger line reaches its fairlead ({100 * contact[i]:.2f} % of the time, "
                   f"tugger {ds['tugger'].values[i]}): the jacket meets the fairlead and the "
                   "line model does not hold there")
    return "; ".join(out)


__all__ = ["route_cells", "choose_cells", "cell_dataset", "record_warning", "directional_sigma", "directional_grid"]
