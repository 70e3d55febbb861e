#!/usr/bin/env bash
# `raster sweep` as a Slurm job array: one array task per shard, then a merge.
# Dask (bench/dask_sweep.py) is the tested path; this is for clusters that run Slurm only.
#
#   sbatch --array=1-8 bench/slurm_sweep.sh OUT SCENE --param NAME=FROM:TO:STEPS[:log] [sweep options]
#   # when every task has finished:
#   build/raster sweep-merge OUT/shard-* --out OUT
#
# Each task writes OUT/shard-K (OUT on a file system every node sees). Run outside Slurm
# with SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT set, it does the same for one shard.
#SBATCH --job-name=raster-sweep
#SBATCH --cpus-per-task=2
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: sbatch --array=1-N $0 OUT SCENE --param ... [sweep options]" >&2; exit 2; }
out=$1; shift
: "${SLURM_ARRAY_TASK_ID:?run as a job array (sbatch --array=1-N), or set SLURM_ARRAY_TASK_ID}"
: "${SLURM_ARRAY_TASK_COUNT:?run as a job array (sbatch --array=1-N), or set SLURM_ARRAY_TASK_COUNT}"
mkdir -p "$out"
raster=${RASTER:-"$(cd "$(dirname "$0")/.." && pwd)/build/raster"}
exec "$raster" sweep "$@" --shard "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT" --out "$out/shard-$SLURM_ARRAY_TASK_ID" --quiet
