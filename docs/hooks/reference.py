"""The documentation's reference pages, generated from the sources of truth when the site is
built (an MkDocs hook, mkdocs.yml ``hooks:``), so that they can never drift from the code:

- ``reference/configuration.md``: every key of ``jls/schemas/config.schema.yaml`` with its
  type, default, unit, bounds and description;
- ``reference/datasets.md``: every dataset of the registry ``jls/schemas/datasets.yaml``
  with its variables, dimensions, units, coordinates and attributes;
- ``reference/cli.md``: every ``jls`` command as its argparse parser prints it.

``python docs/hooks/reference.py OUTDIR`` writes the three pages without MkDocs.
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
from pathlib import Path

import yaml

SCHEMAS = Path(__file__).resolve().parents[2] / "jls" / "schemas"
PAGES = ("reference/configuration.md", "reference/datasets.md", "reference/cli.md")

# Units spelled in key names (the schema's rule: units are in the key names).
_SUFFIX_UNITS = [
    ("_kN_s_per_m", "kN s/m"), ("_kN_per_m", "kN/m"), ("_m_per_s2", "m/s²"), ("_m_per_s", "m/s"),
    ("_rad_per_s", "rad/s"), ("_t_per_m", "t/m"), ("_t_m2", "t m²"), ("_kN_m", "kN m"),
    ("_kN", "kN"), ("_deg", "deg"), ("_rad", "rad"), ("_mm", "mm"), ("_m", "m"), ("_s", "s"),
    ("_h", "h"), ("_t", "t"), ("_hz", "Hz"), ("_mb", "MB"), ("_percent", "%"),
]


def _load(name):
    with open(SCHEMAS / name, encoding="utf-8") as f:
        return yaml.safe_load(f)


def _resolve(node, defs):
    """``node`` with its ``$ref`` (to ``#/$defs/...``) merged in, the node's own keys winning."""
    while isinstance(node, dict) and "$ref" in node:
        base = defs[node["$ref"].rsplit("/", 1)[-1]]
        node = {**base, **{k: v for k, v in node.items() if k != "$ref"}}
    return node


def _unit(key, node):
    m = re.search(r"\[([^\]]+)\]", str(node.get("description", "")))
    if m and len(m.group(1)) <= 24:
        return m.group(1)
    for suffix, unit in _SUFFIX_UNITS:
        if key.endswith(suffix):
            return unit
    return ""


def _fmt(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if v is None:
        return "null"
    if isinstance(v, list):
        text = "[" + ", ".join(_fmt(x) for x in v) + "]"
        return text if len(text) <= 60 else text[:57] + "...]"
    if isinstance(v, float):
        return f"{v:g}"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {_fmt(x)}" for k, x in v.items()) + "}"
    return str(v)


def _bounds(node, defs):
    parts = []
    for key, sym in (("minimum", ">="), ("exclusiveMinimum", ">"), ("maximum", "<="),
                     ("exclusiveMaximum", "<")):
        if key in node:
            parts.append(f"{sym} {_fmt(node[key])}")
    if "enum" in node:
        parts.append("one of " + ", ".join(f"`{_fmt(v)}`" for v in node["enum"]))
    if "const" in node:
        parts.append(f"= `{_fmt(node['const'])}`")
    if "pattern" in node:
        parts.append(f"matches `{node['pattern']}`")
    if "minItems" in node or "maxItems" in node:
        parts.append(f"{node.get('minItems', 0)}-{node.get('maxItems', 'any')} items")
    if node.get("type") == "array" and "items" in node:
        inner = _bounds(_resolve(node["items"], defs), defs)
        if inner:
            parts.append(f"each {inner}")
    for alt in ("oneOf", "anyOf"):
        if alt in node and "properties" not in node:
            alts = [_bounds(_resolve(a, defs), defs) for a in node[alt]]
            alts = [a for a in alts if a]
            if alts:
                parts.append(" or ".join(f"({a})" for a in alts))
    return "; ".join(parts)


def _type(node, defs):
    if "type" in node:
        t = node["type"]
        return " or ".join(t) if isinstance(t, list) else t
    if "enum" in node:
        return "choice"
    for alt in ("oneOf", "anyOf"):
        if alt in node:
            types = []
            for a in node[alt]:
                t = _type(_resolve(a, defs), defs)
                if t and t not in types:
                    types.append(t)
            return " or ".join(types)
    return ""


def _children(node, defs):
    """(key, child) of an object node, alternatives (oneOf/anyOf/then) included."""
    props = dict(node.get("properties", {}))
    for alt in ("oneOf", "anyOf", "allOf"):
        for a in node.get(alt, []):
            a = _resolve(a, defs)
            if isinstance(a, dict):
                for k, v in a.get("properties", {}).items():
                    props.setdefault(k, v)
    return props


def config_rows(schema=None):
    """One row per configuration key: (path, type, default, unit, bounds, description), in the
    schema's order; ``a.b[]`` is an item of the list ``a.b``, ``<name>`` a key of your choice."""
    schema = schema or _load("config.schema.yaml")
    defs = schema.get("$defs", {})
    rows = []

    def walk(node, path):
        node = _resolve(node, defs)
        for key, child in _children(node, defs).items():
            child = _resolve(child, defs)
            here = f"{path}.{key}" if path else key
            rows.append((here, _type(child, defs), _fmt(child["default"]) if "default" in child else "",
                         _unit(key, child), _bounds(child, defs), str(child.get("description", ""))))
            descend(child, here)

    def descend(child, here):
        if _children(child, defs):
            walk(child, here)
        extra = child.get("additionalProperties")
        if isinstance(extra, dict):
            extra = _resolve(extra, defs)
            name = f"{here}.<{'route' if here == 'routes' else 'name'}>"
            if _children(extra, defs):
                walk(extra, name)
            elif here != "":
                rows.append((name, _type(extra, defs), "", "", _bounds(extra, defs),
                             str(extra.get("description", ""))))
        items = child.get("items")
        if isinstance(items, dict):
            items = _resolve(items, defs)
            if _children(items, defs):
                walk(items, f"{here}[]")
        for alt in ("oneOf", "anyOf"):
            for a in child.get(alt, []):
                a = _resolve(a, defs)
                if isinstance(a, dict) and a.get("type") == "array" and isinstance(a.get("items"), dict):
                    it = _resolve(a["items"], defs)
                    if _children(it, defs):
                        walk(it, f"{here}[]")

    walk(schema, "")
    return rows


def _cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def configuration_page(schema=None):
    schema = schema or _load("config.schema.yaml")
    rows = config_rows(schema)
    out = ["# Configuration reference", "",
           "Generated from `jls/schemas/config.schema.yaml` when this site is built: every key, "
           "its type, its default (filled in when the configuration is validated; no code has "
           "a default of its own), its unit and its bounds. `a.b[]` is an item of the list "
           "`a.b`; `<route>` and `<name>` are names of your choice. A key without a default "
           "is required where its block is given, or optional where the description says so.",
           "", f"Top-level keys required: {', '.join(f'`{k}`' for k in schema.get('required', []))}.", ""]
    top = None
    for path, typ, default, unit, bounds, desc in rows:
        head = path.split(".")[0].split("[")[0]
        if head != top:
            top = head
            out += ["", f"## `{head}`", "", "| key | type | default | unit | bounds | description |",
                    "|---|---|---|---|---|---|"]
        out.append(f"| `{path}` | {_cell(typ)} | {_cell(f'`{default}`' if default else '')} | "
                   f"{_cell(unit)} | {_cell(bounds)} | {_cell(desc)} |")
    return "\n".join(out) + "\n"


def datasets_page(registry=None):
    registry = registry or _load("datasets.yaml")
    out = ["# Dataset reference", "",
           "Generated from the registry `jls/schemas/datasets.yaml` when this site is built: "
           "every dataset jls writes, with its variables (dimensions, units, long name), "
           "coordinates and global attributes. Units are UDUNITS strings; `units from X` "
           "means one unit per entry of the coordinate X. The datasets' meaning is in "
           "[The datasets explained](outputs.md).", ""]
    for name, spec in registry.items():
        out += [f"## `{name}`", ""]
        if spec.get("config"):
            out += ["Depends on the configuration: " + ", ".join(f"`{c}`" for c in spec["config"]) + ".", ""]
        out += ["| variable | dimensions | units | long name |", "|---|---|---|---|"]
        for var, v in spec.get("variables", {}).items():
            units = (f"units from `{v['units_from']}`" if "units_from" in v else
                     f"`{v.get('units', '')}`" + (f" ({v['units_note']})" if v.get("units_note") else ""))
            opt = " (optional)" if v.get("optional") else ""
            flags = f"; flags: {v['flag_meanings']}" if v.get("flag_meanings") else ""
            out.append(f"| `{var}`{opt} | {_cell(', '.join(v.get('dims', [])) or 'scalar')} | "
                       f"{_cell(units)} | {_cell(v.get('long_name', ''))}{_cell(flags)} |")
        if spec.get("coordinates"):
            out += ["", "| coordinate | units | long name |", "|---|---|---|"]
            for coord, c in spec["coordinates"].items():
                out.append(f"| `{coord}` | {_cell(c.get('units', ''))} | {_cell(c.get('long_name', ''))} |")
        if spec.get("attrs"):
            out += ["", "Attributes: " + ", ".join(f"`{a}`" for a in spec["attrs"]) + "."]
        out.append("")
    return "\n".join(out) + "\n"


def _subcommands(parser):
    import argparse
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return action.choices
    return {}


def cli_page():
    from jls.cli import build_parser
    with _columns(96):
        parser = build_parser()
        out = ["# Command reference", "",
               "Generated from the `jls` command's argparse parser (`jls.cli.build_parser`) when "
               "this site is built. The workflow itself runs with `snakemake` "
               "([Running an assessment](../guide/running.md)).", "",
               "## `jls`", "", "```text", parser.format_help().rstrip(), "```", ""]
        for name, sub in _subcommands(parser).items():
            out += [f"## `jls {name}`", "", "```text", sub.format_help().rstrip(), "```", ""]
    return "\n".join(out)


@contextlib.contextmanager
def _columns(n):
    old = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = str(n)
    try:
        yield
    finally:
        if old is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = old


def pages():
    """src path in the site -> Markdown text of every generated page."""
    return dict(zip(PAGES, (configuration_page(), datasets_page(), cli_page())))


def on_files(files, config):
    """MkDocs hook: add the generated pages to the site."""
    from mkdocs.structure.files import File
    for path, text in pages().items():
        files.append(File.generated(config, path, content=text))
    return files


if __name__ == "__main__":
    outdir = Path(sys.argv[1] if len(sys.argv) > 1 else "site-reference")
    for path, text in pages().items():
        target = outdir / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")
        print(target)
