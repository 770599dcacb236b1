"""The inputs of a workflow run, checked when the workflow is parsed (before any job).

The Snakefile hands this module the raw configuration files (Snakemake merges them
itself, so their duplicate keys, encoding and the like are checked here with the one
project loader, :mod:`jls.io.yamlio`), the merged configuration, and asks it for the
route tables and the RAO file. Every error is an :class:`jls.errors.InputError` that
names the file the bad value came from: the default ``config/config.yaml``, a
``--configfile``, or ``--config`` on the command line.

Also here: where the pipeline keeps the RAOs it computes itself (``vessel.bem``), the
rule-output guard (no rule writes outside the run's own directories) and the lines the
``onerror:`` handler prints from the logs of failed jobs (:func:`job_errors`,
:func:`failed_jobs`).
"""

from __future__ import annotations

import re
import time
from pathlib import Path

from jls.config.cross_checks import check_values
from jls.config.hull_checks import own_hull
from jls.config.loader import load_yaml, merge, origin_finder, validate
from jls.config.naming import given_by as _given_by
from jls.config.naming import leg_error  # noqa: F401 (for the workflow: common.smk)
from jls.config.plausible import check_config, check_problem_size, check_rao_magnitudes
from jls.config.sea_coverage import check_measured_coverage
from jls.errors import InputError
from jls.io.netcdf import warnings_of
from jls.response.coverage import check_coverage

#: Where the pipeline writes anything at all.
OUTPUT_ROOTS = ("results/", "reports/", "logs/", "benchmarks/out/", "forecasts/")
#: RAOs computed with Capytaine when the configuration has vessel.bem.
BEM_RAO_FILE = "results/vessel/bem_rao.nc"
CLI_OVERRIDES = "--config (command line)"


def read_layers(paths) -> list[tuple[str, dict]]:
    """(file name, mapping) of each configuration file in the order Snakemake merges them,
    each read with the project's loader (:func:`jls.config.loader.load_yaml`)."""
    return [(str(p), load_yaml(p)) for p in paths]


def merged_config(layers, overrides=None) -> dict:
    """The configuration the workflow runs: the files as the project's loader reads them
    (:mod:`jls.io.yamlio`), merged in Snakemake's order, then the ``--config`` mapping.

    Snakemake reads configuration files with PyYAML's YAML 1.1 rules, which differ from
    the project loader's (``4.55e6`` is text to PyYAML, a number to jls; the values YAML
    1.1 and 1.2 read differently are refused by jls). The workflow replaces Snakemake's
    reading with this one, so ``jls check``, the workflow and every job see the same values.
    """
    merged = {}
    for _, data in layers:
        merge(merged, data)
    if overrides:
        merge(merged, dict(overrides))
    return merged


def origin(field, layers) -> str | None:
    """The file a key of the merged configuration came from (None without layers)."""
    return origin_finder(list(layers))(field or "") if layers else None


def _named(exc: InputError, layers) -> InputError:
    file = (origin(exc.field, layers) if exc.field else None) or exc.file
    return InputError(exc.message, file=file, field=exc.field, value=exc.value)


def check_config_files(cfg: dict, layers, overrides=None) -> dict:
    """Validate the merged configuration for the pipeline; errors name the source file.

    layers: [(file, mapping)] as merged by Snakemake; overrides: the ``--config`` mapping.
    """
    layers = list(layers) + ([(CLI_OVERRIDES, dict(overrides))] if overrides else [])
    cfg = validate(cfg, source=" + ".join(name for name, _ in layers) or "config",
                   origin=origin_finder(layers) if layers else None)
    own_hull(cfg, layers)                    # the hull of the vessel whose RAOs are read
    try:
        check_config(cfg, source="config")
        check_pipeline_keys(cfg)
        check_values(cfg, source="config")
    except InputError as exc:
        raise _named(exc, layers) from None
    return cfg


def config_warnings(cfg: dict) -> list[str]:
    """The warnings of a validated configuration's cross-checks
    (:func:`jls.config.cross_checks.check_values`), for the report's first page."""
    return check_values(cfg, source="config")


def check_pipeline_keys(cfg: dict) -> None:
    """Keys that ``jls modes`` reads but the pipeline cannot honour."""
    if "plant_matrices" in cfg:
        raise InputError("is read by 'jls modes' only; the pipeline builds the plant of every "
                         "rigging candidate from the geometry (jacket, rigging): remove it "
                         "from the configuration the workflow runs", field="plant_matrices",
                         value=cfg["plant_matrices"])
    vessel = cfg.get("vessel")
    if not vessel:
        raise InputError("required key is missing: the vessel's RAOs (rao_file or bem)",
                         field="vessel")
    if "bem" in vessel:
        if "rao_file" in vessel:
            raise InputError(f"give rao_file or bem, not both: with bem the pipeline computes "
                             f"the RAOs into {BEM_RAO_FILE}", field="vessel.rao_file",
                             value=vessel["rao_file"])
        import importlib.util
        if importlib.util.find_spec("capytaine") is None:
            raise InputError("computing RAOs needs Capytaine, which is not installed: "
                             "pip install -e '.[bem]', or give vessel.rao_file instead",
                             field="vessel.bem")
    elif "rao_file" not in vessel:
        raise InputError("required key is missing (or vessel.bem to compute the RAOs)",
                         field="vessel.rao_file")


def rao_file(cfg: dict) -> str:
    """The RAO file the vessel-motion rule reads."""
    return BEM_RAO_FILE if "bem" in cfg["vessel"] else cfg["vessel"]["rao_file"]


def check_rao(cfg: dict, tz_by_route: dict, layers=(), base_dir=".") -> list[str]:
    """Read the configured RAO file now (not in a job): readable, complete, plausible
    (:func:`jls.config.plausible.check_rao_magnitudes`: heave and rotations in the long-wave
    limit), holding every route heading as the vessel motion will select it
    (``vessel.heading_interpolation``), and covering each route's sea states (Tz [s]).
    Returns the warnings for the report's first page."""
    if "bem" in cfg["vessel"]:              # computed by a rule; checked when it is read
        w = cfg["vessel"]["bem"]["omega_rad_s"]
        for _, headings in tz_by_route.values():
            check_problem_size(cfg, len(headings), (w["min"], w["max"]), source=origin(
                "response.omega_step_rad_s", list(layers)) or "config")
        return []
    from jls.vessel.headings import read_vessel_rao, select_headings
    vessel = cfg["vessel"]
    path = Path(base_dir) / vessel["rao_file"]
    where = origin("vessel.rao_file", list(layers)) or "config"
    if not path.is_file():
        raise InputError("RAO file not found" if not path.exists() else
                         "RAO file is not a regular file", file=where, field="vessel.rao_file",
                         value=vessel["rao_file"])
    rao = read_vessel_rao(vessel, path, config_source=origin(
        "vessel.rao_reference_point_height_m", list(layers)) or "the configuration",
        g=float(cfg["g_m_per_s2"]))
    for field, h in study_headings(cfg):     # the jobs of every route run these too
        try:
            select_headings(rao, [h], file=path, interpolation=vessel["heading_interpolation"],
                            tolerance_deg=vessel["heading_tolerance_deg"])
        except InputError as exc:
            raise InputError(f"{exc.message.split(';')[0]}, which {field} asks for on every route "
                             f"({_given_by(field, layers)}): "
                             "give a heading the RAO file holds, or vessel.heading_interpolation",
                             file=path, field=field, value=h) from None
    lo, hi = float(rao["omega"].values[0]), float(rao["omega"].values[-1])
    gamma = float(cfg["sea"]["gamma"])
    for route, (tz, headings) in tz_by_route.items():
        select_headings(rao, sorted(headings), file=path, interpolation=vessel["heading_interpolation"],
                        tolerance_deg=vessel["heading_tolerance_deg"])
        check_problem_size(cfg, len(headings), (lo, hi), source=origin(
            "response.omega_step_rad_s", list(layers)) or "config")
        try:
            check_coverage(lo, hi, sorted(set(tz)), gamma, vessel.get("outside_rao_range"),
                           source=str(path))
        except InputError as exc:
            raise InputError(f"route '{route}': {exc.message}", file=exc.file, field=exc.field,
                             value=exc.value) from None
    check_measured_coverage(cfg, lo, hi, layers, base_dir)
    from jls.vessel.phase_checks import check_long_wave_phases
    warnings = check_rao_magnitudes(rao, vessel, file=path, g=float(cfg["g_m_per_s2"]))
    return warnings or check_long_wave_phases(rao, file=path, g=float(cfg["g_m_per_s2"]))


def study_headings(cfg: dict) -> list[tuple[str, float]]:
    """(key, heading [deg]) of the studies every route's jobs run at a heading of their
    own, whatever the route's legs: the tugger studies' slope sweep and, when on, the
    rigging screening's envelope. The vessel motion holds them (workflow/rules/common.smk,
    motion_headings), so the RAO file must."""
    out = [("timedomain.slope_sweep.heading_deg", float(cfg["timedomain"]["slope_sweep"]["heading_deg"]))]
    if cfg["screening"]["enabled"]:
        out.append(("screening.envelope.heading_deg", float(cfg["screening"]["envelope"]["heading_deg"])))
    return out


def outside_roots(rules) -> list[tuple[str, str]]:
    """(rule, output) of every rule output outside :data:`OUTPUT_ROOTS`."""
    bad = []
    for name, outputs in rules:
        for out in outputs:
            text = str(out)
            if Path(text).is_absolute() or ".." in Path(text).parts \
                    or not text.startswith(OUTPUT_ROOTS):
                bad.append((name, text))
    return bad


def job_errors(log_root="logs", since: float = 0.0) -> list[str]:
    """The one-line jls errors in the job logs written since ``since`` (epoch s)."""
    lines = []
    root = Path(log_root)
    if not root.is_dir():
        return lines
    for log in sorted(root.rglob("*.log")):
        try:
            if log.stat().st_mtime < since:
                continue
            text = log.read_text(errors="replace")
        except OSError:
            continue
        for line in text.splitlines():
            m = re.search(r" ERROR jls\.(\w+): (input error: .*)$", line)
            if m:
                lines.append(f"jls {m.group(1)} ({log}): {m.group(2)}")
    return lines


def _error_blocks(text: str) -> list[dict]:
    """The ``Error in rule NAME:`` blocks of a Snakemake log, each as its indented
    ``key: value`` lines (message, jobid, output, log, external_jobid, ...), in order,
    and a ``{"finished": (rule, jobid)}`` entry for each ``Finished jobid: J (Rule: R)``
    line (a job that completed on a retry)."""
    blocks, block = [], None
    for line in text.splitlines():
        done = re.match(r"Finished jobid: (\d+) \(Rule: (\S+)\)", line.strip())
        if done:
            blocks.append({"finished": (done.group(2), done.group(1))})
            block = None
            continue
        m = re.match(r"Error in rule (\S+?):?$", line.strip()) if not line.startswith(" ") else None
        if m:
            block = {"rule": m.group(1)}
            blocks.append(block)
            continue
        if block is None:
            continue
        kv = re.match(r"    (\w+): (.*)$", line)
        if kv:
            block.setdefault(kv.group(1), kv.group(2).strip())
        elif not line.startswith(" "):
            block = None
    return blocks


def _fresh_lines(path: Path, since: float) -> list[str] | None:
    """The non-empty lines of ``path`` when it was written since ``since``, else None."""
    try:
        if path.stat().st_mtime < since:
            return None
        return [ln for ln in path.read_text(errors="replace").splitlines() if ln.strip()]
    except OSError:
        return None


def failed_jobs(snakemake_logs, since: float = 0.0, tail: int = 5, base_dir=".",
                rewrite_stale: bool = False) -> list[str]:
    """Every job that failed in a run, from the run's Snakemake log(s): the rule, its
    output, its scheduler job id and attempts, and the cause.

    The cause is the job's own log (``logs/...``) when this run wrote an error into it:
    its ``input error:`` line, or the line that names the exception of its traceback;
    when the job's log is missing, empty, older than the run or ends without an error
    (the job was killed: out of memory, out of time; or it failed before its step began),
    the last ``tail`` lines of the scheduler's log of the job
    (``.snakemake/slurm_logs/...``) that Snakemake lists beside it: its error lines
    (the scheduler's kill, the interpreter's exception), else its last lines. A job that
    failed more than once (retries) is listed once, with its last attempt's logs; a job
    that completed on a retry is not listed.

    ``rewrite_stale``: a failed job's own log that this run did not write (the job died
    before its step began, so its log still holds an earlier run's lines) is replaced by
    one line saying so and naming the scheduler's log: no log of a failed job keeps a
    line of an earlier run.
    """
    jobs: dict[tuple, dict] = {}
    for log in snakemake_logs or ():
        try:
            text = Path(log).read_text(errors="replace")
        except OSError:
            continue
        for block in _error_blocks(text):
            if "finished" in block:
                jobs.pop(block["finished"], None)
                continue
            key = (block["rule"], block.get("jobid", block.get("output", "")))
            attempts = jobs.get(key, {}).get("attempts", 0) + 1
            jobs[key] = {**block, "attempts": attempts}
    lines = []
    for (rule, _), job in jobs.items():
        output = job.get("output", "")
        logs = [p.strip() for p in re.sub(r"\s*\(check log file\(s\) for error details\)", "",
                                          job.get("log", "")).split(", ") if p.strip()]
        own = [p for p in logs if p.startswith(OUTPUT_ROOTS)]
        scheduler = [p for p in logs if p not in own]
        head = f"failed: rule {rule}"
        if output:
            head += f" ({output})"
        if job.get("external_jobid"):
            head += f", scheduler job {job['external_jobid']}"
        if job["attempts"] > 1:
            head += f", {job['attempts']} attempts"
        lines.append(head)
        cause, state = None, "not written in this run"
        for p in own:
            text = _fresh_lines(Path(base_dir) / p, since)
            if text is None:
                continue
            errors = [ln for ln in text if re.search(r" ERROR jls\.\w+: ", ln)]
            inputs = [ln for ln in errors if "input error:" in ln]
            if errors:
                cause = [f"    {p}: {(inputs or errors)[-1].strip()}"]
                break
            state = f"ends without an error (last line: {text[-1].strip()})" if text else "empty"
        if cause is None and rewrite_stale:
            for p in own:
                path = Path(base_dir) / p
                if path.exists() and _fresh_lines(path, since) is None:
                    stamp = time.strftime("%Y-%m-%d %H:%M:%S,000")
                    path.write_text(f"{stamp} ERROR jls.{rule}: the job failed before its step "
                                    f"began (see {', '.join(scheduler) or 'Snakemake log'}); this "
                                    "log held an earlier run's lines\n")
                    state = "older than this run (rewritten)"
        if cause is None:
            where = f"{', '.join(own)}: {state}" if own else "no log of its own"
            for p in scheduler:
                text = _fresh_lines(Path(base_dir) / p, 0.0)
                if text:
                    # the scheduler's and the interpreter's error lines, else its last lines
                    said = [ln for ln in text if re.search(
                        r"slurmstepd|error|Error|Killed|CANCELLED|memory|TIME LIMIT|Traceback", ln)
                        and "snakemake.logging" not in ln and "did not complete" not in ln]
                    cause = [f"    {where}; the last lines of {p}:"] + [
                        f"        {ln}" for ln in (said or text)[-tail:]]
                    break
        if cause is None:
            cause = [f"    {where}; Snakemake: {job.get('message', 'no message')}"]
        lines.extend(cause)
    return lines


def operability_tz(cfg) -> list[float]:
    """The Tz grid of the operability curves [s]."""
    g = cfg["assessment"]["operability_tz_s"]
    n = int(round((g["max"] - g["min"]) / g["step"])) + 1
    return [round(g["min"] + i * g["step"], 6) for i in range(n)]


def check_run(paths, base_dir=".") -> dict:
    """Everything the workflow checks when it is parsed, for configuration files given
    in Snakemake's order (``jls check``): returns a summary of what would run."""
    from jls.config.environment import check_environment
    from jls.config.time_spans import check_time_spans
    from jls.sea.legs import read_leg
    check_environment()                     # what Snakemake and the jobs inherit
    layers = read_layers(paths)
    merged = {}
    for _, data in layers:
        merge(merged, data)
    cfg = check_config_files(merged, layers)
    if not cfg.get("routes"):
        raise InputError("no routes to assess", file=layers[-1][0], field="routes")
    gamma, rule = float(cfg["sea"]["gamma"]), cfg["sea"]["steepness_rule"]
    need, warnings = {}, config_warnings(cfg)
    for route, spec in cfg["routes"].items():
        tz, headings, tables = list(operability_tz(cfg)), set(), []
        for i, leg in enumerate(spec["legs"]):
            try:
                ds = read_leg(leg, base_dir, rule, gamma, cfg["g_m_per_s2"])
            except InputError as exc:
                raise leg_error(exc, route, i, leg, layers) from None
            tables.append(ds)
            warnings += [f"route '{route}', leg {leg['name']}: {w}" for w in warnings_of(ds)]
            tz += [float(t) for t in ds["tz"].values]
            headings |= {float(h) for h in leg["headings_deg"]}
        check_time_spans(cfg, route, tables, layers, base_dir)
        headings |= {h for _, h in study_headings(cfg)}     # as the workflow's vessel motion
        need[route] = (tz, sorted(headings))
    warnings += check_rao(cfg, need, layers, base_dir)
    from jls.config.forecast_entries import check_forecast_entries
    check_forecast_entries(cfg, base_dir)
    return {"routes": {r: len(cfg["routes"][r]["legs"]) for r in cfg["routes"]},
            "rao_file": rao_file(cfg), "warnings": warnings}
