# Rigging screening and optimisation per route (chapter 5), on when screening.enabled.
# The baseline and the grid candidates are split into chunks of
# screening.chunk_candidates; each chunk job computes their unit-Hs spectral moments on
# the route's sea states and the screening envelope (sea-state cache: a new Tz column is
# the only work a changed leg adds). The gather job scores every candidate (feasibility,
# envelope, route workability), refines the best feasible one and writes screening.nc;
# the leg probabilities enter only there. Its optimum is assessed beside the configured
# candidates as "optimised" (plant_assessed.nc, written by the same job and read by the
# response and the report; they rerun only when that file's content changes).
import math

from jls.config.builders import screening_settings_from_config
from jls.config.workflow_inputs import origin as config_origin
from jls.design.screening import Settings as ScreeningSettings

SCREENING = CFG["screening"]
SCREENING_SETTINGS = screening_settings_from_config(CFG)
SCREENING_CANDIDATES = 1 + math.prod(SCREENING_SETTINGS.grid_points.values())   # baseline + grid
SCREENING_CHUNK = int(SCREENING["chunk_candidates"])
SCREENING_CHUNKS = -(-SCREENING_CANDIDATES // SCREENING_CHUNK)
PLANT_CONFIG = {k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging", "candidates", "candidate_grid")
                if k in CFG}
# What the spectral moments depend on (the chunk jobs' parameters): not the criteria,
# the exposure or the probabilities, so editing those reruns no chunk.
SCREENING_MOMENTS = {
    "plant": {k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging")},
    "grid_points": SCREENING["grid_points"],
    "envelope": SCREENING["envelope"],
    "tuggers": TUGGERS,
    "gamma": GAMMA,
    "omega_step_rad_s": RESPONSE["omega_step_rad_s"],
    "outside": OUTSIDE_RAO_RANGE,
    "chunk_size": SCREENING_SETTINGS.chunk_size,
}

if SCREENING_ON and any(c["name"] == "optimised" for c in CFG.get("candidates", [])):
    parse_error(InputError("a candidate is named 'optimised', the name the screening gives its "
                           "optimum (screening.enabled is true); rename it", field="candidates",
                           value="optimised", file=config_origin("candidates", CONFIG_LAYERS)))


if SCREENING_ON:

    rule screening_chunk:
        """Unit-Hs spectral moments of one chunk of the screening candidates (baseline and
        grid) on the route's Tz values and the screening envelope; sea states already in
        the cache are read, not evaluated. The frequency grid is refined around every
        screening candidate's modes, so the numbers do not depend on the chunking."""
        input:
            motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
        output:
            f"{RESULTS}/{{route}}/screening/chunk-{{chunk}}.nc",   # kept: re-scoring needs no chunk job
        params:
            states=lambda w: {"leg_tz": ROUTE_STATES[w.route]["leg_tz"],
                              "headings_deg": route_headings(w.route)},
            moments=SCREENING_MOMENTS,
            chunk=SCREENING_CHUNK,
            cache=SEA_STATE_CACHE,
        threads: 1  # chunks run side by side
        resources:
            **job_resources(SCREENING_CHUNK),
        log:
            f"{LOGS}/{{route}}/screening/chunk-{{chunk}}.log",
        benchmark:
            f"{BENCH}/{{route}}/screening/chunk-{{chunk}}.tsv"
        conda:
            "../envs/jls.yaml"
        script:
            "../scripts/screening_chunk.py"

    checkpoint screening:
        """Feasibility, envelope scores and route workability of every screening
        candidate from the chunks' moments, sensitivity, refinement from the best
        feasible grid point: results/<route>/screening.nc; and the assessed plant, the
        configured candidates and the optimum named 'optimised' (plant_assessed.nc),
        which the response, workability and report assess. A checkpoint, so that the
        plant's readers rerun only when its content changes (assessed_plant, common.smk)."""
        input:
            sea=f"{RESULTS}/{{route}}/sea_states.nc",
            motion=f"{RESULTS}/{{route}}/vessel_motion.nc",
            chunks=screening_chunks,
        output:
            screening=f"{RESULTS}/{{route}}/screening.nc",
            plant=f"{RESULTS}/{{route}}/plant_assessed.nc",
        params:
            config={k: CFG[k] for k in ("g_m_per_s2", "jacket", "rigging", "candidates", "tuggers", "sea",
                                        "assessment", "response", "screening", "vessel") if k in CFG},
            plant=PLANT_CONFIG,
        threads: 1  # the refinement solves one candidate at a time
        resources:
            **job_resources(SCREENING_CANDIDATES, runtime=30),
        log:
            f"{LOGS}/{{route}}/screening.log",
        benchmark:
            f"{BENCH}/{{route}}/screening.tsv"
        conda:
            "../envs/jls.yaml"
        script:
            "../scripts/screening.py"
