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

The long-wave phase relations that show a likely wrong convention are checked in
:mod:`jls.vessel.phase_checks`.
"""

from __future__ import annotations

import numpy as np

from jls.errors import InputError

#: The jls convention, in the words of ``vessel.rao_conventions``.
JLS_CONVENTIONS = {"phase": "lead", "direction": "to", "x_axis": "forward"}
ALLOWED = {"phase": ("lag", "lead"), "direction": ("from", "to"), "x_axis": ("forward", "aft")}
#: Sign of each DOF (surge, sway, heave, roll, pitch, yaw) in a frame turned 180 deg about z.
AFT_SIGNS = np.array([-1.0, -1.0, 1.0, -1.0, -1.0, 1.0])


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


__all__ = ["resolve_conventions", "to_jls", "AFT_SIGNS", "ALLOWED", "JLS_CONVENTIONS"]
