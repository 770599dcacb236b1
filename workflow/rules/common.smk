# Helpers shared by the rules: the validated configuration, the routes and the keys
# that decide which response jobs a leg needs.
import json
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.config import load_layers, origin_finder, validate
from jls.errors import InputError
from jls.route import leg_key, leg_source, read_leg


def _config_layers():
    """(file, mapping) in the order Snakemake merged them: the Snakefile's configfile,
    then each --configfile, then --config key=value pairs."""
    files = [f for f in workflow.configfiles if f not in workflow.overwrite_configfiles]
    files += list(workflow.overwrite_configfiles)
    layers = [(str(f), load_layers([f])[0]) for f in files]
    cli = getattr(workflow.config_settings, "config", None)
    if cli:
        layers.append(("--config", dict(cli)))
    return layers


def _validated(cfg):
    try:
        layers = _config_layers()
        return validate(cfg, source=" + ".join(name for name, _ in layers),
                        origin=origin_finder(layers))
    except InputError as exc:
        raise WorkflowError(f"invalid configuration: {exc}")


CFG = _validated(config)
ROUTES = list(CFG["routes"])
SEA = CFG["sea"]
GAMMA = float(SEA["gamma"])
STEEPNESS = SEA["steepness_rule"]
TUGGERS = {t["name"]: t["c_kN_s_per_m"] for t in CFG["tuggers"]}
_grid = CFG["assessment"]["operability_tz_s"]
OPERABILITY_TZ = [round(_grid["min"] + i * _grid["step"], 6)
                  for i in range(int(round((_grid["max"] - _grid["min"]) / _grid["step"])) + 1)]


def _leg_keys():
    """(route, leg) -> key of the leg's response work, read from the tables at parse time.

    A malformed table stops the workflow here, before any job runs.
    """
    keys = {}
    for route, spec in CFG["routes"].items():
        for leg in spec["legs"]:
            try:
                ds = read_leg(leg, ".", STEEPNESS, GAMMA, CFG["g_m_per_s2"])
            except InputError as exc:
                raise WorkflowError(f"route '{route}', leg '{leg['name']}': {exc}")
            keys[(route, leg["name"])] = leg_key(ds, leg, GAMMA)
    return keys


LEG_KEYS = _leg_keys()


def leg_files(wildcards):
    return [str(leg_source(leg)) for leg in CFG["routes"][wildcards.route]["legs"]]


def route_headings(route):
    return sorted({float(h) for leg in CFG["routes"][route]["legs"] for h in leg["headings_deg"]})


def response_files(wildcards):
    return [f"results/{wildcards.route}/response/{leg['name']}-{LEG_KEYS[(wildcards.route, leg['name'])]['key']}.nc"
            for leg in CFG["routes"][wildcards.route]["legs"]]


def leg_cells(wildcards):
    k = LEG_KEYS[(wildcards.route, wildcards.leg)]
    if k["key"] != wildcards.key:
        raise WorkflowError(f"response key {wildcards.key} is not current for leg {wildcards.leg}")
    return {"tz": k["tz"], "headings_deg": k["headings_deg"], "gamma": k["gamma"]}


wildcard_constraints:
    route="[A-Za-z0-9_-]+",
    leg="[A-Za-z0-9_-]+",
    key="[0-9a-f]{12}",
