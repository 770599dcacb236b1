"""The time-domain cells of a candidate grid scale (issue 35, item 4): with the shipped
``timedomain.boundary_candidates: assessed`` a grid sends the boundary cells of its
``timedomain.grid_boundary_candidates`` best candidates (frequency-domain route
workability) beside the named ones, so a 21 x 21 grid runs with the shipped defaults; the
grid's other candidates are excluded from the recommendation, whose cells therefore always
ran in the time domain."""

import copy

import numpy as np
import pytest
import xarray as xr

from jls.assessment.recommendation import grid_without_timedomain, recommend
from jls.config.builders import boundary_candidates, grid_boundary_count
from jls.config.plausible import boundary_cell_count, check_config
from jls.errors import InputError
from jls.stages.timedomain_cell import best_grid_candidates


def _grid(cfg, n):
    big = copy.deepcopy(cfg)
    big["candidate_grid"] = {"top_spread_y_m": [round(float(x), 3) for x in np.linspace(36, 60, n)],
                             "drop_height_m": [round(float(x), 3) for x in np.linspace(51, 66.4, n)]}
    return big


def test_a_21_by_21_grid_runs_with_the_shipped_defaults(cfg):
    big = _grid(cfg, 21)
    check_config(big)                                   # refused before: 886 cells > max_cells 200
    assert boundary_candidates(big) == ["baseline", "detuned", "optimised"]
    assert grid_boundary_count(big) == cfg["timedomain"]["grid_boundary_candidates"] == 5
    assert boundary_cell_count(big, 2) == 2 * (3 + 5)   # legs x (named + best) x cells per leg


def test_the_cells_do_not_grow_with_the_grid(cfg):
    counts = {n: boundary_cell_count(_grid(cfg, n), 2) for n in (2, 5, 21)}
    assert counts == {2: 2 * (3 + 4), 5: 16, 21: 16}    # a 2 x 2 grid has only 4 to rank
    assert boundary_cell_count(cfg, 2) == 6             # no grid: the named candidates only
    listed = _grid(cfg, 21)
    listed["timedomain"]["boundary_candidates"] = ["baseline"]
    assert grid_boundary_count(listed) == 0 and boundary_cell_count(listed, 2) == 2


def test_too_many_cells_are_still_refused(cfg):
    big = _grid(cfg, 21)
    big["timedomain"]["grid_boundary_candidates"] = 100
    big["timedomain"]["max_cells"] = 200                # 2 x (3 + 100) = 206
    with pytest.raises(InputError, match="206 boundary cells"):
        check_config(big)


def _work(scores, ran, grid_best):
    """A workability dataset: route workability per (candidate, tugger) and the time-domain
    limit fraction, NaN for the candidates whose cells did not run."""
    cands = list(scores)
    wr = np.array([scores[c] for c in cands])
    frac = np.array([[0.0, 0.0] if c in ran else [np.nan, np.nan] for c in cands])
    work = xr.Dataset({"workability_route": (("candidate", "tugger"), wr),
                       "timedomain_limit_fraction": (("candidate", "tugger"), frac)},
                      coords={"candidate": cands, "tugger": ["none", "low"]})
    work.attrs.update(timedomain_grid_best=grid_best, max_saturation_fraction=0.01,
                      winch_saturation="timedomain", tugger_min_gain=0.01, tie_tolerance=1e-9)
    return work


SCORES = {"baseline": [0.90, 0.91], "g1": [0.93, 0.97], "g2": [0.96, 0.92], "g3": [0.95, 0.95],
          "g4": [0.80, 0.99]}


def test_the_best_grid_candidates_by_their_best_tugger():
    work = _work(SCORES, ran=set(SCORES), grid_best=2)
    assert best_grid_candidates(work, ["baseline"], 2) == ["g4", "g1"]
    assert best_grid_candidates(work, ["baseline"], 3) == ["g4", "g1", "g2"]
    assert best_grid_candidates(work, ["baseline", "g4"], 1) == ["g1"]


def test_grid_candidates_without_cells_are_excluded_from_the_recommendation():
    # g4 has the highest workability but its cells did not run: not recommended
    ran = {"baseline", "g1", "g2"}
    work = _work(SCORES, ran=ran, grid_best=2)
    out = grid_without_timedomain({"workability": work}, [(c, t) for c in SCORES for t in ("none", "low")])
    assert {c for c, _ in out} == {"g3", "g4"}
    assert all(r.short == "no time domain" for r in out.values())
    plant = xr.Dataset({"feasible": ("candidate", [True] * 5), "infeasible_reason": ("candidate", [""] * 5)},
                       coords={"candidate": list(SCORES)})
    best, _, excluded = recommend({"workability": work, "plant": plant}, list(SCORES), ["none", "low"],
                                  {"none": 0.0, "low": 300.0})
    assert best[0] in ran and ("g4", "low") in excluded
    # without the grid rule (attribute 0), the same data excludes nothing of the kind
    off = _work(SCORES, ran=ran, grid_best=0)
    assert grid_without_timedomain({"workability": off}, [("g4", "low")]) == {}
    best, _, _ = recommend({"workability": off, "plant": plant}, list(SCORES), ["none", "low"],
                           {"none": 0.0, "low": 300.0})
    assert best == ("g4", "low")
