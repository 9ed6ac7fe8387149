#!/bin/bash
# sunglint on Slurm: one element of a job array, written by `sunglint @KIND@ --slurm` from
# its template scripts/templates/slurm-array.sh (docs/cluster.md). Element K runs task K:
# @WHAT@. The work lands in files written whole (temporary file + rename), and work already
# there is skipped, so an element that runs twice renders nothing twice.
#
# Each placeholder (a capitalised name between two at signs) is a value sunglint fills in;
# a line whose value is empty is left out (an option not given).
#SBATCH --job-name=@JOB_NAME@
#SBATCH --array=@ARRAY@
#SBATCH --chdir=@WORK_DIR@
#SBATCH --output=@LOG_DIR@/task-%A_%a.log
#SBATCH --open-mode=append
#SBATCH --time=@TIME@
#SBATCH --cpus-per-task=@CPUS@
#SBATCH --partition=@PARTITION@
#SBATCH @REQUEUE@
set -u
echo "sunglint: task ${SLURM_ARRAY_TASK_ID} of job ${SLURM_ARRAY_JOB_ID} on $(hostname)," \
  "restart ${SLURM_RESTART_COUNT:-0}, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
@TASK_COMMAND@
rc=$?
# A task that failed or was killed (an error, the OOM killer, a signal) is requeued at most
# RETRIES times (--requeue; Slurm itself requeues a task whose node fails). Without it, the
# submitting command, run again, resubmits what is still missing.
RETRIES=@RETRIES@
if [ "$rc" -ne 0 ] && [ "${SLURM_RESTART_COUNT:-0}" -lt "$RETRIES" ]; then
  echo "sunglint: task ${SLURM_ARRAY_TASK_ID} failed (exit $rc): requeued" >&2
  scontrol requeue "${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}"
fi
exit "$rc"
