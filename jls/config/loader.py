"""Configuration: load YAML, validate against the JSON Schema, check the physics.

All user errors surface as :class:`jls.errors.InputError` naming the file, the key
path and the value.
"""

from __future__ import annotations

import copy
import math

from jls.config import headings
from jls.config.builders import design_grid_points, rigging_from_config
from jls.config.cross_checks import check_values
from jls.config.plausible import check_config, check_hinge_sign
from jls.design.screening import screened_axes
from jls.errors import InputError
from jls.io import yamlio
from jls.io.schema import schema


def load_yaml(path) -> dict:
    """A configuration file as a mapping (:func:`jls.io.yamlio.load`: UTF-8, no duplicate
    keys, no tabs, bounded aliases, no YTE templates); InputError naming file and line."""
    return yamlio.load(path, refuse_yte=True, what="configuration")




def _where(error) -> str:
    """Dotted path of a jsonschema.ValidationError in the configuration."""
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


def fill_defaults(cfg, sch=None, root=None):
    """Fill the schema's ``default`` values into ``cfg`` in place, recursively.

    Walks ``properties`` (absent keys take a copy of their default, then objects are
    descended), ``additionalProperties`` schemas of maps (e.g. routes) and ``items`` of
    arrays. Defaults live in the schema only; nothing downstream supplies its own.
    """
    root = schema() if root is None else root
    sch = root if sch is None else sch
    if "$ref" in sch:
        sch = _resolve(root, sch["$ref"])
    if isinstance(cfg, dict):
        for key, sub in sch.get("properties", {}).items():
            if "$ref" in sub:
                sub = {**_resolve(root, sub["$ref"]), **{k: v for k, v in sub.items() if k != "$ref"}}
            if key not in cfg and "default" in sub:
                cfg[key] = copy.deepcopy(sub["default"])
            if key in cfg:
                fill_defaults(cfg[key], sub, root)
        extra = sch.get("additionalProperties")
        if isinstance(extra, dict):
            for key, value in cfg.items():
                if key not in sch.get("properties", {}):
                    fill_defaults(value, extra, root)
    elif isinstance(cfg, list) and isinstance(sch.get("items"), dict):
        for item in cfg:
            fill_defaults(item, sch["items"], root)
    return cfg


def _resolve(root, ref):
    node = root
    for part in ref.removeprefix("#/").split("/"):
        node = node[part]
    return node


def validate(cfg, source="config", origin=None, base_dir=".") -> dict:
    """Validate a configuration mapping; returns it with schema defaults filled in and
    every leg's relative headings resolved (:func:`jls.config.headings.resolve`: a leg giving
    the vessel's course gets the ``headings_deg`` and ``heading_probability`` it meets).

    ``source`` names the file in messages; ``origin``, when given, maps a key path to
    the file that set it (see :func:`load`), so an error names the file the bad value
    came from. ``base_dir``: the folder relative paths are taken from (read only for
    legs whose headings come from a course).
    """
    if not isinstance(cfg, dict):
        raise InputError("the configuration must be a mapping of keys", file=source)
    try:
        _validate(cfg, source, origin, base_dir)
    except InputError as exc:
        # an error of a data file read here (a leg's table, the RAO file) keeps its file
        # and line; one of the configuration names the file that set the key
        if origin is not None and exc.field and exc.file in (None, source):
            raise InputError(exc.message, file=origin(exc.field), field=exc.field,
                             value=exc.value) from None
        if origin is not None and exc.file is not None:
            raise InputError(_given_in(exc.message, origin), file=exc.file, field=exc.field,
                             value=exc.value) from None
        raise
    return cfg


def _given_in(message: str, origin) -> str:
    """``message`` with the configuration file named beside each key that gives a data
    file ("the file given by routes.r.legs[0].spectra.file" + " in case.yaml")."""
    import re

    def named(m):
        return f"{m.group(0)} in {origin(m.group(1))}"
    return re.sub(r"the file given by (routes\.[\w.\[\]-]+|vessel\.rao_file)(?! in )", named, message)


def _first_nontext_key(obj, path=""):
    """(path, key) of the first mapping key that is not text (a route named 2024 or NO as
    YAML 1.1 reads them, or a mapping built in Python)."""
    if isinstance(obj, dict):
        for k, v in obj.items():
            if not isinstance(k, str):
                return path or "(top level)", k
            found = _first_nontext_key(v, f"{path}.{k}" if path else k)
            if found:
                return found
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            found = _first_nontext_key(v, f"{path}[{i}]")
            if found:
                return found
    return None


def _validate(cfg, source, origin, base_dir):
    key = _first_nontext_key(cfg)
    if key:
        kind = {bool: "a boolean", int: "a number", float: "a number"}.get(type(key[1]), "not text")
        raise InputError(f"the key {key[1]!r} is {kind}, not text; keys (route "
                         "and leg names among them) must be text: quote it", file=source,
                         field=key[0], value=key[1])
    bad = _first_nonfinite(cfg)
    if bad:
        raise InputError("must be a finite number", file=source, field=bad[0], value=bad[1])
    import jsonschema  # only where validated: fast start-up of every job

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
    _select_routes(cfg, source)
    _check_heading_input(cfg, source)
    fill_defaults(cfg)
    hinge_height(cfg, source)
    _check_geometry(cfg, source)
    headings.resolve(cfg, base_dir, source)


def _select_routes(cfg, source):
    """Keep only the routes ``run_routes`` names, in its order (absent: every route), so
    that the run, its checks and ``jls check`` see those alone."""
    chosen = cfg.get("run_routes")
    if chosen is None:
        return
    chosen = [chosen] if isinstance(chosen, str) else list(chosen)
    routes = cfg.get("routes", {})
    for name in chosen:
        if name not in routes:
            raise InputError(f"names a route that is not in the configuration (routes: "
                             f"{', '.join(routes)})", file=source, field="run_routes", value=name)
    cfg["routes"] = {name: routes[name] for name in chosen}


def _check_heading_input(cfg, source):
    """Before defaults are filled: a leg's heading keys are consistent, and a leg
    without a course records whether its headings were given or are the default."""
    for route, spec in cfg["routes"].items():
        for i, leg in enumerate(spec["legs"]):
            try:
                headings.check_leg(leg, f"routes.{route}.legs[{i}]")
            except InputError as exc:
                raise InputError(exc.message, file=source, field=exc.field, value=exc.value) from None
            if "course_deg" not in leg and "waypoints" not in leg and leg.get("heading_source") not in (
                    "given", "default"):
                leg["heading_source"] = "given" if "headings_deg" in leg else "default"


#: Largest disagreement between a given rigging.limits.hinge_height_m and the vessel's [m].
HINGE_HEIGHT_TOLERANCE_M = 0.01


def bem_reference_height(vessel: dict):
    """Height above the waterline of the point RAOs computed by ``vessel.bem`` refer to
    (the hull's CoG; the mesh frame has z = 0 at the waterline), or None without bem."""
    bem = vessel.get("bem")
    if not bem:
        return None
    if "box" in bem:
        return float(bem["box"]["kg_m"]) - float(bem["box"]["draught_m"])
    return float(bem["mesh"]["center_of_mass_m"][2])


def hinge_height(cfg, source="config") -> float:
    """One geometry: the hinge's height above the water, from the vessel block.

    ``vessel.rao_reference_point_height_m`` (or, with ``vessel.bem``, the computed hull's
    CoG height) places the waterline in the frame of ``vessel.hinge_m``, so the hinge
    sits ``hinge_m z - rao_reference_point_m z + rao_reference_point_height_m`` above the
    water. That value is written to ``rigging.limits.hinge_height_m`` (the splash
    clearance's) and the height of the reference point to the vessel block. A
    configuration that also gives ``rigging.limits.hinge_height_m`` must agree within
    :data:`HINGE_HEIGHT_TOLERANCE_M`; one that gives only that key has its waterline
    derived from it; one that gives neither is an error.
    """
    vessel, limits = cfg.setdefault("vessel", {}), cfg["rigging"]["limits"]
    check_hinge_sign(vessel, source)
    hinge_z = float(vessel["hinge_m"][2]) - float(vessel["rao_reference_point_m"][2])
    given = vessel.get("rao_reference_point_height_m")
    # with rao_file and bem both, the file's height stands until the pipeline's input
    # checks refuse the pair ("give rao_file or bem, not both")
    computed = bem_reference_height(vessel) if "rao_file" not in vessel else None
    if computed is not None and given is not None and abs(float(given) - computed) > HINGE_HEIGHT_TOLERANCE_M:
        raise InputError(f"the RAOs computed by vessel.bem refer to the hull's CoG, {computed:g} m "
                         "above the waterline; give the height once (leave "
                         "rao_reference_point_height_m out with bem)", file=source,
                         field="vessel.rao_reference_point_height_m", value=given)
    height = computed if computed is not None else given
    if height is None:
        if "hinge_height_m" not in limits:
            raise InputError("required key is missing: the height of the RAO reference point "
                             "above the waterline, which places the hinge above the water "
                             "(the lever arm and the splash clearance)", file=source,
                             field="vessel.rao_reference_point_height_m")
        vessel["rao_reference_point_height_m"] = float(limits["hinge_height_m"]) - hinge_z
        return float(limits["hinge_height_m"])
    derived = hinge_z + float(height)
    if not derived >= 1.0:
        raise InputError(f"the hinge would sit {derived:.3f} m above the water (less than 1 m): "
                         "check the sign of rao_reference_point_height_m (height ABOVE the "
                         "waterline, negative below it) and of hinge_m z", file=source,
                         field="vessel.rao_reference_point_height_m", value=height)
    if "hinge_height_m" in limits and abs(float(limits["hinge_height_m"]) - derived) > HINGE_HEIGHT_TOLERANCE_M:
        raise InputError(f"the hinge height above water is given twice and the two disagree: "
                         f"the vessel block puts the hinge {derived:.3f} m above the water "
                         f"(hinge_m z {float(vessel['hinge_m'][2]):g} - rao_reference_point_m z "
                         f"{float(vessel['rao_reference_point_m'][2]):g} + rao_reference_point_height_m "
                         f"{float(height):g}); give it once, in the vessel block", file=source,
                         field="rigging.limits.hinge_height_m", value=limits["hinge_height_m"])
    vessel["rao_reference_point_height_m"] = float(height)
    limits["hinge_height_m"] = derived
    return derived


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
    tugs = [t["name"] for t in cfg["tuggers"]]
    if len(set(tugs)) != len(tugs):
        raise InputError("tugger names must be unique", file=source, field="tuggers", value=tugs)
    for route, spec in cfg["routes"].items():
        names = [leg["name"] for leg in spec["legs"]]
        if len(set(names)) != len(names):
            raise InputError("leg names must be unique", file=source, field=f"routes.{route}.legs",
                             value=names)
        for i, leg in enumerate(spec["legs"]):
            n, hp = len(leg["headings_deg"]), leg["heading_probability"]
            if len(hp) != n or abs(sum(hp) - 1.0) > 1e-6:
                raise InputError("heading_probability needs one value per heading, summing to 1",
                                 file=source, field=f"routes.{route}.legs[{i}].heading_probability",
                                 value=hp)
    for key, spec in rig["design_space"].items():
        lo, hi = spec["bounds"] if isinstance(spec, dict) else spec
        if not lo < hi:
            raise InputError("lower bound must be below the upper bound", file=source,
                             field=f"rigging.design_space.{key}", value=[lo, hi])
    scr = cfg["screening"]
    env = scr["envelope"]
    if env["tz_min_s"] > env["tz_max_s"]:
        raise InputError("tz_min_s must not exceed tz_max_s", file=source,
                         field="screening.envelope", value=env)
    if "tugger" in scr and scr["tugger"] not in tugs:
        raise InputError(f"not a configured tugger (tuggers: {tugs})", file=source,
                         field="screening.tugger", value=scr["tugger"])
    try:
        screened_axes(rigging_from_config(cfg), design_grid_points(scr["grid_points"]))
    except InputError as exc:
        raise InputError(exc.message, file=source, field=exc.field) from None


def merge(base: dict, over: dict) -> dict:
    """Merge ``over`` into ``base`` in place as ``snakemake --configfile`` does: mappings
    are merged key by key, every other value (lists included) replaces."""
    for key, value in over.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            merge(base[key], value)
        else:
            base[key] = copy.deepcopy(value)
    return base


def _keys(field: str) -> list[str]:
    """'routes.default.legs[0].scatter' -> ['routes', 'default', 'legs'] (mapping keys up
    to the first list index: a list is replaced whole by the file that sets it)."""
    keys = []
    for part in field.split("."):
        keys.append(part.split("[", 1)[0])
        if "[" in part:
            break
    return [k for k in keys if k]


def origin_finder(layers):
    """A function mapping a key path to the file that set it, for (name, mapping) layers
    merged in order: the last layer holding the deepest part of the path."""
    def origin(field: str) -> str:
        keys = _keys(field)
        best, depth = layers[-1][0], -1
        for name, data in layers:
            node, d = data, 0
            for k in keys:
                if not isinstance(node, dict) or k not in node:
                    break
                node, d = node[k], d + 1
            if d >= depth and d > 0:
                best, depth = name, d
        return best
    return origin


def load_layers(paths) -> tuple[dict, object]:
    """Read configuration files and merge them in order; returns (config, origin)."""
    layers = []
    for path in paths:
        layers.append((str(path), load_yaml(path)))
    cfg = {}
    for _, data in layers:
        merge(cfg, data)
    return cfg, origin_finder(layers)


def load(*paths) -> dict:
    """Load configuration files (later ones merged over earlier ones, as
    ``snakemake --configfile``) and validate the result; an error names the file that
    set the bad value."""
    from jls.config.hull_checks import own_hull
    layers = [(str(path), load_yaml(path)) for path in paths]
    cfg, origin = {}, origin_finder(layers)
    for _, data in layers:
        merge(cfg, data)
    source = " + ".join(str(p) for p in paths)
    cfg = validate(cfg, source=source, origin=origin)
    own_hull(cfg, layers)                    # the hull of the vessel whose RAOs are read
    try:
        check_config(cfg, source=source)
        check_values(cfg, source=source)
    except InputError as exc:
        raise InputError(exc.message, file=origin(exc.field) if exc.field else source,
                         field=exc.field, value=exc.value) from None
    return cfg


