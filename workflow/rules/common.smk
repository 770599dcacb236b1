# Helpers shared by the rules: the validated configuration, the routes, the sea states
# each route's response work needs and the candidate chunks of that work.
import json
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.errors import InputError
from jls.assessment.workability import TENSION_SENSE
from jls.config.builders import candidate_values
from jls.stages.sea_states import leg_key
from jls.sea.legs import leg_source, read_leg
from jls.config.workflow_inputs import check_config_files, check_rao, operability_tz, rao_file


def _validated(cfg):
    try:
        return check_config_files(cfg, CONFIG_LAYERS, dict(workflow.config_settings.config))
    except InputError as exc:
        raise WorkflowError(f"invalid configuration: {exc}")


CFG = _validated(config)
# A named variant (configuration key `variant`) keeps its datasets, logs and report apart:
# results/variants/<variant>/<route>/, reports/<route>-<variant>.pdf; the default's stay.
VARIANT = CFG.get("variant")
RESULTS = f"results/variants/{VARIANT}" if VARIANT else "results"
LOGS = f"logs/variants/{VARIANT}" if VARIANT else "logs"
BENCH = f"benchmarks/out/variants/{VARIANT}" if VARIANT else "benchmarks/out"
REPORT = f"reports/{{route}}-{VARIANT}.pdf" if VARIANT else "reports/{route}.pdf"
ROUTES = list(CFG["routes"])
SEA = CFG["sea"]
GAMMA = float(SEA["gamma"])
STEEPNESS = SEA["steepness_rule"]
TUGGERS = {t["name"]: t["c_kN_s_per_m"] for t in CFG["tuggers"]}
OPERABILITY_TZ = operability_tz(CFG)


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


# Rigging screening (workflow/rules/screening.smk): its envelope's heading joins the
# vessel motion, and its optimum joins the assessed candidates as "optimised".
SCREENING_ON = bool(CFG["screening"]["enabled"])
OPTIMISED = ["optimised"] if SCREENING_ON else []


def motion_headings(route):
    """Headings of the route's vessel motion: the legs' and the screening envelope's."""
    extra = {float(CFG["screening"]["envelope"]["heading_deg"])} if SCREENING_ON else set()
    return sorted(set(route_headings(route)) | extra)


ROUTE_STATES = _route_states()


def _check_vessel():
    """The RAO file read now, not in a job: complete, plausible, every heading, and
    covering every sea state of the routes and the operability grid."""
    need = {route: (ROUTE_STATES[route]["tz"], motion_headings(route)) for route in ROUTES}
    try:
        check_rao(CFG, need, CONFIG_LAYERS)
    except InputError as exc:
        raise WorkflowError(f"invalid vessel input: {exc}")


_check_vessel()


# Candidates: their number decides the response chunks; the report shows the baseline
# and the named candidates, whose transfer functions are stored (grid candidates keep
# statistics only).
CANDIDATES = list(candidate_values(CFG)) + OPTIMISED
SHOWN_CANDIDATES = ["baseline"] + [c["name"] for c in CFG.get("candidates", [])] + OPTIMISED
# The plant the response and the report read: with the screening on, the configured
# candidates and "optimised" (written by the checkpoint screening), else the configured ones.


def assessed_plant(wildcards):
    """plant_assessed.nc, read through the screening checkpoint. Snakemake re-evaluates the jobs
    that read a checkpoint's output once it has run and compares the file's checksum with
    the one recorded at their last run: a rerun of the screening that leaves the optimum
    as it was (a probability edit, say) writes the same bytes, and nothing downstream of
    the plant reruns. Files above --max-checksum-file-size (profiles/default) are
    compared by modification time only."""
    return checkpoints.screening.get(route=wildcards.route).output.plant


ASSESSED_PLANT = assessed_plant if SCREENING_ON else f"{RESULTS}/{{route}}/plant.nc"
RESPONSE = CFG["response"]
# Where the vessel is taken as still outside the RAO range, and why (optional; jls.response.coverage)
OUTSIDE_RAO_RANGE = CFG["vessel"].get("outside_rao_range")
CHUNK = int(RESPONSE.get("chunk_candidates") or 0) or len(CANDIDATES)
N_CHUNKS = -(-len(CANDIDATES) // CHUNK)
SEA_STATE_CACHE = "results/cache/sea_states"
# Solver threads of a response job: a few candidates solve in a fraction of a second on
# one core, and a second core is worth more to a job running beside it; a large
# candidate set takes both (numba threads). A profile's set-threads overrides this. On a
# cluster a job asks for as many CPUs as it has threads (profiles/slurm). The numbers
# do not depend on the threads (tests/test_determinism.py).
def solver_threads(n_candidates: int) -> int:
    return 2 if n_candidates > 64 else 1


# Memory [MB] and run time [min] of each job, for a scheduler (profiles/slurm; a
# workstation run sets no --resources limit, so they change nothing there). Sized from
# measured peak memory (README, "Cluster sizing, measured"): a SLURM job also holds two
# Snakemake processes (about 200 MB each beside the step's 100-500 MB), so JOB_MEM_MB for
# any job; the jobs that hold the statistics of every candidate add MB_PER_MVALUE per
# million values (candidates x tuggers x sea states of the route). Both memory and run time grow
# with the attempt: a job killed for memory or time reruns (profiles/slurm: retries)
# with twice as much.
JOB_MEM_MB = 1000
JOB_RUNTIME_MIN = 10
MB_PER_MVALUE = 1000


def _mvalues(wildcards, candidates):
    st = ROUTE_STATES.get(getattr(wildcards, "route", None))
    states = len(st["tz"]) * len(st["headings_deg"]) if st else 1
    return candidates * len(TUGGERS) * states / 1e6


def job_resources(candidates=0, mem_mb=JOB_MEM_MB, runtime=JOB_RUNTIME_MIN, per_mvalue=MB_PER_MVALUE):
    """resources of a rule: mem_mb and runtime, times the attempt; with ``candidates``,
    the memory grows by ``per_mvalue`` MB per million statistics values the job holds."""
    return {"mem_mb": lambda wildcards, attempt:
                int(attempt * (mem_mb + per_mvalue * _mvalues(wildcards, candidates))),
            "runtime": lambda wildcards, attempt: int(attempt * runtime)}


def response_chunks(wildcards):
    """The chunk files the route's response assembles; none when one job does it all."""
    if N_CHUNKS == 1:
        return []
    return [f"{RESULTS}/{wildcards.route}/response/chunk-{i}.nc" for i in range(N_CHUNKS)]


# Rigging screening (screening.smk): the chunk files of a route.
def screening_chunks(wildcards):
    return [f"{RESULTS}/{wildcards.route}/screening/chunk-{i}.nc" for i in range(SCREENING_CHUNKS)]


# Uncertainty bands (uncertainty.smk): tension statistics of the variants only when a
# tension criterion is configured.
def needs_tensions():
    """Tension statistics of the variants only when a tension criterion is configured."""
    return any(CFG["assessment"]["criteria"].get(k) is not None for k in TENSION_SENSE)


# Time-domain cells (timedomain.smk): the files of the cells the checkpoint chose.
def timedomain_files(wildcards):
    """The route's time-domain cell files, once the checkpoint has chosen them."""
    with open(checkpoints.timedomain_cells.get(route=wildcards.route).output[0]) as fh:
        cells = json.load(fh)
    return [f"{RESULTS}/{wildcards.route}/timedomain/{c['name']}.nc" for c in cells]


# Weather windows (windows.smk): the hindcast legs and the route's window file.
def hindcast_legs(route):
    """The legs of ``route`` given by an hourly hindcast."""
    return [leg for leg in route_legs(route) if "hindcast" in leg]


def windows_file(wildcards):
    """The route's weather-window file when it has a hindcast leg, else nothing."""
    return [f"{RESULTS}/{wildcards.route}/weather_windows.nc"] if hindcast_legs(wildcards.route) else []


wildcard_constraints:
    route="[A-Za-z0-9_-]+",
    leg="[A-Za-z0-9_-]+",
    chunk="[0-9]+",
