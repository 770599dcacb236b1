# The ROM against the 6-DOF nonlinear reference in MoorDyn (jls.stages.verification_cell):
# per verified combination (the recommendation and the baseline by default) its cells
# nearest the workability boundary, and the design corner when enabled. The choice needs
# the workability and the recommendation, so the workability checkpoint makes it
# (results/<route>/verification/cells.json, assess.smk); each cell is then its own job,
# whose parameters are that cell and the run settings every cell shares, so editing one
# cell reruns only that cell's job. The settings and the input functions are
# in common.smk.


rule verification_cell:
    """One verification cell: the ROM against the 6-DOF reference on one wave record."""
    input:
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        plant=verification_plant,
    output:
        f"{RESULTS}/{{route}}/verification/{{vcell}}.nc",
    params:
        cell=lambda w: parse_verification_cell(w.vcell),
        run=VERIFICATION_RUN,
        plant={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging")},
        candidate=lambda w: verification_candidate(w.vcell),
        tugger=lambda w: verification_tugger(w.vcell),
        vessel={k: CFG["vessel"][k] for k in ("fairlead_half_span_m", "fairlead_drop_m")},
        gamma=GAMMA,
        exposure_h=CFG["assessment"]["exposure_h"],
    threads: 1  # MoorDyn and the ROM integrate on one core; two cells run side by side
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/verification/{{vcell}}.log",
    benchmark:
        f"{BENCH}/{{route}}/verification/{{vcell}}.tsv"
    wildcard_constraints:
        vcell="[A-Za-z0-9_.=-]+__[A-Za-z0-9_.-]+__h[-0-9.e+]+__hs[0-9.e+-]+__tz[0-9.e+-]+",
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/verification_cell.py"


rule verification_study_part:
    """One part of the study comparison (jls.verify.names.STUDY_PARTS): some of the study's
    sea states of table 4.4, or some of the linear range's steps, the ROM against the
    reference on each (jls.verify.study.study_part). The parts need only the vessel
    motion: they run beside the screening, the time-domain cells and each other."""
    input:
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
    output:
        f"{RESULTS}/{{route}}/verification_study/{{part}}.nc",
    params:
        run=VERIFICATION_RUN,
        plant={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging")},
        gamma=GAMMA,
        exposure_h=CFG["assessment"]["exposure_h"],
    threads: 1
    priority: -1  # fill the cores the jobs the verification cells wait on leave free
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/verification_study/{{part}}.log",
    benchmark:
        f"{BENCH}/{{route}}/verification_study/{{part}}.tsv"
    wildcard_constraints:
        part="|".join(STUDY_PARTS),
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/verification_study_part.py"


rule verification_study:
    """The study's table 4.4 beside the ROM against the reference at its sea states, and
    the linear range measured, assembled from the parts (jls.verify.study.assemble)."""
    input:
        parts=lambda w: [f"{RESULTS}/{w.route}/verification_study/{p}.nc" for p in STUDY_PARTS],
    output:
        f"{RESULTS}/{{route}}/verification_study.nc",
    params:
        run=VERIFICATION_RUN,
    threads: 1
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/verification_study.log",
    benchmark:
        f"{BENCH}/{{route}}/verification_study.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/verification_study.py"


rule verification_wires:
    """The wires as wires: the one-segment reference against wires of several segments
    with their mass and axial damping, on one cell per verified combination."""
    input:
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        plant=verification_plant,
    output:
        f"{RESULTS}/{{route}}/verification/wires/{{vcell}}.nc",
    params:
        cell=lambda w: parse_verification_cell(w.vcell),
        run=VERIFICATION_WIRES_RUN,
        wires=VERIFICATION["wires"],
        plant={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging")},
        candidate=lambda w: verification_candidate(w.vcell),
        tugger=lambda w: verification_tugger(w.vcell),
        vessel={k: CFG["vessel"][k] for k in ("fairlead_half_span_m", "fairlead_drop_m")},
        gamma=GAMMA,
    threads: 1
    priority: 1  # the longest of the jobs after the workability: first, the cells beside it
    resources:
        **job_resources(),
    log:
        f"{LOGS}/{{route}}/verification/wires/{{vcell}}.log",
    benchmark:
        f"{BENCH}/{{route}}/verification/wires/{{vcell}}.tsv"
    wildcard_constraints:
        vcell="[A-Za-z0-9_.=-]+__[A-Za-z0-9_.-]+__h[-0-9.e+]+__hs[0-9.e+-]+__tz[0-9.e+-]+",
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/verification_wires.py"
