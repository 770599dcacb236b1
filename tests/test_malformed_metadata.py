"""Catalogue of malformed inputs, continued: what files say about themselves (readers
honour or refuse it), intermediate datasets that are corrupt or foreign, and the
time-domain verdict rule.

Each case stops with one line naming the file and the line, key or value, and nothing is
written under results/ or reports/ of the case's project directory (the autouse fixture
``project_dir`` of tests/test_malformed_inputs.py).
"""

import copy
import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from test_malformed_inputs import BASE, DATA, ROOT, one_line_error, project_dir  # noqa: F401
from test_winch_limits import assessed

from jls.assessment.winch_limits import TIMEDOMAIN_RULE, apply_timedomain, mpm_standard_error
from jls.assessment.workability import assessed_hs
from jls.config.dataset_hash import config_hash
from jls.config.intermediates import problems, set_aside, symlinks
from jls.config.loader import load
from jls.errors import InputError
from jls.io.netcdf import add_warnings, read, warnings_of, write
from jls.names import FREQUENCY_DOMAIN, SATURATED_FAIL, TIME_DOMAIN
from jls.sea.hindcast import read_hindcast
from jls.sea.legs import read_leg
from jls.stages.sea_states import sea_states
from jls.vessel.files import load_rao

METOCEAN = ROOT / "tests" / "data" / "metocean" / "ndbc44007_hourly_hs_tz_1996.txt"
CAPYTAINE = ROOT / "tests" / "data" / "vessel" / "capytaine_rao_split.nc"


# --- scatter tables: corner labels, declared bins, stated totals, header keys -------------

SCATTER_CASES = [
    ("scatter_corner_tp.csv", ["line 5, column 1", "the peak period Tp", "Tz = Tp / 1.286", "hs\\\\tp"]),
    ("scatter_corner_transposed.csv", ["line 5, column 1", "puts Tz first", "transpose"]),
    ("scatter_declared_centres.csv", ["line 6, column 1", "declared as centres", "'0.0-1.0'"]),
    ("scatter_declared_edges.csv", ["line 5, column 2", "declared as edges", "'5.5'"]),
    ("scatter_records_mismatch.csv", ["header key records", "cells sum to 48", "'64'"]),
    ("scatter_span_mismatch.csv", ["header key missing_hours", "make 50 hours", "spans 72"]),
    ("scatter_hs_feet.csv", ["header key hs_units", "'ft'", "['m']"]),
    ("scatter_period_tp.csv", ["header key period", "'tp'"]),
    ("scatter_scale_key.csv", ["header key hs_scale_factor", "does not read"]),
]


@pytest.mark.parametrize("name, needles", SCATTER_CASES, ids=[c[0] for c in SCATTER_CASES])
def test_scatter_metadata(name, needles):
    leg = {"name": "north", "scatter": str(DATA / name), "duration_h": 10}
    one_line_error(lambda: read_leg(leg, ".", "study", 3.3, 9.81), name, *needles)


def test_scatter_metadata_that_is_honoured():
    ds = read_leg({"name": "n", "scatter": str(ROOT / BASE["routes"]["default"]["legs"][0]["scatter"]),
                   "duration_h": 10}, ".", "study", 3.3, 9.81)
    assert ds.attrs["records"] == "82805" and ds.attrs["total"] == 82805     # stated, checked
    assert warnings_of(ds) == []


def test_a_probability_table_that_does_not_sum_to_one_is_stated(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("# layout: matrix\n# hs_bins: edges\n# tz_bins: edges\n# values: probability\n"
                    "hs\\tz,5.0-6.0,6.0-7.0\n0.0-1.0,0.2,0.1\n1.0-2.0,0.3,0.2\n")
    ds = read_leg({"name": "n", "scatter": str(path), "duration_h": 10}, ".", "study", 3.3, 9.81)
    assert float(ds["probability"].sum()) == pytest.approx(1.0)
    assert warnings_of(ds) == ["scatter table p.csv: its probabilities sum to 0.8, neither 1 nor "
                               "100; they were renormalised to 1"]


# --- hindcasts: column names; span, step and calendar coverage stated ---------------------

@pytest.mark.parametrize("name, needles", [
    ("hindcast_peak_period.txt", ["line 1", "the peak period", "convert it to Tz"]),
    ("hindcast_feet.txt", ["line 1", "column 2 is in 'ft'"]),
])
def test_hindcast_column_names(name, needles):
    one_line_error(lambda: read_hindcast(DATA / name), name, *needles)


def _record(tmp_path, keep):
    df = read_hindcast(METOCEAN)
    text = METOCEAN.read_text().splitlines()
    lines = [text[0]] + [line for line, ok in zip(text[1:], keep(df)) if ok]
    path = tmp_path / "cases" / "record.txt"
    path.parent.mkdir(exist_ok=True)
    path.write_text("\n".join(lines) + "\n")
    h = {"file": str(path), "hs_edges_m": [0, 1, 2, 3, 4, 6, 10, 15],
         "tz_edges_s": [2, 4, 5, 6, 7, 8, 10, 14, 20], "outside": "report"}
    return read_leg({"name": "south", "hindcast": h, "duration_h": 24}, ".", "study", 3.3, 9.81)


def test_a_full_hourly_year_states_its_coverage_and_warns_of_nothing(tmp_path):
    ds = _record(tmp_path, lambda df: np.ones(len(df), bool))
    a = ds.attrs
    assert a["record_step_h"] == 1.0 and a["record_missing_months"] == ""
    assert a["record_start"].startswith("1996-01-01") and a["record_end"].startswith("1996-12-31")
    assert a["record_coverage"] == pytest.approx(8616 / 8784, abs=1e-3) and warnings_of(ds) == []


def test_a_three_hourly_record_is_named(tmp_path):
    ds = _record(tmp_path, lambda df: (df.index.hour % 3) == 0)
    assert ds.attrs["record_step_h"] == 3.0
    (line,) = warnings_of(ds)
    assert "record.txt: records every 3 h, not hourly" in line and "67 %" in line


def test_a_seasonal_record_is_named_with_its_months(tmp_path):
    ds = _record(tmp_path, lambda df: (df.index.month >= 4) & (df.index.month <= 9))
    assert ds.attrs["record_missing_months"] == "Jan Feb Mar Oct Nov Dec"
    (line,) = warnings_of(ds)
    assert "covers 6 of the 12 calendar months" in line and "1996-04-01 to 1996-09-30" in line


def test_the_record_summary_reaches_the_sea_states(tmp_path):
    leg = _record(tmp_path, lambda df: (df.index.month >= 4) & (df.index.month <= 9))
    route = {"name": "r", "legs": [{"name": "south", "duration_h": 24, "headings_deg": [90],
                                    "heading_probability": [1.0]}]}
    out = sea_states(route, {"south": leg})
    assert "step 1 h" in out.attrs["record_south"] and "months Apr May Jun Jul Aug Sep" in out.attrs["record_south"]
    assert warnings_of(out) == warnings_of(leg)


# --- RAO files: CSV declarations, phase units, Capytaine coordinates ---------------------

@pytest.mark.parametrize("name, kwargs, needles", [
    ("rao_phase_radians.csv", {}, ["phase_deg", "within +-pi", "phase_units: rad"]),
    ("rao_heading_convention.csv", {}, ["line 1", "declares 'heading_convention'", "does not read"]),
    ("rao_reference_declared.csv", {}, ["line 1", "'reference_point_m'", "vessel block"]),
    ("rao_phase_radians_declared.csv", {"phase": "lag"}, ["phase"]),
], ids=["radians", "heading convention", "reference point", "caller"])
def test_csv_declarations(name, kwargs, needles):
    path = DATA / name
    if kwargs:                              # a declaration the caller contradicts
        text = "# phase: lead\n" + path.read_text()
        path = Path("cases") / name
        path.parent.mkdir(exist_ok=True)
        path.write_text(text)
    one_line_error(lambda: load_rao(path, **kwargs), name, *needles)


def test_declared_radians_are_honoured():
    deg, rad = load_rao(DATA / "rao_physical.csv"), load_rao(DATA / "rao_phase_radians_declared.csv")
    np.testing.assert_allclose(rad["rao"].values, deg["rao"].values, rtol=1e-5, atol=1e-12)
    assert rad.attrs["csv_phase_units"] == "rad"


def _capytaine(tmp_path, edit):
    with xr.open_dataset(CAPYTAINE) as raw:
        ds = edit(raw.load())
    path = tmp_path / "cases" / "capy.nc"
    path.parent.mkdir(exist_ok=True)
    ds.to_netcdf(path)
    return path


@pytest.mark.parametrize("what, edit, needles", [
    ("forward speed", lambda d: d.assign_coords(forward_speed=3.0), ["forward_speed", "forward speed"]),
    ("headings in degrees", lambda d: d.assign_coords(wave_direction=np.degrees(d["wave_direction"].values)),
     ["wave_direction", "degrees"]),
    ("omega in Hz", lambda d: d.assign_coords(omega=d["omega"].assign_attrs(units="Hz")),
     ["omega.units", "'hz'"]),
    ("period against omega", lambda d: d.assign_coords(period=("omega", d["period"].values * 1.1)),
     ["period", "disagrees with omega"]),
])
def test_capytaine_coordinates(tmp_path, what, edit, needles):
    path = _capytaine(tmp_path, edit)
    one_line_error(lambda: load_rao(path), "capy.nc", *needles)


def test_capytaine_depth_is_kept_and_used(tmp_path):
    rao = load_rao(_capytaine(tmp_path, lambda d: d.assign_coords(water_depth=30.0)))
    assert rao.attrs["water_depth_m"] == 30.0


# --- intermediate datasets: corrupt, foreign, of another layout ---------------------------

@pytest.fixture()
def route_dir(tmp_path):
    """A run folder (not the case's project directory) with a valid sea_states.nc."""
    cfg = load(ROOT / "config" / "config.yaml")
    base = tmp_path / "run" / "results"
    sea = sea_states({"name": "default", "legs": cfg["routes"]["default"]["legs"]},
                     {leg["name"]: read_leg({**leg, "scatter": str(ROOT / leg["scatter"])}, ".",
                                            "study", 3.3, 9.81)
                      for leg in cfg["routes"]["default"]["legs"]})
    write(sea, base / "default" / "sea_states.nc", dataset="sea_states", created_by="test",
          config_sha256=config_hash(cfg, "sea_states", "default"))
    return cfg, base


def _check(cfg, base):
    before = sorted((str(p), p.stat().st_mtime_ns) for p in base.rglob("*"))
    out = problems(cfg, base, ["default"], screening=True, n_screening_chunks=2,
                   n_response_chunks=1, windows_routes=())
    assert sorted((str(p), p.stat().st_mtime_ns) for p in base.rglob("*")) == before   # untouched
    return out


def test_a_valid_dataset_passes(route_dir):
    assert _check(*route_dir) == []


@pytest.mark.parametrize("damage, needle", [
    (lambda p: p.write_bytes(p.read_bytes()[:4000]), "cannot read the dataset"),
    (lambda p: p.write_bytes(b"not a dataset at all\n"), "cannot read the dataset"),
    (lambda p: xr.Dataset({"x": ("a", [1.0])}).to_netcdf(p), "not a jls dataset"),
], ids=["truncated", "garbage", "foreign NetCDF"])
def test_a_corrupt_dataset_is_named(route_dir, damage, needle):
    cfg, base = route_dir
    path = base / "default" / "sea_states.nc"
    damage(path)
    ((route, file, why),) = _check(cfg, base)
    assert route == "default" and file == str(path) and needle in why and "\n" not in why
    with pytest.raises(InputError) as err:
        read(path)
    assert str(path) in str(err.value) and "rebuilds it" in str(err.value)


def test_a_dataset_of_another_configuration_or_layout_is_named(route_dir):
    cfg, base = route_dir
    other = copy.deepcopy(cfg)
    other["sea"]["gamma"] = 2.0
    ((_, _, why),) = problems(other, base, ["default"], screening=False, n_screening_chunks=0,
                              n_response_chunks=1)
    assert "made with another configuration" in why
    sea = read(base / "default" / "sea_states.nc")
    write(sea, base / "default" / "vessel_motion.nc", created_by="test", config_sha256="x")
    found = dict((f, w) for _, f, w in _check(cfg, base))
    assert "does not follow the layout 'vessel_motion'" in found[str(base / "default" / "vessel_motion.nc")]


def test_a_bad_cell_listing_and_a_bad_cell_are_named(route_dir):
    cfg, base = route_dir
    cells = base / "default" / "timedomain"
    cells.mkdir()
    (cells / "cells.json").write_text("[{\"name\": \"baseline__h90__hs1.25__tz7.5\"}]")
    (cells / "baseline__h90__hs1.25__tz7.5.nc").write_bytes(b"\x89HDF\r\n")
    (found,) = _check(cfg, base)
    assert found[1].endswith("baseline__h90__hs1.25__tz7.5.nc") and "cannot read" in found[2]
    (cells / "cells.json").write_text("{not json")
    (found,) = _check(cfg, base)
    assert found[1].endswith("cells.json") and "not the list of time-domain cells" in found[2]


def test_a_rejected_dataset_is_set_aside_not_deleted(route_dir):
    _, base = route_dir
    path = base / "default" / "sea_states.nc"
    data = path.read_bytes()
    moved = Path(set_aside(path))
    assert not path.exists() and moved.name == "sea_states.nc.rejected" and moved.read_bytes() == data


def test_symbolic_links_among_the_outputs_are_found(tmp_path):
    run = tmp_path / "run"
    logs, outside = run / "logs" / "default", tmp_path / "elsewhere"
    logs.mkdir(parents=True)
    outside.mkdir()
    (logs / "plant.log").symlink_to(outside / "victim.txt")
    route = run / "results" / "default"
    route.parent.mkdir()
    route.symlink_to(outside, target_is_directory=True)
    found = symlinks([run / "logs"], inner=[route])
    assert found == sorted([str(logs / "plant.log"), str(route)])
    root = run / "reports"
    root.symlink_to(outside, target_is_directory=True)          # a root may be a link
    assert symlinks([root]) == []


def test_warnings_attribute_round_trip(tmp_path):
    ds = add_warnings(xr.Dataset(attrs={"warnings": "a\nb"}), ["b", "c  d", ""])
    assert warnings_of(ds) == ["a", "b", "c d"] and warnings_of(xr.Dataset()) == []


# --- time-domain verdicts: marginal cells keep the frequency domain's -------------------

def _cell(mpm, slack=(0, 0), duration_s=10800.0, **extra):
    return xr.Dataset({"mpm_sigma": ("tugger", list(mpm)), "slack_events": ("tugger", list(slack)),
                       "limit_fraction": ("tugger", [0.0, 0.0]), **extra},
                      coords={"tugger": ["none", "weak"]},
                      attrs={"candidate": "baseline", "heading_deg": 90.0, "hs_m": 2.5, "tz_s": 7.0,
                             "cell": "baseline__h90__hs2.5__tz7", "duration_s": duration_s,
                             "sway_damping_ratio": 0.0098, "sway_natural_period_s": 15.44})


CELL = dict(candidate="baseline", leg="a", heading=90.0, hs=2.5, tz=7.0)


def test_standard_error_of_the_mpm():
    td = _cell([3.0, 3.0])
    expected = 3.0 / (2 * np.sqrt(0.0098 * 2 * np.pi / 15.44 * 10800))
    np.testing.assert_allclose(mpm_standard_error(td).values, expected)
    assert expected == pytest.approx(0.2286, abs=1e-4)                  # 7.6 % of the MPM
    own = _cell([3.0, 3.0], mpm_sigma_stderr=("tugger", [0.01, 0.02]))
    np.testing.assert_allclose(mpm_standard_error(own).values, [0.01, 0.02])


def test_a_marginal_cell_keeps_the_frequency_domain_verdict_or_fails_if_saturated():
    work, sea = assessed("timedomain")
    work = apply_timedomain(work, sea, [_cell([3.05, 2.95])], assessed_hs(sea))
    assert bool(work["timedomain_marginal"].sel(**CELL, tugger="none"))
    assert bool(work["passes"].sel(**CELL, tugger="none"))            # frequency domain: 2.5 m
    assert int(work["verdict_source"].sel(**CELL, tugger="none")) == FREQUENCY_DOMAIN
    assert not bool(work["passes"].sel(**CELL, tugger="weak"))        # saturates: cannot decide
    assert int(work["verdict_source"].sel(**CELL, tugger="weak")) == SATURATED_FAIL
    assert work.attrs["timedomain_rule"] == TIMEDOMAIN_RULE
    (line,) = warnings_of(work)
    assert "baseline__h90__hs2.5__tz7" in line and "none 3.050 +- 0.232 m" in line


def test_a_decided_cell_takes_the_time_domain_verdict():
    work, sea = assessed("timedomain")
    work = apply_timedomain(work, sea, [_cell([3.5, 2.5])], assessed_hs(sea))
    assert not bool(work["passes"].sel(**CELL, tugger="none"))
    assert bool(work["passes"].sel(**CELL, tugger="weak"))
    assert (work["verdict_source"].sel(**CELL) == TIME_DOMAIN).all()
    assert not work["timedomain_marginal"].any() and warnings_of(work) == []


def test_slack_fails_a_cell_whatever_its_margin_and_short_records_widen_it():
    work, sea = assessed("fail")
    work = apply_timedomain(work, sea, [_cell([2.99, 2.0], slack=(1, 0))], assessed_hs(sea))
    assert not bool(work["passes"].sel(**CELL, tugger="none"))
    assert int(work["verdict_source"].sel(**CELL, tugger="none")) == TIME_DOMAIN
    work, sea = assessed("fail")
    short = apply_timedomain(work, sea, [_cell([2.7, 2.0], duration_s=1800.0)], assessed_hs(sea))
    assert bool(short["timedomain_marginal"].sel(**CELL, tugger="none"))   # 0.5 h: +-0.50 m
    work, sea = assessed("fail")
    long = apply_timedomain(work, sea, [_cell([2.7, 2.0])], assessed_hs(sea))
    assert not bool(long["timedomain_marginal"].sel(**CELL, tugger="none"))  # 3 h: +-0.21 m


def test_a_cell_without_its_sway_mode_is_named():
    work, sea = assessed("fail")
    td = _cell([3.0, 3.0])
    del td.attrs["sway_damping_ratio"]
    one_line_error(lambda: apply_timedomain(work, sea, [td], assessed_hs(sea)),
                   "baseline__h90__hs2.5__tz7", "sway_damping_ratio")


def test_the_cell_names_json_is_what_the_listing_check_reads(tmp_path):
    path = tmp_path / "cells.json"
    path.write_text(json.dumps([{"name": "baseline__h90__hs1.25__tz7.5", "reasons": []}]))
    from jls.config.intermediates import cells_problem
    assert cells_problem(path) == (["baseline__h90__hs1.25__tz7.5"], None)


@pytest.mark.parametrize("name", ["voyage.nc", "verification_study.nc"])
def test_every_route_dataset_is_checked(route_dir, name):
    """The voyage extremes and the study comparison are read by the report too: a damaged
    one is named like the others."""
    cfg, base = route_dir
    path = base / "default" / name
    path.write_bytes(b"not a dataset at all\n")
    ((route, file, why),) = _check(cfg, base)
    assert route == "default" and file == str(path) and "cannot read the dataset" in why


def test_a_legs_own_sea_cell_decides_in_that_leg_only_and_a_jonswap_cell_not_in_it():
    """A cell run on a leg's own sea (attribute sea_leg) decides in that leg; a cell on the
    pipeline's JONSWAP decides in no leg whose sea is its own."""
    own = _cell([3.5, 2.5])
    own.attrs.update(sea_leg="other", cell="baseline__h90__hs2.5__tz7__leg-other")
    work, sea = assessed("timedomain")
    work = apply_timedomain(work, sea, [own], assessed_hs(sea))
    assert (work["verdict_source"].sel(**CELL) != TIME_DOMAIN).all()   # leg a: not its sea
    own.attrs.update(sea_leg="a")
    work, sea = assessed("timedomain")
    work = apply_timedomain(work, sea, [own], assessed_hs(sea))
    assert (work["verdict_source"].sel(**CELL) == TIME_DOMAIN).all()
    work, sea = assessed("timedomain")
    work = apply_timedomain(work, sea, [_cell([3.5, 2.5])], assessed_hs(sea), own_sea_legs=["a"])
    assert (work["verdict_source"].sel(**CELL) != TIME_DOMAIN).all()   # a JONSWAP record
    assert bool(work["passes"].sel(**CELL, tugger="none"))
