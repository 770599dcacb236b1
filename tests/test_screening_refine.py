"""The screening refinement's fast evaluation of one design (chapter 5): the numbers of
the datasets without building them, each design evaluated once."""

import copy
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import scoring_from_config, screening_settings_from_config
from jls.config.loader import load
from jls.design import screening as screening_mod
from jls.design.optimise import refine
from jls.design.scoring import PointScorer, score
from jls.design.screening import ROTATIONAL, objective_values
from jls.io import registry
from jls.plant import equilibrium
from jls.plant.candidates import candidate_plants, plant_dataset
from jls.plant.model import build
from jls.plant.rigging import Layout, design_variables
from jls.sea.legs import read_leg
from jls.stages.sea_states import sea_states
from jls.stages.vessel_motion import vessel_motion

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_SETTINGS = screening_settings_from_config(load(ROOT / "config" / "config.yaml"))
SCORES = ("screening_sigma", "screening_mpm", "workability_surrogate")
DESIGNS = {"baseline": {}, "detuned": {"top_spread_y": 37.845, "drop_height": 66.46},
           "wide": {"top_spread_y": 52.0, "drop_height": 60.5},
           "beyond_splash_limit": {"top_spread_y": 40.0, "drop_height": 67.0}}


def _route(cfg, headings, probabilities):
    spec = copy.deepcopy(dict(cfg["routes"]["default"], name="default"))
    for leg in spec["legs"]:
        leg.update(headings_deg=headings, heading_probability=probabilities)
    legs = {leg["name"]: read_leg(leg, ROOT, "study", 3.3, cfg["g_m_per_s2"]) for leg in spec["legs"]}
    return sea_states(spec, legs), vessel_motion(cfg["vessel"], sorted(headings), base_dir=ROOT)


@pytest.fixture(scope="module")
def route(cfg):
    sea, motion = _route(cfg, [90.0], [1.0])
    return sea, motion, scoring_from_config(cfg)


@pytest.mark.parametrize("headings, probabilities, options", [
    ([90.0], [1.0], {}),
    ([120.0, 90.0], [0.4, 0.6], {"hs_in_bin": "upper", "cycles": "fixed"})])
def test_fast_scores_equal_the_dataset_scores(cfg, rig, headings, probabilities, options):
    # Every tugger setting, a heading order other than the sorted one, Hs assessed at
    # the bin's upper edge, the study's fixed number of cycles, an infeasible design:
    # the same numbers as score() on a one-candidate plant dataset.
    sea, motion = _route(cfg, headings, probabilities)
    scoring = replace(scoring_from_config(cfg), **options)
    scorer = PointScorer(motion, sea, scoring)
    for name, values in DESIGNS.items():
        plant, _ = plant_dataset(rig, {name: values})
        expected = score(plant, motion, sea, scoring)
        got = scorer(candidate_plants(rig, {name: values})[0])
        for key in SCORES:
            np.testing.assert_allclose(got[key], expected[key].values[0], rtol=1e-12, atol=0,
                                       err_msg=f"{name} {key}")
        assert got["screening_mpm"].shape == (len(scoring.tuggers), 4)
        assert np.all((got["workability_surrogate"] >= 0) & (got["workability_surrogate"] <= 1))


def test_fast_scores_of_a_plant_that_does_not_exist_are_nan(rig, route):
    # Every anchor 5 m to port: two wires would have to push, the plant has no matrices.
    sea, motion, scoring = route
    lay = Layout(anchors=(rig.layout.anchors + [0.0, 5.0, 0.0])[None], padeyes=rig.layout.padeyes[None],
                 cog_depth=np.array([rig.layout.cog_depth], float))
    p = build(lay, rig.jacket, rig.wire_stiffness, g=rig.g)
    assert not np.isfinite(p.K).all()
    got = PointScorer(motion, sea, scoring)(p)
    assert all(np.isnan(got[key]).all() for key in SCORES)


def test_fast_scores_follow_the_criteria(cfg, rig, route):
    # A tighter yaw criterion lowers the surrogate exactly as in the dataset path.
    sea, motion, scoring = route
    strict = replace(scoring, criteria=dict(scoring.criteria, relative_yaw_deg=0.5))
    values = DESIGNS["detuned"]
    plant, _ = plant_dataset(rig, {"d": values})
    p = candidate_plants(rig, {"d": values})[0]
    loose, tight = PointScorer(motion, sea, scoring)(p), PointScorer(motion, sea, strict)(p)
    np.testing.assert_allclose(tight["workability_surrogate"],
                               score(plant, motion, sea, strict)["workability_surrogate"].values[0],
                               rtol=1e-12, atol=0)
    assert np.all(tight["workability_surrogate"] <= loose["workability_surrogate"])
    assert np.any(tight["workability_surrogate"] < loose["workability_surrogate"])


def _dataset_refine(rig, start, variables, motion, sea, scoring, settings):
    """The refinement evaluated through the plant and score datasets (the reference), each
    safety margin less its tolerance budget (the plant's attributes)."""
    tugger = next(iter(scoring.tuggers))
    scoring = replace(scoring, tuggers={tugger: scoring.tuggers[tugger]})
    cache = {}

    def point(x):
        key = tuple(np.round(x, 10))
        if key not in cache:
            plant, _ = plant_dataset(rig, {"trial": dict(start, **dict(zip(variables, map(float, x))))})
            cache[key] = (plant, score(plant, motion, sea, scoring))
        return cache[key]

    def objective(x):
        return -float(objective_values(point(x)[1], settings.objective, tugger)[1][0])

    def margins(x):
        plant, sc = point(x)
        p = plant.isel(candidate=0)
        weight = plant.attrs["m_grav_t"] * plant.attrs["g_m_per_s2"]
        lead, splash = plant.attrs["lead_angle_budget_deg"], plant.attrs["splash_clearance_budget_m"]
        g = [p["side_lead_margin"] - lead, p["fore_aft_lead_margin"] - lead, p["splash_clearance_margin"] - splash,
             float(p["tension"].min()) / weight - equilibrium.SLACK_FRACTION,
             equilibrium.RESIDUAL_LIMIT - float(np.abs(p["equilibrium_residual"]).max())]
        for key, limit in settings.constraints.items():
            g.append(limit - float(sc["screening_mpm"].sel(tugger=tugger, response=ROTATIONAL[key])[0]))
        return np.array([float(v) for v in g])

    return refine(objective, margins, [start[v] for v in variables],
                  [rig.design_space[v][0] for v in variables],
                  [rig.design_space[v][1] for v in variables],
                  tolerance=settings.tolerance_m, max_evaluations=settings.max_evaluations)


def test_refinement_on_the_fast_path_ends_where_the_dataset_path_does(rig, route):
    # Same optimiser, same settings, same start: the same designs visited and the same
    # optimum, to round-off; each design evaluated once.
    sea, motion, scoring = route
    st = replace(DEFAULT_SETTINGS, constraints={"relative_roll_deg": 0.75}, max_evaluations=25)
    start = {k: float(v) for k, v in design_variables(rig.layout).items()}
    start.update(top_spread_y=44.0, drop_height=63.0)
    variables = ["top_spread_y", "drop_height"]
    visited = []
    fast = screening_mod._refine(rig, start, variables, motion, sea, scoring, st, counter=visited)
    slow = _dataset_refine(rig, start, variables, motion, sea, scoring, st)
    np.testing.assert_allclose(fast.x, slow.x, rtol=1e-12, atol=0)
    np.testing.assert_allclose(fast.objective, slow.objective, rtol=1e-12, atol=0)
    np.testing.assert_allclose(fast.margins, slow.margins, rtol=1e-12, atol=1e-15)
    assert fast.evaluations == slow.evaluations == len(visited)
    keys = {tuple(round(d[v], 10) for v in variables) for d in visited}
    assert len(keys) == len(visited)                   # no design built or scored twice
    before = screening_mod.PointScorer(motion, sea, replace(scoring, tuggers={"none": 0.0}))(
        candidate_plants(rig, {"start": start})[0])
    assert fast.objective <= -float(before["workability_surrogate"][0])   # no worse than the start


def test_refine_evaluates_each_design_once():
    # The trust-region search and the push to the limits revisit designs (the push
    # re-reads its current point at every step): each is computed once.
    calls = {"objective": 0, "margins": 0}

    def objective(x):
        calls["objective"] += 1
        return -(x[0] + x[1])

    def margins(x):
        calls["margins"] += 1
        return np.array([12.0 - x[0] - 2.0 * x[1]])

    r = refine(objective, margins, [1.0, 1.0], [0.0, 0.0], [10.0, 10.0], tolerance=1e-3)
    assert calls["objective"] == calls["margins"] == r.evaluations
    np.testing.assert_allclose(r.x, [10.0, 1.0], atol=1e-2)


def test_screening_import_leaves_the_optimiser_unloaded():
    # Chunk jobs import the screening stage for the moments only: scipy.optimize (slow to
    # import) is loaded by the refinement, when it runs.
    code = ("import sys, jls.design.screening, jls.design.scoring; "
            "print('scipy.optimize' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                         check=True)
    assert out.stdout.strip() == "False"


def test_registry_layout_is_a_copy_and_annotate_replaces_stale_attributes():
    entry = registry.layout("plant")
    entry["variables"]["tension"]["units"] = "t"
    assert registry.layout("plant")["variables"]["tension"]["units"] == "kN"
    import xarray as xr
    ds = xr.Dataset({"tension": (("candidate", "wire"), np.ones((1, 4)), {"units": "m", "note": "kept"})},
                    coords={"candidate": ["a"]})
    registry.annotate(ds, "plant")
    assert ds["tension"].attrs == {"units": "kN", "long_name": "static wire tension", "note": "kept"}
    assert ds["candidate"].attrs["long_name"]
