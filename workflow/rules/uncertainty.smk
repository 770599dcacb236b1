# Uncertainty bands (section 3.5 of the study): the plant's damping (0.5x-2x nominal) and
# sway frequency (+/- 3 %) as extra candidates of one response computation per route.


#: Up to this many candidates every one is varied; beyond (a screening grid) only the shown
#: candidates (baseline and named), so the variants never multiply a grid's cost by nine.
MAX_BAND_CANDIDATES = 64
BAND_CANDIDATES = CANDIDATES if len(CANDIDATES) <= MAX_BAND_CANDIDATES else SHOWN_CANDIDATES


rule response_variants:
    """Unit-Hs statistics of every candidate's plant variants (damping x 0.5, 1, 2 and sway
    frequency x 0.97, 1, 1.03) on the legs' Tz values; the workability rule turns them into
    bands. The cost is linear in candidates (nine variants each); beyond MAX_BAND_CANDIDATES
    candidates only the shown ones are varied."""
    input:
        plant=ASSESSED_PLANT,
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
    output:
        f"{RESULTS}/{{route}}/response_variants.nc",
    params:
        states=lambda w: ROUTE_STATES[w.route],
        tuggers=TUGGERS,
        assessment={k: v for k, v in CFG["assessment"].items() if k != "criteria"},
        response=RESPONSE,
        tip=TIP,
        g=CFG["g_m_per_s2"],
        outside=OUTSIDE_RAO_RANGE,
        tensions=needs_tensions(),
        candidates=BAND_CANDIDATES,
        cache=SEA_STATE_CACHE,
    threads: solver_threads(len(BAND_CANDIDATES))  # see common.smk
    priority: -1  # the workability job needs it last (after the time-domain cells)
    resources:
        **job_resources(9 * len(BAND_CANDIDATES)),
    log:
        f"{LOGS}/{{route}}/response_variants.log",
    benchmark:
        f"{BENCH}/{{route}}/response_variants.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/response_variants.py"
