"""Small synthetic datasets in the layout of the README (Outputs), for the report tests.

The five datasets are made by the library's own builders, as the pipeline makes them,
so they agree with each other and with jls:

* the plant of the shipped rigging and its candidates: :func:`jls.plant.candidates.plant_dataset`;
* a synthetic beam-sea vessel RAO (roll resonance near 15 s, as the representative
  hull; yaw only at round-off level, as a symmetric hull in beam seas) written with
  :func:`jls.vessel.rao.save_rao` and read back by :func:`jls.stages.vessel_motion.vessel_motion`, which
  carries it to the hinge and the fairleads;
* two legs of Hs-Tz scatter (:func:`jls.sea.scatter.scatter_dataset`, different bin sets
  so the union has absent bins) combined by :func:`jls.stages.sea_states.sea_states`;
* transfer functions and unit-Hs statistics: :func:`jls.stages.response.response_dataset`
  on a Tz grid finer than the scatter's, as the operability grid is;
* the assessment: the workability stage's nominal part and attributes
  (:mod:`jls.stages.workability`) with that grid as the operability curve.

Only the synthetic inputs (the RAO shape, the scatter's probabilities) are defined here.
"""

from __future__ import annotations

import hashlib
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

from jls.config.builders import operation_basis, rigging_from_config, tuggers_from_config
from jls.config.loader import fill_defaults, load, schema
from jls.plant.candidates import plant_dataset
from jls.sea.scatter import scatter_dataset
from jls.stages import workability as workability_stage
from jls.stages.response import response_dataset
from jls.stages.sea_states import sea_states as build_sea_states
from jls.stages.vessel_motion import vessel_motion as build_vessel_motion
from jls.vessel.rao import make_rao_dataset, save_rao

ROOT = Path(__file__).resolve().parents[1]

G = 9.81
HINGE = (-215.263, 1.0, 99.998)
CRITERIA = {"relative_sway_m": 3.0, "relative_yaw_deg": 2.0}
# detuned: the study's optimum with the drop at the splash-clearance limit (66.46 m) less
# the tolerance budget (0.75 m), as the shipped configuration
CANDIDATES = {"baseline": {}, "detuned": {"top_spread_y": 37.845, "drop_height": 65.71}}
TUGGERS = {"none": 0.0, "reference": 1000.0}
HEADINGS = [90.0]
CONFIG_SHA = hashlib.sha256(b"synthetic report test configuration").hexdigest()
EXPOSURE_H = 3.0
GAMMA = 3.3
RESPONSE_TZ = np.round(np.arange(3.0, 10.51, 0.25), 3)
OUTSIDE_REASON = "synthetic hull: no motion in waves outside the tabulated range"
VESSEL = {"rao_file": "synthetic_beam_sea.nc", "hinge_m": list(HINGE), "fairlead_drop_m": 82.5,
          "fairlead_half_span_m": 37.5, "rao_reference_point_height_m": 19.462,
          "outside_rao_range": {"zero_below_rad_s": 0.2, "zero_above_rad_s": 2.0,
                                "reason": OUTSIDE_REASON},
          "description": ("Representative hull of the vessel class (synthetic RAO for the report "
                          "tests), not the vessel's own data; roll period 15.3 s.")}
# Sections of the configuration each dataset depends on, and a hash of each as the
# pipeline would write it in the dataset's config_sha256.
SECTION_HASHES = {name: hashlib.sha256(f"synthetic sections of {name}".encode()).hexdigest()
                  for name in ("sea_states", "vessel_motion", "plant", "response", "workability")}


def _global(ds: xr.Dataset, rule: str, config_sha=CONFIG_SHA) -> xr.Dataset:
    ds.attrs.update(jls_version="0.1.0", config_sha256=config_sha, created_by=f"rule {rule}",
                    Conventions="CF-1.10")
    return ds


# -- plant ----------------------------------------------------------------------------
def plant(candidates=None) -> xr.Dataset:
    """The plant dataset of the shipped rigging and ``candidates`` (name -> design
    variables), built as the pipeline builds it."""
    rig = rigging_from_config(load(ROOT / "config" / "config.yaml"))
    ds, _ = plant_dataset(rig, dict(candidates or CANDIDATES))
    return _global(ds, "plant")


# -- vessel ---------------------------------------------------------------------------
def vessel_rao(omega) -> np.ndarray:
    """Synthetic beam-sea RAO (n_w, 6) of a large crane vessel, motion = Re{RAO A e^iwt}.

    Yaw and pitch are round-off noise (1e-17), as a port-starboard symmetric hull gives
    in beam seas."""
    w = np.asarray(omega, float)
    r_roll, r_heave = w / (2 * np.pi / 15.3), w / (2 * np.pi / 9.5)
    slope = w**2 / G * np.exp(-((w / 0.72) ** 4))                  # beam cancels short waves
    roll = 0.55 * slope / (1 - r_roll**2 + 2j * 0.05 * r_roll)
    heave = np.exp(-((w / 0.75) ** 2)) / (1 - r_heave**2 + 2j * 0.25 * r_heave)
    sway = -0.9j / np.sqrt(1 + (w / 0.55) ** 4)
    noise = 1e-17 * np.cos(37.0 * w) * (1 + 1j)
    surge = 1e-16 * np.sin(23.0 * w)
    return np.stack([surge, sway, heave, roll, noise, noise], axis=-1)


def vessel_motion(tmp_dir=None) -> xr.Dataset:
    """The vessel-motion dataset of the synthetic RAO (jls.stages.vessel_motion.vessel_motion)."""
    omega = np.round(np.arange(0.20, 2.0001, 0.02), 4)
    rao = make_rao_dataset(omega, np.radians(HEADINGS), vessel_rao(omega)[:, None, :],
                           source="synthetic_beam_sea.nc", source_format="netcdf")
    with tempfile.TemporaryDirectory(prefix="jls-fixture-") as tmp:
        save_rao(rao, Path(tmp) / VESSEL["rao_file"])
        vessel = fill_defaults(dict(VESSEL), schema()["properties"]["vessel"])
        ds = build_vessel_motion(vessel, HEADINGS, base_dir=tmp)
    return _global(ds, "vessel_motion")


# -- sea states -----------------------------------------------------------------------
LEGS = {  # name: (hs edges, tz edges, duration h, mean ln Hs, Tz offset, records)
    "north_sea": (np.arange(0.0, 6.01, 1.0), np.arange(3.0, 9.01, 1.0), 60.0, 0.35, 3.6, 2920),
    "biscay": (np.arange(0.0, 7.01, 1.0), np.arange(4.0, 10.01, 1.0), 96.0, 0.75, 4.4, 8760),
}


def leg_table(he, te, mu, t0, n_rec) -> xr.Dataset:
    """A leg's scatter: whole counts from a lognormal Hs and a Gaussian Tz about
    t0 + 1.1 sqrt(Hs)."""
    hc, tc = (he[:-1] + he[1:]) / 2, (te[:-1] + te[1:]) / 2
    p = (np.exp(-((np.log(hc) - mu) ** 2) / (2 * 0.55**2)) / hc)[:, None] * np.exp(
        -((tc[None, :] - (t0 + 1.1 * np.sqrt(hc)[:, None])) ** 2) / (2 * 0.9**2))
    counts = np.round(p / p.sum() * n_rec)
    return scatter_dataset(counts, hs_lower=he[:-1], hs_upper=he[1:], tz_lower=te[:-1],
                           tz_upper=te[1:], values_kind="counts")


def sea_states() -> xr.Dataset:
    route = {"name": "test_route",
             "legs": [{"name": name, "scatter": f"{name}.csv", "duration_h": spec[2],
                       "headings_deg": HEADINGS, "heading_probability": [1.0]}
                      for name, spec in LEGS.items()]}
    legs = {}
    for name, (he, te, _, mu, t0, n_rec) in LEGS.items():
        legs[name] = leg_table(he, te, mu, t0, n_rec)
        legs[name].attrs["source"] = f"{name}.csv"
    return _global(build_sea_states(route, legs, "study"), "sea_states")


# -- response and workability ---------------------------------------------------------
def response(plant_ds: xr.Dataset, motion: xr.Dataset, tuggers=None) -> xr.Dataset:
    ds = response_dataset(plant_ds, motion, RESPONSE_TZ, HEADINGS, dict(tuggers or TUGGERS),
                          gamma=GAMMA, exposure_h=EXPOSURE_H, cycles="response",
                          omega_step=0.004, outside_policy=VESSEL["outside_rao_range"])
    return _global(ds, "merge_response")


def workability(sea: xr.Dataset, resp: xr.Dataset, hs_in_bin="centre") -> xr.Dataset:
    """The workability as the workflow's stage makes it (:mod:`jls.stages.workability`):
    its nominal part (criteria, then the winch limits of the tugger settings, winches
    large enough never to saturate here: the tugger chapter's tests construct saturation
    themselves; the 'fail' policy; no time-domain cells) and its global attributes. The
    bands, the limit sweep and the voyage's probability are not added (no variants)."""
    sections = schema()["properties"]
    items = [fill_defaults({"name": n, "c_kN_s_per_m": c, "max_force_kN": 1.0e5}, sections["tuggers"]["items"])
             for n, c in zip(resp["tugger"].values.tolist(), resp["c_tugger"].values.tolist())]
    cfg = {"assessment": {"criteria": dict(CRITERIA), "winch_saturation": "fail",
                          "max_saturation_fraction": 0.01},
           "sea": {"hs_in_bin": hs_in_bin, "steepness_rule": "study", "gamma": GAMMA},
           "tuggers": items, "operation": {},
           "recommendation": fill_defaults({}, sections["recommendation"])}
    ds = workability_stage.nominal(sea, resp, resp, [], cfg, tuggers_from_config(cfg))
    basis, alpha = operation_basis(cfg["operation"], float(sea["duration_h"].sum()))
    return _global(workability_stage.described(ds, resp, cfg, "test_route", basis, alpha), "workability")


def route_config() -> dict:
    """The synthetic route as the configuration gives it (scatter legs, in sailing order)."""
    return {"legs": [{"name": name, "scatter": f"{name}.csv", "duration_h": spec[2],
                      "headings_deg": HEADINGS, "heading_probability": [1.0]}
                     for name, spec in LEGS.items()]}


def voyage(data: dict) -> xr.Dataset:
    """voyage.nc of the synthetic route, by the workflow's stage (jls.stages.voyage)."""
    from jls.stages.voyage import voyage as build_voyage
    ds = build_voyage(data["sea_states"], data["response"], data["response"], CRITERIA, "centre",
                      route_config(), gamma=3.3)
    ds.attrs["route"] = "test_route"
    return _global(ds, "voyage")


def write_records(folder, hours=24 * 400, seed=2) -> dict:
    """Synthetic hourly (Hs; Tz) records of the synthetic legs (storms that persist for
    days, Tz rising with Hs), written in the hindcast format into ``folder``: leg name ->
    file path."""
    import pandas as pd
    rng = np.random.default_rng(seed)
    out = {}
    t = pd.date_range("2001-01-01", periods=hours, freq="1h")
    for k, (name, spec) in enumerate(LEGS.items()):
        x = np.zeros(hours)
        e = rng.normal(0.0, 0.5 * np.sqrt(1 - 0.985 ** 2), hours)
        for i in range(1, hours):
            x[i] = 0.985 * x[i - 1] + e[i]
        hs = np.clip(np.exp(spec[3] + x), 0.05, 5.9)
        tz = np.clip(spec[4] + 1.1 * np.sqrt(hs) + rng.normal(0, 0.3, hours), te_lo := spec[1][0] + 0.01,
                     spec[1][-1] - 0.01)
        del te_lo
        path = Path(folder) / f"{name}_records.txt"
        lines = ["time (YYYY-MM-DD-HH); significant wave height (m); zero-up-crossing period (s)"]
        lines += [f"{a:%Y-%m-%d-%H}; {h:.4f}; {z:.4f}" for a, h, z in zip(t, hs, tz)]
        path.write_text("\n".join(lines) + "\n")
        out[name] = str(path)
    return out


def voyage_plan(data: dict, records: dict | None = None, criteria=None, hold_points=(), durations=None,
                operation=None) -> xr.Dataset:
    """voyage_plan.nc of the synthetic route by the workflow's stage
    (jls.stages.voyage_plan): scatter legs, carrying ``records`` (leg -> file) beside
    their tables when given; ``hold_points``: legs whose start is one; ``durations``:
    leg -> hours in place of the tables' (a shorter route)."""
    from jls.stages.voyage_plan import voyage_plan as build
    route = route_config()
    for leg in route["legs"]:
        if records:
            leg["records"] = {"file": records[leg["name"]]}
        leg["hold_point"] = leg["name"] in hold_points
    sea = data["sea_states"]
    if durations:
        sea = sea.assign(duration_h=sea["duration_h"].copy(data=[durations[str(n)] for n in sea["leg"].values]))
    op = fill_defaults(dict(operation or {}), schema()["properties"]["operation"])
    ds = build(sea, data["response"], route, dict(criteria or CRITERIA), op, gamma=GAMMA, exposure_h=EXPOSURE_H)
    ds.attrs["route"] = "test_route"
    return _global(ds, "voyage_plan")


def provenance() -> dict:
    def sha(text):
        return hashlib.sha256(text.encode()).hexdigest()
    return {
        "jls_version": "0.1.0", "config_sha256": CONFIG_SHA, "created": "2025-01-15T10:30:00+00:00",
        "inputs": {"leg north_sea": {"path": "config/routes/north_sea.csv", "sha256": sha("ns")},
                   "leg biscay": {"path": "config/routes/biscay.csv", "sha256": sha("bb")},
                   "vessel RAO": {"path": "config/vessel/synthetic_beam_sea.nc", "sha256": sha("v")}},
        "vessel_source": "synthetic_beam_sea.nc (netcdf)",
        "vessel_description": VESSEL["description"],
        "python": "3.11.7 (linux)",
        "packages": {"numpy": "2.4.6", "xarray": "2026.9.0", "matplotlib": "3.11.2", "typst": "0.15.2"},
    }


def datasets(candidates=None, tuggers=None) -> dict:
    """The five datasets of a synthetic route, keyed as render_report takes them."""
    p = plant(candidates)
    motion = vessel_motion()
    resp = response(p, motion, tuggers)
    sea = sea_states()
    return {"sea_states": sea, "vessel_motion": motion, "plant": p, "response": resp,
            "workability": workability(sea, resp)}
