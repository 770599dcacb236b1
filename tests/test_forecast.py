"""``jls forecast``: go or no-go on an hourly partitioned forecast.

The decision logic on utilisations known by hand (calm: go now; a storm inside the leg:
first start after it and its contingency; a forecast too short: no-go with that reason);
the physics end to end on the shipped plant (calm forecast: go for every option; a storm
at hour 30 of the 50-h leg: no-go now, first start once the storm has passed the leg's
window; a swell from the beam failing the limit while the total Hs stays low); lead-time
alpha as tabulated; the contract (an hour's utilisation is ``jls response`` for the hour's
systems over the limit, over alpha); and every bad forecast refused with file, column and
value."""

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from jls.assessment.go_no_go import LeadTimeAlpha, decide, window_hours
from jls.cli import main
from jls.commands.forecast import forecast_answer
from jls.errors import InputError
from jls.sea.forecast import read_forecast

HEADER = "time,hs_wind,tp_wind,dir_wind,hs_swell,tp_swell,dir_swell"
GAMMA = {"wind": 3.3, "swell": 3.3}
START = "2026-01-05T00:00Z"


def _write(path, rows, header=HEADER, comments=()):
    path.write_text("\n".join([*comments, header, *rows]) + "\n")
    return path


def _forecast(path, hours, wind=(0.3, 5.0, 200.0), swell=(0.0, 12.0, 200.0), storm=None):
    """An hourly forecast from START; ``storm``: (first hour, last hour, (hs, tp, dir)) of
    the swell system."""
    t = pd.date_range(START, periods=hours, freq="h")
    rows = []
    for k, ti in enumerate(t):
        s = storm[2] if storm and storm[0] <= k <= storm[1] else swell
        rows.append(f"{ti.strftime('%Y-%m-%dT%H:%MZ')},{wind[0]},{wind[1]},{wind[2]},{s[0]},{s[1]},{s[2]}")
    return _write(path, rows)


# -- the decision on utilisations known by hand ----------------------------------------

def test_window_is_duration_plus_contingency_in_whole_hours():
    assert window_hours(50, 0) == 50
    assert window_hours(50, 12) == 62
    assert window_hours(49.5, 0) == 50


def test_calm_goes_now_and_a_storm_moves_the_first_start_past_it():
    n, L = 200, 62
    u = np.full((2, n), 0.4)
    u[1, 30:40] = 1.3                      # a storm at hours 30-39 for the second option
    d = decide(u, u[..., None], ["relative_sway_m"], 0, L)
    assert d[0].go and d[0].first_start == 0 and d[0].governing == ("relative_sway_m", 0)
    assert d[0].margin == pytest.approx(0.6)
    assert not d[1].go and d[1].first_start == 40          # the first hour after the storm
    assert d[1].governing == ("relative_sway_m", 30)
    assert "hour 30" in d[1].reason


def test_a_forecast_shorter_than_the_leg_is_never_a_go():
    u = np.full((1, 40), 0.1)
    d = decide(u, u[..., None], ["relative_sway_m"], 0, 50, uncovered_reason="the forecast ends first")
    assert not d[0].go and d[0].first_start is None and d[0].governing is None
    assert d[0].reason == "the forecast ends first"


def test_an_hour_beyond_the_alpha_table_is_not_inside():
    u = np.full((1, 100), 0.1)
    u[0, 70:] = np.nan
    d = decide(u, u[..., None], ["relative_sway_m"], 0, 50)
    assert d[0].go                                          # hours 0-49 are covered
    d = decide(u, u[..., None], ["relative_sway_m"], 30, 50)
    assert not d[0].go and d[0].first_start is None


def test_lead_time_alpha_as_tabulated():
    a = LeadTimeAlpha("DNV-ST-N001 (2021) table 4-3, level B (as an example of form)",
                      [12, 24, 48], [1.0, 4.0], [[0.9, 0.8], [0.8, 0.7], [0.7, 0.6]])
    lead = np.array([0, 12, 12.5, 24, 30, 48, 49])
    assert a(lead, 1.0).tolist()[:6] == [0.9, 0.9, 0.8, 0.8, 0.7, 0.7]
    assert np.isnan(a(lead, 1.0)[6])                         # beyond the table
    assert a(np.array([20.0]), 2.5)[0] == pytest.approx(0.75)       # linear in Hs
    assert a(np.array([20.0]), 9.0)[0] == pytest.approx(0.7)        # held at the end
    with pytest.raises(InputError, match="alpha"):
        LeadTimeAlpha("x", [12, 24], [1.0], [[0.9], [1.2]])


# -- the physics end to end on the shipped plant ----------------------------------------

def _answer(cfg, path, **kw):
    kw.setdefault("course", 200.0)
    return forecast_answer(cfg, ".", str(path), "partitions-csv", "default", "gulf_of_maine",
                           start=kw.pop("start", START), results="no-results", **kw)


@pytest.fixture(scope="module")
def storm_answer(cfg, tmp_path_factory):
    # swell from 290 deg true meets the vessel on 200 deg on the beam (relative 90 deg)
    path = _forecast(tmp_path_factory.mktemp("fc") / "storm.csv", 130, storm=(30, 44, (3.0, 15.0, 290.0)))
    return _answer(cfg, path)


def test_a_calm_forecast_is_go_now_for_every_option(cfg, tmp_path):
    _, out = _answer(cfg, _forecast(tmp_path / "calm.csv", 60, wind=(0.2, 4.0, 290.0)))
    for per in out["options"].values():
        for o in per.values():
            assert o["go"] and o["first_start"] == "2026-01-05T00:00:00Z", o
            assert 0 < o["margin"] <= 1


def test_a_storm_at_hour_30_of_a_50_h_leg_is_no_go_until_it_has_passed(storm_answer):
    ds, out = storm_answer
    o = out["options"]["baseline"]["none"]
    assert not o["go"]
    assert o["governing"]["criterion"] == "relative_sway_m"
    assert 30 <= o["governing"]["hour_index"] <= 44
    # the first start is the hour after the storm's last failing hour
    u = np.array([h["utilisation"] for h in o["hourly"]])
    last_bad = int(np.flatnonzero(u > 1)[-1])
    assert o["first_start"] == f"{(pd.Timestamp(START) + pd.Timedelta(hours=last_bad + 1)).isoformat()}".replace("+00:00", "Z")
    assert len(o["hourly"]) == 130
    assert out["window_h"] == 50 and out["contingency_h"] == 0


def test_a_beam_swell_fails_while_the_total_hs_stays_low(cfg, tmp_path):
    # 0.3 m of 16-s swell from the beam and 0.3 m of wind sea from ahead: Hs 0.42 m in all
    path = _forecast(tmp_path / "swell.csv", 60, swell=(0.3, 16.0, 290.0))
    ds, out = _answer(cfg, path)
    assert float(ds["hs_total"].max()) < 0.45
    assert not out["options"]["baseline"]["none"]["go"]
    same_from_ahead = _forecast(tmp_path / "ahead.csv", 60, swell=(0.3, 16.0, 200.0))
    _, ahead = _answer(cfg, same_from_ahead)
    u_beam = out["options"]["baseline"]["none"]["hourly"][0]["utilisation"]
    u_head = ahead["options"]["baseline"]["none"]["hourly"][0]["utilisation"]
    assert u_beam > 1 > u_head                     # the direction decides, not the height


def test_hourly_utilisation_is_jls_response_over_the_limit_over_alpha(cfg, tmp_path, capsys):
    cfg = {**cfg, "forecast": {"files": [], "alpha_factors": {
        "source": "test table", "lead_time_h": [24, 96], "hs_m": [1.0, 3.0], "alpha": [[0.9, 0.8], [0.7, 0.6]]}}}
    path = _forecast(tmp_path / "fc.csv", 60, wind=(0.8, 6.0, 150.0), swell=(0.6, 13.0, 260.0))
    ds, out = _answer(cfg, path)
    k = 30                                                   # lead time 30 h: the second row
    hour = out["options"]["detuned"]["low"]["hourly"][k]
    args = [f"--system={s['hs']},{s['tp']},{s['dir_from']},{s['gamma']},{s['spreading']}" for s in hour["systems"]]
    assert main(["response", *args, "--vessel-heading", "200", "--json"]) == 0
    resp = json.loads(capsys.readouterr().out)["candidates"]["detuned"]["low"]
    hs = float(np.hypot(0.8, 0.6))
    alpha = float(np.interp(hs, [1.0, 3.0], [0.7, 0.6]))
    assert hour["alpha"] == pytest.approx(alpha)
    motions = [c for c in cfg["assessment"]["criteria"] if c in resp]
    assert motions
    for c in motions:                         # each motion criterion: jls response's MPM over the limit over alpha
        got = float(ds["criterion_utilisation"].sel(criterion=c, candidate="detuned", tugger="low")[k])
        assert got == pytest.approx(resp[c]["mpm"] / cfg["assessment"]["criteria"][c] / alpha, rel=1e-9)
    # the hour's utilisation: the largest over every criterion evaluated (tip and wires too)
    every = ds["criterion_utilisation"].sel(candidate="detuned", tugger="low")[k]
    assert set(every["criterion"].values) >= {*motions, "tip_air_gap_m", "wire_tension"}
    assert hour["utilisation"] == pytest.approx(float(every.max()), rel=1e-12)
    assert out["alpha_source"] == "test table"


def test_the_command_line_contract(tmp_path, capsys):
    path = _forecast(tmp_path / "fc.csv", 60)
    assert main(["forecast", str(path), "--format", "partitions-csv", "--route", "default", "--leg",
                 "gulf_of_maine", "--start", START, "--course", "200", "--results", str(tmp_path),
                 "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    o = out["options"]["baseline"]["none"]
    assert isinstance(o["go"], bool)
    assert o["first_start"] is None or isinstance(o["first_start"], str)
    assert set(o["governing"]) >= {"criterion", "hour"}
    assert len(o["hourly"]) == 60
    h = o["hourly"][0]
    assert set(h) >= {"time", "utilisation", "systems"}
    assert set(h["systems"][0]) >= {"hs", "tp", "dir_from", "gamma", "spreading"}


# -- bad forecasts ---------------------------------------------------------------------

def _rows(n=5, fmt="{t},1,6,200,0.5,12,250", start=START):
    return [fmt.format(t=ti.strftime("%Y-%m-%dT%H:%MZ")) for ti in pd.date_range(start, periods=n, freq="h")]


@pytest.mark.parametrize("rows,field,value", [
    (lambda r: r[:2] + r[3:], "line 4, column time", "missing hour"),
    (lambda r: r[:3] + [r[2]] + r[3:], "line 5", "not strictly increasing"),
    (lambda r: [r[0].replace("00:00Z", "00:00")] + r[1:], "line 2, column time", "UTC offset"),
])
def test_bad_hours_are_refused_with_line_and_value(tmp_path, rows, field, value):
    path = _write(tmp_path / "bad.csv", rows(_rows()))
    with pytest.raises(InputError) as err:
        read_forecast(path, "partitions-csv", gamma=GAMMA)
    assert str(path) in str(err.value) and field in str(err.value) and value in str(err.value)


def test_directions_in_radians_are_refused(tmp_path):
    path = _write(tmp_path / "rad.csv", _rows(fmt="{t},1,6,3.49,0.5,12,4.36"))
    with pytest.raises(InputError, match="radians") as err:
        read_forecast(path, "partitions-csv", gamma=GAMMA)
    assert "dir_wind" in str(err.value) and "3.49" in str(err.value)


def test_going_to_and_other_periods_are_refused(tmp_path):
    path = _write(tmp_path / "to.csv", _rows(), comments=["# direction: to"])
    with pytest.raises(InputError, match="come FROM") as err:
        read_forecast(path, "partitions-csv", gamma=GAMMA)
    assert "line 1" in str(err.value) and "'to'" in str(err.value)
    path = _write(tmp_path / "tz.csv", _rows(), header=HEADER.replace("tp_swell", "tz_swell"))
    with pytest.raises(InputError, match="peak period tp_swell") as err:
        read_forecast(path, "partitions-csv", gamma=GAMMA)
    assert "tz_swell" in str(err.value)
    path = _write(tmp_path / "tm.csv", _rows(), comments=["# period: tm01"])
    with pytest.raises(InputError, match="peak period"):
        read_forecast(path, "partitions-csv", gamma=GAMMA)


def test_a_local_time_converts_and_a_missing_column_is_named(tmp_path):
    rows = [r.replace("Z,", "+01:00,", 1) for r in _rows()]
    fc = read_forecast(_write(tmp_path / "cet.csv", rows), "partitions-csv", gamma=GAMMA)
    assert fc.times[0] == pd.Timestamp("2026-01-04T23:00Z")
    path = _write(tmp_path / "miss.csv", [r.rsplit(",", 1)[0] for r in _rows()], header=HEADER.rsplit(",", 1)[0])
    with pytest.raises(InputError, match="missing partition column.s. dir_swell"):
        read_forecast(path, "partitions-csv", gamma=GAMMA)


def test_a_start_outside_the_forecast_is_refused(cfg, tmp_path):
    path = _forecast(tmp_path / "fc.csv", 10)
    with pytest.raises(InputError, match="outside the forecast"):
        _answer(cfg, path, start="2026-02-01T00:00Z")


def test_a_forecast_that_ends_inside_the_leg_is_no_go_with_the_reason(cfg, tmp_path):
    _, out = _answer(cfg, _forecast(tmp_path / "short.csv", 30, wind=(0.2, 4.0, 290.0)))
    for per in out["options"].values():
        for o in per.values():
            assert not o["go"] and o["first_start"] is None and "forecast ends" in o["reason"]


# -- the pre-transit report and the workflow's rule --------------------------------------

def test_the_pdf_says_no_go_and_names_what_it_did_not_evaluate(storm_answer, tmp_path):
    import pypdf

    from jls.report.forecast import write_pdf
    ds, out = storm_answer
    pdf = write_pdf(ds, out, tmp_path / "f.pdf")
    text = pypdf.PdfReader(pdf).pages[0].extract_text()
    assert "NO-GO" in text
    assert out["options"]["baseline"]["none"]["go"] is False
    assert all(c in text for c in out["criteria_not_evaluated"])          # none by default
    m = out["options"]["detuned"]["high"]["margin"]
    if m is not None:
        assert f"{100 * m:.0f} %" in text


@pytest.mark.slow
def test_the_rule_writes_the_pre_transit_report_and_reruns_only_on_a_new_forecast(tmp_path):
    import yaml
    from test_pipeline import make_workdir, planned_outputs, snakemake, tiny_config
    cfg = tiny_config(tmp_path)
    cfg.pop("verification")
    cfg["forecast"] = {"files": [{"route": "tiny", "leg": "north", "file": "fc.csv", "issued": "2026-01-05T00:00Z",
                                  "course_deg": 200}]}
    work = make_workdir(tmp_path, cfg)
    _forecast(work / "fc.csv", 60)
    target = "forecasts/tiny/north-20260105T0000Z.pdf"
    r = snakemake(work, target)
    assert r.returncode == 0, r.stderr[-3000:]
    answer = json.loads((work / target).with_suffix(".json").read_text())
    assert answer["options_from"].startswith("the route's assessed plant")
    assert answer["window_h"] == 30 and set(answer["options"]) == {"baseline", "detuned"}
    assert planned_outputs(work, target) == []
    _forecast(work / "fc.csv", 60, swell=(0.5, 15.0, 290.0))
    assert {p for p in planned_outputs(work, target)} == {target, target.replace(".pdf", ".json")}
    # a bad entry is refused when the workflow is parsed, naming the key
    cfg["forecast"]["files"][0]["leg"] = "nowhere"
    (work / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
    r = snakemake(work, "-n", target)
    text = r.stdout + r.stderr
    assert r.returncode != 0 and "forecast.files[0].leg" in text and "nowhere" in text


def test_a_directional_spectra_forecast_meets_the_same_sea_given_as_partitions(cfg, tmp_path):
    pytest.importorskip("wavespectra", reason="the optional extra [spectra] (wavespectra) is not installed")
    from sea_fixtures import ww3_spectra

    from jls.sea.sea_state import WaveSystem, parse_spreading
    swell = WaveSystem("jonswap", 0.4, 15.0, 290.0, parse_spreading("cos2s:13"), "swell", 3.3)
    freq = 0.03 * 1.03 ** np.arange(100)                       # 0.03-0.56 Hz
    dirs_from = np.arange(0.0, 360.0, 5.0)
    w = swell.spreading.density(dirs_from - 290.0)
    D = w / w.sum() / np.radians(5.0)                          # per radian, sums to 1 on the grid
    efth = 2 * np.pi * swell.spectrum(2 * np.pi * freq)[:, None] * D[None, :]          # m2 s rad-1 (per Hz)
    hours = 60
    path = ww3_spectra(tmp_path / "ww3.nc", freq, np.mod(dirs_from + 180.0, 360.0),
                       np.repeat(efth[None], hours, axis=0))
    ds, out = forecast_answer(cfg, ".", str(path), "spectra", "default", "gulf_of_maine", course=200.0,
                              results="no-results", spectra_format="ww3")
    assert float(ds["hs_total"][0]) == pytest.approx(0.4, rel=0.02)
    csv = _forecast(tmp_path / "same.csv", hours, wind=(0.0, 5.0, 200.0), swell=(0.4, 15.0, 290.0))
    start = str(ds["time"].values[0])[:16] + "Z"
    _, parts = forecast_answer(cfg, ".", str(csv), "partitions-csv", "default", "gulf_of_maine", course=200.0,
                               start=START, results="no-results")
    for c in ("baseline", "detuned"):
        u_spec = out["options"][c]["none"]["hourly"][0]["utilisation"]
        u_part = parts["options"][c]["none"]["hourly"][0]["utilisation"]
        assert u_spec == pytest.approx(u_part, rel=0.03), (c, start)
    assert out["options"]["baseline"]["none"]["hourly"][0]["systems"][0]["kind"] == "spectrum"
    # an NDBC density file without its direction files is a spectrum without directions
    import shutil
    one_d = shutil.copy(Path(__file__).parent / "data/spectra/ndbc_41010_2019/41010w2019part.txt.gz", tmp_path)
    with pytest.raises(InputError, match="without directions|whole hours"):
        read_forecast(one_d, "spectra", gamma=GAMMA, spectra_format="ndbc")


def test_the_readmes_forecast_command_runs_on_the_shipped_example(tmp_path, capsys):
    import re
    root = Path(__file__).resolve().parents[1]
    text = (root / "README.md").read_text()
    m = re.search(r"\.venv/bin/jls forecast (.+?)\n```", text, re.S)
    args = m.group(1).replace("\\\n", " ").split()
    args[args.index("--pdf") + 1] = str(tmp_path / "go.pdf")
    assert main(["forecast", *args, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert (tmp_path / "go.pdf").stat().st_size > 0
    # the example's storm makes some options wait and others go
    go = [o["go"] for per in out["options"].values() for o in per.values()]
    assert any(go) and not all(go)


def test_the_contract_command_without_a_course_meets_each_hours_largest_system_at_the_legs_heading(
        tmp_path, capsys, cfg):
    # the shipped leg gives relative headings (beam seas), no course: each hour's largest
    # system is met at 90 deg, and an hour equals jls response at that hour's course
    path = _forecast(tmp_path / "fc.csv", 60, wind=(0.8, 6.0, 150.0), swell=(0.4, 14.0, 260.0))
    assert main(["forecast", str(path), "--format", "partitions-csv", "--route", "default", "--leg",
                 "gulf_of_maine", "--start", START, "--results", str(tmp_path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert "relative heading 90 deg" in out["heading_basis"]
    hour = out["options"]["baseline"]["none"]["hourly"][5]
    assert hour["course_deg"] == pytest.approx((90.0 + 150.0 - 180.0) % 360.0)     # the wind sea is larger
    args = [f"--system={s['hs']},{s['tp']},{s['dir_from']},{s['gamma']},{s['spreading']}" for s in hour["systems"]]
    assert main(["response", *args, "--vessel-heading", str(hour["course_deg"]), "--json"]) == 0
    resp = json.loads(capsys.readouterr().out)["candidates"]["baseline"]["none"]
    motions = max(resp[c]["mpm"] / lim for c, lim in cfg["assessment"]["criteria"].items() if c in resp)
    assert hour["utilisation"] >= motions * (1 - 1e-9)          # the largest over every criterion
