"""Configuration: load YAML, validate against the JSON Schema, check the physics.

All user errors surface as :class:`jls.errors.InputError` naming the file, the key
path and the value.
"""

from __future__ import annotations

import hashlib
import json
import math
from importlib import resources
from pathlib import Path

import jsonschema
import numpy as np

from jls import yamlio
from jls.errors import InputError
from jls.plausible import check_config

SCHEMA_FILE = "config.schema.yaml"


def load_yaml(path) -> dict:
    """A configuration file as a mapping (:func:`jls.yamlio.load`: UTF-8, no duplicate
    keys, no tabs, bounded aliases, no YTE templates); InputError naming file and line."""
    return yamlio.load(path, refuse_yte=True, what="configuration")


def schema() -> dict:
    text = resources.files("jls.schemas").joinpath(SCHEMA_FILE).read_text()
    return yamlio.loads(text, source=SCHEMA_FILE)


def _where(error: jsonschema.ValidationError) -> str:
    parts = []
    for p in error.absolute_path:
        parts.append(f"[{p}]" if isinstance(p, int) else (("." if parts else "") + str(p)))
    return "".join(parts) or "(top level)"


def _first_nonfinite(obj, path=""):
    if isinstance(obj, float) and not math.isfinite(obj):
        return path, obj
    if isinstance(obj, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in obj.items())
    elif isinstance(obj, list):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(obj))
    else:
        return None
    for p, v in items:
        found = _first_nonfinite(v, p)
        if found:
            return found
    return None


def validate(cfg, source="config") -> dict:
    """Validate a configuration mapping; returns it with schema defaults filled in."""
    if not isinstance(cfg, dict):
        raise InputError("the configuration must be a mapping of keys", file=source)
    bad = _first_nonfinite(cfg)
    if bad:
        raise InputError("must be a finite number", file=source, field=bad[0], value=bad[1])
    validator = jsonschema.Draft202012Validator(schema())
    errors = sorted(validator.iter_errors(cfg), key=lambda e: (len(e.absolute_path), e.path))
    if errors:
        err = errors[0]
        if err.validator == "oneOf" and err.context:
            err = min(err.context, key=lambda e: len(e.absolute_path))
        if err.validator == "required":
            missing = err.message.split("'")[1]
            field = f"{_where(err)}.{missing}" if err.absolute_path else missing
            raise InputError("required key is missing", file=source, field=field)
        if err.validator == "additionalProperties":
            raise InputError(f"unknown key: {err.message}", file=source, field=_where(err))
        raise InputError(err.message, file=source, field=_where(err), value=err.instance)
    _check_geometry(cfg, source)
    return cfg


def _check_geometry(cfg, source):
    rig, jacket = cfg["rigging"], cfg["jacket"]
    cog_depth = rig["h_drop_m"] + jacket["z_p_m"]
    names = [w["name"] for w in rig["wires"]]
    if len(set(names)) != len(names):
        raise InputError("wire names must be unique", file=source, field="rigging.wires", value=names)
    for i, w in enumerate(rig["wires"]):
        anchor_z = w["anchor_m"][2]
        padeye_z = w["padeye_m"][2] - cog_depth
        if padeye_z >= anchor_z:
            raise InputError(f"padeye of wire '{w['name']}' is not below its anchor "
                             f"(padeye at z = {padeye_z:.3f} m, anchor at z = {anchor_z:.3f} m "
                             "in the hinge frame)", file=source,
                             field=f"rigging.wires[{i}].padeye_m", value=w["padeye_m"])
    cands = [c["name"] for c in cfg.get("candidates", [])]
    if len(set(cands)) != len(cands):
        raise InputError("candidate names must be unique", file=source, field="candidates", value=cands)
    tugs = [t["name"] for t in cfg.get("tuggers", [])]
    if len(set(tugs)) != len(tugs):
        raise InputError("tugger names must be unique", file=source, field="tuggers", value=tugs)
    for route, spec in cfg.get("routes", {}).items():
        names = [leg["name"] for leg in spec["legs"]]
        if len(set(names)) != len(names):
            raise InputError("leg names must be unique", file=source, field=f"routes.{route}.legs",
                             value=names)
        for i, leg in enumerate(spec["legs"]):
            n = len(leg.get("headings_deg", [90.0]))
            hp = leg.get("heading_probability", [1.0 / n] * n if "headings_deg" not in leg else None)
            if hp is None and n == 1:
                continue
            if hp is None or len(hp) != n or abs(sum(hp) - 1.0) > 1e-6:
                raise InputError("heading_probability needs one value per heading, summing to 1",
                                 file=source, field=f"routes.{route}.legs[{i}].heading_probability",
                                 value=hp)
    for key, (lo, hi) in rig.get("design_space", {}).items():
        if not lo < hi:
            raise InputError("lower bound must be below the upper bound", file=source,
                             field=f"rigging.design_space.{key}", value=[lo, hi])


def load(path) -> dict:
    """Load and validate a configuration file."""
    cfg = validate(load_yaml(path), source=str(path))
    check_config(cfg, source=str(path))
    return cfg


def config_hash(cfg) -> str:
    """Stable SHA-256 of a configuration mapping (sorted JSON)."""
    text = json.dumps(cfg, sort_keys=True, default=lambda o: np.asarray(o).tolist())
    return hashlib.sha256(text.encode()).hexdigest()


def file_sha256(path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()
