"""Round three of the input checks (docs/inputs.md), continued: files that contradict
the configuration, conventions checked by physics, and the spectra files: their errors
named where they are (the data file, its line, the key and configuration file that give
it), enough data, one missing value one hour, and the RAO-range rule for measured and
partitioned seas."""

from pathlib import Path

import pytest
from test_malformed_round3 import _check

from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]


# --- (d) files against the configuration; (e) conventions checked by physics -------------

HLV = ROOT / "config" / "vessel" / "representative_hlv.nc"


def _capytaine_layout(path, *, rotation_center=(-23.2945, 0.0, 19.462), conjugate=True):
    """The shipped RAOs written as Capytaine writes them: exp(-i w t) (the conjugate of
    jls's), split into re/im along ``complex``, ``radiating_dof`` names, rotation_center."""
    import numpy as np
    import xarray as xr

    from jls.vessel.files import load_rao
    rao = load_rao(HLV)
    values = rao["rao"].transpose("omega", "wave_direction", "dof").values
    values = np.conj(values) if conjugate else values
    da = xr.DataArray(np.stack([values.real, values.imag], axis=-1),
                      dims=("omega", "wave_direction", "radiating_dof", "complex"),
                      coords={"omega": rao["omega"].values, "wave_direction": rao["wave_direction"].values,
                              "radiating_dof": ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"],
                              "complex": ["re", "im"]})
    ds = da.to_dataset(name="rao")
    ds["rotation_center"] = ("xyz", np.asarray(rotation_center, float))
    ds.to_netcdf(path)
    return path


def _vessel_overlay(path, fmt):
    return f"vessel:\n  rao_file: {path}\n  rao_format: {fmt}\n"


def test_capytaine_layout_of_the_shipped_raos_is_accepted(tmp_path, monkeypatch):
    import numpy as np

    from jls.vessel.files import load_rao
    from jls.vessel.phase_checks import long_wave_agreement
    path = _capytaine_layout(tmp_path / "capy.nc")
    back = load_rao(path, "capytaine")
    np.testing.assert_allclose(back["rao"].values, load_rao(HLV)["rao"].values, rtol=1e-12)
    assert long_wave_agreement(back) > 0.99


def test_capytaine_reference_point_at_the_keel(tmp_path, monkeypatch):
    path = _capytaine_layout(tmp_path / "keel.nc", rotation_center=(-23.29, 0.0, -14.0))
    text = _check(tmp_path, monkeypatch, _vessel_overlay(path, "capytaine"))
    assert text.startswith(f"{path}: vessel.rao_reference_point_height_m:")
    assert "z = -14 m (rotation_center" in text and "config/config.yaml puts the RAO reference point 19.462 m" in text
    assert "33.46 m off" in text and "(got 19.462)" in text


def test_capytaine_file_conjugated_twice(tmp_path, monkeypatch):
    path = _capytaine_layout(tmp_path / "plus.nc", conjugate=False)    # already exp(+i w t)
    text = _check(tmp_path, monkeypatch, _vessel_overlay(path, "capytaine"))
    assert text.startswith(f"{path}: phase convention:") and "signs of the other phase convention" in text
    assert "already in exp(+i omega t)" in text and "(got -1.0)" in text


def _csv(path, *, lag, declare=None):
    import numpy as np

    from jls.vessel.files import load_rao
    rao = load_rao(HLV)
    lines = [] if declare is None else [f"# phase: {declare}"]
    lines.append("omega_rad_s,wave_direction_deg,dof,amplitude,phase_deg")
    v = rao["rao"].transpose("omega", "wave_direction", "dof").values
    for i, w in enumerate(rao["omega"].values):
        for j, b in enumerate(np.degrees(rao["wave_direction"].values)):
            for k, dof in enumerate(rao["dof"].values):
                phase = np.degrees(np.angle(v[i, j, k])) * (-1 if lag else 1)
                lines.append(f"{float(w)!r},{float(b)!r},{dof},{float(abs(v[i, j, k]))!r},{float(phase)!r}")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_csv_in_the_lag_convention_without_its_declaration(tmp_path, monkeypatch):
    path = _csv(tmp_path / "lag.csv", lag=True)
    text = _check(tmp_path, monkeypatch, _vessel_overlay(path, "csv"))
    assert text.startswith(f"{path}: phase convention:") and "read as phase lead (the default)" in text
    assert "declare '# phase: lag' before the header" in text


def test_csv_lag_declared_is_accepted_and_equals_the_lead_file(tmp_path):
    import numpy as np

    from jls.vessel.files import load_rao
    from jls.vessel.phase_checks import check_phase_convention
    lag = load_rao(_csv(tmp_path / "lag.csv", lag=True, declare="lag"), "csv")
    lead = load_rao(_csv(tmp_path / "lead.csv", lag=False), "csv")
    assert check_phase_convention(lag) > 0.99 and check_phase_convention(lead) > 0.99
    np.testing.assert_allclose(lag["rao"].values, lead["rao"].values, atol=1e-12)
    with pytest.raises(InputError, match="remove the '# phase: lag' declaration"):
        check_phase_convention(load_rao(_csv(tmp_path / "x.csv", lag=False, declare="lag"), "csv"))


def test_long_wave_phase_undecided_outside_long_waves(tmp_path):
    """A file stopping short of long waves (heave far from 1) decides nothing."""
    from jls.vessel.files import load_rao
    from jls.vessel.phase_checks import long_wave_agreement
    rao = load_rao(HLV)
    assert long_wave_agreement(rao.isel(omega=slice(40, None))) is None


# --- (f) spectra files: their errors named where they are, enough data, one hour a gap ---

def _buoy(tmp_path, monkeypatch, edit=None, *, course=True, compress_density=False, kinds="wdijk",
          dir_edges=None):
    """A project with the shipped configuration and a route 'buoy' whose one leg is the
    committed NDBC 41010 spectra (copied plain, ``edit`` applied), binned by direction
    on a course (or at beam seas); returns the path of case.yaml."""
    import gzip
    import shutil

    import sea_fixtures as fx
    monkeypatch.chdir(tmp_path)
    shutil.copytree(ROOT / "config", tmp_path / "config")
    (tmp_path / "buoy").mkdir()
    density = fx.write_historical(tmp_path / "buoy", edit, kinds=kinds)
    name = density.name
    if compress_density:
        (tmp_path / "buoy" / (name + ".gz")).write_bytes(gzip.compress(density.read_bytes()))
        density.unlink()
        name += ".gz"
    heading = "course_deg: 190" if course else "headings_deg: [90]"
    edges = ", dir_edges_deg: [0, 90, 180, 270, 360]" if (course if dir_edges is None else dir_edges) else ""
    (tmp_path / "case.yaml").write_text(
        "routes:\n  buoy:\n    legs:\n      - name: b\n"
        f"        spectra: {{file: buoy/{name}, format: ndbc{edges}}}\n"
        f"        duration_h: 50\n        {heading}\n")
    return [Path("config/config.yaml"), Path("case.yaml")]


def _edit(kind_to_edit, row, col, value):
    def edit(kind, header, rows):
        if kind == kind_to_edit:
            rows[row][5 + col] = value
        return header, rows
    return edit


@pytest.mark.parametrize("course", [True, False])
def test_spectra_error_names_the_data_file_its_line_and_the_key(tmp_path, monkeypatch, course):
    from jls.config.workflow_inputs import check_run
    files = _buoy(tmp_path, monkeypatch, _edit("j", 5, 20, "150"), course=course)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert text.startswith("buoy/41010j2019part.txt: line 7, frequency .1600 Hz:"), text
    assert "r1 outside 0-1" in text and "the r1 file beside the density file 41010w2019part.txt" in text
    assert "the file given by routes.buoy.legs[0].spectra.file in case.yaml" in text
    assert text.endswith("(got 150.0)") and "case.yaml: line" not in text


def test_one_missing_direction_value_drops_one_hour(tmp_path, monkeypatch):
    from jls.config.workflow_inputs import check_run
    from jls.sea.measured import read_ndbc_spectra
    files = _buoy(tmp_path, monkeypatch, _edit("j", 5, 20, "999.0"))
    summary = check_run(files)
    assert any("1 record(s) with a missing-value code (999) in 41010w2019part.txt or its direction "
               "files, left out as gaps (density file lines 7)" in w for w in summary["warnings"])
    efth = read_ndbc_spectra(tmp_path / "buoy" / "41010w2019part.txt")
    assert efth.sizes["time"] == 98 and efth.sizes["dir"] == 24


def test_compressed_density_beside_plain_direction_files(tmp_path, monkeypatch):
    import numpy as np
    import sea_fixtures as fx

    from jls.config.workflow_inputs import check_run
    from jls.sea.measured import read_ndbc_spectra
    check_run(_buoy(tmp_path, monkeypatch, compress_density=True))
    mixed = read_ndbc_spectra(tmp_path / "buoy" / "41010w2019part.txt.gz")
    plain = read_ndbc_spectra(fx.NDBC_DENSITY)
    assert mixed.sizes["dir"] == 24
    np.testing.assert_allclose(mixed.values, plain.values, rtol=1e-12)


def test_one_dimensional_spectra_binned_by_direction_name_the_missing_files(tmp_path, monkeypatch):
    from jls.config.workflow_inputs import check_run
    files = _buoy(tmp_path, monkeypatch, kinds="w", course=False, dir_edges=True)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert "buoy/41010w2019part.txt" in text and "one-dimensional" in text
    assert "(41010d2019part.txt, 41010i2019part.txt, 41010j2019part.txt, 41010k2019part.txt)" in text


def test_spectra_cut_to_two_bands(tmp_path, monkeypatch):
    from jls.config.workflow_inputs import check_run

    def two(kind, header, rows):
        return header[:5] + header[20:22], [r[:5] + r[20:22] for r in rows]
    files = _buoy(tmp_path, monkeypatch, two, course=False)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert text.startswith("buoy/41010w2019part.txt: frequencies:")
    assert "2 frequency band(s) (0.11-0.12 Hz), fewer than the 15" in text and "(got 2)" in text
    assert "routes.buoy.legs[0].spectra.file in case.yaml" in text


def test_measured_energy_below_the_rao_range(tmp_path, monkeypatch):
    """50 m2/Hz at 0.015 Hz (0.094 rad/s), below the shipped RAOs' 0.1 rad/s: the rule of
    the parametric sea states (0.1 % of the energy outside the range and the stated bands)
    applies to measured spectra too."""
    from jls.config.workflow_inputs import check_run

    def swell(kind, header, rows):
        header = header[:5] + [".0150"] + header[6:]
        if kind == "w":
            rows[3][5] = "50.0"
        return header, rows
    files = _buoy(tmp_path, monkeypatch, swell, course=False)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert text.startswith("buoy/41010w2019part.txt: vessel.outside_rao_range: route 'buoy', leg 'b': 1 of "
                           "the 99 spectra have more than 0.1 % of their energy outside the RAO range "
                           "[0.100, 3.000] rad/s"), text
    assert "the largest at 2019-02-06T03:40" in text and "below it (bands from 0.094 rad/s, 0.015 Hz)" in text
    assert "routes.buoy.legs[0].spectra.file in case.yaml" in text


def test_measured_energy_inside_a_stated_band_is_accepted():
    import numpy as np
    import xarray as xr

    from jls.response.coverage import check_spectra_coverage, spectra_outside
    f = np.linspace(0.015, 0.4, 40)
    e = np.exp(-((f - 0.1) / 0.03) ** 2)[None, :] * np.ones((2, 1))
    e[1, 0] = 50.0
    efth = xr.DataArray(e, dims=("time", "freq"), coords={"freq": f, "time": [0, 1]})
    zeroed, unexplained = spectra_outside(efth, 0.1, 3.0)
    assert unexplained[0] < 1e-3 < unexplained[1] and np.allclose(zeroed, unexplained)
    with pytest.raises(InputError, match="1 of the 2 spectra"):
        check_spectra_coverage(efth, 0.1, 3.0)
    policy = {"zero_below_rad_s": 0.1, "reason": "no vessel response to swell this long"}
    check_spectra_coverage(efth, 0.1, 3.0, policy)


# --- (e) spectra against a companion parameter file of the same buoy ---------------------

PARAMS = ROOT / "tests" / "data" / "metocean" / "41010h2019part.txt"


def _with_parameters(files, tmp_path):
    text = (tmp_path / "case.yaml").read_text()
    (tmp_path / "case.yaml").write_text(text.replace("format: ndbc", f"format: ndbc, parameters_file: {PARAMS}"))
    return files


def test_spectra_agree_with_their_parameter_file(tmp_path, monkeypatch):
    """The committed 41010 spectra against NDBC's own WVHT and MWD of the same hours:
    Hs ratio 1.000, mean direction within 0.01 deg in the median."""
    from jls.config.workflow_inputs import check_run
    from jls.sea.companions import check_parameters
    from jls.sea.measured import read_spectra
    from jls.sea.metocean import read_metocean
    from jls.sea.records import spectra_series
    check_run(_with_parameters(_buoy(tmp_path, monkeypatch), tmp_path))
    import sea_fixtures as fx
    found = check_parameters(spectra_series(read_spectra(fx.NDBC_DENSITY, "ndbc")),
                             read_metocean(PARAMS, "ndbc_stdmet"), "w", "h")
    assert found["n_common"] == 99 and abs(found["hs_ratio"] - 1) < 0.01
    assert abs(found["direction_difference_deg"]) < 1.0


def test_density_per_rad_s_named_by_its_parameter_file(tmp_path, monkeypatch):
    import math

    from jls.config.workflow_inputs import check_run

    def per_rad_s(kind, header, rows):
        if kind == "w":
            rows = [r[:5] + [f"{float(v) / (2 * math.pi):.4f}" for v in r[5:]] for r in rows]
        return header, rows
    files = _with_parameters(_buoy(tmp_path, monkeypatch, per_rad_s, course=False), tmp_path)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert text.startswith("buoy/41010w2019part.txt: legs[b].spectra.parameters_file:")
    assert "0.40 x, 1/sqrt(2 pi): the density is per rad/s" in text and "41010h2019part.txt states WVHT" in text
    assert "the file given by routes.buoy.legs[0].spectra.file in case.yaml" in text


def test_directions_going_to_named_by_their_parameter_file(tmp_path, monkeypatch):
    from jls.config.workflow_inputs import check_run

    def going_to(kind, header, rows):
        if kind == "d":
            rows = [r[:5] + [str((float(v) + 180.0) % 360.0) if float(v) < 999 else v for v in r[5:]]
                    for r in rows]
        return header, rows
    files = _with_parameters(_buoy(tmp_path, monkeypatch, going_to), tmp_path)
    with pytest.raises(InputError) as exc:
        check_run(files)
    text = str(exc.value)
    assert "buoy/41010w2019part.txt" in text and "41010h2019part.txt's MWD by" in text
    assert "the direction the waves go TO" in text


@pytest.mark.parametrize("course, refused", [(3.49, True), (1.5708, True), (3.5, False), (190, False),
                                             (12.25, False)])
def test_course_in_radians(tmp_path, monkeypatch, course, refused):
    """3.49 is 200 deg in radians (k pi/36 with k = 40): flagged like the headings'
    radians; 3.5 deg or 12.25 deg are courses in degrees."""
    from jls.config.workflow_inputs import check_run
    files = _buoy(tmp_path, monkeypatch)
    text = (tmp_path / "case.yaml").read_text().replace("course_deg: 190", f"course_deg: {course}")
    (tmp_path / "case.yaml").write_text(text)
    if not refused:
        check_run(files)
        return
    with pytest.raises(InputError) as exc:
        check_run(files)
    assert str(exc.value).startswith("case.yaml: routes.buoy.legs[0].course_deg: these angles are in "
                                     "degrees, and the value looks like radians")
    assert f"(got {course})" in str(exc.value)


def test_partitioned_sea_with_a_swell_below_the_rao_range(tmp_path):
    """An ERA5 leg assessed on its total Hs and period hides a long swell partition: each
    partition is checked as a JONSWAP of its own period, weighted by its energy."""
    import sea_fixtures as fx

    from jls.config.sea_coverage import check_partition_coverage
    n = 4
    fx.era5_parameters(tmp_path / "era5.nc", {
        "swh": [2.2] * n, "pp1d": [8.0] * n, "mwp": [7.0] * n, "mwd": [200.0] * n,
        "shww": [1.0] * n, "mpww": [6.0] * n, "shts": [0.3, 0.3, 2.0, 2.0], "mpts": [20.0] * n})
    leg = {"name": "era", "metocean": {"file": "era5.nc", "format": "era5", "period": "tp"}}
    cfg = {"sea": {"gamma": 3.3}, "vessel": {}}
    layers = [("case.yaml", {"routes": {"r": {"legs": [leg]}}})]
    with pytest.raises(InputError) as exc:
        check_partition_coverage(cfg, leg, "r", 0, 0.3, 3.0, layers, tmp_path)
    text = str(exc.value)
    assert text.startswith(f"{tmp_path / 'era5.nc'}: vessel.outside_rao_range: route 'r', leg 'era': 4 of the 4 records")
    assert "the largest at 2019-02-06T02:00 with 40.27 %" in text and "partition swell_hs 2 m, swell_te 20 s" in text
    assert "routes.r.legs[0].metocean.file in case.yaml" in text
    cfg["vessel"]["outside_rao_range"] = {"zero_below_rad_s": 0.3, "zero_above_rad_s": 3.0,
                                          "reason": "swell this long and waves this short move no hull"}
    check_partition_coverage(cfg, leg, "r", 0, 0.3, 3.0, layers, tmp_path)


def test_density_per_rad_s_found_by_the_stdmet_file_beside_it(tmp_path, monkeypatch):
    """NDBC's standard meteorological file beside the density file (41010h... beside
    41010w...) is used without being named."""
    import math
    import shutil

    from jls.config.workflow_inputs import check_run
    from jls.sea.records import leg_files

    def per_rad_s(kind, header, rows):
        if kind == "w":
            rows = [r[:5] + [f"{float(v) / (2 * math.pi):.4f}" for v in r[5:]] for r in rows]
        return header, rows
    files = _buoy(tmp_path, monkeypatch, per_rad_s, course=False)
    shutil.copy(PARAMS, tmp_path / "buoy" / "41010h2019part.txt")
    with pytest.raises(InputError, match=r"0.40 x, 1/sqrt\(2 pi\).*41010h2019part.txt states WVHT"):
        check_run(files)
    leg = {"name": "b", "spectra": {"file": "buoy/41010w2019part.txt", "format": "ndbc"}}
    assert "buoy/41010h2019part.txt" in leg_files(leg, tmp_path)
