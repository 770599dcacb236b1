# Helpers shared by the rules: the validated configuration, the routes, the sea states
# each route's response work needs and the candidate chunks of that work.
import json
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.config import load_layers, origin_finder, validate
from jls.errors import InputError
from jls.candidates import candidate_values
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


def _route_states():
    """route -> the sea states its response work needs, read from the tables at parse time:
    ``leg_tz`` (the legs' Tz values), ``tz`` (those and the operability grid), the
    route's headings and gamma. Editing only probabilities leaves them unchanged, so no
    response job reruns; a new Tz column changes them, and the response jobs then
    evaluate that column alone (the sea-state cache holds the others).

    A malformed table stops the workflow here, before any job runs.
    """
    states = {}
    for route, spec in CFG["routes"].items():
        leg_tz = set()
        for leg in spec["legs"]:
            try:
                ds = read_leg(leg, ".", STEEPNESS, GAMMA, CFG["g_m_per_s2"])
            except InputError as exc:
                raise WorkflowError(f"route '{route}', leg '{leg['name']}': {exc}")
            leg_tz |= set(leg_key(ds, leg, GAMMA)["tz"])
        states[route] = {"leg_tz": sorted(leg_tz), "tz": sorted(leg_tz | set(OPERABILITY_TZ)),
                         "operability_tz": OPERABILITY_TZ, "headings_deg": route_headings(route),
                         "gamma": GAMMA}
    return states


def route_headings(route):
    return sorted({float(h) for leg in CFG["routes"][route]["legs"] for h in leg["headings_deg"]})


ROUTE_STATES = _route_states()


def leg_files(wildcards):
    return [str(leg_source(leg)) for leg in CFG["routes"][wildcards.route]["legs"]]


# Candidates: their number decides the response chunks; the report shows the baseline
# and the named candidates, whose transfer functions are stored (grid candidates keep
# statistics only).
CANDIDATES = list(candidate_values(CFG))
SHOWN_CANDIDATES = ["baseline"] + [c["name"] for c in CFG.get("candidates", [])]
RESPONSE = CFG["response"]
CHUNK = int(RESPONSE.get("chunk_candidates") or 0) or len(CANDIDATES)
N_CHUNKS = -(-len(CANDIDATES) // CHUNK)
SEA_STATE_CACHE = "results/cache/sea_states"


def response_chunks(wildcards):
    """The chunk files the route's response assembles; none when one job does it all."""
    if N_CHUNKS == 1:
        return []
    return [f"results/{wildcards.route}/response/chunk-{i}.nc" for i in range(N_CHUNKS)]


wildcard_constraints:
    route="[A-Za-z0-9_-]+",
    leg="[A-Za-z0-9_-]+",
    chunk="[0-9]+",
