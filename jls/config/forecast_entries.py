"""The ``forecast.files`` entries of a configuration (the workflow's pre-transit reports,
``forecasts/<route>/<leg>-<issued>.pdf``): checked when the workflow is parsed and by
``jls check``, and the issue time's tag that names the report."""

from __future__ import annotations

from pathlib import Path

from jls.errors import InputError

__all__ = ["check_forecast_entries", "issued_tag", "utc_time"]


def check_forecast_entries(cfg, base_dir="."):
    """Every ``forecast.files`` entry names a route and leg of the configuration, an
    existing forecast file (relative to ``base_dir``), and issue and start times with their
    UTC offset (checked when the workflow is parsed)."""
    for i, e in enumerate(cfg["forecast"]["files"]):
        key = f"forecast.files[{i}]"
        routes = cfg["routes"]
        if e["route"] not in routes:
            raise InputError(f"no such route (routes: {', '.join(routes)})", field=f"{key}.route", value=e["route"])
        legs = [str(x["name"]) for x in routes[e["route"]]["legs"]]
        if e["leg"] not in legs:
            raise InputError(f"no such leg of route {e['route']} (legs: {', '.join(legs)})", field=f"{key}.leg",
                             value=e["leg"])
        if not (Path(base_dir) / e["file"]).is_file():
            raise InputError("no such forecast file", field=f"{key}.file", value=e["file"])
        utc_time(e["issued"], f"{key}.issued")
        if e.get("start") is not None and utc_time(e["start"], f"{key}.start") < utc_time(e["issued"], key):
            raise InputError("the planned start lies before the forecast's issue time", field=f"{key}.start",
                             value=e["start"])


def issued_tag(text) -> str:
    """The issue time as it names a pre-transit report: 20260105T0000Z (UTC)."""
    return utc_time(text, "forecast.files.issued").strftime("%Y%m%dT%H%MZ")


def utc_time(text, field):
    """``text`` (ISO 8601 with its UTC offset) as a UTC timestamp; without an offset an error."""
    import pandas as pd
    try:
        t = pd.Timestamp(str(text))
    except (ValueError, TypeError):
        raise InputError("not an ISO 8601 time", field=field, value=text) from None
    if t.tzinfo is None:
        raise InputError("a time without its UTC offset (write e.g. 2026-01-05T00:00Z)", field=field, value=text)
    return t.tz_convert("UTC")
