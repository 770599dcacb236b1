"""Stage builders: one module per dataset the workflow writes, named after it.

    sea_states       route legs (scatter tables or hindcasts)  -> sea_states.nc
    vessel_motion    vessel RAOs, hinge and fairlead motion    -> vessel_motion.nc
    plant            rigging candidates: M, K, Kb, C, modes     -> plant.nc, plant_assessed.nc
    screening        rigging screening and optimisation         -> screening.nc
    response         unit-Hs statistics per (Tz, heading)       -> response.nc, operability.nc,
                                                                   response_variants.nc
    timedomain_cell  one nonlinear time-domain cell             -> timedomain/<cell>.nc
    tugger_studies   decay tests and the damping-slope sweep    -> tugger_studies.nc
    workability      MPM per cell, pass/fail, route fractions   -> workability.nc
    weather_windows  persistence from hourly hindcasts          -> weather_windows.nc
    verification_cell  the ROM against the 6-DOF reference      -> verification/<cell>.nc

Each builder returns an xarray Dataset in the layout the registry defines
(jls/schemas/datasets.yaml) and puts together the layers below it (jls.sea, jls.vessel,
jls.plant, jls.response, jls.tugger, jls.assessment, jls.timedomain, jls.design,
jls.verify), with the settings objects of jls.config.builders. Only this layer and jls.config read the raw
configuration. Nothing here knows of Snakemake: workflow/scripts are thin adapters
around these functions.
"""
