"""Stage builders: one module per dataset the workflow writes, named after it.

    sea_states       route legs (scatter tables or hindcasts)  -> sea_states.nc
    vessel_motion    vessel RAOs, hinge and fairlead motion    -> vessel_motion.nc
    plant            rigging candidates: M, K, Kb, C, modes     -> plant.nc
    response         unit-Hs statistics per (Tz, heading)       -> response.nc, operability.nc
    workability      MPM per cell, pass/fail, route fractions   -> workability.nc
    screening        rigging screening and optimisation         -> screening.nc
    weather_windows  persistence from hourly hindcasts          -> weather_windows.nc

Each builder returns an xarray Dataset in the layout the registry defines
(jls/schemas/datasets.yaml); the physics they call lives in the modules of ``jls``
(frequency_domain, statistics, plant, tension, tugger, ...). Nothing here knows of
Snakemake: workflow/scripts are thin adapters around these functions.
"""
