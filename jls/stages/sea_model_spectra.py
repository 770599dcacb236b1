"""The spectra E(t, f, dir) of a leg whose sea model is not the pipeline's JONSWAP, as the
measured-spectrum response integrates them (:mod:`jls.stages.measured_response`):

* ``measured`` (a spectra leg): its spectra as read;
* ``partitions`` (an hourly file of wind-sea and swell partitions): each hour's systems,
  JONSWAP of ``sea.gamma`` spread by the leg's spreading (:mod:`jls.sea.partitions`), laid
  out on the direction grid; hours without a partition are gaps;
* ``torsethaugen`` (a scatter table in Hs-Tp): each cell with probability, at its Hs (the
  bin's centre, or its upper edge with ``sea.hs_in_bin: upper``) and Tp, split into its
  wind sea and swell (:func:`jls.sea.sea_state.torsethaugen_systems`); the cells stand as
  records one hour apart from 2000-01-01 (a table has no time), weighted by their
  probability. A table leg has no wave directions: its systems come from the leg's headings
  (the response meets the frequency spectrum long-crested at each, as for any spectra leg
  without a course).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import xarray as xr

from jls.errors import InputError
from jls.sea.partitions import directional_spectra, sea_states
from jls.sea.records import leg_partitions, leg_source, leg_spreading, read_leg_spectra, sea_model
from jls.sea.scatter import read_scatter
from jls.sea.sea_state import SeaState, torsethaugen_systems

__all__ = ["leg_spectra", "TABLE_EPOCH"]

TABLE_EPOCH = np.datetime64("2000-01-01T00:00", "ns")


def leg_spectra(leg: dict, base_dir=".", *, gamma: float, sea: dict | None) -> tuple[xr.DataArray, np.ndarray | None]:
    """(efth (time, freq, dir), weights (time,) or None) of the leg (module docstring)."""
    model = sea_model(leg)
    if model == "measured":
        return read_leg_spectra(leg, base_dir), None
    if sea is None:
        raise InputError("a partitions or Torsethaugen leg needs the configuration's sea block "
                         "(its spreading)", field=f"legs[{leg['name']}].spectrum", value=model)
    spreading = leg_spreading(leg, sea)
    if model == "partitions":
        frame = leg_partitions(leg, base_dir, gamma=gamma)
        states, kept = sea_states(frame, gamma=gamma, spreading=spreading)
        if not states:
            raise InputError("no hour with a partition", file=frame.attrs.get("path"),
                             field=f"legs[{leg['name']}].metocean.file")
        attrs = {k: frame.attrs[k] for k in ("source", "sha256", "path") if k in frame.attrs}
        attrs["format"] = f"partitions ({frame.attrs.get('format', '')})"
        return directional_spectra(states, frame.index[kept], attrs=attrs), None
    if model == "torsethaugen":
        return _table_spectra(leg, base_dir, gamma, sea, spreading)
    raise InputError("a JONSWAP leg has no spectra of its own", field=f"legs[{leg['name']}].spectrum", value=model)


def _table_spectra(leg, base_dir, gamma, sea, spreading):
    path = f"{base_dir}/{leg_source(leg)}"
    ds = read_scatter(path, **{k: leg[k] for k in ("layout", "bins", "values", "period") if k in leg})
    hs = ds["hs_upper"].values if sea["hs_in_bin"] == "upper" else ds["hs"].values
    p = ds["probability"].values
    cells = np.argwhere(p > 0)
    states = []
    for i, j in cells:
        states.append(SeaState(tuple(torsethaugen_systems(float(hs[i]), "tp", float(ds["tz"].values[j]),
                                                          from_deg=0.0, spreading=spreading))))
    times = pd.DatetimeIndex(TABLE_EPOCH + np.arange(len(states)) * np.timedelta64(1, "h"))
    attrs = {"source": str(leg_source(leg).name), "format": "torsethaugen table (Hs-Tp)"}
    return directional_spectra(states, times, attrs=attrs), p[cells[:, 0], cells[:, 1]]
