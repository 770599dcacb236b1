"""Make the fine-grid RAOs of a ship-shaped hull: tests/data/vessel/ship_form_fine.nc.

The data of the test of the RAO interpolation order (tests/test_vessel_interpolation.py):
the pipeline interpolates the vessel's six RAOs per DOF onto its grid and then carries
them to the hinge (jls.vessel.transfer.motion_on_grid); the test subsamples this file to
about 40 frequencies and checks that the relative sway computed from the coarse file
stays within 2 % of the fine one at oblique headings, and that the other order
(interpolating the hinge motion) does worse.

How it was made (python scripts/make_rao_interpolation_data.py, needs the "bem" extra,
about 15 min on 2 cores):

* hull: jls.vessel.hulls.ship_hull(300, 50, 15, panel_size=6): a 300 m x 50 m ship
  form at 15 m draught, parallel middle body half the length, a fine entrance
  (1 - s^2) and a fuller run (1 - s^3), rounded bilge (1 - (z/T)^6); 700 hull panels
  and 156 lid panels of 12 m (irregular-frequency removal), centreplane symmetry;
* mass: the displaced mass, floating level; CoG on the centre of buoyancy's vertical,
  2 m below the waterline (KG 13 m, GM about 9.9 m); radii of gyration 0.38 B,
  0.25 L, 0.26 L; viscous roll damping 5 % of critical (bilge keels);
* Capytaine (deep water), frequencies 0.10-1.50 rad/s every 0.006 and 1.55-3.00 every
  0.05 (264), wave directions 0, 30, 50, 90, 130, 150, 180 deg;
* the RAOs refer to the CoG (reference_point_m in the mesh frame, z = 0 at the
  waterline).

Above about 1.3 rad/s the 6 m panels no longer resolve the waves; the test compares the
file with its own subsample, so that does not matter there.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "data" / "vessel" / "ship_form_fine.nc"
HULL = {"length": 300.0, "beam": 50.0, "draught": 15.0, "panel_size": 6.0}
COG_Z = -2.0
RADII_FACTORS = (0.38, 0.25, 0.26)          # kxx / B, kyy / L, kzz / L
ROLL_DAMPING = 0.05
HEADINGS_DEG = (0.0, 30.0, 50.0, 90.0, 130.0, 150.0, 180.0)


def fine_omega() -> np.ndarray:
    return np.unique(np.round(np.concatenate([np.arange(0.10, 1.5 + 1e-9, 0.006),
                                              np.arange(1.55, 3.0 + 1e-9, 0.05)]), 6))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    from jls.io.hashing import file_sha256
    from jls.vessel.bem import compute_hull_raos
    from jls.vessel.hulls import ship_hull
    from jls.vessel.rao import save_rao

    hm = ship_hull(HULL["length"], HULL["beam"], HULL["draught"], HULL["panel_size"])
    radii = (RADII_FACTORS[0] * HULL["beam"], RADII_FACTORS[1] * HULL["length"],
             RADII_FACTORS[2] * HULL["length"])
    start = time.perf_counter()
    ds = compute_hull_raos(hm, COG_Z, radii, ROLL_DAMPING, fine_omega(),
                           np.radians(HEADINGS_DEG))
    ds.attrs.update({
        "title": "fine-grid RAOs of a ship-shaped hull (Capytaine), interpolation test data",
        "source": "scripts/make_rao_interpolation_data.py",
        "source_sha256": file_sha256(Path(__file__)),
        "note": "a ship form of jls.vessel.hulls.ship_hull, not any particular vessel's data",
        "radii_of_gyration_m": list(radii),
        "run_time_s": round(time.perf_counter() - start, 1),
    })
    save_rao(ds, args.out)
    print(f"wrote {args.out} ({args.out.stat().st_size / 1e3:.0f} kB): {ds.sizes['omega']} "
          f"frequencies, {ds.sizes['wave_direction']} headings, roll period "
          f"{ds.attrs['roll_natural_period_s']:.2f} s, GM {ds.attrs['gm_t_m']:.2f} m, "
          f"{ds.attrs['run_time_s']:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
