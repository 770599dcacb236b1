"""The measured-spectrum response of a route's spectra legs (``measured_response.nc``),
and of every leg whose declared sea model is not the pipeline's JONSWAP: partitions legs
(each hour's partitions laid out as E(t, f, dir)) and Torsethaugen tables (each cell's two
systems, the cells weighted by probability; :mod:`jls.stages.sea_model_spectra`). Beside
the long-crested JONSWAP reference, a short-crested one (``sea.spreading.wind`` about the
hour's mean direction) gives ``sigma_ratio_short_crested``.

A leg given by spectra (``spectra: {file, format}``) is assessed like a hindcast leg on
its hourly Hs and Tm02 (:mod:`jls.sea.records`); this stage adds what that single-JONSWAP
view of each hour leaves out. For every recorded hour and every candidate x tugger the
relative-sway sigma is integrated directly over the measured spectrum
(:func:`jls.response.directional.directional_moments`, one matrix product over hours x
options), and beside it the sigma of the pipeline's JONSWAP (gamma and Tp = f(Tz) of the
response stage) with the hour's Hs and Tz = Tm02, met at the relative heading of the
hour's mean wave direction (long-crested, |H|^2 interpolated between the RAO headings as
in the directional integral).

Cases of a leg, each with its probability:

* a directional spectrum and the vessel's course (``course_deg``, or ``waypoints``:
  one case per segment bearing, weighted by its share of the distance): every direction
  bin is met at its relative heading;
* otherwise (a 1-D spectrum, or a leg with given relative headings): the frequency
  spectrum long-crested at each of the leg's headings with its probability (the spectrum's
  directions, if any, are not used without a course: attribute ``integration_<leg>``).

The per-hour sigmas are probability-weighted over the cases; the leg's ratio is

    sigma_ratio = sum_t sigma_measured(t) / sum_t sigma_jonswap(t)

over the leg's recorded hours (each hour equally probable, as in the leg's binned
scatter), per candidate and tugger: what a single JONSWAP on the same (Hs, Tz) makes of
the sway the measured seas drive.

``utilisation`` (leg, time, heading, candidate, tugger, criterion; with the configuration,
``cfg``): every criterion of each hour on the hour's own directional sea
(:mod:`jls.stages.hourly_seas`), which the workability, the weather windows and the route
and departure simulations judge the leg's hours on; beside it what the voyage extremes
need of each hour on its own sea: ``tz_response_own``, the criterion's up-crossing period
(the governing tip point's or wire's for the tip clearance and the tensions); the
standard deviation of the criterion's level (utilisation x limit for a relative motion,
the utilisation for the others) is not stored: it is the sigma whose MPM over the
exposure at that period is the level, formed where it is used
(:func:`jls.assessment.hourly.own_sigma`). ``probability``
(leg, time, heading): each record's probability at each heading within the leg (a
table's cell probability times the heading's; an hour's share of the leg's recorded hours
met at the heading): ``heading_weight`` normalised over the leg.

``heading_weight`` (leg, time, heading) says at which of the leg's relative headings each
hour is met (:func:`jls.sea.headings.hour_headings`), so that the hourly verdicts of the weather windows
and the workability (:mod:`jls.assessment.hourly`) weigh each hour as the leg's binned
sea states do.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from jls.io import registry
from jls.names import RELATIVE_SWAY, RESPONSES
from jls.response.directional import directional_moments, heading_weights
from jls.response.moments import excitation
from jls.response.solver import relative_power
from jls.response.statistics import trapezoid_weights, unit_spectra
from jls.sea.headings import hour_headings, leg_courses, relative_heading
from jls.sea.measured import frequency_spectrum
from jls.sea.records import mean_direction, read_leg_spectra, sea_model, spectra_series
from jls.sea.sea_state import parse_spreading
from jls.sea.spectra import tp_from_tz

SWAY = RESPONSES.index(RELATIVE_SWAY)
TZ_STEP_S = 0.05          # Tz grid of the JONSWAP reference (m0 linear between its points)
CHUNK = 4096              # hours per block of the JONSWAP reference
SHORT_CRESTED_BLOCK = 512  # hours per block of the short-crested reference


def sway_power(plant: xr.Dataset, motion: xr.Dataset, tuggers: dict, omega_step: float,
               threads=None) -> xr.DataArray:
    """|H|^2 of the relative sway [m^2/m^2] (candidate, tugger, heading, omega) of every
    candidate and tugger at every heading of the vessel motion."""
    exc = excitation(plant, motion, motion["heading"].values, omega_step)
    P = relative_power(plant["M"].values, plant["K"].values, plant["Kb"].values, plant["C"].values,
                       exc.omega, exc.qb, exc.fairlead_sway, [float(c) for c in tuggers.values()],
                       threads=threads)[:, :, :, SWAY, :]
    return xr.DataArray(P, dims=("candidate", "tugger", "heading", "omega"),
                        coords={"candidate": plant["candidate"].values, "tugger": list(tuggers),
                                "heading": exc.headings, "omega": exc.omega})


def _cases(leg: dict, efth: xr.DataArray):
    """[(efth on (time, freq, dir), course, weight)] and a description of the integration."""
    if "dir" in efth.dims and ("course_deg" in leg or "waypoints" in leg):
        courses, weights = leg_courses(leg, f"legs[{leg['name']}]")
        text = "directional spectrum, course " + ", ".join(f"{c:.0f}" for c in courses) + " deg"
        return [(efth, float(c), float(w)) for c, w in zip(courses, weights)], text
    e1 = efth
    if "dir" in efth.dims:
        e1 = frequency_spectrum(efth)
    out = []
    for h, p in zip(leg["headings_deg"], leg["heading_probability"]):
        d = np.mod(180.0 - float(h), 360.0)         # met at relative heading h on course 0
        out.append(((e1 / 360.0).expand_dims(dir=[d], axis=-1), 0.0, float(p)))
    why = "1-D spectrum" if "dir" not in efth.dims else "no course given: directions not used"
    text = (f"frequency spectrum long-crested at the leg's headings ({why}): "
            + ", ".join(f"{float(h):g} deg ({float(p):.2f})" for h, p in
                        zip(leg["headings_deg"], leg["heading_probability"])))
    return out, text


def _jonswap_unit_m0(power: xr.DataArray, tz_grid, gamma) -> np.ndarray:
    """m0 at Hs = 1 m (candidate, tugger, heading, tz) of the pipeline's JONSWAP."""
    omega = power["omega"].values
    S = unit_spectra(omega, tz_grid, gamma)                        # (n_tz, n_w)
    return np.einsum("cthw,zw->cthz", power.values * trapezoid_weights(omega), S)


def _jonswap_sigma(unit_m0, headings, tz_grid, hs, tz, beta) -> np.ndarray:
    """sigma (time, candidate, tugger) of JONSWAP(Hs, Tz) met at relative heading beta."""
    i0, i1, w1 = heading_weights(headings, beta, False)
    j = np.clip(np.searchsorted(tz_grid, tz) - 1, 0, tz_grid.size - 2)
    a = np.clip((tz - tz_grid[j]) / (tz_grid[j + 1] - tz_grid[j]), 0.0, 1.0)

    def at(i):
        return (1 - a)[:, None, None] * np.moveaxis(unit_m0[:, :, i, j], -1, 0) + \
            a[:, None, None] * np.moveaxis(unit_m0[:, :, i, j + 1], -1, 0)
    m0 = (1 - w1)[:, None, None] * at(i0) + w1[:, None, None] * at(i1)
    return hs[:, None, None] * np.sqrt(np.maximum(m0, 0.0))


def _short_crested_sigma(hs, tz, d, gamma, spreading, power, course, times):
    """sigma (time, candidate, tugger) of JONSWAP(Hs, Tz) spread by ``spreading`` about the
    directions ``d`` [deg, from] met on ``course`` (the short-crested reference), in blocks
    of hours (bounded memory)."""
    from jls.sea.partitions import directional_spectra
    from jls.sea.sea_state import SeaState, WaveSystem
    out = np.empty((len(hs), power.sizes["candidate"], power.sizes["tugger"]))
    tp = np.asarray(tp_from_tz(tz, gamma), float)
    for a in range(0, len(hs), SHORT_CRESTED_BLOCK):
        b = slice(a, a + SHORT_CRESTED_BLOCK)
        states = [SeaState((WaveSystem("jonswap", float(h), float(t), float(x) % 360.0, spreading, "wind",
                                       float(gamma)),)) for h, t, x in zip(hs[b], tp[b], d[b])]
        e = directional_spectra(states, pd.DatetimeIndex(times[b]))
        out[b] = directional_moments(e, power, course)["sigma"].transpose("time", "candidate", "tugger").values
    return out


def leg_response(leg: dict, power: xr.DataArray, *, gamma: float, base_dir=".", efth=None,
                 weights=None, short_crested=None, cases=None) -> xr.Dataset:
    """The per-hour variables of one spectra leg (module docstring), dims (time, candidate,
    tugger). ``efth``: the leg's spectra when already read (else read from its file);
    ``weights`` (time,): each record's probability when the records are the cells of a
    table (:func:`jls.stages.sea_model_spectra.leg_spectra`), else each hour alike;
    ``short_crested``: a :class:`jls.sea.sea_state.Spreading` for the short-crested JONSWAP
    reference (``sigma_jonswap_short_crested``, ``sigma_ratio_short_crested``); ``cases``:
    ([(efth, course, weight)], description) when the leg's sea sets them itself (a table's
    systems spread about each of the leg's headings), else :func:`_cases`."""
    efth = read_leg_spectra(leg, base_dir) if efth is None else efth
    series = spectra_series(efth)                  # hours with energy; the others are gaps
    if weights is not None:
        weights = np.asarray(weights, float)[np.isin(efth["time"].values, series.index.tz_convert(None).to_numpy())]
    if len(series) < efth.sizes["time"]:           # leave out the hours without energy
        efth = efth.sel(time=series.index.tz_convert(None).to_numpy())
    hs, tz = series["hs"].to_numpy(float), series["tz"].to_numpy(float)
    cases, text = _cases(leg, efth) if cases is None else cases
    tz_grid = np.arange(np.floor(tz.min() / TZ_STEP_S) - 1, np.ceil(tz.max() / TZ_STEP_S) + 2) * TZ_STEP_S
    unit_m0 = _jonswap_unit_m0(power, tz_grid, gamma)
    shape = (len(hs), power.sizes["candidate"], power.sizes["tugger"])
    meas, jons, outside = np.zeros(shape), np.zeros(shape), np.zeros(len(hs))
    short = np.zeros(shape)
    for e, course, w in cases:
        mom = directional_moments(e, power, course)
        meas += w * mom["sigma"].transpose("time", "candidate", "tugger").values
        outside += w * mom["energy_outside"].values
        d = mean_direction(e) if e.sizes["dir"] > 1 else np.full(len(hs), e["dir"].values[0])
        beta = relative_heading(course, d)
        for a in range(0, len(hs), CHUNK):      # bounded memory: (candidate, tugger) x CHUNK hours
            b = slice(a, a + CHUNK)
            jons[b] += w * _jonswap_sigma(unit_m0, power["heading"].values, tz_grid, hs[b], tz[b], beta[b])
        if short_crested is not None:
            short += w * _short_crested_sigma(hs, tz, d, gamma, short_crested, power, course,
                                              series.index.tz_convert(None).to_numpy())
    dims = ("time", "candidate", "tugger")
    direction = series["direction"].to_numpy(float) if "direction" in series else np.full(len(hs), np.nan)
    hw = hour_headings(leg, direction)
    if weights is not None:                        # a table's cells: each with its probability
        hw = hw * (weights / weights.sum() * len(hs))[:, None]
    ds = xr.Dataset({"sigma_measured": (dims, meas), "sigma_jonswap": (dims, jons),
                     "hs": ("time", hs), "tz": ("time", tz), "energy_outside": ("time", outside),
                     "heading_weight": (("time", "heading"), hw)},
                    coords={"time": series.index.tz_convert(None).to_numpy(),
                            "candidate": power["candidate"].values, "tugger": power["tugger"].values,
                            "heading": np.asarray(leg["headings_deg"], float)})
    w = xr.DataArray(hw.sum(axis=1) if weights is not None else np.ones(len(hs)), dims="time")
    ds["sigma_ratio"] = (w * ds["sigma_measured"]).sum("time") / (w * ds["sigma_jonswap"]).sum("time")
    if short_crested is not None:
        ds["sigma_jonswap_short_crested"] = (dims, short)
        ds["sigma_ratio_short_crested"] = (w * ds["sigma_measured"]).sum("time") / (w * ds["sigma_jonswap_short_crested"]).sum("time")
    ds["hours"] = len(hs)
    ds.attrs.update(integration=text, source=str(efth.attrs.get("source", "")),
                    sha256=str(efth.attrs.get("sha256", "")), format=str(efth.attrs.get("format", "")))
    return ds


def mean_spectrum(efth: xr.DataArray, weights, omega) -> np.ndarray:
    """S(omega) [m^2 s/rad] on ``omega`` of the leg's records ``efth`` (time, freq[, dir]),
    their probability-weighted mean (``weights`` per record, a table's cell probabilities,
    else every record with energy alike): the leg's typical spectrum, E(f) / 2 pi at omega = 2 pi f,
    linear between the frequencies and zero outside."""
    e1 = np.nan_to_num(frequency_spectrum(efth).transpose("time", "freq").values)
    w = np.ones(e1.shape[0]) if weights is None else np.asarray(weights, float)
    w = np.where(e1.sum(axis=1) > 0, w, 0.0)          # a record without energy is a gap
    mean = np.einsum("t,tf->f", w / w.sum(), e1)
    return np.interp(omega, 2 * np.pi * efth["freq"].values, mean / (2 * np.pi), left=0.0, right=0.0)


def measured_response(route: dict, plant: xr.Dataset, motion: xr.Dataset, tuggers: dict, *,
                      gamma: float, omega_step: float, base_dir=".", threads=None, sea: dict | None = None,
                      cfg: dict | None = None) -> xr.Dataset:
    """``measured_response.nc`` of the route's legs whose sea is not the pipeline's JONSWAP
    (layout ``measured_response`` of the registry): spectra legs, partitions legs and
    Torsethaugen tables (:func:`jls.sea.records.sea_model`; their spectra laid out by
    :func:`jls.stages.sea_model_spectra.leg_spectra`, which needs ``sea``, the
    configuration's sea block). ``route``: the route's configuration with ``name``.
    ``cfg``: the validated configuration; with it, ``utilisation`` (leg, time, heading,
    candidate, tugger, criterion): every criterion of each hour on the hour's own
    directional sea (:mod:`jls.stages.hourly_seas`), which the workability judges the
    leg's hours on."""
    from jls.stages.sea_model_spectra import leg_spectra
    legs = [leg for leg in route["legs"] if sea_model(leg) != "jonswap"]
    power = sway_power(plant, motion, tuggers, omega_step, threads)
    tr = None
    if cfg is not None:
        from jls.response.sea_state import sea_state_transfer
        tr = sea_state_transfer(plant, motion, tuggers, omega_step, cfg["vessel"].get("outside_rao_range"))
    parts, attrs = [], {}
    for leg in legs:
        efth, weights, cases = leg_spectra(leg, base_dir, gamma=gamma, sea=sea)
        short = None if sea is None else parse_spreading(sea["spreading"]["wind"], "sea.spreading.wind")
        part = leg_response(leg, power, gamma=gamma, base_dir=base_dir, efth=efth, weights=weights,
                            short_crested=short, cases=cases)
        part["spectrum_mean"] = ("omega", mean_spectrum(efth, weights, power["omega"].values))
        part = part.assign_coords(omega=power["omega"].values)
        part.attrs["integration"] = f"{sea_model(leg)}: {part.attrs['integration']}"
        if tr is not None:
            part = part.merge(_own_utilisation(tr, cfg, leg, part, efth, base_dir, gamma, sea, threads))
        for k in ("integration", "source", "sha256", "format"):
            attrs[f"{k}_{leg['name']}"] = part.attrs.pop(k)
        parts.append(part.expand_dims(leg=[leg["name"]]))
    ds = xr.concat(parts, dim="leg", join="outer")
    for v in ("sigma_measured", "sigma_jonswap", "sigma_jonswap_short_crested"):
        if v in ds:
            ds[v] = ds[v].transpose("leg", "time", "candidate", "tugger")
    ds["heading_weight"] = ds["heading_weight"].fillna(0.0).transpose("leg", "time", "heading")
    hw = ds["heading_weight"]
    ds["probability"] = hw / hw.sum(("time", "heading"))        # each record at each heading, within the leg
    if "utilisation" in ds:
        from jls.stages.hourly_seas import RULE
        for v in ("utilisation", "tz_response_own"):
            ds[v] = ds[v].transpose("leg", "time", "heading", "candidate", "tugger", "criterion")
        attrs["hourly_utilisation_rule"] = RULE
    ds["hours"] = ds["hours"].astype(np.int64)
    registry.annotate(ds, "measured_response")
    ds.attrs.update(attrs, route=route.get("name", ""), gamma=float(gamma), response=RELATIVE_SWAY,
                    ratio="sum over the leg's hours of sigma over the measured spectrum / the same "
                          "over JONSWAP(Hs, Tz = Tm02) at the mean direction's heading")
    return ds


def _own_utilisation(tr, cfg, leg, part, efth, base_dir, gamma, sea, threads):
    """The leg's hourly ``utilisation`` on its own seas (:mod:`jls.stages.hourly_seas`)."""
    from jls.stages.hourly_seas import leg_utilisation, model_states
    states, directional = model_states(leg, part["time"].values, efth=efth, base_dir=base_dir,
                                       gamma=gamma, sea=sea)
    return leg_utilisation(tr, cfg, leg, states, part["heading_weight"].values, directional=directional,
                           threads=threads, source=part.attrs.get("source")).assign_coords(time=part["time"])


__all__ = ["sway_power", "leg_response", "measured_response", "mean_spectrum"]

