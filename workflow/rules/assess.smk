rule workability:
    """MPM per cell, pass/fail, workability per leg and route, limiting Hs(Tz); uncertainty
    bands over the plant variants and Hs choices; route workability against the sway limit;
    winch saturation flags and the time-domain verdicts where cells ran."""
    input:
        sea="results/{route}/sea_states.nc",
        response="results/{route}/response.nc",
        curve="results/{route}/operability.nc",
        variants="results/{route}/response_variants.nc",
        timedomain=timedomain_files,
    output:
        "results/{route}/workability.nc",
    params:
        criteria=CFG["assessment"]["criteria"],
        sea=SEA,
        tuggers=CFG["tuggers"],
        winch_saturation=CFG["assessment"]["winch_saturation"],
        max_saturation_fraction=CFG["assessment"]["max_saturation_fraction"],
    log:
        "logs/{route}/workability.log",
    benchmark:
        "benchmarks/out/{route}/workability.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/workability.py"
