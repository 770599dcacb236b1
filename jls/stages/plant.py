"""The plant dataset (``plant.nc``, and ``plant_assessed.nc`` with the screening's
optimum): every rigging candidate of a configuration with its M, K, Kb, C, modes, static
tensions and safety constraints (layout ``plant`` of the registry)."""

from __future__ import annotations

import xarray as xr

from jls.config.builders import candidate_values, plant_from_config, rigging_from_config
from jls.design.screening import optimised_values
from jls.plant.candidates import plant_dataset


def plant(cfg: dict, source="config") -> xr.Dataset:
    """The configured candidates ('baseline' first). The baseline must itself be a valid
    plant (a slack wire, an unbalanced or unstable layout is an InputError naming it)."""
    plant_from_config(cfg, source=source)
    ds, _ = plant_dataset(rigging_from_config(cfg), candidate_values(cfg))
    return ds


def assessed_plant(cfg: dict, screening: xr.Dataset, file=None) -> xr.Dataset:
    """The configured candidates and the screening's optimum, named ``optimised``
    (attribute ``optimised_from``: the screening candidate it came from)."""
    values = {**candidate_values(cfg), "optimised": optimised_values(screening, file)}
    ds, _ = plant_dataset(rigging_from_config(cfg), values)
    ds.attrs["optimised_from"] = screening.attrs["optimum_candidate"]
    return ds
