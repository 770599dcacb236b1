"""RAO conventions: what a file's phase, direction and x axis mean, their conversion to
the jls convention (:mod:`jls.vessel.rao`), and the long-wave phase relations that show
a likely wrong convention.

Three statements describe an RAO table against the jls convention (a lead on the
wave crest at the reference point, the direction the waves travel to, x forward):

* ``phase``: ``lead`` (motion = Re{|R| A exp(i(wt + phase))}, jls) or ``lag``
  (motion = |R| A cos(wt - phase)): a lag is a lead of the opposite sign, so the RAO
  is conjugated;
* ``direction``: ``to`` (the direction the waves travel, jls) or ``from`` (where they
  come from): ``beta_jls = beta_file + 180 deg``;
* ``x_axis``: ``forward`` (jls) or ``aft``: the file's frame is the jls frame turned
  180 deg about z (x aft, y to starboard, z up), so surge, sway, roll and pitch change
  sign, heave and yaw do not, and a direction measured from the file's x axis is
  ``beta_jls = beta_file + 180 deg``.

A format that fixes a convention (AQWA: phases are lags, directions are where the
waves travel) or a file that states it (an OrcaFlex vessel type's
``RAOPhaseConvention``) gives it; the configuration's ``vessel.rao_conventions`` must
agree, and must state what neither gives (:func:`resolve_conventions`).

:func:`check_long_wave_phases` holds the converted RAO against what any free-floating
hull does in waves much longer than itself (jls convention, deep water, at the
reference point, the wave crest there at t = 0):

* heave follows the surface: phase 0 (not 180: a trough reference or heave down; not
  +-90: a zero-crossing reference or a phase origin elsewhere);
* head or following seas: the hull pitches with the slope, pitch = i k cos(beta) x
  the elevation (positive pitch bow down), so pitch leads heave by +90 deg in following
  seas (beta = 0) and lags it by 90 deg in head seas (beta = 180): the wrong sign is a
  flipped phase (lead/lag), a reversed direction (from/to) or a pitch of the other sign;
* beam seas: roll = -i k sin(beta) and sway = -i sin(beta) x the elevation (positive
  roll lifts the port side), so roll and sway are in phase: opposite phases are a roll
  or sway of the other sign.

Heading mirror image (the x axis aft) leaves every relation unchanged, so ``x_axis``
cannot be checked from the RAO: it moves the hinge to the other end of the lever arm
and must be stated.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError

#: The jls convention, in the words of ``vessel.rao_conventions``.
JLS_CONVENTIONS = {"phase": "lead", "direction": "to", "x_axis": "forward"}
ALLOWED = {"phase": ("lag", "lead"), "direction": ("from", "to"), "x_axis": ("forward", "aft")}
#: Sign of each DOF (surge, sway, heave, roll, pitch, yaw) in a frame turned 180 deg about z.
AFT_SIGNS = np.array([-1.0, -1.0, 1.0, -1.0, -1.0, 1.0])

LONG_WAVE_PERIOD_S = 25.0          # the long-wave regime of jls.config.plausible
HEAVE_LONG_WAVE = (0.7, 1.4)
HEAVE_FOLLOWS = (0.9, 1.1)         # heave this close to 1 m/m: the hull follows the waves
NEAR_AXIS_DEG = 20.0               # headings this close to 0/180 (pitch) or 90/270 (roll)
MIN_SHARE = 0.1                    # a rotation below 0.1 x its long-wave value is not judged
HEAVE_PHASE_DEG = 45.0             # heave phase beyond this from 0: another phase reference
RELATION_DEG = 45.0                # a relation more than this into the wrong half-plane


def resolve_conventions(given: dict, configured: dict | None, *, file=None,
                        field: str = "vessel.rao_conventions") -> dict:
    """The conventions of a file's RAO table: ``given`` (what the format fixes or the file
    states, ``None`` where it says nothing) completed by ``configured`` (the
    configuration's ``vessel.rao_conventions``). A configured value that contradicts the
    file, or a convention neither states, is an InputError naming the key; ``x_axis`` not
    stated is taken forward, the frame every jls reader assumes (recorded by the reader).
    """
    configured = dict(configured or {})
    unknown = sorted(set(configured) - set(ALLOWED))
    if unknown:
        raise InputError(f"unknown RAO convention(s); allowed: {sorted(ALLOWED)}", file=file,
                         field=field, value=unknown)
    out = {}
    for key, allowed in ALLOWED.items():
        stated, wanted = given.get(key), configured.get(key)
        if wanted is not None and wanted not in allowed:
            raise InputError(f"must be one of {list(allowed)}", file=file, field=f"{field}.{key}",
                             value=wanted)
        if stated is not None and wanted is not None and stated != wanted:
            raise InputError(f"the file's RAO {key} convention is '{stated}' "
                             f"({given.get(key + '_source', 'as the format fixes it')}); the "
                             f"configuration says '{wanted}'", file=file, field=f"{field}.{key}",
                             value=wanted)
        value = stated if stated is not None else wanted
        if value is None and key != "x_axis":
            raise InputError(f"the file does not state its RAO {key} convention and jls does not "
                             f"guess it: state {field}.{key} ({' or '.join(allowed)})", file=file,
                             field=f"{field}.{key}")
        out[key] = value if value is not None else "forward"
    return out


def to_jls(values, wave_direction_deg, conventions: dict):
    """RAO values (omega, direction, dof) and directions [deg] in ``conventions`` turned into
    the jls convention: (values, directions [deg]); directions are kept as written when no
    turn applies, else wrapped into [0, 360)."""
    values = np.asarray(values, complex)
    beta = np.asarray(wave_direction_deg, float)
    if conventions["phase"] == "lag":
        values = np.conj(values)
    turns = (conventions["direction"] == "from") + (conventions["x_axis"] == "aft")
    if conventions["x_axis"] == "aft":
        values = values * AFT_SIGNS
    if turns % 2:
        beta = np.mod(beta + 180.0, 360.0)
    return values, beta


def check_long_wave_phases(rao: xr.Dataset, *, file=None, field: str = "vessel.rao_conventions",
                           g: float = 9.81) -> list[str]:
    """The long-wave phase relations of the module docstring at the RAO's longest period,
    when it is in the long-wave regime: heave (median over the headings) within 0.9-1.1 m/m
    (the hull follows the waves), or within 0.7-1.4 m/m at 25 s or longer.

    Returns the notes of what could not be judged (the file stops short of long waves);
    raises InputError with the numbers when a relation has the wrong sign: a likely wrong
    phase, direction or sign convention."""
    omega = np.asarray(rao["omega"].values, float)
    w0 = float(omega[0])
    t0 = 2 * np.pi / w0
    values = rao["rao"].transpose("omega", "wave_direction", "dof").values[0]
    beta = np.degrees(np.asarray(rao["wave_direction"].values, float))
    heave = values[:, 2]
    median = float(np.median(np.abs(heave)))
    lo, hi = HEAVE_LONG_WAVE
    follows = HEAVE_FOLLOWS[0] <= median <= HEAVE_FOLLOWS[1]
    if not follows and (t0 < LONG_WAVE_PERIOD_S or not lo <= median <= hi):
        return [f"the RAO's longest period, {t0:.3g} s, is short of the long-wave regime "
                f"(heave {median:.3g} m/m there): its phase conventions were not checked"]
    k = w0 ** 2 / g          # the deep-water wave number, at most the file's depth's: a
    #                          rotation below a tenth of the slope it gives is not judged
    at = f"at the file's longest period, {t0:.4g} s"
    ph = np.degrees(np.angle(heave))
    bad = np.abs(ph) > HEAVE_PHASE_DEG
    if bad.any():
        i = int(np.argmax(np.abs(ph)))
        raise InputError(f"{at}, the heave phase in waves from {beta[i]:g} deg is {ph[i]:.1f} deg; "
                         "in long waves a hull rises with the crest (0 deg): phases relative to "
                         "the trough (180) or a zero crossing (+-90), heave positive down, or "
                         "a phase origin away from the RAO reference point?", file=file,
                         field=field, value=round(float(ph[i]), 3))
    cos_b, sin_b = np.cos(np.radians(beta)), np.sin(np.radians(beta))
    near = np.cos(np.radians(NEAR_AXIS_DEG))
    for i in np.nonzero(np.abs(cos_b) >= near)[0]:
        pitch = values[i, 4]
        if abs(pitch) < MIN_SHARE * k * abs(cos_b[i]):
            continue
        lead = float(np.degrees(np.angle(pitch / heave[i])))
        expected = 90.0 if cos_b[i] > 0 else -90.0
        if np.cos(np.radians(lead - expected)) < -np.sin(np.radians(RELATION_DEG)):
            sea = "following" if cos_b[i] > 0 else "head"
            raise InputError(f"{at}, in {sea} seas ({beta[i]:g} deg) the pitch leads the heave by "
                             f"{lead:.1f} deg; a hull pitching with the wave slope (bow down "
                             f"positive) leads it by {expected:+.0f} deg there: phases lags "
                             "read as leads (or the reverse), directions 'from' read as 'to' "
                             "(or the reverse), or pitch positive bow up?", file=file,
                             field=field, value=round(lead, 3))
    for i in np.nonzero(np.abs(sin_b) >= near)[0]:
        roll, sway = values[i, 3], values[i, 1]
        if abs(roll) < MIN_SHARE * k * abs(sin_b[i]) or abs(sway) < MIN_SHARE * abs(sin_b[i]):
            continue
        lead = float(np.degrees(np.angle(roll / sway)))
        if np.cos(np.radians(lead)) < -np.sin(np.radians(RELATION_DEG)):
            raise InputError(f"{at}, in beam seas ({beta[i]:g} deg) the roll leads the sway by "
                             f"{lead:.1f} deg; a hull rolling with the wave slope (port side up "
                             "positive) rolls in phase with its sway (0 deg): roll positive "
                             "starboard up, or sway positive to starboard?", file=file,
                             field=field, value=round(lead, 3))
    return []
