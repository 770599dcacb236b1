from jls.config.builders import boundary_candidates, grid_boundary_count

# Nonlinear time-domain cells of a route (jls.stages.timedomain_cell): the cells nearest
# the workability boundary, the cells whose winch saturates in the frequency domain (when
# assessment.winch_saturation is 'timedomain') and the configured ones. The choice needs
# the frequency-domain results, so it is a checkpoint; each cell is then its own job,
# whose parameters are that cell and the settings every cell shares, so editing one
# cell reruns only that cell's job.

# The configuration parts one cell's run depends on (not the list of cells).
TD_RUN = {k: v for k, v in CFG["timedomain"].items()
          if k not in ("cells", "boundary_candidates", "boundary_cells_per_leg", "max_cells", "slope_sweep",
                       "decay_release_m")}
# The candidates whose boundary cells run (timedomain.boundary_candidates; by default every
# assessed one, so the recommendation, chosen afterwards in the workability stage among
# the same candidates, always has its cells in the time domain; of a candidate grid, the
# timedomain.grid_boundary_candidates best by frequency-domain workability, the others
# being excluded from the recommendation).
BOUNDARY_CANDIDATES = boundary_candidates(CFG)
# What the tugger studies share of it (not the cells' own record length, trace or seeds).
TD_STUDIES = {k: v for k, v in TD_RUN.items() if k not in ("duration_h", "trace_s", "seeds_per_cell")}


checkpoint timedomain_cells:
    """The route's time-domain cells, chosen from the frequency-domain workability."""
    input:
        sea=f"{RESULTS}/{{route}}/sea_states.nc",
        response=f"{RESULTS}/{{route}}/response.nc",
    output:
        f"{RESULTS}/{{route}}/timedomain/cells.json",
    params:
        criteria=CFG["assessment"]["criteria"],
        winch_saturation=CFG["assessment"]["winch_saturation"],
        sea=SEA,
        tuggers=CFG["tuggers"],
        choice={**{k: CFG["timedomain"][k] for k in ("cells", "boundary_cells_per_leg", "max_cells")},
                "boundary_candidates": BOUNDARY_CANDIDATES,    # 'assessed' resolved to the names
                "grid_best": grid_boundary_count(CFG)},        # and a grid's best, ranked in the job
        model_legs=lambda w: [leg["name"] for leg in spectra_legs(w.route)],   # cells on their own sea
    priority: 1  # before the voyage and the band variants: the cells wait on it, they on nothing
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/timedomain/cells.log",
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/timedomain_cells.py"


rule timedomain_cell:
    """One time-domain cell: every tugger setting on one wave record."""
    input:
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        plant=timedomain_plant,
        sea_files=lambda w: record_files(cell_leg(w)) if cell_leg(w) else [],
    output:
        f"{RESULTS}/{{route}}/timedomain/{{cell}}.nc",
    params:
        cell=lambda w: parse_cell(w.cell),
        sea_leg=cell_leg,                    # the leg whose own sea the cell runs in, or None
        sea=SEA,
        omega_step=RESPONSE["omega_step_rad_s"],
        run=TD_RUN,
        plant={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging", "candidates", "candidate_grid")
               if k in CFG},
        tuggers=CFG["tuggers"],
        gamma=GAMMA,
        exposure_h=CFG["assessment"]["exposure_h"],
    threads: 1  # runs beside the band variants; set-threads 2 runs the settings side by side
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/timedomain/{{cell}}.log",
    benchmark:
        f"{BENCH}/{{route}}/timedomain/{{cell}}.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/timedomain_cell.py"


rule tugger_studies:
    """Decay tests (section 6.6) and the damping-slope sweep (table 6.6), baseline rigging."""
    input:
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
    output:
        f"{RESULTS}/{{route}}/tugger_studies.nc",
    params:
        run=TD_STUDIES,
        sweep=CFG["timedomain"]["slope_sweep"],
        release_m=CFG["timedomain"]["decay_release_m"],
        tuggers=CFG["tuggers"],
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/tugger_studies.log",
    benchmark:
        f"{BENCH}/{{route}}/tugger_studies.tsv"
    threads: 1  # off the critical path: runs beside the screening and response jobs
    priority: -1  # after the jobs the report waits on longest
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/tugger_studies.py"


wildcard_constraints:
    cell="[A-Za-z0-9_.=-]+__h[-0-9.e+]+__hs[0-9.e+-]+__tz[0-9.e+-]+(__leg-[A-Za-z0-9_.-]+)?",
