"""Uncertainty bands: plant variants, bands and the robustness of a recommendation."""

from pathlib import Path

import numpy as np
import xarray as xr

from jls.assessment.uncertainty import (
    assess_variants,
    bands,
    plant_variants,
    unstack_variants,
    workability_bands,
)
from jls.assessment.workability import assess
from jls.config.builders import rigging_from_config
from jls.config.loader import load
from jls.names import RESPONSES
from jls.plant.candidates import plant_dataset
from jls.response.solver import frequency_grid, transfer_functions
from jls.response.statistics import unit_statistics
from jls.sea.scatter import scatter_dataset
from jls.stages.sea_states import sea_states

ROOT = Path(__file__).resolve().parents[1]
NOMINAL = {"damping_factor": 1.0, "sway_frequency_factor": 1.0, "hs_in_bin": "centre"}


def config_plant():
    rig = rigging_from_config(load(ROOT / "config" / "config.yaml"))
    ds, _ = plant_dataset(rig, {"baseline": {}, "detuned": {"top_spread_y": 37.845,
                                                            "drop_height": 66.46}})
    return ds


def hinge_rao(omega):
    """Beam-sea hinge motion of a large hull: sway and roll, rolling near 15 s."""
    r = omega / (2 * np.pi / 15.3)
    roll = 0.4 * omega**2 / 9.81 * np.exp(-(omega / 0.7) ** 4) / (1 - r**2 + 0.1j * r)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[0, :, 0] = -100.0 * roll            # the hinge 100 m above the roll centre
    qb[0, :, 2] = roll
    return qb


def unit_stats(plant, tz, tuggers=(0.0,)):
    """Unit-Hs relative-motion statistics in the layout of response.nc."""
    omega = frequency_grid(0.2, 2.5, 0.005, 2 * np.pi / plant["natural_period"].values,
                           plant["damping_ratio"].values)
    qb = hinge_rao(omega)
    _, Hrel = transfer_functions(plant["M"].values, plant["K"].values, plant["Kb"].values,
                                 plant["C"].values, omega, qb, qb[..., 0], list(tuggers))
    Hrel = Hrel * np.where([False, False, True, True], 180 / np.pi, 1.0)
    stats = unit_statistics(omega, np.moveaxis(Hrel, -1, -2), tz)
    dims = ("candidate", "tugger", "heading", "response", "tz")
    return xr.Dataset({k: (dims, v) for k, v in stats.items()},
                      coords={"candidate": plant["candidate"].values,
                              "tugger": [f"c{c:g}" for c in tuggers], "heading": [90.0],
                              "response": list(RESPONSES), "tz": list(tz)})


def route_sea(tz=(6.5, 7.5, 8.5, 9.5)):
    edges = np.arange(0.0, 6.01, 0.5)
    tz = np.asarray(tz)
    counts = np.round(np.outer(np.exp(-np.arange(12) / 4.0), np.ones(tz.size)) * 100) + 1
    leg = scatter_dataset(counts, hs_lower=edges[:-1], hs_upper=edges[1:], tz_lower=tz - 0.5,
                          tz_upper=tz + 0.5, values_kind="counts")
    return sea_states({"name": "r", "legs": [{"name": "a", "duration_h": 10, "headings_deg": [90.0],
                                                    "heading_probability": [1.0]}]}, {"a": leg})


def test_variants_shift_the_sway_frequency_and_damping_only():
    plant = config_plant()
    var = plant_variants(plant)
    assert var.sizes["candidate"] == 2 * 9
    for name in plant["candidate"].values:
        nom = var.where((var["base_candidate"] == name) & (var["damping_factor"] == 1.0)
                        & (var["sway_frequency_factor"] == 1.0), drop=True).squeeze("candidate")
        for v in ("K", "Kb", "C", "natural_period", "damping_ratio"):
            np.testing.assert_allclose(nom[v].values, plant[v].sel(candidate=name).values,
                                       rtol=1e-9, atol=1e-9 * float(abs(plant[v]).max()))
    for i in range(var.sizes["candidate"]):
        v = var.isel(candidate=i)
        p = plant.sel(candidate=str(v["base_candidate"].values))
        f, d = float(v["sway_frequency_factor"]), float(v["damping_factor"])
        np.testing.assert_allclose(v["natural_period"].values[0], p["natural_period"].values[0] / f,
                                   rtol=1e-9)
        np.testing.assert_allclose(v["natural_period"].values[1:], p["natural_period"].values[1:],
                                   rtol=1e-9)
        np.testing.assert_allclose(v["damping_ratio"].values[:2], d * p["damping_ratio"].values[:2],
                                   rtol=1e-9)
        K, Kb = v["K"].values, v["Kb"].values
        np.testing.assert_allclose(K, K.T, rtol=1e-12, atol=1e-6)
        # Rigid-body identities: a common translation or yaw strains nothing; a common roll
        # about the hinge only tilts gravity (W e_sway).
        for j in (0, 1, 3):
            np.testing.assert_allclose(Kb[:, j], -K[:, j], rtol=1e-9, atol=1e-6 * abs(K).max())
        W = plant.attrs["m_grav_t"] * plant.attrs["g_m_per_s2"]
        roll = -K[:, 2] - float(v["cog_depth"]) * K[:, 0] + W * np.eye(4)[0]
        np.testing.assert_allclose(Kb[:, 2], roll, rtol=1e-8, atol=1e-6 * abs(K).max())


def test_more_damping_never_lowers_a_sway_governed_workability():
    var = plant_variants(config_plant(), damping_factors=(0.5, 1.0, 2.0, 4.0),
                         frequency_factors=(0.97, 1.0, 1.03))
    tz = [6.5, 7.5, 8.5, 9.5]
    work = assess_variants(unit_stats(var, tz), route_sea(tz), {"relative_sway_m": 3.0}, var)
    route = work["workability_route"]
    steps = route.diff("damping_factor")
    assert float(steps.min()) >= 0.0
    assert float(steps.max()) > 0.0                     # and it does raise it somewhere
    # The sway MPM itself falls with damping at every Tz near the sway resonance.
    mpm = unstack_variants(unit_stats(var, tz)["mpm"].sel(response="relative_sway"), var)
    assert float(mpm.sel(tz=9.5).diff("damping_factor").max()) < 0.0


def test_bands_contain_the_nominal_plant():
    plant = config_plant()
    var = plant_variants(plant)
    tz = [6.5, 7.5, 8.5, 9.5]
    sea = route_sea(tz)
    work = assess_variants(unit_stats(var, tz), sea, {"relative_sway_m": 3.0}, var)
    band = workability_bands(work["workability_route"], NOMINAL)
    # The nominal value computed from the original plant, not from the variants.
    direct = assess(unit_stats(plant, tz), sea, {"relative_sway_m": 3.0})["workability_route"]
    np.testing.assert_allclose(band["workability_nominal"].transpose(*direct.dims).values,
                               direct.values, rtol=1e-9)
    assert bool((band["workability_min"] <= direct).all()) and bool((direct <= band["workability_max"]).all())
    assert float((band["workability_max"] - band["workability_min"]).max()) > 0.0
    upper = work["workability_route"].sel(hs_in_bin="upper")
    assert bool((upper <= work["workability_route"].sel(hs_in_bin="centre") + 1e-12).all())
    legs = bands(work["workability_leg"], NOMINAL)
    assert legs["workability_min"].dims == ("candidate", "tugger", "leg")


def test_recommendation_holds_or_not_by_hand():
    def work(values):
        return xr.DataArray(np.asarray(values, float)[:, None, :], dims=("candidate", "tugger", "variant"),
                            coords={"candidate": ["a", "b"], "tugger": ["none"], "variant": [0, 1, 2]})
    nominal = {"variant": 1}
    robust = workability_bands(work([[0.85, 0.90, 0.95], [0.70, 0.80, 0.86]]), nominal)
    assert robust.attrs["recommended_candidate"] == "a"
    assert bool(robust["recommendation_holds"]) and not bool(robust["recommendation_dominates"])
    clear = workability_bands(work([[0.90, 0.92, 0.95], [0.70, 0.80, 0.86]]), nominal)
    assert bool(clear["recommendation_holds"]) and bool(clear["recommendation_dominates"])
    fragile = workability_bands(work([[0.85, 0.90, 0.95], [0.88, 0.80, 0.86]]), nominal)
    assert not bool(fragile["recommendation_holds"])
    np.testing.assert_array_equal(fragile["is_best"].sel(tugger="none").values,
                                  [[False, True, True], [True, False, False]])
    # An infeasible candidate is never recommended.
    feas = xr.DataArray([False, True], dims="candidate", coords={"candidate": ["a", "b"]})
    only_b = workability_bands(work([[0.85, 0.90, 0.95], [0.70, 0.80, 0.86]]), nominal, feasible=feas)
    assert only_b.attrs["recommended_candidate"] == "b" and bool(only_b["recommendation_dominates"])


def test_page_one_warns_when_the_recommendation_does_not_hold_across_the_band():
    """Page 1 carries the band's verdict only when it goes against the recommendation:
    silent when "a" stays best in every variant, a warning naming the count when "b"
    beats it in one."""
    from types import SimpleNamespace

    from jls.report.summary import page_one_warnings

    def cx_for(values):
        da = xr.DataArray(np.asarray(values, float).reshape(2, 1, 1, 3, 1),
                          dims=("candidate", "tugger", "damping_factor", "sway_frequency_factor", "hs_in_bin"),
                          coords={"candidate": ["a", "b"], "tugger": ["none"], "damping_factor": [1.0],
                                  "sway_frequency_factor": [0.97, 1.0, 1.03], "hs_in_bin": ["centre"]})
        work = xr.Dataset({"workability_route_variant": da}, attrs={"tie_tolerance": 1e-4})
        dg = SimpleNamespace(best=("a", "none"), combos=[("a", "none"), ("b", "none")], excluded={},
                             at_limit={}, hash_mismatch=[])
        return SimpleNamespace(work=work, dg=dg, feasible=lambda c: True, sec=lambda k: f"section {k}")

    assert not any("does not hold" in w for w in page_one_warnings(cx_for([[0.85, 0.90, 0.95],
                                                                             [0.70, 0.80, 0.86]])))
    warned = [w for w in page_one_warnings(cx_for([[0.85, 0.90, 0.95], [0.88, 0.80, 0.86]]))
              if "does not hold" in w]
    assert len(warned) == 1 and "best in 1 of 3 variants" in warned[0]
