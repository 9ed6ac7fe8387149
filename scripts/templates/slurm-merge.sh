#!/bin/bash
# sunglint on Slurm: the merge of a sharded study, written by `sunglint compare --slurm`
# from its template scripts/templates/slurm-merge.sh (docs/cluster.md). It runs once every
# task of job array @ARRAY_JOB@ has succeeded (--dependency=afterok), reads every frame
# from the cache, renders nothing, and writes the report: @OUT_DIR@/index.html.
#SBATCH --job-name=@JOB_NAME@
#SBATCH --chdir=@WORK_DIR@
#SBATCH --output=@LOG_DIR@/merge-%j.log
#SBATCH --time=@TIME@
#SBATCH --cpus-per-task=@CPUS@
#SBATCH --partition=@PARTITION@
set -u
echo "sunglint: merge job ${SLURM_JOB_ID} on $(hostname), $(date -u +%Y-%m-%dT%H:%M:%SZ)"
@MERGE_COMMAND@
