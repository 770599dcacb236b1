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
* a plain value that YAML 1.1 (PyYAML, Snakemake's reader) and YAML 1.2 read differently
  is refused, naming the line: the booleans ``yes``/``no``/``on``/``off`` in any case
  (``NO`` as a route key is ``False`` in YAML 1.1, text in 1.2), sexagesimal numbers
  (``50:00`` is 3000 in YAML 1.1), octal and binary forms (``017``, ``0o17``, ``0b11``),
  numbers with underscores (``1_000``) and dates (``2024-01-01``); quote them for text;
* mapping keys must be text (``2024:`` as a route name is refused; quote it);
* the file must be a regular file of bounded size (:mod:`jls.io.files`: a named pipe or
  ``/dev/zero`` is refused before anything is read);
* the top level must be a mapping when ``mapping=True`` (the default);
* with ``refuse_yte=True`` a file that asks for Snakemake's YTE templating
  (``__use_yte__``) is refused: jls reads such files itself and does not evaluate them.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml
from yaml.constructor import ConstructorError
from yaml.nodes import MappingNode, ScalarNode, SequenceNode

from jls.errors import InputError
from jls.io.files import MAX_YAML_BYTES, read_bytes

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


_TAG = "tag:yaml.org,2002:"
_OCTAL_12 = re.compile(r"^[-+]?0o[0-7]+$")          # YAML 1.2 octal, text in YAML 1.1
_LEADING_ZERO = re.compile(r"^[-+]?0[0-9_]+$")       # YAML 1.1 octal, decimal in YAML 1.2


def _ambiguous(node) -> str | None:
    """Why a plain scalar reads differently in YAML 1.1 and 1.2 (None when it does not)."""
    if not isinstance(node, ScalarNode) or node.style:      # plain: None (PyYAML) or "" (libyaml)
        return None
    text, tag = node.value, node.tag.removeprefix(_TAG)
    if tag == "bool" and text.lower() not in ("true", "false"):
        return (f"{text!r} is the boolean {text.lower() in ('yes', 'on')} in YAML 1.1 (Snakemake's "
                "reader) and text in YAML 1.2: write true or false, or quote it for text")
    if tag in ("int", "float") and ":" in text:
        return (f"{text!r} is a base-60 (sexagesimal) number in YAML 1.1 "
                f"({_sexagesimal(text):g}) and text in YAML 1.2: write the number itself")
    if tag == "int" and (text.lstrip("+-").startswith("0b") or _LEADING_ZERO.match(text)):
        return (f"{text!r} is an octal or binary number in YAML 1.1 and not in YAML 1.2: write "
                "the decimal number without leading zeros")
    if tag == "str" and _OCTAL_12.match(text):
        return f"{text!r} is an octal number in YAML 1.2 and text in YAML 1.1: write the decimal number"
    if tag in ("int", "float") and "_" in text:
        return (f"{text!r} is a number in YAML 1.1 and text in YAML 1.2: write it without "
                "underscores")
    if tag == "timestamp":
        return f"{text!r} is a date in YAML 1.1 and text in YAML 1.2: quote it"
    return None


def _sexagesimal(text: str) -> float:
    sign = -1.0 if text.startswith("-") else 1.0
    value = 0.0
    for part in text.lstrip("+-").replace("_", "").split(":"):
        value = value * 60 + float(part)
    return sign * value


def _check_scalars(root, source) -> None:
    """Refuse plain scalars YAML 1.1 and 1.2 read differently, and keys that are not text."""
    seen, stack = set(), [root]
    while stack:
        node = stack.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        if isinstance(node, SequenceNode):
            stack.extend(node.value)
        elif isinstance(node, MappingNode):
            for key, value in node.value:
                if key.tag == _TAG + "merge":
                    stack.append(value)
                    continue
                if isinstance(key, ScalarNode) and key.tag != _TAG + "str":
                    kind = {"int": "a number", "float": "a number", "null": "empty"}.get(
                        key.tag.removeprefix(_TAG), key.tag.removeprefix(_TAG))
                    why = _ambiguous(key) or f"the key {key.value!r} is read as {kind}, not as text"
                    raise InputError(f"{why}; keys must be text (quote it: '{key.value}')",
                                     file=source, field=f"line {key.start_mark.line + 1}")
                if not isinstance(key, ScalarNode):
                    raise InputError("a key must be text, not a list or mapping", file=source,
                                     field=f"line {key.start_mark.line + 1}")
                stack.append(value)
        else:
            why = _ambiguous(node)
            if why:
                raise InputError(why, file=source, field=f"line {node.start_mark.line + 1}")


def _tab_line(text: str):
    for number, line in enumerate(text.splitlines(), start=1):
        indent = line[:len(line) - len(line.lstrip(" \t"))]
        if "\t" in indent and line.strip() and not line.lstrip().startswith("#"):
            return number
    return None


def read_text(path, what="file") -> str:
    """The text of a UTF-8 file (a leading BOM is dropped); InputError otherwise."""
    path = Path(path)
    raw = read_bytes(path, what, MAX_YAML_BYTES)
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
        _check_scalars(node, source)
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
