"""The response dataset of the plant variants (``response_variants.nc``): the unit-Hs
statistics of every candidate's variants in damping and sway frequency
(:func:`jls.assessment.uncertainty.plant_variants`) on the legs' Tz values, tugger loads
included, so that the uncertainty bands are judged on each variant's own winch loads
(layout ``response_variants`` of the registry)."""

from __future__ import annotations

import xarray as xr

from jls.assessment.uncertainty import VARIANT_DIMS, plant_variants
from jls.io import registry
from jls.stages.response import response_dataset


def response_variants(plant: xr.Dataset, motion: xr.Dataset, candidates, tz, headings_deg,
                      tuggers: dict, **options) -> xr.Dataset:
    """``candidates``: the candidates whose variants are solved; ``options`` as
    :func:`jls.stages.response.response_dataset` (gamma, exposure, cycles, frequency step,
    RAO-range policy, cache, threads, tensions)."""
    keep = set(candidates)
    variants = plant_variants(plant.sel(candidate=[c for c in plant["candidate"].values.tolist()
                                                   if c in keep]))
    ds = response_dataset(variants, motion, tz, headings_deg, tuggers, shown=(),
                          tugger_loads=True, **options)  # the winch limits hold for the variants too
    ds = ds.assign_coords(base_candidate=("candidate", variants["base_candidate"].values),
                          **{k: ("candidate", variants[k].values) for k in VARIANT_DIMS})
    registry.annotate(ds, "response_variants")
    ds.attrs.update(damping_factors=variants.attrs["damping_factors"],
                    sway_frequency_factors=variants.attrs["sway_frequency_factors"])
    return ds
