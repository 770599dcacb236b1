"""Time spans stated both by the configuration and by the legs' files, compared before any
job (docs/inputs.md, class d): a scatter table's stated record span against the records
file beside it, the departure months (operation.departure_rule.months) against each leg's
records, and the voyage against the records' common span. Each error names the data file,
the key and both spans; each has a valid opposite that passes."""

from pathlib import Path

import pandas as pd
import pytest

from jls.config.time_spans import _months_in, records_span
from jls.config.workflow_inputs import check_run
from jls.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
SPECTRA = ROOT / "config" / "examples" / "spectra_route.yaml"


def _run(tmp_path, overlay: str, *extra):
    (tmp_path / "my.yaml").write_text(overlay)
    return check_run([ROOT / "config" / "config.yaml", *extra, tmp_path / "my.yaml"], base_dir=ROOT)


def _refused(tmp_path, overlay: str, *extra) -> str:
    with pytest.raises(InputError) as exc:
        _run(tmp_path, overlay, *extra)
    text = str(exc.value)
    assert "\n" not in text
    return text


def test_records_span_of_the_shipped_records():
    first, last, i0, i1 = records_span(ROOT / "config/routes/default/ndbc44007_hourly_hs_tz_1996-2005.txt.gz")
    assert (first, last) == (pd.Timestamp("1996-01-01 00:00", tz="UTC"), pd.Timestamp("2005-12-31 23:00", tz="UTC"))
    assert (i0, i1) == (2, 82806)          # 82805 records after the column-name row
    assert _months_in(first, last) == set(range(1, 13))
    assert _months_in(pd.Timestamp("2019-02-06", tz="UTC"), pd.Timestamp("2019-03-01", tz="UTC")) == {2, 3}
    assert _months_in(pd.Timestamp("2019-11-20", tz="UTC"), pd.Timestamp("2020-01-02", tz="UTC")) == {11, 12, 1}


def test_departure_months_the_records_do_not_hold(tmp_path):
    # the spectra and parameters of NDBC 41010 run 2019-02-06 to 2019-02-10
    text = _refused(tmp_path, "operation:\n  departure_rule:\n    months: [6, 7, 8]\n", SPECTRA)
    assert text.startswith("tests/data/spectra/ndbc_41010_2019/41010w2019part.txt.gz: "
                           "operation.departure_rule.months:")
    assert "route 'buoy_41010', leg 'spectra_leg'" in text
    assert "run 2019-02-06" in text and "months 2," in text and "[6, 7, 8]" in text
    assert "my.yaml" in text                       # where the months are set
    assert "routes.buoy_41010.legs[0].spectra.file" in text and "(got [6, 7, 8])" in text


def test_departure_months_the_records_hold_are_accepted(tmp_path):
    out = _run(tmp_path, "operation:\n  departure_rule:\n    months: [2, 3]\n", SPECTRA)
    assert out["routes"] == {"buoy_41010": 2}
    # the default route's ten years hold every month
    assert _run(tmp_path, "operation:\n  departure_rule:\n    months: [7]\n")["routes"]["default"] == 2


def _hindcast(path, start, hours):
    t = pd.date_range(start, periods=hours, freq="1h")
    path.write_text("time (YYYY-MM-DD-HH); significant wave height (m); zero-up-crossing period (s)\n"
                    + "".join(f"{x:%Y-%m-%d-%H}; 1.0; 6.0\n" for x in t))
    return path


def _two_legs(tmp_path, start2, dur1=10, dur2=10, start1="2019-01-01 00:00", hours=48):
    _hindcast(tmp_path / "a.txt", start1, hours)
    _hindcast(tmp_path / "b.txt", start2, hours)
    edges = "      hs_edges_m: [0, 2, 4]\n      tz_edges_s: [4, 8, 12]\n"
    return ("run_routes: [r]\nroutes:\n  r:\n    legs:\n"
            f"    - name: one\n      duration_h: {dur1}\n      headings_deg: [90]\n"
            f"      hindcast:\n        file: {tmp_path / 'a.txt'}\n  " + edges.replace("\n      ", "\n        ")
            + f"    - name: two\n      duration_h: {dur2}\n      headings_deg: [90]\n"
            f"      hindcast:\n        file: {tmp_path / 'b.txt'}\n  " + edges.replace("\n      ", "\n        "))


def test_voyage_past_the_common_span_of_the_records(tmp_path):
    # leg one's record: 2019-01-01 00:00 to 01-02 23:00; leg two's starts 2019-03-01: no
    # departure has leg two's hours inside its record
    text = _refused(tmp_path, _two_legs(tmp_path, "2019-03-01 00:00"))
    assert "route 'r', leg 'one'" in text and "a.txt: time:" in text
    assert "the voyage (20 h) cannot depart" in text and "ends at 2019-01-02 23:00 UTC" in text
    assert "2019-02-28 14:00 UTC" in text     # the earliest departure leg two allows: 10 h before its start
    assert "routes.r.legs[0].hindcast.file" in text


def test_voyage_within_the_common_span_is_accepted(tmp_path):
    # leg two's record starts 10 h after leg one's: departing at 00:00 the voyage reaches
    # leg two at 10:00, and 38 departures remain
    assert _run(tmp_path, _two_legs(tmp_path, "2019-01-01 10:00"))["routes"] == {"r": 2}


def test_no_departure_in_the_stated_months(tmp_path):
    # both records hold January and February hours, but the departures they allow (from
    # 2019-01-31 14:00 to 2019-01-31 18:00) are all in January
    overlay = _two_legs(tmp_path, "2019-01-31 14:00", start1="2019-01-31 14:00", hours=24)
    text = _refused(tmp_path, overlay + "operation:\n  departure_rule:\n    months: [2]\n")
    assert "operation.departure_rule.months:" in text and "departure rule would sail no voyage" in text
    assert "from 2019-01-31 14:00 UTC to 2019-01-31 18:00 UTC" in text and "(got [2])" in text


def _table(path, first, last, years=None):
    head = "# hs_bins: edges\n# tz_bins: edges\n# values: counts\n"
    head += (f"# first_record: {first}\n# last_record: {last}\n" if first else f"# years: {years}\n")
    path.write_text(head + "hs\\tz,4-8,8-12\n0-2,20,10\n2-4,10,8\n")
    return path


def _table_leg(tmp_path, table):
    _hindcast(tmp_path / "rec.txt", "2019-01-01 00:00", 48)
    return ("run_routes: [t]\nroutes:\n  t:\n    legs:\n    - name: tab\n      duration_h: 10\n"
            f"      headings_deg: [90]\n      scatter: {table}\n      records: {{file: {tmp_path / 'rec.txt'}}}\n")


def test_table_and_records_of_different_periods(tmp_path):
    table = _table(tmp_path / "tab.csv", "1996-01-01 00:00 UTC", "1996-01-02 23:00 UTC")
    text = _refused(tmp_path, _table_leg(tmp_path, table))
    assert text.startswith(f"{tmp_path / 'rec.txt'}: time:")
    assert "route 't', leg 'tab'" in text
    assert "run 1996-01-01 00:00 UTC to 1996-01-02 23:00 UTC (first_record 1996-01-01 00:00 UTC" in text
    assert "records file runs 2019-01-01 00:00 UTC (line 2) to 2019-01-02 23:00 UTC (line 49)" in text
    assert "routes.t.legs[0].records.file" in text
    # a table stating only its years
    table = _table(tmp_path / "tab.csv", None, None, years="1996-2005")
    assert "(years 1996-2005)" in _refused(tmp_path, _table_leg(tmp_path, table))


def test_table_and_records_of_the_same_period_are_accepted(tmp_path):
    table = _table(tmp_path / "tab.csv", "2019-01-01 00:00 UTC", "2019-01-02 23:00 UTC")
    assert _run(tmp_path, _table_leg(tmp_path, table))["routes"] == {"t": 1}
    # the shipped route: tables and records both 1996-2005 (leg 2 from 01:00)
    assert _run(tmp_path, "run_routes: [default]\n")["routes"] == {"default": 2}


# --- a forecast entry's start and issue time against the forecast file's hours -----------

def _forecast_cfg(tmp_path, **entry):
    rows = [f"{t:%Y-%m-%dT%H:%MZ},0.3,5.0,200.0,0.5,12.0,200.0"
            for t in pd.date_range("2026-01-05 00:00", periods=24, freq="h")]
    (tmp_path / "fc.csv").write_text("time,hs_wind,tp_wind,dir_wind,hs_swell,tp_swell,dir_swell\n"
                                     + "\n".join(rows) + "\n")
    e = {"route": "r", "leg": "one", "file": "fc.csv", "format": "partitions-csv",
         "issued": "2026-01-05T00:00Z", **entry}
    return {"routes": {"r": {"legs": [{"name": "one"}]}}, "sea": {"gamma": 3.3},
            "forecast": {"files": [e]}}


def test_forecast_start_outside_the_forecast_file(tmp_path):
    from jls.config.forecast_entries import check_forecast_entries
    cfg = _forecast_cfg(tmp_path, start="2026-01-07T00:00Z")
    with pytest.raises(InputError) as exc:
        check_forecast_entries(cfg, tmp_path)
    text = str(exc.value)
    assert text.startswith("fc.csv: forecast.files[0].start: the planned start 2026-01-07T00:00:00+00:00")
    assert "the file's hours run 2026-01-05T00:00:00+00:00 to 2026-01-05T23:00:00+00:00" in text
    assert "(got '2026-01-07T00:00Z')" in text
    # issued after the file's first hour, with no start: the check would start before the issue
    cfg = _forecast_cfg(tmp_path, issued="2026-01-05T06:00Z")
    with pytest.raises(InputError, match=r"^fc.csv: forecast.files\[0\].issued: the forecast is said to "
                                         r"be issued at 2026-01-05T06:00:00\+00:00, after its own first hour"):
        check_forecast_entries(cfg, tmp_path)


def test_forecast_start_within_the_forecast_file_is_accepted(tmp_path):
    from jls.config.forecast_entries import check_forecast_entries
    check_forecast_entries(_forecast_cfg(tmp_path, start="2026-01-05T23:00Z"), tmp_path)
    check_forecast_entries(_forecast_cfg(tmp_path, issued="2026-01-04T12:00+00:00"), tmp_path)
    check_forecast_entries(_forecast_cfg(tmp_path, issued="2026-01-05T06:00Z", start="2026-01-05T06:00Z"),
                           tmp_path)
