"""The phase convention of an RAO file checked by physics: what any free-floating hull does
in waves much longer than itself decides lag/lead and exp(+-i w t), and flags a
mismatch with the convention a file declares or is assumed to have (every format, after
its reader has turned it into the jls convention, :mod:`jls.vessel.conventions`). Two
checks, on the same long-wave limit:

**The convention (all headings at once).** jls holds RAOs as leads on the wave crest
in exp(+i w t) (docs/vessel.md). In waves much longer than the hull the hull follows
the water: heave tends to 1 and the hull tilts with the wave slope. For a wave ``Re{A exp(i(w t - k (x cos b + y sin b)))}``
(x forward, y to port, z up; b the direction of propagation, 180 deg head seas) the
slope gives, with roll positive starboard down and pitch positive bow down,

    roll  -> -i k sin b,      pitch -> +i k cos b      (per m of wave amplitude)

so in the lead convention roll lags the crest by 90 deg in beam seas from starboard
(b = 90 deg) and pitch leads it by 90 deg in following seas. A file read in the other
convention (phases that are lags read as leads, a Capytaine file already in
exp(+i w t) conjugated a second time) has both signs reversed. The projection

    c = Re{ sum conj(e) r } / sum |e|^2     (e the long-wave values above, r the file's
                                            roll and pitch at its lowest frequency)

(normalised as a correlation, :func:`long_wave_agreement`) is about +1 for a file in the
jls convention and about -1 for one in the other;
:func:`check_phase_convention` refuses c <= -:data:`MIN_AGREEMENT` naming the file and what
it declared or was assumed to be. Where the file stops short of long waves (heave at its
lowest frequency outside 0.7-1.4 m/m, as :func:`jls.config.plausible.check_rao_magnitudes`)
or the rotations there are too small to tell, nothing is decided.

**The relations heading by heading** (:func:`check_long_wave_phases`, at parse time from
:func:`jls.config.workflow_inputs.check_rao`) hold the converted RAO against the same
limit (jls convention, deep water, at the reference point, the wave crest there at
t = 0) where the file reaches it (heave within 0.9-1.1 m/m, or within 0.7-1.4 m/m at 25 s
or longer); what cannot be judged is returned as a note for the report:

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

#: |c| at or above this decides the convention (the files checked give 0.99-1.01).
MIN_AGREEMENT = 0.5
#: Heave at the lowest frequency within these bounds: the long-wave regime is reached
#: (jls.config.plausible judges the magnitudes on the same bounds).
HEAVE_LONG_WAVE = (0.7, 1.4)
#: The longest period at which a hull follows the waves whatever its size:
#: check_long_wave_phases judges a file reaching it with heave within HEAVE_LONG_WAVE, or
#: one whose heave is within HEAVE_FOLLOWS at any period.
LONG_WAVE_PERIOD_S = 25.0
HEAVE_FOLLOWS = (0.9, 1.1)         # heave this close to 1 m/m: the hull follows the waves
NEAR_AXIS_DEG = 20.0               # headings this close to 0/180 (pitch) or 90/270 (roll)
MIN_SHARE = 0.1                    # a rotation below 0.1 x its long-wave value is not judged
HEAVE_PHASE_DEG = 45.0             # heave phase beyond this from 0: another phase reference
RELATION_DEG = 45.0                # a relation more than this into the wrong half-plane


def long_wave_agreement(rao) -> float | None:
    """c of the module docstring at the file's lowest frequency, as a correlation (the
    file's roll and pitch against the long-wave shapes -i sin b, +i cos b, each
    normalised: independent of k, of the depth and of a rotation unit, which
    :func:`jls.config.plausible.check_rao_magnitudes` checks), or None where the frequency
    is not in the long-wave regime or the rotations there vanish."""
    values = rao["rao"].transpose("omega", "wave_direction", "dof").values[0]
    heave = float(np.median(np.abs(values[:, 2])))
    if not HEAVE_LONG_WAVE[0] <= heave <= HEAVE_LONG_WAVE[1]:
        return None
    beta = np.asarray(rao["wave_direction"].values, float)
    expected = np.concatenate([-1j * np.sin(beta), 1j * np.cos(beta)])
    found = np.concatenate([values[:, 3], values[:, 4]])
    norm = float(np.linalg.norm(expected) * np.linalg.norm(found))
    if not norm > 0:
        return None
    return float(np.real(np.vdot(expected, found)) / norm)


def _assumed(rao) -> tuple[str, str]:
    """(what the file declared or was taken to be, how to state the other convention)."""
    fmt = str(rao.attrs.get("source_format", ""))
    if fmt == "csv":
        phase = str(rao.attrs.get("csv_phase", "lead"))
        other = "lag" if phase == "lead" else "lead"
        return (f"read as phase {phase} ({'declared' if phase == 'lag' else 'the default'})",
                f"declare '# phase: {other}' before the header" if phase == "lead" else
                "remove the '# phase: lag' declaration")
    if fmt == "capytaine":
        return ("read as Capytaine's exp(-i omega t) and conjugated",
                "the file is already in exp(+i omega t) (conjugated before): give Capytaine's "
                "own output, or write it as a jls NetCDF or CSV file in the lead convention")
    if fmt == "wamit4":
        return ("read in WAMIT's convention (exp(+i omega t), phase lead)",
                "the file's phases were edited or written by another program: regenerate it")
    return (f"a jls file ({rao.attrs.get('phase_convention', 'exp(+i omega t), lead')})",
            "the file's phases were conjugated after it was written: regenerate it")


def check_phase_convention(rao, file=None) -> float | None:
    """Refuse an RAO whose long-wave roll and pitch have the signs of the other phase
    convention; returns c (None: not decided)."""
    c = long_wave_agreement(rao)
    if c is not None and c <= -MIN_AGREEMENT:
        w0 = float(rao["omega"].values[0])
        read, fix = _assumed(rao)
        raise InputError(f"at the file's lowest frequency, {w0:.3g} rad/s, roll and pitch have the "
                         f"signs of the other phase convention: in long waves a hull tilts with the "
                         f"wave slope (roll -i k sin b, pitch +i k cos b in the lead convention, "
                         f"exp(+i omega t)), and this file's rotations correlate with those at "
                         f"{c:+.2f} (+1 expected). It was {read}; {fix}", file=file,
                         field="phase convention", value=round(c, 3))
    return c


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


__all__ = ["check_phase_convention", "check_long_wave_phases", "long_wave_agreement",
           "HEAVE_LONG_WAVE", "LONG_WAVE_PERIOD_S"]
