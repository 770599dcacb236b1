"""Dynamic tip clearance: the tip's motion relative to the wave surface under it, checked
against hand calculations (a jacket moving rigidly with a heaving or rolling hinge), the
phase convention (a point that follows the wave surface has no relative motion), the
crest-height correction (Forristall 2000 by hand), the pass/fail at the limiting Hs, and
the datasets' layout."""

import copy

import numpy as np
import pytest
import xarray as xr

from jls.assessment import tip_clearance
from jls.assessment.criterion_levels import criterion_statistics
from jls.assessment.workability import assess, criteria_array
from jls.config.builders import scoring_from_config, tip_settings_from_config
from jls.config.loader import validate
from jls.io import registry
from jls.response.moments import Excitation
from jls.response.solver import transfer_functions
from jls.response.tip import (
    TipSettings,
    elevation_transfer,
    relative_transfer,
    tail_moments,
    tip_response,
)
from jls.sea.scatter import scatter_dataset
from jls.stages.sea_states import sea_states
from jls.vessel.rao import make_rao_dataset
from jls.vessel.transfer import hinge_excitation

G = 9.81
OMEGA = np.arange(0.05, 8.0 + 1e-9, 0.002)     # wide: the spectra's energy beyond is negligible
TZ = np.array([6.0, 8.0])
EXPOSURE_S = 3 * 3600.0
HINGE_HEIGHT, DROP, PADEYE_TO_TIP = 115.5, 60.0, 48.0     # tip 7.5 m above the still water


def rigid_plant(n=1):
    """A jacket that moves rigidly with the hinge: stiff (natural frequencies 4000 rad/s),
    Kb = -K, so q = qb within (omega / omega_n)^2 over the wave band."""
    M = np.diag([7719.0, 7719.0, 4.55e6, 3.286e6])
    K = np.diag(np.diag(M) * 4000.0**2)
    padeye = np.array([[-6.7, 24.4, 22.4], [8.3, 20.9, 22.4], [-6.7, -24.4, 22.4], [8.3, -20.9, 22.4]])
    return xr.Dataset(
        {"M": (("candidate", "dof", "dof_col"), np.broadcast_to(M, (n, 4, 4)).copy()),
         "K": (("candidate", "dof", "dof_col"), np.broadcast_to(K, (n, 4, 4)).copy()),
         "Kb": (("candidate", "dof", "dof_col"), np.broadcast_to(-K, (n, 4, 4)).copy()),
         "C": (("candidate", "dof", "dof_col"), np.zeros((n, 4, 4))),
         "padeye": (("candidate", "wire", "axis"), np.broadcast_to(padeye, (n, 4, 3)).copy()),
         "drop_height": ("candidate", np.full(n, DROP))},
        coords={"candidate": [f"c{i}" for i in range(n)], "wire": ["pf", "pa", "sf", "sa"],
                "axis": ["x", "y", "z"]})


def excitation(qb_of_omega, headings):
    """Excitation with the hinge RAO qb (n_h, n_w, 4) on OMEGA."""
    qb = np.asarray(qb_of_omega, complex)
    return Excitation(OMEGA, np.asarray(headings, float), qb, np.zeros(qb.shape[:2], complex))


def settings(crest="linear", offsets=((0.0, 20.0), (0.0, -20.0))):
    return TipSettings(crest=crest, hinge_height_m=HINGE_HEIGHT, padeye_to_tip_m=PADEYE_TO_TIP,
                       tip_offsets_m=offsets)


def tip_stats(qb, headings=(0.0,), crest="linear", offsets=((0.0, 20.0), (0.0, -20.0)),
              hinge_xy=(0.0, 0.0)):
    ds = tip_response(rigid_plant(), excitation(qb, headings), hinge_xy, TZ, {"none": 0.0},
                      settings(crest, offsets), gamma=3.3, exposure_h=3.0, g=G)
    ds.attrs["tip_crest"] = crest
    return ds


def constant_hinge(heave=0.0, roll=0.0, n_h=1):
    qb = np.zeros((n_h, OMEGA.size, 4), complex)
    qb[..., 1], qb[..., 2] = heave, roll
    return qb


def hand_mpm(sigma, tz_r):
    return sigma * np.sqrt(2.0 * np.log(EXPOSURE_S / tz_r))


# -- the wave under the tip: jls's phase convention ------------------------------------------

def test_the_elevation_is_the_incident_wave_travelling_in_the_heading_direction():
    # A crest at the reference point at t = 0 arrives at distance d along the heading after
    # d / c, c = omega / k the deep-water phase speed: eta = Re{H exp(i omega t)} = 1 there.
    omega, d = 0.6, 37.0
    k = omega**2 / G
    for beta in (0.0, 45.0, 90.0, 180.0, 270.0):
        b = np.radians(beta)
        H = elevation_transfer([omega], [beta], d * np.cos(b), d * np.sin(b), G)[0, 0]
        assert (H * np.exp(1j * omega * d / (omega / k))).real == pytest.approx(1.0, abs=1e-12)
    # head seas: a point at the bow (x > 0) sees the crest first, exp(+i k x) (docs/vessel.md);
    # beam seas from starboard: a point to port (y > 0) sees it later, exp(-i k y)
    H = elevation_transfer([omega], [180.0, 90.0], 50.0, 0.0, G)
    assert H[0, 0] == pytest.approx(np.exp(1j * k * 50.0))
    assert elevation_transfer([omega], [90.0], 0.0, 50.0, G)[0, 0] == pytest.approx(np.exp(-1j * k * 50.0))


def test_a_tip_that_follows_the_wave_surface_has_no_relative_motion():
    # The hinge heaves exactly with the wave surface at its position (X, Y), no roll; the
    # jacket follows it rigidly: the tip point below the CoG moves with the surface.
    X, Y, headings = -215.263, 1.0, [0.0, 60.0, 90.0, 180.0, 270.0]
    qb = np.zeros((len(headings), OMEGA.size, 4), complex)
    qb[..., 1] = elevation_transfer(OMEGA, headings, X, Y, G)
    p = rigid_plant()
    Hq, _ = transfer_functions(p["M"].values, p["K"].values, p["Kb"].values, p["C"].values,
                               OMEGA, qb, None, [0.0])
    eta = elevation_transfer(OMEGA, headings, np.array([[X]]), np.array([[Y]]), G)
    Hr = relative_transfer(Hq, eta, np.zeros((1, 1)))
    assert np.abs(Hr).max() < 1e-5                     # the rigid plant's (omega/omega_n)^2
    ds = tip_stats(qb, headings, offsets=((0.0, 0.0),), hinge_xy=(X, Y))
    # what remains is the wave energy above the RAO range (8 rad/s), where the hull is still
    # (about 1 % of the wave's sigma)
    tail0, _ = tail_moments(OMEGA[-1], TZ)
    np.testing.assert_allclose(ds["tip_sigma"].squeeze().transpose("heading", "tz"),
                               np.broadcast_to(np.sqrt(tail0), (5, 2)), rtol=1e-4)


def test_a_surface_following_hull_in_long_waves_carries_the_tip_with_the_surface():
    # A hull that rides long waves as a rigid plane (heave 1, roll and pitch the surface
    # slopes: roll = -i k sin(beta), pitch = +i k cos(beta), head-sea pitch k at -90 deg as
    # docs/vessel.md), its RAOs carried to the hinge by jls.vessel.transfer and the jacket
    # rigid below it: the tip moves with the surface to first order in k r.
    omega = np.linspace(0.02, 0.06, 9)
    k = omega**2 / G
    headings = [90.0, 180.0]
    b = np.radians(headings)
    rao = np.zeros((omega.size, 2, 6), complex)
    rao[..., 2] = 1.0
    rao[..., 3] = -1j * k[:, None] * np.sin(b)
    rao[..., 4] = 1j * k[:, None] * np.cos(b)
    hinge = (-215.263, 1.0, 99.998)
    qb = hinge_excitation(make_rao_dataset(omega, b, rao), hinge).transpose(
        "wave_direction", "omega", "dof_b").values
    tips = {90.0: ((-6.7, 24.4), (8.3, -20.9)), 180.0: ((0.0, 24.4), (0.0, -20.9))}
    for i, beta in enumerate(headings):          # head seas: no fore-aft offset (no jacket pitch)
        tx, ty = (np.array([[t[j] for t in tips[beta]]]) for j in (0, 1))
        eta = elevation_transfer(omega, [beta], hinge[0] + tx, hinge[1] + ty, G)
        Hq = np.broadcast_to(qb[i][None, None, None], (1, 1, 1, omega.size, 4))
        Hr = relative_transfer(Hq, eta, ty)
        theta = k[None, :] * np.abs((hinge[0] + tx) * np.cos(b[i]) + (hinge[1] + ty) * np.sin(b[i]))[..., None]
        assert np.all(np.abs(Hr[0, 0, :, 0]) <= 0.5 * theta[0] ** 2 * 1.01 + 1e-12)
        assert np.abs(Hr).max() < 0.05 * theta.max()    # a sign slip would leave about 2 theta


# -- hand calculations: pure heave, pure roll ---------------------------------------------------

def test_pure_heave_by_hand():
    # The hinge heaves down as the crest passes, z_b = -0.5 eta; the jacket follows rigidly;
    # following seas and the tips abeam of the hinge at the reference point: eta = 1 at
    # both, r = 1.5 eta, sigma = 1.5 x 0.25 m per m of Hs.
    ds = tip_stats(constant_hinge(heave=-0.5)).sel(candidate="c0", tugger="none", heading=0.0)
    np.testing.assert_allclose(ds["wave_sigma"], 0.25, rtol=1e-4)
    np.testing.assert_allclose(ds["tip_sigma"], 0.375, rtol=1e-3)
    np.testing.assert_allclose(ds["tip_tz_response"], TZ[:, None] * [1, 1], rtol=5e-3)
    np.testing.assert_allclose(ds["tip_mpm"], hand_mpm(0.375, TZ)[:, None] * [1, 1], rtol=1e-3)
    np.testing.assert_allclose(ds["tip_height"], HINGE_HEIGHT - DROP - PADEYE_TO_TIP)


def test_pure_roll_by_hand():
    # Hinge roll 0.02 rad/m in phase with the crest, no heave: z_t = y_t phi, so the port tip
    # (y 20 m) rises with the crest (r = 0.6 eta) and the starboard one falls (r = 1.4 eta).
    ds = tip_stats(constant_hinge(roll=0.02)).sel(candidate="c0", tugger="none", heading=0.0)
    np.testing.assert_allclose(ds["tip_sigma"].sel(tip="tip-1"), 0.6 * 0.25, rtol=1e-3)
    np.testing.assert_allclose(ds["tip_sigma"].sel(tip="tip-2"), 1.4 * 0.25, rtol=1e-3)
    stats = with_motions(tip_stats(constant_hinge(roll=0.02)))
    u = tip_clearance.unit_utilisation(stats, 1.5)
    # the worst corner governs: Hs_lim = (7.5 - 1.5) / MPM of the starboard tip
    np.testing.assert_allclose(1.0 / u.values.ravel(), 6.0 / hand_mpm(0.35, TZ), rtol=1e-3)


# -- the criterion: pass/fail at the limiting Hs, linear and crest-corrected ----------------------

def with_motions(ds):
    """The tip statistics as a response dataset: relative motions far inside their limits."""
    mpm = np.full((1, 1, ds.sizes["heading"], 4, ds.sizes["tz"]), 1e-3)
    dims = ("candidate", "tugger", "heading", "response", "tz")
    out = ds.assign(mpm=(dims, mpm), sigma=(dims, mpm / 3.8), tz_response=(dims, np.full_like(mpm, 8.0)))
    out = out.assign_coords(response=["relative_sway", "relative_heave", "relative_roll", "relative_yaw"])
    out.attrs = dict(ds.attrs)
    return out


def sea_around(hs_values, tz=8.0):
    """A one-leg table of one Tz bin with thin Hs bins centred on hs_values."""
    hs = np.asarray(hs_values, float)
    legs = {"a": scatter_dataset(np.ones((hs.size, 1)), hs_lower=hs - 0.01, hs_upper=hs + 0.01,
                                 tz_lower=[tz - 0.5], tz_upper=[tz + 0.5], values_kind="counts")}
    route = {"name": "r", "legs": [{"name": "a", "duration_h": 10, "headings_deg": [0.0],
                                    "heading_probability": [1.0]}]}
    return sea_states(route, legs)


def forristall_hand(hs, tz, long_crested=True):
    """alpha, beta of Forristall (2000), deep water, with T1 from Tz by DNV-RP-C205 (gamma 3.3)."""
    tp = tz / (0.6673 + 0.05037 * 3.3 - 0.006230 * 3.3**2 + 0.0003341 * 3.3**3)
    t1 = tp * (0.7303 + 0.04936 * 3.3 - 0.006556 * 3.3**2 + 0.0003610 * 3.3**3)
    s1 = 2 * np.pi * hs / (G * t1**2)
    a, b = (0.2892, 2.1597) if long_crested else (0.2568, 1.7912)
    return 0.3536 + a * s1, 2.0 - b * s1


@pytest.mark.parametrize("crest", ["linear", "forristall_long_crested", "forristall_short_crested"])
def test_the_criterion_passes_and_fails_at_the_hand_computed_limiting_hs(crest):
    stats = with_motions(tip_stats(constant_hinge(heave=-0.5), crest=crest))
    mr, me = hand_mpm(0.375, 8.0), hand_mpm(0.25, 8.0)       # unit MPM, Tz 8 s
    n = EXPOSURE_S / 8.0

    def D(hs):                         # the downward relative motion's MPM with the crest excess
        if crest == "linear":
            return hs * mr
        alpha, beta = forristall_hand(hs, 8.0, crest.endswith("long_crested"))
        return hs * mr + (alpha / 0.3536 * np.log(n) ** (1 / beta - 0.5) - 1.0) * hs * me

    lo, hi = 0.1, 20.0                 # D(Hs) = 7.5 - 1.5 by bisection
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if D(mid) < 6.0 else (lo, mid)
    hs_lim = 0.5 * (lo + hi)
    if crest == "linear":
        assert hs_lim == pytest.approx(6.0 / mr, rel=1e-9)
    else:
        assert hs_lim < 0.97 * 6.0 / mr                     # the crest correction lowers it
    crit = {"relative_sway_m": 3.0, "tip_air_gap_m": 1.5}
    ds = assess(stats, sea_around([hs_lim - 0.02, hs_lim + 0.02]), crit)
    h = ds["hs_limit_criterion"].sel(criterion="tip_air_gap_m", tz=8.0).item()
    assert h == pytest.approx(hs_lim, rel=2e-3)
    passes = ds["passes"].sel(candidate="c0", tugger="none", leg="a", heading=0.0, tz=8.0).values
    assert passes.tolist() == [True, False]
    # the cell's extreme is the clearance left: 7.5 m - D(Hs) at the worst tip point
    clearance = ds["mpm"].sel(criterion="tip_air_gap_m", tz=8.0).squeeze().values
    np.testing.assert_allclose(clearance, [7.5 - D(hs_lim - 0.02), 7.5 - D(hs_lim + 0.02)], rtol=2e-3)
    assert ds.attrs["tip_crest"] == crest


def test_a_tip_fixed_in_space_sees_forristalls_crest():
    # No hinge motion: the tip stands still, so the clearance lost is the crest itself,
    # alpha Hs (ln N)^(1/beta) with the MPM of N waves (Forristall 2000).
    stats = with_motions(tip_stats(constant_hinge(), crest="forristall_long_crested"))
    hs = xr.DataArray([2.0, 4.0, 6.0], dims="hs")
    c = tip_clearance.lowest_clearance(stats, hs).sel(candidate="c0", tugger="none", heading=0.0)
    for tz in TZ:
        n = float(stats["wave_n_cycles"].sel(tz=tz))           # exposure / Tz of the sea
        assert n == pytest.approx(EXPOSURE_S / tz, rel=5e-3)
        alpha, beta = forristall_hand(hs.values, tz)
        np.testing.assert_allclose(7.5 - c.sel(tz=tz).values, alpha * hs.values * np.log(n) ** (1 / beta),
                                   rtol=1e-3)


def test_newton_agrees_with_bisection_and_limits_are_monotone():
    rng = np.random.default_rng(3)
    A, mr, me = rng.uniform(0.5, 12, 200), rng.uniform(0.0, 2.0, 200), rng.uniform(0.8, 1.1, 200)
    s, n = rng.uniform(0.005, 0.06, 200), rng.uniform(400, 4000, 200)
    for crest in ("forristall_long_crested", "forristall_short_crested"):
        H = tip_clearance.limiting_hs(A, mr, me, s, n, crest)
        lo, hi = np.zeros_like(A), np.full_like(A, 200.0)
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            below = tip_clearance.demand(mid, mr, me, s, n, crest)[0] < A
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
        np.testing.assert_allclose(H, 0.5 * (lo + hi), rtol=1e-9)
        assert np.all(H <= A / np.maximum(mr, 1e-300))        # never above the linear limit
    assert tip_clearance.limiting_hs(-1.0, 1.0, 1.0, 0.01, 1000, "linear") == 0.0   # broken at rest
    assert np.isinf(tip_clearance.limiting_hs(5.0, 0.0, 1.0, 0.01, 1000, "linear"))


def test_a_tip_below_the_air_gap_at_rest_fails_in_any_sea():
    stats = with_motions(tip_stats(constant_hinge(heave=-0.5)))
    u = tip_clearance.unit_utilisation(stats, 8.0)          # air gap above the 7.5 m tip
    assert np.isinf(u.values).all()
    vs = tip_clearance.criterion_statistics(stats, 8.0)
    assert np.isinf(vs["sigma"].values).all()


def test_voyage_statistics_of_the_tip_are_the_governing_tip_utilisation():
    stats = with_motions(tip_stats(constant_hinge(roll=0.02), crest="forristall_long_crested"))
    out = criterion_statistics(stats, criteria_array({"relative_sway_m": 3.0, "tip_air_gap_m": 1.5}))
    tip = out.sel(criterion="tip_air_gap_m").sel(candidate="c0", tugger="none", heading=0.0)
    assert float(tip["limit"]) == 1.0 and str(tip["level_units"].values) == "1"
    u = tip_clearance.unit_utilisation(stats, 1.5).sel(candidate="c0", tugger="none", heading=0.0)
    np.testing.assert_allclose(tip["mpm"], u)
    # sigma scaled like the MPM: their ratio is the governing (starboard) tip's
    gov = stats.sel(candidate="c0", tugger="none", heading=0.0, tip="tip-2")
    np.testing.assert_allclose(tip["sigma"] / tip["mpm"], gov["tip_sigma"] / gov["tip_mpm"], rtol=1e-12)


# -- configuration, builders and the datasets' layout -----------------------------------------------

def test_the_criterion_is_on_by_default_and_can_be_switched_off(cfg):
    assert cfg["assessment"]["criteria"]["tip_air_gap_m"] == 1.5
    tip = tip_settings_from_config(cfg)
    assert tip.crest == "forristall_long_crested" and tip.tip_offsets_m is None
    assert tip.hinge_height_m == pytest.approx(119.46) and tip.padeye_to_tip_m == 48.0
    off = copy.deepcopy(cfg)
    off["assessment"]["criteria"]["tip_air_gap_m"] = None
    off = validate(off)
    assert tip_settings_from_config(off) is None
    assert "tip_air_gap_m" not in criteria_array(off["assessment"]["criteria"])["criterion"].values
    # the screening scores its grid on the motion criteria; the tip is judged on the
    # assessed candidates
    assert "tip_air_gap_m" not in scoring_from_config(cfg).criteria


def test_tip_points_default_to_below_the_padeyes():
    p = rigid_plant(2)
    ds = tip_response(p, excitation(constant_hinge(heave=1.0), [90.0]), (0.0, 0.0), TZ,
                      {"none": 0.0}, settings(offsets=None), gamma=3.3, g=G)
    assert ds["tip"].values.tolist() == ["pf", "pa", "sf", "sa"]
    np.testing.assert_allclose(ds["tip_y"], p["padeye"].sel(axis="y"))
    np.testing.assert_allclose(ds["tip_x"], p["padeye"].sel(axis="x"))


def test_response_datasets_follow_the_registry_with_the_tip_statistics(cfg):
    import report_fixtures as rf

    from jls.stages.response import response_dataset
    from jls.stages.response_variants import response_variants
    from jls.tugger.loads import LOAD_VARIABLES
    plant, motion = rf.plant(), rf.vessel_motion()
    tip = tip_settings_from_config(cfg)
    kw = dict(gamma=3.3, exposure_h=3.0, omega_step=0.01,
              outside_policy={"zero_above_rad_s": 2.0, "reason": "test"}, shown=())
    ds = response_dataset(plant, motion, [6.5, 8.5], rf.HEADINGS, {"none": 0.0}, tip=tip, g=G, **kw)
    for name in ("tip_sigma", "tip_tz_response", "tip_n_cycles", "tip_mpm"):
        assert ds[name].dims == ("candidate", "tugger", "heading", "tz", "tip")
    assert ds["tip_height"].dims == ("candidate",) and ds["wave_mpm"].dims == ("tz",)
    assert ds.attrs["tip_crest"] == "forristall_long_crested"
    registry.check(ds, "response")
    registry.check(ds.drop_vars(LOAD_VARIABLES), "operability")
    kw.pop("shown")
    variants = response_variants(plant, motion, ["baseline"], [6.5], rf.HEADINGS, {"none": 0.0},
                                 tip=tip, g=G, **kw)
    registry.check(variants, "response_variants")
    assert variants["tip_mpm"].sizes["candidate"] == 9
    without = response_dataset(plant, motion, [6.5], rf.HEADINGS, {"none": 0.0}, g=G, **kw)
    assert "tip_mpm" not in without and without.attrs["tip_crest"].startswith("not computed")
    registry.check(without, "response")
    # the tip taken lower by the splash clearance's tolerance budget (0.75 m by default)
    assert tip.height_allowance_m == pytest.approx(0.75)
    np.testing.assert_allclose(ds["tip_height"], 119.46 - plant["drop_height"].values - 48.0 - 0.75)
    for layout in ("response", "operability", "response_variants"):
        spec = registry.layout(layout)
        assert {"tip_crest", "tip_clearance"} <= set(spec["attrs"])
        assert "assessment.tip_clearance" in spec["config"]
        for name in ("tip_sigma", "tip_tz_response", "tip_n_cycles", "tip_mpm", "tip_x", "tip_y",
                     "tip_height", "wave_sigma", "wave_n_cycles", "wave_mpm", "wave_steepness"):
            var = spec["variables"][name]
            assert var["optional"] and tuple(var["dims"]) == ds[name].dims, (layout, name)
    assert "tip_crest" in registry.layout("workability")["attrs"]


def test_the_tip_is_taken_lower_by_the_splash_budget(cfg):
    """The splash clearance's tolerance budget (wire length and creep, hinge height,
    draught and trim, tip fabrication) lowers the tip the criterion takes; a budget of
    nothing leaves the nominal height."""
    tip = tip_settings_from_config(cfg)
    budget = cfg["rigging"]["limits"]["tolerance_budget"]["splash_clearance_m"]
    assert tip.height_allowance_m == pytest.approx(sum(budget.values()))
    assert "below the nominal" in tip.describe()
    bare = copy.deepcopy(cfg)
    bare["rigging"]["limits"]["tolerance_budget"]["splash_clearance_m"] = {}
    none = tip_settings_from_config(bare)
    assert none.height_allowance_m == 0.0 and "below the nominal" not in none.describe()
    from jls.response.tip import still_water_height
    assert float(still_water_height(none, 60.0) - still_water_height(tip, 60.0)) == pytest.approx(
        tip.height_allowance_m)


def _brentq_limit(A, mr, me, s, n, crest):
    """Hs with D(Hs) = A by scipy's brentq on the demand of the module (an independent
    root finder: bracketing, no derivative)."""
    from scipy.optimize import brentq
    if not A > 0:
        return 0.0
    f = lambda h: float(tip_clearance.demand(h, mr, me, s, n, crest)[0]) - A  # noqa: E731
    return brentq(f, 0.0, A / mr, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)


@pytest.mark.parametrize("crest", ["forristall_long_crested", "forristall_short_crested"])
def test_compiled_newton_equals_brentq_to_1e_9(crest):
    # the limiting Hs of the compiled kernel against an independent bracketing solver on
    # random hours (allowances, motions, steepness below and beyond the S1 cap), and the
    # special entries: allowance not positive -> 0, no motion -> the cap's closed form or
    # infinity, NaN statistics -> NaN
    rng = np.random.default_rng(11)
    m = 300
    A, mr, me = rng.uniform(0.2, 15, m), rng.uniform(0.05, 2.5, m), rng.uniform(0.5, 1.3, m)
    s, n = rng.uniform(0.002, 0.08, m), rng.uniform(2, 5000, m)
    H = tip_clearance.limiting_hs(A, mr, me, s, n, crest)
    ref = np.array([_brentq_limit(*x, crest) for x in zip(A, mr, me, s, n)])
    np.testing.assert_allclose(H, ref, rtol=1e-9)
    assert (s * H > tip_clearance.S1_MAX).any() and (s * H < tip_clearance.S1_MAX).any()   # both branches
    odd = tip_clearance.limiting_hs([-1.0, 0.0, 5.0, np.nan, 5.0], [1.0, 1.0, np.nan, 1.0, 1.0],
                                    [1.0, 1.0, 1.0, 1.0, np.nan], 0.01, 1000.0, crest)
    assert odd[0] == 0.0 and odd[1] == 0.0 and np.isnan(odd[2:]).all()


def test_hourly_tip_utilisation_is_the_worst_tip_points_by_brentq():
    # sea_state_criteria.tip_utilisation solves at the tip point of the largest MPM_r only:
    # the result equals the largest Hs / Hs_lim over every point solved on its own
    from jls.assessment.sea_state_criteria import tip_utilisation
    from jls.response.statistics import from_moments
    rng = np.random.default_rng(5)
    n_s, n_c, n_t, n_p = 6, 3, 2, 3
    stats = {"tip_m0": rng.uniform(0.05, 0.6, (n_s, n_c, n_t, n_p)), "hs": rng.uniform(0.5, 4.0, n_s),
             "wave_m0": rng.uniform(0.05, 0.8, n_s), "wave_t1": rng.uniform(5.0, 12.0, n_s),
             "tip_height": np.array([7.5, 9.0, 1.0])}                     # the last below the gap
    stats["tip_m2"] = stats["tip_m0"] * rng.uniform(0.2, 0.6, stats["tip_m0"].shape)
    stats["wave_m2"] = stats["wave_m0"] * rng.uniform(0.3, 0.8, n_s)
    stats["tip_m0"][2, 1, 0, 1] = np.nan                                  # unknown statistics: NaN
    gap, crest, T = 1.5, "forristall_long_crested", 3 * 3600.0
    u, clearance = tip_utilisation(stats, gap, crest, exposure_h=3.0, cycles="response", g=G)
    r = from_moments(stats["tip_m0"], stats["tip_m2"], T, "response")["mpm"]
    w = from_moments(stats["wave_m0"], stats["wave_m2"], T, "response")
    hs = stats["hs"]
    for i, c, t in np.ndindex(n_s, n_c, n_t):
        A = stats["tip_height"][c] - gap
        args = (w["mpm"][i] / hs[i], 2 * np.pi / (G * stats["wave_t1"][i] ** 2), w["n_cycles"][i], crest)
        per_point = [hs[i] / _brentq_limit(A, r[i, c, t, p] / hs[i], *args) if np.isfinite(r[i, c, t, p])
                     else np.nan for p in range(n_p)] if A > 0 else [np.inf]
        F = tip_clearance.crest_factor(hs[i], args[1], args[2], crest)[0]
        lowest = min(stats["tip_height"][c] - r[i, c, t, p] - (F - 1) * w["mpm"][i] for p in range(n_p))
        if np.isnan(per_point).any():
            assert np.isnan(u[i, c, t]) and np.isnan(clearance[i, c, t])
        elif c == 2:
            assert np.isinf(u[i, c, t])
        else:
            assert u[i, c, t] == pytest.approx(max(per_point), rel=1e-9)
            assert clearance[i, c, t] == pytest.approx(lowest, rel=1e-12)
