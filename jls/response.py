"""Frequency-domain response of the suspended jacket (sections 3.3, 4.4 and 6.7).

For each wave frequency omega and heading, the hinge moves as qb(omega) (complex
amplitude per unit wave amplitude) and the jacket responds as

    (K - omega^2 M + i omega C) q = -Kb qb

(eq. 3.10 in the frequency domain, time factor exp(i omega t)). A damping tugger is a
linear damper of slope c [kN s/m] between the fairlead and the jacket, acting along the
sway direction at the height of the CoG (section 6.3, frequency-domain form, no winch
limits): it adds i omega c to the sway-sway term and i omega c y_f to the load, with y_f
the fairlead sway. Relative motions are taken against the hinge: y - y_b, z - z_b,
phi - phi_b, psi - psi_b.
"""

from __future__ import annotations

import numpy as np

RESPONSES = ("relative_sway", "relative_heave", "relative_roll", "relative_yaw")
ROTATIONAL = (False, False, True, True)


def dynamic_stiffness_inverse(M, K, C, omega, c_tugger=0.0):
    """Receptance G = (K - w^2 M + i w C_total)^-1.

    M, K, C: (..., 4, 4) candidate matrices; omega: (n_w,); c_tugger: (n_t,) or scalar.
    Returns (..., n_t, n_w, 4, 4) complex.
    """
    M, K, C = (np.asarray(a, float)[..., None, None, :, :] for a in (M, K, C))
    w = np.asarray(omega, float)[:, None, None]
    c_t = np.atleast_1d(np.asarray(c_tugger, float))[:, None]
    A = K - w**2 * M + 1j * w * C
    A = np.broadcast_to(A, A.shape[:-4] + (c_t.shape[0], w.shape[0], 4, 4)).copy()
    A[..., 0, 0] += 1j * c_t * np.asarray(omega, float)
    return np.linalg.inv(A)


def transfer_functions(M, K, Kb, C, omega, qb, fairlead_sway=None, c_tugger=0.0):
    """Transfer functions of q and of the relative motions per unit wave amplitude.

    Parameters
    ----------
    M, K, Kb, C : (..., 4, 4) plant matrices of one or many candidates
    omega : (n_w,) rad/s
    qb : (n_h, n_w, 4) complex hinge RAO [y_b, z_b, phi_b, psi_b] per heading
    fairlead_sway : (n_h, n_w) complex sway RAO of the tugger fairleads (needed when
        any tugger slope is non-zero)
    c_tugger : (n_t,) tugger damping slopes [kN s/m]

    Returns
    -------
    Hq, Hrel : (..., n_t, n_h, n_w, 4) complex, m/m and rad/m.
    """
    c_t = np.atleast_1d(np.asarray(c_tugger, float))
    qb = np.asarray(qb, complex)
    if np.any(c_t != 0) and fairlead_sway is None:
        raise ValueError("a tugger needs the fairlead sway RAO")
    G = dynamic_stiffness_inverse(M, K, C, omega, c_t)              # (..., t, w, 4, 4)
    load = -np.einsum("...ij,hwj->...hwi", np.asarray(Kb, float), qb)  # (..., h, w, 4)
    load = np.broadcast_to(load[..., None, :, :, :],
                           load.shape[:-3] + (c_t.shape[0],) + load.shape[-3:]).copy()
    if fairlead_sway is not None:
        iw = 1j * np.asarray(omega, float)
        load[..., 0] += (c_t[:, None, None] * iw * np.asarray(fairlead_sway, complex))
    Hq = np.einsum("...twij,...thwj->...thwi", G, load)
    return Hq, Hq - qb


def response_grid(omega_lo, omega_hi, step, natural_omega=(), zeta=0.0098, points_per_bandwidth=12):
    """Frequency grid over [omega_lo, omega_hi] refined around lightly damped modes.

    A uniform grid of ``step`` plus, around each natural frequency w_n in range, points
    spaced a ``points_per_bandwidth``-th of the half-power bandwidth 2 zeta w_n over
    +/- 25 bandwidths, so that resonance peaks are integrated accurately whatever the
    base step.
    """
    grid = [np.arange(omega_lo, omega_hi, step), [omega_hi]]
    for wn in np.atleast_1d(np.asarray(natural_omega, float)).ravel():
        if not np.isfinite(wn) or not omega_lo < wn < omega_hi:
            continue
        bw = 2.0 * zeta * wn
        fine = wn + np.arange(-25 * points_per_bandwidth, 25 * points_per_bandwidth + 1) * (
            bw / points_per_bandwidth)
        grid.append(fine[(fine > omega_lo) & (fine < omega_hi)])
    g = np.unique(np.round(np.concatenate(grid), 12))
    return g
