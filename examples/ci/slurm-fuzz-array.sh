#!/bin/bash
# Slurm: a job array of 4 tasks runs the shards (--shard auto reads SLURM_ARRAY_TASK_ID,
# SLURM_ARRAY_TASK_COUNT and SLURM_ARRAY_TASK_MIN, so --array=0-3 and --array=1-4 both work), and a
# job that starts when they all succeeded merges them and writes the report:
#   jobid=$(sbatch --parsable slurm-fuzz-array.sh)
#   sbatch --dependency=afterany:$jobid slurm-merge.sh
# The `cyclecert` lines are run by tests/ci_examples_test.sh with the variables Slurm would set.
#SBATCH --job-name=cyclecert-fuzz
#SBATCH --array=0-3
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -u
export ENGINE=${ENGINE:-process:$HOME/my-controller-sim}  # your engine (`cyclecert engines`)
export SEED=${SEED:-20261126}   # one campaign: every shard the same seed and case count
export CASES=${CASES:-200000}
export RESULTS=${RESULTS:-$HOME/cyclecert-results}       # on a file system every node sees

cyclecert fuzz --engine "$ENGINE" --seed "$SEED" --cases "$CASES" --shard auto --jobs "$SLURM_CPUS_PER_TASK" --out "$RESULTS/shard-$SLURM_ARRAY_TASK_ID" --regressions "$RESULTS/shard-$SLURM_ARRAY_TASK_ID/regressions"
