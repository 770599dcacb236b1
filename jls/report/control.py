"""Document control of the report: number, revision, sign-off, software version and
source commit, and the creation time.

The configuration's optional ``document`` section (jls/schemas/config.schema.yaml)
reaches the report as ``provenance['document']``. The creation time is
``SOURCE_DATE_EPOCH`` when that is set (reproducible builds: the same inputs then give
the same PDF bytes), else ``provenance['created']``.
"""

from __future__ import annotations

import os
import subprocess
from datetime import datetime, timezone
from pathlib import Path

import jls
from jls.errors import InputError

FIELDS = ("number", "revision", "title", "prepared", "checked", "approved", "client", "project")
NOT_ASSIGNED = "not assigned"
NOT_GIT = "not from a git checkout"


def document_info(provenance: dict) -> dict:
    """The document section as strings, every field present ('' when not given)."""
    doc = provenance.get("document") or {}
    return {k: str(doc.get(k) or "").strip() for k in FIELDS}


def source_commit(package_dir=None) -> str:
    """The git commit of the jls source (with '+ local changes' when the work tree differs
    from it), or :data:`NOT_GIT` when jls does not run from a git checkout of itself."""
    pkg = Path(package_dir or Path(jls.__file__).parent).resolve()
    try:
        top = subprocess.run(["git", "-C", str(pkg), "rev-parse", "--show-toplevel"],
                             capture_output=True, text=True, timeout=10)
        if top.returncode != 0 or Path(top.stdout.strip()).resolve() / pkg.name != pkg:
            return NOT_GIT          # not a checkout, or jls installed inside another repository
        head = subprocess.run(["git", "-C", str(pkg), "rev-parse", "HEAD"],
                              capture_output=True, text=True, timeout=10)
        if head.returncode != 0:
            return NOT_GIT
        dirty = subprocess.run(["git", "-C", str(pkg), "status", "--porcelain", "--", str(pkg)],
                               capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.SubprocessError):
        return NOT_GIT
    commit = head.stdout.strip()
    return commit + (" + local changes" if dirty.stdout.strip() else "")


def created(provenance: dict) -> str:
    """ISO-8601 creation time: SOURCE_DATE_EPOCH (UTC) when set, else the provenance's."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    if epoch:
        try:
            stamp = datetime.fromtimestamp(int(epoch), tz=timezone.utc)
        except (ValueError, OverflowError, OSError):
            raise InputError("must be whole seconds since 1970-01-01 UTC",
                             field="SOURCE_DATE_EPOCH", value=epoch) from None
        return stamp.isoformat(timespec="seconds")
    return str(provenance.get("created", "?"))


def short_commit(commit: str) -> str:
    return commit if commit == NOT_GIT else commit[:12] + commit[40:]
