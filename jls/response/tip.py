"""The jacket tip's vertical motion relative to the wave surface under it (dynamic tip
clearance), per unit wave amplitude and as unit-Hs statistics for the response dataset.

**The tip.** The jacket's lowest point lies ``padeye_to_tip_m`` below its padeyes; its
still-water height above the water is the splash-clearance geometry of
:class:`jls.plant.rigging.Limits`,

    h_tip = hinge_height - drop_height - padeye_to_tip      (per candidate)

(the static splash clearance is ``h_tip - splash_clearance``). Its horizontal position is
one or more points of the jacket's bottom footprint, offsets (x_t, y_t) from the CoG:
configured (``assessment.tip_clearance.tip_offsets_m``), or by default the four points
below the padeyes (the lift points sit on the legs, so for vertical legs these are the
corners of the bottom footprint; a battered jacket's feet lie further out and should be
configured). Every point is evaluated and the criterion takes the worst.

**Its vertical motion** (small angles, R = Rz(psi) Rx(phi)): ``z_t = z + y_t phi`` from the
solver's absolute transfer functions of the CoG heave z and roll phi
(:func:`jls.response.solver.transfer_functions`, hinge heave, roll and yaw included
through the plant). Yaw moves the tip horizontally only; the jacket's pitch is not in the
4-DOF model, so a fore-aft offset x_t adds no vertical motion (it does change the phase of
the wave under the tip).

**The wave under it.** The incident wave (deep water, k = omega^2 / g) at the tip's
horizontal position in the vessel frame, (X, Y) = hinge lever arm from the RAO reference
point + (x_t, y_t) (the CoG hangs below the hinge). With jls's phase convention
(:data:`jls.vessel.rao.PHASE_CONVENTION`: a motion is Re{rao A exp(+i omega t)} for a wave
elevation Re{A exp(+i omega t)} at the reference point) a wave travelling in direction beta
(WAMIT: propagation relative to +x, counter-clockwise) is eta(x, y, t) = Re{A exp(i(omega t
- k (x cos beta + y sin beta)))}, so the elevation per unit amplitude at (X, Y) is

    H_eta = exp(-i k (X cos beta + Y sin beta))

(in head seas a point at the bow, X > 0, sees the crest first: exp(+i k X), as
docs/vessel.md states). The hull's diffraction and radiation are not included.

**The relative motion** is downward-positive, r = eta - z_t: the clearance left is
``h_tip - r``. Its transfer function is ``H_eta - (H_z + y_t H_phi)``. Above the RAO's
frequency range the hull and the jacket are still (the stated band of
:mod:`jls.response.coverage`) but the waves are not: the spectrum's energy there is added
to the relative motion and to the wave elevation (below the range the coverage check
leaves no energy). Statistics at Hs = 1 m as for the motions
(:mod:`jls.response.statistics`): sigma, zero-crossing period, cycles, MPM.

The wave elevation's own statistics (``wave_*``, per Tz) and its mean steepness per
metre of Hs, ``2 pi / (g T1^2)`` (T1 = 2 pi m0/m1, DNV-RP-C205 from Tz), are kept beside
them for the crest-height correction of the criterion (:mod:`jls.assessment.tip_clearance`).
Cost: one solve of the candidates' absolute transfer functions per block of
:data:`jls.response.moments.BLOCK`, like the wire tensions, linear in candidates.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.response.solver import moment_weights, spectral_moments, transfer_functions
from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, unit_spectra
from jls.sea.spectra import jonswap, t1_from_tp, tp_from_tz

#: crest-height models of the criterion (:mod:`jls.assessment.tip_clearance`)
CREST_MODELS = ("forristall_long_crested", "forristall_short_crested", "linear")
TIP_STATS = ("tip_sigma", "tip_tz_response", "tip_n_cycles", "tip_mpm")
WAVE_STATS = ("wave_sigma", "wave_n_cycles", "wave_mpm")
#: global attribute of a response dataset computed without the tip statistics
NOT_COMPUTED = "not computed (no tip-clearance criterion)"


@dataclass(frozen=True)
class TipSettings:
    """What the tip statistics depend on (:func:`jls.config.builders.tip_settings_from_config`):
    the crest-height model (one of :data:`CREST_MODELS`, used by the criterion and stated
    with the statistics), the hinge height above the water and the padeye-to-tip drop [m]
    (``rigging.limits``), and the tip points' offsets (x, y) from the CoG [m] (None: below
    each padeye). ``height_allowance_m``: the tolerance budget of the splash clearance
    (wire length and creep, hinge height, draught and trim, tip fabrication), by which
    the tip may stand lower than its nominal height; the criterion takes the tip that
    much lower, as the splash-clearance constraint keeps that budget."""

    crest: str
    hinge_height_m: float
    padeye_to_tip_m: float
    tip_offsets_m: tuple | None = None
    height_allowance_m: float = 0.0

    def __post_init__(self):
        if self.crest not in CREST_MODELS:
            raise ValueError(f"crest must be one of {', '.join(CREST_MODELS)}, got {self.crest!r}")

    def describe(self) -> str:
        where = ("the points below the padeyes" if self.tip_offsets_m is None
                 else f"{len(self.tip_offsets_m)} configured points of the bottom footprint")
        low = (f", its height taken {self.height_allowance_m:g} m below the nominal (the splash "
               "clearance's tolerance budget)" if self.height_allowance_m else "")
        return (f"jacket tip {self.padeye_to_tip_m:g} m below the padeyes, at {where}{low}; vertical "
                "motion z + y_t phi (small angles; jacket pitch not modelled) against the incident "
                "wave at the tip (deep water, k = omega^2/g, no diffraction or radiation); downward "
                "relative motion eta - z_t")


def elevation_transfer(omega, headings_deg, x, y, g):
    """Incident wave elevation per unit amplitude at the reference point, at horizontal
    positions (x, y) [m] from it: exp(-i k (x cos beta + y sin beta)), k = omega^2/g.

    omega (n_w,) rad/s; headings_deg (n_h,) WAMIT convention; x, y any (matching) shape
    (...). Returns (..., n_h, n_w) complex.
    """
    omega = np.asarray(omega, float)
    return np.exp(-1j * _along(headings_deg, x, y)[..., None] * (omega**2 / float(g)))


def _along(headings_deg, x, y):
    """The distance of (x, y) along each heading's direction of travel (..., n_h) [m]."""
    beta = np.radians(np.asarray(headings_deg, float))
    x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
    return x[..., None] * np.cos(beta) + y[..., None] * np.sin(beta)


class _Elevation:
    """:func:`elevation_transfer` at many points of which few are distinct (a grid's
    candidates share their padeyes' footprint: 10 000 candidates of a four-variable grid
    have 100): the exponential once per distinct distance along the heading (the same
    bits, element by element), gathered per block of candidates; ``[sel]`` gives the
    block's (c, n_tip, n_h, n_w)."""

    def __init__(self, omega, headings_deg, x, y, g):
        along = _along(headings_deg, x, y)
        bits, inverse = np.unique(np.ascontiguousarray(along).view(np.uint64), return_inverse=True)
        self.index = inverse.reshape(along.shape)
        self.table = np.exp(-1j * bits.view(float)[:, None] * (np.asarray(omega, float)**2 / float(g)))

    def __getitem__(self, sel):
        return self.table[self.index[sel]]


def relative_transfer(Hq, eta, tip_y):
    """Downward relative motion of the tip points against the wave surface, eta - (z + y_t phi).

    Hq: (n_c, n_t, n_h, n_w, 4) absolute response of q = [y, z, phi, psi] per unit wave
    amplitude; eta: (n_c, n_tip, n_h, n_w) wave elevation at the points; tip_y: (n_c,
    n_tip) lateral offsets from the CoG [m]. Returns (n_c, n_t, n_tip, n_h, n_w) [m/m].
    """
    z = Hq[..., 1][:, :, None]                       # (c, t, 1, h, w)
    phi = Hq[..., 2][:, :, None]
    y = np.asarray(tip_y, float)[:, None, :, None, None]
    return eta[:, None] - (z + y * phi)


def tip_points(plant: xr.Dataset, settings: TipSettings):
    """Names (n_tip,) and offsets from the CoG x, y (n_c, n_tip) [m] of the tip points."""
    n_c = plant.sizes["candidate"]
    if settings.tip_offsets_m is None:
        p = plant["padeye"].transpose("candidate", "wire", "axis")
        xy = p.sel(axis=["x", "y"]).values if "axis" in p.coords else p.values[..., :2]
        return [str(w) for w in plant["wire"].values], xy[..., 0], xy[..., 1]
    xy = np.asarray(settings.tip_offsets_m, float).reshape(-1, 2)
    names = [f"tip-{i + 1}" for i in range(xy.shape[0])]
    return names, np.broadcast_to(xy[:, 0], (n_c, xy.shape[0])), np.broadcast_to(xy[:, 1], (n_c, xy.shape[0]))


def tail_moments(omega_hi, tz, gamma=3.3, decades=3.0, points=4000):
    """m0 and m2 (n_tz,) of the unit-Hs spectra above ``omega_hi`` [rad/s]: a geometric grid
    over ``decades`` and the analytic omega^-5 tail beyond it."""
    tz = np.atleast_1d(np.asarray(tz, float))
    w = np.geomspace(float(omega_hi), float(omega_hi) * 10.0**decades, points)
    S = jonswap(w[None, :], 1.0, tp_from_tz(tz, gamma)[:, None], gamma)
    m0 = np.trapezoid(S, w, axis=-1) + S[:, -1] * w[-1] / 4.0
    m2 = np.trapezoid(S * w**2, w, axis=-1) + S[:, -1] * w[-1] ** 3 / 2.0
    return m0, m2


def wave_steepness(tz, gamma, g):
    """Mean wave steepness S1 = 2 pi Hs / (g T1^2) per metre of Hs [1/m], T1 from Tz (DNV-RP-C205)."""
    t1 = t1_from_tp(tp_from_tz(np.atleast_1d(np.asarray(tz, float)), gamma), gamma)
    return 2.0 * np.pi / (float(g) * np.asarray(t1) ** 2)


def still_water_height(settings: TipSettings, drop_height):
    """Tip height above the still water the criterion takes [m]: hinge height - drop
    height - padeye to tip - the height allowance (the splash clearance's budget)."""
    return (settings.hinge_height_m - np.asarray(drop_height, float) - settings.padeye_to_tip_m
            - settings.height_allowance_m)


def tip_response(plant: xr.Dataset, exc, hinge_xy, tz, tuggers: dict, settings: TipSettings, *,
                 gamma=3.3, exposure_h=3.0, cycles="response", g=9.81, block=None,
                 threads=None) -> xr.Dataset:
    """Unit-Hs statistics of the tip's downward relative motion (candidate, tugger, heading,
    tz, tip), the wave elevation's (tz), the still-water tip height (candidate) and the tip
    points' offsets (candidate, tip), in the layout of ``response.nc``.

    plant: the geometric plant dataset (``padeye``, ``drop_height``); exc:
    :class:`jls.response.moments.Excitation`; hinge_xy: the hinge's horizontal lever arm
    from the RAO reference point [m] (``vessel_motion.nc`` attribute ``hinge_m``); tz [s];
    tuggers: name -> slope [kN s/m]; cycles "response" or "fixed" (N = 1000).
    """
    from jls.response.moments import BLOCK, _matrices

    need = ["drop_height"] + (["padeye"] if settings.tip_offsets_m is None else [])
    missing = [v for v in need if v not in plant]
    if missing:
        raise InputError(f"the tip clearance needs the rigging geometry ({', '.join(missing)}): "
                         "the plant dataset has none (a plant given as matrices?)",
                         field="assessment.criteria.tip_air_gap_m")
    block = int(block or BLOCK)
    tz = np.atleast_1d(np.asarray(tz, float))
    c_t = [float(tuggers[n]) for n in tuggers]
    names, tx, ty = tip_points(plant, settings)
    M, K, Kb, C = _matrices(plant, slice(None))
    n_c, n_tip = M.shape[0], len(names)
    n_cycles = FIXED_CYCLES_STUDY if cycles == "fixed" else "response"
    exposure_s = exposure_h * 3600.0
    W = moment_weights(exc.omega, unit_spectra(exc.omega, tz, gamma))
    t0, t2 = tail_moments(float(exc.omega[-1]), tz, gamma)
    eta = _Elevation(exc.omega, exc.headings, hinge_xy[0] + tx, hinge_xy[1] + ty, g)
    shape = (n_c, len(c_t), n_tip, exc.headings.size, tz.size)
    out = {name: np.full(shape, np.nan) for name in TIP_STATS}
    for lo in range(0, n_c, block):
        sel = slice(lo, min(lo + block, n_c))
        Hq, _ = transfer_functions(M[sel], K[sel], Kb[sel], C[sel], exc.omega, exc.qb,
                                   exc.fairlead_sway, c_t, threads=threads)
        Hr = relative_transfer(Hq, eta[sel], ty[sel])                    # (c, t, tip, h, w)
        m0, m2 = spectral_moments(np.ascontiguousarray(Hr.real**2 + Hr.imag**2), W)
        stats = from_moments(m0 + t0, m2 + t2, exposure_s, n_cycles)
        for name in TIP_STATS:
            out[name][sel] = stats[name.removeprefix("tip_")]
    inside = W.sum(axis=0)
    wave = from_moments(inside[:tz.size] + t0, inside[tz.size:] + t2, exposure_s, n_cycles)
    dims = ("candidate", "tugger", "heading", "tz", "tip")
    ds = xr.Dataset({name: (dims, np.moveaxis(v, 2, -1)) for name, v in out.items()},
                    coords={"candidate": plant["candidate"].values, "tugger": list(tuggers),
                            "tip": names, "heading": np.asarray(exc.headings, float), "tz": tz})
    for name in WAVE_STATS:
        ds[name] = ("tz", wave[name.removeprefix("wave_")])
    ds["wave_steepness"] = ("tz", wave_steepness(tz, gamma, g))
    ds["tip_height"] = ("candidate", still_water_height(settings, plant["drop_height"].values))
    ds["tip_x"] = (("candidate", "tip"), np.asarray(tx, float))
    ds["tip_y"] = (("candidate", "tip"), np.asarray(ty, float))
    return ds


__all__ = ["CREST_MODELS", "NOT_COMPUTED", "TIP_STATS", "WAVE_STATS", "TipSettings",
           "elevation_transfer", "relative_transfer", "tip_points", "tail_moments",
           "wave_steepness", "still_water_height", "tip_response"]
