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
        tuggers={t["name"]: t["c_kN_s_per_m"] for t in CFG.get("tuggers", [{"name": "none", "c_kN_s_per_m": 0.0}])},
        assessment={k: v for k, v in CFG.get("assessment", {}).items() if k != "criteria"},
        response=CFG.get("response", {}),
        outside=CFG.get("vessel", {}).get("outside_rao_range", "error"),
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
