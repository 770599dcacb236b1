"""The one exception type for bad user input.

Every reader and validator raises :class:`InputError` naming where the bad value
came from (file, field, value) so the command line can print one clear line
instead of a traceback.
"""

from __future__ import annotations


class InputError(ValueError):
    """Bad user input: names the source file, the field and the offending value."""

    def __init__(self, message: str, *, file: str | None = None, field: str | None = None,
                 value: object = None):
        self.message = message
        self.file = str(file) if file is not None else None
        self.field = field
        self.value = value
        parts = []
        if self.file:
            parts.append(self.file)
        if field:
            parts.append(field)
        where = ": ".join(parts)
        text = f"{where}: {message}" if where else message
        if value is not None:
            text += f" (got {value!r})"
        super().__init__(text)
