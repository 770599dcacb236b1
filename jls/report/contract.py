"""What the report reads from the five datasets, checked before anything is drawn.

:func:`check` verifies that every variable the report uses exists with the dimensions of
docs/reference/outputs.md (in any order) and that the datasets describe the same candidates,
tuggers, legs and headings; a violation is an :class:`~jls.errors.InputError` naming
the dataset and the variables, raised before a figure is made or a file written.

:func:`digest` turns the datasets into the numbers the text quotes: the baseline and
best combinations, the governing criterion, the cells outside the linear range and
a cross-check of the workability against the pass flags, the constraints met only at
their limit and the datasets made with another configuration. The operability curves
are read by :mod:`jls.report.curves`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from jls.assessment.recommendation import best_with_ties, recommend, smallest_margin, tie_tolerance
from jls.assessment.workability import assessed_hs
from jls.errors import InputError
from jls.io import registry
from jls.names import CRITERIA, RELATIVE_ROLL, RELATIVE_SWAY, RELATIVE_YAW, SWAY_M, WIRE_TENSION_CRITERION
from jls.report.choices import Selection, dot_selection, plot_selection, table_selection

C, T, L, H = "candidate", "tugger", "leg", "heading"
#: What the report reads from each dataset; their dimensions come from the registry
#: (jls/schemas/datasets.yaml), the one place dataset layouts are defined.
READS = {
    "sea_states": ["probability", "hs_lower", "hs_upper", "tz_lower", "tz_upper", "steep",
                   "steep_probability", "heading_probability", "cell_probability", "duration_h",
                   "leg_weight"],
    "vessel_motion": ["rao", "hinge"],
    "plant": ["natural_period", "damping_ratio", "energy_fraction", "tension",
              "unstretched_length", "anchor", "padeye", "cog_depth", "top_spread_y",
              "bottom_spread_y", "bottom_spread_x", "drop_height", "side_lead_margin",
              "fore_aft_lead_margin", "splash_clearance_margin", "equilibrium_residual",
              "feasible"],
    "response": ["transfer", "mpm"],
    "workability": ["mpm", "passes", "workability_leg", "workability_route", "governing_share",
                    "hs_limit", "hs_limit_criterion", "steepness_limit", "limit"],
}
#: What the report reads from the datasets it may be given (checked when given).
OPTIONAL_READS = {
    "voyage": ["exceedance_probability", "voyage_level", "exceedance_probability_any", "limit"],
    "measured_response": ["sigma_ratio", "sigma_measured", "sigma_jonswap", "hours"],
    "voyage_plan": ["design_level", "design_utilisation", "design_acceptable", "limit", "leg_stretch",
                    "leg_hold_point", "master_hs_opwf"],
}
REQUIRED = {name: {var: dims[var] for var in names}          # one registry look-up per dataset
            for name, names in READS.items() for dims in [registry.dims(name)]}
OPTIONAL = {name: {var: dims[var] for var in names}
            for name, names in OPTIONAL_READS.items() for dims in [registry.dims(name)]}
REQUIRED["response"]["c_tugger"] = (T,)          # a coordinate the report reads as a variable
LINEAR_SWAY_FACTOR = 2.0      # MPM relative sway beyond this multiple of its limit
LINEAR_ANGLE_DEG = 5.0        # MPM relative roll or yaw beyond this
# An amplitude below this fraction of the largest amplitude of the same kind (translation
# or rotation) at the same heading is floating-point round-off: it is shown as zero.
ROUNDOFF_RELATIVE = 1e-9


def complex_var(ds: xr.Dataset, name: str) -> xr.DataArray | None:
    """``name`` as one complex variable, whether stored whole or as _re/_im."""
    if name in ds:
        return ds[name]
    if f"{name}_re" in ds and f"{name}_im" in ds:
        return ds[f"{name}_re"] + 1j * ds[f"{name}_im"]
    return None


def flag(da: xr.DataArray) -> xr.DataArray:
    """An int8/bool/float flag as bool (NaN -> False)."""
    return da.fillna(0) > 0.5


def on_sea_grid(da: xr.DataArray, sea: xr.Dataset) -> xr.DataArray:
    """``da`` at the scatter's Hs and Tz centres (matched to 1e-6, NaN where absent)."""
    for dim in ("hs", "tz"):
        if dim in da.dims:
            da = da.reindex({dim: sea[dim].values}, method="nearest", tolerance=1e-6)
    return da


def check(datasets: dict, optional: dict | None = None) -> None:
    """Raise InputError unless the datasets carry what the report needs; ``optional``:
    name -> dataset or None, the datasets of :data:`OPTIONAL_READS` (checked when given)."""
    problems = []
    given = {k: v for k, v in (optional or {}).items() if v is not None}
    wanted_all = {**REQUIRED, **{k: OPTIONAL[k] for k in given}}
    for name, wanted in wanted_all.items():
        ds = datasets.get(name, given.get(name))
        if not isinstance(ds, xr.Dataset):
            raise InputError(f"expected an xarray.Dataset, got {type(ds).__name__}", field=name)
        missing, bad_dims = [], []
        for var, dims in wanted.items():
            da = complex_var(ds, var)
            if da is None:
                missing.append(var)
            elif set(da.dims) != set(dims):
                bad_dims.append(f"{var} {tuple(da.dims)} (expected {dims})")
        if missing:
            problems.append(f"{name}: missing variable(s) {', '.join(missing)}")
        if bad_dims:
            problems.append(f"{name}: wrong dimensions {'; '.join(bad_dims)}")
    if problems:
        raise InputError("the datasets do not follow docs/reference/outputs.md: " + " | ".join(problems),
                         field="report")
    sea, work, plant, resp = (datasets[k] for k in ("sea_states", "workability", "plant", "response"))
    pairs = [("leg", sea, work), ("candidate", work, plant), ("candidate", work, resp),
             ("tugger", work, resp), ("heading", work, sea), ("heading", work, resp)]
    if "voyage" in given:
        pairs += [("candidate", work, given["voyage"]), ("tugger", work, given["voyage"])]
    if "voyage_plan" in given:
        pairs += [("candidate", work, given["voyage_plan"]), ("tugger", work, given["voyage_plan"])]
    for dim, a, b in pairs:
        extra = sorted(set(a[dim].values.tolist()) - set(b[dim].values.tolist()))
        if extra:
            raise InputError(f"{dim} value(s) {extra} are missing from the other dataset",
                             field=dim)
    if set(sea["leg"].values.tolist()) != set(work["leg"].values.tolist()):
        raise InputError("sea_states and workability have different legs", field="leg")


def pct(x: float) -> str:
    """A fraction as a percentage with one decimal (non-breaking space before %)."""
    return "n/a" if not np.isfinite(x) else f"{100.0 * float(x):.1f}\u00a0%"


def criterion_label(name: str) -> str:
    """'relative_sway_m' -> 'relative sway'."""
    base = name
    for suffix in ("_m", "_deg", "_kN"):
        base = base.removesuffix(suffix)
    return base.replace("_", " ")


def limit_text(dg: "Digest", c: str) -> str:
    """A criterion's limit with its unit: '3 m' or '2°'; the wire-tension criterion's floor
    as a share of the static tension."""
    if c == WIRE_TENSION_CRITERION:
        return f"{100 * dg.limits[c]:g}\u00a0% of the static tension"
    return f"{dg.limits[c]:g}°" if dg.units[c] == "degree" else f"{dg.limits[c]:g} {dg.units[c]}"


@dataclass
class Digest:
    """The numbers and choices the text and figures share.

    ``combos`` is every candidate x tugger (the tables show all of them); ``plot`` is
    what a figure can show distinctly, with its selection rule."""

    route: str
    baseline: str
    no_tugger: str
    best: tuple
    best_any: tuple
    candidates: list
    tuggers: list
    combos: list
    plot: Selection
    table: Selection                 # the combinations per-combination tables list
    dots: Selection
    criteria: list
    limits: dict
    units: dict
    governing: dict                  # combo -> route-weighted share per criterion
    exposure_h: float
    mpm_cycles: str
    hs_in_bin: str
    ties: list = field(default_factory=list)     # combinations tied with ``best``
    ties_any: list = field(default_factory=list)
    at_limit: dict = field(default_factory=dict)     # candidate -> "" or what is at its limit
    infeasible: dict = field(default_factory=dict)   # candidate -> "" or why not feasible
    excluded: dict = field(default_factory=dict)     # combo -> why the recommendation skips it
    margins: dict = field(default_factory=dict)      # candidate -> smallest relative safety margin
    tie_tolerance: float = 0.0                       # route workabilities this close are tied
    tugger_min_gain: float = 0.0                     # a tugger must add more than this
    linear: dict = field(default_factory=dict)   # combo -> flagged-cell statistics
    recheck: float = 0.0
    hash_mismatch: list = field(default_factory=list)
    hash_basis: str = "configuration"            # what the dataset hashes were compared with
    same_config: dict = field(default_factory=dict)  # dataset -> True / False / None (no hash)

    def governing_name(self, combo) -> str | None:
        share = self.governing[combo]
        if not share or max(share.values()) <= 0:
            return None
        return max(share, key=share.get)


def _no_tugger(resp: xr.Dataset, tuggers) -> str:
    c = resp["c_tugger"].sel(tugger=tuggers)
    return str(c["tugger"].values[int(np.argmin(np.abs(c.values)))])


def linear_ranges(sea, resp, work, hs_in_bin) -> dict:
    """Cells outside the range of the linear model, for every combination at once.

    A cell is flagged when its MPM relative sway exceeds LINEAR_SWAY_FACTOR times the
    relative-sway limit, or its MPM relative roll or yaw exceeds LINEAR_ANGLE_DEG.
    Returns {(candidate, tugger): statistics}.
    """
    cands = work["candidate"].values
    tugs = work["tugger"].values
    unit = on_sea_grid(resp["mpm"].sel(candidate=cands, tugger=tugs), sea)
    mpm = assessed_hs(sea, hs_in_bin) * unit
    limit = work["limit"]
    sway = [str(c) for c in limit["criterion"].values if str(c) == SWAY_M]
    sway_lim = float(limit.sel(criterion=sway[0])) if sway else 3.0
    big = xr.zeros_like(mpm.isel(response=0), dtype=bool)
    if RELATIVE_SWAY in mpm["response"].values:
        big = big | (mpm.sel(response=RELATIVE_SWAY) > LINEAR_SWAY_FACTOR * sway_lim)
    for r in (RELATIVE_ROLL, RELATIVE_YAW):
        if r in mpm["response"].values:
            big = big | (abs(mpm.sel(response=r)) > LINEAR_ANGLE_DEG)
    weight = sea["cell_probability"]
    live = weight > 0
    passes = flag(on_sea_grid(work["passes"].sel(candidate=cands, tugger=tugs), sea))
    flagged = big & live
    cells = ("heading", "hs", "tz")
    leg_p = (weight * flagged).sum(cells)
    route_p = (leg_p * sea["leg_weight"]).sum("leg")
    n_cells = flagged.sum(("leg",) + cells)
    n_pass = (flagged & passes).sum(("leg",) + cells)
    pass_p = ((weight * (flagged & passes)).sum(cells) * sea["leg_weight"]).sum("leg")
    legs = [str(v) for v in leg_p["leg"].values]
    ct = ("candidate", "tugger")
    n_cells, n_pass, route_p, pass_p = (a.transpose(*ct).values for a in (n_cells, n_pass, route_p, pass_p))
    leg_p = leg_p.transpose(*ct, "leg").values
    flagged = flagged.transpose(*ct, ...)
    n_live = int(live.sum())
    out = {}
    for i, c in enumerate(cands):
        for j, tg in enumerate(tugs):
            out[(str(c), str(tg))] = {
                "cells": int(n_cells[i, j]), "live_cells": n_live,
                "route_probability": float(route_p[i, j]),
                "leg_probability": dict(zip(legs, map(float, leg_p[i, j]))),
                "passing_cells": int(n_pass[i, j]),
                "passing_probability": float(pass_p[i, j]),
                "sway_threshold": LINEAR_SWAY_FACTOR * sway_lim, "sway_limit_found": bool(sway),
                "mask": flagged[i, j]}
    return out


def _text_var(plant, name) -> list:
    """A per-candidate string variable of plant.nc as text per candidate ('' when empty),
    or [] when absent."""
    if name not in plant:
        return []
    out = []
    for v in plant[name].transpose("candidate").values.tolist():
        v = v.decode() if isinstance(v, bytes) else v
        out.append("" if v is None or (isinstance(v, float) and not np.isfinite(v)) else str(v).strip())
    return out


def constraint_flags(plant: xr.Dataset) -> tuple[dict, dict]:
    """({candidate: what is at its limit}, {candidate: why it is not feasible}), as the
    plant dataset states them (``at_limit``, ``infeasible_reason``; jls.plant.feasibility),
    each variable read once (a ``.sel`` per candidate cost a 10 000-candidate grid seconds)."""
    cands = [str(c) for c in plant["candidate"].values]
    feasible = np.asarray(flag(plant["feasible"]).transpose("candidate").values, bool)
    at_limit = _text_var(plant, "at_limit") or [""] * len(cands)
    reason = _text_var(plant, "infeasible_reason") or [""] * len(cands)
    at = dict(zip(cands, at_limit))
    why = {c: "" if ok else r for c, ok, r in zip(cands, feasible, reason)}
    return at, why


def negligible(amplitude, reference) -> bool:
    """True when every value of ``amplitude`` is round-off against ``reference`` (the
    largest amplitude of the same kind): at most ROUNDOFF_RELATIVE of it, or zero."""
    a = float(np.nanmax(np.abs(np.asarray(amplitude, float)))) if np.size(amplitude) else 0.0
    return a == 0.0 or a <= ROUNDOFF_RELATIVE * float(reference)


def reference_amplitude(vessel: xr.Dataset, heading, rotation: bool) -> float:
    """Largest vessel RAO amplitude of one kind at a heading: rotations [rad/m] (roll,
    pitch, yaw) or translations [m/m] (surge, sway, heave) - the scale round-off is
    judged against."""
    rao = complex_var(vessel, "rao").sel(heading=heading)
    dofs = ("roll", "pitch", "yaw") if rotation else ("surge", "sway", "heave")
    present = [d for d in dofs if d in rao["vessel_dof"].values]
    return float(np.nanmax(np.abs(rao.sel(vessel_dof=present).values))) if present else 0.0


DATASET_NAMES = ("sea_states", "vessel_motion", "plant", "response", "workability")


def config_comparison(datasets: dict, provenance: dict) -> tuple[dict, str]:
    """Whether each dataset was made with the report's configuration.

    Each dataset's ``config_sha256`` is compared with the report's hash of the same
    configuration sections, ``provenance['config_sha256_datasets'][name]``; only when that
    mapping is absent, with the hash of the whole configuration. Returns
    ({name: True / False / None (not comparable)}, basis of the comparison).
    """
    per = provenance.get("config_sha256_datasets")
    whole = provenance.get("config_sha256")
    out = {}
    for name in DATASET_NAMES:
        got = datasets[name].attrs.get("config_sha256")
        want = per.get(name) if isinstance(per, dict) else whole
        out[name] = None if not (got and want) else str(got) == str(want)
    basis = ("the configuration sections each dataset depends on" if isinstance(per, dict)
             else "the whole configuration")
    return out, basis


def digest(route: str, sea, vessel, plant, resp, work, provenance) -> Digest:
    cands = [str(c) for c in work["candidate"].values]
    tugs = [str(t) for t in work["tugger"].values]
    baseline = "baseline" if "baseline" in cands else cands[0]
    no_tug = _no_tugger(resp, tugs)
    c_tug = {t: float(resp["c_tugger"].sel(tugger=t)) for t in tugs}
    combos = [(c, t) for c in cands for t in tugs]
    margins = smallest_margin(plant)
    best_any, ties_any = best_with_ties(work, combos, baseline, c_tug, margins)
    best, ties, excluded = recommend({"plant": plant, "response": resp, "workability": work,
                                      "sea_states": sea}, cands, tugs, c_tug)
    plot = plot_selection(work, cands, tugs, baseline, no_tug, best, work.sizes["heading"])
    crit = [str(c) for c in work["criterion"].values]
    limits = {c: float(work["limit"].sel(criterion=c)) for c in crit}
    units = {c: CRITERIA[c][1] for c in crit}
    share = (work["governing_share"] * sea["leg_weight"]).sum("leg").transpose(
        "candidate", "tugger", "criterion")
    governing = {(str(c), str(tg)): dict(zip(crit, map(float, share.values[i, j])))
                 for i, c in enumerate(share["candidate"].values)
                 for j, tg in enumerate(share["tugger"].values)}
    exposure = work.attrs.get("exposure_h", resp.attrs.get("exposure_h", np.nan))
    cycles = work.attrs.get("mpm_cycles", resp.attrs.get("mpm_cycles", "not stated"))
    hs_in_bin = str(work.attrs.get("hs_in_bin", "centre"))
    at_limit, infeasible = constraint_flags(plant)
    d = Digest(route=route, baseline=baseline, no_tugger=no_tug, best=best, best_any=best_any,
               candidates=cands, tuggers=tugs, combos=combos, plot=plot,
               table=table_selection(work, combos, baseline, best, ties),
               dots=dot_selection(work, cands, tugs, baseline, no_tug, best), criteria=crit,
               limits=limits, units=units, governing=governing, exposure_h=float(exposure),
               mpm_cycles=str(cycles), hs_in_bin=hs_in_bin, ties=ties, ties_any=ties_any,
               at_limit=at_limit, infeasible=infeasible, excluded=excluded, margins=margins,
               tie_tolerance=tie_tolerance(work),
               tugger_min_gain=float(work.attrs["tugger_min_gain"]))
    d.linear = linear_ranges(sea, resp, work, hs_in_bin)
    # cross-check: workability recomputed from the pass flags and the probabilities (a leg
    # judged hour by hour: its cells checked against its binned figure, its hourly one taken)
    weight = sea["cell_probability"]
    passes = flag(on_sea_grid(work["passes"], sea))
    leg = (weight * passes).sum(("heading", "hs", "tz"))
    if "leg_hourly" in work:
        leg = xr.where(work["leg_hourly"].astype(bool),
                       work["workability_leg"] + (leg - work["workability_leg_binned"]), leg)
    route_re = (leg * sea["leg_weight"]).sum("leg")
    d.recheck = float(np.nanmax(np.abs(route_re - work["workability_route"]).values))
    data = dict(zip(DATASET_NAMES, (sea, vessel, plant, resp, work)))
    d.same_config, d.hash_basis = config_comparison(data, provenance)
    d.hash_mismatch = [f"{name} ({str(data[name].attrs['config_sha256'])[:12]})"
                       for name, same in d.same_config.items() if same is False]
    return d
