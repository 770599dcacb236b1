# Weather windows of the legs given by an hourly hindcast: how often a workable window of
# the leg's duration opens, per calendar month (README, "Weather windows").


def hindcast_legs(route):
    """The legs of ``route`` given by an hourly hindcast."""
    return [leg for leg in route_legs(route) if "hindcast" in leg]


def windows_file(wildcards):
    """The route's weather-window file when it has a hindcast leg, else nothing."""
    return [f"results/{wildcards.route}/weather_windows.nc"] if hindcast_legs(wildcards.route) else []


rule weather_windows:
    """Hourly workable flag and window probability per leg and month for every option, and
    for the assessed option (best feasible by route workability) in the README's layout."""
    input:
        operability="results/{route}/operability.nc",
        workability="results/{route}/workability.nc",
        plant="results/{route}/plant.nc",
        hindcasts=lambda w: [leg["hindcast"]["file"] for leg in hindcast_legs(w.route)],
    output:
        "results/{route}/weather_windows.nc",
    params:
        legs=lambda w: hindcast_legs(w.route),
        criteria=CFG["assessment"]["criteria"],
        tuggers=TUGGERS,
        windows=CFG["weather_windows"],
    log:
        "logs/{route}/weather_windows.log",
    benchmark:
        "benchmarks/out/{route}/weather_windows.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/weather_windows.py"
