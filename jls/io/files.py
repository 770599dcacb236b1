"""Input files jls reads: regular files of bounded size, nothing else.

A path given as a table, a record or a configuration must name a regular file (a named
pipe would block the reader forever, ``/dev/zero`` or ``/dev/urandom`` would fill the
memory) of at most the stated size. :func:`regular_file` checks it before anything is
read and raises :class:`jls.errors.InputError` naming the file.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from jls.errors import InputError

MB = 1 << 20
#: Largest configuration or plant-matrices YAML file [bytes].
MAX_YAML_BYTES = 10 * MB
#: Largest scatter table or hindcast record [bytes] (ten years of hourly records: 3 MB).
MAX_TABLE_BYTES = 200 * MB
#: Largest RAO text file (WAMIT .4, CSV) [bytes].
MAX_RAO_TEXT_BYTES = 200 * MB


def _kind(mode: int) -> str:
    if stat.S_ISFIFO(mode):
        return "a named pipe"
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def regular_file(path, what: str = "file", max_bytes: int = MAX_TABLE_BYTES,
                 field: str | None = None) -> Path:
    """``path`` if it is a regular file of at most ``max_bytes``; InputError otherwise
    (not found, a directory, a pipe or device, too large). Symbolic links are followed:
    what counts is the file they lead to. An empty path names no file (it would read as
    the current folder)."""
    if isinstance(path, str) and not path.strip():
        raise InputError(f"an empty path names no {what}: give the file's path", field=field,
                         value=path)
    path = Path(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise InputError(f"{what} not found", file=path, field=field) from None
    except OSError as exc:
        raise InputError(f"cannot read {what}: {exc.strerror}", file=path, field=field) from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError(f"{what} is a directory, not a file", file=path, field=field)
    if not stat.S_ISREG(st.st_mode):
        raise InputError(f"{what} is {_kind(st.st_mode)}, not a regular file; give the "
                         "file itself", file=path, field=field)
    if st.st_size > max_bytes:
        raise InputError(f"{what} is {st.st_size / MB:.0f} MB, more than the {max_bytes / MB:.0f} MB "
                         "jls reads; is it the right file?", file=path, field=field)
    return path


def read_bytes(path, what: str = "file", max_bytes: int = MAX_TABLE_BYTES, field=None) -> bytes:
    """The bytes of a regular file of bounded size (:func:`regular_file`)."""
    path = regular_file(path, what, max_bytes, field)
    try:
        with open(path, "rb") as fh:
            raw = fh.read(max_bytes + 1)
    except OSError as exc:
        raise InputError(f"cannot read {what}: {exc.strerror}", file=path, field=field) from None
    if len(raw) > max_bytes:                 # grew while being read
        raise InputError(f"{what} is larger than the {max_bytes / MB:.0f} MB jls reads",
                         file=path, field=field)
    return raw
