"""The phase convention of an RAO file checked by physics, and what the file states about
itself checked against the configuration (CSV, Capytaine and jls NetCDF files; WAMIT
``.4`` files too, whose convention is fixed).

**Phase.** jls holds RAOs as leads on the wave crest in exp(+i w t) (docs/vessel.md). In
waves much longer than the hull the hull follows the water: heave tends to 1 and the
hull tilts with the wave slope. For a wave ``Re{A exp(i(w t - k (x cos b + y sin b)))}``
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

**Stated things.** A file that states the point its RAOs refer to (a Capytaine file's
``rotation_center``, or the ``reference_point_m`` of a file jls computed with Capytaine,
``source_format`` capytaine-bem), in the frame of its model with z = 0 at the still
waterline, states that point's height above the water; the
configuration states it too (``vessel.rao_reference_point_height_m``, or derived from
``rigging.limits.hinge_height_m``). :func:`check_stated_reference` refuses a disagreement
of more than :data:`REFERENCE_TOLERANCE_M`, naming both sources: the hinge's lever arm
from the reference point, and so its motion, would be wrong by the difference. A file's
``g`` (Capytaine) is compared with ``g_m_per_s2`` likewise.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from jls.errors import InputError

#: |c| at or above this decides the convention (the files checked give 0.99-1.01).
MIN_AGREEMENT = 0.5
#: Heave at the lowest frequency within these bounds: the long-wave regime is reached.
HEAVE_LONG_WAVE = (0.7, 1.4)
#: The largest disagreement between the reference height stated by the file and by the
#: configuration [m].
REFERENCE_TOLERANCE_M = 0.05
#: The largest relative disagreement between a file's g and the configuration's.
G_TOLERANCE = 0.005


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


def stated_reference_height(rao) -> float | None:
    """The height above the still waterline of the point the file says its RAOs refer to,
    or None when the file does not state it."""
    fmt = str(rao.attrs.get("source_format", ""))
    source = str(rao.attrs.get("reference_point_source", ""))
    # stated: a Capytaine file's rotation_center, or a file jls computed with Capytaine
    # (vessel.bem, scripts/make_default_vessel.py: the hull's CoG in the mesh frame, z = 0
    # at the waterline). A reader's default origin (WAMIT, CSV, a file without
    # rotation_center) states nothing.
    if not (source.startswith("rotation_center") or fmt == "capytaine-bem"):
        return None
    if "reference_point_m" not in rao.attrs:
        return None
    return float(np.asarray(rao.attrs["reference_point_m"], float)[2])


def check_stated_reference(rao, vessel: dict, file=None, config_source: str = "config",
                           g: float | None = None, g_source: str = "config") -> None:
    """The file's stated reference point (height above the waterline) and g against the
    configuration's; InputError naming both sources."""
    name = Path(str(file)).name if file else "the RAO file"
    stated = stated_reference_height(rao)
    if stated is not None and "rao_reference_point_height_m" in vessel:
        conf = float(vessel["rao_reference_point_height_m"])
        if abs(stated - conf) > REFERENCE_TOLERANCE_M:
            where = ("rotation_center" if rao.attrs.get("reference_point_source", "").startswith(
                "rotation_center") else "reference_point_m")
            raise InputError(f"{name} states that its RAOs refer to a point at z = {stated:g} m "
                             f"({where}, in its model's frame: z = 0 at the waterline), and "
                             f"{config_source} puts the RAO reference point {conf:g} m above the "
                             f"waterline (vessel.rao_reference_point_height_m): the hinge's lever arm "
                             f"from it would be {abs(stated - conf):.2f} m off. Give the file's height, "
                             "or RAOs about the configured point (jls.vessel.transfer."
                             "shift_reference_point)", file=file,
                             field="vessel.rao_reference_point_height_m", value=conf)
    if g is not None and "capytaine_g" in rao.attrs:
        fg = float(rao.attrs["capytaine_g"])
        if abs(fg - g) > G_TOLERANCE * g:
            raise InputError(f"{name} was computed with g = {fg:g} m/s2 and {g_source} gives "
                             f"g_m_per_s2 = {g:g}: the wave numbers of the two disagree", file=file,
                             field="g_m_per_s2", value=g)


__all__ = ["check_phase_convention", "check_stated_reference", "long_wave_agreement",
           "stated_reference_height"]
