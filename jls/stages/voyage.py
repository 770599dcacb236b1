"""The voyage dataset (``voyage.nc``): the distribution of the largest response over the
whole voyage per option and criterion, from the legs' scatter tables (long-term, "all sea
states"), and, for a route whose every leg is an hourly record (hindcast, metocean or spectra), the route sailed from
every recorded departure hour (layout ``voyage`` of the registry; the physics is
:mod:`jls.assessment.voyage` and :mod:`jls.assessment.route_simulation`, the criteria's
levels :mod:`jls.assessment.criterion_levels`, the route's hours
:mod:`jls.assessment.route_hours`).

A transit cannot pause: workability answers how much of the time the sea is inside the
limits; this answers how likely this voyage is to stay inside them from start to end.

``exceedance_curve`` is the same long-term distribution at the levels of
:data:`CURVE_LEVELS` (multiples of each criterion's limit), so that the report draws
P(voyage max > x) from the dataset rather than recomputing it.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.criterion_levels import criterion_statistics
from jls.assessment.hourly import (
    OWN_SEA_NOT_USED,
    route_own_heading_utilisation,
    route_own_rows,
    route_sway_scale,
)
from jls.assessment.route_hours import common_hours
from jls.assessment.route_simulation import route_simulation
from jls.assessment.voyage import (
    exceedance_at_levels,
    hindcast_long_term,
    long_term_extreme,
    voyage_dataset,
)
from jls.assessment.windows import read_route_hindcasts
from jls.assessment.workability import assessed_hs, criteria_array
from jls.sea.records import is_hourly, leg_source

#: Levels of the exceedance curve, as multiples of the criterion's limit: 0.04 to 250
#: times, 25 points a decade (ratio 1.096 between neighbours), the limit itself (1) among them.
CURVE_LEVELS = 10.0 ** (np.arange(-35, 61) * 0.04)


def exceedance_curve(crit: xr.Dataset, sea: xr.Dataset, hs_in_bin: str, threads=1, own=None) -> xr.DataArray:
    """P(voyage max > x) (candidate, tugger, criterion, level) at x = level x limit, by
    :func:`jls.assessment.voyage.exceedance_at_levels` (the long-term extreme with the
    limit swept over the levels); ``own``: the own-sea legs' records (:func:`own_table_seas`)."""
    curve = exceedance_at_levels(crit["sigma"], crit["tz_response"], sea["cell_probability"],
                                 assessed_hs(sea, hs_in_bin), sea["duration_h"], crit["limit"],
                                 CURVE_LEVELS, threads=threads, own=own)
    return curve.transpose("candidate", "tugger", "criterion", "level")


def own_table_seas(measured: xr.Dataset | None, sea: xr.Dataset, criteria, *, limit=None,
                   exposure_h=None, cycles="response") -> tuple:
    """(own, left): the own-sea records of the legs of ``measured_response.nc`` that carry
    ``tz_response_own`` for every one of ``criteria``, laid out for
    :func:`jls.assessment.voyage.long_term_extreme` (``sigma``, ``tz_response``,
    ``probability``, ``hs_cell``, ``tz_cell``), or None; ``left``: {leg: reason} of the
    legs that keep their JONSWAP cells. A record is credited to the scatter cell of
    ``sea_states.nc`` it is binned in: a table's cells in the table's order (its records
    are its cells of positive probability, :mod:`jls.stages.sea_model_spectra`), an hour
    by its Hs and Tz (Tm02) within the leg's bin edges. A record's ``sigma`` is that whose
    MPM over ``exposure_h`` at its own period is its level, utilisation x ``limit``
    (criterion; :func:`jls.assessment.hourly.own_sigma`, ``cycles`` as
    ``assessment.mpm_cycles``)."""
    from jls.assessment.hourly import own_sigma
    from jls.assessment.voyage_own_seas import own_criteria_missing
    if measured is None:
        return None, {}
    legs = [str(x) for x in measured["leg"].values]
    if "tz_response_own" not in measured:
        return None, {leg: "measured_response.nc holds no tz_response_own" for leg in legs}
    if limit is None or exposure_h is None:
        raise ValueError("own-sea records need limit and exposure_h")
    missing = own_criteria_missing(measured, criteria)
    if missing:
        return None, {leg: f"no own-sea statistics of {', '.join(missing)}" for leg in legs}
    parts = []
    for leg in legs:
        m = measured.sel(leg=leg)
        times = m["time"].values[m["hs"].notnull().values]
        m = m.sel(time=times)
        hs_c, tz_c = _cells_of(m, sea.sel(leg=leg), str(measured.attrs.get(f"integration_{leg}", "")))
        u, tz = m["utilisation"], m["tz_response_own"]
        lim = limit.reset_coords(drop=True).reindex(criterion=u["criterion"].values).broadcast_like(u)
        sigma = u.copy(data=own_sigma(u.values * lim.transpose(*u.dims).values, tz.transpose(*u.dims).values,
                                      exposure_h, cycles))
        part = xr.Dataset({"sigma": sigma, "tz_response": tz,
                           "probability": m["probability"].fillna(0.0),
                           "hs_cell": ("time", hs_c), "tz_cell": ("time", tz_c)})
        parts.append(part.drop_vars([c for c in part.coords if c not in part.dims]).expand_dims(leg=[leg]))
    own = xr.concat(parts, dim="leg", join="outer", fill_value={"probability": 0.0, "hs_cell": 0, "tz_cell": 0})
    return own, {}


def _cells_of(m: xr.Dataset, leg_sea: xr.Dataset, integration: str):
    """(hs index, tz index) into sea_states.nc's grid of each record of one leg (own_table_seas)."""
    p = leg_sea["probability"].values
    cells = np.argwhere(np.nan_to_num(p) > 0)
    if integration.startswith("torsethaugen") and len(cells) == m.sizes["time"]:
        return cells[:, 0], cells[:, 1]

    def locate(x, upper):
        ok = np.flatnonzero(np.isfinite(upper))
        i = np.clip(np.searchsorted(upper[ok], x, side="left"), 0, ok.size - 1)
        return ok[i]
    return (locate(m["hs"].values, leg_sea["hs_upper"].values),
            locate(m["tz"].values, leg_sea["tz_upper"].values))


def own_sea_not_used(measured: xr.Dataset, hourly: bool = True, left: dict | None = None) -> str:
    """What the voyage extremes do not take from the own seas of the legs of
    ``measured_response.nc`` (attribute ``own_sea_not_used`` of ``voyage.nc``), "" when
    nothing: ``left`` {leg: reason} the legs whose scatter cells stay JONSWAP
    (:func:`own_table_seas`); ``hourly``: every leg of the route is an hourly record (the
    hindcast extreme and route simulation exist)."""
    out = []
    if left:
        out.append("the long-term extreme of the scatter cells (voyage_level, exceedance_curve) of "
                   + "; ".join(f"leg {leg} is that of JONSWAP seas on the binned (Hs, Tz): {why}"
                               for leg, why in left.items()))
    legs_own = ", ".join(str(leg) for leg in measured["leg"].values)
    if hourly and "utilisation" not in measured:
        out.append(f"the hindcast long-term extreme of leg(s) {legs_own} is that of JONSWAP seas on the "
                   f"hours' (Hs, Tz); the route simulation of leg(s) {legs_own} {OWN_SEA_NOT_USED}")
    elif hourly and "tz_response_own" not in measured:
        out.append(f"the hindcast long-term extreme (hindcast_*) and route simulation of leg(s) {legs_own} "
                   "take each hour's level on its own sea with the up-crossings at the response period of "
                   "the JONSWAP on the hour's (Hs, Tz) (measured_response.nc holds no tz_response_own)")
    return "; ".join(out)


def voyage(sea: xr.Dataset, response: xr.Dataset, operability: xr.Dataset, criteria: dict,
           hs_in_bin: str, route: dict, base_dir=".", threads=1, *, gamma: float,
           measured: xr.Dataset | None = None) -> xr.Dataset:
    """``response``: response.nc (statistics on the legs' Tz); ``operability``: the same on
    the fine Tz grid, which the hourly records are interpolated on; ``route``: the route's
    configuration (its legs in sailing order); ``gamma``: sea.gamma (a metocean leg's
    declared period other than Tz is converted with it); ``measured``:
    ``measured_response.nc`` of a route with legs given by spectra, whose hours the route
    simulation judges with the relative sway scaled by the hour's measured-spectrum ratio
    (:func:`jls.assessment.hourly.route_sway_scale`), or, where it holds ``utilisation``,
    on every criterion of the hour's own sea; the hindcast hours as cells
    (``hindcast_*``) take the same own-sea levels (:mod:`jls.assessment.voyage_own_seas`).
    The long-term extreme of the scatter cells takes the own-sea legs' records in place of
    their binned JONSWAP cells (:func:`own_table_seas`), and ``voyage_level_jonswap`` /
    ``own_sea_level_ratio`` compare it with every leg's binned JONSWAP; what is still not
    taken from the own seas is attribute ``own_sea_not_used``."""
    limit = criteria_array(criteria)
    crit = criterion_statistics(response, limit)
    exposure = {"exposure_h": float(response.attrs["exposure_h"]), "cycles": response.attrs["mpm_cycles"]}
    own_records, left = own_table_seas(measured, sea, crit["criterion"].values.tolist(), limit=crit["limit"],
                                       **exposure)
    lt = long_term_extreme(crit["sigma"], crit["tz_response"], sea["cell_probability"],
                           assessed_hs(sea, hs_in_bin), sea["duration_h"], crit["limit"],
                           threads=threads, own=own_records)
    if own_records is not None:                  # the same voyage with every leg's binned JONSWAP
        jonswap = long_term_extreme(crit["sigma"], crit["tz_response"], sea["cell_probability"],
                                    assessed_hs(sea, hs_in_bin), sea["duration_h"], crit["limit"],
                                    shares=False, threads=threads)
        lt["voyage_level_jonswap"] = jonswap["voyage_level"]
        with np.errstate(divide="ignore", invalid="ignore"):
            lt["own_sea_level_ratio"] = lt["voyage_level"] / jonswap["voyage_level"]
    simulated = hindcast = None
    legs = route["legs"]
    if legs and all(is_hourly(leg) for leg in legs):
        records = read_route_hindcasts(route, base_dir, gamma=gamma)
        hours = common_hours({leg["name"]: records[leg["name"]] for leg in legs})
        op = criterion_statistics(operability, limit)
        sources = {leg["name"]: str(leg_source(leg)) for leg in legs}
        simulated = route_simulation(op, hours, sea["heading_probability"], sea["duration_h"],
                                     op["limit"], strict=limit["strict"], sources=sources,
                                     sway_scale=route_sway_scale(measured, hours),
                                     own=route_own_rows(measured, hours), threads=threads, **exposure)
        own = route_own_heading_utilisation(measured, hours, sea["heading_probability"]["heading"].values)
        hindcast = hindcast_long_term(op["sigma"], op["tz_response"], hours, sea["duration_h"],
                                      sea["heading_probability"], op["limit"], threads=threads, own=own,
                                      mpm_unit=op["mpm"], exposure_h=float(response.attrs["exposure_h"]),
                                      cycles=response.attrs["mpm_cycles"])
    lt["exceedance_curve"] = exceedance_curve(crit, sea, hs_in_bin, threads=threads, own=own_records)
    attrs = {"hs_in_bin": hs_in_bin, "exposure_h": response.attrs["exposure_h"],
             "mpm_cycles": response.attrs["mpm_cycles"]}
    if measured is not None and simulated is not None:
        attrs["measured_sway_legs"] = " ".join(str(leg) for leg in measured["leg"].values)
    if measured is not None:
        attrs["own_sea_not_used"] = own_sea_not_used(measured, hourly=simulated is not None, left=left)
    return voyage_dataset(lt, crit["limit"], route=simulated, hindcast=hindcast, attrs=attrs)
