"""Uncertainty bands: how far the workability moves over the plausible plant, and whether
the recommended option survives it.

Section 3.5 of the study identifies the sway damping (0.98 % of critical) from free
decays and places the plausible range at roughly a factor of two in damping (0.51 %
without the block connection system, rising with amplitude and wind) and +/- 3 % in the
sway frequency. Each candidate of a plant dataset is therefore repeated as variants:

* **Damping factor** d (default 0.5, 1, 2): the Rayleigh damping is rebuilt with the
  ratio d x nominal on the same two anchor modes (the plant's ``damping_ratio`` and
  ``damping_anchor_modes`` attributes), C = alpha M + beta K of the variant's K.
* **Sway-frequency factor** f (default 0.97, 1, 1.03): the sway mode's modal stiffness is
  scaled by f^2. With phi the mass-normalised sway mode and w its frequency,

      dK = (f^2 - 1) w^2 (M phi)(M phi)^T,

  which moves the sway frequency by exactly f and leaves every other mode, and every mode
  shape, unchanged (phi_j^T M phi = 0 for the others). The added stiffness acts on the
  jacket's motion relative to the hinge carried rigidly (q = T qb, T the identity with
  T[sway, roll] = CoG depth, a roll about the hinge swinging the CoG sideways), so
  ``dKb = -dK T`` and the rigid-body identities of Kb hold in every variant: a hinge
  motion the jacket follows rigidly strains nothing, whatever f. A stiffness change was
  chosen over a mass change because a mass change would move every mode.

The variants are extra candidates named ``<candidate>|damping x<d>|sway frequency x<f>``
with the coordinates ``base_candidate``, ``damping_factor`` and ``sway_frequency_factor``,
so any response computation that takes a plant dataset takes them unchanged;
:func:`unstack_variants` turns its results back into dims (candidate, damping_factor,
sway_frequency_factor). The Hs of a bin (centre or upper edge) is a third axis, from
:func:`jls.assessment.workability.assess`'s ``hs_in_bin``; :func:`assess_variants` runs both.
:func:`bands` reduces any of these into min / nominal / max per option, and
:func:`workability_bands` also states whether the nominal recommendation (the best
option) holds across the band.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.assessment.workability import assess
from jls.plant import modes as modal
from jls.plant.linearise import DOF

DAMPING_FACTORS = (0.5, 1.0, 2.0)
FREQUENCY_FACTORS = (0.97, 1.0, 1.03)
VARIANT_DIMS = ("damping_factor", "sway_frequency_factor")
SWAY, ROLL = DOF.index("sway"), DOF.index("roll")


def variant_name(candidate: str, damping: float, frequency: float) -> str:
    return f"{candidate}|damping x{damping:g}|sway frequency x{frequency:g}"


def shifted_stiffness(M, K, Kb, cog_depth, factor):
    """K and Kb with the sway mode's frequency multiplied by ``factor`` (module docstring).

    M, K, Kb: (..., 4, 4); cog_depth: (...) [m]; factor: scalar or (...). Returns K', Kb'.
    """
    md = modal.modal_analysis(M, K)
    i = md.mode_of("sway")
    phi = np.take_along_axis(md.shapes, i[..., None, None], -1)[..., 0]          # (..., 4)
    w = np.take_along_axis(md.omega, i[..., None], -1)[..., 0]
    m_phi = np.einsum("...ij,...j->...i", M, phi)
    scale = (np.asarray(factor, float) ** 2 - 1.0) * w**2
    dK = scale[..., None, None] * m_phi[..., :, None] * m_phi[..., None, :]
    T = np.broadcast_to(np.eye(4), dK.shape).copy()
    T[..., SWAY, ROLL] = np.asarray(cog_depth, float)
    return K + dK, Kb - dK @ T


def plant_variants(plant: xr.Dataset, damping_factors=DAMPING_FACTORS,
                   frequency_factors=FREQUENCY_FACTORS) -> xr.Dataset:
    """The plant dataset with every candidate repeated over the damping and sway-frequency
    factors (module docstring). Variables that depend on K or C (``K``, ``Kb``, ``C``,
    ``natural_period``, ``damping_ratio``, ``energy_fraction``, ``mode_shape``,
    ``dominant_dof``) are rebuilt; the static state (geometry, tensions) is kept.

    New candidate coordinates: ``base_candidate``, ``damping_factor`` [-],
    ``sway_frequency_factor`` [-]. Attributes ``damping_factors`` and
    ``sway_frequency_factors`` list the factors.
    """
    if "damping_ratio" not in plant.attrs or "cog_depth" not in plant:
        raise ValueError("plant variants need a geometric plant with Rayleigh damping "
                         "(attribute damping_ratio and variable cog_depth)")
    zeta = float(plant.attrs["damping_ratio"])
    anchors = tuple(str(plant.attrs.get("damping_anchor_modes", "sway yaw")).split())
    d = np.asarray(damping_factors, float)
    f = np.asarray(frequency_factors, float)
    if np.any(d <= 0) or np.any(f <= 0):
        raise ValueError("damping and frequency factors must be positive")
    names = plant["candidate"].values
    base, dd, ff = (a.ravel() for a in np.meshgrid(np.arange(names.size), d, f, indexing="ij"))
    base = base.astype(int)
    out = plant.isel(candidate=base)
    M = out["M"].transpose("candidate", "dof", "dof_col").values
    K0 = out["K"].transpose("candidate", "dof", "dof_col").values
    Kb0 = out["Kb"].transpose("candidate", "dof", "hinge_dof").values
    K, Kb = shifted_stiffness(M, K0, Kb0, out["cog_depth"].values, ff)
    md = modal.modal_analysis(M, K)
    C = np.empty_like(K)
    ratios = np.empty(K.shape[:-1])
    for factor in np.unique(dd):
        sel = dd == factor
        sub = modal.Modes(omega=md.omega[sel], shapes=md.shapes[sel],
                          energy_fraction=md.energy_fraction[sel])
        C[sel], _, _, ratios[sel] = modal.rayleigh_damping(M[sel], K[sel], sub, zeta * factor, anchors)
    new = {"K": (("candidate", "dof", "dof_col"), K), "Kb": (("candidate", "dof", "hinge_dof"), Kb),
           "C": (("candidate", "dof", "dof_col"), C),
           "natural_period": (("candidate", "mode"), md.period),
           "damping_ratio": (("candidate", "mode"), ratios),
           "energy_fraction": (("candidate", "mode", "dof"), md.energy_fraction),
           "mode_shape": (("candidate", "dof", "mode"), md.shapes),
           "dominant_dof": (("candidate", "mode"), md.dominant.astype(np.int8))}
    for name, (dims, values) in new.items():
        out[name] = xr.DataArray(values, dims=dims, attrs=out[name].attrs)
    out = out.assign_coords(
        candidate=[variant_name(str(names[b]), x, y) for b, x, y in zip(base, dd, ff)],
        base_candidate=("candidate", names[base]),
        damping_factor=("candidate", dd), sway_frequency_factor=("candidate", ff))
    out["damping_factor"].attrs.update(long_name="damping ratio over its nominal value", units="1")
    out["sway_frequency_factor"].attrs.update(long_name="sway natural frequency over its nominal value",
                                              units="1")
    out.attrs.update(damping_factors=d.tolist(), sway_frequency_factors=f.tolist(),
                     sway_frequency_shift="sway-mode modal stiffness scaled by the factor squared")
    return out


def unstack_variants(ds: xr.Dataset | xr.DataArray, variants: xr.Dataset):
    """Results over the variant candidates of ``variants`` -> dims (candidate,
    damping_factor, sway_frequency_factor), ``candidate`` the original names."""
    lookup = variants[["base_candidate", *VARIANT_DIMS]].to_dataframe()
    names = [str(c) for c in ds["candidate"].values]
    unknown = sorted(set(names) - set(lookup.index))
    if unknown:
        raise ValueError(f"candidates {unknown[:3]} are not variants of this plant")
    rows = lookup.loc[names]
    ds = ds.assign_coords(base_candidate=("candidate", rows["base_candidate"].to_numpy()),
                          **{k: ("candidate", rows[k].to_numpy()) for k in VARIANT_DIMS})
    ds = ds.set_index(candidate=["base_candidate", *VARIANT_DIMS]).unstack("candidate")
    return ds.rename(base_candidate="candidate").transpose("candidate", ...)


def assess_variants(response: xr.Dataset, sea: xr.Dataset, criteria: dict, variants: xr.Dataset,
                    hs_in_bin=("centre", "upper"), adjust=None, **kwargs) -> xr.Dataset:
    """Workability over the plant variants and the Hs-in-bin choices.

    response: unit-Hs statistics of the variant candidates; returns the workability
    dataset of :func:`jls.assessment.workability.assess` (without per-cell variables) with dims
    candidate, damping_factor, sway_frequency_factor, hs_in_bin. ``adjust(work, h)``, when
    given, amends each assessment (Hs-in-bin choice ``h``) before it is kept, e.g. with
    the winch limits.
    """
    keep = ("workability_leg", "workability_route", "governing_share", "hs_limit")
    runs = []
    for h in hs_in_bin:
        work = assess(response, sea, criteria, hs_in_bin=h, **kwargs)
        runs.append((adjust(work, h) if adjust else work)[list(keep)])
    out = xr.concat(runs, dim=xr.DataArray(list(hs_in_bin), dims="hs_in_bin"))
    return unstack_variants(out, variants)


def bands(work: xr.DataArray, nominal: dict) -> xr.Dataset:
    """Lowest, nominal and highest workability over the variant dims named in ``nominal``
    (their nominal values, e.g. ``{"damping_factor": 1.0, "sway_frequency_factor": 1.0,
    "hs_in_bin": "centre"}``); any other dims (candidate, tugger, leg) are kept.

    Variables ``workability_min``, ``workability_nominal``, ``workability_max``, each
    over the remaining dims, in 1.
    """
    dims = list(nominal)
    missing = [d for d in dims if d not in work.dims]
    if missing:
        raise ValueError(f"nominal names dims the workability does not have: {missing}")
    out = xr.Dataset({"workability_min": work.min(dims), "workability_nominal": work.sel(nominal),
                      "workability_max": work.max(dims)})
    for name, text in (("workability_min", "lowest workability over the variants"),
                       ("workability_nominal", "workability of the nominal plant"),
                       ("workability_max", "highest workability over the variants")):
        out[name].attrs.update(long_name=text, units="1")
    out.attrs.update(variant_dims=" ".join(dims),
                     nominal=", ".join(f"{k} = {v}" for k, v in nominal.items()))
    return out


def workability_bands(work: xr.DataArray, nominal: dict, *, feasible: xr.DataArray | None = None,
                      tolerance=1e-9) -> xr.Dataset:
    """Bands of route workability and whether the recommendation holds across them.

    work: route workability with dims candidate, tugger and the variant dims named in
    ``nominal`` (see :func:`bands`); feasible: (candidate) flag, the options (candidate,
    tugger pairs) restricted to feasible candidates when given. The recommended option
    is the best under the nominal plant.

    Variables (besides those of :func:`bands`, over candidate, tugger):

    ============================ ============================== ===== =========================
    ``is_best``                  candidate, tugger, <variants>  flag  the option is (one of) the
                                                                      best in the variant
    ``recommendation_holds``     ()                             flag  the recommended option is
                                                                      best in every variant
    ``recommendation_dominates`` ()                             flag  its lowest value reaches
                                                                      every other option's
                                                                      highest
    ============================ ============================== ===== =========================

    Attributes ``recommended_candidate``, ``recommended_tugger``.
    """
    out = bands(work, nominal)
    dims = list(nominal)
    extra = set(work.dims) - {"candidate", "tugger", *dims}
    if extra:
        raise ValueError(f"a recommendation is judged on route workability; reduce {sorted(extra)} first")
    options = work if feasible is None else work.where(feasible.astype(bool))
    nom = options.sel(nominal)
    if not np.isfinite(nom.values).any():
        raise ValueError("no feasible option to recommend")
    c, t = np.unravel_index(int(np.nanargmax(nom.transpose("candidate", "tugger").values)),
                            (nom.sizes["candidate"], nom.sizes["tugger"]))
    best = (nom["candidate"].values[c], nom["tugger"].values[t])
    is_best = options >= options.max(("candidate", "tugger")) - tolerance
    mine = options.sel(candidate=best[0], tugger=best[1])
    is_other = ~((options["candidate"] == best[0]) & (options["tugger"] == best[1]))
    others_max = options.where(is_other).max()
    out["is_best"] = is_best.transpose("candidate", "tugger", ...)
    out["recommendation_holds"] = is_best.sel(candidate=best[0], tugger=best[1]).all()
    out["recommendation_dominates"] = (mine.min() >= others_max - tolerance) | others_max.isnull()
    for name, text in (("is_best", "option is the best (within tolerance) in the variant"),
                       ("recommendation_holds", "the recommended option is best in every variant"),
                       ("recommendation_dominates", "the recommended option's lowest value reaches "
                                                    "every other option's highest")):
        out[name].attrs.update(long_name=text, units="1")
    out.attrs.update(recommended_candidate=str(best[0]), recommended_tugger=str(best[1]))
    return out


__all__ = ["DAMPING_FACTORS", "FREQUENCY_FACTORS", "variant_name", "shifted_stiffness",
           "plant_variants", "unstack_variants", "assess_variants", "bands", "workability_bands"]
