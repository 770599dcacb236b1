"""The one YAML reader of jls: configurations, plant-matrices files, vessel YAML files.

Stricter than ``yaml.safe_load`` so that a slip in a file is an error naming the file
and line instead of a silently different input:

* the file must be UTF-8 text and hold something (an empty file or one of comments
  only is an error);
* a key given twice in the same mapping is an error (PyYAML keeps the last one);
* a tab in the indentation is reported as such (YAML indents with spaces);
* aliases may not expand into more than :data:`MAX_NODES` nodes (an "alias bomb"
  of nested anchors would otherwise make every later walk of the data hang);
* ``4.55e6`` (YAML 1.2 style, no dot) is read as a float, as engineers write it;
* the top level must be a mapping when ``mapping=True`` (the default);
* with ``refuse_yte=True`` a file that asks for Snakemake's YTE templating
  (``__use_yte__``) is refused: jls reads such files itself and does not evaluate them.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml
from yaml.constructor import ConstructorError
from yaml.nodes import MappingNode, SequenceNode

from jls.errors import InputError

#: Largest number of nodes a document may expand to once aliases are resolved.
MAX_NODES = 200_000

_FLOAT = re.compile(r"""^(?:[-+]?(?:[0-9][0-9_]*)\.[0-9_]*(?:[eE][-+]?[0-9]+)?
                  |[-+]?(?:[0-9][0-9_]*)(?:[eE][-+]?[0-9]+)
                  |\.[0-9_]+(?:[eE][-+]?[0-9]+)?
                  |[-+]?\.(?:inf|Inf|INF)
                  |\.(?:nan|NaN|NAN))$""", re.X)


#: libyaml's C parser when PyYAML was built with it (parsing ~10x faster; the same events)
_BASE = yaml.CSafeLoader if getattr(yaml, "__with_libyaml__", False) else yaml.SafeLoader


class StrictLoader(_BASE):
    """Safe loader that reads 4.55e6 as a float and refuses duplicate keys."""

    def construct_mapping(self, node, deep=False):
        if isinstance(node, MappingNode):
            seen = {}
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    first = seen.get(key)
                except TypeError:               # unhashable key: SafeLoader reports it
                    continue
                line = key_node.start_mark.line + 1
                if first is not None:
                    raise _Duplicate(key, line, first)
                seen[key] = line
        return super().construct_mapping(node, deep=deep)


StrictLoader.add_implicit_resolver("tag:yaml.org,2002:float", _FLOAT, list("-+0123456789."))


class _Duplicate(ConstructorError):
    def __init__(self, key, line, first):
        super().__init__(problem=f"key {key!r} given twice (lines {first} and {line})")
        self.key, self.line, self.first = key, line, first


def _expanded_size(node, limit) -> int:
    """Number of nodes of the document with every alias expanded (stops above limit)."""
    memo = {}

    def size(n):
        key = id(n)
        if key in memo:
            return memo[key]
        memo[key] = limit + 1            # a node that contains itself is unbounded
        if isinstance(n, SequenceNode):
            total = 1 + sum(size(c) for c in n.value)
        elif isinstance(n, MappingNode):
            total = 1 + sum(size(k) + size(v) for k, v in n.value)
        else:
            total = 1
        memo[key] = min(total, limit + 1)
        return memo[key]

    return size(node)


def _tab_line(text: str):
    for number, line in enumerate(text.splitlines(), start=1):
        indent = line[:len(line) - len(line.lstrip(" \t"))]
        if "\t" in indent and line.strip() and not line.lstrip().startswith("#"):
            return number
    return None


def read_text(path, what="file") -> str:
    """The text of a UTF-8 file (a leading BOM is dropped); InputError otherwise."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise InputError(f"{what} not found", file=path) from None
    except IsADirectoryError:
        raise InputError(f"{what} is a directory, not a file", file=path) from None
    except OSError as exc:
        raise InputError(f"cannot read {what}: {exc.strerror}", file=path) from None
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise InputError(f"not a UTF-8 text file (byte 0x{raw[exc.start]:02x} on line {line}); "
                         "save it as UTF-8", file=path) from None


def loads(text: str, source="<string>", *, mapping=True, refuse_yte=False, what="file"):
    """Parse YAML text with the rules of the module docstring; ``source`` names it."""
    if not any(line.strip() and not line.lstrip().startswith("#") for line in text.splitlines()):
        raise InputError(f"empty {what}: no keys", file=source)
    tab = _tab_line(text)
    if tab is not None:
        raise InputError("tab character in the indentation; YAML indents with spaces",
                         file=source, field=f"line {tab}")
    loader = StrictLoader(text)
    try:
        node = loader.get_single_node()
        if node is None:
            raise InputError(f"empty {what}: no keys", file=source)
        if _expanded_size(node, MAX_NODES) > MAX_NODES:
            raise InputError(f"aliases expand to more than {MAX_NODES} nodes (nested anchors "
                             "that multiply, an 'alias bomb'); write the values out",
                             file=source)
        data = loader.construct_document(node)
    except _Duplicate as exc:
        raise InputError(f"key given twice (first on line {exc.first}); remove one",
                         file=source, field=f"line {exc.line}", value=exc.key) from None
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        where = f"line {mark.line + 1}, column {mark.column + 1}" if mark else None
        problem = exc.problem or exc.context or "not valid YAML"
        raise InputError(f"not valid YAML: {problem}", file=source, field=where) from None
    except yaml.YAMLError as exc:
        raise InputError(f"not valid YAML: {exc}", file=source) from None
    finally:
        loader.dispose()
    if mapping and not isinstance(data, dict):
        kind = {list: "a list", str: "a single text", int: "a number",
                float: "a number"}.get(type(data), type(data).__name__)
        raise InputError(f"the top level must be a mapping of keys (key: value), not {kind}",
                         file=source)
    if refuse_yte and isinstance(data, dict) and "__use_yte__" in data:
        raise InputError("YTE templates (__use_yte__) are not evaluated by jls; give the "
                         "plain values", file=source, field="__use_yte__")
    return data


def load(path, *, mapping=True, refuse_yte=False, what="file"):
    """Read and parse a YAML file (see :func:`loads`); errors name the file."""
    path = Path(path)
    return loads(read_text(path, what), source=str(path), mapping=mapping,
                 refuse_yte=refuse_yte, what=what)
