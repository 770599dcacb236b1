"""Legs given by measured spectra in the workability: judged hour by hour.

A leg given by hourly spectra (``spectra: {file, format}``) is binned like a hindcast leg
into scatter cells of JONSWAP seas (:mod:`jls.sea.records`); those cells carry the winch
limits, the time-domain verdicts, the uncertainty bands and the voyage extremes like any
other. Its *workability* is instead judged on its hours as recorded: each recorded hour
of ``measured_response.nc`` (:mod:`jls.stages.measured_response`) at each relative
heading it is met at (``heading_weight``), every criterion on the hour's own directional
sea (``utilisation``, :mod:`jls.stages.hourly_seas`: the functions of ``jls response`` and
``jls forecast``). A dataset without ``utilisation`` (written before it existed) falls
back to the JONSWAP of the hour's (Hs, Tz = Tm02) with its relative sway scaled by the
ratio of the sway over its measured spectrum to that over the JONSWAP
(:mod:`jls.assessment.hourly`). So swell that a JONSWAP on the hour's combined (Hs, Tz)
leaves out counts in every criterion of the leg's workability, as it does in the weather
windows and the route and departure simulations.

The leg's workability is the share of its hours x heading weights that pass; an hour
also fails where its scatter cell fails on a saturating winch (``verdict_source``
saturated-fail: the frequency domain is unreliable there). Time-domain verdicts judge a
cell's JONSWAP sea and are not carried to the measured hours. The governing share and
the criterion sensitivity of the leg are judged on the hours in the same way (a trial
limit moves the swept criterion's own-sea utilisation by its ratio to the JONSWAP's,
exact for a criterion that is its value over a limit). The
binned JONSWAP figure stays beside it (``workability_leg_binned``), and the uncertainty
band of the leg (variants of the plant and the Hs choice) is moved by the difference
between the two: the variants' binned figures plus (hourly - binned nominal), clipped
to 0-1, the nominal value inside the band as before.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.bands import BAND_DIMS
from jls.assessment.hourly import hourly_utilisation, sway_ratio
from jls.assessment.workability import cell_passes, criteria_array, unit_utilisation
from jls.errors import InputError
from jls.names import SATURATED_FAIL

__all__ = ["leg_workability"]


def _cell_index(x, lower, upper):
    """Bin of each value among bins [lower, upper) (ascending, contiguous), held at the
    end bins for a value beyond them; -1 for NaN."""
    i = np.clip(np.searchsorted(np.asarray(upper, float), x, side="right"), 0, len(upper) - 1)
    return np.where(np.isfinite(x), i, -1)


def leg_workability(measured: xr.Dataset, leg: str, unit_util: xr.DataArray, *, tz_outside="error",
                    cell_fails: xr.DataArray | None = None, sea: xr.Dataset | None = None,
                    sensitivity: dict | None = None, block=2048) -> xr.Dataset:
    """The hourly workability of a leg given by measured spectra.

    Each recorded hour of ``measured_response.nc`` (its Hs, Tz = Tm02 and sway ratio,
    :func:`sway_ratio`) is judged at each of the leg's headings it is met at (its
    ``heading_weight``) by :func:`hourly_utilisation` on ``unit_util`` (candidate, tugger,
    heading, tz, criterion; the fine Tz grid of ``operability.nc``). ``cell_fails``
    (candidate, tugger, heading, hs, tz, on the bins of ``sea`` for this leg): cells that
    fail whatever their criteria say (a saturating winch); an hour in such a cell fails
    too (an hour beyond the bins takes the nearest). ``sensitivity``: (criterion, its unit
    utilisation at each trial limit, dims trial_limit, candidate, tugger, heading, tz,
    criterion of one) re-judges the hours with that criterion at each trial limit, the
    other criteria kept.

    Returns ``workability`` (candidate, tugger), ``governing_share`` (candidate, tugger,
    criterion: the share of the hours a criterion fails, by the criterion the most utilised;
    the hours failing on a saturating winch alone are the rest, 1 - workability - the sum),
    ``workability_sensitivity`` (candidate, tugger, trial_limit) when asked, ``hours``
    (the hours judged) and ``hours_outside_tz``.
    """
    full = measured.sel(leg=leg, drop=True)
    kept = np.flatnonzero(np.isfinite(full["hs"].values))           # the recorded hours
    # the hours' variables; the hour-level arrays (utilisation, sway ratio) are taken a
    # block of hours at a time below, never copied whole
    m = full[["hs", "tz", "heading_weight"]].isel(time=kept)
    hw = m["heading_weight"]
    hw = hw.isel(heading=np.flatnonzero(hw.sum("time").values > 0))      # the headings met
    heads = [float(h) for h in hw["heading"].values]
    missing = sorted(set(heads) - {float(h) for h in unit_util["heading"].values})
    if missing:
        raise InputError("no statistics at the leg's heading(s)", field=f"legs[{leg}].headings_deg",
                         value=missing)
    u = unit_util.sel(heading=heads)
    crit = u["criterion"]
    if sensitivity is not None:
        swept, trial_util = sensitivity
        trial_util = trial_util.sel(heading=heads, candidate=u["candidate"], tugger=u["tugger"])
        rest = [c for c in crit.values.tolist() if c != swept]
    hs, tz = m["hs"].values, m["tz"].values
    source = measured.attrs.get(f"source_{leg}") or f"legs[{leg}]"      # the spectra file, for errors
    w = hw.values                                                  # (time, heading)
    shape = (u.sizes["candidate"], u.sizes["tugger"])
    work = np.zeros(shape)
    share = np.zeros(shape + (crit.size,))
    sens = np.zeros(shape + ((trial_util.sizes["trial_limit"],) if sensitivity is not None else (0,)))
    grid = u["tz"].values
    outside = int((np.isfinite(tz) & ((tz < grid.min()) | (tz > grid.max()))).sum())
    if cell_fails is not None:
        ih = _cell_index(hs, sea["hs_lower"].sel(leg=leg).values, sea["hs_upper"].sel(leg=leg).values)
        it = _cell_index(tz, sea["tz_lower"].sel(leg=leg).values, sea["tz_upper"].sel(leg=leg).values)
        fails = cell_fails.sel(heading=heads).transpose("candidate", "tugger", "heading", "hs", "tz").values
    order = ("candidate", "tugger", "heading", "time", "criterion")
    own = ratio = None
    if "utilisation" in full:                  # every criterion on the hour's own sea
        own = full["utilisation"]
        at = {"candidate": u["candidate"], "tugger": u["tugger"],
              "criterion": [c for c in crit.values.tolist() if c in own["criterion"].values]}
    else:
        ratio = sway_ratio(measured, leg).sel(candidate=u["candidate"], tugger=u["tugger"])
    for k, h in enumerate(heads):              # each heading on the hours met at it only
        hours = np.flatnonzero(w[:, k] > 0)
        u_h = u.sel(heading=[h])
        for a in range(0, hours.size, block):
            tb = hours[a:a + block]
            util, _ = hourly_utilisation(hs[tb], tz[tb], u_h, tz_outside, source,
                                         None if own is not None else ratio.isel(time=tb))
            util = util.transpose(*order)
            if own is not None:
                jons = util
                util = _own(util, _block(own, kept[tb], h, at))
            criteria_ok = cell_passes(util).values[:, :, 0]        # (cand, tug, time)
            ok = criteria_ok & ~fails[:, :, k][:, :, ih[tb], it[tb]] if cell_fails is not None else criteria_ok
            wb = w[tb, k]
            work += ok @ wb
            gov = np.nan_to_num(util.values[:, :, 0], nan=-np.inf).argmax(-1)
            for c in range(crit.size):
                share[..., c] += (~criteria_ok & (gov == c)) @ wb
            if sensitivity is not None:                            # every trial limit at once
                fixed = cell_passes(util.sel(criterion=rest)).values[:, :, 0] if rest else True
                ut, _ = hourly_utilisation(hs[tb], tz[tb], trial_util.sel(heading=[h]), tz_outside,
                                           source, None if own is not None else ratio.isel(time=tb))
                if own is not None and swept in at["criterion"]:            # the own sea's share
                    ut = _scaled(ut, util.sel(criterion=[swept]), jons.sel(criterion=[swept]))
                ok_t = fixed & cell_passes(ut.transpose("trial_limit", *order)).values[:, :, :, 0]
                sens += np.einsum("jcgt,t->cgj", ok_t, wb)
    total = float(w.sum())
    dims = ("candidate", "tugger")
    coords = {"candidate": u["candidate"].values, "tugger": u["tugger"].values}
    ds = xr.Dataset({"workability": (dims, work / total),
                     "governing_share": (dims + ("criterion",), share / total),
                     "hours": ((), float(total)), "hours_outside_tz": ((), outside)},
                    coords={**coords, "criterion": crit.values})
    if sensitivity is not None:
        ds["workability_sensitivity"] = (dims + ("trial_limit",), sens / total)
        ds = ds.assign_coords(trial_limit=trial_util["trial_limit"].values)
    return ds


def _block(own: xr.DataArray, times, heading, at: dict) -> xr.DataArray:
    """The hours ``times`` (positions) of ``own`` at ``heading``, on the labels ``at`` (a
    dimension already on them is not indexed again)."""
    o = own.isel(time=times).sel(heading=[heading])
    differ = {d: v for d, v in at.items() if not np.array_equal(o[d].values, np.asarray(v))}
    return o.sel(differ) if differ else o


def _own(util: xr.DataArray, own: xr.DataArray) -> xr.DataArray:
    """``util`` (candidate, tugger, heading, time, criterion) with the criteria of ``own``
    (time, heading, candidate, tugger, criterion; the hour's own sea) in place of the
    JONSWAP's."""
    out = util.copy()
    o = own.transpose(*util.dims)
    out.loc[{"criterion": o["criterion"].values}] = o.values
    return out


def _scaled(trial, own, jons):
    """The trial limits' utilisation moved from the JONSWAP's to the own sea's: trial x
    own / JONSWAP (exact for a criterion whose utilisation is its value over a limit)."""
    o = own.transpose(*[d for d in trial.dims if d != "trial_limit"]).values
    j = jons.transpose(*[d for d in trial.dims if d != "trial_limit"]).values
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.where((j > 0) & np.isfinite(j), o / j, np.where(o > 0, np.inf, 0.0))
        return trial * r


#: How the workability judges a leg given by measured spectra (dataset attribute).
HOURLY_RULE = (
    "A leg given by measured spectra, partitions or a two-peak table is judged hour by hour: "
    "each recorded hour at the relative headings it is met at, every criterion on the hour's "
    "own directional sea (measured_response.nc utilisation, jls.stages.hourly_seas); an hour "
    "in a cell whose winch saturates fails. The binned JONSWAP figure is "
    "workability_leg_binned; the leg's band is moved by the difference.")
#: The rule when measured_response.nc carries no hourly utilisation (an older dataset).
SWAY_RATIO_RULE = (
    "A leg given by measured spectra is judged hour by hour: each recorded hour at the "
    "relative headings it is met at, its relative sway scaled by the ratio of the sway over "
    "its measured spectrum to that over the JONSWAP on its (Hs, Tm02), the other criteria on "
    "the JONSWAP; an hour in a cell whose winch saturates fails. The binned JONSWAP figure "
    "is workability_leg_binned; the leg's band is moved by the difference.")


def _unit(curve: xr.Dataset, criteria: dict, work: xr.Dataset) -> xr.DataArray:
    stats = curve.sel(candidate=work["candidate"], tugger=work["tugger"])
    return unit_utilisation(stats, criteria_array(criteria))


def apply_measured_legs(work: xr.Dataset, sea: xr.Dataset, curve: xr.Dataset, measured: xr.Dataset,
                        criteria: dict, *, tz_outside="error") -> xr.Dataset:
    """The workability dataset with its spectra legs judged hour by hour (module
    docstring): ``workability_leg``, ``governing_share`` and ``workability_leg_sensitivity``
    of those legs replaced, ``workability_route`` (and its sensitivity) recomputed, the
    bands moved; ``workability_leg_binned`` and ``leg_hourly`` added. ``curve``: the
    unit-Hs statistics on the fine Tz grid (``operability.nc``)."""
    legs = [str(leg) for leg in measured["leg"].values]
    absent = sorted(set(legs) - {str(leg) for leg in work["leg"].values})
    if absent:
        raise InputError("the measured-spectrum response names legs the route does not have",
                         field="measured_response.leg", value=absent)
    unit_util = _unit(curve, criteria, work)
    sens = None
    if "workability_leg_sensitivity" in work:
        swept = str(work.attrs["sensitivity_criterion"])
        trial = work["trial_limit"].values
        parts = [_unit(curve, {swept: float(v)}, work) for v in trial]
        sens = (swept, xr.concat(parts, dim=xr.DataArray(trial, dims="trial_limit")))
    fails = work["verdict_source"] == SATURATED_FAIL if "verdict_source" in work else None
    work["workability_leg_binned"] = work["workability_leg"].copy()
    for leg in legs:
        r = leg_workability(measured, leg, unit_util, tz_outside=tz_outside, sea=sea,
                            cell_fails=None if fails is None else fails.sel(leg=leg, drop=True),
                            sensitivity=sens)
        at = {"leg": leg}
        work["workability_leg"].loc[at] = r["workability"].transpose("candidate", "tugger").values
        work["governing_share"].loc[at] = r["governing_share"].transpose(
            *[d for d in work["governing_share"].dims if d != "leg"]).values
        if sens is not None:
            work["workability_leg_sensitivity"].loc[at] = r["workability_sensitivity"].transpose(
                *[d for d in work["workability_leg_sensitivity"].dims if d != "leg"]).values
    weight = sea["leg_weight"]
    work["workability_route"] = (work["workability_leg"] * weight).sum("leg").transpose(
        "candidate", "tugger").assign_attrs(work["workability_route"].attrs)
    if sens is not None:
        work["workability_route_sensitivity"] = (work["workability_leg_sensitivity"] * weight).sum(
            "leg").transpose(*work["workability_route_sensitivity"].dims).assign_attrs(
            work["workability_route_sensitivity"].attrs)
    if "workability_leg_variant" in work:
        delta = work["workability_leg"] - work["workability_leg_binned"]
        v = (work["workability_leg_variant"] + delta).clip(0.0, 1.0)
        work["workability_leg_variant"] = v.transpose(*work["workability_leg_variant"].dims).assign_attrs(
            work["workability_leg_variant"].attrs)
        route = (v * weight).sum("leg", skipna=False)
        work["workability_route_variant"] = route.transpose(*work["workability_route_variant"].dims).assign_attrs(
            work["workability_route_variant"].attrs)
        for name, var in (("workability_leg", v), ("workability_route", route)):
            lo, hi = f"{name}_min", f"{name}_max"          # the nominal value inside its band
            work[lo] = np.minimum(var.min(BAND_DIMS), work[name]).transpose(*work[lo].dims).assign_attrs(work[lo].attrs)
            work[hi] = np.maximum(var.max(BAND_DIMS), work[name]).transpose(*work[hi].dims).assign_attrs(work[hi].attrs)
    work["leg_hourly"] = xr.DataArray([str(leg) in legs for leg in work["leg"].values], dims="leg",
                                      coords={"leg": work["leg"]})
    work.attrs["hourly_rule"] = HOURLY_RULE if "utilisation" in measured else SWAY_RATIO_RULE
    return work


__all__ += ["HOURLY_RULE", "apply_measured_legs"]
