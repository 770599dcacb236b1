rule report:
    """The per-route PDF assessment report."""
    input:
        sea="results/{route}/sea_states.nc",
        motion="results/{route}/vessel_motion.nc",
        plant=ASSESSED_PLANT,
        response="results/{route}/response.nc",
        workability="results/{route}/workability.nc",
        windows=windows_file,
        timedomain=timedomain_files,
        cells="results/{route}/timedomain/cells.json",
        studies="results/{route}/tugger_studies.nc",
        legs=leg_files,
        screening=["results/{route}/screening.nc"] if SCREENING_ON else [],
        rao=RAO_FILE,
    output:
        "reports/{route}.pdf",
    log:
        "logs/{route}/report.log",
    benchmark:
        "benchmarks/out/{route}/report.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/report.py"
