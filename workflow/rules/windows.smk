# Weather windows of the legs given by an hourly hindcast: how often a workable window of
# the leg's duration opens, per calendar month (docs/reference/outputs.md, "weather_windows.nc").


rule weather_windows:
    """Hourly workable flag and window probability per leg and month for every option, and
    for the assessed option (the report's recommendation) in the layout of docs/reference/outputs.md."""
    input:
        operability=f"{RESULTS}/{{route}}/operability.nc",
        workability=f"{RESULTS}/{{route}}/workability.nc",
        plant=ASSESSED_PLANT,
        hindcasts=lambda w: [f for leg in hindcast_legs(w.route) for f in leg_files(leg)],
        measured=measured_file,
    output:
        f"{RESULTS}/{{route}}/weather_windows.nc",
    params:
        legs=lambda w: hindcast_legs(w.route),
        criteria=CFG["assessment"]["criteria"],
        gamma=GAMMA,
        tuggers=TUGGERS,
        windows=CFG["weather_windows"],
        operation=CFG["operation"],
        route_legs=lambda w: CFG["routes"][w.route]["legs"],
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/weather_windows.log",
    benchmark:
        f"{BENCH}/{{route}}/weather_windows.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/weather_windows.py"
