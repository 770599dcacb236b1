"""Reader for the displacement RAOs of an OrcaFlex vessel type (text data file, YAML).

The file is an OrcaFlex model saved as text (``.yml``): a ``VesselTypes`` list, each
vessel type with its convention settings and ``Draughts``, each draught with
``DisplacementRAOs``::

    General: {UnitsSystem: SI}                 # optional; SI or LengthUnits m only
    VesselTypes:
      - Name: HLV
        WavesReferredToBy: period (s)          # or frequency (rad/s), frequency (Hz)
        RAOResponseUnits: degrees              # rotations per unit amplitude: degrees|radians
        RAOWaveUnit: amplitude                 # per wave amplitude (the only one read)
        RAOPhaseConvention: lags               # lags|leads
        RAOPhaseUnitsConvention: degrees       # degrees|radians
        RAOPhaseRelativeToConvention: crest    # crest|trough|zero up-crossing|zero down-crossing
        SurgePositive: forward                 # and SwayPositive port, HeavePositive up,
        ...                                    # RollPositiveStarboard down, PitchPositiveBow
        Symmetry: None                         # down, YawPositiveBow port; None|xz plane|
        Draughts:                              # yz plane|xz and yz planes
          - Name: Operating
            DisplacementRAOs:
              RAOOrigin: [x, y, z]             # vessel axes, m
              PhaseOrigin: [~, ~, ~]           # ~: the RAO origin
              RAOs:
                - RAODirection: 180
                  RAOPeriodOrFrequency, RAOSurgeAmp, RAOSurgePhase, ..., RAOYawPhase:
                    - [period or frequency, amp, phase, ... (13 numbers)]

Conversion to the jls convention (:mod:`jls.vessel.rao`), each stated once:

* frame: OrcaFlex vessel axes are x forward, y to port, z up, the jls frame; a motion
  whose ``...Positive`` setting is the other way (surge aft, sway starboard, heave down,
  roll starboard up, pitch bow up, yaw bow to starboard) changes sign;
* direction: ``RAODirection`` [deg] is the direction the waves travel, measured
  anticlockwise (seen from above) from the vessel x axis (0 = waves from astern, 90 =
  travelling to port): the jls ``wave_direction``, wrapped into [0, 360) deg (-90 is 270)
  and converted to rad;
* abscissa: ``WavesReferredToBy`` period [s] -> omega = 2 pi / T, frequency [rad/s] as
  is, frequency [Hz] -> 2 pi f; the rows of period 0 or frequency Infinity (infinite
  frequency) and of period Infinity or frequency 0 carry no motion and are skipped
  (counted in ``orcaflex_limit_rows_skipped``);
* amplitude: translations m/m (OrcaFlex's are always per unit amplitude); rotations per
  unit wave amplitude in ``RAOResponseUnits`` (degrees -> x pi/180); the rotation per
  maximum wave slope or per wave steepness (``RAOWaveUnit``) is refused (it needs the
  wave number, hence the water depth, which a vessel type does not hold); a length unit
  other than m (``General.LengthUnits``, ``UnitsSystem`` US) is refused;
* phase: ``RAOPhaseConvention`` lags (motion = |R| A cos(wt - phase)) are conjugated
  into jls leads; phases in ``RAOPhaseUnitsConvention`` radians are taken as such; a
  phase relative to the trough, the zero down-crossing or the zero up-crossing
  (``RAOPhaseRelativeToConvention``) is referred to the crest (a lag grows by 180, 90 and
  270 deg); the phases are relative to the crest at ``PhaseOrigin``, which must lie on
  the RAO origin's vertical (``~`` takes the RAO origin); another phase origin is refused;
* reference point: ``RAOOrigin`` (vessel axes; [0, 0, 0] when left out) is
  ``reference_point_m``; the configuration's ``hinge_m - rao_reference_point_m`` is the
  lever arm from it (with ``hinge_m`` in vessel axes, ``rao_reference_point_m`` is the
  RAO origin);
* symmetry: ``xz plane`` adds the mirror image of every direction not given
  (beta -> -beta; sway, roll and yaw change sign), ``yz plane`` the fore-and-aft image
  (beta -> 180 - beta; surge, pitch and yaw change sign), ``xz and yz planes`` both;
  ``circular`` is refused. ``None`` keeps the directions given.

A convention key the vessel type omits is taken as the value OrcaFlex writes for a new
vessel type (:data:`ORCAFLEX_DEFAULTS`; the OrcaFlex 11.5b file of the tests shows them),
except ``Symmetry``, taken as None (no direction is added that the file does not give),
and named in ``orcaflex_defaults_taken``; never the phase convention: a file without
``RAOPhaseConvention`` needs ``vessel.rao_conventions.phase`` (jls never guesses one). The direction convention and the x axis are
OrcaFlex's own (``to``, ``forward``); ``vessel.rao_conventions`` may restate them, not
contradict them.

Refused, naming the key: no ``VesselTypes``, several vessel types or draughts without a
choice (``vessel.orcaflex_vessel_type``, ``vessel.orcaflex_draught``), a draught with load
RAOs only, a missing column (a DOF missing), a row of the wrong length, a non-number,
a negative amplitude, a duplicate period or direction, an incomplete grid.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr
import yaml

from jls.errors import InputError
from jls.io.files import MAX_RAO_TEXT_BYTES, read_bytes
from jls.vessel.conventions import resolve_conventions, to_jls
from jls.vessel.rao import DOFS, rao_from_records

#: The settings OrcaFlex writes for a new vessel type (Symmetry: none added), used for a
#: key the file omits.
ORCAFLEX_DEFAULTS = {
    "WavesReferredToBy": "period (s)", "RAOResponseUnits": "degrees",
    "RAOWaveUnit": "amplitude", "RAOPhaseUnitsConvention": "degrees",
    "RAOPhaseRelativeToConvention": "crest", "SurgePositive": "forward",
    "SwayPositive": "port", "HeavePositive": "up", "RollPositiveStarboard": "down",
    "PitchPositiveBow": "down", "YawPositiveBow": "port", "Symmetry": "None",
}
SIGN_KEYS = {   # key: (dof index, {setting: sign against the jls frame})
    "SurgePositive": (0, {"forward": 1.0, "aft": -1.0, "backward": -1.0}),
    "SwayPositive": (1, {"port": 1.0, "starboard": -1.0}),
    "HeavePositive": (2, {"up": 1.0, "down": -1.0}),
    "RollPositiveStarboard": (3, {"down": 1.0, "up": -1.0}),
    "PitchPositiveBow": (4, {"down": 1.0, "up": -1.0}),
    "YawPositiveBow": (5, {"port": 1.0, "starboard": -1.0}),
}
ABSCISSA = ("period (s)", "frequency (rad/s)", "frequency (Hz)")
PHASE_REFERENCE_LAG_DEG = {"crest": 0.0, "trough": 180.0, "zero down-crossing": 90.0,
                           "zero up-crossing": 270.0}
SYMMETRY = ("None", "xz plane", "yz plane", "xz and yz planes")
COLUMNS = ["RAOPeriodOrFrequency"] + [f"RAO{d.capitalize()}{part}" for d in DOFS
                                      for part in ("Amp", "Phase")]
TABLE_KEY = ", ".join(COLUMNS)
_REFLECT = {"xz": (lambda b: -b, np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])),
            "yz": (lambda b: 180.0 - b, np.array([-1.0, 1.0, 1.0, 1.0, -1.0, -1.0]))}


class _Map(dict):
    line = 0
    key_lines: dict = {}


class _Seq(list):
    line = 0


class _Loader(yaml.SafeLoader):
    """Safe YAML with the line of every mapping, key and list kept for the messages."""


def _map(loader, node):
    loader.flatten_mapping(node)
    out = _Map()
    out.line = node.start_mark.line + 1
    out.key_lines = {}
    for key_node, value_node in node.value:
        key = loader.construct_object(key_node, deep=True)
        if key in out:
            raise yaml.constructor.ConstructorError(None, None, f"key given twice: {key}",
                                                    key_node.start_mark)
        out[key] = loader.construct_object(value_node, deep=True)
        out.key_lines[key] = key_node.start_mark.line + 1
    return out


def _seq(loader, node):
    out = _Seq(loader.construct_object(child, deep=True) for child in node.value)
    out.line = node.start_mark.line + 1
    return out


_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _map)
_Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_SEQUENCE_TAG, _seq)


def load_yaml(path):
    """The one YAML document of an OrcaFlex text data file, with line numbers."""
    raw = read_bytes(path, "OrcaFlex file", MAX_RAO_TEXT_BYTES)
    try:
        docs = [d for d in yaml.load_all(raw.decode("utf-8-sig"), Loader=_Loader) if d is not None]
    except UnicodeDecodeError as exc:
        raise InputError(f"cannot read file: {exc}", file=path) from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f"line {mark.line + 1}" if mark is not None else None
        raise InputError(f"not valid YAML: {getattr(exc, 'problem', None) or exc}", file=path,
                         field=where) from None
    if len(docs) != 1 or not isinstance(docs[0], dict):
        raise InputError("expected one YAML document holding a mapping (an OrcaFlex text data "
                         "file)", file=path, value=len(docs))
    return docs[0]


def _at(mapping, key) -> str:
    line = getattr(mapping, "key_lines", {}).get(key) or getattr(mapping, "line", 0)
    return f"line {line}" if line else ""


def _named(items, name, what, field, path, where):
    """The item of ``items`` (a list of mappings with ``Name``) called ``name``; the only
    one when ``name`` is None."""
    if not isinstance(items, list) or not items or not all(isinstance(i, dict) for i in items):
        raise InputError(f"{where} must be a non-empty list of {what}s", file=path, field=where)
    names = [str(i.get("Name", "")) for i in items]
    if name is None:
        if len(items) > 1:
            raise InputError(f"the file holds {len(items)} {what}s; choose one with {field}",
                             file=path, field=field, value=names)
        return items[0], names[0]
    if str(name) not in names:
        raise InputError(f"no {what} of that name in {where} (available: {names})", file=path,
                         field=field, value=name)
    return items[names.index(str(name))], str(name)


def read_orcaflex_vessel_type(path, *, vessel_type: str | None = None, draught: str | None = None,
                              conventions: dict | None = None) -> xr.Dataset:
    """Read the displacement RAOs of one vessel type and draught into the jls layout.

    vessel_type, draught: the ``Name`` of each (needed when the file holds several).
    conventions: the configuration's ``vessel.rao_conventions`` (see the module docstring).
    """
    path = Path(path)
    doc = load_yaml(path)
    general = doc.get("General") if isinstance(doc.get("General"), dict) else {}
    units, length = general.get("UnitsSystem", "SI"), general.get("LengthUnits", "m")
    if units not in ("SI", "User") or length != "m":
        key = "LengthUnits" if "LengthUnits" in general else "UnitsSystem"
        raise InputError("only lengths in m are read (UnitsSystem SI, or LengthUnits m): a "
                         "rotation RAO per ft is not per m", file=path,
                         field=f"General.{key} ({_at(general, key)})", value=general.get(key, units))
    if "VesselTypes" not in doc:
        raise InputError("no VesselTypes list: not an OrcaFlex model saved as text", file=path,
                         field="VesselTypes")
    vt, vt_name = _named(doc["VesselTypes"], vessel_type, "vessel type",
                         "vessel.orcaflex_vessel_type", path, "VesselTypes")
    where_vt = f"VesselTypes[{vt_name}]"
    settings = {key: str(vt.get(key, default)) for key, default in ORCAFLEX_DEFAULTS.items()}
    defaults = [key for key in ORCAFLEX_DEFAULTS if key not in vt]
    phase_stated = vt.get("RAOPhaseConvention")
    if phase_stated is not None and phase_stated not in ("lags", "leads"):
        raise InputError("RAOPhaseConvention must be lags or leads", file=path,
                         field=f"{where_vt}.RAOPhaseConvention ({_at(vt, 'RAOPhaseConvention')})",
                         value=phase_stated)
    conv = resolve_conventions(
        {"phase": {"lags": "lag", "leads": "lead"}.get(phase_stated),
         "phase_source": f"RAOPhaseConvention: {phase_stated}",
         "direction": "to", "direction_source": "OrcaFlex's RAODirection: where the waves travel",
         "x_axis": "forward", "x_axis_source": "OrcaFlex's vessel x axis points to the bow"},
        conventions, file=path)
    allowed = {"WavesReferredToBy": ABSCISSA, "RAOResponseUnits": ("degrees", "radians"),
               "RAOWaveUnit": ("amplitude",), "RAOPhaseUnitsConvention": ("degrees", "radians"),
               "RAOPhaseRelativeToConvention": tuple(PHASE_REFERENCE_LAG_DEG), "Symmetry": SYMMETRY}
    allowed.update({k: tuple(v[1]) for k, v in SIGN_KEYS.items()})
    for key, values in allowed.items():
        if settings[key] not in values:
            raise InputError(f"{key} '{settings[key]}' is not one jls reads ({list(values)})",
                             file=path, field=f"{where_vt}.{key} ({_at(vt, key)})",
                             value=settings[key])
    dr, dr_name = _named(vt.get("Draughts"), draught, "draught", "vessel.orcaflex_draught", path,
                         f"{where_vt}.Draughts")
    where = f"{where_vt}.Draughts[{dr_name}].DisplacementRAOs"
    disp = dr.get("DisplacementRAOs")
    if not isinstance(disp, dict) or not disp.get("RAOs"):
        what = ("load RAOs only (LoadRAOs): jls needs the motions, the displacement RAOs"
                if dr.get("LoadRAOs") else "no displacement RAOs")
        raise InputError(f"the draught has {what}", file=path,
                         field=f"{where} ({_at(dr, 'DisplacementRAOs') or _at(dr, 'Name')})")
    origin = _vector(disp.get("RAOOrigin", [0.0, 0.0, 0.0]), path, f"{where}.RAOOrigin", disp)
    defaults += [] if "RAOOrigin" in disp else ["RAOOrigin"]
    phase_origin = disp.get("PhaseOrigin", [None, None, None])
    if not isinstance(phase_origin, list) or len(phase_origin) != 3:
        raise InputError("PhaseOrigin must be three numbers or ~", file=path,
                         field=f"{where}.PhaseOrigin ({_at(disp, 'PhaseOrigin')})", value=phase_origin)
    po = _vector([origin[i] if v is None else v for i, v in enumerate(phase_origin)], path,
                 f"{where}.PhaseOrigin", disp)
    if abs(po[0] - origin[0]) > 1e-9 or abs(po[1] - origin[1]) > 1e-9:
        raise InputError(f"the phases refer to the crest at PhaseOrigin {po}, away from the RAO "
                         f"origin {origin}; jls reads phases on the RAO origin's vertical only "
                         "(set PhaseOrigin to ~ or the RAO origin in OrcaFlex and export again)",
                         file=path, field=f"{where}.PhaseOrigin ({_at(disp, 'PhaseOrigin')})",
                         value=phase_origin)
    omega, beta, values, lines, skipped = _tables(disp["RAOs"], settings, path, f"{where}.RAOs",
                                                  lag=conv["phase"] == "lag")
    omega, beta, values, lines = _symmetry(settings["Symmetry"], omega, beta, values, lines)
    values, beta = to_jls(values, beta, conv)
    n = omega.size
    attrs = {"orcaflex_vessel_type": vt_name, "orcaflex_draught": dr_name,
             "orcaflex_settings": "; ".join(f"{k}: {v}" for k, v in settings.items()),
             "orcaflex_defaults_taken": ", ".join(defaults) or "none",
             "orcaflex_phase_origin_m": [float(v) for v in po],
             "orcaflex_limit_rows_skipped": int(skipped),
             "rao_conventions": "; ".join(f"{k}: {v}" for k, v in conv.items())}
    return rao_from_records(np.repeat(omega, 6), np.radians(np.repeat(beta, 6)),
                            np.tile(np.arange(6), n), values.reshape(-1), np.repeat(lines, 6),
                            file=path, reference_point_m=origin, source_format="orcaflex",
                            attrs=attrs)


def _vector(value, path, field, mapping):
    key = field.rsplit(".", 1)[-1]
    try:
        out = [float(v) for v in value]
    except (TypeError, ValueError):
        out = []
    if len(out) != 3 or not np.all(np.isfinite(out)):
        raise InputError("must be three finite numbers", file=path,
                         field=f"{field} ({_at(mapping, key)})", value=value)
    return out


def _number(value, path, field):
    if isinstance(value, str) and value.strip().lower() in ("infinity", "inf"):
        return np.inf
    try:
        out = float(value)
    except (TypeError, ValueError):
        raise InputError("not a number", file=path, field=field, value=value) from None
    if np.isnan(out):
        raise InputError("not a number", file=path, field=field, value=value)
    return out


def _tables(raos, settings, path, where, lag: bool):
    """(omega, direction [deg], values (n, 6) in the file's phase sense relative to the
    crest, jls units and signs, line numbers, rows skipped) of every direction table.
    A lag on the trough (the zero down-, up-crossing) is a lag on the crest grown by 180
    (90, 270) deg; a lead shrinks by as much."""
    if not isinstance(raos, list):
        raise InputError("must be a list of direction tables", file=path, field=where)
    rot = np.pi / 180.0 if settings["RAOResponseUnits"] == "degrees" else 1.0
    scale = np.array([1.0, 1.0, 1.0, rot, rot, rot])
    for key, (i, signs) in SIGN_KEYS.items():
        scale[i] *= signs[settings[key]]
    ph_unit = np.pi / 180.0 if settings["RAOPhaseUnitsConvention"] == "degrees" else 1.0
    offset = np.radians(PHASE_REFERENCE_LAG_DEG[settings["RAOPhaseRelativeToConvention"]])
    offset = offset if lag else -offset
    kind = settings["WavesReferredToBy"]
    omega, beta, values, lines, seen, skipped = [], [], [], [], {}, 0
    for j, table in enumerate(raos):
        here = f"{where}[{j}]"
        if not isinstance(table, dict) or "RAODirection" not in table:
            raise InputError("direction table without RAODirection", file=path,
                             field=f"{here} (line {getattr(table, 'line', 0)})")
        b = _number(table["RAODirection"], path, f"{here}.RAODirection ({_at(table, 'RAODirection')})")
        if not np.isfinite(b) or abs(b) > 360.0:
            raise InputError("RAODirection must be a direction in degrees within +-360", file=path,
                             field=f"{here}.RAODirection ({_at(table, 'RAODirection')})",
                             value=table["RAODirection"])
        wrapped = round(b % 360.0, 6)
        if wrapped in seen:
            raise InputError(f"direction {b:g} deg given twice (also at {seen[wrapped]})", file=path,
                             field=f"{here}.RAODirection ({_at(table, 'RAODirection')})", value=b)
        seen[wrapped] = _at(table, "RAODirection")
        keys = [k for k in table if isinstance(k, str) and k.replace(" ", "").startswith(
            "RAOPeriodOrFrequency")]
        if len(keys) != 1:
            raise InputError(f"direction table without its columns key ('{TABLE_KEY}')",
                             file=path, field=f"{here} ({_at(table, 'RAODirection')})")
        names = [c.strip() for c in keys[0].split(",")]
        missing = [c for c in COLUMNS if c not in names]
        if missing or len(names) != len(COLUMNS):
            raise InputError(f"the columns must be {COLUMNS} (in any order); missing "
                             f"{missing or 'none'}, given {names}", file=path,
                             field=f"{here} ({_at(table, keys[0])})", value=missing or names)
        col = [names.index(c) for c in COLUMNS]
        rows = table[keys[0]]
        if not isinstance(rows, list) or not rows:
            raise InputError("no rows", file=path, field=f"{here} ({_at(table, keys[0])})")
        for row in rows:
            at = f"{here} (line {getattr(row, 'line', 0)})"
            if not isinstance(row, list) or len(row) != len(COLUMNS):
                raise InputError(f"a row must hold {len(COLUMNS)} numbers", file=path, field=at,
                                 value=row)
            nums = np.array([_number(row[c], path, at) for c in col])
            x = nums[0]
            w = {"period (s)": 2 * np.pi / x if 0 < x < np.inf else 0.0,
                 "frequency (rad/s)": x, "frequency (Hz)": 2 * np.pi * x}[kind]
            if x < 0 or not np.all(np.isfinite(nums[1:])):
                raise InputError(f"a {kind.split()[0]} must be >= 0 and amplitudes and phases "
                                 "finite", file=path, field=at, value=row)
            if x == 0 or not np.isfinite(x) or w == 0:         # infinite or zero frequency
                skipped += 1
                continue
            amp, ph = nums[1::2], nums[2::2] * ph_unit + offset
            if np.any(amp < 0):
                raise InputError("negative RAO amplitude", file=path, field=at, value=row)
            omega.append(w)
            beta.append(b % 360.0)
            values.append(amp * scale * np.exp(1j * ph))
            lines.append(getattr(row, "line", 0))
    if not omega:
        raise InputError("no RAO rows", file=path, field=where)
    return np.array(omega), np.array(beta), np.array(values), np.array(lines), skipped


def _symmetry(symmetry, omega, beta, values, lines):
    """The directions OrcaFlex adds by symmetry, each from the row it reflects."""
    planes = {"None": (), "xz plane": ("xz",), "yz plane": ("yz",),
              "xz and yz planes": ("xz", "yz")}[symmetry]
    for plane in planes:
        turn, signs = _REFLECT[plane]
        have = {round(b % 360.0, 6) for b in beta}
        image = np.mod(turn(beta), 360.0)
        new = np.array([round(b, 6) not in have for b in image])
        omega = np.concatenate([omega, omega[new]])
        beta = np.concatenate([beta, image[new]])
        values = np.concatenate([values, values[new] * signs])
        lines = np.concatenate([lines, lines[new]])
    return omega, beta, values, lines
