"""Snakemake adapter: hindcasts + unit-Hs statistics -> results/<route>/weather_windows.nc.

Inputs:   results/<route>/operability.nc (statistics on the operability Tz grid),
          workability.nc and the assessed plant (the recommended option), the legs' hourly records,
          measured_response.nc when a leg is given by spectra (its hours' sway ratio)
Outputs:  results/<route>/weather_windows.nc
Settings: assessment.criteria, sea.gamma, the route's hourly legs (hindcast, metocean, spectra: (duration, headings),
          weather_windows (alpha, gaps, tz_outside), operation (alpha_factors, the route's stretches:
          the voyage plan's alpha)

Run by hand for debugging: python workflow/scripts/weather_windows.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.assessment.windows import read_route_hindcasts
from jls.config.dataset_hash import config_hash
from jls.io import registry
from jls.io.netcdf import read, write
from jls.io.provenance import workflow_step
from jls.stages.weather_windows import assessed_option, operational_alpha, route_windows

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("weather_windows")
sm = snakemake
with workflow_step(sm.log[0], "weather_windows") as log:
    legs = sm.params.legs
    hindcasts = read_route_hindcasts({"legs": legs}, gamma=sm.params.gamma)
    option = assessed_option(read(sm.input.workability), read(sm.input.plant),
                             {k: float(v) for k, v in sm.params.tuggers.items()})
    w = sm.params.windows
    measured = read(sm.input.measured[0]) if sm.input.measured else None
    table, periods = operational_alpha(sm.params.route_legs, sm.params.operation)   # the voyage plan's alpha
    ds = route_windows(legs, hindcasts, read(sm.input.operability), sm.params.criteria, option,
                       alpha=w["alpha"], gaps=w["gaps"], tz_outside=w["tz_outside"], measured=measured,
                       alpha_factors=table, leg_period_h=periods)
    ds.attrs["route"] = sm.wildcards.route
    registry.annotate(ds, "weather_windows")
    for leg in ds["leg"].values:
        log.info("leg %s, option %s with tugger %s: window probability %.1f %% over the record "
                 "(%d hours outside the Tz grid)", leg, *option,
                 100 * float(ds["window_probability_all"].sel(leg=leg)),
                 int(ds["hours_outside_tz"].sel(leg=leg)))
    write(ds, sm.output[0], created_by="rule weather_windows", dataset="weather_windows",
          config_sha256=config_hash(sm.config, "weather_windows", sm.wildcards.route))
