rule plant:
    """Plant (M, K, Kb, C, modes, tensions, feasibility) of every rigging candidate."""
    output:
        f"{RESULTS}/{{route}}/plant.nc",
    params:
        plant={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging", "candidates", "candidate_grid")
               if k in CFG},
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/plant.log",
    benchmark:
        f"{BENCH}/{{route}}/plant.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/plant.py"
