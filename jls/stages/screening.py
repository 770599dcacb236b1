"""The screening dataset (``screening.nc``): the rigging grid of the route scored, the
one-at-a-time sensitivity and the refined optimum (layout ``screening`` of the registry;
the algorithm is :mod:`jls.design.screening`)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.config.builders import (
    margin_families,
    rigging_from_config,
    scoring_from_config,
    screening_settings_from_config,
)
from jls.design.margins import margin_sweep
from jls.design.scoring import screening_states
from jls.design.screening import optimised_values, screening_dataset
from jls.errors import InputError
from jls.io import registry


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
    rig, settings = rigging_from_config(cfg), screening_settings_from_config(cfg)
    ds = screening_dataset(rig, motion, sea, scoring, settings, moments=moments, threads=threads)
    ds.attrs["design_hs_m"] = float(cfg["screening"]["design_hs_m"])   # the report's Tz window
    families = margin_families(cfg, optimised_values(ds) if ds.attrs["optimum_candidate"] else None)
    sweep = margin_sweep(rig, families, cfg["screening"]["margin_sweep_m"], motion, sea, scoring, settings)
    attrs = dict(ds.attrs)
    ds.attrs = {}
    ds = xr.merge([ds, sweep], compat="override", join="outer", combine_attrs="override")
    ds.attrs.update(attrs)
    return registry.annotate(ds, "screening")
