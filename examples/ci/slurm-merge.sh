#!/bin/bash
# Slurm: after the array of slurm-fuzz-array.sh, the shards merged into one report
# (sbatch --dependency=afterany:<array job id> slurm-merge.sh).
#SBATCH --job-name=cyclecert-report
#SBATCH --time=00:30:00
set -u
export RESULTS=${RESULTS:-$HOME/cyclecert-results}

cyclecert merge --out "$RESULTS/merged" "$RESULTS"/shard-*
cyclecert report "$RESULTS/merged"
