"""The voyage plan (``voyage_plan.nc``, layout ``voyage_plan`` of the registry): the
transit as it will be sailed, per option.

* **The class** of every stretch between hold points and of the route (DNV-ST-N001,
  :func:`jls.assessment.operation.stretch_classes`): the route is weather-restricted
  when every stretch is;
* **the unrestricted design check** (:mod:`jls.assessment.design_contour`): the design
  levels along the IFORM contour of each leg's sea states (its hourly records in the
  departure months when it has them, else its scatter table) for the configured return
  period;
* **the departure rule** sailed through the legs' hourly records from every departure
  hour of the season (:mod:`jls.assessment.voyage_plan`), when every leg has records
  (a leg given by them, or a table leg carrying the records it was binned from); else
  the dataset says why not (attribute ``plan_reason``);
* **consistency** of a leg given by a table and records: the records binned on the
  table's bins against the table (attribute ``consistency``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import xarray as xr

from jls.assessment.criterion_levels import criterion_statistics
from jls.assessment.design_contour import METHOD, contours, design_check, fit, reliability_index, verdict
from jls.assessment.hourly import OWN_SEA_NOT_USED, route_own_utilisation, route_sway_scale
from jls.assessment.operation import RESTRICTED, UNRESTRICTED, AlphaTable, stretch_classes
from jls.assessment.route_hours import common_hours
from jls.assessment.voyage_plan import alpha_periods, forecast_table
from jls.assessment.voyage_plan import voyage_plan as simulate_plan
from jls.assessment.workability import criteria_array
from jls.errors import InputError
from jls.io import registry
from jls.sea.hindcast import bin_hindcast, read_hindcast
from jls.sea.records import is_hourly, leg_series, leg_source
from jls.sea.spectra import tp_from_tz, tz_from_tp
from jls.stages.swell_limits import partition_legs, swell_table

CONSISTENT = "the records binned on the table's bins equal the table within rounding"
#: peak periods of the master's table [s] when no leg says otherwise
MASTER_TP_S = np.arange(4.0, 20.01, 1.0)
#: columns of the master's table at most (page 1): the step in Tp widens beyond it
MASTER_MAX_COLUMNS = 17


def leg_tp_range(sea: xr.Dataset, records: dict, gamma: float) -> dict:
    """Leg name -> (smallest, largest) peak period [s] of the leg's seas: the Tz of its
    table's columns that hold probability and of its hourly records, as the JONSWAP of
    ``gamma`` has them."""
    out = {}
    for leg in (str(x) for x in sea["leg"].values):
        p = sea["probability"].sel(leg=leg).fillna(0.0).sum("hs").values
        tz = list(np.asarray(sea["tz"].values, float)[p > 0])
        if leg in records:
            r = np.asarray(records[leg]["tz"], float)
            tz += list(r[np.isfinite(r)])
        if tz:
            out[leg] = (float(tp_from_tz(min(tz), gamma)), float(tp_from_tz(max(tz), gamma)))
    return out


def master_periods(ranges: dict) -> np.ndarray:
    """The peak periods of the master's table: whole seconds from below the smallest to
    above the largest Tp of every leg's seas (:func:`leg_tp_range`), in steps of 1 s, or
    wider to keep :data:`MASTER_MAX_COLUMNS`; :data:`MASTER_TP_S` without a range."""
    if not ranges:
        return MASTER_TP_S
    lo = float(np.floor(min(r[0] for r in ranges.values())))
    hi = float(np.ceil(max(r[1] for r in ranges.values())))
    step = max(1.0, float(np.ceil((hi - lo) / (MASTER_MAX_COLUMNS - 1))))
    n = int(np.ceil((hi - lo) / step - 1e-9)) + 1
    return lo + step * np.arange(n)


def leg_records(route: dict, base_dir=".", *, gamma: float) -> dict:
    """Leg name -> hourly record of every leg that has one: a leg given by records, or a
    scatter-table leg's ``records``."""
    out = {}
    for leg in route["legs"]:
        if is_hourly(leg):
            out[leg["name"]] = leg_series(leg, base_dir, gamma=gamma)
        elif "records" in leg:
            path = Path(base_dir) / leg["records"]["file"]
            if not path.exists():
                raise InputError("file not found", file=path, field=f"legs[{leg['name']}].records.file")
            df = read_hindcast(path)
            df.attrs["source"] = str(leg["records"]["file"])
            out[leg["name"]] = df
    return out


def consistency(sea: xr.Dataset, leg: str, record: pd.DataFrame) -> str:
    """The records of a table leg binned on the table's bins against the table: equal
    within rounding (half a record per cell), or the largest difference stated."""
    lo_h, up_h = sea["hs_lower"].sel(leg=leg).values, sea["hs_upper"].sel(leg=leg).values
    lo_t, up_t = sea["tz_lower"].sel(leg=leg).values, sea["tz_upper"].sel(leg=leg).values
    ih, it = np.flatnonzero(np.isfinite(lo_h)), np.flatnonzero(np.isfinite(lo_t))   # the leg's own bins
    binned = bin_hindcast(record, np.r_[lo_h[ih[:1]], up_h[ih]], np.r_[lo_t[it[:1]], up_t[it]],
                          outside="report")
    n = int(binned.attrs["n_records"])
    p_rec = binned["count"].values / max(n, 1)
    p_tab = sea["probability"].sel(leg=leg).transpose("hs", "tz").values[np.ix_(ih, it)]
    diff = np.abs(p_rec - p_tab)
    tol = 0.5 / max(n, 1) + 1e-9
    outside = int(binned.attrs.get("n_outside", 0))
    if diff.max() <= tol and outside == 0:
        return CONSISTENT
    i, j = np.unravel_index(int(np.argmax(diff)), diff.shape)
    text = (f"the records binned on the table's bins differ from the table: largest cell difference "
            f"{100 * diff[i, j]:.2f} percentage points (Hs {float(sea['hs'].values[ih[i]]):g} m, Tz "
            f"{float(sea['tz'].values[it[j]]):g} s)")
    return text + (f"; {outside} records lie outside the table's bins" if outside else "")


def _design(sea, op, records, months, cfg_op, exposure_h):
    """Contours (leg, angle), their basis per leg and the design check."""
    beta_all = {}
    models, basis = {}, {}
    share = len(months) / 12.0
    for leg in (str(x) for x in sea["leg"].values):
        if leg in records:
            r = records[leg]
            r = r[np.isin(pd.DatetimeIndex(r.index).month, months)]
            models[leg] = fit(r["hs"].values, r["tz"].values, source=r.attrs.get("source"))
            basis[leg] = f"hourly records, months {' '.join(map(str, months))}"
            beta_all[leg] = reliability_index(cfg_op["design_return_period_years"], exposure_h, share)
        else:
            p = sea["probability"].sel(leg=leg).transpose("hs", "tz")
            hs, tz = np.meshgrid(sea["hs"].values, sea["tz"].values, indexing="ij")
            models[leg] = fit(hs, tz, p.values)
            basis[leg] = "scatter table (all year)"
            beta_all[leg] = reliability_index(cfg_op["design_return_period_years"], exposure_h)
    parts = [contours({leg: m}, beta_all[leg]) for leg, m in models.items()]
    cont = xr.concat(parts, dim="leg")
    return cont, basis, design_check(op, cont, sea["heading_probability"], op["limit"])


def route_stretches(legs: list[dict], duration_h, operation: dict):
    """(hold point per leg, contingency per leg, the stretches' classes) of a route's legs
    (configuration mappings, in sailing order) of durations ``duration_h``: the route's
    ``operation.contingency_h`` goes to its last leg when it is one stretch and no leg
    states its own."""
    names = [leg["name"] for leg in legs]
    hold = [True] + [bool(leg["hold_point"]) for leg in legs[1:]]
    cont_leg = [leg.get("contingency_h") for leg in legs]
    if all(c is None for c in cont_leg) and sum(hold) == 1 and operation.get("contingency_h") is not None:
        cont_leg[-1] = float(operation["contingency_h"])          # the route's T_C: one stretch
    return hold, cont_leg, stretch_classes(names, [float(d) for d in duration_h], hold, cont_leg)


def alpha_table(operation: dict) -> AlphaTable | None:
    """The configuration's alpha table (``operation.alpha_factors``), None without one."""
    table = operation.get("alpha_factors")
    return None if table is None else AlphaTable(source=table["source"], period_h=table["planned_period_h"],
                                                 hs_m=table["hs_m"], alpha=table["alpha"])


def leg_periods(classes) -> dict:
    """Leg name -> the planned period of its stretch [h]: where alpha is read."""
    return {leg: float(s.basis.planned_h) for s in classes for leg in s.legs}


def voyage_plan(sea: xr.Dataset, operability: xr.Dataset, route: dict, criteria: dict, operation: dict,
                *, gamma: float, exposure_h: float, base_dir=".", measured: xr.Dataset | None = None,
                transfer=None, config: dict | None = None) -> xr.Dataset:
    """``operation``: the configuration's ``operation`` section (``departure_rule``,
    ``design_return_period_years``, ``alpha_factors``, ``contingency_h``); ``route``: the
    route's configuration; ``transfer``, ``config``: the options' sea-state transfer
    (:func:`jls.commands.response.transfer_from_config` of the assessed plant) and the
    validated configuration, for the swell table of partitioned legs
    (:mod:`jls.stages.swell_limits`; needed when the route has one). Returns the dataset
    (module docstring)."""
    legs = route["legs"]
    names = [leg["name"] for leg in legs]
    rule = operation["departure_rule"]
    months = sorted(int(m) for m in rule["months"])
    limit = criteria_array(criteria)
    op = criterion_statistics(operability, limit)
    dur = [float(sea["duration_h"].sel(leg=n)) for n in names]
    hold, cont_leg, classes = route_stretches(legs, dur, operation)
    records = leg_records(route, base_dir, gamma=gamma)
    cont, design_basis, design = _design(sea, op, records, months, operation, exposure_h)
    ok = verdict(design, strict=limit["strict"] if "strict" in limit.coords else None)
    ds = xr.Dataset({
        "design_level": design["design_level"].transpose("candidate", "tugger", "criterion", "leg"),
        "design_utilisation": design["design_utilisation"].transpose("candidate", "tugger", "criterion", "leg"),
        "design_hs": design["design_hs"].transpose("candidate", "tugger", "criterion", "leg"),
        "design_tz": design["design_tz"].transpose("candidate", "tugger", "criterion", "leg"),
        "design_acceptable": ok.astype(np.int8).transpose("candidate", "tugger"),
        "contour_hs": cont["contour_hs"], "contour_tz": cont["contour_tz"],
        "limit": op["limit"],
    })
    stretch_of = {leg: i for i, s in enumerate(classes) for leg in s.legs}
    cls_of = {leg: s.basis.operation_class for s in classes for leg in s.legs}
    ds["leg_class"] = ("leg", np.array([cls_of[n] for n in names], dtype=object))
    ds["leg_stretch"] = ("leg", np.array([stretch_of[n] for n in names], np.int64))
    ds["leg_hold_point"] = ("leg", np.array(hold, np.int8))
    ds["leg_design_basis"] = ("leg", np.array([design_basis[n] for n in names], dtype=object))
    route_class = RESTRICTED if all(s.restricted for s in classes) else UNRESTRICTED
    ds.attrs.update(
        route_class=route_class,
        stretches="; ".join(f"{', '.join(s.legs)}: {s.basis.operation_class} ({s.basis.reason})" for s in classes),
        class_statement="; ".join(s.statement for s in classes if s.statement),
        design_method=METHOD, design_return_period_years=float(operation["design_return_period_years"]),
        forecast=str(rule["forecast"]), forecast_horizon_h=float(rule["forecast_horizon_h"]),
        max_wait_h=float(rule["max_wait_h"]), months=" ".join(map(str, months)),
        alpha_source=(operation["alpha_factors"]["source"] if operation.get("alpha_factors") else ""),
        hours_per_record="1")
    alpha = alpha_table(operation)
    leg_period = [leg_periods(classes)[n] for n in names]
    ranges = leg_tp_range(sea, records, gamma)
    tps = master_periods(ranges)
    master = forecast_table(op, sea["heading_probability"], names, op["limit"],
                            limit["strict"] if "strict" in limit.coords else False,
                            tz_from_tp(tps, gamma), leg_period, alpha)
    tzv = master["tz"].values
    master = master.drop_vars("tz").rename_dims(tz="tp").assign_coords(tp=tps, tz=("tp", tzv))
    grid = np.asarray(op["tz"].values, float)
    inside = xr.DataArray((tzv >= grid.min() - 1e-9) & (tzv <= grid.max() + 1e-9), dims="tp")
    for v in master.data_vars:          # no figure beyond the statistics' Tz range (never held)
        ds[v] = master[v].where(inside).transpose("candidate", "tugger", "leg", "tp")
    nan = float("nan")
    ds["leg_tp_min"] = ("leg", np.array([ranges.get(n, (nan, nan))[0] for n in names]))
    ds["leg_tp_max"] = ("leg", np.array([ranges.get(n, (nan, nan))[1] for n in names]))
    if alpha is not None:
        held = [f"{', '.join(s.legs)} ({s.basis.planned_h:g} h)" for s in classes
                if float(alpha_periods([s.basis.planned_h], alpha)[0]) != s.basis.planned_h]
        ds.attrs["alpha_note"] = ("alpha read at the table's nearest planned period for " + "; ".join(held)
                                  + ": the table does not cover it") if held else ""
    if partition_legs(route):
        if transfer is None or config is None:
            raise ValueError("a route with partitioned legs needs the options' transfer and the configuration "
                             "for its swell table")
        swell = swell_table(route, names, leg_period, config, transfer, ds["candidate"].values.tolist(),
                            ds["tugger"].values.tolist(), gamma=gamma, alpha=alpha, periods=master_periods,
                            base_dir=base_dir)
        ds = xr.merge([ds, swell], compat="override", combine_attrs="override")
        ds.attrs.update(swell.attrs)
    checks = [f"{leg['name']}: {consistency(sea, leg['name'], records[leg['name']])}"
              for leg in legs if not is_hourly(leg) and leg["name"] in records]
    ds.attrs["consistency"] = "; ".join(checks)
    missing = [n for n in names if n not in records]
    if missing:
        ds.attrs["plan_reason"] = (f"no departure simulation: leg{'s' if len(missing) > 1 else ''} "
                                   f"{', '.join(missing)} {'are' if len(missing) > 1 else 'is'} given by a "
                                   "scatter table only, without the hourly records a departure rule is sailed "
                                   "through (give the leg's records beside its table: legs[].records.file)")
        return registry.annotate(ds, "voyage_plan")
    hours = common_hours({n: records[n] for n in names})
    sources = {n: str(records[n].attrs.get("source", leg_source(leg))) for n, leg in zip(names, legs)}
    plan = simulate_plan(op, hours, sea["heading_probability"], dur, op["limit"],
                         strict=limit["strict"] if "strict" in limit.coords else None, hold_point=hold,
                         contingency_h=cont_leg, horizon_h=rule["forecast_horizon_h"],
                         max_wait_h=rule["max_wait_h"], months=months, alpha=alpha, sources=sources,
                         sway_scale=route_sway_scale(measured, hours), own=_own_levels(measured, hours))
    ds = xr.merge([ds, plan.transpose("candidate", "tugger", ...)], compat="override")
    ds.attrs["plan_reason"] = ""
    if route_sway_scale(measured, hours) is not None and route_own_utilisation(measured, hours) is None:
        ds.attrs["own_sea_not_used"] = (f"the departure simulation of leg(s) "
                                        f"{', '.join(str(leg) for leg in measured['leg'].values)} {OWN_SEA_NOT_USED}")
    ds.attrs["record_span"] = (f"{pd.Timestamp(hours['time'].values[0]):%Y-%m-%d}"
                               f" to {pd.Timestamp(hours['time'].values[-1]):%Y-%m-%d}")
    return registry.annotate(ds, "voyage_plan")


def _own_levels(measured, hours):
    """The own-sea hours' utilisation for the departure simulation, which takes their levels
    only (not their sigma and period: memory)."""
    own = route_own_utilisation(measured, hours)
    return None if own is None else own["utilisation"]
