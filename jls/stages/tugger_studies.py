"""Tugger studies of the report (chapter 6 of the study), baseline rigging: the decay
tests of section 6.6 (release from the nonlinear static equilibrium at an offset on a
still vessel, every configured setting) and the damping-slope sweep of table 6.6 (time
domain, winch capacity held fixed, one wave record per wave period shared by every
slope, ending at the plant's own critical slope 2 M w_n unless
``slope_sweep.end_at_critical`` is off). Layout ``tugger_studies`` of the registry.
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
    from jls.timedomain.resolution import require_resolution
    from jls.timedomain.run import record_spacing
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
    ds["decay_initial_heave"] = ("tugger", [r.q0[1] for r in runs])
    ds["decay_initial_wire_tension_min"] = ("tugger", [r.wire_tension0.min() for r in runs])
    ds["decay_initial_wire_tension_max"] = ("tugger", [r.wire_tension0.max() for r in runs])
    sw = td["slope_sweep"]
    settings = settings_from_config(cfg)
    om = motion["omega"].values
    field, value = (("timedomain.n_components", settings.n_components) if settings.n_components
                    else ("timedomain.slope_sweep.duration_h", sw["duration_h"]))
    require_resolution(plant, record_spacing(plant, settings, sw["duration_h"] * 3600.0, (om.min(), om.max())),
                       field=field, value=value, source=source)
    sweep = slope_sweep(plant, motion, sw["slopes_kN_s_per_m"], sw["tz_s"], sw["hs_m"],
                        sw["heading_deg"], capacity_kN=sw["capacity_kN"],
                        floor_kN=sw["floor_kN"], gamma=cfg["sea"]["gamma"],
                        duration_s=sw["duration_h"] * 3600.0, settings=settings,
                        end_at_critical=sw["end_at_critical"], workers=workers)
    sweep = sweep.rename(tz="sweep_tz")
    for name in ("mpm", "at_capacity_fraction", "sigma_reduction", "mpm_no_tugger"):
        ds[f"sweep_{name}"] = sweep[name]
    registry.annotate(ds, "tugger_studies")
    ds.attrs.update(release_m=release, sweep_hs_m=float(sw["hs_m"]),
                    sweep_heading_deg=float(sw["heading_deg"]),
                    sweep_capacity_kN=float(sw["capacity_kN"]),
                    sweep_duration_s=float(sweep.attrs["duration_s"]),
                    critical_slope_kN_s_per_m=float(sweep.attrs["critical_slope_kN_s_per_m"]),
                    sweep_ends_at_critical=int(sweep.attrs["sweep_ends_at_critical"]),
                    sweep_note=_sweep_note(sweep.attrs),
                    decay_release_state="nonlinear static equilibrium at the offset (sway held; "
                                        "heave, roll and yaw free), still vessel, from rest")
    return ds


def _sweep_note(attrs) -> str:
    """One sentence on the sweep's slopes for the report."""
    crit = float(attrs["critical_slope_kN_s_per_m"])
    if not attrs["sweep_ends_at_critical"]:
        return f"the slopes as configured; the plant's critical slope 2 M w_n is {crit:.0f} kN s/m"
    out = f"the last slope is the plant's own critical damping 2 M w_n = {crit:.0f} kN s/m"
    left = attrs["slopes_left_out_kN_s_per_m"]
    if len(left):
        out += ", in place of the configured " + ", ".join(f"{v:g}" for v in left) + " kN s/m"
    return out


__all__ = ["tugger_studies"]
