#!/bin/bash
# sunglint on Slurm: one element of a job array, written by `sunglint compare --slurm` from
# its template scripts/templates/slurm-array.sh (docs/cluster.md). Element K runs task K:
# its units of the study, rendered into the frame cache. The work lands in files written whole (temporary file + rename), and work already
# there is skipped, so an element that runs twice renders nothing twice.
#
# Each placeholder (a capitalised name between two at signs) is a value sunglint fills in;
# a line whose value is empty is left out (an option not given).
#SBATCH --job-name=sunglint-s4
#SBATCH --array=0-10%3
#SBATCH --chdir=@WORK@
#SBATCH --output=@WORK@/s4/slurm/1/task-%A_%a.log
#SBATCH --open-mode=append
#SBATCH --time=0:10:00
#SBATCH --cpus-per-task=1
#SBATCH --partition=short
#SBATCH --requeue
set -u
echo "sunglint: task ${SLURM_ARRAY_TASK_ID} of job ${SLURM_ARRAY_JOB_ID} on $(hostname)," \
  "restart ${SLURM_RESTART_COUNT:-0}, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
@SUNGLINT@ compare @SRC@/scenes/simple.json -m point -m taa -m 'supersample --samples 2x2x1' --frames 0-1 --width 32 --height 18 --reference 2x2x1 --budgets 1x1x1 --no-video --out s4 -q -j "${SLURM_CPUS_PER_TASK:-1}" --plan-file @WORK@/s4/slurm/1/plan.json --task "$SLURM_ARRAY_TASK_ID"
rc=$?
# A task that failed or was killed (an error, the OOM killer, a signal) is requeued at most
# RETRIES times (--requeue; Slurm itself requeues a task whose node fails). Without it, the
# submitting command, run again, resubmits what is still missing.
RETRIES=2
if [ "$rc" -ne 0 ] && [ "${SLURM_RESTART_COUNT:-0}" -lt "$RETRIES" ]; then
  echo "sunglint: task ${SLURM_ARRAY_TASK_ID} failed (exit $rc): requeued" >&2
  scontrol requeue "${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID}"
fi
exit "$rc"
