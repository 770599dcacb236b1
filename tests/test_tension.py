"""Wire tensions: gradients of the wire lengths, dynamic tension, tension statistics."""

from pathlib import Path

import numpy as np
import pytest

from jls.config.builders import rigging_from_config
from jls.config.loader import load
from jls.plant.candidates import plant_dataset
from jls.plant.linearise import rotation, stiffness_matrices
from jls.plant.model import Jacket, build
from jls.plant.rigging import Layout
from jls.response.solver import transfer_functions
from jls.response.tension import (
    dynamic_amplification,
    dynamic_tension,
    length_gradients,
    slack_margin,
    tension_dataset,
    tension_transfer,
    wire_directions,
)

ROOT = Path(__file__).resolve().parents[1]
G = 9.81
K_WIRE = 63274.0


def vertical_layout(drop=60.0, half_x=8.0, half_y=22.0):
    """Four vertical wires, lifting points at the CoG height plus nothing (z_p = 0)."""
    xy = np.array([[half_x, half_y], [-half_x, half_y], [half_x, -half_y], [-half_x, -half_y]])
    anchors = np.column_stack([xy, np.zeros(4)])
    padeyes = np.column_stack([xy, np.zeros(4)])
    return Layout(anchors=anchors, padeyes=padeyes, cog_depth=np.asarray(drop))


def config_plant():
    rig = rigging_from_config(load(ROOT / "config" / "config.yaml"))
    ds, _ = plant_dataset(rig, {"baseline": {}, "detuned": {"top_spread_y": 37.845,
                                                            "drop_height": 66.46}})
    return ds


def exact_lengths(q, qb, anchors, padeyes, cog_depth):
    """Eq. 3.6 evaluated exactly for one geometry."""
    r_cog = np.array([0.0, q[0], q[1] - cog_depth])
    r_hinge = np.array([0.0, qb[0], qb[1]])
    d = (r_hinge + anchors @ rotation(qb[2], qb[3]).T) - (r_cog + padeyes @ rotation(q[2], q[3]).T)
    return np.linalg.norm(d, axis=-1)


def asymmetric_geometry():
    ds = config_plant()
    rng = np.random.default_rng(3)
    anchors = ds["anchor"].values + rng.normal(0.0, 1.5, (2, 4, 3)) * [1, 1, 0.1]
    padeyes = ds["padeye"].values + rng.normal(0.0, 1.5, (2, 4, 3)) * [1, 1, 0.1]
    return anchors, padeyes, ds["cog_depth"].values


def test_vertical_wire_under_heave_carries_k_times_its_elongation():
    lay = vertical_layout()
    gq, gb = length_gradients(lay.anchors, lay.padeyes, lay.cog_depth)
    dz = 0.05                                   # jacket 5 cm down: each wire 5 cm longer
    q = np.array([0.0, -dz, 0.0, 0.0])
    t = dynamic_tension(q, np.zeros(4), gq, gb, np.full(4, K_WIRE))
    np.testing.assert_allclose(t, K_WIRE * dz, rtol=1e-12)
    exact = exact_lengths(q, np.zeros(4), lay.anchors, lay.padeyes, float(lay.cog_depth))
    np.testing.assert_allclose(t, K_WIRE * (exact - float(lay.cog_depth)), rtol=1e-12)
    # Hinge up by the same amount: the same elongation from the other end.
    t_b = dynamic_tension(np.zeros(4), -q, gq, gb, np.full(4, K_WIRE))
    np.testing.assert_allclose(t_b, t, rtol=1e-12)


def test_static_tensions_hold_the_weight():
    ds = config_plant()
    e, _ = wire_directions(ds["anchor"].values, ds["padeye"].values, ds["cog_depth"].values)
    force = np.einsum("cw,cwa->ca", ds["tension"].values, e)
    weight = ds.attrs["m_grav_t"] * ds.attrs["g_m_per_s2"]
    np.testing.assert_allclose(force[:, 2], weight, rtol=1e-9)
    np.testing.assert_allclose(force[:, 1], 0.0, atol=1e-6 * weight)


def test_gradients_equal_finite_differences_of_the_wire_lengths():
    anchors, padeyes, depth = asymmetric_geometry()
    gq, gb = length_gradients(anchors, padeyes, depth)
    eps = 1e-6
    for c in range(2):
        for j in range(4):
            step = np.zeros(4)
            step[j] = eps
            zero = np.zeros(4)
            fd_q = (exact_lengths(step, zero, anchors[c], padeyes[c], depth[c])
                    - exact_lengths(-step, zero, anchors[c], padeyes[c], depth[c])) / (2 * eps)
            fd_b = (exact_lengths(zero, step, anchors[c], padeyes[c], depth[c])
                    - exact_lengths(zero, -step, anchors[c], padeyes[c], depth[c])) / (2 * eps)
            np.testing.assert_allclose(gq[c, :, j], fd_q, rtol=1e-7, atol=1e-8)
            np.testing.assert_allclose(gb[c, :, j], fd_b, rtol=1e-7, atol=1e-8)


def test_gradients_are_those_of_the_linearisation():
    # Without tension eq. 3.9 keeps only its elastic part, sum_i k_i g_i g_i^T.
    anchors, padeyes, depth = asymmetric_geometry()
    k = np.array([[63e3, 60e3, 70e3, 65e3], [50e3, 55e3, 52e3, 58e3]])
    K, Kb = stiffness_matrices(anchors, padeyes, depth, k, np.zeros_like(k))
    gq, gb = length_gradients(anchors, padeyes, depth)
    np.testing.assert_allclose(np.einsum("cw,cwi,cwj->cij", k, gq, gq), K, rtol=1e-10, atol=1e-6)
    np.testing.assert_allclose(np.einsum("cw,cwi,cwj->cij", k, gq, gb), Kb, rtol=1e-10, atol=1e-6)


def test_rigid_body_motions_of_hinge_and_jacket_strain_no_wire():
    anchors, padeyes, depth = asymmetric_geometry()
    gq, gb = length_gradients(anchors, padeyes, depth)
    k = np.full((2, 4), K_WIRE)
    for common in ([0.3, 0.0, 0.0, 0.0], [0.0, -0.2, 0.0, 0.0], [0.0, 0.0, 0.0, 0.01]):
        t = dynamic_tension(np.array(common), np.array(common), gq, gb, k)
        np.testing.assert_allclose(t, 0.0, atol=1e-9 * K_WIRE)
    # A common roll about the hinge carries the CoG sideways by depth x phi.
    phi = 0.01
    q = np.stack([depth * phi, np.zeros(2), np.full(2, phi), np.zeros(2)], -1)
    t = dynamic_tension(q, np.array([0.0, 0.0, phi, 0.0]), gq, gb, k)
    np.testing.assert_allclose(t, 0.0, atol=1e-9 * K_WIRE)
    # ... while a relative motion does strain them.
    assert np.abs(dynamic_tension(np.array([0.3, 0, 0, 0]), np.zeros(4), gq, gb, k)).max() > 1.0


def test_mirrored_wires_share_heave_and_oppose_sway_roll_yaw():
    ds = config_plant()
    gq, gb = length_gradients(ds["anchor"].values, ds["padeye"].values, ds["cog_depth"].values)
    port, stbd = [0, 1], [2, 3]                 # the config's mirror pairs
    np.testing.assert_allclose(gq[:, port, 1], gq[:, stbd, 1], rtol=1e-12)
    np.testing.assert_allclose(gq[:, port][..., [0, 2, 3]], -gq[:, stbd][..., [0, 2, 3]], rtol=1e-12,
                               atol=1e-15)


def test_tension_transfer_obeys_newton_in_heave():
    # Vertical wires, no damping, hinge heaving: the wires' dynamic tensions are the
    # only vertical force, so their sum equals M_kin times the jacket's acceleration.
    m = 7650.0
    p = build(vertical_layout(), Jacket(m_grav=m, m_kin=m, ixx=4.55e6, izz=3.286e6, z_p=0.0),
              K_WIRE, g=G)
    omega = np.linspace(0.2, 4.0, 60)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 1] = 1.0
    Hq, _ = transfer_functions(p.M, p.K, p.Kb, np.zeros((4, 4)), omega, qb)
    gq, gb = length_gradients(p.layout.anchors, p.layout.padeyes, p.layout.cog_depth)
    HT = tension_transfer(Hq[None], qb, gq[None], gb[None], p.wire_stiffness[None])
    np.testing.assert_allclose(HT.sum(-1)[0, 0, 0], -omega**2 * m * Hq[0, 0, :, 1], rtol=1e-9)
    # Quasi-static limit: the jacket follows the hinge and the wires barely notice.
    assert abs(HT[0, 0, 0, 0, 0]) < 1e-2 * m * G / 4


def test_tension_dataset_layout_and_margins():
    ds = config_plant()
    omega = np.linspace(0.2, 2.0, 400)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 2.0 / (1 + (omega / 0.5) ** 4)        # hinge sway, dying out at short periods
    qb[..., 2] = 0.01 / (1 + (omega / 0.5) ** 4)       # and roll
    Hq, _ = transfer_functions(ds["M"].values, ds["K"].values, ds["Kb"].values, ds["C"].values,
                               omega, qb, qb[..., 0], [0.0, 1000.0])
    out = tension_dataset(ds, omega, Hq, qb, [6.0, 8.0], tuggers=["none", "reference"],
                          headings_deg=[90.0], with_transfer=True)
    assert out["tension_mpm"].dims == ("candidate", "tugger", "heading", "tz", "wire")
    assert out["tension_static"].dims == ("candidate", "wire")
    assert np.all(out["tension_mpm"] > out["tension_sigma"])
    # Longer waves come nearer the baseline's sway resonance; the tugger damps it.
    mpm = out["tension_mpm"].sel(heading=90.0)
    base = mpm.sel(candidate="baseline", tugger="none")
    assert np.all(base.sel(tz=8.0) > 2 * base.sel(tz=6.0))
    assert np.all(mpm.sel(tugger="reference") < mpm.sel(tugger="none"))
    hs = 2.0
    daf = dynamic_amplification(out["tension_static"], mpm, hs)
    margin = slack_margin(out["tension_static"], mpm, hs)
    np.testing.assert_allclose((daf - 1) * out["tension_static"], out["tension_static"] - margin,
                               rtol=1e-12)
    assert float(daf.min()) > 1.0
    with pytest.raises(ValueError, match="matrices"):
        tension_dataset(ds.drop_vars("anchor"), omega, Hq, qb, [6.0], tuggers=["none", "reference"],
                        headings_deg=[90.0])


def test_tension_statistics_merge_into_the_response_and_drive_the_assessment():
    import xarray as xr

    from jls.assessment.workability import assess
    from jls.names import RESPONSES
    from jls.response.statistics import unit_statistics
    from jls.sea.scatter import scatter_dataset
    from jls.stages.sea_states import sea_states

    ds = config_plant()
    omega = np.linspace(0.2, 2.0, 600)
    qb = np.zeros((1, omega.size, 4), complex)
    qb[..., 0] = 2.0 / (1 + (omega / 0.5) ** 4)
    tz = [6.0, 8.0]
    Hq, Hrel = transfer_functions(ds["M"].values, ds["K"].values, ds["Kb"].values, ds["C"].values,
                                  omega, qb)
    stats = unit_statistics(omega, np.moveaxis(Hrel, -1, -2), tz)
    dims = ("candidate", "tugger", "heading", "response", "tz")
    resp = xr.Dataset({k: (dims, v) for k, v in stats.items()},
                      coords={"candidate": ds["candidate"].values, "tugger": ["none"],
                              "heading": [90.0], "response": list(RESPONSES), "tz": tz})
    resp = resp.merge(tension_dataset(ds, omega, Hq, qb, tz, tuggers=["none"], headings_deg=[90.0]))
    leg = scatter_dataset(np.full((8, 2), 10.0), hs_lower=np.arange(8.0) * 0.5,
                          hs_upper=np.arange(1, 9) * 0.5, tz_lower=[5, 7], tz_upper=[7, 9],
                          values_kind="counts")
    sea = sea_states({"name": "r", "legs": [{"name": "a", "duration_h": 10, "headings_deg": [90.0],
                                                    "heading_probability": [1.0]}]}, {"a": leg})
    sway = assess(resp, sea, {"relative_sway_m": 3.0})["workability_route"]
    loose = assess(resp, sea, {"relative_sway_m": 3.0, "max_wire_tension_kN": 1e6})["workability_route"]
    xr.testing.assert_equal(sway, loose)
    swl = float(ds["tension"].max()) + 300.0
    tight = assess(resp, sea, {"relative_sway_m": 3.0, "max_wire_tension_kN": swl})
    assert bool((tight["workability_route"] <= sway).all())
    assert bool((tight["workability_route"] < sway).any())
    # The limiting Hs of the safe working load is eq. 2.7 generalised, worst wire.
    expected = ((swl - resp["tension_static"]) / resp["tension_mpm"]).min("wire")
    np.testing.assert_allclose(
        tight["hs_limit_criterion"].sel(criterion="max_wire_tension_kN").values,
        expected.transpose("candidate", "tugger", "heading", "tz").values, rtol=1e-12)


def test_tension_sigma_equals_a_time_series_realisation():
    # Random-phase realisation of the hinge motion at Hs = 1 m; the jacket's motion and
    # the wires' tensions follow component by component. The tensions combine q and qb
    # with their phases, which the spectral sigma must respect.
    from jls.response.tension import tension_statistics
    from jls.sea.spectra import jonswap, tp_from_tz

    ds = config_plant().isel(candidate=[0])
    dw = 0.004
    omega = np.arange(0.2, 2.0, dw) + dw / 2
    qb = np.zeros((1, omega.size, 4), complex)
    qb[0, :, 0] = 2.0 * np.exp(-0.5j * omega) / (1 + (omega / 0.6) ** 4)
    qb[0, :, 1] = 0.6j * np.exp(-(omega / 0.8) ** 2)
    qb[0, :, 2] = 0.02 / (1 + (omega / 0.6) ** 4)
    Hq, _ = transfer_functions(ds["M"].values, ds["K"].values, ds["Kb"].values, ds["C"].values,
                               omega, qb)
    gq, gb = length_gradients(ds["anchor"].values, ds["padeye"].values, ds["cog_depth"].values)
    k = ds["wire_stiffness"].values
    tz = 7.0
    sigma = tension_statistics(omega, Hq, qb, gq, gb, k, [tz])["tension_sigma"][0, 0, 0, 0]
    S = jonswap(omega, 1.0, tp_from_tz(np.array([tz]), 3.3)[0], 3.3)
    amp = np.sqrt(2 * S * dw) * np.exp(2j * np.pi * np.random.default_rng(5).random(omega.size))
    t = np.arange(0.0, 2 * np.pi / dw, 0.25)
    phase = np.exp(1j * np.outer(t, omega))                        # (time, w)
    q_t = np.real(phase @ (amp[:, None] * Hq[0, 0, 0]))            # (time, 4)
    qb_t = np.real(phase @ (amp[:, None] * qb[0]))
    T_t = dynamic_tension(q_t[:, None, :], qb_t[:, None, :], gq, gb, k)[:, 0]   # (time, wire)
    # Trapezoid weights of a uniform grid halve the two end points, where S is ~0.
    np.testing.assert_allclose(T_t.std(axis=0), sigma, rtol=2e-3)
