"""Snakemake adapter: the route's legs -> results/<route>/sea_states.nc.

Inputs:   the route's leg tables and records (scatter CSV, hindcast, metocean, spectra)
Outputs:  results/<route>/sea_states.nc
Settings: sea (gamma, steepness rule), g, the route's legs

Run by hand for debugging: python workflow/scripts/sea_states.py [route=NAME] [--configfile FILE ...]
"""

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.config.dataset_hash import config_hash
from jls.io.hashing import file_sha256
from jls.io.netcdf import write
from jls.io.provenance import workflow_step
from jls.sea.legs import read_leg
from jls.sea.records import leg_source
from jls.stages.sea_states import sea_states

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("sea_states")
sm = snakemake
with workflow_step(sm.log[0], "sea_states") as log:
    route = dict(sm.params.route, name=sm.wildcards.route)
    sea = sm.params.sea
    rule_ = sea["steepness_rule"]
    legs = {}
    for leg in route["legs"]:
        legs[leg["name"]] = read_leg(leg, ".", rule_, sea["gamma"], sm.params.g)
        ds = legs[leg["name"]]
        log.info("leg %s: %d Hs x %d Tz cells, total %s, steep cells %d", leg["name"], ds.sizes["hs"],
                 ds.sizes["tz"], ds.attrs.get("total"), int(ds["steep"].sum()))
    out = sea_states(route, legs, rule_)
    inputs = {f"leg_{leg['name']}": file_sha256(leg_source(leg)) for leg in route["legs"]}
    write(out, sm.output[0], config_sha256=config_hash(sm.config, "sea_states", sm.wildcards.route), created_by="rule sea_states", dataset="sea_states",
          inputs=inputs)
    log.info("wrote %s", sm.output[0])
