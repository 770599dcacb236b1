"""The configuration schema (``jls/schemas/config.schema.yaml``) as data.

The schema is the one place where a default is stated. The configuration layer validates
against it and fills its defaults; a library object built without a configuration (a
tugger setting in a benchmark, a sweep's settings) takes its defaults from here too, so
no module restates a number the schema holds.
"""

from __future__ import annotations

import copy
from functools import cache
from importlib import resources

from jls.io import yamlio

SCHEMA_FILE = "config.schema.yaml"


@cache
def _loaded() -> dict:
    text = resources.files("jls.schemas").joinpath(SCHEMA_FILE).read_text()
    return yamlio.loads(text, source=SCHEMA_FILE)


def schema() -> dict:
    """The schema, a fresh copy (callers may fill or change it)."""
    return copy.deepcopy(_loaded())


def default(path: str):
    """The schema's default at a dotted path of property names, ``items`` stepping into
    an array's items: ``default("tuggers.items.max_force_kN")`` is the winch capacity a
    tugger setting gets when none is given. A path without a stated default is an error
    (a library default must exist in the schema)."""
    node = _loaded()
    for part in path.split("."):
        node = node["items"] if part == "items" else node["properties"][part]
    if "default" not in node:
        raise KeyError(f"{SCHEMA_FILE}: no default at {path}")
    return copy.deepcopy(node["default"])


def bounds(path: str) -> tuple[float | None, float | None, bool]:
    """(lower, upper, lower excluded) of the number at a dotted path (as :func:`default`):
    the schema's ``minimum`` or ``exclusiveMinimum`` and ``maximum``, so that a command-line
    option standing for a configuration key is bounded as the key is."""
    node = _loaded()
    for part in path.split("."):
        node = node["items"] if part == "items" else node["properties"][part]
    if "exclusiveMinimum" in node:
        return node["exclusiveMinimum"], node.get("maximum"), True
    return node.get("minimum"), node.get("maximum"), False
