rule vessel_motion:
    """Vessel RAOs at the route's headings, transferred to the hinge and the fairleads."""
    input:
        rao=RAO_FILE,
    output:
        f"{RESULTS}/{{route}}/vessel_motion.nc",
    params:
        vessel={**{k: v for k, v in CFG["vessel"].items() if k != "bem"}, "rao_file": RAO_FILE},
        headings=lambda w: motion_headings(w.route),
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/vessel_motion.log",
    benchmark:
        f"{BENCH}/{{route}}/vessel_motion.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/vessel_motion.py"


if "bem" in CFG["vessel"]:

    rule vessel_bem:
        """Vessel RAOs computed with Capytaine when the configuration asks for it
        (vessel.bem); needs the 'bem' extra. Written into results/, never to a path the
        configuration names."""
        input:
            mesh=[CFG["vessel"]["bem"]["mesh"]["file"]] if "mesh" in CFG["vessel"]["bem"] else [],
        output:
            RAO_FILE,
        params:
            bem=CFG["vessel"]["bem"],
        resources:
            **job_resources(mem_mb=4000, runtime=60),
        log:
            "logs/vessel_bem.log",
        benchmark:
            "benchmarks/out/vessel_bem.tsv"
        conda:
            "../envs/jls.yaml"
        script:
            "../scripts/vessel_bem.py"
