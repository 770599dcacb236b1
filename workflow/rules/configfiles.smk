# The raw configuration files, read with jls's own YAML loader before Snakemake merges
# them: duplicate keys, encoding, tabs, alias bombs and YTE templates stop the run here,
# naming the file and line. Included before the configfile directive.
import sys
import time
from pathlib import Path

from jls.errors import InputError
from jls.config.workflow_inputs import read_layers

RUN_STARTED = time.time()
DEFAULT_CONFIG = "config/config.yaml"


def parse_error(error):
    """Stop the parse on a bad input with the one line `jls check` prints for it
    (``jls: error: FILE: KEY: what (got VALUE)``), exit status 1. Not a WorkflowError:
    Snakemake prints one with the stack frames of the rule files it passed through, which
    reads as a crash. Stops the job server first (nothing has run)."""
    if JOB_SERVER:
        _server.stop(JOB_SERVER.pop())
    print(f"jls: error: {error}", file=sys.stderr)
    raise SystemExit(1)


def _relative(path):
    path = Path(path)
    try:
        return path.resolve().relative_to(Path.cwd().resolve())
    except ValueError:
        return path


# --replace-workflow-config: Snakemake drops the workflow's own configfile.
_WITH_DEFAULT = (Path(DEFAULT_CONFIG).exists()
                 and not getattr(workflow.config_settings, "replace_workflow_config", False))
try:
    CONFIG_LAYERS = read_layers(
        ([DEFAULT_CONFIG] if _WITH_DEFAULT else [])
        + [_relative(p) for p in workflow.overwrite_configfiles])
except InputError as exc:
    parse_error(exc)
