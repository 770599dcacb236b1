"""The chapter Wave spectra's figure (jls.report.spectra_figure): per leg its typical spectra
against the recommendation's relative-sway transfer function, every number from the
datasets; and the leg's mean spectrum the measured-response stage stores for it."""

from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

from jls.report.spectra_figure import NAME, leg_heading, leg_spectra, sea_transfer
from jls.sea.sea_state import torsethaugen_systems
from jls.sea.spectra import jonswap, tp_from_tz
from jls.stages.measured_response import mean_spectrum

OMEGA = np.linspace(0.2, 2.5, 400)


def _efth(hs, tp):
    f = OMEGA / (2 * np.pi)
    E = np.array([jonswap(OMEGA, h, p, 3.3) * 2 * np.pi for h, p in zip(hs, tp)])     # m^2/Hz
    E = np.concatenate([E, np.zeros((1, f.size))])                                       # a gap hour
    return xr.DataArray(E, dims=("time", "freq"), coords={"time": np.arange(len(hs) + 1), "freq": f})


def test_the_mean_spectrum_is_the_weighted_mean_of_the_records_and_keeps_their_variance():
    e = _efth([1.0, 2.0], [8.0, 14.0])
    m0 = [np.trapezoid(jonswap(OMEGA, h, p, 3.3), OMEGA) for h, p in ((1.0, 8.0), (2.0, 14.0))]
    assert m0 == pytest.approx([1 / 16, 4 / 16], rel=0.01)            # the grid holds the records
    S = mean_spectrum(e, None, OMEGA)
    # every record with energy alike (the gap hour left out): the mean variance
    assert np.trapezoid(S, OMEGA) == pytest.approx((m0[0] + m0[1]) / 2, rel=1e-9)
    S2 = mean_spectrum(e, [3.0, 1.0, 5.0], OMEGA)
    assert np.trapezoid(S2, OMEGA) == pytest.approx((3 * m0[0] + m0[1]) / 4, rel=1e-9)
    # the swell record's peak stays where it was
    assert 2 * np.pi / OMEGA[np.argmax(S)] == pytest.approx(14.0, rel=0.03)


def _cx(model):
    legs, heads, hs, tz = ["a"], [60.0, 90.0], np.array([0.75, 1.25]), np.array([6.5, 7.5, 12.5])
    p = np.zeros((1, 2, 2, 3))
    p[0, 1, 1, 2] = 0.5        # most probable: heading 90, Hs 1.25, T 12.5
    p[0, 1, 0, 0] = 0.3
    p[0, 0, 0, 1] = 0.1
    sea = xr.Dataset({"cell_probability": (("leg", "heading", "hs", "tz"), p),
                      "hs_upper": (("leg", "hs"), [hs + 0.25])},
                     coords={"leg": legs, "heading": heads, "hs": hs, "tz": tz})
    H = np.zeros((1, 1, 2, 1, OMEGA.size), complex)
    H[0, 0, 1, 0] = 1.0 / np.abs(1 - (OMEGA / 0.4) ** 2 + 0.05j)
    resp = xr.Dataset({"transfer_re": (("shown_candidate", "tugger", "heading", "response", "omega"), H.real),
                       "transfer_im": (("shown_candidate", "tugger", "heading", "response", "omega"), H.imag)},
                      coords={"shown_candidate": ["baseline"], "tugger": ["none"], "heading": heads,
                              "response": ["relative_sway"], "omega": OMEGA}, attrs={"gamma": 3.3})
    plant = xr.Dataset({"natural_period": (("candidate", "mode"), [[15.7, 5.0]])}, coords={"candidate": ["baseline"]})
    measured = None
    if model in ("partitions", "measured"):
        measured = xr.Dataset({"spectrum_mean": (("leg", "omega"), [jonswap(OMEGA, 1.0, 14.0, 3.3)]),
                               "hours": ("leg", [168])}, coords={"leg": legs, "omega": OMEGA})
    return SimpleNamespace(sea=sea, resp=resp, plant=plant, measured=measured, work=xr.Dataset(attrs={"hs_in_bin": "centre"}),
                           dg=SimpleNamespace(best=("baseline", "none")), legs=legs)


def test_a_jonswap_legs_spectra_are_its_most_probable_cells_from_the_sea_states():
    cx = _cx("jonswap")
    assert leg_heading(cx, "a") == 90.0
    out = leg_spectra(cx, "a", "jonswap", OMEGA)
    assert [label for label, _ in out] == ["Hs 1.25 m, Tz 12.5 s (56 %)", "Hs 0.75 m, Tz 6.5 s (33 %)",
                                           "Hs 0.75 m, Tz 7.5 s (11 %)"]
    np.testing.assert_allclose(out[0][1], jonswap(OMEGA, 1.25, float(tp_from_tz(12.5, 3.3)), 3.3))
    # a Torsethaugen leg's period axis is Tp: its cells are the two systems' sum
    tors = leg_spectra(cx, "a", "torsethaugen", OMEGA)
    expected = sum(s.spectrum(OMEGA) for s in torsethaugen_systems(1.25, "tp", 12.5, from_deg=0.0,
                                                                    spreading={"wind": "long-crested",
                                                                               "swell": "long-crested"}))
    np.testing.assert_allclose(tors[0][1], expected)
    assert tors[0][0].startswith("Hs 1.25 m, Tp 12.5 s")


def test_a_partitions_legs_spectrum_is_the_stored_mean_and_the_figure_draws(tmp_path):
    cx = _cx("partitions")
    (label, S), = leg_spectra(cx, "a", "partitions", OMEGA)
    assert label == "mean of 168 hours (partitions)"
    np.testing.assert_allclose(S, cx.measured["spectrum_mean"].sel(leg="a").values)
    path = sea_transfer(cx, {"a": "partitions"}, tmp_path)
    assert path.name == f"{NAME}.svg" and path.stat().st_size > 1000
    # a recommendation without a stored transfer function is said so, not drawn
    cx.dg.best = ("other", "none")
    assert "no stored transfer function of other" in sea_transfer(cx, {"a": "partitions"}, tmp_path).read_text()
