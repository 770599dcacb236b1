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

from jls.assessment import wire_tension as wt
from jls.errors import InputError
from jls.names import (
    FREQUENCY_DOMAIN,
    SATURATED_FAIL,
    SATURATED_UNRESOLVED,
    SWAY_M,
    TIME_DOMAIN,
    VERDICT_MEANINGS,
    WIRE_TENSION_CRITERION,
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
             "saturation_share", "saturation_share_route", "timedomain_limit_fraction",
             "timedomain_marginal")


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


#: How far from the limit a time-domain MPM must lie, in its standard errors, to decide.
MARGIN_STANDARD_ERRORS = 1.0

TIMEDOMAIN_RULE = (
    "A time-domain cell decides only where its relative-sway MPM lies more than one standard "
    "error from the limit. The MPM comes from one record: its standard error is about "
    "MPM / (2 sqrt(zeta w_n T)) (the variance estimate of a lightly damped response over a "
    "record of T seconds; zeta and w_n of the rigging's sway mode without tugger, so the "
    "error is not understated). A cell within that margin is marginal: it keeps the "
    "frequency-domain verdict, or fails where its winch saturates (the frequency domain is "
    "unreliable there and the time domain cannot decide); a hoist wire going slack in the "
    "record fails the cell in any case.")


def mpm_standard_error(td: xr.Dataset, statistic="mpm_sigma") -> xr.DataArray:
    """Standard error [m] per tugger of a time-domain cell's MPM: the cell's own
    ``<statistic>_stderr`` when it has one, else MPM / (2 sqrt(zeta w_n T)) from the cell's
    sway damping ratio and natural period (attributes ``sway_damping_ratio``,
    ``sway_natural_period_s``) and its recorded duration ``duration_s``."""
    if f"{statistic}_stderr" in td:
        return td[f"{statistic}_stderr"]
    try:
        zeta = float(td.attrs["sway_damping_ratio"])
        w_n = 2 * np.pi / float(td.attrs["sway_natural_period_s"])
        duration = float(td.attrs["duration_s"])
    except KeyError as exc:
        raise InputError(f"the time-domain cell has no {exc.args[0]}: its MPM's standard error "
                         "cannot be judged; rerun the cell", file=td.attrs.get("cell"),
                         field=exc.args[0]) from None
    return td[statistic] / (2.0 * np.sqrt(zeta * w_n * duration))


def apply_timedomain(work: xr.Dataset, sea: xr.Dataset, cells: list[xr.Dataset],
                     hs: xr.DataArray, static: xr.DataArray | None = None, own_sea_legs=()) -> xr.Dataset:
    """Replace the verdict of every cell a time-domain dataset covers (same candidate,
    heading, assessed Hs and Tz, in every leg where that cell occurs) where the time
    domain decides (:data:`TIMEDOMAIN_RULE`): the relative-sway criterion is judged in the
    time domain (:func:`timedomain_verdict`), the other criteria keep their
    frequency-domain verdict, ``verdict_source`` says time domain. A marginal cell (MPM
    within :data:`MARGIN_STANDARD_ERRORS` standard errors of the limit) keeps the
    frequency-domain verdict, or fails where its winch saturates, and is flagged
    ``timedomain_marginal``; the dataset states the rule (``timedomain_rule``) and names
    the marginal cells in its ``warnings``. With the criterion ``wire_tension``, the
    record's own extremes judge the wires instead of the frequency domain's
    (:func:`jls.assessment.wire_tension.timedomain_passes`; ``static``: the static wire
    tensions, candidate x wire [kN]), and a record whose wires fail it fails the cell,
    marginal or not. Recomputes the workabilities. Needs a ``relative_sway_m`` criterion.
    A cell run on its leg's own sea (attribute ``sea_leg``, :mod:`jls.timedomain.cell_sea`)
    decides in that leg only; a cell on the pipeline's JONSWAP decides in no leg of
    ``own_sea_legs`` (the legs whose sea is their own: partitions, measured, Torsethaugen)."""
    occupancy(work, cells)
    work["timedomain_marginal"] = xr.zeros_like(work["passes"], dtype=bool)
    work.attrs["timedomain_rule"] = TIMEDOMAIN_RULE
    work.attrs.setdefault("warnings", "")
    if not cells:
        return _annotate(work)
    crit = [str(c) for c in work["criterion"].values]
    if SWAY_M not in crit:
        raise InputError("time-domain verdicts judge the relative sway; the criteria have no "
                         + SWAY_M, field="assessment.criteria")
    limit = float(work["limit"].sel(criterion=SWAY_M))
    tension = WIRE_TENSION_CRITERION in crit
    if tension and static is None:
        raise InputError("the time-domain verdict of the wire-tension criterion needs the static "
                         "wire tensions (tension_static of the response dataset)",
                         field=f"assessment.criteria.{WIRE_TENSION_CRITERION}")
    if tension:
        floor = float(work["limit"].sel(criterion=WIRE_TENSION_CRITERION))
        ceiling = float(work["limit"]["tension_ceiling_kN"].sel(criterion=WIRE_TENSION_CRITERION))
    others = [c for c in crit if c not in (SWAY_M, WIRE_TENSION_CRITERION)]
    passes, source, marginal = work["passes"], work["verdict_source"], work["timedomain_marginal"]
    saturates = work["winch_saturates"] if "winch_saturates" in work else None
    fd_others = (work["utilisation"].sel(criterion=others) <= 1.0).all("criterion") if others else None
    tz_all = work["tz"].values
    hs_grid = hs.broadcast_like(sea["hs_upper"]).transpose("leg", "hs")
    # positions instead of labels: one cell at a time, label lookups were most of the cost
    pos = {d: {v: i for i, v in enumerate(work[d].values.tolist())} for d in ("candidate", "tugger")}
    arrays = {name: np.array(da.values) for name, da in      # copies, set below
              (("passes", passes), ("source", source), ("marginal", marginal))}
    sat = np.asarray(saturates.values) if saturates is not None else None
    fdo = np.asarray(fd_others.values) if fd_others is not None else None

    def at(da, ix):
        return tuple(ix[d] for d in da.dims)

    notes = []
    for td in cells:
        cand = str(td.attrs["candidate"])
        head, h, tz = (float(td.attrs[k]) for k in ("heading_deg", "hs_m", "tz_s"))
        jt = np.flatnonzero(np.isclose(tz_all, tz))
        if cand not in work["candidate"].values or not jt.size or head not in work["heading"].values:
            continue
        verdict = timedomain_verdict(td, limit)
        wires_ok = (wt.timedomain_passes(td, static.sel(candidate=cand), floor, ceiling)
                    if tension else xr.ones_like(verdict, dtype=bool))
        wires_of = dict(zip(wires_ok["tugger"].values.tolist(), wires_ok.values.tolist()))
        stderr = mpm_standard_error(td)
        close = (np.abs(td["mpm_sigma"] - limit) <= MARGIN_STANDARD_ERRORS * stderr) & (td["slack_events"] == 0)
        close_of = dict(zip(td["tugger"].values.tolist(), close.values.tolist()))
        verdict_of = dict(zip(verdict["tugger"].values.tolist(), verdict.values.tolist()))
        jh = int(np.flatnonzero(work["heading"].values == head)[0])
        shown = []
        own = str(td.attrs.get("sea_leg", ""))
        for li, leg in enumerate(str(v) for v in work["leg"].values):
            if (leg != own) if own else (leg in set(map(str, own_sea_legs))):
                continue                       # the record's sea is not this leg's
            for ih in np.flatnonzero(np.isclose(hs_grid.values[li], h)):
                for tug in td["tugger"].values.tolist():
                    if tug not in pos["tugger"]:
                        continue
                    ix = dict(candidate=pos["candidate"][cand], tugger=pos["tugger"][tug], leg=li,
                              heading=jh, hs=int(ih), tz=int(jt[0]))
                    if not wires_of[tug]:              # the record's wires fail: decided
                        arrays["passes"][at(passes, ix)] = False
                        arrays["source"][at(source, ix)] = TIME_DOMAIN
                        continue
                    if close_of[tug]:
                        arrays["marginal"][at(marginal, ix)] = True
                        if sat is not None and sat[at(saturates, ix)]:
                            arrays["passes"][at(passes, ix)] = False
                            arrays["source"][at(source, ix)] = SATURATED_FAIL
                        if str(tug) not in shown:
                            shown.append(str(tug))
                        continue
                    ok = bool(verdict_of[tug])
                    if fdo is not None:
                        ok = ok and bool(fdo[at(fd_others, ix)])
                    arrays["passes"][at(passes, ix)] = ok
                    arrays["source"][at(source, ix)] = TIME_DOMAIN
        if shown:
            mpm = ", ".join(f"{t} {float(td['mpm_sigma'].sel(tugger=t)):.3f} +- "
                            f"{float(stderr.sel(tugger=t)):.3f} m" for t in shown)
            notes.append(f"time-domain cell {td.attrs.get('cell', cand)}: relative-sway MPM within one "
                         f"standard error of the {limit:g} m limit ({mpm}): marginal, the "
                         "frequency-domain verdict kept (failed where the winch saturates)")
    work["passes"] = passes.copy(data=arrays["passes"])
    work["verdict_source"] = source.copy(data=arrays["source"])
    work["timedomain_marginal"] = marginal.copy(data=arrays["marginal"])
    lines = [line for line in str(work.attrs["warnings"]).splitlines() if line] + notes
    work.attrs["warnings"] = "\n".join(lines)
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
           "timedomain_verdict", "mpm_standard_error", "TIMEDOMAIN_RULE", "MARGIN_STANDARD_ERRORS",
           "saturated_cells", "reweigh", "VERDICT_MEANINGS"]
