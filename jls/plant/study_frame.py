"""The reference study's plant frame (z down) and the project frame (z up).

**The study's frame.** Section 3.3.2 writes the Lagrangian with

    r_CoG = (0, y, z + z_eq),  z_eq = h_drop + z_p > 0,   V = -M_grav g (z + z_eq) + ...

so the jacket's CoG sits at +z_eq from the hinge and its potential energy falls as z
grows: **z points down**. Its x and y are those of the hinge transfer, eq. 3.1, which is
the small-rotation sum of the z-up seakeeping frame (x forward, y to port; the hinge
sway is H_sway + H_yaw dx - H_roll dz with dz = +99.998 m *above* the CoG): the
Lagrangian reverses z alone. A point at r in the project frame (x forward, y to port,
z up; :mod:`jls.plant.linearise`) is at ``S r`` in the study's, S = diag(1, 1, -1). The
study's rotations are the textbook matrices in its own coordinates, R = Rz(psi) Rx(phi);
the same physical rotation in project coordinates is

    S Rx(phi_s) S = Rx(-phi_s),      S Rz(psi_s) S = Rz(psi_s),

so sway and yaw keep their sign and heave and roll change it:

    q_project = T q_study,  qb_project = T qb_study,   T = diag(1, -1, -1, 1)  (T^-1 = T).

V is a scalar, so its Hessians (eq. 3.9) transform as K -> T K T and Kb -> T Kb T, and
M (diagonal) and a Rayleigh C = alpha M + beta K as M and K do; the periods, damping
ratios and modal energy fractions are unchanged. Sway-roll and roll-yaw coupling (K13,
K34, their Kb entries) change sign; sway-yaw coupling K14 does not.

Had the study meant a right-handed z-down frame (x forward, y to *starboard*), T would be
diag(-1, -1, 1, -1) = T times the port/starboard mirror diag(-1, 1, -1, -1). For a
port/starboard-symmetric plant (the appendix prints zero heave couplings) the two give
the same matrices, so the conversion does not depend on that reading.

**The check.** A common roll of hinge and jacket about the hinge strains no wire; it
only tilts gravity. With the CoG at z_eq below the hinge this gives, in the study's
frame, ``Kb[:, roll] = -K[:, roll] + z_eq K[:, sway] - W e_sway`` and, in the project
frame, ``Kb[:, roll] = -K[:, roll] - z_eq K[:, sway] + W e_sway`` (T maps one onto the
other); the sway, heave and yaw columns are ``-K`` in both (a common translation or yaw
strains no wire). Appendix A.1 prints Kb to four decimals of 1e8 and its roll column
(0.0002, -1.1794, 0.0653)e8 is the study-frame identity of its own K to the last digit
(and its diagnostic Kb33 + K33 = +3.048e6 = z_eq K31): the printed K is in the z-down
frame. :func:`appendix_a1` completes Kb from that identity and converts the plant.
"""

from __future__ import annotations

import numpy as np

#: q_project = T q_study for q = [sway, heave, roll, yaw] (and qb).
T = np.diag([1.0, -1.0, -1.0, 1.0])

# Appendix A.1 as printed (study frame, t, kN, m, rad). K from its "Diagonal stiffness"
# and "Cross-coupling" lines (four significant figures); Kb's print: 1e8 x 4 decimals.
A1_M = np.diag([7719.0, 7719.0, 4.55e6, 3.286e6])
A1_K_STUDY = np.array([[1.559e3, 0.0, 3.695e4, 5.425e4],
                       [0.0, 2.339e5, 0.0, 0.0],
                       [3.695e4, 0.0, 1.2099e8, -2.052e6],
                       [5.425e4, 0.0, -2.052e6, 1.024e7]])
A1_PRINT_SCALE = 1.0e8
A1_K_PRINTED = np.array([[0.0000, 0, 0.0004, 0.0005],
                         [0, 0.0023, 0, 0],
                         [0.0004, 0, 1.2099, -0.0205],
                         [0.0005, 0, -0.0205, 0.1024]])
A1_KB_PRINTED = np.array([[-0.0000, 0, 0.0002, -0.0005],
                          [0, -0.0023, 0, 0],
                          [-0.0004, 0, -1.1794, 0.0205],
                          [-0.0005, 0, 0.0653, -0.1024]])
#: Half the last printed digit: a value reproduces a printed entry within this.
A1_PRINT_HALF_STEP = 0.5e-4 * A1_PRINT_SCALE
#: Its diagnostic line "K_base(3,3) + K(3,3) = 3.048e+06" (four significant figures).
A1_KB33_PLUS_K33 = 3.048e6
# Table 3.3: M_grav 7650 t, g 9.81, z_eq = h_drop + z_p = 60.091 + 22.41 m.
A1_M_GRAV = 7650.0
A1_G = 9.81
A1_Z_EQ = 60.091 + 22.41


def to_project(matrix):
    """A 4x4 plant matrix (M, K, Kb or C, batched over leading axes) from the study's
    z-down frame to the project's z-up frame: T A T."""
    return T @ np.asarray(matrix, float) @ T


def to_study(matrix):
    """The inverse of :func:`to_project` (the same map: T is its own inverse)."""
    return to_project(matrix)


def kb_from_rigid_body(K, z_eq, weight, frame="project"):
    """Kb of a plant hung ``z_eq`` below the hinge from its K by rigid-body invariance.

    Columns sway, heave, yaw: -K; roll: -K[:, roll] -/+ z_eq K[:, sway] +/- W e_sway
    (upper signs in the project frame, z up; lower in the study's, z down).
    """
    if frame not in ("project", "study"):
        raise ValueError(f"frame must be 'project' or 'study', not {frame!r}")
    K = np.asarray(K, float)
    s = 1.0 if frame == "project" else -1.0
    Kb = -K.copy()
    Kb[:, 2] = -K[:, 2] - s * z_eq * K[:, 0]
    Kb[0, 2] += s * weight
    return Kb


def appendix_a1(frame="project") -> dict[str, np.ndarray]:
    """The appendix A.1 plant: M, K and Kb completed from the study-frame identity
    (module docstring), in the project frame (default) or the study's."""
    kb = kb_from_rigid_body(A1_K_STUDY, A1_Z_EQ, A1_M_GRAV * A1_G, frame="study")
    mats = {"M": A1_M.copy(), "K": A1_K_STUDY.copy(), "Kb": kb}
    if frame == "study":
        return mats
    if frame != "project":
        raise ValueError(f"frame must be 'project' or 'study', not {frame!r}")
    return {name: to_project(m) for name, m in mats.items()}


def printed_deviation(matrix, printed=A1_KB_PRINTED):
    """|matrix - printed| [kN, kN m, ...] of a study-frame matrix against its print;
    an entry is reproduced when this is at most :data:`A1_PRINT_HALF_STEP`."""
    return np.abs(np.asarray(matrix, float) - np.asarray(printed, float) * A1_PRINT_SCALE)
