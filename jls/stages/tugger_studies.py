"""Tugger studies of the report (chapter 6 of the study), baseline rigging: the decay
tests of section 6.6 (release from an offset on a still vessel, every configured setting)
and the damping-slope sweep of table 6.6 (time domain, winch capacity held fixed, one wave
record per wave period shared by every slope). Layout ``tugger_studies`` of the registry.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.io import registry

#: Decay curves are stored at this step [s] (the integration runs at its own).
DECAY_STORE_STEP_S = 0.5


def tugger_studies(cfg, motion: xr.Dataset, source="config", workers=1) -> xr.Dataset:
    """Decay curves and measures per configured tugger, and the slope sweep of
    ``timedomain.slope_sweep``."""
    from jls.config.builders import candidate_plant, settings_from_config, tuggers_from_config
    from jls.timedomain.decay import decay
    from jls.timedomain.sweep import slope_sweep

    td = cfg["timedomain"]
    plant = candidate_plant(cfg, "baseline", source)
    tuggers = list(tuggers_from_config(cfg, source).values())
    off = motion.attrs["fairlead_offset_m"]
    release = float(td["decay_release_m"])
    runs = [decay(plant, t, release, fairlead_offset_m=off) for t in tuggers]
    stride = max(1, int(round(DECAY_STORE_STEP_S / (runs[0].time[1] - runs[0].time[0]))))
    t = runs[0].time[::stride]
    ds = xr.Dataset(coords={"tugger": [tg.name for tg in tuggers], "decay_time": t,
                            "c_tugger": ("tugger", [tg.c for tg in tuggers])})
    ds["decay_sway"] = (("tugger", "decay_time"), np.array([r.sway[::stride] for r in runs]))
    ds["decay_time_to_10pct"] = ("tugger", [r.time_to_10pct for r in runs])
    ds["decay_zeta_first_cycle"] = ("tugger", [r.zeta_first_cycle for r in runs])
    sw = td["slope_sweep"]
    sweep = slope_sweep(plant, motion, sw["slopes_kN_s_per_m"], sw["tz_s"], sw["hs_m"],
                        sw["heading_deg"], capacity_kN=sw["capacity_kN"],
                        floor_kN=sw["floor_kN"], gamma=cfg["sea"]["gamma"],
                        duration_s=sw["duration_h"] * 3600.0, settings=settings_from_config(cfg),
                        workers=workers)
    sweep = sweep.rename(tz="sweep_tz")
    for name in ("mpm", "at_capacity_fraction", "sigma_reduction", "mpm_no_tugger"):
        ds[f"sweep_{name}"] = sweep[name]
    registry.annotate(ds, "tugger_studies")
    ds.attrs.update(release_m=release, sweep_hs_m=float(sw["hs_m"]),
                    sweep_heading_deg=float(sw["heading_deg"]),
                    sweep_capacity_kN=float(sw["capacity_kN"]),
                    sweep_duration_s=float(sweep.attrs["duration_s"]),
                    critical_slope_kN_s_per_m=float(sweep.attrs["critical_slope_kN_s_per_m"]))
    return ds


__all__ = ["tugger_studies"]
