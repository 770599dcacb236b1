"""The sea of a time-domain cell of a leg whose sea model is not the pipeline's JONSWAP
(``spectrum: partitions | measured | torsethaugen``, :func:`jls.sea.records.sea_model`):
the wave systems the cell's multi-directional record is synthesised from
(:class:`jls.timedomain.directional.DirectionalCase`), never a JONSWAP on the cell's (Hs, Tz).

A cell is (candidate, relative heading h, Hs, Tz) of the leg's binned scatter. Its sea:

* ``torsethaugen`` (a table in Hs-Tp, the cell's ``tz`` being the table's Tp): the cell's
  Torsethaugen wind sea and swell (:func:`jls.sea.sea_state.torsethaugen_systems`), both
  from the direction met at h on course 0, each spread by the leg's spreading of its kind,
  as the frequency domain integrates the table (:mod:`jls.stages.sea_model_spectra`);
* ``partitions`` and ``measured`` (hourly records): the **probability-weighted mixture of
  the hours binned into the cell**: the hours whose Hs and Tz fall in the cell's Hs and Tz
  bins (the leg's edges, as :func:`jls.sea.hindcast.bin_hindcast` bins them), each weighted
  by the share it is met at h (:func:`jls.sea.headings.hour_headings`, the
  weights of the binned scatter). Each hour is turned so that its mean direction is met at
  h on course 0, its systems keeping their directions relative to that mean (the swell
  stays where it is against the wind sea) and their spreading; the systems of all the
  hours then stand together, an hour's variances times its probability in the cell, so the
  mixture's spectrum is the cell's mean directional spectrum and a linear response's
  variance the probability-weighted mean of the hours' variances. The whole is scaled to
  the cell's assessed Hs (the Hs the workability assesses the cell at: bin centre or upper
  edge), keeping its shape. Why the mixture and not one representative hour: it is the
  cell's sea as the binned assessment weighs it (every hour of the cell with its
  probability), it uses every hour's swell and not the one a choice happens to pick, and
  its response variance is the mean over the hours, what the cell's frequency-domain
  statistic is. Partitions are each a JONSWAP of ``sea.gamma`` spread by the leg's
  spreading (wind: ``wind``, the others ``swell``, :func:`jls.sea.partitions.sea_states`);
  measured directional spectra are long-crested per direction bin (as measured, no fit),
  the hours' bins gathered on a 10 deg grid of directions relative to the mean.

Without a course (a leg of given relative headings) the frequency domain meets every hour's
frequency spectrum long-crested at the leg's headings (:mod:`jls.stages.measured_response`):
so does the cell, its mixture's systems long-crested from the direction met at h.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError
from jls.sea.records import leg_kind, leg_partitions, leg_series, leg_spreading, read_leg_spectra, sea_model
from jls.sea.sea_state import (
    Spreading,
    WaveSystem,
    measured_systems,
    torsethaugen_systems,
)

__all__ = ["MODEL_LEG_SEAS", "cell_systems", "cell_hours"]

#: the sea models whose time-domain cells are synthesised from the leg's own sea
MODEL_LEG_SEAS = ("partitions", "measured", "torsethaugen")
GRID_DEG = 10.0           # direction grid of a measured cell's gathered bins


def _bin(x, edges):
    """Bin index of a cell's Hs (centre or upper edge) or Tz (centre): lower < x <= upper."""
    e = np.asarray(edges, float)
    i = int(np.searchsorted(e, float(x), side="left")) - 1
    return min(max(i, 0), e.size - 2)


def _hour_bins(values, edges):
    from jls.sea.hindcast import _index
    return _index(np.asarray(values, float), np.asarray(edges, float))


def cell_hours(leg: dict, series, cell: dict) -> np.ndarray:
    """Weight (n_hours,) of each hour of the leg's record ``series`` (hs, tz, direction)
    in the cell: its share met at the cell's heading if its Hs and Tz lie in the cell's
    bins, else 0 (module docstring)."""
    from jls.sea.headings import hour_headings
    src = leg[leg_kind(leg)]
    ih = _bin(cell["hs"], src["hs_edges_m"])
    it = _bin(cell["tz"], src["tz_edges_s"])
    heads = np.asarray(leg["headings_deg"], float)
    k = np.flatnonzero(np.isclose(heads, float(cell["heading"])))
    if k.size == 0:
        raise InputError(f"the cell's heading is none of the leg's ({', '.join(f'{h:g}' for h in heads)})",
                         field=f"legs[{leg['name']}].headings_deg", value=cell["heading"])
    direction = series["direction"].to_numpy(float) if "direction" in series else np.full(len(series), np.nan)
    w = hour_headings(leg, direction)[:, int(k[0])]
    inside = (_hour_bins(series["hs"], src["hs_edges_m"]) == ih) & (_hour_bins(series["tz"], src["tz_edges_s"]) == it)
    return np.where(inside, w, 0.0)


def _has_course(leg):
    return "course_deg" in leg or "waypoints" in leg


def cell_systems(leg: dict, cell: dict, *, sea: dict, gamma: float, base_dir=".") -> tuple[list, float, str]:
    """(wave systems, course [deg true] they are met on, a sentence saying what they are) of
    the time-domain cell ``cell`` (candidate, heading, hs, tz) of ``leg`` (module
    docstring); ``sea``: the configuration's sea block (spreading, gamma)."""
    model = sea_model(leg)
    field = f"legs[{leg['name']}].spectrum"
    if model not in MODEL_LEG_SEAS:
        raise InputError("a JONSWAP leg's cells are the pipeline's JONSWAP on (Hs, Tz)", field=field, value=model)
    h = float(cell["heading"])
    toward = float(np.mod(180.0 - h, 360.0))          # from this direction, met at h on course 0
    spreading = leg_spreading(leg, sea)
    if model == "torsethaugen":
        systems = torsethaugen_systems(float(cell["hs"]), "tp", float(cell["tz"]), from_deg=toward,
                                       spreading=spreading)
        return systems, 0.0, (f"torsethaugen: the cell's wind sea and swell of Hs {float(cell['hs']):g} m, Tp "
                              f"{float(cell['tz']):g} s met at {h:g} deg, spread "
                              + ", ".join(f"{k} {v}" for k, v in spreading.items()))
    if model == "partitions":
        from jls.sea.partitions import sea_states
        frame = leg_partitions(leg, base_dir, gamma=gamma)
        states, kept = sea_states(frame, gamma=gamma, spreading=spreading)
        series = leg_series(leg, base_dir, gamma=gamma)
        if len(series) != len(states) or not series.index.equals(frame.index[kept]):
            raise InputError("the partitions' hours and the leg's record differ", file=frame.attrs.get("path"),
                             field=f"legs[{leg['name']}].metocean.file")
        w = cell_hours(leg, series, cell)
        hours = [(states[t].systems, float(series["direction"].iloc[t]), w[t]) for t in np.flatnonzero(w > 0)]
        systems = _mixture(leg, hours, toward)
    else:
        efth = read_leg_spectra(leg, base_dir)
        from jls.sea.records import spectra_series
        series = spectra_series(efth)
        efth = efth.sel(time=series.index.tz_convert(None).to_numpy())
        w = cell_hours(leg, series, cell)
        systems = _measured_mixture(leg, efth, series, w, toward)
    if not systems:
        raise InputError("no hour of the leg's record lies in the cell", field=f"legs[{leg['name']}]",
                         value=f"heading {h:g}, Hs {float(cell['hs']):g}, Tz {float(cell['tz']):g}")
    n = int(np.count_nonzero(w > 0))
    m0 = sum(s.m0() for s in systems)
    scale = (float(cell["hs"]) / (4.0 * np.sqrt(m0))) ** 2 if m0 > 0 else 0.0
    systems = [_scaled(s, scale) for s in systems]
    how = ("each hour turned so its mean direction is met at the cell's heading, its systems spread "
           + ", ".join(f"{k} {v}" for k, v in spreading.items()) if model == "partitions" and _has_course(leg)
           else "each hour's directional spectrum turned so its mean direction is met at the cell's heading, "
                "long-crested per direction bin" if _has_course(leg) and "dir" in efth.dims
           else "each hour's frequency spectrum long-crested at the cell's heading (no course)")
    count = f"{n} hours" if n != 1 else "one hour"
    return systems, 0.0, (f"{model}: the probability-weighted mixture of the {count} binned into the cell "
                          f"({how}), scaled to Hs {float(cell['hs']):g} m")


def _scaled(s: WaveSystem, f: float) -> WaveSystem:
    """The system with its variance times ``f`` (the same shape and directions)."""
    if s.shape == "measured":
        dens = s.density * f
        return WaveSystem("measured", 4.0 * float(np.sqrt(max(np.trapezoid(dens, s.omega), 0.0))), s.tp,
                          s.from_deg, s.spreading, s.kind, omega=s.omega, density=dens)
    return WaveSystem(s.shape, s.hs * float(np.sqrt(f)), s.tp, s.from_deg, s.spreading, s.kind, s.gamma)


def _mixture(leg, hours, toward) -> list:
    """The systems of partition hours [(systems, mean direction, weight)] turned and weighted."""
    total = sum(w for _, _, w in hours)
    out = []
    for systems, mean, w in hours:
        for s in systems:
            if _has_course(leg):
                d, spread = np.mod(s.from_deg - mean + toward, 360.0), s.spreading
            else:
                d, spread = toward, Spreading("long-crested")
            out.append(WaveSystem(s.shape, s.hs * float(np.sqrt(w / total)), s.tp, float(d), spread, s.kind,
                                  s.gamma))
    return out


def _measured_mixture(leg, efth, series, w, toward) -> list:
    """The mean measured spectrum of the weighted hours: directional, each hour's bins turned
    onto a grid of directions relative to its mean; else (1-D, or no course) the mean
    frequency spectrum long-crested from ``toward``."""
    keep = np.flatnonzero(w > 0)
    if keep.size == 0:
        return []
    p = w[keep] / w[keep].sum()
    f = efth["freq"].values
    if "dir" in efth.dims and _has_course(leg):
        from jls.sea.directional import direction_widths
        dirs = efth["dir"].values.astype(float)
        width = direction_widths(dirs)
        grid = np.arange(0.0, 360.0, GRID_DEG)
        E = np.zeros((f.size, grid.size))
        e = efth.transpose("time", "freq", "dir").values
        mean = series["direction"].to_numpy(float)
        for t, pt in zip(keep, p):
            rel = np.mod(dirs - mean[t] + toward, 360.0)
            k = np.mod(np.rint(rel / GRID_DEG).astype(int), grid.size)
            np.add.at(E.T, k, (pt * e[t] * width / GRID_DEG).T)
        return measured_systems(f, E, grid)
    e1 = efth
    if "dir" in efth.dims:
        from jls.sea.measured import frequency_spectrum
        e1 = frequency_spectrum(efth)
    E1 = np.einsum("t,tf->f", p, e1.transpose("time", "freq").values[keep])
    return measured_systems(f, E1, from_deg=toward, spreading="long-crested")
