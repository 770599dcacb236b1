"""The end-of-run summary of failed jobs (jls.config.workflow_inputs.failed_jobs), read
from a Snakemake log: the cause from the job's own log, or from the scheduler's log when
the job's log is empty or older than the run; retries counted; a job that completed on
its retry left out; a stale job log rewritten."""

import os
import time

from jls.config.workflow_inputs import failed_jobs

SNAKEMAKE_LOG = """Building DAG of jobs...
Job 0 has been submitted with SLURM jobid 41 (log: {d}/.snakemake/slurm_logs/rule_plant/tiny/41.log).
Error in rule plant:
    message: SLURM-job '41' failed, SLURM status is: 'FAILED'. Reason: Unknown.
    jobid: 0
    output: results/tiny/plant.nc
    log: logs/tiny/plant.log, {d}/.snakemake/slurm_logs/rule_plant/tiny/41.log (check log file(s) for error details)
    external_jobid: 41
Error in rule sea_states:
    jobid: 1
    output: results/tiny/sea_states.nc
    log: logs/tiny/sea_states.log, {d}/.snakemake/slurm_logs/rule_sea_states/tiny/42.log (check log file(s) for error details)
    external_jobid: 42
Error in rule response:
    jobid: 2
    output: results/tiny/response.nc, results/tiny/operability.nc
    log: logs/tiny/response.log, {d}/.snakemake/slurm_logs/rule_response/tiny/43.log (check log file(s) for error details)
    external_jobid: 43
Trying to restart job 0.
Trying to restart job 1.
Error in rule plant:
    jobid: 0
    output: results/tiny/plant.nc
    log: logs/tiny/plant.log, {d}/.snakemake/slurm_logs/rule_plant/tiny/44.log (check log file(s) for error details)
    external_jobid: 44
Finished jobid: 1 (Rule: sea_states)
"""


def test_failed_jobs_name_their_causes(tmp_path):
    d = tmp_path
    (d / "logs" / "tiny").mkdir(parents=True)
    slurm = d / ".snakemake" / "slurm_logs"
    for rule, job in (("plant", 41), ("plant", 44), ("sea_states", 42), ("response", 43)):
        (slurm / f"rule_{rule}" / "tiny").mkdir(parents=True, exist_ok=True)
    (slurm / "rule_plant" / "tiny" / "44.log").write_text(
        "Building DAG of jobs...\nslurmstepd-n1: error: Exceeded job memory limit\n"
        "slurmstepd-n1: error: *** JOB 44 ON n1 CANCELLED ***\n")
    (slurm / "rule_response" / "tiny" / "43.log").write_text("Traceback ...\nOSError: corrupt\n")
    plant_log = d / "logs" / "tiny" / "plant.log"
    plant_log.write_text("2026-01-01 00:00:00,000 INFO jls.plant: wrote results/tiny/plant.nc\n")
    os.utime(plant_log, (1.7e9, 1.7e9))                      # an earlier run's
    (d / "logs" / "tiny" / "response.log").write_text(
        "2026-12-01 10:00:00,000 INFO jls.response: 2 candidates\n"
        "2026-12-01 10:00:01,000 ERROR jls.response: failed: OSError: corrupt\n"
        "Traceback (most recent call last):\n  File ...\nOSError: corrupt\n")
    log = d / "run.snakemake.log"
    log.write_text(SNAKEMAKE_LOG.format(d=d))
    lines = failed_jobs([log], since=time.time() - 60, base_dir=d, rewrite_stale=True)
    text = "\n".join(lines)
    assert "sea_states" not in text                          # completed on its retry
    assert lines[0] == "failed: rule plant (results/tiny/plant.nc), scheduler job 44, 2 attempts"
    assert lines[1].startswith("    logs/tiny/plant.log: older than this run (rewritten); "
                               "the last lines of ")
    assert lines[2:4] == ["        slurmstepd-n1: error: Exceeded job memory limit",
                          "        slurmstepd-n1: error: *** JOB 44 ON n1 CANCELLED ***"]
    assert lines[4] == ("failed: rule response (results/tiny/response.nc, "
                        "results/tiny/operability.nc), scheduler job 43")
    assert lines[5] == ("    logs/tiny/response.log: 2026-12-01 10:00:01,000 ERROR jls.response: "
                        "failed: OSError: corrupt")
    assert len(lines) == 6
    rewritten = plant_log.read_text()
    assert "wrote" not in rewritten and "failed before its step began" in rewritten
