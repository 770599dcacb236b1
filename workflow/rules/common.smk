# Helpers shared by the rules: the validated configuration, the routes, the sea states
# each route's response work needs and the candidate chunks of that work.
import json
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.errors import InputError
from jls.names import TENSION_KEYS
import dataclasses

from jls.config.builders import candidate_values, tip_settings_from_config
from jls.config.headings import rao_headings
from jls.stages.sea_states import leg_key
from jls.config.time_spans import check_time_spans
from jls.sea.legs import read_leg
from jls.sea.records import sea_model
from jls.sea.records import is_hourly, leg_files as record_files
from jls.config.workflow_inputs import (check_config_files, check_rao, config_warnings,
                                        leg_error, merged_config, operability_tz, rao_file)
from jls.io.netcdf import warnings_of
from jls.timedomain.cells import parse_cell
from jls.verify.names import parse_cell as parse_verification_cell
from jls.verify.names import STUDY_PARTS, wire_cells


def _validated(cfg):
    """The configuration as jls reads it (one YAML semantics with `jls check`: Snakemake's
    own reading of the files is replaced, in place, by the project loader's), validated."""
    overrides = dict(workflow.config_settings.config)
    jls_read = merged_config(CONFIG_LAYERS, overrides)
    cfg.clear()
    cfg.update(jls_read)
    try:
        return check_config_files(cfg, CONFIG_LAYERS, overrides)
    except InputError as exc:
        parse_error(exc)


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
        leg_tz, tables = set(), []
        LEG_WARNINGS[route] = []
        for i, leg in enumerate(spec["legs"]):
            try:
                ds = read_leg(leg, ".", STEEPNESS, GAMMA, CFG["g_m_per_s2"])
            except InputError as exc:          # as jls check names it
                parse_error(leg_error(exc, route, i, leg, CONFIG_LAYERS))
            leg_tz |= set(leg_key(ds, leg, GAMMA)["tz"])
            LEG_WARNINGS[route] += [f"leg {leg['name']}: {w}" for w in warnings_of(ds)]
            tables.append(ds)
        try:                                   # the records' spans against the season
            check_time_spans(CFG, route, tables, CONFIG_LAYERS)
        except InputError as exc:
            parse_error(exc)
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


def leg_files(leg):
    """The files a leg reads (its table or record; NDBC spectra with their direction files)."""
    return record_files(leg)


def route_files(wildcards):
    return [f for leg in route_legs(wildcards.route) for f in leg_files(leg)]


def route_headings(route):
    return sorted({float(h) for leg in route_legs(route) for h in leg["headings_deg"]})


# Rigging screening (workflow/rules/screening.smk): its envelope's heading joins the
# vessel motion, and its optimum joins the assessed candidates as "optimised".
SCREENING_ON = bool(CFG["screening"]["enabled"])
OPTIMISED = ["optimised"] if SCREENING_ON else []


def spectra_legs(route):
    """The legs of ``route`` whose sea is not the pipeline's JONSWAP: spectra, partitions,
    Torsethaugen tables (measured_response.nc, jls.sea.records.sea_model)."""
    return [leg for leg in route_legs(route) if sea_model(leg) != "jonswap"]


def measured_file(wildcards):
    """The route's measured-spectrum response when it has a spectra leg, else nothing."""
    return [f"{RESULTS}/{wildcards.route}/measured_response.nc"] if spectra_legs(wildcards.route) else []


def motion_headings(route):
    """Headings of the route's vessel motion: the legs', the screening envelope's and, for
    a spectra leg sailing a course (each direction bin met at its own relative heading),
    every heading of the RAOs (mirrored for a symmetric hull)."""
    extra = {float(CFG["screening"]["envelope"]["heading_deg"])} if SCREENING_ON else set()
    if any("course_deg" in leg or "waypoints" in leg for leg in spectra_legs(route)):
        extra |= set(rao_headings(CFG))
    # the tugger studies' slope sweep runs at its own heading on every route (beam seas
    # by default, on a route that may have none): the motion holds it too, and the RAO
    # file is checked for it at parse time (_check_vessel), not in the job
    extra.add(float(CFG["timedomain"]["slope_sweep"]["heading_deg"]))
    return sorted(set(route_headings(route)) | extra)


LEG_WARNINGS = {}       # route -> the warnings its tables and records carry (page 1)
ROUTE_STATES = _route_states()


def _check_vessel():
    """The RAO file read now, not in a job: complete, plausible, every heading, and
    covering every sea state of the routes and the operability grid. Returns the
    warnings the report prints on its first page."""
    need = {route: (ROUTE_STATES[route]["tz"], motion_headings(route)) for route in ROUTES}
    try:
        return check_rao(CFG, need, CONFIG_LAYERS)
    except InputError as exc:
        parse_error(exc)


RAO_WARNINGS = _check_vessel()
# What the report prints on its first page about the inputs of a route: the configuration's
# cross-checks, the RAO file's and the route's tables' (workability.nc, attribute warnings).
CONFIG_WARNINGS = config_warnings(CFG)
INPUT_WARNINGS = {route: CONFIG_WARNINGS + RAO_WARNINGS + LEG_WARNINGS[route] for route in ROUTES}


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
# measured peak memory (docs/guide/cluster-run.md, "Cluster sizing, measured"): a SLURM job also holds two
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
    return any(CFG["assessment"]["criteria"].get(k) is not None for k in TENSION_KEYS)


# Dynamic tip clearance (jls.response.tip): its settings for the response jobs, or None when
# the criterion is off; the air gap itself is judged in the workability job only.
_TIP = tip_settings_from_config(CFG)
TIP = dataclasses.asdict(_TIP) if _TIP is not None else None


# Time-domain cells (timedomain.smk): the files of the cells the checkpoint chose.
def timedomain_files(wildcards):
    """The route's time-domain cell files, once the checkpoint has chosen them."""
    with open(checkpoints.timedomain_cells.get(route=wildcards.route).output[0]) as fh:
        cells = json.load(fh)
    return [f"{RESULTS}/{wildcards.route}/timedomain/{c['name']}.nc" for c in cells]


# Weather windows (windows.smk): the legs with an hourly record and the route's window file.
def hindcast_legs(route):
    """The legs of ``route`` given by an hourly record (hindcast, metocean or spectra)."""
    return [leg for leg in route_legs(route) if is_hourly(leg)]


def windows_file(wildcards):
    """The route's weather-window file when it has a hindcast leg, else nothing."""
    return [f"{RESULTS}/{wildcards.route}/weather_windows.nc"] if hindcast_legs(wildcards.route) else []


def swell_inputs(w):
    """The assessed plant and the RAO file of a route with partitioned legs: the swell
    table of the master's (jls.stages.swell_limits) builds the options' transfer from them,
    as jls forecast does."""
    if not any(sea_model(leg) == "partitions" for leg in route_legs(w.route)):
        return []
    plant = ASSESSED_PLANT(w) if callable(ASSESSED_PLANT) else ASSESSED_PLANT.format(route=w.route)
    return [plant, RAO_FILE]


def plan_record_files(route):
    """The hourly records the voyage plan reads: record legs' files, table legs' records."""
    out = []
    for leg in route_legs(route):
        if is_hourly(leg):
            out += leg_files(leg)
        elif "records" in leg:
            out.append(leg["records"]["file"])
    return out


# Verification against the nonlinear reference (verification.smk): the choice's and the
# cells' settings, the cell files the checkpoint chose, and the plant a cell needs.
VERIFICATION = CFG["verification"]
VERIFICATION_ON = bool(VERIFICATION["enabled"])
# The configuration parts the choice of cells depends on, and those one cell's run does.
VERIFICATION_CHOICE = ("enabled", "combinations", "boundary_cells", "design_corner", "max_cells",
                       "stressed_cells")
VERIFICATION_RUN = {k: v for k, v in VERIFICATION.items()
                    if k not in VERIFICATION_CHOICE + ("study_comparison", "wires")}
# what a wire check reads of the run settings (as its dataset's configuration hash,
# layout verification_wires): a change of the records' length, start or harmonic tests
# reruns the cells, not the wire checks
VERIFICATION_WIRES_RUN = {k: VERIFICATION_RUN[k] for k in ("tolerance", "seed", "dt_s", "kinematics",
                                                           "pitch_inertia_t_m2") if k in VERIFICATION_RUN}
VERIFICATION_STUDY = VERIFICATION_ON and bool(VERIFICATION["study_comparison"])
CONFIGURED_CANDIDATES_VALUES = candidate_values(CFG)
CONFIGURED_CANDIDATES = list(CONFIGURED_CANDIDATES_VALUES)


def verification_files(wildcards):
    """The route's verification cell files, once the checkpoint has chosen them (none
    when verification.enabled is false)."""
    if not VERIFICATION_ON:
        return []
    with open(checkpoints.workability.get(route=wildcards.route).output.verification_cells) as fh:
        cells = json.load(fh)
    return [f"{RESULTS}/{wildcards.route}/verification/{c['name']}.nc" for c in cells]


def verification_wires_files(wildcards):
    """Per verified combination the wire check of its design-corner cell
    (verification.wires), once the checkpoint has chosen the cells."""
    if not (VERIFICATION_ON and VERIFICATION["wires"]["enabled"]):
        return []
    with open(checkpoints.workability.get(route=wildcards.route).output.verification_cells) as fh:
        cells = json.load(fh)
    return [f"{RESULTS}/{wildcards.route}/verification/wires/{c['name']}.nc" for c in wire_cells(cells)]


def verification_study_file(wildcards):
    """The route's study comparison (verification.study_comparison), else nothing."""
    return [f"{RESULTS}/{wildcards.route}/verification_study.nc"] if VERIFICATION_STUDY else []


def verification_cells_file(wildcards):
    return [f"{RESULTS}/{wildcards.route}/verification/cells.json"] if VERIFICATION_ON else []


def verification_candidate(vcell):
    """The design values of a cell's configured candidate (None: from the assessed plant),
    so that editing another candidate reruns no cell of this one."""
    return CONFIGURED_CANDIDATES_VALUES.get(parse_verification_cell(vcell)["candidate"])


def verification_tugger(vcell):
    """The configured settings of a cell's tugger (what its job depends on of the tuggers)."""
    name = parse_verification_cell(vcell)["tugger"]
    return [t for t in CFG["tuggers"] if t["name"] == name]


def verification_plant(wildcards):
    """The assessed plant, for a cell whose candidate no configuration lists (the
    screening's optimised); the other cells build theirs from the configuration."""
    if parse_verification_cell(wildcards.vcell)["candidate"] in CONFIGURED_CANDIDATES:
        return []
    return [ASSESSED_PLANT(wildcards) if callable(ASSESSED_PLANT) else ASSESSED_PLANT.format(route=wildcards.route)]


wildcard_constraints:
    route="[A-Za-z0-9_-]+",
    leg="[A-Za-z0-9_-]+",
    chunk="[0-9]+",


# Snakemake commands that parse the workflow without running it: bad datasets are named only.
INSPECT_ONLY = {"--unlock", "--summary", "-S", "--detailed-summary", "-D", "--list", "-l",
                "--list-rules", "--list-target-rules", "--lt", "--dag", "--rulegraph",
                "--filegraph", "--lint", "--touch", "-t", "--cleanup-metadata", "--cm",
                "--delete-all-output", "--delete-temp-output", "--list-changes", "--lc",
                "--list-input-changes", "--li", "--list-params-changes", "--lp",
                "--list-code-changes", "--print-compilation", "--containerize"}


def check_outputs():
    """Refuse symbolic links among the run's outputs; set aside every existing dataset that
    is corrupt, foreign or made with another configuration (named on stderr, moved to
    <file>.rejected, never deleted), so that Snakemake rebuilds it. A dry run only names
    them. Called from the Snakefile once every rule is defined."""
    from jls.config.intermediates import problems, set_aside, symlinks
    links = symlinks(["reports", LOGS, BENCH], inner=[f"{RESULTS}/{r}" for r in ROUTES])
    if links:
        parse_error(f"{links[0]} is a symbolic link; the run's outputs (results/<route>/, "
                    "reports/, logs/, benchmarks/out/) must be plain files and folders: "
                    f"remove the link ({len(links)} in all)")
    if not getattr(workflow, "is_main_process", True):
        return
    bad = problems(CFG, RESULTS, ROUTES, screening=SCREENING_ON,
                   n_screening_chunks=SCREENING_CHUNKS if SCREENING_ON else 0,
                   n_response_chunks=N_CHUNKS, windows_routes={r for r in ROUTES if hindcast_legs(r)})
    dry = bool(getattr(getattr(workflow, "output_settings", None), "dryrun", False)) or any(
        arg.split("=")[0] in INSPECT_ONLY for arg in sys.argv[1:])
    for route, path, why in bad:
        if dry:
            print(f"jls: {path}: {why}; a run sets it aside and rebuilds it", file=sys.stderr)
        else:
            print(f"jls: {path}: {why}; set aside as {set_aside(path)} and rebuilt", file=sys.stderr)
    from jls.config.intermediates import missing
    rejected = {str(path) for _, path, _ in bad}            # set aside just now: named above
    gone = {route: [p for p in missing(RESULTS, route, REPORT.format(route=route),
                                       screening=SCREENING_ON, windows=bool(hindcast_legs(route)),
                                       measured=bool(spectra_legs(route)),
                                       verification=VERIFICATION_ON) if p not in rejected]
            for route in ROUTES}
    for route, paths in gone.items():
        for path in paths:
            print(f"jls: {path} is missing (deleted?); {'a run rebuilds it' if dry else 'rebuilt'}, with "
                  "what depends on it", file=sys.stderr)
    for route in sorted({route for route, _, _ in bad} | {r for r, p in gone.items() if p}):
        pdf = Path(REPORT.format(route=route))
        if pdf.exists() and not dry:             # rebuilt from the rebuilt dataset
            print(f"jls: {pdf}: built from a rejected or missing dataset; set aside as "
                  f"{set_aside(pdf)} and rebuilt", file=sys.stderr)


# Time-domain cells (timedomain.smk): the leg whose own sea a cell runs in.
def cell_leg(wildcards):
    """The leg whose own sea a time-domain cell runs in (a cell named ``__leg-<leg>``, of a
    leg of spectrum partitions, measured or torsethaugen: jls.timedomain.cell_sea), else None."""
    name = parse_cell(wildcards.cell).get("leg")
    return next((leg for leg in route_legs(wildcards.route) if leg["name"] == name), None) if name else None


# Time-domain cells (timedomain.smk): the assessed plant a cell needs.
def timedomain_plant(wildcards):
    """The assessed plant, for a cell whose candidate no configuration lists (the
    screening's optimised, a boundary candidate by default); the other cells build
    theirs from the configuration, so they do not rerun when the optimum moves."""
    if parse_cell(wildcards.cell)["candidate"] in CONFIGURED_CANDIDATES:
        return []
    return [ASSESSED_PLANT(wildcards) if callable(ASSESSED_PLANT) else ASSESSED_PLANT.format(route=wildcards.route)]


# -- pre-transit forecast checks (workflow/rules/forecast.smk) --------------------------
from jls.config.forecast_entries import check_forecast_entries, issued_tag

FORECASTS = f"forecasts/variants/{VARIANT}" if VARIANT else "forecasts"
try:
    check_forecast_entries(CFG)
except InputError as exc:
    parse_error(exc)


def forecast_entry(w):
    """The forecast.files entry of a pre-transit report's wildcards."""
    for entry in CFG["forecast"]["files"]:
        if entry["route"] == w.route and entry["leg"] == w.leg and issued_tag(entry["issued"]) == w.issued:
            return entry
    raise WorkflowError(f"no forecast.files entry for route {w.route}, leg {w.leg}, issued {w.issued}")


def forecast_reports():
    return [f"{FORECASTS}/{e['route']}/{e['leg']}-{issued_tag(e['issued'])}.pdf" for e in CFG["forecast"]["files"]]
