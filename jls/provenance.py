"""Provenance and logging for workflow steps: versions, hashes, log files."""

from __future__ import annotations

import logging
import os
from contextlib import contextmanager
import platform
import sys
from datetime import datetime, timezone
from importlib import metadata

from jls import __version__
from jls.config import config_hash, file_sha256
from jls.errors import InputError

PACKAGES = ("numpy", "scipy", "xarray", "netCDF4", "pandas", "matplotlib", "snakemake", "typst")


def package_versions() -> dict:
    out = {}
    for name in PACKAGES:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            out[name] = "not installed"
    return out


def creation_time() -> datetime:
    """Now (UTC, to the second), or the time the ``SOURCE_DATE_EPOCH`` environment
    variable fixes (whole seconds since 1970, the reproducible-builds convention) so
    that two runs of the same inputs give the same report bytes."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if not epoch:
        return datetime.now(timezone.utc).replace(microsecond=0)
    try:
        return datetime.fromtimestamp(int(epoch), timezone.utc)
    except (ValueError, OverflowError, OSError):
        raise InputError("must be whole seconds since 1970-01-01 UTC", file="environment",
                         field="SOURCE_DATE_EPOCH", value=epoch) from None


def provenance(cfg: dict, inputs: dict) -> dict:
    """The provenance block of a report: versions, config hash, input checksums."""
    return {
        "jls_version": __version__,
        "config_sha256": config_hash(cfg),
        "created": creation_time().isoformat(timespec="seconds"),
        "inputs": {name: {"path": str(p), "sha256": file_sha256(p)} for name, p in inputs.items()},
        "python": f"{platform.python_version()} ({sys.platform})",
        "packages": package_versions(),
    }


def step_logger(log_path, name) -> logging.Logger:
    """A logger writing to the step's log file (and stderr), with timestamps."""
    logger = logging.getLogger(f"jls.{name}")
    logger.setLevel(logging.INFO)
    logger.handlers.clear()
    fmt = logging.Formatter("%(asctime)s %(levelname)s %(name)s: %(message)s")
    for handler in (logging.FileHandler(log_path, mode="w"), logging.StreamHandler(sys.stderr)):
        handler.setFormatter(fmt)
        logger.addHandler(handler)
    return logger


@contextmanager
def workflow_step(log_path, name):
    """Run a workflow step: a logger for progress, and a bad input ends the job with one
    line naming the input and the reason (in the log and on stderr), no traceback."""
    logger = step_logger(log_path, name)
    try:
        yield logger
    except InputError as exc:
        logger.error("input error: %s", exc)
        raise SystemExit(f"jls {name}: input error: {exc}") from None
