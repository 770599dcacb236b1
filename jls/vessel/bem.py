"""Optional BEM computation of vessel RAOs with Capytaine (the "bem" extra).

Three entry points, all returning the jls RAO dataset (reference point = CoG unless
another is asked for):

* :func:`compute_box_raos` for a rectangular barge of given main dimensions
  (the box alternative of scripts/make_default_vessel.py);
* :func:`compute_hull_raos` for a parametric hull of :mod:`jls.vessel.hulls` (the
  slotted twin hull of the default vessel, the ship form of the interpolation test
  data), floating level with its CoG above the centre of buoyancy;
* :func:`compute_mesh_raos` for a hull mesh file (GDF, PNL, STL, ... - any
  format capytaine.load_mesh reads).

Units are t, kN, m, s throughout (Capytaine is run with rho in t/m^3, so its
forces come out in kN and its masses in t). Rigid-body mass matrix about the
CoG: diag(m, m, m, m kxx^2, m kyy^2, m kzz^2). A linear viscous roll damping
of ``roll_damping_ratio`` of critical at the undamped roll natural frequency
(including the roll added inertia there) is added to the roll-roll damping:
B44v = 2 zeta sqrt(C44 (I44 + A44(omega_n))). Irregular frequencies are
removed with a lid just below the free surface. Capytaine is imported only
when a computation is asked for.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io.hashing import file_sha256
from jls.vessel.bem_motion import (
    CPT_DOFS as _CPT_DOFS,
)
from jls.vessel.bem_motion import (
    capytaine,
    rao_from_hydrodynamics,
    roll_natural_frequency,
    with_mass_properties,
)

RHO_SEAWATER = 1.025  # t/m^3
G = 9.81  # m/s^2
__all__ = ["box_hydrostatics", "box_mesh", "compute_box_raos", "compute_hull_raos",
           "compute_mesh_raos", "half_mesh", "hull_hydrodynamics", "hull_raos",
           "rao_from_hydrodynamics", "roll_natural_frequency", "solve_hydrodynamics",
           "with_mass_properties"]


_capytaine = capytaine


def box_hydrostatics(length, beam, draught, kg, rho=RHO_SEAWATER, g=G) -> dict:
    """Analytical hydrostatics of a rectangular box floating level (t, kN, m)."""
    for name, value in (("length", length), ("beam", beam), ("draught", draught),
                        ("kg", kg)):
        if not np.isfinite(value) or value <= 0:
            raise InputError("must be a positive length in m", field=name, value=value)
    volume = length * beam * draught
    mass = rho * volume
    kb = draught / 2
    bm_t = beam ** 2 / (12 * draught)
    bm_l = length ** 2 / (12 * draught)
    gm_t = kb + bm_t - kg
    gm_l = kb + bm_l - kg
    if gm_t <= 0:
        raise InputError("box is unstable in roll (GM <= 0): lower KG", field="kg", value=kg)
    weight = mass * g
    return {"volume_m3": volume, "displacement_t": mass, "kb_m": kb, "bm_t_m": bm_t,
            "bm_l_m": bm_l, "gm_t_m": gm_t, "gm_l_m": gm_l,
            "waterplane_area_m2": length * beam,
            "c33_kn_m": rho * g * length * beam, "c44_knm_rad": weight * gm_t,
            "c55_knm_rad": weight * gm_l, "cog_z_m": kg - draught}


def box_mesh(length, beam, draught, panel_size):
    """Doubly symmetric (centreplane and midship) panel mesh of the wetted box."""
    cpt = _capytaine()
    if not np.isfinite(panel_size) or panel_size <= 0:
        raise InputError("panel_size must be a positive length in m", field="panel_size",
                         value=panel_size)
    resolution = (2 * max(1, int(np.ceil(length / panel_size / 2))),
                  2 * max(1, int(np.ceil(beam / panel_size / 2))),
                  max(1, int(np.ceil(draught / panel_size))))
    return cpt.mesh_parallelepiped(size=(length, beam, draught), center=(0, 0, -draught / 2),
                                   resolution=resolution, missing_sides={"top"},
                                   reflection_symmetry=True, name="box")


def compute_box_raos(length, beam, draught, kg, radii, roll_damping_ratio, omega, headings,
                     *, panel_size=8.0, rho=RHO_SEAWATER, g=G, lid=True,
                     n_jobs=1) -> xr.Dataset:
    """RAOs at the CoG of a box hull (length x beam, draught, KG above keel).

    radii: radii of gyration (kxx, kyy, kzz) in m about the CoG.
    omega: wave angular frequencies in rad/s; headings: wave directions in
    rad (direction of propagation, 0 following, pi/2 beam from starboard,
    pi head seas). panel_size: target panel side in m.
    """
    start = time.perf_counter()
    hydro = box_hydrostatics(length, beam, draught, kg, rho, g)
    mesh = box_mesh(length, beam, draught, panel_size)
    cog = np.array([0.0, 0.0, hydro["cog_z_m"]])
    stiffness = np.zeros((6, 6))
    stiffness[2, 2] = hydro["c33_kn_m"]
    stiffness[3, 3] = hydro["c44_knm_rad"]
    stiffness[4, 4] = hydro["c55_knm_rad"]
    ds = _solve(mesh, cog, hydro["displacement_t"], radii, stiffness, roll_damping_ratio,
                omega, headings, rho=rho, g=g, lid=lid, lid_z=-0.02 * draught, n_jobs=n_jobs)
    ds.attrs.update({
        "source": "jls.vessel.bem.compute_box_raos", "source_sha256": "",
        "source_format": "capytaine-bem",
        "hull": f"rectangular box {length:g} m x {beam:g} m, draught {draught:g} m",
        "kg_m": float(kg), "panel_size_m": float(panel_size),
        **{f"hydrostatics_{k}": float(v) for k, v in hydro.items()},
        "run_time_s": round(time.perf_counter() - start, 1),
    })
    return ds


def compute_mesh_raos(mesh_file, mass, center_of_mass, radii, roll_damping_ratio, omega,
                      headings, *, symmetry: str | None = None, mesh_format=None,
                      rho=RHO_SEAWATER, g=G, lid=True, n_jobs=1,
                      mass_tolerance=0.02) -> xr.Dataset:
    """RAOs at the CoG of a hull given as a mesh file (vessel frame, z=0 waterline).

    mass in t (must equal the displaced mass within ``mass_tolerance``),
    center_of_mass (x, y, z) in m in the mesh frame, radii (kxx, kyy, kzz)
    in m about the CoG. ``symmetry="xOz"`` rebuilds the mesh from its y < 0
    half with centreplane symmetry (half the cost) when the file carries none.
    Hydrostatic stiffness comes from Capytaine (waterplane and volume).
    """
    cpt = _capytaine()
    start = time.perf_counter()
    path = Path(mesh_file)
    if not path.is_file():
        raise InputError("mesh file not found", file=path, field="mesh_file", value=str(path))
    try:
        mesh = cpt.load_mesh(path, file_format=mesh_format)
    except Exception as exc:  # capytaine raises assorted types on bad files
        raise InputError(f"cannot read mesh: {exc}", file=path) from exc
    mesh = mesh.immersed_part()
    if symmetry == "xOz" and not isinstance(mesh, cpt.ReflectionSymmetricMesh):
        full_volume = mesh.volume
        half = mesh.clipped(origin=(0, 0, 0), normal=(0, 1, 0))
        mesh = cpt.ReflectionSymmetricMesh(half, plane="xOz", name=path.stem)
        if not np.isclose(mesh.volume, full_volume, rtol=0.01):
            raise InputError("mesh is not symmetric about the centreplane y = 0",
                             file=path, field="symmetry", value=symmetry)
    elif symmetry not in (None, "xOz"):
        raise InputError("symmetry must be None or 'xOz'", file=path, field="symmetry",
                         value=symmetry)
    cog = np.asarray(center_of_mass, float)
    if cog.shape != (3,) or not np.all(np.isfinite(cog)):
        raise InputError("center_of_mass must be three finite numbers", file=path,
                         field="center_of_mass", value=np.asarray(center_of_mass).tolist())
    # second-order quadrature: waterplane moments exact on flat panels
    probe = cpt.FloatingBody(mesh=mesh.with_quadrature("Gauss-Legendre 2"),
                             dofs=cpt.rigid_body_dofs(rotation_center=cog),
                             center_of_mass=cog, mass=mass, name=path.stem)
    displaced = probe.disp_mass(rho=rho)
    if not np.isfinite(mass) or abs(mass - displaced) > mass_tolerance * displaced:
        raise InputError(f"mass must equal the displaced mass {displaced:.6g} t "
                         f"(free floating)", file=path, field="mass", value=mass)
    stiffness = np.asarray(probe.compute_hydrostatic_stiffness(rho=rho, g=g)
                           .sel(influenced_dof=list(_CPT_DOFS),
                                radiating_dof=list(_CPT_DOFS)).values, float)
    draught = -float(mesh.vertices[:, 2].min())
    ds = _solve(mesh, cog, float(mass), radii, stiffness, roll_damping_ratio, omega,
                headings, rho=rho, g=g, lid=lid, lid_z=-0.02 * draught, n_jobs=n_jobs)
    ds.attrs.update({"source": path.name, "source_sha256": file_sha256(path),
                     "source_format": "capytaine-bem (mesh file)",
                     "run_time_s": round(time.perf_counter() - start, 1)})
    return ds


def half_mesh(hm):
    """Capytaine meshes (hull, lid) of a :class:`jls.vessel.hulls.HalfMesh`, both
    reflection-symmetric about the centreplane (the solver works on half-size blocks)."""
    cpt = _capytaine()
    hull = cpt.ReflectionSymmetricMesh(cpt.Mesh(hm.vertices, hm.faces, name="hull half"),
                                       plane="xOz", name="hull")
    lid = cpt.ReflectionSymmetricMesh(cpt.Mesh(hm.lid_vertices, hm.lid_faces, name="lid half",
                                               auto_check=False), plane="xOz", name="lid")
    return hull, lid


def hull_hydrodynamics(hm, omega, headings, *, rho=RHO_SEAWATER, g=G, n_jobs=1) -> xr.Dataset:
    """Capytaine hydrodynamic dataset of a parametric hull (:mod:`jls.vessel.hulls`) with
    the rigid-body DOFs about O, the waterline point above the centre of buoyancy
    (attrs ``rotation_center_m``), and the buoyancy part of the hydrostatic stiffness
    about O (``hydrostatic_stiffness``, the weight's share added by :func:`hull_raos`):
    solved once, it gives the RAOs for any CoG height, radii and roll damping."""
    cpt = _capytaine()
    mesh, lid = half_mesh(hm)
    probe = cpt.FloatingBody(mesh=mesh.with_quadrature("Gauss-Legendre 2"),
                             dofs=cpt.rigid_body_dofs(), name="probe")
    centre = np.array([float(probe.center_of_buoyancy[0]), 0.0, 0.0])
    mass = float(probe.disp_mass(rho=rho))
    probe = cpt.FloatingBody(mesh=mesh.with_quadrature("Gauss-Legendre 2"),
                             dofs=cpt.rigid_body_dofs(rotation_center=centre),
                             center_of_mass=centre, mass=mass, name="probe")
    stiffness = np.asarray(probe.compute_hydrostatic_stiffness(rho=rho, g=g)
                           .sel(influenced_dof=list(_CPT_DOFS),
                                radiating_dof=list(_CPT_DOFS)).values, float)
    radii, omega, headings = _check_inputs((1.0, 1.0, 1.0), 0.0, omega, headings)
    hdb = solve_hydrodynamics(mesh, centre, mass, radii, stiffness, omega, headings, rho=rho,
                              g=g, lid=lid, n_jobs=n_jobs)
    hdb.attrs.update({"rotation_center_m": centre.tolist(), "displacement_t": mass,
                      "volume_m3": mass / rho, "hull": hm.description})
    return hdb


def hull_raos(hdb: xr.Dataset, cog_z, radii, roll_damping_ratio, *, reference_point=None,
              g=G) -> xr.Dataset:
    """RAOs of a :func:`hull_hydrodynamics` hull floating level with its CoG on O's
    vertical at height ``cog_z`` (m, z = 0 at the waterline), radii of gyration about the
    CoG; about the CoG, or about ``reference_point`` (mesh frame) when given."""
    from jls.vessel.transfer import shift_reference_point
    centre = np.asarray(hdb.attrs["rotation_center_m"], float)
    mass = float(hdb.attrs["displacement_t"])
    cog = centre + (0.0, 0.0, float(cog_z))
    stiffness = hdb["hydrostatic_stiffness"].sel(influenced_dof=list(_CPT_DOFS),
                                                 radiating_dof=list(_CPT_DOFS)).values.copy()
    stiffness[3, 3] -= mass * g * float(cog_z)    # the weight acting at the CoG, above O
    stiffness[4, 4] -= mass * g * float(cog_z)
    if not stiffness[3, 3] > 0:
        raise InputError("the hull is unstable in roll (GM <= 0): lower the CoG", field="cog_z",
                         value=cog_z)
    radii, _, _ = _check_inputs(radii, roll_damping_ratio, hdb["omega"].values,
                                hdb["wave_direction"].values)
    ds = rao_from_hydrodynamics(with_mass_properties(hdb, mass, cog, radii, stiffness),
                                roll_damping_ratio)
    ds.attrs.update({"source": "jls.vessel.bem.hull_raos", "source_sha256": "",
                     "source_format": "capytaine-bem", "cog_m": cog.tolist(),
                     "gm_t_m": float(stiffness[3, 3] / (mass * g)),
                     "gm_l_m": float(stiffness[4, 4] / (mass * g))})
    if reference_point is not None:
        ds = shift_reference_point(ds, np.subtract(reference_point, cog))
    return ds


def compute_hull_raos(hm, cog_z, radii, roll_damping_ratio, omega, headings, *,
                      reference_point=None, rho=RHO_SEAWATER, g=G, n_jobs=1) -> xr.Dataset:
    """RAOs of a parametric hull (:mod:`jls.vessel.hulls`) floating level and free: the
    displaced mass, the CoG on the centre of buoyancy's vertical at ``cog_z``
    (:func:`hull_hydrodynamics` then :func:`hull_raos`)."""
    start = time.perf_counter()
    hdb = hull_hydrodynamics(hm, omega, headings, rho=rho, g=g, n_jobs=n_jobs)
    ds = hull_raos(hdb, cog_z, radii, roll_damping_ratio, reference_point=reference_point, g=g)
    ds.attrs["run_time_s"] = round(time.perf_counter() - start, 1)
    return ds


def _make_lid(mesh, z):
    """Lid at z for irregular-frequency removal, panels no larger than the hull's.

    Capytaine's default lid panel size can exceed a coarse hull's waterplane
    and then leaves no lid panel at all; the lid is asked for with the median
    hull panel radius, halved until it covers the waterplane.
    """
    radius = float(np.median(mesh.faces_radiuses))
    for _ in range(4):
        lid = mesh.generate_lid(z=z, faces_max_radius=radius)
        if lid.nb_faces > 0:
            return lid
        radius /= 2
    raise InputError("could not mesh a lid inside the waterline for irregular-frequency "
                     "removal; pass lid=False", field="lid", value=z)


def _release_caches():
    """Free Capytaine 3.0's per-frequency matrix cache of doubly symmetric meshes.

    NestedBlockCirculantMatrix.to_BlockCirculantMatrix is an lru_cache on a
    method, which keeps every frequency's influence matrices alive (about
    0.5 GB per frequency for the default hull); clearing it after each
    frequency keeps the memory flat.
    """
    try:
        from capytaine.tools.block_circulant_matrices import NestedBlockCirculantMatrix
    except ImportError:  # pragma: no cover - other Capytaine versions
        return
    method = getattr(NestedBlockCirculantMatrix, "to_BlockCirculantMatrix", None)
    if hasattr(method, "cache_clear"):
        method.cache_clear()


def _check_inputs(radii, roll_damping_ratio, omega, headings):
    radii = np.asarray(radii, float)
    if radii.shape != (3,) or not np.all(np.isfinite(radii)) or np.any(radii <= 0):
        raise InputError("radii must be three positive radii of gyration in m",
                         field="radii", value=np.asarray(radii).tolist())
    if not np.isfinite(roll_damping_ratio) or not 0 <= roll_damping_ratio < 1:
        raise InputError("roll_damping_ratio must be within [0, 1)",
                         field="roll_damping_ratio", value=roll_damping_ratio)
    omega = np.asarray(omega, float)
    if omega.ndim != 1 or omega.size < 2 or not np.all(np.isfinite(omega)) \
            or np.any(omega <= 0) or np.any(np.diff(omega) <= 0):
        raise InputError("omega must be ascending positive values in rad/s", field="omega",
                         value=omega.tolist()[:5])
    headings = np.atleast_1d(np.asarray(headings, float))
    if headings.ndim != 1 or not np.all(np.isfinite(headings)) \
            or np.unique(headings).size != headings.size:
        raise InputError("headings must be distinct finite wave directions in rad",
                         field="headings", value=headings.tolist())
    return radii, omega, headings


def _solve(mesh, cog, mass, radii, stiffness, zeta, omega, headings, *, rho, g, lid, lid_z,
           n_jobs):
    radii, omega, headings = _check_inputs(radii, zeta, omega, headings)
    hdb = solve_hydrodynamics(mesh, cog, mass, radii, stiffness, omega, headings, rho=rho,
                              g=g, lid=lid, lid_z=lid_z, n_jobs=n_jobs)
    return rao_from_hydrodynamics(hdb, zeta)


def solve_hydrodynamics(mesh, cog, mass, radii, stiffness, omega, headings, *,
                        rho=RHO_SEAWATER, g=G, lid=True, lid_z=-0.4, n_jobs=1) -> xr.Dataset:
    """Capytaine hydrodynamic dataset (added mass, damping, excitation) of a hull mesh.

    Adds ``inertia_matrix`` (about ``cog``) and ``hydrostatic_stiffness`` and
    records mesh facts in attrs. Capytaine's own time convention exp(-i omega t).
    """
    cpt = _capytaine()
    radii = np.asarray(radii, float)
    if lid is True:
        lid_mesh = _make_lid(mesh, lid_z)
    else:                                   # False: none; or a lid mesh of the caller's
        lid_mesh = lid or None
        lid_z = None if lid_mesh is None else float(np.mean(lid_mesh.vertices[:, 2]))
    body = cpt.FloatingBody(mesh=mesh, lid_mesh=lid_mesh,
                            dofs=cpt.rigid_body_dofs(rotation_center=cog),
                            center_of_mass=cog, mass=mass, name="hull")
    inertia = np.diag([mass, mass, mass, mass * radii[0] ** 2, mass * radii[1] ** 2,
                       mass * radii[2] ** 2])
    solver = cpt.BEMSolver()
    parts = []
    for w in np.asarray(omega, float):   # one frequency at a time: see _release_caches
        test = xr.Dataset(coords={"omega": [w],
                                  "wave_direction": np.asarray(headings, float),
                                  "radiating_dof": list(_CPT_DOFS), "water_depth": np.inf,
                                  "rho": rho, "g": g})
        parts.append(solver.fill_dataset(test, body, n_jobs=n_jobs, progress_bar=False,
                                         _check_wavelength=False))
        _release_caches()
    ds = xr.concat(parts, dim="omega", data_vars="minimal", coords="minimal",
                   compat="override", combine_attrs="drop_conflicts")
    labels = {"influenced_dof": list(_CPT_DOFS), "radiating_dof": list(_CPT_DOFS)}
    ds["inertia_matrix"] = xr.DataArray(inertia, dims=list(labels), coords=labels)
    ds["hydrostatic_stiffness"] = xr.DataArray(np.asarray(stiffness, float),
                                               dims=list(labels), coords=labels)
    lid_faces = 0 if lid_mesh is None else int(lid_mesh.nb_faces)
    ds.attrs.update({
        "mass_t": float(mass), "cog_m": np.asarray(cog, float).tolist(),
        "rotation_center_m": np.asarray(cog, float).tolist(),
        "radii_of_gyration_m": radii.tolist(),
        "mesh_panels_hull": int(mesh.nb_faces), "mesh_panels_lid": lid_faces,
        "mesh_max_panel_radius_m": float(mesh.faces_radiuses.max()),
        "bem_shortest_resolved_wavelength_m": float(body.minimal_computable_wavelength),
        "bem_highest_resolved_omega_rad_s": float(
            np.sqrt(2 * np.pi * g / body.minimal_computable_wavelength)),
        "bem_first_irregular_omega_rad_s": float(body.first_irregular_frequency_estimate(g=g)),
        "bem_solver": f"capytaine {cpt.__version__}, deep water, lid at z = {lid_z:g} m"
                      if lid_mesh is not None else f"capytaine {cpt.__version__}, deep water, no lid",
        "rho_t_m3": float(rho), "g_m_s2": float(g),
    })
    return ds
