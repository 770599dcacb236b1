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
"""

from jls.verify.chapter4 import (
    DecayComparison,
    free_decay,
    harmonic,
    irregular_sea,
    reference_modes,
    transient_s,
)
from jls.verify.excitation import Excitation, harmonic_hinge, still, vessel_record
from jls.verify.identify import DecayFit, compare, harmonic_fit, log_decrement, statistics
from jls.verify.model import Reference, build_reference, summary
from jls.verify.moordyn_model import ReferenceUnavailable
from jls.verify.moordyn_model import available as reference_available
from jls.verify.records import (
    MotionRecord,
    ResponseRecord,
    highpass,
    read_motion_record,
    read_response_record,
    rom_from_record,
)
from jls.verify.simulate import Run, run

__all__ = ["build_reference", "Reference", "summary", "reference_available",
           "ReferenceUnavailable", "run", "Run", "Excitation", "harmonic_hinge", "still",
           "vessel_record", "reference_modes", "free_decay", "DecayComparison", "harmonic",
           "irregular_sea", "transient_s", "log_decrement", "DecayFit", "harmonic_fit",
           "compare", "statistics", "read_motion_record", "read_response_record",
           "MotionRecord", "ResponseRecord", "highpass", "rom_from_record"]
