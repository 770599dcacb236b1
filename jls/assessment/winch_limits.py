"""Winch limits in the workability: where the frequency domain is unreliable because a
tugger winch saturates, and which verdict each cell carries (section 6.4).

The frequency domain treats a tugger pair as a linear damper without limits. Each line
follows T = T0 + c/n u between its floor T_min and its capacity T_max, so the force a
line has available for damping is T_max - T0 (per line, the study's definition; T0 is
midway) and the pair's net force is capped at n (T_max - T0). A cell whose 3-h MPM net
force Hs MPM_F(Hs = 1) exceeds that cap is marked *frequency domain unreliable: winch
saturates* (``winch_saturates``). The configuration says what happens to it
(``assessment.winch_saturation``):

* ``fail`` (default, the safe choice): the cell fails;
* ``timedomain``: the cell keeps its frequency-domain verdict until a time-domain run of
  that cell replaces it (:func:`apply_timedomain`); the pipeline sends every flagged cell
  with non-zero probability to the time domain.

``verdict_source`` says where each cell's verdict comes from (flag values below).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import (
    FREQUENCY_DOMAIN,
    SATURATED_FAIL,
    SATURATED_UNRESOLVED,
    SWAY_M,
    TIME_DOMAIN,
    VERDICT_MEANINGS,
)
from jls.tugger.setting import Tugger

POLICIES = ("fail", "timedomain")
ORDER = ("candidate", "tugger", "leg", "heading", "hs", "tz")


def damping_capacity(tuggers: dict[str, Tugger], names) -> xr.DataArray:
    """Net force of each pair available for damping, n (T_max - T0) [kN]; infinite for a
    setting without damping (it never saturates)."""
    cap = [tuggers[str(n)].n_lines * (tuggers[str(n)].max_force - tuggers[str(n)].pretension)
           if tuggers[str(n)].active else np.inf for n in names]
    return xr.DataArray(np.asarray(cap, float), dims="tugger", coords={"tugger": list(names)},
                        attrs={"units": "kN", "long_name": "net tugger force available for damping, n (T_max - T0)"})


def saturation(response: xr.Dataset, hs: xr.DataArray, capacity: xr.DataArray):
    """(cell MPM net force [kN], saturates flag) per candidate, tugger, leg, heading, hs, tz.

    response: unit-Hs statistics with ``tugger_mpm_force``; hs: assessed Hs (leg, hs)."""
    if "tugger_mpm_force" not in response:
        raise InputError("the winch check needs the tugger loads (tugger_mpm_force) in the "
                         "response dataset", field="assessment.winch_saturation")
    force = hs * response["tugger_mpm_force"]
    return force, force > capacity


#: Variables this module adds to the workability dataset (attributes from the registry).
VARIABLES = ("tugger_force_mpm", "damping_capacity", "winch_saturates", "verdict_source",
             "saturation_share", "saturation_share_route", "timedomain_limit_fraction")


def _annotate(work: xr.Dataset) -> xr.Dataset:
    from jls.io import registry
    spec = registry.layout("workability")["variables"]
    for v in VARIABLES:
        if v in work:
            work[v].attrs.update({k: spec[v][k] for k in ("units", "long_name", "flag_meanings")
                                  if k in spec[v]})
    return work


def reweigh(work: xr.Dataset, sea: xr.Dataset) -> xr.Dataset:
    """workability_leg and workability_route from the (changed) pass flags."""
    weight = sea["cell_probability"]
    leg = (weight * work["passes"]).sum(("heading", "hs", "tz"))
    attrs_leg, attrs_route = work["workability_leg"].attrs, work["workability_route"].attrs
    work["workability_leg"] = leg.transpose("candidate", "tugger", "leg").assign_attrs(attrs_leg)
    work["workability_route"] = (leg * sea["leg_weight"]).sum("leg").transpose(
        "candidate", "tugger").assign_attrs(attrs_route)
    return work


def apply_winch_limits(work: xr.Dataset, response: xr.Dataset, sea: xr.Dataset,
                       tuggers: dict[str, Tugger], hs: xr.DataArray, policy="fail") -> xr.Dataset:
    """Add ``tugger_force_mpm``, ``winch_saturates``, ``saturation_share`` and
    ``verdict_source`` to the workability dataset; under ``fail`` the flagged cells fail
    and the workabilities are recomputed."""
    if policy not in POLICIES:
        raise InputError(f"winch saturation policy must be one of {', '.join(POLICIES)}",
                         field="assessment.winch_saturation", value=policy)
    stats = response.sel(tz=work["tz"], candidate=work["candidate"], tugger=work["tugger"])
    force, sat = saturation(stats, hs, damping_capacity(tuggers, work["tugger"].values))
    sat = sat.transpose(*ORDER)
    work["tugger_force_mpm"] = force.transpose(*ORDER)
    work["damping_capacity"] = damping_capacity(tuggers, work["tugger"].values)
    work["winch_saturates"] = sat
    source = xr.where(sat, SATURATED_FAIL if policy == "fail" else SATURATED_UNRESOLVED,
                      FREQUENCY_DOMAIN).astype(np.int8)
    work["verdict_source"] = source.transpose(*ORDER)
    if policy == "fail":
        work["passes"] = (work["passes"] & ~sat).transpose(*ORDER)
        reweigh(work, sea)
    weight = sea["cell_probability"]
    work["saturation_share"] = ((weight * sat).sum(("heading", "hs", "tz"))
                                .transpose("candidate", "tugger", "leg"))
    work["saturation_share_route"] = (work["saturation_share"] * sea["leg_weight"]).sum("leg")
    work.attrs["winch_saturation"] = policy
    return _annotate(work)


def timedomain_verdict(td: xr.Dataset, limit_m: float, statistic="mpm_sigma") -> xr.DataArray:
    """Pass flag per tugger of a time-domain cell (:mod:`jls.stages.timedomain_cell`): the relative-sway MPM within
    the limit (the MPM from sigma with N from the record's own Tz, as the frequency
    domain defines it) and no hoist wire slack."""
    ok = (td[statistic] <= limit_m) & (td["slack_events"] == 0)
    return ok


def apply_timedomain(work: xr.Dataset, sea: xr.Dataset, cells: list[xr.Dataset],
                     hs: xr.DataArray) -> xr.Dataset:
    """Replace the verdict of every cell a time-domain dataset covers (same candidate,
    heading, assessed Hs and Tz, in every leg where that cell occurs): the relative-sway
    criterion is judged in the time domain (:func:`timedomain_verdict`), the other
    criteria keep their frequency-domain verdict. Sets ``verdict_source`` to time domain
    there and recomputes the workabilities. Needs a ``relative_sway_m`` criterion."""
    occupancy(work, cells)
    if not cells:
        return work
    crit = [str(c) for c in work["criterion"].values]
    if SWAY_M not in crit:
        raise InputError("time-domain verdicts judge the relative sway; the criteria have no "
                         + SWAY_M, field="assessment.criteria")
    limit = float(work["limit"].sel(criterion=SWAY_M))
    others = [c for c in crit if c != SWAY_M]
    passes = work["passes"].copy()
    source = work["verdict_source"].copy()
    fd_others = (work["utilisation"].sel(criterion=others) <= 1.0).all("criterion") if others else None
    tz_all = work["tz"].values
    hs_grid = hs.broadcast_like(sea["hs_upper"]).transpose("leg", "hs")
    for td in cells:
        cand = str(td.attrs["candidate"])
        head, h, tz = (float(td.attrs[k]) for k in ("heading_deg", "hs_m", "tz_s"))
        jt = np.flatnonzero(np.isclose(tz_all, tz))
        if cand not in work["candidate"].values or not jt.size or head not in work["heading"].values:
            continue
        verdict = timedomain_verdict(td, limit)
        for li, leg in enumerate(work["leg"].values):
            for ih in np.flatnonzero(np.isclose(hs_grid.values[li], h)):
                for tug in td["tugger"].values:
                    if tug not in work["tugger"].values:
                        continue
                    sel = dict(candidate=cand, tugger=tug, leg=leg, heading=head,
                               hs=work["hs"].values[ih], tz=tz_all[jt[0]])
                    ok = bool(verdict.sel(tugger=tug))
                    if fd_others is not None:
                        ok = ok and bool(fd_others.sel(sel))
                    passes.loc[sel] = ok
                    source.loc[sel] = TIME_DOMAIN
    work["passes"] = passes
    work["verdict_source"] = source
    return _annotate(reweigh(work, sea))


def occupancy(work: xr.Dataset, cells: list[xr.Dataset]) -> xr.Dataset:
    """``timedomain_limit_fraction``: the largest fraction of time a line sits at a force
    limit over the time-domain cells of each (candidate, tugger); NaN where none ran."""
    frac = xr.full_like(work["workability_route"], np.nan, dtype=float)
    for td in cells:
        cand = str(td.attrs["candidate"])
        if cand not in work["candidate"].values:
            continue
        for tug in td["tugger"].values:
            if tug in work["tugger"].values:
                old = float(frac.sel(candidate=cand, tugger=tug))
                new = float(td["limit_fraction"].sel(tugger=tug))
                frac.loc[dict(candidate=cand, tugger=tug)] = np.fmax(old, new)
    work["timedomain_limit_fraction"] = frac.assign_attrs(
        units="1", long_name="largest fraction of time a tugger line is at a force limit over "
                             "the time-domain cells (NaN: no cell)")
    return work


def saturated_cells(work: xr.Dataset, sea: xr.Dataset) -> list[dict]:
    """The flagged cells with non-zero probability, one per (candidate, heading, assessed
    Hs, Tz) over the tuggers and legs: what the ``timedomain`` policy sends to the time
    domain."""
    live = (sea["cell_probability"] > 0)
    flagged = (work["winch_saturates"] & live).any(("tugger", "leg"))
    out = []
    for idx in np.argwhere(flagged.transpose("candidate", "heading", "hs", "tz").values):
        c, h, i, j = idx
        out.append({"candidate": str(work["candidate"].values[c]),
                    "heading": float(work["heading"].values[h]),
                    "hs_bin": float(work["hs"].values[i]), "tz": float(work["tz"].values[j])})
    return out


__all__ = ["POLICIES", "damping_capacity", "saturation", "apply_winch_limits", "apply_timedomain",
           "timedomain_verdict", "saturated_cells", "reweigh", "VERDICT_MEANINGS"]
