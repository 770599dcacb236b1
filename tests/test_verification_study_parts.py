"""The study comparison in parts (jls.verify.study.study_part and assemble): each part a job
of its own in the workflow, the assembled dataset the one the whole comparison gives."""

import numpy as np
import pytest
import xarray as xr

from jls.io import registry
from jls.verify import chapter4, reference_available, study
from jls.verify.names import STUDY_PARTS

OK, WHY = reference_available()
TOL = 0.10


def part(name, labels, hs, tz, mpm):
    """A part with the given records: the MPM ratio as given, the rest derived from it."""
    hs, mpm = np.asarray(hs, float), np.asarray(mpm, float)
    ds = xr.Dataset(coords={"record": list(labels), "hs": ("record", hs), "tz": ("record", np.asarray(tz, float))})
    for v, values in (("sigma_rom", mpm), ("sigma_reference", np.ones(hs.size)), ("sigma_ratio", mpm),
                      ("mpm_ratio", mpm), ("mpm_reference", 10.0 * hs), ("slack_fraction", np.zeros(hs.size))):
        ds[v] = ("record", values)
    ds["wall_time"] = ((), 1.5)
    ds.attrs.update(part=name, heading_deg=90.0, gamma=3.3, duration_s=1200.0, transient_s=100.0, dt_s=0.1,
                    seed=1, kinematics="rigid", tolerance=TOL)
    registry.annotate(ds, study.PART_LAYOUT)
    registry.check(ds, study.PART_LAYOUT)
    return ds


def table_parts():
    return [part("table-1", ["V1", "V2", "V3"], [2.4, 2.4, 2.5], [4.3, 6.6, 7.5], [0.99, 1.0, 1.01]),
            part("table-2", ["V4", "S1"], [2.4, 2.7], [8.5, 9.0], [1.07, 1.17])]


def test_the_parts_cover_the_table_and_the_range_once():
    tables = [s for k, v in STUDY_PARTS.items() if k.startswith("table") for s in v]
    assert sorted(tables) == sorted(r[0] for r in study.TABLE_4_4)
    ranges = [v for k, v in STUDY_PARTS.items() if k.startswith("range")]
    assert ranges[0][0] == 0 and ranges[-1][1] is None                      # from the first step, to the end
    assert all(a[1] == b[0] for a, b in zip(ranges, ranges[1:]))             # contiguous
    # the steps summed as the sequential range sums them
    assert chapter4.range_steps(0.5, 0.5, 5.4) == [0.5 * k for k in range(1, 11)]
    assert chapter4.range_steps(0.3, 0.3, 0.9) == [0.3, 0.3 + 0.3, 0.3 + 0.3 + 0.3]


def test_assembled_range_continues_into_the_next_part_and_stops_where_it_leaves():
    r1 = part("range-1", ["step1", "step2"], [0.5, 1.0], [9, 9], [1.01, 1.03])
    r2 = part("range-2", ["step3", "step4"], [1.5, 2.0], [9, 9], [1.07, 1.11])
    ds = study.assemble([*table_parts(), r1, r2], tolerance=TOL)
    registry.check(ds, study.LAYOUT)
    np.testing.assert_array_equal(ds["step_hs"], [0.5, 1.0, 1.5, 2.0])
    assert ds.attrs["linear_range_hs_inside_m"] == 1.5 and ds.attrs["linear_range_hs_leaves_m"] == 2.0
    assert ds.attrs["linear_range_mpm_inside_m"] == 15.0
    np.testing.assert_array_equal(ds["mpm_ratio"], [0.99, 1.0, 1.01, 1.07, 1.17])   # the study's order
    assert float(ds["wall_time"]) == 4 * 1.5
    # the parts in any order give the same answer
    again = study.assemble([r2, *table_parts()[::-1], r1], tolerance=TOL)
    assert again.identical(ds)


def test_a_range_left_in_the_first_part_drops_the_next_parts_steps():
    r1 = part("range-1", ["step1", "step2"], [0.5, 1.0], [9, 9], [1.02, 1.2])
    r2 = part("range-2", ["step3"], [1.5], [9], [1.3])
    ds = study.assemble([*table_parts(), r1, r2], tolerance=TOL)
    np.testing.assert_array_equal(ds["step_hs"], [0.5, 1.0])
    assert ds.attrs["linear_range_hs_inside_m"] == 0.5 and ds.attrs["linear_range_hs_leaves_m"] == 1.0
    # never left up to the largest step: no Hs where it leaves
    r1 = part("range-1", ["step1", "step2"], [0.5, 1.0], [9, 9], [1.0, 1.0])
    r2 = part("range-2", ["step3"], [1.5], [9], [1.05])
    ds = study.assemble([*table_parts(), r1, r2], tolerance=TOL)
    assert ds.attrs["linear_range_hs_inside_m"] == 1.5 and np.isnan(ds.attrs["linear_range_hs_leaves_m"])


def test_assembly_refuses_missing_or_repeated_parts_and_says_why_a_part_did_not_run():
    r1 = part("range-1", ["step1"], [0.5], [9], [1.2])
    with pytest.raises(ValueError, match="each of its parts once"):
        study.assemble([*table_parts(), r1], tolerance=TOL)
    with pytest.raises(ValueError, match="each of its parts once"):
        study.assemble([*table_parts(), r1, r1, r1], tolerance=TOL)
    gone = study.unavailable_part("MoorDyn cannot be imported", "range-2")
    registry.check(gone, study.PART_LAYOUT)
    ds = study.assemble([*table_parts(), r1, gone], tolerance=TOL)
    registry.check(ds, study.LAYOUT)
    assert ds.attrs["reason"] == "MoorDyn cannot be imported" and np.isnan(ds["sigma_ratio"]).all()
    with pytest.raises(ValueError, match="no study part"):
        study.study_part(None, None, "table-3")


@pytest.mark.skipif(not OK, reason=WHY)
def test_the_parts_give_the_sequential_comparison_to_the_last_digit():
    """Short records: every part run on its own and assembled equals the study's table
    and the linear range run one after the other in one process (chapter4.linear_range)."""
    from jls.config.builders import candidate_plant
    from jls.config.loader import load
    from jls.stages.vessel_motion import vessel_motion
    cfg = load("config/config.yaml")
    motion = vessel_motion(cfg["vessel"], [90.0], base_dir=".")
    plant = candidate_plant(cfg, "baseline")
    run = dict(duration_s=60.0, transient_time_constants=0.2, dt=0.1, tolerance=0.05)
    parts = [study.study_part(plant, motion, p, **run) for p in STUDY_PARTS]
    for p in parts:
        registry.check(p, study.PART_LAYOUT)
    ds = study.assemble(parts, tolerance=0.05)
    registry.check(ds, study.LAYOUT)
    from jls.verify import model
    ref = model.build_reference(plant, vessel_lever_m=motion.attrs["hinge_m"])
    tr, dt = ds.attrs["transient_s"], ds.attrs["dt_s"]
    lr = chapter4.linear_range(ref, plant, motion, 9.0, 90.0, hs_start=0.5, hs_step=0.5, hs_max=5.4,
                               tolerance=0.05, duration_s=60.0, transient=tr, dt=dt)
    assert ds.sizes["step"] >= 3                                  # the range ran into its second part
    np.testing.assert_array_equal(ds["step_hs"], lr["hs"])
    np.testing.assert_array_equal(ds["step_mpm_ratio"], lr["mpm_ratio"])
    np.testing.assert_array_equal(ds["step_mpm_reference"], lr["mpm_reference"])
    o = chapter4.irregular_sea(ref, plant, motion, 2.4, 8.5, 90.0, duration_s=60.0, transient=tr, dt=dt)
    assert float(ds["mpm_ratio"].sel(sea_state="V4")) == o["mpm_ratio_rom_to_reference"]
    assert float(ds["sigma_reference"].sel(sea_state="V4")) == o["reference"]["sigma"]
