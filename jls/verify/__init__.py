"""Independent nonlinear verification of the ROM against a 6-DOF reference in MoorDyn.

The reference (:func:`build_reference`) is generated from the ROM's plant of any
rigging candidate: the jacket a free 6-DOF body on four elastic hoist wires whose
tips move rigidly with the vessel's six DOFs, in air, with the ROM's damping as
dashpots and the tugger lines under the winch law with its limits. The study's
chapter-4 tests run on it (:mod:`jls.verify.chapter4`), and the ROM can be driven by a
user's own motion record (:mod:`jls.verify.records`). MoorDyn-C 2.x (NREL, BSD-3) is
imported only when a reference runs; where it cannot be imported,
:func:`reference_available` says why and every run raises
:class:`ReferenceUnavailable`: nothing is then verified. Units t, kN, m, s, rad.

The names below load their module when first used (the package itself imports
nothing), so that the workflow can import :mod:`jls.verify.names` when it is parsed and a
job loads only what it runs.
"""

from __future__ import annotations

import importlib

#: public name -> (module, name in it)
_EXPORTS = {
    **{n: ("chapter4", n) for n in ("DecayComparison", "free_decay", "harmonic", "irregular_sea",
                                    "reference_modes", "transient_s")},
    **{n: ("excitation", n) for n in ("Excitation", "harmonic_hinge", "still", "vessel_record")},
    **{n: ("identify", n) for n in ("DecayFit", "compare", "harmonic_fit", "log_decrement", "statistics")},
    **{n: ("model", n) for n in ("Reference", "build_reference", "summary")},
    "ReferenceUnavailable": ("moordyn_model", "ReferenceUnavailable"),
    "reference_available": ("moordyn_model", "available"),
    **{n: ("records", n) for n in ("MotionRecord", "ResponseRecord", "highpass", "read_motion_record",
                                   "read_response_record", "rom_from_record")},
    **{n: ("simulate", n) for n in ("Run", "run")},
}


def __getattr__(name):
    if name not in _EXPORTS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    module, attr = _EXPORTS[name]
    value = getattr(importlib.import_module(f"{__name__}.{module}"), attr)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))


__all__ = ["build_reference", "Reference", "summary", "reference_available",
           "ReferenceUnavailable", "run", "Run", "Excitation", "harmonic_hinge", "still",
           "vessel_record", "reference_modes", "free_decay", "DecayComparison", "harmonic",
           "irregular_sea", "transient_s", "log_decrement", "DecayFit", "harmonic_fit",
           "compare", "statistics", "read_motion_record", "read_response_record",
           "MotionRecord", "ResponseRecord", "highpass", "rom_from_record"]
