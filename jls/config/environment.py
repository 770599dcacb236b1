"""The environment a workflow run inherits, checked when the workflow is parsed (and by
``jls check``), before any job: a variable that a job, numba or the report would refuse
is refused here, naming the variable and its value.

* ``SOURCE_DATE_EPOCH`` (the report's creation time, :func:`jls.report.control.created`):
  whole seconds since 1970-01-01 UTC, not after the present (a report cannot be made in
  the future; one day is allowed for clocks that differ);
* ``NUMBA_NUM_THREADS`` (the compiled kernels' threads): a whole number >= 1 (numba's own
  check would stop every job and the job server); ``NUMBA_THREADING_LAYER`` one numba knows;
* Snakemake's source cache (``$XDG_CACHE_HOME``, else ``~/.cache``): a folder that can be
  made and written; Snakemake creates it before it reads the workflow, so a read-only home
  folder stops it with a traceback before jls runs. ``jls check`` says so and how to point
  it elsewhere (``XDG_CACHE_HOME=/a/writable/folder``).

Errors are :class:`jls.errors.InputError` with ``file="environment"``.
"""

from __future__ import annotations

import os
import re
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path

from jls.errors import InputError

ENVIRONMENT = "environment"
#: Seconds a SOURCE_DATE_EPOCH may lie after the present (clocks that differ).
FUTURE_SLACK_S = 86400


def check_source_date_epoch(env=None, now: float | None = None) -> None:
    env = os.environ if env is None else env
    text = env.get("SOURCE_DATE_EPOCH", "")
    if not text.strip():
        return
    epoch = text.strip()
    if not re.fullmatch(r"\d+", epoch):
        raise InputError("must be whole seconds since 1970-01-01 UTC (e.g. $(git log -1 "
                         "--format=%ct)); unset it for the present time", file=ENVIRONMENT,
                         field="SOURCE_DATE_EPOCH", value=text)
    now = time.time() if now is None else now
    try:
        stamp = datetime.fromtimestamp(int(epoch), tz=timezone.utc)
    except (ValueError, OverflowError, OSError):
        stamp = None
    if stamp is None or int(epoch) > now + FUTURE_SLACK_S:
        present = datetime.fromtimestamp(now, tz=timezone.utc).isoformat(timespec="seconds")
        when = stamp.isoformat(timespec="seconds") if stamp else "beyond the year 9999"
        raise InputError(f"lies in the future ({when}, the present is {present}): the report's "
                         "creation time cannot be later than now", file=ENVIRONMENT,
                         field="SOURCE_DATE_EPOCH", value=text)


def check_numba_threads(env=None) -> None:
    env = os.environ if env is None else env
    text = env.get("NUMBA_NUM_THREADS")
    if text is None or not text.strip():
        return
    if not re.fullmatch(r"\s*\d+\s*", text) or int(text) < 1:
        raise InputError("must be a whole number of threads >= 1 (numba refuses anything else "
                         "and every job would fail); unset it to use every core",
                         file=ENVIRONMENT, field="NUMBA_NUM_THREADS", value=text)


#: The threading layers numba knows (NUMBA_THREADING_LAYER).
THREADING_LAYERS = ("default", "safe", "forksafe", "threadsafe", "tbb", "omp", "workqueue")


def check_numba_layer(env=None) -> None:
    env = os.environ if env is None else env
    text = env.get("NUMBA_THREADING_LAYER")
    if text is None or not text.strip():
        return
    if text.strip().lower() not in THREADING_LAYERS:
        raise InputError(f"is not a threading layer numba knows ({', '.join(THREADING_LAYERS)}): "
                         "every job's compiled kernels would fail; unset it", file=ENVIRONMENT,
                         field="NUMBA_THREADING_LAYER", value=text)


def snakemake_cache_dir(env=None) -> Path:
    """The folder Snakemake keeps its source cache in (platformdirs' user cache folder on
    Linux: ``$XDG_CACHE_HOME``, else ``~/.cache``)."""
    env = os.environ if env is None else env
    base = env.get("XDG_CACHE_HOME", "").strip()
    if not base or not os.path.isabs(base):
        base = os.path.join(env.get("HOME") or os.path.expanduser("~"), ".cache")
    return Path(base) / "snakemake"


def check_cache_dir(env=None) -> None:
    folder = snakemake_cache_dir(env)
    try:                                      # what Snakemake does first: make it, write in it
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
        return
    except OSError as exc:
        why = exc.strerror or type(exc).__name__
    field = "XDG_CACHE_HOME" if (env or os.environ).get("XDG_CACHE_HOME") else "HOME"
    raise InputError(f"Snakemake keeps its source cache in {folder}, which cannot be made or "
                     f"written ({why}): "
                     "Snakemake would stop before reading the workflow; point it at a writable "
                     "folder: XDG_CACHE_HOME=/tmp/$USER-cache snakemake ...", file=ENVIRONMENT,
                     field=field, value=str((env or os.environ).get(field)))


def check_environment(env=None, *, cache: bool = True) -> None:
    """Every check of this module (``cache``: the Snakemake cache folder too, which only
    ``jls check`` can report: Snakemake stops on it before it reads the workflow)."""
    check_source_date_epoch(env)
    check_numba_threads(env)
    check_numba_layer(env)
    if cache:
        check_cache_dir(env)


__all__ = ["check_environment", "check_source_date_epoch", "check_numba_threads", "check_numba_layer",
           "check_cache_dir", "snakemake_cache_dir"]
