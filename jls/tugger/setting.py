"""Damping tuggers: settings, setpoint law and loads in the frequency domain (chapter 6).

A damping tugger is a pair of opposing lines from fairleads on the vessel to the jacket
at CoG height (section 6.3.2: fairleads 82.5 m below the hinge and 37.5 m either side,
jacket half-width 22.5 m, free length 15 m). Each line follows the maximum-force setpoint
(eq. 6.2)

    T = sat[T_min, T_max](T0 + c/n u),    T0 = (T_min + T_max) / 2,

with u the pay-out velocity of that line (eq. 6.3), so that the net force of the pair is
c u while neither line is at a limit. In the frequency domain the pair is a linear damper
of slope c between the fairlead sway and the jacket sway (:mod:`jls.response.solver`); this
module turns that closed-loop response into the loads on the winch, and flags where the
linear picture breaks down because the winch would saturate.

Winch settings (table 6.3): Low 300 kN s/m on 1000 kN, Reference 1000 / 1000, High
2000 / 2000; floor T_min = 20 kN; two lines. A setting given without a capacity gets the
1000 kN winch the study holds fixed in its slope sweep (section 6.5.1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.io.schema import default

# The schema's defaults of a setting (jls/schemas/config.schema.yaml, tuggers.items).
T_MIN_KN = float(default("tuggers.items.min_force_kN"))
DEFAULT_CAPACITY_KN = float(default("tuggers.items.max_force_kN"))
DEFAULT_LAG_S = float(default("tuggers.items.lag_s"))
JACKET_HALF_WIDTH_M = float(default("tuggers.items.attachment_half_width_m"))
N_LINES = 2          # a pair of opposing lines: the model's geometry, not a setting
#: Table 6.3 of the study: name -> (slope kN s/m, capacity kN).
STUDY_SETTINGS = {"low": (300.0, 1000.0), "reference": (1000.0, 1000.0), "high": (2000.0, 2000.0)}


@dataclass(frozen=True)
class Tugger:
    """One tugger setting: slope c of the pair [kN s/m], per-line force limits [kN],
    first-order actuator lag [s] (0: ideal force source), number of lines, jacket
    half-width at the attachment [m]."""

    name: str
    c: float
    max_force: float = DEFAULT_CAPACITY_KN
    min_force: float = T_MIN_KN
    lag: float = DEFAULT_LAG_S
    n_lines: int = N_LINES
    half_width: float = JACKET_HALF_WIDTH_M

    @property
    def active(self) -> bool:
        return self.c > 0

    @property
    def pretension(self) -> float:
        """T0, midway between the floor and the capacity (section 6.3.2)."""
        return 0.5 * (self.max_force + self.min_force)

    @property
    def net_force_limit(self) -> float:
        """Largest net force of the pair available for damping: T_max - T_min [kN]."""
        return self.max_force - self.min_force

    @property
    def saturation_velocity(self) -> float:
        """Pay-out speed at which a line reaches a limit, (T_max - T0) n / c [m/s]."""
        return np.inf if self.c <= 0 else (self.max_force - self.pretension) * self.n_lines / self.c


def tension(tugger: Tugger, u):
    """Per-line tension [kN] of the setpoint law (eq. 6.2) at pay-out velocity u [m/s]."""
    return np.clip(tugger.pretension + tugger.c / tugger.n_lines * np.asarray(u, float),
                   tugger.min_force, tugger.max_force)


def settings_table(tuggers) -> xr.Dataset:
    """Table 6.3 for the given settings: slope, capacity, floor, pretension, saturation
    speed and net force limit, per tugger."""
    tuggers = list(tuggers)
    ds = xr.Dataset(
        {"c": ("tugger", [t.c for t in tuggers], {"units": "kN s/m", "long_name": "damping slope of the pair"}),
         "max_force": ("tugger", [t.max_force for t in tuggers], {"units": "kN", "long_name": "winch capacity per line"}),
         "min_force": ("tugger", [t.min_force for t in tuggers], {"units": "kN", "long_name": "no-slack floor per line"}),
         "pretension": ("tugger", [t.pretension for t in tuggers], {"units": "kN", "long_name": "pretension per line"}),
         "saturation_velocity": ("tugger", [t.saturation_velocity for t in tuggers],
                                 {"units": "m/s", "long_name": "pay-out speed at which a line reaches a limit"}),
         "net_force_limit": ("tugger", [t.net_force_limit for t in tuggers],
                             {"units": "kN", "long_name": "largest net force of the pair"})},
        coords={"tugger": [t.name for t in tuggers]})
    return ds


__all__ = ["Tugger", "tension", "settings_table", "STUDY_SETTINGS", "T_MIN_KN"]
