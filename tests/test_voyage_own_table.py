"""The scatter-table voyage extremes of legs given by their own seas: such a leg's binned
JONSWAP cells are replaced by its records (each hour or table cell at each heading) with
their stored probability, own sigma and own up-crossing period
(jls.assessment.voyage_own_seas.table_own_cells)."""

import numpy as np
import pytest
import xarray as xr
from scipy.optimize import brentq
from test_voyage_own_seas import LIMIT, statistics

from jls.assessment.voyage import exceedance_at_levels, long_term_extreme

HEADINGS = [60.0, 90.0]
HS = np.array([1.0, 2.0, 3.5])


def table():
    """Two legs on the statistics' Tz grid: (cell_probability, hs, duration)."""
    sigma, _, _ = statistics()
    tz = sigma["tz"].values[[2, 4, 6]]
    rng = np.random.default_rng(3)
    p = rng.uniform(0, 1, (2, 2, HS.size, tz.size))
    p[1, 1] = 0.0                                             # the second leg meets 60 deg only
    p /= p.sum((1, 2, 3), keepdims=True)
    cell = xr.DataArray(p, dims=("leg", "heading", "hs", "tz"),
                        coords={"leg": ["open", "table"], "heading": HEADINGS, "hs": HS, "tz": tz})
    dur = xr.DataArray([40.0, 25.0], dims="leg", coords={"leg": ["open", "table"]})
    return cell, xr.DataArray(HS, dims="hs", coords={"hs": HS}), dur


def binned_records(scale=1.0, period=1.0):
    """The "table" leg's own records as its binned JONSWAP cells themselves (a JONSWAP of
    gamma 3.3 declared as the leg's own sea): one record per Hs-Tz cell, its probability at
    each heading the cell's, sigma Hs sigma(Tz) x ``scale``, the period x ``period``."""
    sigma, tzr, _ = statistics()
    cell, hs, _ = table()
    c = cell.sel(leg="table")
    rec = [(i, j) for i in range(HS.size) for j in range(c.sizes["tz"])]
    prob = np.array([[float(c.isel(hs=i, tz=j).sel(heading=h)) for h in HEADINGS] for i, j in rec])
    at = {v: xr.concat([a.sel(tz=float(c["tz"][j])) * (HS[i] if v == "sigma" else 1.0) for i, j in rec],
                       dim="time").assign_coords(time=np.arange(len(rec)))
          for v, a in (("sigma", sigma), ("tz_response", tzr))}
    own = xr.Dataset({"sigma": at["sigma"] * scale, "tz_response": at["tz_response"] * period,
                      "probability": (("time", "heading"), prob),
                      "hs_cell": ("time", [i for i, _ in rec]), "tz_cell": ("time", [j for _, j in rec])},
                     coords={"heading": HEADINGS})
    return own.expand_dims(leg=["table"])


def solve(own=None, q=(0.5, 0.9)):
    sigma, tzr, _ = statistics()
    cell, hs, dur = table()
    return long_term_extreme(sigma, tzr, cell, hs, dur, LIMIT, non_exceedance=list(q), own=own)


def test_an_own_jonswap_leg_is_the_binned_path():
    """The consistency limit: own records that are the binned gamma-3.3 JONSWAP cells give
    the binned path's voyage, its exceedance curve and its crossing shares."""
    a, b = solve(), solve(binned_records())
    for v in ("expected_exceedances", "voyage_level", "crossing_share", "crossing_share_leg"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=1e-6, atol=1e-12)
    sigma, tzr, _ = statistics()
    cell, hs, dur = table()
    levels = [0.5, 1.0, 2.0]
    np.testing.assert_allclose(exceedance_at_levels(sigma, tzr, cell, hs, dur, LIMIT, levels, own=binned_records()),
                               exceedance_at_levels(sigma, tzr, cell, hs, dur, LIMIT, levels), rtol=1e-9)


def test_an_own_table_legs_voyage_extreme_is_the_hand_computation():
    """Lambda(x) = sum over the open leg's cells p D 3600 / Tz_r exp(-x^2 / 2 (Hs sigma)^2)
    + sum over the table leg's records and headings p D 3600 / Tz_own exp(-x^2 / 2 sigma_own^2),
    the voyage level the root of Lambda = -ln q; the curve 1 - exp(-Lambda(x limit))."""
    sigma, tzr, _ = statistics()
    cell, hs, dur = table()
    rng = np.random.default_rng(7)
    own = binned_records()
    own["sigma"] = own["sigma"] * xr.DataArray(rng.uniform(0.5, 3.0, own.sizes["time"]), dims="time")
    own["tz_response"] = own["tz_response"] * xr.DataArray(rng.uniform(0.8, 1.3, own.sizes["time"]), dims="time")
    q = [0.5, 0.9]
    got = solve(own, q)
    curve = exceedance_at_levels(sigma, tzr, cell, hs, dur, LIMIT, [0.7, 1.0], own=own)
    for c in sigma["candidate"].values:
        for k in LIMIT["criterion"].values:
            s_o, t_o = (own[v].sel(leg="table", candidate=c, criterion=k).transpose("time", "heading").values
                        for v in ("sigma", "tz_response"))
            p_o = own["probability"].sel(leg="table").transpose("time", "heading").values
            terms = [(p_o * 25.0 * 3600.0 / t_o).ravel(), s_o.ravel()]
            po = cell.sel(leg="open")
            for h in HEADINGS:
                for i, hh in enumerate(HS):
                    for tz in po["tz"].values:
                        terms[0] = np.append(terms[0], float(po.sel(heading=h, hs=hh, tz=tz)) * 40.0 * 3600.0
                                             / float(tzr.sel(candidate=c, criterion=k, heading=h, tz=tz)))
                        terms[1] = np.append(terms[1], hh * float(sigma.sel(candidate=c, criterion=k, heading=h,
                                                                               tz=tz)))
            w, s = terms

            def lam(x):
                return float(np.sum(np.where(w > 0, w * np.exp(-x * x / (2 * s * s)), 0.0)))
            for qq in q:
                x = brentq(lambda x: lam(x) + np.log(qq), 1e-9, 100.0, xtol=1e-14)
                assert float(got["voyage_level"].sel(candidate=c, criterion=k, non_exceedance=qq)) \
                    == pytest.approx(x, rel=1e-8)
            lim = float(LIMIT.sel(criterion=k))
            assert float(got["expected_exceedances"].sel(candidate=c, criterion=k)) == pytest.approx(lam(lim), rel=1e-9)
            for lv in (0.7, 1.0):
                assert float(curve.sel(candidate=c, criterion=k, level=lv)) == pytest.approx(
                    -np.expm1(-lam(lv * lim)), rel=1e-9)
    # every record's share credited to its table cell: the leg's shares sum to its own share
    sh = got["crossing_share"].sum(("heading", "hs", "tz"))
    np.testing.assert_allclose(sh.values, got["crossing_share_leg"].values, rtol=1e-5, atol=1e-7)
    np.testing.assert_allclose(got["crossing_share_leg"].sum("leg").values, 1.0, rtol=1e-6)


def test_a_larger_own_sea_raises_the_voyage_level_and_a_smaller_lowers_it():
    base = solve(binned_records())["voyage_level"]
    up = solve(binned_records(scale=1.3))["voyage_level"]
    down = solve(binned_records(scale=0.7))["voyage_level"]
    assert (up > base).all() and (down < base).all()
    # a longer up-crossing period alone (fewer cycles) lowers it a little
    slow = solve(binned_records(period=1.5))["voyage_level"]
    assert (slow < base).all() and (slow > down).all()


def test_a_leg_without_own_records_keeps_its_binned_cells():
    own = binned_records()
    own["probability"] = own["probability"] * 0.0
    np.testing.assert_allclose(solve(own)["voyage_level"].values, solve()["voyage_level"].values, rtol=1e-12)


def test_page_ones_sentence_gives_the_datasets_voyage_level_ratio():
    """Page 1 gives the recommendation's voyage-level ratio of the relative sway (own seas
    over the binned JONSWAP, voyage.nc own_sea_level_ratio), above or below 1 as it is,
    and what is not on the own seas where the dataset says so."""
    from types import SimpleNamespace

    from jls.report.spectra import _scatter_sentence, own_sea_level_ratio
    for value, side in ((1.2437, "above"), (0.9512, "below")):
        r = xr.DataArray(np.full((2, 2, 1, 2), 0.5), dims=("candidate", "tugger", "criterion", "non_exceedance"),
                         coords={"candidate": ["a", "b"], "tugger": ["none", "t1"],
                                 "criterion": ["relative_sway_m"], "non_exceedance": [0.5, 0.9]})
        r.loc[{"candidate": "b", "tugger": "t1", "non_exceedance": 0.5}] = value
        v = xr.Dataset({"own_sea_level_ratio": r})
        v.attrs["own_sea_not_used"] = ""
        cx = SimpleNamespace(voyage=v, dg=SimpleNamespace(best=("b", "t1")))
        assert own_sea_level_ratio(cx) == value
        text = _scatter_sentence(cx)
        assert f"is {value:.2f} x that of JONSWAP seas" in text and f"({side} it;" in text
        assert "unconservative" not in text and "not on their own seas" not in text
        v.attrs["own_sea_not_used"] = "leg x keeps JONSWAP"
        assert "not on their own seas: leg x keeps JONSWAP" in _scatter_sentence(cx)
    cx = SimpleNamespace(voyage=xr.Dataset(), dg=SimpleNamespace(best=("b", "t1")))
    assert own_sea_level_ratio(cx) is None
    assert "is not the ratio of their voyage levels" in _scatter_sentence(cx)


def test_what_the_voyage_extremes_cannot_take_from_the_own_seas_is_named():
    """voyage.nc's own_sea_not_used: empty when every own-sea leg's records carry their own
    period for every criterion; else the leg, what it keeps and why. The records' sigma,
    not stored, is the one whose 3-h MPM at the period is the level (utilisation x limit):
    the voyage extremes of records stored as their level and period are those of their
    sigma and period to 1e-12."""
    from jls.stages.voyage import own_sea_not_used, own_table_seas
    cell, _, _ = table()
    sea = xr.Dataset({"probability": cell.sum("heading"),
                      "hs_upper": (("leg", "hs"), np.tile(HS + 0.25, (2, 1))),
                      "tz_upper": (("leg", "tz"), np.tile(cell["tz"].values + 0.5, (2, 1)))})
    own = binned_records().isel(leg=0, drop=True)
    k = np.sqrt(2.0 * np.log(3 * 3600.0 / own["tz_response"]))               # MPM / sigma over 3 h
    m = xr.Dataset({"utilisation": own["sigma"] * k / LIMIT.reset_coords(drop=True),
                    "tz_response_own": own["tz_response"],
                    "probability": own["probability"], "hs": ("time", HS[own["hs_cell"].values]),
                    "tz": ("time", cell["tz"].values[own["tz_cell"].values])}).expand_dims(leg=["table"])
    crit = LIMIT["criterion"].values.tolist()
    with pytest.raises(ValueError, match="exposure_h"):
        own_table_seas(m, sea, crit)
    rec, left = own_table_seas(m, sea, crit, limit=LIMIT, exposure_h=3.0, cycles="response")
    assert left == {} and own_sea_not_used(m, hourly=False, left=left) == ""
    np.testing.assert_array_equal(rec["hs_cell"].values[0], own["hs_cell"].values)      # binned by the edges
    np.testing.assert_array_equal(rec["tz_cell"].values[0], own["tz_cell"].values)
    np.testing.assert_allclose(solve(rec)["voyage_level"].values, solve(binned_records())["voyage_level"].values,
                               rtol=1e-12)
    _, left = own_table_seas(m, sea, [*crit, "tip_air_gap_m"], limit=LIMIT, exposure_h=3.0)
    note = own_sea_not_used(m, hourly=False, left=left)
    assert "leg table is that of JONSWAP seas" in note and "no own-sea statistics of tip_air_gap_m" in note
    _, left = own_table_seas(m.drop_vars(["tz_response_own"]), sea, crit)
    note = own_sea_not_used(m.drop_vars(["tz_response_own"]), hourly=True, left=left)
    assert "holds no tz_response_own" in note and "response period of the JONSWAP" in note


def test_sigma_from_mpm_inverts_from_moments():
    """The own sigma is the one whose MPM over the exposure at the own period is the level
    (both cycle rules); no cycles to reach a level: unknown, and a level 0 has sigma 0."""
    from jls.response.statistics import FIXED_CYCLES_STUDY, from_moments, sigma_from_mpm
    rng = np.random.default_rng(11)
    m0, tz = rng.uniform(0.01, 4.0, 50), rng.uniform(3.0, 25.0, 50)
    for cycles in ("response", FIXED_CYCLES_STUDY):
        st = from_moments(m0, m0 * (2 * np.pi / tz) ** 2, 3 * 3600.0, cycles)
        np.testing.assert_allclose(sigma_from_mpm(st["mpm"], st["tz_response"], 3 * 3600.0, cycles), st["sigma"],
                                   rtol=1e-12)
    got = sigma_from_mpm(np.array([0.0, 1.0, 1.0]), np.array([np.nan, np.nan, 3 * 3600.0]))
    assert got[0] == 0.0 and np.isnan(got[1:]).all()
