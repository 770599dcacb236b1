"""The 6-DOF reference model of one rigging candidate, generated from the ROM's plant.

What the reference is (and what MoorDyn is given, :mod:`jls.verify.moordyn_model`):

* the jacket a free rigid body in six DOFs at its CoG: inertial mass M_kin and roll and
  yaw inertia as the ROM has them, a pitch inertia of its own (the ROM has none;
  default: the roll inertia), its weight that of the gravitational mass M_grav (a
  constant upward force (M_kin - M_grav) g at the CoG keeps the weight at M_grav g
  while the body's mass is M_kin, as the ROM separates them);
* each hoist wire a line from its lift-beam tip to its padeye with the ROM's axial
  stiffness (the series steel and fibre stiffness, eq. 3.2) as EA = k L0, L0 the
  unstretched length of the ROM's static state, a mass per length (default none:
  the ROM's M_kin already carries the rigging's share) and one segment by default
  (both ends attached, so no node of its own; with several segments the inner nodes
  are free masses, start on the straight line and MoorDyn sub-steps them, about ten
  times slower; the static pose is solved with the wire mass lumped half at each end);
  a wire pulls only;
* the four tips coupled points moved rigidly with the vessel's six DOFs
  (:mod:`jls.verify.excitation`), and the tugger fairleads likewise;
* the tugger lines (when a setting is given) lines whose tension follows the winch law
  with its limits (:mod:`jls.tugger.setting`), updated every step;
* dashpots giving the ROM's damping (:mod:`jls.verify.damping`);
* in air: everything above the water line (the hinge ``hinge_height_m`` above it) and
  no drag, added mass or buoyancy anywhere.

Frame: x forward, y to port, z up; origin on the water line below the hinge at rest.
Units t, kN, m, s, rad.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from jls.errors import InputError
from jls.tugger.setting import Tugger
from jls.verify import damping as damp
from jls.verify import statics

#: Hinge height above the water line of the study (table 5.1), m.
HINGE_HEIGHT_M = 119.46
#: Study's hinge centroid B from the vessel CoG (section 3.2.1), m.
VESSEL_LEVER_M = (-215.263, 1.0, 99.998)


@dataclass(frozen=True)
class Reference:
    """The reference model of one candidate (see the module docstring).

    Jacket: m_kin, m_grav [t], inertia (3,) [t m^2] (roll, pitch, yaw about the CoG),
    g [m/s^2]. Geometry: hinge (3,) at rest, anchors (4, 3) of the tips from the
    hinge, padeyes (4, 3) from the CoG in the body frame, cog_rest (3,) the ROM's CoG
    position. Wires: k (4,) [kN/m], L0 (4,) [m], wire_mass_per_length [t/m],
    segments. Tuggers: tugger (or None), fairleads (2, 3) from the hinge, attachments
    (2, 3) from the CoG. Vessel: vessel_lever (3,), the hinge from the point the
    vessel's motions refer to. State: pose (6,) the static pose, tension (4,) [kN].
    Damping: dashpots. Names: wire_names.
    """

    m_kin: float
    m_grav: float
    inertia: np.ndarray
    g: float
    hinge: np.ndarray
    anchors: np.ndarray
    padeyes: np.ndarray
    cog_rest: np.ndarray
    k: np.ndarray
    L0: np.ndarray
    wire_mass_per_length: float
    segments: int
    tugger: Tugger | None
    fairleads: np.ndarray
    attachments: np.ndarray
    vessel_lever: np.ndarray
    wire_names: tuple
    pose: np.ndarray | None = None
    tension: np.ndarray | None = None
    #: the wires' axial damping as MoorDyn's BA: [kN s], or negative, minus the damping
    #: ratio of a segment's axial vibration
    wire_axial_damping: float = 0.0
    dashpots: damp.Dashpots | None = None
    modes: statics.Modes6 | None = None
    K6: np.ndarray | None = None
    M6: np.ndarray | None = None

    @property
    def tips_rest(self) -> np.ndarray:
        return self.hinge + self.anchors

    @property
    def fairleads_rest(self) -> np.ndarray:
        return self.hinge + self.fairleads

    @property
    def lever(self) -> float:
        """CoG depth below the hinge [m], the length scale of moments."""
        return float(self.hinge[2] - self.cog_rest[2])


def build_reference(plant, *, pitch_inertia_t_m2=None, wire_mass_t_per_m=0.0, segments=1,
                    wire_axial_damping=0.0,
                    tugger: Tugger | None = None, fairlead_offset_m=(0.0, 37.5, -82.5),
                    hinge_height_m=HINGE_HEIGHT_M, vessel_lever_m=VESSEL_LEVER_M,
                    wire_names=None) -> Reference:
    """The reference model of a geometric plant (:func:`jls.plant.model.build`, one candidate).

    pitch_inertia_t_m2: pitch inertia about the CoG [t m^2] (default: the roll
    inertia); wire_mass_t_per_m: hoist-wire mass per length [t/m]; wire_axial_damping:
    the wires' axial damping (MoorDyn's BA [kN s]; negative: minus a segment's axial
    damping ratio); segments: line
    segments per wire (more than one needs a wire mass); tugger: the setting whose
    lines act on the jacket (None: no tugger lines); fairlead_offset_m: the port
    fairlead from the hinge, (x, half span, -drop) [m] (starboard mirrored);
    hinge_height_m: the hinge above the water line [m]; vessel_lever_m: the hinge from
    the vessel's motion reference point [m]. Solves the static pose, linearises, and
    sizes the dashpots (:mod:`jls.verify.damping`).
    """
    if getattr(plant, "layout", None) is None or plant.unstretched_length is None:
        raise InputError("the nonlinear reference needs the wire geometry; a plant given as "
                         "matrices has none", field="plant_matrices")
    if np.ndim(plant.M) != 2:
        raise InputError("the reference models one rigging candidate at a time", field="candidates")
    segments = int(segments)
    if segments < 1 or (segments > 1 and not wire_mass_t_per_m > 0):
        raise InputError("a wire of more than one segment needs a positive mass per length "
                         "(its inner nodes are free masses)", field="segments", value=segments)
    if wire_mass_t_per_m < 0:
        raise InputError("must be >= 0", field="wire_mass_t_per_m", value=wire_mass_t_per_m)
    L = plant.layout
    M = np.asarray(plant.M, float)
    ixx, izz = float(M[2, 2]), float(M[3, 3])
    iyy = ixx if pitch_inertia_t_m2 is None else float(pitch_inertia_t_m2)
    if not iyy > 0:
        raise InputError("must be positive", field="pitch_inertia_t_m2", value=pitch_inertia_t_m2)
    depth = float(L.cog_depth)
    hinge = np.array([0.0, 0.0, float(hinge_height_m)])
    if hinge[2] - depth <= 0.0:
        raise InputError("the jacket's CoG would be below the water line; the reference is in air",
                         field="hinge_height_m", value=hinge_height_m)
    off = np.asarray(fairlead_offset_m, float)
    t = tugger if (tugger is not None and tugger.active) else None
    hw = t.half_width if t is not None else 22.5
    ref = Reference(
        m_kin=float(M[0, 0]), m_grav=float(plant.m_grav), inertia=np.array([ixx, iyy, izz]),
        g=float(plant.g), hinge=hinge, anchors=np.asarray(L.anchors, float),
        padeyes=np.asarray(L.padeyes, float), cog_rest=hinge - (0.0, 0.0, depth),
        k=np.broadcast_to(np.asarray(plant.wire_stiffness, float), (4,)).copy(),
        L0=np.asarray(plant.unstretched_length, float).copy(),
        wire_mass_per_length=float(wire_mass_t_per_m), segments=segments, tugger=t,
        wire_axial_damping=float(wire_axial_damping),
        fairleads=np.array([[off[0], off[1], off[2]], [off[0], -off[1], off[2]]]),
        attachments=np.array([[0.0, hw, 0.0], [0.0, -hw, 0.0]]),
        vessel_lever=np.asarray(vessel_lever_m, float),
        wire_names=tuple(wire_names) if wire_names else tuple(f"wire{i + 1}" for i in range(4)))
    pose = statics.solve_pose(ref)
    ld = statics.loads(ref, *statics.pose_matrix(pose))
    K6, M6 = statics.stiffness(ref, pose), statics.mass(ref, pose)
    md = statics.modes(K6, M6)
    if not np.all(np.isfinite(md.omega)):
        raise InputError("the reference is statically unstable at its pose", field="rigging.wires")
    rom = plant.modes
    rom_dom = [("sway", "heave", "roll", "yaw")[i] for i in np.argmax(rom.energy_fraction, axis=-1)]
    target = damp.targets(md, rom.period, plant.damping_ratio, rom_dom, plant.rayleigh)
    dash = damp.design(md, target, pose_rotation=statics.rotation(*pose[3:]))
    return dataclasses.replace(ref, pose=pose, tension=ld.tension, dashpots=dash, modes=md,
                               K6=K6, M6=M6)


def summary(ref: Reference) -> dict:
    """Static pose, tensions, periods and damping of the reference (JSON-ready)."""
    md = ref.modes
    return {
        "pose_offset_m": (ref.pose[:3] - ref.cog_rest).tolist(),
        "pose_angles_rad": ref.pose[3:].tolist(),
        "tension_kN": ref.tension.tolist(),
        "natural_period_s": md.period.tolist(),
        "dominant_dof": list(md.dominant),
        "damping_ratio_target": ref.dashpots.target_ratio.tolist(),
        "damping_ratio_linearised": ref.dashpots.achieved_ratio.tolist(),
        "dashpot_c_kN_s_per_m": dict(zip(ref.dashpots.names, ref.dashpots.c.tolist())),
        "pitch_inertia_t_m2": float(ref.inertia[1]),
        "wire_mass_t_per_m": ref.wire_mass_per_length, "segments": ref.segments,
    }


__all__ = ["Reference", "build_reference", "summary", "HINGE_HEIGHT_M", "VESSEL_LEVER_M"]
