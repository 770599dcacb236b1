"""Snakemake adapter: a forecast file + the route's assessed plant -> the pre-transit
report forecasts/<route>/<leg>-<issued>.pdf and its answer as JSON beside it.

Inputs:   the forecast file of the forecast.files entry, the assessed plant of the route
Outputs:  forecasts/<route>/<leg>-<issued>.pdf and .json
Settings: forecast (alpha_factors, files), sea (gamma, spreading), assessment (criteria,
          exposure), the route's leg (duration, contingency, course), the vessel

Run by hand for debugging: python workflow/scripts/forecast.py route=NAME leg=LEG issued=TAG [--configfile FILE ...]
"""

import json

import _job  # noqa: F401  (before numpy, xarray and jls: see there)

from jls.commands.common import json_default
from jls.commands.forecast import forecast_answer
from jls.io.atomic import write_atomically
from jls.io.netcdf import read
from jls.io.provenance import workflow_step
from jls.report.forecast import write_pdf

if "snakemake" not in globals():              # run by hand, see workflow/scripts/_debug.py
    from _debug import snakemake_for
    snakemake = snakemake_for("forecast")
sm = snakemake
with workflow_step(sm.log[0], "forecast") as log:
    e = sm.params.entry
    ds, out = forecast_answer(sm.config, ".", sm.input.forecast, e["format"], e["route"], e["leg"],
                              start=e.get("start"), issued=e["issued"], course=e.get("course_deg"),
                              plant=read(sm.input.plant), plant_source=sm.input.plant)

    def _json(tmp):
        with open(tmp, "w") as f:
            f.write(json.dumps(out, default=json_default))

    write_atomically(sm.output.json, _json, suffix=".json")
    write_pdf(ds, out, sm.output.pdf)
    for c, per in out["options"].items():
        for t, o in per.items():
            log.info("%s / %s: %s, first start %s", c, t, "GO" if o["go"] else "NO-GO", o["first_start"])
