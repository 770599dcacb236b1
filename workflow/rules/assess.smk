from jls.config.builders import grid_boundary_count

checkpoint workability:
    """MPM per cell, pass/fail, workability per leg and route, limiting Hs(Tz); uncertainty
    bands over the plant variants and Hs choices; route workability against the sway limit;
    winch saturation flags and the time-domain verdicts where cells ran. Also the route's
    verification cells (verification.smk), which need this workability and its
    recommendation and nothing else: chosen in this job rather than a job of their own,
    which cost the critical path a process start (0.8 s of a 1-s job). A checkpoint, so
    that the verification cells are known once it has run."""
    input:
        sea=f"{RESULTS}/{{route}}/sea_states.nc",
        response=f"{RESULTS}/{{route}}/response.nc",
        curve=f"{RESULTS}/{{route}}/operability.nc",
        variants=f"{RESULTS}/{{route}}/response_variants.nc",
        voyage=f"{RESULTS}/{{route}}/voyage.nc",
        plan=f"{RESULTS}/{{route}}/voyage_plan.nc",
        timedomain=timedomain_files,
        measured=measured_file,
        plant=ASSESSED_PLANT,
    output:
        workability=f"{RESULTS}/{{route}}/workability.nc",
        verification_cells=f"{RESULTS}/{{route}}/verification/cells.json",
    params:
        criteria=CFG["assessment"]["criteria"],
        sea=SEA,
        tuggers=CFG["tuggers"],
        winch_saturation=CFG["assessment"]["winch_saturation"],
        max_saturation_fraction=CFG["assessment"]["max_saturation_fraction"],
        recommendation=CFG["recommendation"],
        operation=CFG["operation"],
        tz_outside=CFG["weather_windows"]["tz_outside"],
        input_warnings=lambda w: INPUT_WARNINGS[w.route],
        verification={k: VERIFICATION[k] for k in VERIFICATION_CHOICE},
        verification_tuggers=TUGGERS,
        # the legs whose sea is their own: no verification cell of theirs (the reference runs a JONSWAP)
        sea_models=lambda w: {leg["name"]: sea_model(leg) for leg in spectra_legs(w.route)},
        grid_best=grid_boundary_count(CFG),
    resources:
        **job_resources(len(CANDIDATES)),
    log:
        f"{LOGS}/{{route}}/workability.log",
    benchmark:
        f"{BENCH}/{{route}}/workability.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/workability.py"
