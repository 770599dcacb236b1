"""Small synthetic datasets in the layout of the README (Outputs), for the report tests.

Everything is computed, not typed in, so the five datasets agree with each other the
way the pipeline's do:

* the plant of two candidates ("baseline", the shipped layout, and "detuned", the
  study's optimum direction: narrower top spread, drop at the splash limit) from
  :func:`jls.candidates.plant_dataset`;
* a synthetic beam-sea vessel RAO (roll resonance near 15 s, as the representative
  hull), transferred to the hinge and fairleads by rigid-body kinematics;
* transfer functions (M, C, K with a linear tugger damper) and JONSWAP unit-Hs
  statistics with N = 3 h / Tz_response;
* two legs of Hs-Tz scatter (different bin sets, so the union has absent bins) and
  the workability computed from the pass flags and the probabilities.

The Tz grid of the response (and so of ``hs_limit``) is finer than the scatter's, as
it may be in the pipeline; the scatter cells of ``workability`` then carry NaN at the
Tz values that no leg has.
"""

from __future__ import annotations

import hashlib

import numpy as np
import xarray as xr

from pathlib import Path

from jls.assembly import rigging_from_config
from jls.candidates import plant_dataset
from jls.config import load

ROOT = Path(__file__).resolve().parents[1]

G = 9.81
DOF = ["sway", "heave", "roll", "yaw"]
VESSEL_DOF = ["surge", "sway", "heave", "roll", "pitch", "yaw"]
RESPONSES = ["relative_sway", "relative_heave", "relative_roll", "relative_yaw"]
WIRES = ["port-fwd-anchor", "port-aft-anchor", "starboard-fwd-anchor", "starboard-aft-anchor"]
HINGE = np.array([-215.263, 1.0, 99.998])
FAIRLEAD_OFFSET = np.array([0.0, 37.5, -82.5])
CRITERIA = {"relative_sway_m": ("relative_sway", 3.0), "relative_yaw_deg": ("relative_yaw", 2.0)}
TUGGERS = {"none": 0.0, "reference": 1000.0}
HEADINGS = [90.0]
CONFIG_SHA = hashlib.sha256(b"synthetic report test configuration").hexdigest()
EXPOSURE_H = 3.0


def _attrs(ds: xr.Dataset, table: dict) -> xr.Dataset:
    for name, (long_name, units) in table.items():
        ds[name].attrs.update(long_name=long_name, units=units)
    return ds


def _global(ds: xr.Dataset, rule: str) -> None:
    ds.attrs.update(jls_version="0.1.0", config_sha256=CONFIG_SHA, created_by=rule,
                    Conventions="CF-1.10")


# -- plant ----------------------------------------------------------------------------
def plant() -> xr.Dataset:
    """The plant dataset of the shipped rigging, baseline and detuned, as the pipeline
    builds it (jls.candidates.plant_dataset)."""
    rig = rigging_from_config(load(ROOT / "config" / "config.yaml"))
    ds, _ = plant_dataset(rig, {"baseline": {}, "detuned": {"top_spread_y": 37.845,
                                                            "drop_height": 66.46}})
    _global(ds, "plant")
    return ds


# -- vessel ---------------------------------------------------------------------------
def vessel_rao(omega) -> np.ndarray:
    """Synthetic beam-sea RAO (n_w, 6) of a large crane vessel, motion = Re{RAO A e^iwt}."""
    w = np.asarray(omega, float)
    r_roll, r_heave = w / (2 * np.pi / 15.3), w / (2 * np.pi / 9.5)
    slope = w**2 / G * np.exp(-((w / 0.72) ** 4))                  # beam cancels short waves
    roll = 0.55 * slope / (1 - r_roll**2 + 2j * 0.05 * r_roll)
    heave = np.exp(-((w / 0.75) ** 2)) / (1 - r_heave**2 + 2j * 0.25 * r_heave)
    sway = -0.9j / np.sqrt(1 + (w / 0.55) ** 4)
    yaw = 4e-4 * np.exp(-(((w - 0.55) / 0.15) ** 2)) * (1 + 0.5j)
    small = 0.05 * np.exp(-((w / 0.5) ** 2))
    return np.stack([small, sway, heave, roll, 0.2 * small / 100, yaw], axis=-1)


def point_translation(rao, r) -> np.ndarray:
    return rao[..., 0:3] + np.cross(rao[..., 3:6], np.asarray(r, float))


def hinge_rao(rao) -> np.ndarray:
    t = point_translation(rao, HINGE)
    return np.stack([t[..., 1], t[..., 2], rao[..., 3], rao[..., 5]], axis=-1)


def vessel_motion() -> xr.Dataset:
    omega = np.round(np.arange(0.20, 1.6001, 0.02), 4)
    rao = vessel_rao(omega)[:, None, :]                             # one heading
    qb = hinge_rao(rao)
    fl = np.stack([point_translation(rao, HINGE + FAIRLEAD_OFFSET * s)
                   for s in (np.array([1, 1, 1]), np.array([1, -1, 1]))], axis=2)
    ds = xr.Dataset(
        {"rao_re": (("omega", "heading", "vessel_dof"), rao.real),
         "rao_im": (("omega", "heading", "vessel_dof"), rao.imag),
         "hinge_re": (("omega", "heading", "dof"), qb.real),
         "hinge_im": (("omega", "heading", "dof"), qb.imag),
         "fairlead_re": (("omega", "heading", "side", "axis"), fl.real),
         "fairlead_im": (("omega", "heading", "side", "axis"), fl.imag)},
        coords={"omega": omega, "heading": HEADINGS, "vessel_dof": VESSEL_DOF, "dof": DOF,
                "side": ["port", "starboard"], "axis": ["x", "y", "z"]})
    for part in ("re", "im"):
        _attrs(ds, {f"rao_{part}": ("vessel RAO", "m/m or rad/m"),
                    f"hinge_{part}": ("hinge excitation", "m/m or rad/m"),
                    f"fairlead_{part}": ("tugger fairlead translation", "m/m")})
    _attrs(ds, {"omega": ("wave angular frequency", "rad/s"),
                "heading": ("relative wave heading", "degree")})
    _global(ds, "vessel_motion")
    ds.attrs.update(
        reference_point_m=[0.0, 0.0, 0.0], hinge_m=HINGE.tolist(),
        fairlead_offset_m=FAIRLEAD_OFFSET.tolist(),
        heading_convention="WAMIT: propagation relative to +x, 180 head seas, 90 beam seas",
        phase_convention="motion = Re{RAO A exp(i omega t)}",
        vessel_source="synthetic_beam_sea.csv (csv)",
        vessel_description=("Representative hull of the vessel class (synthetic RAO for the "
                            "report tests), not the vessel's own data; roll period 15.3 s."),
        extrapolation="none: sea states with more than 0.1 % of their energy outside the "
                      "RAO range are rejected")
    return ds


# -- response -------------------------------------------------------------------------
def tp_from_tz(tz, gamma=3.3):
    return tz / (0.6673 + 0.05037 * gamma - 0.006230 * gamma**2 + 0.0003341 * gamma**3)


def jonswap_unit(omega, tz, gamma=3.3):
    """JONSWAP at Hs = 1 m, normalised numerically to m0 = 1/16: (n_tz, n_w)."""
    wp = 2 * np.pi / tp_from_tz(np.asarray(tz, float))[:, None]
    w = np.asarray(omega, float)[None, :]
    sig = np.where(w <= wp, 0.07, 0.09)
    s = w**-5 * np.exp(-1.25 * (wp / w) ** 4) * gamma ** np.exp(-((w - wp) ** 2) / (2 * sig**2 * wp**2))
    x = np.linspace(0.05, 6.0, 8000)[None, :]
    wx = x * wp
    sx = wx**-5 * np.exp(-1.25 * (wp / wx) ** 4) * gamma ** np.exp(
        -((wx - wp) ** 2) / (2 * np.where(wx <= wp, 0.07, 0.09) ** 2 * wp**2))
    return s / (16.0 * np.trapezoid(sx, wx, axis=-1)[:, None])


def response(plant_ds: xr.Dataset, tz) -> xr.Dataset:
    wn = 2 * np.pi / plant_ds["natural_period"].values[:, :2].ravel()
    fine = np.concatenate([wn_i + np.linspace(-0.03, 0.03, 121) for wn_i in wn])
    omega = np.unique(np.round(np.concatenate([np.arange(0.2, 1.6, 0.005), fine]), 8))
    rao = vessel_rao(omega)
    qb = hinge_rao(rao)                                             # (w, 4)
    y_f = point_translation(rao, HINGE + FAIRLEAD_OFFSET)[:, 1]     # same sway both sides
    M, K, C, Kb = (plant_ds[k].values for k in ("M", "K", "C", "Kb"))
    c_t = np.array(list(TUGGERS.values()))
    A = (K[:, None, None] - omega[None, None, :, None, None] ** 2 * M[:, None, None]
         + 1j * omega[None, None, :, None, None] * C[:, None, None])
    A = np.broadcast_to(A, (2, len(c_t), len(omega), 4, 4)).copy()
    A[..., 0, 0] += 1j * omega[None, None, :] * c_t[None, :, None]
    load = -np.einsum("cij,wj->cwi", Kb, qb)[:, None].repeat(len(c_t), 1)
    load[..., 0] += 1j * omega * c_t[:, None] * y_f
    q = np.linalg.solve(A, load[..., None])[..., 0]                 # (c, t, w, 4)
    rel = (q - qb) * np.array([1, 1, 180 / np.pi, 180 / np.pi])
    H = rel[:, :, None]                                             # heading axis
    S = jonswap_unit(omega, tz)                                     # (tz, w)
    wts = np.gradient(omega)
    H2 = np.abs(H) ** 2                                             # (c, t, h, w, r)
    m0 = np.einsum("cthwr,w,zw->cthzr", H2, wts, S)
    m2 = np.einsum("cthwr,w,zw->cthzr", H2, wts * omega**2, S)
    sigma = np.sqrt(m0)
    tz_r = 2 * np.pi * np.sqrt(m0 / m2)
    n = EXPOSURE_H * 3600 / tz_r
    mpm = sigma * np.sqrt(2 * np.log(n))
    dims = ("candidate", "tugger", "heading", "tz", "response")
    ds = xr.Dataset(
        {"transfer_re": (("shown_candidate", "tugger", "heading", "omega", "response"), H.real),
         "transfer_im": (("shown_candidate", "tugger", "heading", "omega", "response"), H.imag),
         "sigma": (dims, sigma), "tz_response": (dims, tz_r), "n_cycles": (dims, n),
         "mpm": (dims, mpm)},
        coords={"candidate": plant_ds["candidate"].values,
                "shown_candidate": plant_ds["candidate"].values, "tugger": list(TUGGERS),
                "c_tugger": ("tugger", c_t), "heading": HEADINGS, "tz": tz, "omega": omega,
                "response": RESPONSES})
    per = "m or degree per m of Hs"
    _attrs(ds, {"transfer_re": ("relative motion per unit wave amplitude", "m/m or degree/m"),
                "transfer_im": ("relative motion per unit wave amplitude", "m/m or degree/m"),
                "sigma": ("standard deviation at Hs = 1 m", per),
                "tz_response": ("response zero-crossing period", "s"),
                "n_cycles": ("response cycles in the exposure", "1"),
                "mpm": ("most probable maximum at Hs = 1 m", per),
                "c_tugger": ("tugger damping slope", "kN s/m"), "tz": ("Tz", "s"),
                "omega": ("wave angular frequency", "rad/s")})
    _global(ds, "response")
    ds.attrs.update(exposure_h=EXPOSURE_H, mpm_cycles="response: N = exposure / Tz_response",
                    gamma=3.3, spectrum="JONSWAP, sigma_a 0.07, sigma_b 0.09")
    return ds


# -- sea states -----------------------------------------------------------------------
LEGS = {  # name: (hs edges, tz edges, duration h, mean ln Hs, Tz offset, records)
    "north_sea": (np.arange(0.0, 6.01, 1.0), np.arange(3.0, 9.01, 1.0), 60.0, 0.35, 3.6, 2920),
    "biscay": (np.arange(0.0, 7.01, 1.0), np.arange(4.0, 10.01, 1.0), 96.0, 0.75, 4.4, 8760),
}


def steepness_hs(tz, steepness=1 / 15):
    return G * np.asarray(tz, float) ** 2 * steepness / (2 * np.pi)


def sea_states() -> xr.Dataset:
    hs = np.arange(0.5, 7.0, 1.0)
    tz = np.arange(3.5, 10.0, 1.0)
    n_leg = len(LEGS)
    prob = np.zeros((n_leg, hs.size, tz.size))
    edges = {k: np.full((n_leg, n), np.nan) for k, n in
             (("hs_lower", hs.size), ("hs_upper", hs.size), ("tz_lower", tz.size), ("tz_upper", tz.size))}
    totals, durations = [], []
    for i, (name, (he, te, dur, mu, t0, n_rec)) in enumerate(LEGS.items()):
        hc, tc = (he[:-1] + he[1:]) / 2, (te[:-1] + te[1:]) / 2
        ih, it = np.searchsorted(hs, hc), np.searchsorted(tz, tc)
        p = (np.exp(-((np.log(hc) - mu) ** 2) / (2 * 0.55**2)) / hc)[:, None] * np.exp(
            -((tc[None, :] - (t0 + 1.1 * np.sqrt(hc)[:, None])) ** 2) / (2 * 0.9**2))
        counts = np.round(p / p.sum() * n_rec)
        prob[i][np.ix_(ih, it)] = counts / counts.sum()
        edges["hs_lower"][i, ih], edges["hs_upper"][i, ih] = he[:-1], he[1:]
        edges["tz_lower"][i, it], edges["tz_upper"][i, it] = te[:-1], te[1:]
        totals.append(counts.sum())
        durations.append(dur)
    steep = hs[:, None] > steepness_hs(tz)[None, :] + 1e-9
    steep = np.broadcast_to(steep, prob.shape) & ~np.isnan(edges["hs_upper"][:, :, None]) & \
        ~np.isnan(edges["tz_upper"][:, None, :])
    dur = np.array(durations)
    ds = xr.Dataset(
        {"probability": (("leg", "hs", "tz"), prob),
         **{k: (("leg", k[:2]), v) for k, v in edges.items()},
         "steep": (("leg", "hs", "tz"), steep.astype(np.int8)),
         "steep_probability": ("leg", (prob * steep).sum((1, 2))),
         "heading_probability": (("leg", "heading"), np.ones((n_leg, 1))),
         "duration_h": ("leg", dur), "leg_weight": ("leg", dur / dur.sum()),
         "record_total": ("leg", np.array(totals))},
        coords={"leg": list(LEGS), "hs": hs, "tz": tz, "heading": HEADINGS})
    _attrs(ds, {"probability": ("probability of the Hs-Tz cell within the leg", "1"),
                "hs_lower": ("lower Hs bin edge", "m"), "hs_upper": ("upper Hs bin edge", "m"),
                "tz_lower": ("lower Tz bin edge", "s"), "tz_upper": ("upper Tz bin edge", "s"),
                "steep": ("cell above the wave-steepness ceiling", "1"),
                "steep_probability": ("probability carried by steep cells", "1"),
                "heading_probability": ("probability of the relative wave heading", "1"),
                "duration_h": ("leg duration", "h"), "leg_weight": ("leg weight", "1"),
                "record_total": ("sum of the raw table values", "1"),
                "hs": ("significant wave height, bin centre", "m"),
                "tz": ("zero-up-crossing period, bin centre", "s"),
                "heading": ("relative wave heading", "degree")})
    ds["steep"].attrs.update(flag_values=np.array([0, 1], np.int8), flag_meanings="false true")
    _global(ds, "sea_states")
    ds.attrs.update(route="test_route", steepness_rule="study",
                    **{f"source_{leg}": f"{leg}.csv" for leg in LEGS})
    return ds


# -- workability ----------------------------------------------------------------------
def workability(sea: xr.Dataset, resp: xr.Dataset, hs_in_bin="centre") -> xr.Dataset:
    names = list(CRITERIA)
    limit = xr.DataArray([CRITERIA[k][1] for k in names], dims="criterion",
                         coords={"criterion": names,
                                 "response": ("criterion", [CRITERIA[k][0] for k in names])})
    unit = resp["mpm"].sel(response=limit["response"]).drop_vars("response")
    hs = sea["hs"].broadcast_like(sea["hs_upper"]) if hs_in_bin == "centre" else sea["hs_upper"]
    mpm = hs * unit.sel(tz=sea["tz"])
    util = mpm / limit
    passes = (util <= 1.0).all("criterion")
    governing = util.fillna(-np.inf).argmax("criterion")
    weight = sea["probability"] * sea["heading_probability"]
    work_leg = (weight * passes).sum(("heading", "hs", "tz"))
    index = xr.DataArray(np.arange(len(names)), dims="criterion", coords={"criterion": names})
    share = (weight * ~passes * (governing == index)).sum(("heading", "hs", "tz"))
    hs_lim_c = limit / unit
    ceiling = xr.DataArray(steepness_hs(resp["tz"].values), dims="tz", coords={"tz": resp["tz"]})
    order = ("candidate", "tugger", "leg", "heading", "hs", "tz")
    ds = xr.Dataset({
        "mpm": mpm.transpose(*order, "criterion"),
        "utilisation": util.transpose(*order, "criterion"),
        "passes": passes.transpose(*order).astype(np.int8),
        "governing": governing.transpose(*order).astype(np.int8),
        "workability_leg": work_leg.transpose("candidate", "tugger", "leg"),
        "workability_route": (work_leg * sea["leg_weight"]).sum("leg"),
        "governing_share": share.transpose("candidate", "tugger", "leg", "criterion"),
        "hs_limit": np.minimum(hs_lim_c.min("criterion"), ceiling).transpose(
            "candidate", "tugger", "heading", "tz"),
        "hs_limit_criterion": hs_lim_c.transpose("candidate", "tugger", "heading", "tz", "criterion"),
        "steepness_limit": ceiling, "limit": limit})
    _attrs(ds, {"mpm": ("most probable maximum in the cell", "m or degree"),
                "utilisation": ("MPM over the criterion limit", "1"),
                "passes": ("every criterion holds in the cell", "1"),
                "governing": ("criterion with the highest utilisation (index)", "1"),
                "workability_leg": ("workable fraction of the leg", "1"),
                "workability_route": ("workable fraction of the route", "1"),
                "governing_share": ("probability of failing cells governed by the criterion", "1"),
                "hs_limit": ("limiting significant wave height", "m"),
                "hs_limit_criterion": ("limiting significant wave height of the criterion", "m"),
                "steepness_limit": ("wave steepness ceiling", "m"),
                "limit": ("criterion limit", "m or degree")})
    ds["governing"].attrs["flag_meanings"] = " ".join(names)
    _global(ds, "workability")
    ds.attrs.update(route="test_route", hs_in_bin=hs_in_bin, exposure_h=EXPOSURE_H,
                    mpm_cycles=resp.attrs["mpm_cycles"])
    return ds


def provenance() -> dict:
    def sha(text):
        return hashlib.sha256(text.encode()).hexdigest()
    return {
        "jls_version": "0.1.0", "config_sha256": CONFIG_SHA, "created": "2025-01-15T10:30:00+00:00",
        "inputs": {"leg north_sea": {"path": "config/routes/north_sea.csv", "sha256": sha("ns")},
                   "leg biscay": {"path": "config/routes/biscay.csv", "sha256": sha("bb")},
                   "vessel RAO": {"path": "config/vessel/synthetic_beam_sea.csv", "sha256": sha("v")}},
        "vessel_source": "synthetic_beam_sea.csv (csv)",
        "vessel_description": vessel_motion().attrs["vessel_description"],
        "python": "3.11.7 (linux)",
        "packages": {"numpy": "2.4.6", "xarray": "2026.9.0", "matplotlib": "3.11.2", "typst": "0.15.2"},
    }


def datasets() -> dict:
    """The five datasets of a synthetic route, keyed as render_report takes them."""
    p = plant()
    resp = response(p, np.round(np.arange(3.0, 10.51, 0.25), 3))
    sea = sea_states()
    return {"sea_states": sea, "vessel_motion": vessel_motion(), "plant": p, "response": resp,
            "workability": workability(sea, resp)}
