# Helpers shared by the rules: the validated configuration, the routes and the keys
# that decide which response jobs a leg needs.
import json
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.errors import InputError
from jls.route import leg_key, leg_source, read_leg
from jls.workflow_inputs import check_config_files, check_rao, operability_tz, rao_file


def _validated(cfg):
    try:
        return check_config_files(cfg, CONFIG_LAYERS, dict(workflow.config_settings.config))
    except InputError as exc:
        raise WorkflowError(f"invalid configuration: {exc}")


CFG = _validated(config)
ROUTES = list(CFG["routes"])
SEA = CFG["sea"]
GAMMA = float(SEA["gamma"])
STEEPNESS = SEA["steepness_rule"]
TUGGERS = {t["name"]: t["c_kN_s_per_m"] for t in CFG["tuggers"]}
OPERABILITY_TZ = operability_tz(CFG)


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
RAO_FILE = rao_file(CFG)


def route_legs(route):
    if route not in CFG["routes"]:
        raise WorkflowError(f"route '{route}' is not in the configuration (routes: "
                            f"{', '.join(ROUTES)})")
    return CFG["routes"][route]["legs"]


def leg_files(wildcards):
    return [str(leg_source(leg)) for leg in route_legs(wildcards.route)]


def route_headings(route):
    return sorted({float(h) for leg in route_legs(route) for h in leg["headings_deg"]})


def response_files(wildcards):
    return [f"results/{wildcards.route}/response/{leg['name']}-{LEG_KEYS[(wildcards.route, leg['name'])]['key']}.nc"
            for leg in route_legs(wildcards.route)]


def _check_vessel():
    """The RAO file read now, not in a job: complete, plausible, every heading, and
    covering every sea state of the routes and the operability grid."""
    need = {route: ([t for (r, _), k in LEG_KEYS.items() if r == route for t in k["tz"]]
                    + OPERABILITY_TZ, route_headings(route)) for route in ROUTES}
    try:
        check_rao(CFG, need, CONFIG_LAYERS)
    except InputError as exc:
        raise WorkflowError(f"invalid vessel input: {exc}")


_check_vessel()


def leg_cells(wildcards):
    k = LEG_KEYS[(wildcards.route, wildcards.leg)]
    if k["key"] != wildcards.key:
        raise WorkflowError(f"response key {wildcards.key} is not current for leg {wildcards.leg}")
    return {"tz": k["tz"], "headings_deg": k["headings_deg"], "gamma": k["gamma"]}


wildcard_constraints:
    route="[A-Za-z0-9_-]+",
    leg="[A-Za-z0-9_-]+",
    key="[0-9a-f]{12}",
