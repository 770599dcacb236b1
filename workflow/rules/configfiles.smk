# The raw configuration files, read with jls's own YAML loader before Snakemake merges
# them: duplicate keys, encoding, tabs, alias bombs and YTE templates stop the run here,
# naming the file and line. Included before the configfile directive.
import time
from pathlib import Path

from snakemake.exceptions import WorkflowError

from jls.errors import InputError
from jls.config.workflow_inputs import read_layers

RUN_STARTED = time.time()
DEFAULT_CONFIG = "config/config.yaml"


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
    raise WorkflowError(f"invalid configuration: {exc}")
