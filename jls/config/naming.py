"""Where a configuration value comes from, for error messages: which configuration file
sets a key (or that the schema's default stands), and a leg's file error prefixed with its
route, leg and the key that names the file."""

from __future__ import annotations

from jls.config.loader import origin_finder
from jls.errors import InputError

__all__ = ["given_by", "leg_error"]


def given_by(field: str, layers) -> str:
    """Which configuration file sets a dotted key, or that the schema's default stands."""
    for name, data in reversed(list(layers)):
        node = data
        for key in field.split("."):
            node = node.get(key) if isinstance(node, dict) else None
        if node is not None:
            return f"set in {name}"
        continue
    return "the schema's default"


def leg_error(exc: InputError, route: str, index: int, leg: dict, layers) -> InputError:
    """An error reading a leg's file, prefixed with the route and leg, its file and line
    kept, and the configuration key that names the file given in full with the
    configuration file that sets it ("the file given by routes.r.legs[0].spectra.file in
    case.yaml")."""
    from jls.config.loader import _given_in
    message = exc.message.replace(f"the file given by legs[{leg['name']}].",
                                  f"the file given by routes.{route}.legs[{index}].")
    if layers:
        message = _given_in(message, origin_finder(list(layers)))
    return InputError(f"route '{route}', leg '{leg['name']}': {message}", file=exc.file,
                      field=exc.field, value=exc.value)
