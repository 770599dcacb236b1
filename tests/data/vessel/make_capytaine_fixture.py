"""Regenerate the Capytaine RAO fixtures in this folder (needs the "bem" extra).

A small floating box (20 m x 10 m x 5 m draught) solved by Capytaine at a few
frequencies and two headings; the RAO from capytaine.post_pro.rao is written
twice: split into re/im with capytaine.io.xarray.separate_complex_values
(``capytaine_rao_split.nc``) and as separate ``rao_re``/``rao_im`` variables
with radiating_dof names in lower case (``capytaine_rao_reim.nc``), the two
layouts read_capytaine_nc accepts. Run: python make_capytaine_fixture.py
"""

from pathlib import Path

import numpy as np
import xarray as xr


def main():
    import capytaine as cpt
    from capytaine.io.xarray import separate_complex_values
    from capytaine.post_pro.rao import rao

    here = Path(__file__).parent
    length, beam, draught, rho = 20.0, 10.0, 5.0, 1025.0
    mesh = cpt.mesh_parallelepiped(size=(length, beam, draught), center=(0, 0, -draught / 2),
                                   resolution=(8, 4, 2), missing_sides={"top"})
    cog = (0.0, 0.0, -1.0)
    body = cpt.FloatingBody(mesh=mesh, dofs=cpt.rigid_body_dofs(rotation_center=cog),
                            center_of_mass=cog, name="box")
    body.inertia_matrix = body.compute_rigid_body_inertia(rho=rho)
    body.hydrostatic_stiffness = body.compute_hydrostatic_stiffness(rho=rho)
    test = xr.Dataset(coords={"omega": [0.4, 0.8, 1.2, 1.6, 2.0],
                              "wave_direction": [np.pi / 2, np.pi],
                              "radiating_dof": list(body.dofs), "water_depth": np.inf,
                              "rho": rho})
    ds = cpt.BEMSolver().fill_dataset(test, body, progress_bar=False)
    ds["inertia_matrix"] = body.inertia_matrix
    ds["hydrostatic_stiffness"] = body.hydrostatic_stiffness
    motion = rao(ds)
    split = separate_complex_values(motion.to_dataset(name="rao"))
    split["radiating_dof"] = split["radiating_dof"].astype(str)
    split.to_netcdf(here / "capytaine_rao_split.nc")
    reim = xr.Dataset({"rao_re": motion.real, "rao_im": motion.imag})
    reim["radiating_dof"] = [str(d).lower() for d in motion["radiating_dof"].values]
    reim = reim.transpose("radiating_dof", "wave_direction", "omega")
    reim.to_netcdf(here / "capytaine_rao_reim.nc")


if __name__ == "__main__":
    main()
