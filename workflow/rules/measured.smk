# The measured-spectrum response of the legs given by spectra: per hour, candidate and
# tugger, the relative-sway sigma over the measured spectrum and over the pipeline's
# JONSWAP on the same (Hs, Tz) (docs/sea.md, "Measured and hindcast spectra").


rule measured_response:
    """Relative-sway sigma per hour of every spectra leg, integrated directly over the
    measured spectra, beside the JONSWAP on the same (Hs, Tm02); the legs' ratios; every
    criterion's utilisation of each hour on its own directional sea."""
    input:
        plant=ASSESSED_PLANT,
        motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        spectra=lambda w: [f for leg in spectra_legs(w.route) for f in leg_files(leg)],
    output:
        f"{RESULTS}/{{route}}/measured_response.nc",
    params:
        route=lambda w: CFG["routes"][w.route],
        tuggers=TUGGERS,
        gamma=GAMMA,
        sea=CFG["sea"],
        omega_step=RESPONSE["omega_step_rad_s"],
        # what each hour's criteria read (jls.stages.hourly_seas): not the whole configuration,
        # so that a report setting does not rerun the rule
        cfg={k: CFG[k] for k in ("assessment", "vessel", "rigging", "g_m_per_s2")},
    threads: 2
    resources:
        # ten years of hourly 40 x 24 spectra x 100 candidates x 4 tuggers peak at 3.2 GB
        # (benchmarks/measured_leg.py); doubled on a retry like every job's
        **job_resources(mem_mb=4000),
    log:
        f"{LOGS}/{{route}}/measured_response.log",
    benchmark:
        f"{BENCH}/{{route}}/measured_response.tsv"
    conda:
        "../envs/jls.yaml"
    script:
        "../scripts/measured_response.py"
