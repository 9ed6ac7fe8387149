#!/bin/bash
# sunglint on Slurm: the merge of a sharded study, written by `sunglint compare --slurm`
# from its template scripts/templates/slurm-merge.sh (docs/cluster.md). It runs once every
# task of job array 4001 has succeeded (--dependency=afterok), reads every frame
# from the cache, renders nothing, and writes the report: @WORK@/s4/index.html.
#SBATCH --job-name=sunglint-s4
#SBATCH --chdir=@WORK@
#SBATCH --output=@WORK@/s4/slurm/1/merge-%j.log
#SBATCH --time=0:10:00
#SBATCH --cpus-per-task=1
#SBATCH --partition=short
set -u
echo "sunglint: merge job ${SLURM_JOB_ID} on $(hostname), $(date -u +%Y-%m-%dT%H:%M:%SZ)"
@SUNGLINT@ compare @SRC@/scenes/simple.json -m point -m taa -m 'supersample --samples 2x2x1' --frames 0-1 --width 32 --height 18 --reference 2x2x1 --budgets 1x1x1 --no-video --out s4 -q -j "${SLURM_CPUS_PER_TASK:-1}" --merge
