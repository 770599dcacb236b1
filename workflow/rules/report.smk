rule report:
    """The per-route PDF assessment report."""
    input:
        sea=f"{RESULTS}/{{route}}/sea_states.nc",
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        plant=ASSESSED_PLANT,
        response=f"{RESULTS}/{{route}}/response.nc",
        workability=f"{RESULTS}/{{route}}/workability.nc",
        windows=windows_file,
        measured=measured_file,
        voyage=f"{RESULTS}/{{route}}/voyage.nc",
        plan=f"{RESULTS}/{{route}}/voyage_plan.nc",
        timedomain=timedomain_files,
        cells=f"{RESULTS}/{{route}}/timedomain/cells.json",
        studies=f"{RESULTS}/{{route}}/tugger_studies.nc",
        verification=verification_files,
        verification_cells=verification_cells_file,
        verification_study=verification_study_file,
        verification_wires=verification_wires_files,
        legs=route_files,
        screening=[f"{RESULTS}/{{route}}/screening.nc"] if SCREENING_ON else [],
        rao=RAO_FILE,
    output:
        REPORT,
    threads: 2  # figures drawn by two processes (the report runs last, alone)
    resources:
        **job_resources(len(CANDIDATES), mem_mb=2000, runtime=30, per_mvalue=5000),
    log:
        f"{LOGS}/{{route}}/report.log",
    benchmark:
        f"{BENCH}/{{route}}/report.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/report.py"
