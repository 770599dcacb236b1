# jls: route-specific rigging assessment. Run: snakemake --cores 2
# Rules live in workflow/rules by stage; scripts in workflow/scripts are thin adapters
# around the jls library. The configuration is validated before anything runs.
import atexit
import gc
import importlib.util
import sys
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.config.environment import check_environment
from jls.errors import InputError

# The environment first (SOURCE_DATE_EPOCH, NUMBA_NUM_THREADS): a value numba or the
# report would refuse stops the run here, before the job server or any job starts.
try:
    check_environment(cache=False)
except InputError as _exc:      # one line, as jls check prints it (no stack frames)
    print(f"jls: error: invalid environment: {_exc}", file=sys.stderr)
    raise SystemExit(1)

# Jobs on this machine start from the job server's imported process
# (workflow/scripts/_server.py), started first so that its imports run beside the parse;
# a run that executes nothing (a dry run, --lint, a summary) and a cluster's job start
# none, and a cluster run stops it before submitting (onstart). Loaded from its file:
# workflow/scripts is not put on this process's module path.
_spec = importlib.util.spec_from_file_location(
    "jls_job_server", Path(workflow.basedir) / "workflow" / "scripts" / "_server.py")
_server = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_server)
JOB_SERVER = [_server.start()] if workflow.is_main_process and _server.runs_jobs(sys.argv) else []

from snakemake.utils import min_version

from jls.config.workflow_inputs import failed_jobs, job_errors, outside_roots

min_version("9.0")


include: "workflow/rules/configfiles.smk"


configfile: "config/config.yaml"


include: "workflow/rules/common.smk"


rule all:
    input:
        expand(REPORT, route=ROUTES),
        lambda w: forecast_reports(),
    default_target: True


include: "workflow/rules/sea.smk"
include: "workflow/rules/vessel.smk"
include: "workflow/rules/plant.smk"
include: "workflow/rules/screening.smk"
include: "workflow/rules/response.smk"
include: "workflow/rules/uncertainty.smk"
include: "workflow/rules/timedomain.smk"
include: "workflow/rules/assess.smk"
include: "workflow/rules/windows.smk"
include: "workflow/rules/voyage.smk"
include: "workflow/rules/measured.smk"
include: "workflow/rules/verification.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/forecast.smk"


# No rule writes, or may delete, anything outside the run's own directories.
_outside = outside_roots((r.name, r.output) for r in workflow.rules)
if _outside:
    raise WorkflowError(f"rule {_outside[0][0]} would write outside results/, reports/, logs/ "
                        f"and benchmarks/out/: {_outside[0][1]}")


# Every existing dataset a job would read: opens, follows its registry layout, was made
# with this configuration; a bad one is named and rebuilt (jls.config.intermediates).
# Outputs must not be symbolic links (a log written through one lands where it points).
check_outputs()


onerror:
    _server.stop(JOB_SERVER.pop() if JOB_SERVER else None)
    # The one-line jls errors of the failed jobs, which Snakemake's output buries; then
    # every failed job with its cause: its log's error line, or, when its log is empty
    # or stale (killed for memory or time on a cluster), the end of its scheduler log; a
    # stale log of a failed job is rewritten to say so (no line of an earlier run stays).
    for line in job_errors("logs", since=RUN_STARTED):
        print(line, file=sys.stderr)
    _failed = failed_jobs(log, since=RUN_STARTED, rewrite_stale=True)
    if _failed:
        print("Failed jobs:", *_failed, sep="\n", file=sys.stderr)


onstart:
    # A run on this machine needs no job-rate limit (Snakemake's 100 jobs/s guard is for
    # cluster schedulers); its limiter arms a one-second timer after every scheduling
    # round, which keeps a finished local run alive for up to a second more. Cluster
    # executors keep it. (Guarded: a Snakemake without these attributes changes nothing.)
    _scheduler = getattr(workflow, "scheduler", None)
    if getattr(workflow, "local_exec", False) and hasattr(_scheduler, "job_rate_limiter"):
        _scheduler.job_rate_limiter = None
    # The interpreter's final garbage collections walk every object Snakemake and its
    # plugins made (0.3 s a run); the process is ending, so they are skipped, as in
    # each job (jls.io.provenance.workflow_step).
    atexit.register(gc.freeze)
    if JOB_SERVER and not getattr(workflow, "local_exec", False):
        _server.stop(JOB_SERVER.pop())


onsuccess:
    _server.stop(JOB_SERVER.pop() if JOB_SERVER else None)
