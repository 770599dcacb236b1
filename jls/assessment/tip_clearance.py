"""Dynamic tip clearance: the criterion ``tip_air_gap_m`` of ``assessment.criteria`` on the
jacket tip's vertical motion relative to the wave surface under it.

The response dataset holds, per candidate, tugger, heading, Tz and tip point, the unit-Hs
statistics of the tip's downward relative motion r = eta - z_tip (:mod:`jls.response.tip`),
the still-water tip height h_tip (candidate) and the wave elevation's statistics and
steepness per Tz. In a sea state of height Hs the clearance left is

    c(Hs) = h_tip - D(Hs),      D = three-hour MPM of r at the worst tip point,

and the criterion holds when c >= air gap, i.e. D(Hs) <= A = h_tip - air gap.

* ``linear``: D(Hs) = Hs MPM_r(Hs = 1), MPM = sigma sqrt(2 ln N) as every motion.
* ``forristall_long_crested`` (default) / ``forristall_short_crested``: the crest of the
  wave under the tip is taken second order, by the crest-height distribution of Forristall
  (2000, "Wave crest distributions: observations and second-order theory", J. Phys.
  Oceanogr. 30, 1931-1943; also DNV-RP-C205), P(crest > x) = exp(-(x / (alpha Hs))^beta),
  deep water (Ursell number 0):

      long-crested (2-D):  alpha = 0.3536 + 0.2892 S1,  beta = 2 - 2.1597 S1
      short-crested (3-D): alpha = 0.3536 + 0.2568 S1,  beta = 2 - 1.7912 S1

  with S1 = 2 pi Hs / (g T1^2) the mean steepness. The MPM crest of N waves is
  alpha Hs (ln N)^(1/beta); at S1 = 0 it is the Rayleigh crest alpha0 Hs sqrt(ln N) =
  sigma_eta sqrt(2 ln N) (alpha0 = 0.3536). The crest factor F = (alpha / alpha0)
  (ln N)^(1/beta - 1/2) >= 1 scales the linear crest MPM, and the crest's excess over it is
  added in full to the linear relative motion:

      D(Hs) = Hs MPM_r + (F(Hs) - 1) Hs MPM_eta.

  For a tip fixed in space D is Forristall's MPM crest; for a tip that follows the linear
  surface D is the second-order excess alone, which the first-order motions of vessel and
  jacket do not follow. By the triangle inequality on standard deviations,
  sigma(r + (F - 1) eta) <= sigma(r) + (F - 1) sigma(eta), this bounds from above the
  alternative of scaling the elevation by F inside the relative motion (an asymmetry
  factor on eta). The jls seas are long-crested (one heading per sea state), hence the
  long-crested default, which also gives the higher crests. N is the number of waves in
  the exposure, exposure / Tz of the elevation (or the fixed 1000), ln N taken at least 1;
  S1 is capped at S1_MAX, beyond the steepest sea states (the steepness ceiling lies near
  S1 = 0.06) so that beta stays positive.

**In the workability framework.** D rises monotonically with Hs (F does), so the criterion
holds exactly when Hs <= Hs_lim with D(Hs_lim) = A. Its unit utilisation is u = 1 / Hs_lim
(the largest over the tip points) and a cell's utilisation Hs u = Hs / Hs_lim: pass/fail,
the governing criterion (the lowest limiting Hs) and eq. 2.7's limiting Hs are exact; with
the linear model Hs u = D / A, the demand over the allowance as for every criterion. A tip
at or below the air gap at rest has u = infinity (fails at any Hs). Hs_lim is closed-form
for the linear model and found by Newton's method otherwise (D is convex and increasing:
from a point right of the root the iterates fall monotonically onto it), entry by entry
in a compiled kernel (:mod:`jls.assessment.limiting_hs_kernel`).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.names import TIP_AIR_GAP_M

#: Forristall (2000), deep water: crest model -> (alpha slope, beta slope) in S1
FORRISTALL = {"forristall_long_crested": (0.2892, 2.1597), "forristall_short_crested": (0.2568, 1.7912)}
ALPHA0 = 0.3536
S1_MAX = 0.12
NEWTON_ITERATIONS = 40
REQUIRED = ("tip_mpm", "tip_height", "wave_mpm", "wave_n_cycles", "wave_steepness")


def _stats(stats: xr.Dataset):
    missing = [v for v in REQUIRED if v not in stats]
    if missing:
        raise InputError(f"the criterion {TIP_AIR_GAP_M} needs the tip statistics "
                         f"({', '.join(missing)}) in the response dataset",
                         field=f"assessment.criteria.{TIP_AIR_GAP_M}")
    crest = stats.attrs.get("tip_crest")
    if crest not in (*FORRISTALL, "linear"):
        raise InputError(f"the response dataset does not state a known crest model (tip_crest "
                         f"{crest!r})", field="assessment.tip_clearance.crest")
    return crest


def crest_factor(hs, steepness, n_waves, crest):
    """F = MPM crest (Forristall) / MPM crest (Rayleigh) >= 1 and dF/dHs, at wave height
    ``hs`` [m], steepness S1 per m of Hs [1/m] and ``n_waves``; broadcasting. ``linear``: 1, 0."""
    hs, s, n = (np.asarray(v, float) for v in (hs, steepness, n_waves))
    if crest == "linear":
        shape = np.broadcast_shapes(hs.shape, s.shape, n.shape)
        return np.ones(shape), np.zeros(shape)
    log_n = np.log(np.maximum(n, np.e))
    return _forristall(hs, s, log_n, np.log(log_n), *FORRISTALL[crest])


def _forristall(hs, s, log_n, log_log_n, a, b):
    """F and dF/dHs of :func:`crest_factor` from ln N and ln ln N (formed once by a caller
    that evaluates them often)."""
    s1 = s * hs
    free = s1 <= S1_MAX
    s1 = np.minimum(s1, S1_MAX)
    alpha, beta = ALPHA0 + a * s1, 2.0 - b * s1
    F = alpha / ALPHA0 * log_n ** (1.0 / beta - 0.5)
    dF = np.where(free, s * F * (a / alpha + log_log_n * b / beta**2), 0.0)
    return F, dF


def _demand(hs, mpm_r, mpm_eta, F, dF):
    return hs * (mpm_r + (F - 1.0) * mpm_eta), mpm_r + (F - 1.0) * mpm_eta + hs * dF * mpm_eta


def demand(hs, mpm_r, mpm_eta, steepness, n_waves, crest):
    """D(Hs) = Hs MPM_r + (F - 1) Hs MPM_eta [m] (module docstring) and dD/dHs; broadcasting."""
    F, dF = crest_factor(hs, steepness, n_waves, crest)
    return _demand(np.asarray(hs, float), mpm_r, mpm_eta, F, dF)


def limiting_hs(allowance, mpm_r, mpm_eta, steepness, n_waves, crest):
    """Hs with D(Hs) = allowance [m], broadcasting (numpy): infinite where nothing limits
    it, 0 where the allowance is not positive, NaN where the statistics are."""
    A, mr, me, s, n = np.broadcast_arrays(*(np.asarray(v, float) for v in
                                            (allowance, mpm_r, mpm_eta, steepness, n_waves)))
    with np.errstate(divide="ignore", invalid="ignore"):
        if crest == "linear":
            H = A / mr
        else:
            cap = S1_MAX / s                                     # Hs where S1 reaches its cap
            Fc, _ = crest_factor(cap, s, n, crest)
            H = A / (mr + (Fc - 1.0) * me)                       # exact when at or beyond the cap
            inner = H < cap                                      # else the root lies below the cap,
            H = np.where(inner, np.minimum(A / mr, cap), H)     # right of it: Newton falls onto it
            H = _newton(H, inner & np.isfinite(H), A, mr, me, s, n, crest)
        H = np.where(A > 0, H, 0.0)
    return np.where(np.isnan(A) | np.isnan(mr) | np.isnan(me), np.nan, H)


def _newton(H, active, A, mr, me, s, n, crest):
    """Newton's method for D(H) = A from H at the entries ``active`` (H is returned, the
    others as given): each entry iterated on its own by the compiled kernel
    :func:`jls.assessment.limiting_hs_kernel.forristall_newton` until its step is at
    most 1e-13 of its H, exactly zero (a fixed point), or after NEWTON_ITERATIONS; ln N
    and ln ln N formed once."""
    from jls.assessment.limiting_hs_kernel import forristall_newton
    a, b = FORRISTALL[crest]
    out = np.array(H, float).reshape(-1)
    idx = np.flatnonzero(active)
    if not idx.size:
        return out.reshape(np.shape(H))
    A, mr, me, s, n = (np.ascontiguousarray(np.broadcast_to(v, np.shape(H)).reshape(-1)[idx], float)
                       for v in (A, mr, me, s, n))
    log_n = np.log(np.maximum(n, np.e))
    out[idx] = forristall_newton(out[idx], A, mr, me, s, log_n, np.log(log_n), a, b, ALPHA0, S1_MAX,
                                 1e-13, NEWTON_ITERATIONS)
    return out.reshape(np.shape(H))


def _per_tip_limit(stats: xr.Dataset, air_gap: float) -> xr.DataArray:
    crest = _stats(stats)
    allowance = stats["tip_height"] - float(air_gap)
    mr, A, me, s, n = xr.broadcast(stats["tip_mpm"], allowance, stats["wave_mpm"],
                                   stats["wave_steepness"], stats["wave_n_cycles"])
    H = limiting_hs(A.values, mr.values, me.values, s.values, n.values, crest)
    return mr.copy(data=H)


def unit_utilisation(stats: xr.Dataset, air_gap: float) -> xr.DataArray:
    """u = 1 / Hs_lim per metre of Hs at the worst tip point (candidate, tugger, heading, tz)."""
    with np.errstate(divide="ignore"):
        u = 1.0 / _per_tip_limit(stats, air_gap)
    return u.max("tip", skipna=False)


def lowest_clearance(stats: xr.Dataset, hs) -> xr.DataArray:
    """The clearance left at wave height ``hs`` (any DataArray, e.g. (leg, hs)) at the worst
    tip point, h_tip - D(Hs) [m] (candidate, tugger, heading, tz, dims of hs)."""
    crest = _stats(stats)
    hs = hs if isinstance(hs, xr.DataArray) else xr.DataArray(float(hs))
    h, s, n = xr.broadcast(hs.astype(float), stats["wave_steepness"], stats["wave_n_cycles"])
    F = h.copy(data=crest_factor(h.values, s.values, n.values, crest)[0])
    mr = stats["tip_mpm"].max("tip", skipna=False)
    return stats["tip_height"] - hs * (mr + (F - 1.0) * stats["wave_mpm"])


def criterion_statistics(stats: xr.Dataset, air_gap: float) -> xr.Dataset:
    """The voyage extremes' statistics of the criterion
    (:func:`jls.assessment.criterion_levels.criterion_statistics`), in utilisation units
    (limit 1): at each (heading, Tz) the governing tip point's ``mpm`` = u (1 / Hs_lim per
    m of Hs), and its sigma and zero-crossing period with sigma scaled like its MPM,
    sigma_r u / MPM_r: the crest correction enters as the factor it has at the limiting Hs
    of that Tz (exact there, conservative below it)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        u = 1.0 / _per_tip_limit(stats, air_gap)
        gov = {"tip": u.fillna(-np.inf).argmax("tip")}
        scale = xr.where(stats["tip_mpm"] > 0, u / stats["tip_mpm"], 0.0)
    broken = np.isinf(u.isel(gov))
    return xr.Dataset({"sigma": xr.where(broken, np.inf, (stats["tip_sigma"] * scale).isel(gov)),
                       "tz_response": stats["tip_tz_response"].isel(gov),
                       "mpm": u.isel(gov)})


__all__ = ["FORRISTALL", "ALPHA0", "S1_MAX", "crest_factor", "demand", "limiting_hs",
           "unit_utilisation", "lowest_clearance", "criterion_statistics"]
