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
  probability. A table leg has no wave directions: at each of the leg's relative headings
  (with its probability) both systems come from the direction met at that heading, each
  spread by the leg's spreading of its kind (one case per heading, course 0).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from jls.errors import InputError
from jls.sea.partitions import directional_spectra, sea_states
from jls.sea.records import leg_partitions, leg_source, leg_spreading, read_leg_spectra, sea_model
from jls.sea.scatter import read_scatter
from jls.sea.sea_state import SeaState, torsethaugen_systems

__all__ = ["leg_spectra", "TABLE_EPOCH"]

TABLE_EPOCH = np.datetime64("2000-01-01T00:00", "ns")


def leg_spectra(leg: dict, base_dir=".", *, gamma: float, sea: dict | None):
    """(efth (time, freq, dir), weights (time,) or None, cases or None) of the leg (module
    docstring); ``cases`` as :func:`jls.stages.measured_response.leg_response` takes them,
    where the leg's sea sets its own (a table), else None."""
    model = sea_model(leg)
    if model == "measured":
        return read_leg_spectra(leg, base_dir), None, None
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
        return directional_spectra(states, frame.index[kept], attrs=attrs), None, None
    if model == "torsethaugen":
        return _table_spectra(leg, base_dir, gamma, sea, spreading)
    raise InputError("a JONSWAP leg has no spectra of its own", field=f"legs[{leg['name']}].spectrum", value=model)


def _table_spectra(leg, base_dir, gamma, sea, spreading):
    path = f"{base_dir}/{leg_source(leg)}"
    ds = read_scatter(path, **{k: leg[k] for k in ("layout", "bins", "values", "period") if k in leg})
    hs = ds["hs_upper"].values if sea["hs_in_bin"] == "upper" else ds["hs"].values
    p = ds["probability"].values
    cells = np.argwhere(p > 0)
    times = pd.DatetimeIndex(TABLE_EPOCH + np.arange(len(cells)) * np.timedelta64(1, "h"))
    attrs = {"source": str(leg_source(leg).name), "format": "torsethaugen table (Hs-Tp)"}
    cases = []
    for h, prob in zip(leg["headings_deg"], leg["heading_probability"]):
        d = float(np.mod(180.0 - float(h), 360.0))           # met at relative heading h on course 0
        states = [SeaState(tuple(torsethaugen_systems(float(hs[i]), "tp", float(ds["tz"].values[j]),
                                                      from_deg=d, spreading=spreading))) for i, j in cells]
        cases.append((directional_spectra(states, times, attrs=attrs), 0.0, float(prob)))
    text = ("Torsethaugen wind sea and swell spread (" + ", ".join(f"{k} {v}" for k, v in spreading.items())
            + ") about the leg's headings: " + ", ".join(f"{float(h):g} deg ({float(p):.2f})" for h, p in
                                                         zip(leg["headings_deg"], leg["heading_probability"])))
    return cases[0][0], p[cells[:, 0], cells[:, 1]], (cases, text)
