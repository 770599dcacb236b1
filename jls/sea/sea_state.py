"""A sea state is one or more wave systems, each with its spectrum shape, Hs, period,
mean direction and directional spreading.

Directions are degrees true, the direction the waves come FROM. Every system is

    S_j(omega, theta) = S_j(omega) D_j(theta - from_j)        [m^2 s/rad per rad]

and the sea state is their sum; the response is the sum over the systems, each met over
its directions at the relative headings ``(course - theta + 180) mod 360``
(:mod:`jls.response.sea_state`).

**Shapes** (``S_j(omega)`` carries exactly Hs_j^2/16):

* ``jonswap`` with its gamma (:func:`jls.sea.spectra.jonswap`); ``pm``, Pierson-Moskowitz,
  is the JONSWAP of gamma 1;
* ``torsethaugen``: ONE of the two systems a Torsethaugen sea state (Hs, Tp) splits into
  (DNV-RP-C205 3.5.7; :func:`jls.sea.two_peak.torsethaugen_parameters`), each of the
  x^-4 Torsethaugen shape with its own Hs_j, Tp_j and gamma_j: :func:`torsethaugen_systems`
  gives both, so that each can have its own direction and spreading;
* ``measured``: a 1-D spectrum S(omega) given on its frequencies (linear between them,
  zero outside).

**Periods**: a system is given by Tp or by Tz, Tm01 or Te, turned into Tp by its shape's
own relation (:func:`jls.sea.periods.tp_from_period`, the one statement of it).

**Spreading** (``D`` per radian, integrating to 1 over the circle):

* ``cos2s:S`` (Longuet-Higgins 1963; DNV-RP-C205 3.5.8.7)::

      D(theta) = Gamma(s + 1) / (2 sqrt(pi) Gamma(s + 1/2)) cos^2s(theta / 2),  |theta| <= pi
      circular spread sigma = sqrt(2 (1 - r1)),  r1 = E[cos theta] = s / (s + 1)

* ``cosn:N`` (DNV-RP-C205 3.5.8.4)::

      D(theta) = Gamma(n/2 + 1) / (sqrt(pi) Gamma(n/2 + 1/2)) cos^n(theta),  |theta| <= pi/2
      r1 = C(n) / C(n + 1) with C(n) the constant above

* ``long-crested``: all of the system's energy from its mean direction (an explicit choice,
  never a fallback).

On a direction grid a spread system is sampled at ``DIRECTIONS`` (36) directions centred on
its mean direction, 10 deg apart, and the weights normalised to sum to 1 on the grid.
DNV-RP-C205 (3.5.8.4, 3.5.8.7) gives typical values n = 2-4 (s = 4-9) for wind sea and
n >= 6 (s > 13) for swell; the defaults of a configuration are its ``sea.spreading``
(the schema), not this module's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from jls.errors import InputError
from jls.sea import periods, spectra, two_peak

__all__ = ["SHAPES", "KINDS", "SPREADINGS", "DIRECTIONS", "Spreading", "WaveSystem", "SeaState",
           "parse_spreading", "wave_system", "torsethaugen_systems", "single_sea_state", "measured_systems"]

SHAPES = ("jonswap", "pm", "torsethaugen", "measured")
KINDS = ("wind", "swell", "measured")
SPREADINGS = ("cos2s", "cosn", "long-crested")
#: Directions of a spread system on its grid (36: 10 deg apart).
DIRECTIONS = 36
D2R = math.pi / 180.0


def _cos2s_constant(s):
    return math.exp(math.lgamma(s + 1.0) - math.lgamma(s + 0.5)) / (2.0 * math.sqrt(math.pi))


def _cosn_constant(n):
    return math.exp(math.lgamma(n / 2.0 + 1.0) - math.lgamma(n / 2.0 + 0.5)) / math.sqrt(math.pi)


@dataclass(frozen=True)
class Spreading:
    """Directional spreading of one wave system: ``kind`` cos2s (exponent s), cosn
    (exponent n) or long-crested (no value)."""

    kind: str
    value: float | None = None

    def __post_init__(self):
        if self.kind not in SPREADINGS:
            raise InputError(f"spreading must be one of {', '.join(SPREADINGS)}", field="spreading",
                             value=self.kind)
        if self.kind == "long-crested":
            if self.value is not None:
                raise InputError("a long-crested sea has no spreading exponent", field="spreading",
                                 value=self.value)
        elif self.value is None or not (math.isfinite(self.value) and 0 < self.value <= 1000):
            raise InputError(f"the {self.kind} spreading exponent must be a number in (0, 1000]",
                             field="spreading", value=self.value)

    def __str__(self):
        return self.kind if self.value is None else f"{self.kind}:{self.value:g}"

    @property
    def long_crested(self) -> bool:
        return self.kind == "long-crested"

    def density(self, theta_deg):
        """D(theta) per radian at ``theta_deg`` [deg] from the mean direction (any shape)."""
        t = np.mod(np.asarray(theta_deg, float) + 180.0, 360.0) - 180.0
        if self.kind == "cos2s":
            return _cos2s_constant(self.value) * np.abs(np.cos(0.5 * D2R * t)) ** (2 * self.value)
        if self.kind == "cosn":
            c = np.cos(D2R * t)
            return np.where(np.abs(t) <= 90.0, _cosn_constant(self.value) * np.abs(c) ** self.value, 0.0)
        raise InputError("a long-crested sea has no density: its energy is at one direction",
                         field="spreading", value=self.kind)

    def r1(self) -> float:
        """E[cos theta] of the distribution (1 long-crested)."""
        if self.kind == "cos2s":
            return self.value / (self.value + 1.0)
        if self.kind == "cosn":
            return _cosn_constant(self.value) / _cosn_constant(self.value + 1.0)
        return 1.0

    def spread_deg(self) -> float:
        """Circular spread sigma = sqrt(2 (1 - r1)) [deg] (0 long-crested)."""
        return math.sqrt(2.0 * (1.0 - self.r1())) / D2R

    def on_grid(self, n=DIRECTIONS):
        """(offsets [deg] from the mean direction, weights summing to 1): one direction of
        weight 1 long-crested, else ``n`` directions 360/n apart centred on the mean."""
        if self.long_crested:
            return np.zeros(1), np.ones(1)
        offsets = (np.arange(n) - n // 2) * (360.0 / n)
        w = self.density(offsets)
        keep = w > 0
        return offsets[keep], w[keep] / w[keep].sum()


def parse_spreading(text, field="spreading") -> Spreading:
    """``cos2s:S``, ``cosn:N`` or ``long-crested`` (also ``long``) -> :class:`Spreading`."""
    if isinstance(text, Spreading):
        return text
    s = str(text).strip().lower()
    if s in ("long-crested", "long_crested", "long", "longcrested"):
        return Spreading("long-crested")
    kind, _, value = s.partition(":")
    if kind not in ("cos2s", "cosn") or not value:
        raise InputError("spreading must be cos2s:S, cosn:N or long-crested", field=field, value=text)
    try:
        v = float(value)
    except ValueError:
        raise InputError("the spreading exponent must be a number", field=field, value=text) from None
    try:
        return Spreading(kind, v)
    except InputError as exc:
        raise InputError(exc.message, field=field, value=text) from None


@dataclass(frozen=True)
class WaveSystem:
    """One wave system: ``shape`` (:data:`SHAPES`), ``hs`` [m], ``tp`` [s], ``gamma``
    (the JONSWAP's, or the Torsethaugen system's own), ``from_deg`` [deg true],
    ``spreading`` and ``kind`` (wind or swell: what it is, for the report and defaults).
    A measured system carries its spectrum ``omega`` [rad/s] and ``density`` [m^2 s/rad]."""

    shape: str
    hs: float
    tp: float
    from_deg: float
    spreading: Spreading
    kind: str = "wind"
    gamma: float = 1.0
    omega: np.ndarray | None = field(default=None, compare=False, repr=False)
    density: np.ndarray | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        if self.shape not in SHAPES:
            raise InputError(f"spectrum must be one of {', '.join(SHAPES)}", field="spectrum",
                             value=self.shape)
        if self.kind not in KINDS:
            raise InputError(f"a wave system is one of {', '.join(KINDS)}", field="kind", value=self.kind)
        for name, v, lo in (("hs", self.hs, 0.0), ("tp", self.tp, 1e-9), ("gamma", self.gamma, 1.0)):
            if not (math.isfinite(v) and v >= lo):
                raise InputError(f"{name} must be a finite number >= {lo:g}", field=name, value=v)
        if not (math.isfinite(self.from_deg) and 0 <= self.from_deg <= 360):
            raise InputError("a direction is in degrees, 0-360 (from, true)", field="dir_from",
                             value=self.from_deg)
        if not isinstance(self.spreading, Spreading):
            raise InputError("spreading must be a Spreading", field="spreading", value=self.spreading)
        if self.shape == "measured" and (self.omega is None or self.density is None):
            raise InputError("a measured system needs its spectrum", field="spectrum", value="measured")

    def spectrum(self, omega):
        """S_j(omega) [m^2 s/rad] (any shape of omega)."""
        w = np.asarray(omega, float)
        if self.hs == 0 and self.shape != "measured":
            return np.zeros_like(w)
        if self.shape == "jonswap":
            return np.asarray(spectra.jonswap(w, self.hs, self.tp, self.gamma), float)
        if self.shape == "pm":
            return np.asarray(spectra.jonswap(w, self.hs, self.tp, 1.0), float)
        if self.shape == "torsethaugen":
            return np.asarray(two_peak._system(w, np.float64(self.hs), np.float64(self.tp),
                                               np.float64(self.gamma), "exact"), float)
        return np.interp(w, self.omega, self.density, left=0.0, right=0.0)

    def m0(self) -> float:
        """Variance [m^2]: Hs^2/16 (a measured system's, by the trapezoid rule)."""
        if self.shape == "measured":
            return float(np.trapezoid(self.density, self.omega))
        return self.hs**2 / 16.0

    def directions(self, n=DIRECTIONS):
        """(directions from [deg true, 0-360), weights summing to 1) of the system."""
        off, w = self.spreading.on_grid(n)
        return np.mod(self.from_deg + off, 360.0), w

    def describe(self) -> str:
        g = f", gamma {self.gamma:g}" if self.shape in ("jonswap", "torsethaugen") else ""
        return (f"{self.kind} {self.shape} Hs {self.hs:g} m, Tp {self.tp:g} s{g}, "
                f"from {self.from_deg:g} deg, {self.spreading}")


def wave_system(shape, hs, period, value, *, from_deg, spreading, gamma=None, kind="wind") -> WaveSystem:
    """A JONSWAP or PM system given by ``period`` (tp, tz, tm01 or te) = ``value`` [s], the
    period turned into Tp by the shape's relation (:func:`jls.sea.periods.tp_from_period`)."""
    if shape not in ("jonswap", "pm"):
        raise InputError("wave_system builds jonswap or pm systems; a Torsethaugen sea state is "
                         "split by torsethaugen_systems", field="spectrum", value=shape)
    g = 1.0 if shape == "pm" else gamma
    if g is None:
        raise InputError("a JONSWAP system needs its gamma", field="gamma")
    tp = periods.tp_from_period("jonswap", period, value, gamma=float(g))
    return WaveSystem(shape, float(hs), float(tp), float(from_deg), parse_spreading(spreading),
                      kind, float(g))


def torsethaugen_systems(hs, period, value, *, from_deg, spreading: dict) -> list[WaveSystem]:
    """The two systems of a Torsethaugen sea state (Hs, ``period`` = ``value``), both from
    ``from_deg``: the primary (peak at Tp) is the swell when the sea is swell-dominated
    (Tp > Tf = 6.6 Hs^(1/3)), else the wind sea; ``spreading``: {"wind": .., "swell": ..}.
    A secondary system of zero height is left out."""
    tp = periods.tp_from_period("torsethaugen", period, value, hs=float(hs))
    p = two_peak.torsethaugen_parameters(float(hs), float(tp))
    wind = bool(p["wind_dominated"])
    out = []
    for j, kind in (("1", "wind" if wind else "swell"), ("2", "swell" if wind else "wind")):
        h = float(p["hs" + j])
        if h > 0 and math.isfinite(float(p["tp" + j])):
            out.append(WaveSystem("torsethaugen", h, float(p["tp" + j]), float(from_deg),
                                  parse_spreading(spreading[kind], f"spreading.{kind}"), kind,
                                  float(p["gamma" + j])))
    return out


@dataclass(frozen=True)
class SeaState:
    """A sea state: its wave systems (at least one)."""

    systems: tuple

    def __post_init__(self):
        if not self.systems:
            raise InputError("a sea state needs at least one wave system", field="systems")

    @property
    def hs(self) -> float:
        """Total Hs = 4 sqrt(sum of the systems' variances) [m]."""
        return 4.0 * math.sqrt(sum(s.m0() for s in self.systems))

    def spectrum(self, omega):
        """S(omega) [m^2 s/rad], the sum over the systems."""
        return sum(s.spectrum(omega) for s in self.systems)

    def describe(self) -> str:
        return "; ".join(s.describe() for s in self.systems)


def single_sea_state(systems) -> SeaState:
    """A :class:`SeaState` from a list of systems (or one system)."""
    if isinstance(systems, WaveSystem):
        systems = [systems]
    return SeaState(tuple(systems))


def measured_systems(freq_hz, density, dirs=None, *, from_deg=None, spreading=None) -> list[WaveSystem]:
    """The systems of one measured spectrum: a directional E(f, dir) [m^2/(Hz deg)] on
    ``dirs`` [deg, from] is one long-crested measured system per direction bin (its energy
    E(f, dir) times the bin's width, so the sea is integrated as measured, no fit); a 1-D
    E(f) [m^2/Hz] is one system from ``from_deg`` spread by ``spreading``. Densities are
    turned into S(omega) [m^2 s/rad]; frequencies [Hz] into omega [rad/s]."""
    from jls.sea.directional import direction_widths
    f = np.asarray(freq_hz, float)
    E = np.asarray(density, float)
    omega = 2 * np.pi * f
    if dirs is None:
        if from_deg is None or spreading is None:
            raise InputError("a 1-D spectrum needs its direction and spreading", field="spectrum")
        return [_measured(omega, E / (2 * np.pi), float(from_deg) % 360.0, parse_spreading(spreading))]
    d = np.asarray(dirs, float)
    width = direction_widths(d)
    out = []
    for j in range(d.size):
        S = E[:, j] * width[j] / (2 * np.pi)
        if np.any(S > 0):
            out.append(_measured(omega, S, float(d[j]) % 360.0, Spreading("long-crested")))
    if not out:
        raise InputError("the spectrum has no energy", field="spectrum")
    return out


def _measured(omega, S, from_deg, spreading):
    """A measured system with its Hs = 4 sqrt(m0) and Tp = 2 pi / omega at the peak."""
    hs = 4.0 * math.sqrt(max(float(np.trapezoid(S, omega)), 0.0))
    tp = 2 * math.pi / float(omega[int(np.argmax(S))]) if np.any(S > 0) else 1.0
    return WaveSystem("measured", hs, tp, from_deg, spreading, "measured", omega=omega, density=S)
