"""The package's layers: every import inside ``jls`` points down the layer order, no
module imports itself back through others, and only the configuration and stage layers
read the raw configuration mapping.

Layer order, lowest first (a module may import from its own layer's package and from any
lower layer; a package's ``__init__`` may re-export its own modules):

    base        jls (the package itself), jls.collector, jls.errors, jls.names, jls.threads
    io          atomic writes, NetCDF, dataset registry, provenance, hashing, YAML
    sea, vessel, plant
    response    solver, kernels, statistics, coverage, tensions, wire loads, moments
    tugger      settings, law and loads
    assessment, timedomain
    design, verify   scoring, optimisation, screening; the 6-DOF nonlinear reference
    config      validation, heading resolution, workflow input checks, builders
    stages      one builder per dataset
    report, commands   the report; the bodies of the larger ``jls`` subcommands
    cli         the command line: parser and dispatch
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "jls"

LAYERS = [
    {"jls", "jls.collector", "jls.errors", "jls.names", "jls.threads"},
    {"jls.io"},
    {"jls.sea", "jls.vessel", "jls.plant"},
    {"jls.response"},
    {"jls.tugger"},
    {"jls.assessment", "jls.timedomain"},
    {"jls.design", "jls.verify"},
    {"jls.config"},
    {"jls.stages"},
    {"jls.report", "jls.commands"},
    {"jls.cli"},
]
RAW_CONFIG_ALLOWED = ("jls.config", "jls.stages", "jls.commands", "jls.cli")
CONFIG_NAMES = {"cfg", "config", "configuration"}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def group(module: str) -> str:
    """The layer group a module belongs to: its top-level package (``jls.io``), or the
    module itself for a top-level file (``jls.errors``)."""
    parts = module.split(".")
    return ".".join(parts[:2]) if len(parts) > 1 else module


def rank(module: str) -> int:
    g = group(module)
    for i, layer in enumerate(LAYERS):
        if g in layer:
            return i
    raise AssertionError(f"{module}: its package {g} is in no layer of tests/test_layering.py")


def jls_imports(path: Path) -> list[tuple[int, str]]:
    """(line, imported module) of every import of a jls module, at any depth (function
    bodies included). ``from a.b import c`` counts as ``a.b.c`` when that is a module."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and node.level == 0 and node.module \
                and (node.module == "jls" or node.module.startswith("jls.")):
            for alias in node.names:
                sub = f"{node.module}.{alias.name}"
                out.append((node.lineno, sub if sub in MODULES else node.module))
        elif isinstance(node, ast.Import):
            out += [(node.lineno, a.name) for a in node.names if a.name.split(".")[0] == "jls"]
        elif isinstance(node, ast.ImportFrom) and node.level:
            raise AssertionError(f"{path}:{node.lineno}: relative import; jls imports absolutely")
    return out


def test_every_package_has_a_layer():
    for module in MODULES:
        rank(module)


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_point_down(module):
    here = rank(module)
    own = group(module)
    for line, target in jls_imports(MODULES[module]):
        if target in ("jls",) or target.startswith("jls.schemas"):
            continue
        if group(target) == own:
            continue
        assert rank(target) < here, (f"{MODULES[module].relative_to(ROOT)}:{line} imports "
                                     f"{target} (layer {rank(target)}) from layer {here}")


def _graph() -> dict[str, set[str]]:
    return {m: {t for _, t in jls_imports(p) if t in MODULES and t != m} for m, p in MODULES.items()}


def test_no_import_cycles():
    graph, state, cycles = _graph(), {}, []

    def visit(m, stack):
        state[m] = 1
        for t in sorted(graph[m]):
            if state.get(t) == 1:
                cycles.append(stack[stack.index(t):] + [t] if t in stack else [m, t])
            elif t not in state:
                visit(t, stack + [t])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m, [m])
    # a package __init__ re-exporting its modules is not a cycle of logic
    cycles = [c for c in cycles if not any(MODULES[x].name == "__init__.py" for x in c)]
    assert not cycles, "import cycles: " + "; ".join(" -> ".join(c) for c in cycles)


def raw_config_reads(path: Path) -> list[int]:
    """Lines subscripting a name that holds the raw configuration (``cfg["..."]``)."""
    lines = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Name) \
                and node.value.id in CONFIG_NAMES:
            lines.append(node.lineno)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr == "get" and isinstance(node.func.value, ast.Name) \
                and node.func.value.id in CONFIG_NAMES:
            lines.append(node.lineno)
    return lines


@pytest.mark.parametrize("module", sorted(m for m in MODULES if not m.startswith(RAW_CONFIG_ALLOWED)))
def test_raw_configuration_only_in_config_and_stages(module):
    lines = raw_config_reads(MODULES[module])
    assert not lines, (f"{MODULES[module].relative_to(ROOT)} reads the raw configuration at "
                       f"lines {lines}; build a settings object in jls.config.builders")


def test_the_checker_sees_an_upward_import(tmp_path):
    """The checks can fail: an upward import and a raw configuration read are found."""
    bad = tmp_path / "bad.py"
    bad.write_text("from jls.stages.response import response_dataset\n"
                   "def f(cfg):\n    return cfg['sea']\n")
    assert jls_imports(bad) == [(1, "jls.stages.response")]
    assert rank("jls.stages.response") > rank("jls.sea.legs")
    assert raw_config_reads(bad) == [3]



def test_tugger_defaults_are_the_schemas():
    """A tugger setting built without a configuration gets the schema's defaults, the same
    as one built from a configuration that gives only its name and slope: the defaults are
    stated once (jls/schemas/config.schema.yaml)."""
    import yaml

    from jls.config.builders import tuggers_from_config
    from jls.config.loader import fill_defaults
    from jls.io.schema import schema
    from jls.tugger.setting import Tugger
    raw = yaml.safe_load((ROOT / "jls" / "schemas" / "config.schema.yaml").read_text())
    item = raw["properties"]["tuggers"]["items"]["properties"]
    bare = Tugger("x", 300.0)
    assert (bare.max_force, bare.min_force, bare.lag, bare.half_width) == (
        item["max_force_kN"]["default"], item["min_force_kN"]["default"],
        item["lag_s"]["default"], item["attachment_half_width_m"]["default"])
    filled = fill_defaults({"name": "x", "c_kN_s_per_m": 300.0}, schema()["properties"]["tuggers"]["items"])
    assert tuggers_from_config({"tuggers": [filled], "vessel": {}})["x"] == bare
