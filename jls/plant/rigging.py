"""Rigging geometry: wires, their stiffness, mass lumping and the design variables.

Plant frame (section 3.3.2 and DESIGN notes): origin at the hinge, x forward, y to
port, z up. Anchors are given relative to the hinge, padeyes relative to the jacket
CoG, which hangs ``cog_depth = h_drop + z_p`` below the hinge.

Design variables (chapter 5, table 5.1) are a parametrisation of a four-wire layout of
the reconstructed kind: two crossed pairs fore-aft, port/starboard mirror-symmetric.

* ``top_spread_y``    port-starboard distance between the anchors, mean of the pairs;
* ``bottom_spread_y`` port-starboard distance between the padeyes, mean of the pairs;
* ``bottom_spread_x`` fore-aft distance between the padeyes of one side;
* ``drop_height``     vertical drop from the anchors to the padeyes.

A candidate moves the anchors and padeyes of the baseline layout: transverse spreads
shift every anchor (padeye) outboard by half the change, so the difference between
the pairs is kept; the fore-aft padeye spread scales the padeye x about their mean;
the drop height lowers the jacket. Anchor x positions belong to the lift beams and
stay fixed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

DESIGN_VARIABLES = ("top_spread_y", "bottom_spread_y", "bottom_spread_x", "drop_height")


def series_stiffness(segments):
    """Axial stiffness [kN/m] of segments in series, eq. 3.2.

    segments: iterable of (length [m], EA [kN]).
    """
    compliance = sum(length / ea for length, ea in segments)
    return 1.0 / compliance


def lumped_inertial_mass(m_jacket, wire_length, block_mass=0.0, block_distance=0.0,
                         wire_mass_per_length=0.0):
    """Kinetic-energy equivalent mass at the CoG, eq. 3.3.

    A point mass at distance s below the anchor of a wire of length L moves with the
    fraction s/L of the jacket's pendular velocity; a uniform wire adds mu L / 3.
    ``wire_length``: (..., 4) [m]; block quantities per wire. Returns (...) [t].
    """
    wire_length = np.asarray(wire_length, float)
    ratio = np.asarray(block_distance, float) / wire_length
    extra = np.asarray(block_mass, float) * ratio**2 + np.asarray(wire_mass_per_length, float) * wire_length / 3.0
    return m_jacket + extra.sum(axis=-1)


@dataclass(frozen=True)
class Layout:
    """Anchors (..., 4, 3), padeyes (..., 4, 3) and CoG depth (...) of one or many
    candidate geometries."""

    anchors: np.ndarray
    padeyes: np.ndarray
    cog_depth: np.ndarray

    def lead_angles(self):
        """Side (athwartships) and fore-aft lead angles of each wire from the
        vertical [rad], (..., 4) each."""
        d = self.anchors - self.padeyes
        d = d.copy()
        d[..., 2] += self.cog_depth[..., None]
        return np.arctan2(np.abs(d[..., 1]), d[..., 2]), np.arctan2(np.abs(d[..., 0]), d[..., 2])

    def drop_height(self):
        """Mean vertical drop from anchors to padeyes [m]."""
        return (self.anchors[..., 2] - self.padeyes[..., 2]).mean(-1) + self.cog_depth


def design_variables(layout: Layout) -> dict[str, np.ndarray]:
    """The four chapter-5 design variables of a layout (see module docstring)."""
    a, p = layout.anchors, layout.padeyes
    top = 2.0 * np.abs(a[..., 1]).mean(-1)
    bottom = 2.0 * np.abs(p[..., 1]).mean(-1)
    bottom_x = p[..., 0].max(-1) - p[..., 0].min(-1)
    return {"top_spread_y": top, "bottom_spread_y": bottom, "bottom_spread_x": bottom_x,
            "drop_height": layout.drop_height()}


def apply_design(baseline: Layout, z_p: float, **values) -> Layout:
    """Candidate layouts from a baseline and design-variable values.

    Each value may be an array; all broadcast together to the candidate shape. Missing
    variables keep the baseline value.
    """
    base = design_variables(baseline)
    shape = np.broadcast_shapes(*(np.shape(v) for v in values.values())) if values else ()
    get = {name: np.broadcast_to(np.asarray(values.get(name, base[name]), float), shape)
           for name in DESIGN_VARIABLES}
    unknown = set(values) - set(DESIGN_VARIABLES)
    if unknown:
        raise KeyError(f"unknown design variable(s): {sorted(unknown)}")
    anchors = np.broadcast_to(baseline.anchors, shape + (4, 3)).copy()
    padeyes = np.broadcast_to(baseline.padeyes, shape + (4, 3)).copy()
    sa, sp = np.sign(anchors[..., 1]), np.sign(padeyes[..., 1])
    anchors[..., 1] += sa * 0.5 * (get["top_spread_y"] - base["top_spread_y"])[..., None]
    padeyes[..., 1] += sp * 0.5 * (get["bottom_spread_y"] - base["bottom_spread_y"])[..., None]
    xm = padeyes[..., 0].mean(-1, keepdims=True)
    padeyes[..., 0] = xm + (padeyes[..., 0] - xm) * (get["bottom_spread_x"] / base["bottom_spread_x"])[..., None]
    cog_depth = baseline.cog_depth + (get["drop_height"] - base["drop_height"])
    return Layout(anchors=anchors, padeyes=padeyes, cog_depth=np.asarray(cog_depth, float))


def _total(components) -> float:
    return float(sum(v for _, v in components))


@dataclass(frozen=True)
class Budget:
    """The tolerance budget of the safety constraints: named components (name, value)
    that add up, so a constraint holds only with its budget to spare. Splash clearance
    [m], lead angles [deg] (side and fore-aft alike), static tension [kN] plus a percent
    of the wire's static tension. Built from ``rigging.limits.tolerance_budget``
    (:func:`jls.config.builders.rigging_from_config`); none by default here."""

    splash_clearance_m: tuple = ()
    lead_angle_deg: tuple = ()
    tension_kN: tuple = ()
    tension_percent: tuple = ()

    @property
    def splash(self) -> float:
        return _total(self.splash_clearance_m)

    @property
    def lead_angle(self) -> float:
        return _total(self.lead_angle_deg)

    def tension(self, static_kN):
        """Budget on the tension margin [kN] for the largest static tension ``static_kN``."""
        return _total(self.tension_kN) + _total(self.tension_percent) / 100.0 * np.asarray(static_kN, float)

    def describe(self, what: str) -> str:
        """The components of one budget in words ("wire length and creep 0.30 m, ...")."""
        comps, unit = {"splash": (self.splash_clearance_m, "m"), "lead": (self.lead_angle_deg, "deg"),
                       "tension": (self.tension_kN + self.tension_percent, None)}[what]
        if what == "tension":
            return ", ".join([f"{k.replace('_', ' ')} {v:g} kN" for k, v in self.tension_kN]
                             + [f"{k.replace('_', ' ')} {v:g} %" for k, v in self.tension_percent]) or "none"
        return ", ".join(f"{k.replace('_', ' ')} {v:.2f} {unit}" for k, v in comps) or "none"


@dataclass(frozen=True)
class Limits:
    """Rigging and clearance constraints of table 5.1 (angles in degrees), an optional
    static wire-tension limit, the tolerance budget each must keep (:class:`Budget`) and
    the numerical resolution within which a margin sits "at the limit" of its budget."""

    side_lead_max_deg: float = 10.0
    fore_aft_lead_max_deg: float = 50.0
    hinge_height_m: float = 119.46
    padeye_to_tip_m: float = 48.0
    splash_clearance_m: float = 5.0
    max_tension_kN: float | None = None
    at_limit_tolerance_m: float = 0.01
    at_limit_tolerance_deg: float = 0.01
    at_limit_tolerance_kN: float = 10.0
    budget: Budget = Budget()

    def max_drop(self) -> float:
        """Largest drop height that keeps the jacket tip clear of the water [m]."""
        return self.hinge_height_m - self.padeye_to_tip_m - self.splash_clearance_m

    def max_drop_in_budget(self) -> float:
        """Largest drop height that keeps the splash-clearance budget as well [m]."""
        return self.max_drop() - self.budget.splash

    def check(self, layout: Layout) -> dict[str, np.ndarray]:
        """Margins (positive = satisfied) of every constraint, (...) each."""
        side, fore_aft = layout.lead_angles()
        return {
            "side_lead_margin_deg": self.side_lead_max_deg - np.degrees(side).max(-1),
            "fore_aft_lead_margin_deg": self.fore_aft_lead_max_deg - np.degrees(fore_aft).max(-1),
            "splash_clearance_margin_m": self.max_drop() - layout.drop_height(),
        }
