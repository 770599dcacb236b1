"""Sea states for the route assessment: spectra, steepness ceiling, scatter tables, hindcasts.

Two-peak spectra (``two_peak``), the period conventions (``periods``), measured and
hindcast spectra (``measured``, ``ndbc``, ``directional``) and integrated-parameter
files (``metocean``) are imported from their modules.

Units: m, s, rad/s; directions in degrees at the file boundary.  See docs/sea.md.
"""

from jls.sea.hindcast import GapSummary, bin_hindcast, hindcast_gaps, read_hindcast
from jls.sea.scatter import read_scatter, scatter_dataset, write_scatter
from jls.sea.spectra import (
                             gamma_dnv,
                             jonswap,
                             jonswap_normalisation,
                             jonswap_shape_moment,
                             pierson_moskowitz,
                             spectral_moment,
                             t1_from_tp,
                             te_from_tp,
                             tp_from_tz,
                             tz_from_tp,
)
from jls.sea.steepness import exceeds_steepness, flag_steep, steepness_limit_hs

__all__ = [
    "jonswap", "pierson_moskowitz", "spectral_moment", "jonswap_normalisation",
    "jonswap_shape_moment", "tz_from_tp", "tp_from_tz", "t1_from_tp", "te_from_tp", "gamma_dnv",
    "steepness_limit_hs", "exceeds_steepness", "flag_steep",
    "read_scatter", "write_scatter", "scatter_dataset",
    "read_hindcast", "hindcast_gaps", "GapSummary", "bin_hindcast",
]
