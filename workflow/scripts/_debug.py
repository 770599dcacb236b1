"""Run a workflow script by hand, outside a Snakemake run, for debugging.

Each script starts with::

    if "snakemake" not in globals():          # run by hand: see workflow/scripts/_debug.py
        from _debug import snakemake_for
        snakemake = snakemake_for("plant")

so that ``python workflow/scripts/plant.py [route=default] [--configfile my.yaml ...]``
from the project folder builds the same job Snakemake would (the rule's inputs,
outputs, params, log and the validated configuration) and runs the script on it in the
current process, where a debugger or ``python -i`` can reach it. Wildcards are given as
``name=value``; the route defaults to the first one configured.
"""

from __future__ import annotations

import sys
from pathlib import Path


def snakemake_for(rule_name: str, argv=None):
    """The ``snakemake`` object a script would get for ``rule_name``'s job."""
    from snakemake.api import SnakemakeApi
    from snakemake.dag import DAG
    from snakemake.jobs import Job
    from snakemake.script import Snakemake
    from snakemake.settings.types import ConfigSettings, DAGSettings, OutputSettings, ResourceSettings

    argv = sys.argv[1:] if argv is None else argv
    configfiles = [Path(a) for a in argv[argv.index("--configfile") + 1:]] if "--configfile" in argv else []
    wildcards = dict(a.split("=", 1) for a in argv if "=" in a and not a.startswith("--"))
    root = Path(__file__).resolve().parents[2]
    with SnakemakeApi(OutputSettings(quiet={"all"})) as api:
        wapi = api.workflow(resource_settings=ResourceSettings(),
                            config_settings=ConfigSettings(configfiles=configfiles),
                            snakefile=root / "Snakefile", workdir=root)
        workflow = wapi._workflow
        workflow.dag_settings = DAGSettings()
        rule = workflow.get_rule(rule_name)
        if "route" in rule.wildcard_names and "route" not in wildcards:
            wildcards["route"] = next(iter(workflow.globals["ROUTES"]))
        checkpoints = workflow.globals["checkpoints"]
        for other in workflow.rules:          # checkpoint outputs already made count as done
            if other.is_checkpoint and set(other.wildcard_names) <= set(wildcards):
                done, _ = other.expand_output(wildcards)
                checkpoints.created_output.update(f for f in done if Path(f).exists())
        job = Job(rule, DAG(workflow, rules=[rule]), wildcards)
        for path in [*job.output, *job.log]:
            Path(path).parent.mkdir(parents=True, exist_ok=True)
        return Snakemake(job.input, job.output, job.params, job.wildcards, 1, job.resources,
                         job.log, workflow.config, rule.name, None, scriptdir=Path(__file__).parent)
