"""The screening dataset (``screening.nc``): the rigging grid of the route scored, the
one-at-a-time sensitivity and the refined optimum (layout ``screening`` of the registry;
the algorithm is :mod:`jls.design.screening`)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.config.builders import rigging_from_config, scoring_from_config, screening_settings_from_config
from jls.design.scoring import screening_states
from jls.design.screening import screening_dataset
from jls.errors import InputError


def screening(cfg: dict, motion: xr.Dataset, sea: xr.Dataset, chunks: dict, threads=None) -> xr.Dataset:
    """Score the grid from the chunk jobs' moments (``chunks``: file -> dataset of
    :func:`jls.response.moments.moments_dataset`, in candidate order), refine the optimum.
    A chunk computed on other sea states than the route's is an InputError naming it."""
    scoring = scoring_from_config(cfg)
    tz, headings = screening_states(sea, scoring)
    for path, part in chunks.items():
        if not (np.allclose(part["tz"].values, tz) and np.allclose(part["heading"].values, headings)):
            raise InputError("the chunk's sea states differ from the route's; rerun its chunk job",
                             file=path, field="tz", value=part["tz"].values.tolist())
    parts = list(chunks.values())
    moments = tuple(np.concatenate([p[k].values for p in parts], axis=0) for k in ("m0", "m2"))
    ds = screening_dataset(rigging_from_config(cfg), motion, sea, scoring,
                           screening_settings_from_config(cfg), moments=moments, threads=threads)
    ds.attrs["design_hs_m"] = float(cfg["screening"]["design_hs_m"])   # the report's Tz window
    return ds
