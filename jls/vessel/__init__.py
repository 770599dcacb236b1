"""Vessel motions: RAO datasets, readers and the rigid-body transfer to the hinge.

Public API::

    load_rao(path, format=None, **kw)   # .4 WAMIT, .csv, .nc (jls or Capytaine), .yml, .lis
    read_wamit4, read_capytaine_nc, read_rao_csv, read_rao_netcdf, save_rao
    read_orcaflex_vessel_type, read_aqwa_lis  # OrcaFlex vessel type, AQWA-LINE listing
    make_rao_dataset, validate_rao, interp_rao, frequency_range, mirror_headings
    point_motion, hinge_excitation, fairlead_motion, shift_reference_point
    motion_on_grid, carry, GridMotion   # the one transfer, after per-DOF interpolation

The optional BEM computation lives in :mod:`jls.vessel.bem` (needs Capytaine,
the "bem" extra) and is not imported here; :mod:`jls.vessel.hulls` meshes its
parametric hulls (plain numpy).
"""

from jls.vessel.aqwa import read_aqwa_lis
from jls.vessel.capytaine_io import read_capytaine_nc
from jls.vessel.csv_io import read_rao_csv
from jls.vessel.files import load_rao
from jls.vessel.orcaflex import read_orcaflex_vessel_type
from jls.vessel.rao import (
                            DOFS,
                            frequency_range,
                            interp_rao,
                            make_rao_dataset,
                            mirror_headings,
                            read_rao_netcdf,
                            save_rao,
                            validate_rao,
)
from jls.vessel.transfer import (
                            FAIRLEAD_DROP_M,
                            FAIRLEAD_HALF_SPAN_M,
                            HINGE_POSITION_M,
                            GridMotion,
                            carry,
                            fairlead_motion,
                            hinge_excitation,
                            motion_on_grid,
                            point_motion,
                            shift_reference_point,
)
from jls.vessel.wamit import read_wamit4

__all__ = [
    "DOFS", "FAIRLEAD_DROP_M", "FAIRLEAD_HALF_SPAN_M", "HINGE_POSITION_M", "GridMotion",
    "carry", "fairlead_motion", "frequency_range", "hinge_excitation", "interp_rao",
    "load_rao", "make_rao_dataset", "mirror_headings", "motion_on_grid", "point_motion",
    "read_aqwa_lis", "read_capytaine_nc", "read_orcaflex_vessel_type",
    "read_rao_csv", "read_rao_netcdf", "read_wamit4", "save_rao", "shift_reference_point",
    "validate_rao",
]
