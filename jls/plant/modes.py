"""Modal analysis and Rayleigh damping of the 4-DOF plant (sections 3.4 and 3.5).

Batched over leading candidate axes: M, K have shape (..., 4, 4).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jls.plant.linearise import DOF


@dataclass(frozen=True)
class Modes:
    """Undamped modes sorted by descending period.

    omega (..., 4) rad/s; shapes (..., 4 dof, 4 modes) mass-normalised;
    energy_fraction (..., 4 modes, 4 dof) modal kinetic-energy fraction per DOF;
    dominant (..., 4) index of the DOF with the largest fraction.
    """

    omega: np.ndarray
    shapes: np.ndarray
    energy_fraction: np.ndarray

    @property
    def period(self) -> np.ndarray:
        return 2.0 * np.pi / self.omega

    @property
    def dominant(self) -> np.ndarray:
        return np.argmax(self.energy_fraction, axis=-1)

    def mode_of(self, dof: str) -> np.ndarray:
        """Index of the mode carrying the largest kinetic-energy share of ``dof``."""
        return np.argmax(self.energy_fraction[..., DOF.index(dof)], axis=-1)


def modal_analysis(M, K) -> Modes:
    """Solve K phi = omega^2 M phi for symmetric K and diagonal-positive M.

    A K that is not positive definite (a statically unstable layout) gives NaN
    frequencies for that candidate; :func:`require_stable` turns that into an error.
    """
    M = np.asarray(M, float)
    K = np.asarray(K, float)
    m_diag = np.diagonal(M, axis1=-2, axis2=-1)
    if np.any(M - m_diag[..., :, None] * np.eye(M.shape[-1]) != 0.0):
        # General symmetric positive-definite M: use its Cholesky factor.
        L = np.linalg.cholesky(M)
        Linv = np.linalg.inv(L)
        A = Linv @ K @ np.swapaxes(Linv, -1, -2)
        lam, v = np.linalg.eigh(0.5 * (A + np.swapaxes(A, -1, -2)))
        shapes = np.swapaxes(Linv, -1, -2) @ v
    else:
        m_half_inv = 1.0 / np.sqrt(m_diag)
        A = m_half_inv[..., :, None] * K * m_half_inv[..., None, :]
        lam, v = np.linalg.eigh(0.5 * (A + np.swapaxes(A, -1, -2)))
        shapes = m_half_inv[..., :, None] * v
    omega = np.sqrt(np.where(lam > 0, lam, np.nan))
    ke = shapes**2 * m_diag[..., :, None]                     # (..., dof, mode)
    fraction = np.swapaxes(ke / ke.sum(axis=-2, keepdims=True), -1, -2)
    return Modes(omega=omega, shapes=shapes, energy_fraction=fraction)


def require_stable(modes: Modes) -> None:
    """Raise ValueError if any frequency is undefined (K not positive definite)."""
    if np.any(~np.isfinite(modes.omega)):
        raise ValueError("the stiffness matrix is not positive definite: the layout is "
                         "statically unstable")


def rayleigh_coefficients(omega_1, omega_2, zeta):
    """alpha, beta of C = alpha M + beta K giving ``zeta`` at both anchor frequencies
    (eq. 3.11 with zeta_1 = zeta_2)."""
    omega_1 = np.asarray(omega_1, float)
    omega_2 = np.asarray(omega_2, float)
    alpha = 2.0 * zeta * omega_1 * omega_2 / (omega_1 + omega_2)
    beta = 2.0 * zeta / (omega_1 + omega_2)
    return alpha, beta


def rayleigh_damping(M, K, modes: Modes, zeta, anchors=("sway", "yaw")):
    """C = alpha M + beta K anchored on the modes dominated by ``anchors``.

    Returns C (..., 4, 4), alpha, beta and the damping ratio of every mode (..., 4).
    """
    w = modes.omega
    w1 = np.take_along_axis(w, modes.mode_of(anchors[0])[..., None], -1)[..., 0]
    w2 = np.take_along_axis(w, modes.mode_of(anchors[1])[..., None], -1)[..., 0]
    alpha, beta = rayleigh_coefficients(w1, w2, zeta)
    C = alpha[..., None, None] * np.asarray(M) + beta[..., None, None] * np.asarray(K)
    ratios = 0.5 * (alpha[..., None] / w + beta[..., None] * w)
    return C, alpha, beta, ratios


def modal_damping_ratios(M, K, C, modes: Modes):
    """Damping ratio of each undamped mode, phi^T C phi / (2 omega) for mass-normalised
    shapes (exact for proportional damping, the usual estimate otherwise)."""
    phi = modes.shapes
    c = np.einsum("...im,...ij,...jm->...m", phi, np.asarray(C, float), phi)
    return c / (2.0 * modes.omega)
