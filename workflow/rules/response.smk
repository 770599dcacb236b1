rule response_chunk:
    """Unit-Hs spectral moments of one chunk of candidates (response.chunk_candidates) for
    every sea state the route needs; sea states already in the cache are read, not
    evaluated. Runs only when the candidates are split into several chunks."""
    input:
        plant=ASSESSED_PLANT,
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
    output:
        temp(f"{RESULTS}/{{route}}/response/chunk-{{chunk}}.nc"),
    params:
        states=lambda w: ROUTE_STATES[w.route],
        tuggers=TUGGERS,
        response=RESPONSE,
        chunk=CHUNK,
        cache=SEA_STATE_CACHE,
    threads: 2  # solver threads of a chunk of many candidates (a cluster job: its CPUs)
    resources:
        **job_resources(CHUNK),
    log:
        f"{LOGS}/{{route}}/response/chunk-{{chunk}}.log",
    benchmark:
        f"{BENCH}/{{route}}/response/chunk-{{chunk}}.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/response_chunk.py"


rule response:
    """Unit-Hs statistics of every candidate on the legs' Tz values (response.nc) and on
    the operability grid (operability.nc), from one response computation per route: the
    legs and the operability curves share it, and each sea state (Tz, heading, gamma) is
    evaluated once (results/cache/sea_states). The parameters change only when the set
    of sea states does, so editing probabilities reruns no response job."""
    input:
        plant=ASSESSED_PLANT,
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        chunks=response_chunks,
    output:
        response=f"{RESULTS}/{{route}}/response.nc",
        operability=f"{RESULTS}/{{route}}/operability.nc",
    params:
        states=lambda w: ROUTE_STATES[w.route],
        tuggers=TUGGERS,
        shown=SHOWN_CANDIDATES,
        tensions_all=needs_tensions(),
        assessment={k: v for k, v in CFG["assessment"].items() if k != "criteria"},
        response=RESPONSE,
        tip=TIP,
        g=CFG["g_m_per_s2"],
        outside=OUTSIDE_RAO_RANGE,
        cache=SEA_STATE_CACHE,
    threads: solver_threads(len(CANDIDATES))  # see common.smk
    resources:
        **job_resources(len(CANDIDATES), runtime=30),
    log:
        f"{LOGS}/{{route}}/response.log",
    benchmark:
        f"{BENCH}/{{route}}/response.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/response.py"
