"""Spectra checked against a companion parameter file of the same buoy.

NDBC publishes, beside a buoy's spectral files, its standard meteorological file
(``41010h2019.txt``: WVHT, the significant height NDBC computes from the same spectra, and
MWD, the direction the dominant waves come from). A leg given by spectra may name it
(``spectra.parameters_file``); the records of the two files at the same hour (within
30 min) are compared:

* **Hs**: the median ratio of the spectra's Hs = 4 sqrt(m0) to WVHT must lie within
  :data:`HS_RATIO`. A ratio near 1/sqrt(2 pi) = 0.40 (or sqrt(2 pi) = 2.51) is a density
  per rad/s given as per Hz (or the other way round) and named as such: the 2 pi factor;
  any other is named with both files.
* **direction**: the median circular difference between the spectra's energy-weighted
  mean direction and MWD; within :data:`OPPOSITE_DEG` of 180 deg the directions of one
  file are "going to" where the other's are "coming from". Smaller differences are not
  judged (MWD is the direction of the peak period's waves, not the mean of all).

Errors are :class:`jls.errors.InputError` naming the spectra file, the parameter file and
the two numbers.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from jls.errors import InputError

#: The spectra's Hs over the parameter file's, median over common records.
HS_RATIO = (0.85, 1.18)
#: A median direction difference within this of 180 deg: going-to against coming-from.
OPPOSITE_DEG = 45.0
#: Records of the two files closer than this are the same hour.
TOLERANCE = pd.Timedelta("30min")
#: Only records with an Hs of at least this much are compared [m].
MIN_HS_M = 0.3
TWO_PI_ROOT = float(np.sqrt(2.0 * np.pi))


def _pairs(series: pd.DataFrame, params: pd.DataFrame) -> pd.DataFrame:
    a = series.sort_index().reset_index().rename(columns={series.index.name or "index": "time"})
    b = params.sort_index().reset_index().rename(columns={params.index.name or "index": "time"})
    a["time"] = pd.to_datetime(a["time"], utc=True).astype("datetime64[ns, UTC]")
    b["time"] = pd.to_datetime(b["time"], utc=True).astype("datetime64[ns, UTC]")
    return pd.merge_asof(a, b, on="time", suffixes=("", "_params"), tolerance=TOLERANCE,
                         direction="nearest")


def check_parameters(series: pd.DataFrame, params: pd.DataFrame, spectra_file, params_file,
                     field: str = "parameters_file") -> dict:
    """Compare a spectra leg's hourly record (``hs``[, ``direction``]; from
    :func:`jls.sea.records.spectra_series`) with the parameter file's (``hs``[,
    ``direction``]; :func:`jls.sea.metocean.read_metocean`). Returns the medians found
    (``hs_ratio``, ``direction_difference_deg``, ``n_common``)."""
    sname, pname = Path(str(spectra_file)).name, Path(str(params_file)).name
    both = _pairs(series, params)
    both = both[np.isfinite(both["hs"]) & np.isfinite(both["hs_params"])
                & (both["hs_params"] >= MIN_HS_M)]
    if both.empty:
        raise InputError(f"no record of {sname} lies within {TOLERANCE} of one of {pname} with "
                         f"an Hs of {MIN_HS_M:g} m or more: is it the same buoy and time span?",
                         file=params_file, field=field, value=str(params_file))
    ratio = float(np.median(both["hs"] / both["hs_params"]))
    out = {"hs_ratio": ratio, "n_common": int(len(both))}
    if not HS_RATIO[0] <= ratio <= HS_RATIO[1]:
        if abs(ratio * TWO_PI_ROOT - 1.0) < 0.1:
            why = (f"{ratio:.2f} x, 1/sqrt(2 pi): the density is per rad/s where per Hz is "
                   "read (a factor 2 pi in the density): convert it to m2/Hz")
        elif abs(ratio / TWO_PI_ROOT - 1.0) < 0.1:
            why = (f"{ratio:.2f} x, sqrt(2 pi): the density was multiplied by 2 pi (per Hz "
                   "given as per rad/s?)")
        else:
            why = f"{ratio:.3g} x: another buoy, another unit, or a scaled file?"
        raise InputError(f"the spectra's Hs (4 sqrt(m0)) is, in the median over {len(both)} "
                         f"common hours, {why}; {pname} states WVHT "
                         f"{float(np.median(both['hs_params'])):.2f} m against the spectra's "
                         f"{float(np.median(both['hs'])):.2f} m", file=spectra_file, field=field,
                         value=round(ratio, 4))
    if "direction" in both and "direction_params" in both:
        d = both[np.isfinite(both["direction"]) & np.isfinite(both["direction_params"])]
        if len(d):
            diff = np.mod(d["direction"] - d["direction_params"] + 180.0, 360.0) - 180.0
            med = float(np.degrees(np.angle(np.mean(np.exp(1j * np.radians(diff))))))
            out["direction_difference_deg"] = med
            if abs(abs(med) - 180.0) <= OPPOSITE_DEG:
                raise InputError(f"the spectra's mean directions differ from {pname}'s MWD by "
                                 f"{med:+.0f} deg in the median over {len(d)} common hours: one "
                                 "file gives the direction the waves go TO where the other gives "
                                 "where they come FROM (jls reads 'coming from', as NDBC's MWD)",
                                 file=spectra_file, field=field, value=round(med, 1))
    return out


__all__ = ["check_parameters", "HS_RATIO", "OPPOSITE_DEG"]
