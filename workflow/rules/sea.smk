rule sea_states:
    """Per-leg Hs-Tz scatter of a route with steepness flags and leg weights."""
    input:
        route_files,
    output:
        f"{RESULTS}/{{route}}/sea_states.nc",
    params:
        route=lambda w: CFG["routes"][w.route],
        sea=SEA,
        g=CFG["g_m_per_s2"],
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/sea_states.log",
    benchmark:
        f"{BENCH}/{{route}}/sea_states.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/sea_states.py"
