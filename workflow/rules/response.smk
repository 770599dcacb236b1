rule response:
    """Unit-Hs response statistics for one leg's set of (Tz, heading). The key in the
    file name changes only when that set changes, so editing probabilities reruns none."""
    input:
        plant="results/{route}/plant.nc",
        motion="results/{route}/vessel_motion.nc",
    output:
        "results/{route}/response/{leg}-{key}.nc",
    params:
        cells=leg_cells,
        tuggers=TUGGERS,
        assessment={k: v for k, v in CFG["assessment"].items() if k != "criteria"},
        response=CFG["response"],
        outside=CFG["vessel"].get("outside_rao_range"),
    log:
        "logs/{route}/response/{leg}-{key}.log",
    benchmark:
        "benchmarks/out/{route}/response/{leg}-{key}.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/response.py"


rule merge_response:
    """All legs' unit-Hs statistics of a route in one dataset."""
    input:
        response_files,
    output:
        "results/{route}/response.nc",
    log:
        "logs/{route}/merge_response.log",
    benchmark:
        "benchmarks/out/{route}/merge_response.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/merge_response.py"


rule operability:
    """Unit-Hs statistics on a fine Tz grid for the operability curves; depends on the
    plant and the vessel only, so no leg edit reruns it."""
    input:
        plant="results/{route}/plant.nc",
        motion="results/{route}/vessel_motion.nc",
    output:
        "results/{route}/operability.nc",
    params:
        tz=OPERABILITY_TZ,
        headings=lambda w: route_headings(w.route),
        gamma=GAMMA,
        tuggers=TUGGERS,
        assessment={k: v for k, v in CFG["assessment"].items() if k != "criteria"},
        response=CFG["response"],
        outside=CFG["vessel"].get("outside_rao_range"),
    log:
        "logs/{route}/operability.log",
    benchmark:
        "benchmarks/out/{route}/operability.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/operability.py"
