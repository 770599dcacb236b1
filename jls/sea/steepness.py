"""Wave steepness ceiling: the largest physically realistic Hs for a wave period.

Units: Hs in m, Tz and Tp in s, g = 9.81 m/s^2.

Two rules:

* ``"study"`` (the reference study, table 6.9): Hs <= g Tz^2 / (2 pi * 15), i.e. a
  steepness 2 pi Hs / (g Tz^2) of at most 1/15 (the ratio is configurable).
* ``"dnv"`` (DNV-RP-C205, 3.5.5.6): the steepness Sp = 2 pi Hs / (g Tp^2) is at most
  1/15 for Tp <= 8 s, 1/25 for Tp >= 15 s, linear in Tp between.  Tp comes from Tz by the
  DNV-RP-C205 JONSWAP relation at the given gamma (default 3.3, Tp = 1.286 Tz), see
  :func:`jls.sea.spectra.tp_from_tz`.

Cells of a scatter table above the ceiling are *flagged* (``steep`` variable), never
dropped: whether to exclude them is the assessment's decision, and it must be reported.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from jls.errors import InputError
from jls.io import registry
from jls.sea.spectra import GAMMA_DEFAULT, _check, _scalar, tp_from_tz

__all__ = ["G", "RULES", "steepness_limit_hs", "exceeds_steepness", "flag_steep"]

G = 9.81  # m/s^2, as used by the study
BREAKING_STEEPNESS = 1.0 / 7.0  # Hs / L of the steepest possible sea
RULES = {
    "study": "Hs <= g Tz^2 / (2 pi / steepness), steepness 1/15 (reference study, table 6.9)",
    "dnv": ("DNV-RP-C205 3.5.5.6: 2 pi Hs / (g Tp^2) <= 1/15 for Tp <= 8 s, 1/25 for "
            "Tp >= 15 s, linear between; Tp from Tz by the DNV JONSWAP relation"),
}


def _rule(rule):
    if rule not in RULES:
        raise InputError(f"unknown steepness rule; expected one of {sorted(RULES)}",
                         field="rule", value=rule)
    return rule


def steepness_limit_hs(tz, rule="study", *, gamma=GAMMA_DEFAULT, steepness=1.0 / 15.0, g=G):
    """Largest Hs [m] allowed by the steepness ceiling at zero-crossing period Tz [s].

    rule="study": g Tz^2 steepness / (2 pi) with steepness = 1/15 by default
    (3.75 m at Tz = 6 s, 6.66 m at Tz = 8 s).
    rule="dnv": Sp(Tp) g Tp^2 / (2 pi) with Sp = 1/15 (Tp <= 8 s) ... 1/25 (Tp >= 15 s),
    Tp = tp_from_tz(Tz, gamma) (DNV polynomial); `steepness` is not used.
    g: gravitational acceleration [m/s^2] (the configuration's ``g_m_per_s2``).
    """
    tz = _check("tz", tz, positive=True)
    if _rule(rule) == "study":
        s = float(_check("steepness", steepness, positive=True))
        return _scalar(g * tz**2 * s / (2.0 * np.pi))
    tp = tp_from_tz(tz, gamma)
    sp = np.interp(tp, [8.0, 15.0], [1.0 / 15.0, 1.0 / 25.0])
    return _scalar(sp * g * tp**2 / (2.0 * np.pi))


def exceeds_steepness(hs, tz, rule="study", **kwargs):
    """True where the sea state (Hs [m], Tz [s], broadcast) is above the ceiling.

    Strictly above: a sea state exactly on the ceiling is allowed (1e-9 m tolerance).
    Extra keyword arguments go to :func:`steepness_limit_hs`.
    """
    hs = _check("hs", hs, nonneg=True)
    return _scalar(hs > steepness_limit_hs(tz, rule, **kwargs) + 1e-9)


def flag_steep(ds: xr.Dataset, rule="study", **kwargs) -> xr.Dataset:
    """Return a copy of a scatter Dataset with the boolean ``steep`` flag (dims hs, tz).

    The flag compares each cell's Hs centre against the ceiling at its Tz centre.
    Nothing is removed; the attrs record the rule, the number of steep cells holding
    data and the probability they carry (``steep_probability``), so a report can say
    how much of the scatter lies beyond the ceiling.
    """
    _rule(rule)
    steep = exceeds_steepness(ds["hs"].values[:, None], ds["tz"].values[None, :], rule, **kwargs)
    flag = xr.DataArray(np.asarray(steep, dtype=bool), dims=("hs", "tz"), attrs={
        **registry.attributes("sea_states", "steep"),     # the sea-state dataset's flag
        "rule": rule,
        "rule_description": RULES[rule],
        **{k: float(v) for k, v in kwargs.items()},
    })
    out = ds.assign(steep=flag)
    p = ds["probability"]
    if "direction" in p.dims:
        p = p.sum("direction")
    out.attrs["steepness_rule"] = rule
    out.attrs["steep_cells_with_data"] = int(((p > 0) & flag).sum())
    out.attrs["steep_probability"] = float(p.where(flag, 0.0).sum())
    return out


def require_not_breaking(hs, tz, *, g=G, fields=("--hs", "--tz"), file=None) -> None:
    """One sea state (Hs [m], Tz [s]) no steeper than breaking waves, Hs <= L/7 with
    L = g Tz^2 / (2 pi) (:data:`BREAKING_STEEPNESS`, the scatter tables' rule,
    :func:`jls.sea.legs.check_sea_table`): a steeper one cannot exist (Hs and Tz
    swapped, or a typing slip)."""
    length = g * float(tz) ** 2 / (2.0 * np.pi)
    if float(hs) > BREAKING_STEEPNESS * length:
        raise InputError(f"Hs {float(hs):g} m at Tz {float(tz):g} s is steeper than breaking waves "
                         f"(Hs/L = {float(hs) / length:.2f} > 1/7; L = g Tz^2/(2 pi) = {length:.1f} m; "
                         f"the steepest Hs at this Tz is {BREAKING_STEEPNESS * length:.2f} m): "
                         "are Hs and Tz swapped?", file=file, field=f"{fields[0]}, {fields[1]}",
                         value=(float(hs), float(tz)))
