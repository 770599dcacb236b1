"""The linear 4-DOF plant M q'' + C q' + K q = -Kb qb (eq. 3.10).

A plant is built from a rigging layout (equilibrium, linearisation, modes, Rayleigh
damping) or read from a matrices file. Everything is vectorised over leading candidate
axes so that thousands of rigging geometries are assessed in one call.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from jls.errors import InputError
from jls.io import yamlio
from jls.plant import equilibrium
from jls.plant import modes as modal
from jls.plant.linearise import DOF, stiffness_matrices
from jls.plant.rigging import Layout, lumped_inertial_mass


@dataclass(frozen=True)
class Jacket:
    """Mass properties: gravitational mass [t], inertial mass [t] (None: lumped from
    ``lumping``), roll and yaw inertia [t m^2], padeye height above the CoG [m]."""

    m_grav: float
    m_kin: float | None
    ixx: float
    izz: float
    z_p: float
    lumping: dict | None = None


@dataclass(frozen=True)
class Plant:
    """Matrices (..., 4, 4) in t, kN, m, s, rad with their modes and, when built from
    geometry, the wires' static state."""

    M: np.ndarray
    K: np.ndarray
    Kb: np.ndarray
    C: np.ndarray
    modes: modal.Modes
    damping_ratio: np.ndarray
    m_grav: float
    g: float
    layout: Layout | None = None
    wire_stiffness: np.ndarray | None = None
    tension: np.ndarray | None = None
    unstretched_length: np.ndarray | None = None
    residual: np.ndarray | None = None
    rayleigh: tuple | None = None

    @property
    def balanced(self) -> np.ndarray:
        return np.all(np.abs(self.residual) <= equilibrium.RESIDUAL_LIMIT, axis=-1)


def mass_matrix(m_kin, ixx, izz):
    """M = diag(M_kin, M_kin, Ixx, Izz) (eq. 3.7), broadcast over m_kin."""
    m_kin = np.asarray(m_kin, float)
    M = np.zeros(m_kin.shape + (4, 4))
    M[..., 0, 0] = M[..., 1, 1] = m_kin
    M[..., 2, 2] = ixx
    M[..., 3, 3] = izz
    return M


def build(layout: Layout, jacket: Jacket, k, g=9.81, zeta=0.0098,
          anchor_modes=("sway", "yaw")) -> Plant:
    """Plant of one or many layouts.

    Tensions follow from :func:`jls.plant.equilibrium.solve`; a layout with a slack or
    compressed wire (:func:`jls.plant.equilibrium.slack`) gets NaN matrices (callers decide
    whether that is an error, see :func:`require_taut`).
    """
    weight = jacket.m_grav * g
    eq = equilibrium.solve(layout.anchors, layout.padeyes, layout.cog_depth, weight)
    k = np.broadcast_to(np.asarray(k, float), eq.tension.shape)
    K, Kb = stiffness_matrices(layout.anchors, layout.padeyes, layout.cog_depth, k, eq.tension)
    taut = ~np.any(equilibrium.slack(eq.tension, weight), axis=-1)
    K = np.where(taut[..., None, None], K, np.nan)
    Kb = np.where(taut[..., None, None], Kb, np.nan)
    if jacket.m_kin is not None:
        m_kin = np.full(taut.shape, jacket.m_kin)
    else:
        if jacket.lumping is None:
            raise ValueError("the inertial mass needs jacket.m_kin or the mass lumping (eq. 3.3)")
        lump = jacket.lumping
        m_kin = lumped_inertial_mass(jacket.m_grav, eq.length, lump["block_mass_t"],
                                     lump["block_distance_from_anchor_m"],
                                     lump["wire_mass_t_per_m"])
    M = mass_matrix(m_kin, jacket.ixx, jacket.izz)
    K_safe = np.where(taut[..., None, None], K, np.eye(4))
    md = modal.modal_analysis(M, K_safe)
    C, alpha, beta, ratios = modal.rayleigh_damping(M, K_safe, md, zeta, anchor_modes)
    return Plant(M=M, K=K, Kb=Kb, C=np.where(taut[..., None, None], C, np.nan), modes=md,
                 damping_ratio=ratios, m_grav=jacket.m_grav, g=g, layout=layout,
                 wire_stiffness=k, tension=eq.tension,
                 unstretched_length=eq.length - eq.tension / k, residual=eq.residual,
                 rayleigh=(alpha, beta))


def require_taut(plant: Plant, names, source="rigging") -> None:
    """Raise InputError naming the first slack or compressed wire of a single plant
    (the rule of :func:`jls.plant.equilibrium.slack`)."""
    tension = np.atleast_1d(plant.tension)
    for name, t, is_slack in zip(names, tension, equilibrium.slack(tension, plant.m_grav * plant.g)):
        if is_slack:
            raise InputError(f"wire '{name}' is slack or in compression at equilibrium "
                             f"(tension {t:.1f} kN, at or below {equilibrium.SLACK_FRACTION:g} "
                             "of the weight); the layout cannot hold the jacket",
                             file=source, field=f"rigging.wires[{name}]", value=float(t))


def require_balanced(plant: Plant, source="rigging") -> None:
    """Raise InputError naming the largest six-equation residual of a single plant whose
    surge or pitch cannot be balanced (:data:`jls.plant.equilibrium.RESIDUAL_LIMIT`)."""
    if bool(plant.balanced):
        return
    i, value = equilibrium.worst_residual(plant.residual)
    raise InputError(f"the layout does not hold the jacket in equilibrium: {equilibrium.EQUATIONS[int(i)]} "
                     f"residual {float(value):.2e} of the weight (limit {equilibrium.RESIDUAL_LIMIT:g}); "
                     "the jacket would not hang where the model assumes",
                     file=source, field="rigging.wires", value=float(value))


_MATRIX_KEYS = ("M", "K", "Kb", "C", "zeta", "m_grav_t", "g_m_per_s2", "description")


def from_matrices(path, *, g: float, zeta: float) -> Plant:
    """Read a plant given as matrices (YAML or JSON).

    Keys: ``M``, ``K``, ``Kb`` (4x4, rows/columns sway, heave, roll, yaw of the CoG
    and of the hinge), optional ``C`` (4x4) or ``zeta`` (Rayleigh on sway and yaw;
    absent: the configuration's ``zeta``), ``m_grav_t``, ``g_m_per_s2`` (absent: the
    configuration's ``g``). Units t, kN, m, s, rad.
    """
    path = Path(path)
    if path.suffix.lower() == ".json":
        data = _load_json(path)
    else:
        data = yamlio.load(path, what="plant matrices file")
    unknown = sorted(str(k) for k in data if k not in _MATRIX_KEYS)
    if unknown:
        raise InputError(f"unknown key(s); allowed: {', '.join(_MATRIX_KEYS)}", file=path,
                         field=unknown[0], value=unknown)
    if "C" in data and "zeta" in data:
        raise InputError("give C or zeta, not both", file=path, field="zeta", value=data["zeta"])
    mats = {}
    for key in ("M", "K", "Kb", "C"):
        if key not in data:
            if key == "C":
                continue
            raise InputError("missing matrix", file=path, field=key)
        try:
            a = np.asarray(data[key], dtype=float)
        except (TypeError, ValueError):
            raise InputError("must be a 4x4 array of numbers", file=path, field=key,
                             value=data[key]) from None
        if a.shape != (4, 4):
            raise InputError(f"must be 4x4, got shape {a.shape}", file=path, field=key)
        if not np.all(np.isfinite(a)):
            raise InputError("non-finite entry", file=path, field=key, value=data[key])
        mats[key] = a
    if np.any(np.diag(mats["M"]) <= 0):
        raise InputError("mass matrix must have positive diagonal", file=path, field="M",
                         value=np.diag(mats["M"]).tolist())
    if not np.allclose(mats["K"], mats["K"].T, rtol=1e-9, atol=1e-9 * np.abs(mats["K"]).max()):
        raise InputError("stiffness matrix must be symmetric", file=path, field="K")
    try:
        md = modal.modal_analysis(mats["M"], mats["K"])
        modal.require_stable(md)
    except ValueError as exc:
        raise InputError(str(exc), file=path, field="K") from None
    rayleigh = None
    if "C" in mats:
        C = mats["C"]
        ratios = modal.modal_damping_ratios(mats["M"], mats["K"], C, md)
    else:
        zeta = _scalar(data, "zeta", zeta, path, 0.0, 0.5)
        C, alpha, beta, ratios = modal.rayleigh_damping(mats["M"], mats["K"], md, zeta)
        rayleigh = (alpha, beta)
    return Plant(M=mats["M"], K=mats["K"], Kb=mats["Kb"], C=C, modes=md,
                 damping_ratio=ratios, m_grav=_scalar(data, "m_grav_t", np.nan, path, 0.0, 1e5),
                 g=_scalar(data, "g_m_per_s2", g, path, 9.7, 9.9), rayleigh=rayleigh)


def _load_json(path):
    """A JSON plant-matrices file; duplicate keys and non-mappings are errors."""
    def pairs(items):
        out = {}
        for k, v in items:
            if k in out:
                raise InputError("key given twice", file=path, field=k)
            out[k] = v
        return out
    try:
        data = json.loads(yamlio.read_text(path, "plant matrices file"), object_pairs_hook=pairs)
    except json.JSONDecodeError as exc:
        raise InputError(f"not valid JSON: {exc.msg}", file=path,
                         field=f"line {exc.lineno}, column {exc.colno}") from None
    if not isinstance(data, dict):
        raise InputError("the top level must be a mapping with keys M, K, Kb", file=path)
    return data


def _scalar(data, key, default, path, lo, hi):
    """An optional scalar of a matrices file, a finite number within [lo, hi]."""
    if key not in data:
        return float(default)
    v = data[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not lo <= v <= hi:
        raise InputError(f"must be a number within [{lo:g}, {hi:g}]", file=path, field=key,
                         value=v)
    return float(v)


def summary(plant: Plant) -> dict:
    """The ``jls modes --json`` contract for a single plant."""
    out = {
        "dof": list(DOF),
        "natural_period_s": plant.modes.period.tolist(),
        "damping_ratio": np.asarray(plant.damping_ratio).tolist(),
        "energy_fraction": plant.modes.energy_fraction.tolist(),
        "dominant_dof": [DOF[i] for i in plant.modes.dominant],
        "M": plant.M.tolist(), "K": plant.K.tolist(), "Kb": plant.Kb.tolist(),
        "C": np.asarray(plant.C).tolist(),
        "m_grav_t": plant.m_grav, "g_m_per_s2": plant.g,
    }
    if plant.rayleigh is not None:
        out["rayleigh_alpha_per_s"] = float(plant.rayleigh[0])
        out["rayleigh_beta_s"] = float(plant.rayleigh[1])
    if plant.layout is not None:
        side, fore_aft = plant.layout.lead_angles()
        out.update({
            "anchors_m": plant.layout.anchors.tolist(),
            "padeyes_m": plant.layout.padeyes.tolist(),
            "cog_depth_m": float(plant.layout.cog_depth),
            "wire_stiffness_kN_per_m": plant.wire_stiffness.tolist(),
            "tension_kN": plant.tension.tolist(),
            "unstretched_length_m": plant.unstretched_length.tolist(),
            "side_lead_deg": np.degrees(side).tolist(),
            "fore_aft_lead_deg": np.degrees(fore_aft).tolist(),
            "equilibrium_residual": dict(zip(equilibrium.EQUATIONS, plant.residual.tolist())),
            "in_equilibrium": bool(plant.balanced),
        })
    return out


__all__ = ["Jacket", "Plant", "build", "from_matrices", "summary", "require_taut",
           "require_balanced", "mass_matrix"]
