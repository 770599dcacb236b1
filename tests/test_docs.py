"""The documentation's generated reference (docs/hooks/reference.py) lists every key of the
configuration schema, every dataset, variable and coordinate of the registry and every
option of every jls command; the site's navigation names only pages that exist. The keys
are collected here by a walk of the raw YAML of its own, so that a key the generator
skips, or a renamed key, fails."""

import importlib.util
import re
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]


def _generator():
    spec = importlib.util.spec_from_file_location("docs_reference", ROOT / "docs/hooks/reference.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def ref():
    return _generator()


def _schema_keys(node, out):
    """Every name under any ``properties`` of the schema, whatever its nesting."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "properties" and isinstance(value, dict):
                out.update(value)
            _schema_keys(value, out)
    elif isinstance(node, list):
        for value in node:
            _schema_keys(value, out)
    return out


def _documented_keys(page):
    """Last components of the keys in the page's tables."""
    keys = set()
    for path in re.findall(r"^\| `([^`]+)` \|", page, flags=re.M):
        keys.add(re.split(r"[.\[\]]+", path.rstrip("[]"))[-1])
    return keys


def test_every_schema_key_is_in_the_configuration_reference(ref):
    schema = yaml.safe_load((ROOT / "jls/schemas/config.schema.yaml").read_text())
    keys = set(_schema_keys({k: v for k, v in schema.items() if k != "$defs"}, set())) - {"$schema"}
    # keys that only a $defs entry holds are reached through their $ref
    keys |= set(_schema_keys(schema.get("$defs", {}), set()))
    page = ref.configuration_page(schema)
    missing = sorted(keys - _documented_keys(page))
    assert not missing, f"schema keys missing from docs reference/configuration.md: {missing}"
    assert len(keys) > 200


def test_configuration_reference_states_defaults_units_and_bounds(ref):
    rows = {r[0]: r for r in ref.config_rows()}
    path, typ, default, unit, bounds, desc = rows["g_m_per_s2"]
    assert (typ, default, unit) == ("number", "9.81", "m/s^2")
    assert ">= 9.7" in bounds and "<= 9.9" in bounds
    assert rows["timedomain.max_cells"][2] != ""
    assert rows["jacket.m_grav_t"][3] == "t"
    assert "routes.<route>.legs[].duration_h" in rows


def test_a_renamed_key_fails(ref):
    schema = yaml.safe_load((ROOT / "jls/schemas/config.schema.yaml").read_text())
    page = ref.configuration_page(schema)
    # the reference of a schema without `jacket.z_p_m` no longer documents it
    del schema["properties"]["jacket"]["properties"]["z_p_m"]
    assert "z_p_m" in _documented_keys(page)
    assert "z_p_m" not in _documented_keys(ref.configuration_page(schema))


def test_every_dataset_variable_and_coordinate_is_in_the_dataset_reference(ref):
    registry = yaml.safe_load((ROOT / "jls/schemas/datasets.yaml").read_text())
    page = ref.datasets_page(registry)
    sections = dict(re.findall(r"^## `([^`]+)`\n(.*?)(?=^## |\Z)", page, flags=re.M | re.S))
    assert set(sections) == set(registry)
    for name, spec in registry.items():
        names = set(spec.get("variables", {})) | set(spec.get("coordinates", {}))
        documented = set(re.findall(r"^\| `([^`]+)`", sections[name], flags=re.M))
        missing = sorted(names - documented)
        assert not missing, f"{name}: variables missing from docs reference/datasets.md: {missing}"
        for var, v in spec.get("variables", {}).items():
            row = re.search(rf"^\| `{re.escape(var)}`.*$", sections[name], flags=re.M).group(0)
            assert ", ".join(v.get("dims", [])) in row
            assert v.get("units", v.get("units_from", "")) in row


def test_every_command_and_option_is_in_the_command_reference(ref):
    from jls.cli import build_parser
    page = ref.cli_page()
    parser = build_parser()
    commands = ref._subcommands(parser)
    assert {"modes", "check", "verify", "spectrum"} <= set(commands)
    for name, sub in commands.items():
        assert f"## `jls {name}`" in page
        for action in sub._actions:
            for opt in action.option_strings:
                assert opt in page, f"jls {name} {opt} missing from docs reference/cli.md"


def test_the_navigation_names_existing_pages():
    config = yaml.safe_load((ROOT / "mkdocs.yml").read_text())
    generated = set(_generator().PAGES)

    def pages(nav):
        for item in nav:
            value = next(iter(item.values())) if isinstance(item, dict) else item
            if isinstance(value, list):
                yield from pages(value)
            else:
                yield value

    listed = list(pages(config["nav"]))
    for page in listed:
        assert page in generated or (ROOT / "docs" / page).is_file(), page
    written = {str(p.relative_to(ROOT / "docs")) for p in (ROOT / "docs").rglob("*.md")}
    assert written <= set(listed), f"pages outside the navigation: {sorted(written - set(listed))}"


def test_the_built_site_holds_every_key_and_variable():
    """The site as `mkdocs build --strict` wrote it (CI builds it before the tests run)."""
    site = ROOT / "site" / "reference"
    if not (site / "configuration" / "index.html").is_file():
        pytest.skip("the documentation site is not built here (mkdocs build --strict; CI builds it)")
    schema = yaml.safe_load((ROOT / "jls/schemas/config.schema.yaml").read_text())
    html = (site / "configuration" / "index.html").read_text(encoding="utf-8")
    keys = _schema_keys(schema, set()) - {"$schema"}
    missing = sorted(k for k in keys if f"{k}</code>" not in html and f".{k}" not in html)
    assert not missing, f"schema keys missing from the built site: {missing}"
    registry = yaml.safe_load((ROOT / "jls/schemas/datasets.yaml").read_text())
    html = (site / "datasets" / "index.html").read_text(encoding="utf-8")
    for name, spec in registry.items():
        for var in list(spec.get("variables", {})) + list(spec.get("coordinates", {})):
            assert f"<code>{var}</code>" in html, f"{name}.{var} missing from the built site"
