# Go or no-go on a forecast (jls forecast): forecasts/<route>/<leg>-<issued>.pdf and .json
# for each entry of forecast.files; rebuilt when the forecast file or the route's assessed
# plant changes (docs/forecast.md).

rule forecast:
    """Go or no-go per option on the forecast of a leg: the pre-transit report."""
    input:
        forecast=lambda w: forecast_entry(w)["file"],
        plant=ASSESSED_PLANT,
        rao=RAO_FILE,
    output:
        pdf=f"{FORECASTS}/{{route}}/{{leg}}-{{issued}}.pdf",
        json=f"{FORECASTS}/{{route}}/{{leg}}-{{issued}}.json",
    wildcard_constraints:
        issued="[0-9]{8}T[0-9]{4}Z",
    params:
        entry=forecast_entry,
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/forecast-{{leg}}-{{issued}}.log",
    benchmark:
        f"{BENCH}/{{route}}/forecast-{{leg}}-{{issued}}.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/forecast.py"
