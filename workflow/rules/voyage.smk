# Voyage extremes of a route: the probability that the voyage's largest response stays
# inside each limit (scatter tables, all sea states), and for a route of hourly hindcasts
# the route sailed from every recorded departure hour (docs/reference/outputs.md, "voyage.nc: voyage extremes").


rule voyage:
    """Exceedance probability and non-exceedance levels of the voyage's largest response
    per option and criterion; per departure and month on hindcast routes."""
    input:
        sea=f"{RESULTS}/{{route}}/sea_states.nc",
        response=f"{RESULTS}/{{route}}/response.nc",
        operability=f"{RESULTS}/{{route}}/operability.nc",
        hindcasts=lambda w: [f for leg in hindcast_legs(w.route) for f in leg_files(leg)],
        measured=measured_file,
    output:
        f"{RESULTS}/{{route}}/voyage.nc",
    params:
        route=lambda w: CFG["routes"][w.route],
        criteria=CFG["assessment"]["criteria"],
        gamma=GAMMA,
        hs_in_bin=SEA["hs_in_bin"],
    # blocks of options side by side (the blocks do not depend on the threads): a few
    # candidates take one core, so that the voyage runs beside the time-domain cells
    # rather than waiting for both cores
    threads: solver_threads(len(CANDIDATES))
    priority: -1  # the workability job needs it last (after the time-domain cells)
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/voyage.log",
    benchmark:
        f"{BENCH}/{{route}}/voyage.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/voyage.py"


# The voyage plan (docs/voyage_plan.md): the class of every stretch between hold points,
# the unrestricted design check on the legs' environmental contours, and the departure
# rule sailed through the legs' hourly records (a record leg's file, or the records a
# table leg carries beside its table: editing one reruns only what reads it).
rule voyage_plan:
    """Class, unrestricted design check and departure rule per option; the swell table of
    partitioned legs."""
    input:
        sea=f"{RESULTS}/{{route}}/sea_states.nc",
        operability=f"{RESULTS}/{{route}}/operability.nc",
        records=lambda w: plan_record_files(w.route),
        measured=measured_file,
        swell=swell_inputs,
    output:
        f"{RESULTS}/{{route}}/voyage_plan.nc",
    params:
        route=lambda w: CFG["routes"][w.route],
        criteria=CFG["assessment"]["criteria"],
        operation=CFG["operation"],
        gamma=GAMMA,
        exposure_h=CFG["assessment"]["exposure_h"],
    threads: 1
    priority: -1
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/voyage_plan.log",
    benchmark:
        f"{BENCH}/{{route}}/voyage_plan.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/voyage_plan.py"
