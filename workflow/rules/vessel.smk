rule vessel_motion:
    """Vessel RAOs at the route's headings, transferred to the hinge and the fairleads."""
    input:
        rao=CFG["vessel"]["rao_file"] if "vessel" in CFG else [],
    output:
        "results/{route}/vessel_motion.nc",
    params:
        vessel=CFG.get("vessel", {}),
        headings=lambda w: route_headings(w.route),
    log:
        "logs/{route}/vessel_motion.log",
    benchmark:
        "benchmarks/out/{route}/vessel_motion.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/vessel_motion.py"
