"""Route legs given by metocean parameter files and by spectra (jls.sea.records): the
hourly record each gives, its binning to the leg's scatter, the declared period and the
errors that name the leg's field."""

from pathlib import Path

import numpy as np
import pytest
import sea_fixtures as fx

from jls.assessment.windows import read_route_hindcasts
from jls.errors import InputError
from jls.sea.legs import read_leg
from jls.sea.measured import integrated_parameters, read_spectra
from jls.sea.records import leg_files, leg_series, leg_source
from jls.sea.spectra import te_from_tp, tz_from_tp

DATA = Path(__file__).parent / "data"
STDMET = "metocean/41010h2019part.txt"
SPECTRA = "spectra/ndbc_41010_2019/41010w2019part.txt.gz"
EDGES = {"hs_edges_m": [0, 1, 2, 3, 4, 6], "tz_edges_s": [2, 4, 5, 6, 7, 8, 10, 14], "outside": "error"}


def metocean_leg(file=STDMET, fmt="ndbc_stdmet", period="tz", **extra):
    return {"name": "buoy", "duration_h": 6, "headings_deg": [90], "heading_probability": [1.0],
            "metocean": {"file": file, "format": fmt, "period": period, **EDGES, **extra}}


def spectra_leg(**extra):
    return {"name": "spec", "duration_h": 6, "headings_deg": [90], "heading_probability": [1.0],
            "spectra": {"file": SPECTRA, "format": "ndbc", **EDGES, **extra}}


def test_ndbc_stdmet_leg_is_binned_like_a_hindcast():
    ds = read_leg(metocean_leg(), DATA, "study", 3.3, 9.81)
    assert int(ds["count"].sum()) == 99 and ds.attrs["n_records"] == 99
    assert ds.attrs["source"] == "41010h2019part.txt" and ds.attrs["leg_kind"] == "metocean"
    assert ds.attrs["period_conversion"].startswith("Tz (Tm02) as given")
    s = leg_series(metocean_leg(), DATA, gamma=3.3)
    assert list(s.columns) == ["hs", "tz", "direction"]
    np.testing.assert_allclose(s["tz"].iloc[0], 7.14)


def test_declared_peak_period_is_converted_with_the_jonswap_relation():
    tz = leg_series(metocean_leg(), DATA, gamma=3.3)
    tp = leg_series(metocean_leg(period="tp"), DATA, gamma=3.3)
    raw = leg_series(metocean_leg(period="tz"), DATA, gamma=3.3)
    assert len(tp) == len(raw) == len(tz)
    dpd = np.loadtxt(DATA / STDMET, comments="#", usecols=9)
    np.testing.assert_allclose(tp["tz"].to_numpy(), dpd * float(tz_from_tp(1.0, 3.3)), rtol=1e-12)
    assert "x tp" in tp.attrs["period_conversion"] and "gamma 3.3" in tp.attrs["period_conversion"]
    # gamma matters: the ratio is the configured JONSWAP's
    tp1 = leg_series(metocean_leg(period="tp"), DATA, gamma=1.0)
    np.testing.assert_allclose(tp1["tz"].to_numpy(), dpd * float(tz_from_tp(1.0, 1.0)), rtol=1e-12)


def test_era5_leg_with_declared_mean_period(tmp_path):
    n = 30
    values = {"swh": np.linspace(1.0, 3.0, n), "pp1d": np.full(n, 10.0), "mwp": np.full(n, 8.0),
              "mwd": np.full(n, 270.0)}
    fx.era5_parameters(tmp_path / "era5.nc", values)
    leg = metocean_leg(file="era5.nc", fmt="era5", period="te", dir_edges_deg=[-45, 45, 135, 225, 315])
    s = leg_series(leg, tmp_path, gamma=3.3)
    np.testing.assert_allclose(s["tz"].to_numpy(), 8.0 * float(tz_from_tp(1.0, 3.3) / te_from_tp(1.0, 3.3)))
    leg.pop("headings_deg"), leg.pop("heading_probability")
    ds = read_leg({**leg, "heading_source": "direction_table", "course_deg": 0.0, "headings_deg": [0, 90, 180, 270]},
                  tmp_path, "study", 3.3, 9.81)
    assert float(ds["cell_probability"].sum()) == pytest.approx(1.0)
    # waves from the west met on a northward course: from port, relative heading 270
    assert float(ds["cell_probability"].sel(heading=270).sum()) == pytest.approx(1.0)
    # ERA5 gives no Tz: a leg declaring it is refused, naming the field
    with pytest.raises(InputError, match=r"legs\[buoy\]\.metocean\.period.*no tz column"):
        leg_series(metocean_leg(file="era5.nc", fmt="era5", period="tz"), tmp_path, gamma=3.3)


def test_spectra_leg_is_binned_on_its_hs_and_tm02():
    efth = read_spectra(DATA / SPECTRA, "ndbc")
    ip = integrated_parameters(efth)
    s = leg_series(spectra_leg(), DATA, gamma=3.3)
    np.testing.assert_allclose(s["hs"].to_numpy(), ip["hs"].values)
    np.testing.assert_allclose(s["tz"].to_numpy(), ip["tm02"].values)
    assert s.attrs["kind"] == "spectra" and "Tm02" in s.attrs["period_conversion"]
    ds = read_leg(spectra_leg(), DATA, "study", 3.3, 9.81)
    assert int(ds["count"].sum()) == 99
    # the stdmet file of the same records bins to the same cells (its values rounded)
    ds2 = read_leg(metocean_leg(), DATA, "study", 3.3, 9.81)
    assert np.abs(ds["count"].values - ds2["count"].values).sum() <= 4
    assert leg_source(spectra_leg()) == Path(SPECTRA)
    files = leg_files(spectra_leg(), DATA)
    assert len(files) == 5 and files[0] == SPECTRA        # the density and four direction files


def test_hourly_legs_feed_the_weather_windows():
    route = {"legs": [metocean_leg(), spectra_leg(),
                      {"name": "s", "duration_h": 3, "scatter": "sea/matrix_counts_edges.csv"}]}
    got = read_route_hindcasts(route, DATA, gamma=3.3)
    assert list(got) == ["buoy", "spec"] and len(got["spec"]) == 99


def test_bad_leg_files_are_named(tmp_path):
    with pytest.raises(InputError, match=r"legs\[buoy\]\.metocean\.file"):
        leg_series(metocean_leg(file="absent.txt"), DATA, gamma=3.3)
    bad = tmp_path / "41010h2019.txt"
    bad.write_text((DATA / STDMET).read_text().replace("WVHT", "WAVE"))
    with pytest.raises(InputError, match="41010h2019.txt"):
        leg_series(metocean_leg(file=str(bad)), DATA, gamma=3.3)
    with pytest.raises(InputError, match=r"legs\[buoy\]\.metocean\.bins: 34 records .*metocean\.outside"):
        read_leg(metocean_leg(hs_edges_m=[0, 1]), DATA, "study", 3.3, 9.81)
    spec = tmp_path / "41010w2019.txt"
    spec.write_text("#YY  MM DD hh mm\n2019 02 06 00 40 1.0\n")
    leg = spectra_leg()
    leg["spectra"]["file"] = str(spec)
    with pytest.raises(InputError, match="41010w2019.txt"):
        leg_series(leg, DATA, gamma=3.3)


def test_configured_legs_validate_and_take_their_headings_from_the_record():
    import yaml

    from jls.config.loader import validate
    root = DATA.parents[1]
    cfg = yaml.safe_load((root / "config" / "config.yaml").read_text())
    cfg["vessel"]["rao_file"] = str(root / cfg["vessel"]["rao_file"])
    spec = {"file": str(DATA / SPECTRA), "format": "ndbc", "hs_edges_m": [0, 1, 2, 3, 6],
            "tz_edges_s": [4, 6, 8, 10], "dir_edges_deg": [-15 + 30 * k for k in range(13)]}
    met = {"file": str(DATA / STDMET), "format": "ndbc_stdmet", "period": "tz",
           "hs_edges_m": [0, 1, 2, 3, 6], "tz_edges_s": [4, 6, 8, 10]}
    cfg["routes"]["default"]["legs"] = [
        {"name": "a", "duration_h": 6.0, "course_deg": 180.0, "heading_step_deg": 30, "spectra": spec},
        {"name": "b", "duration_h": 6.0, "metocean": met}]
    legs = validate(cfg, base_dir=root)["routes"]["default"]["legs"]
    assert legs[0]["heading_source"] == "direction_table"
    assert legs[0]["spectra"]["outside"] == "error"            # the schema's default
    assert sum(legs[0]["heading_probability"]) == pytest.approx(1.0)
    assert legs[1]["headings_deg"] == [90] and legs[1]["metocean"]["period"] == "tz"
    bad = yaml.safe_load(yaml.safe_dump(cfg))
    bad["routes"]["default"]["legs"][1]["metocean"]["period"] = "peak"
    with pytest.raises(InputError, match="period"):
        validate(bad, base_dir=root)
    bad["routes"]["default"]["legs"][1]["metocean"].pop("period")
    with pytest.raises(InputError, match=r"metocean\.period.*required key is missing|required key is missing"):
        validate(bad, base_dir=root)


def test_a_1d_spectrum_has_no_direction_to_bin(tmp_path):
    import shutil
    shutil.copy(DATA / SPECTRA, tmp_path / "41010w2019part.txt.gz")        # no direction files beside it
    leg = spectra_leg(dir_edges_deg=[0, 180, 360])
    leg["spectra"]["file"] = "41010w2019part.txt.gz"
    assert "direction" not in leg_series(leg, tmp_path, gamma=3.3).columns
    assert leg_files(leg, tmp_path) == ["41010w2019part.txt.gz"]
    with pytest.raises(InputError, match=r"legs\[spec\]\.spectra\.dir_edges_deg.*one-dimensional.*"
                                         r"direction files beside the density file are missing \(41010d2019"):
        read_leg(leg, tmp_path, "study", 3.3, 9.81)


def test_a_spectra_leg_needs_only_its_file_and_format():
    """The issue's contract: ``spectra: {file: PATH, format: NAME}`` is assessed like a
    hindcast leg; the bins are the schema's defaults (0.5 m in Hs, 1 s in Tz)."""
    import yaml

    from jls.config.loader import validate
    root = DATA.parents[1]
    cfg = yaml.safe_load((root / "config" / "config.yaml").read_text())
    cfg["vessel"]["rao_file"] = str(root / cfg["vessel"]["rao_file"])
    cfg["routes"]["default"]["legs"] = [
        {"name": "a", "duration_h": 6.0, "spectra": {"file": str(DATA / SPECTRA), "format": "ndbc"}},
        {"name": "b", "duration_h": 6.0, "metocean": {"file": str(DATA / STDMET), "format": "ndbc_stdmet",
                                                      "period": "tz"}}]
    legs = validate(cfg, base_dir=root)["routes"]["default"]["legs"]
    for leg in legs:
        ds = read_leg(leg, root, "study", 3.3, 9.81)
        assert int(ds["count"].sum()) == 99
        np.testing.assert_allclose(np.diff(ds["hs_lower"].values), 0.5)
        np.testing.assert_allclose(np.diff(ds["tz_lower"].values), 1.0)
