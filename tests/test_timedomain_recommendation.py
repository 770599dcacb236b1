"""The recommendation's boundary cells run in the time domain by default (issue 20, item 3):
``timedomain.boundary_candidates: assessed`` sends every assessed rigging candidate's
boundary cells, so whichever the workability stage then recommends, its cells are among
them; the DAG needs no recommendation before the cells are chosen."""

import copy

import numpy as np
import pytest
import xarray as xr

from jls.assessment.recommendation import recommend
from jls.config.builders import boundary_candidates
from jls.config.loader import validate
from jls.config.plausible import boundary_cell_count, check_config
from jls.errors import InputError
from jls.stages.timedomain_cell import choose_cells

C_TUGGER = {"none": 0.0, "low": 300.0}
CANDS = ["baseline", "detuned", "optimised"]


def constructed(best: str):
    """Three candidates, two tuggers, two legs; ``best`` without tugger has the highest
    route workability (every tugger gains nothing), each candidate's own boundary cell."""
    legs, hs, tz = ["north", "south"], np.array([0.75, 1.25, 1.75]), np.array([6.5, 7.5, 8.5])
    u = np.full((3, 2, 2, 1, 3, 3), 0.3)
    for i in range(3):
        u[i, :, :, 0, i, i] = 0.98 + 0.01 * i       # candidate i nearest 1 at (Hs i, Tz i)
    wr = np.full((3, 2), 0.90)
    wr[CANDS.index(best)] = 0.95
    work = xr.Dataset(
        {"utilisation": (("candidate", "tugger", "leg", "heading", "hs", "tz"), u),
         "workability_route": (("candidate", "tugger"), wr)},
        coords={"candidate": CANDS, "tugger": list(C_TUGGER), "leg": legs, "heading": [90.0],
                "hs": hs, "tz": tz})
    work["utilisation"] = work["utilisation"].expand_dims(criterion=["relative_sway_m"], axis=-1)
    work.attrs.update(max_saturation_fraction=0.01, winch_saturation="timedomain", tugger_min_gain=0.01,
                      tie_tolerance=1e-9, workability_route_min=0)
    sea = xr.Dataset({"cell_probability": (("leg", "heading", "hs", "tz"), np.ones((2, 1, 3, 3)))},
                     coords={"leg": legs, "heading": [90.0], "hs": hs, "tz": tz})
    plant = xr.Dataset({"feasible": ("candidate", [True] * 3), "infeasible_reason": ("candidate", [""] * 3),
                        "splash_clearance_margin": ("candidate", [6.37, 0.75, 0.75])},
                       coords={"candidate": CANDS}, attrs={"splash_clearance_m": 5.0})
    return work, sea, plant, xr.DataArray(np.tile(hs, (2, 1)), dims=("leg", "hs"),
                                          coords={"leg": legs, "hs": hs})


def test_default_boundary_candidates_are_every_assessed_rigging(cfg):
    assert cfg["timedomain"]["boundary_candidates"] == "assessed"       # the schema's default
    assert boundary_candidates(cfg) == CANDS
    assert boundary_cell_count(cfg, 2) == 6                             # the default route: 6 cells
    off = copy.deepcopy(cfg)
    off["screening"]["enabled"] = False
    assert boundary_candidates(off) == ["baseline", "detuned"]
    listed = copy.deepcopy(cfg)
    listed["timedomain"]["boundary_candidates"] = ["baseline"]
    assert boundary_candidates(validate(listed)) == ["baseline"]


@pytest.mark.parametrize("best", CANDS)
def test_time_domain_cells_include_the_recommendation(cfg, best):
    work, sea, plant, hs = constructed(best)
    data = {"workability": work, "plant": plant}
    recommended, _, _ = recommend(data, CANDS, list(C_TUGGER), C_TUGGER)
    assert recommended == (best, "none")
    cells = choose_cells(work, sea, hs, cfg)          # the default configuration's choice
    assert {c["candidate"] for c in cells} == set(CANDS)
    mine = [c for c in cells if c["candidate"] == best]
    i = CANDS.index(best)
    assert [(c["hs"], c["tz"]) for c in mine] == [(work["hs"].values[i], work["tz"].values[i])]
    assert {r for c in mine for r in c["reasons"]} == {"nearest the workability boundary, leg north",
                                                        "nearest the workability boundary, leg south"}


def test_a_grid_too_large_for_max_cells_is_refused_when_read(cfg):
    big = copy.deepcopy(cfg)
    big["candidate_grid"] = {"top_spread_y_m": list(np.linspace(38, 47, 10)),
                             "drop_height_m": list(np.linspace(55, 65, 10))}
    big["timedomain"]["max_cells"] = 15      # 2 legs x (3 named + the grid's 5 best) = 16
    with pytest.raises(InputError, match="boundary_candidates"):
        check_config(big)
    big["timedomain"]["boundary_candidates"] = ["baseline", "optimised"]
    check_config(big)
