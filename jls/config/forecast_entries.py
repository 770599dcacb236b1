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
    UTC offset, the start within the file's hours and the issue time not after it
    (checked when the workflow is parsed)."""
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
        _check_span(cfg, e, key, base_dir)


def _check_span(cfg, e, key, base_dir):
    """The entry's start (absent: the forecast's first hour) within the forecast file's
    hours, and its issue time not after that start: the forecast job refused both after
    the route's datasets were written, naming the command's --start and --issued."""
    from jls.sea.forecast import read_forecast
    gamma = {"wind": float(cfg["sea"]["gamma"]), "swell": float(cfg["sea"]["gamma"])}
    try:
        fc = read_forecast(Path(base_dir) / e["file"], e["format"], gamma=gamma)
    except InputError as exc:
        raise InputError(f"{exc.message} (the forecast file given by {key}.file)", file=exc.file,
                         field=exc.field, value=exc.value) from None
    first, last = fc.times[0], fc.times[-1]
    span = f"the file's hours run {first.isoformat()} to {last.isoformat()}"
    if e.get("start") is not None:
        start = utc_time(e["start"], f"{key}.start")
        if start < first or start > last:
            raise InputError(f"the planned start {start.isoformat()} lies outside the forecast "
                             f"{e['file']}: {span}", file=e["file"], field=f"{key}.start", value=e["start"])
        return
    issued = utc_time(e["issued"], f"{key}.issued")
    if issued > first:
        raise InputError(f"the forecast is said to be issued at {issued.isoformat()}, after its own "
                         f"first hour: {span}, and without {key}.start the check starts at the first "
                         "hour; give the issue time of the file, or a start after it", file=e["file"],
                         field=f"{key}.issued", value=e["issued"])


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
