#!/usr/bin/env bash
# One shard of a marchstudio sequence per Slurm array task (docs/scale-out.md).
#
#   sbatch --array=0-3 tools/slurm/render_array.sh SCENE A..B OUT_PATTERN [render flags...]
#
# e.g. sbatch --array=0-15 tools/slurm/render_array.sh scenes/seed.toml 0..599 \
#          /shared/out/frame_%04d.png --fps 60 --size 1920x1080
#
# Task k of an array of N renders `--shard k/N` (every N-th frame), so the
# tasks together render each frame exactly once, whatever the array's first
# index or step. OUT_PATTERN must be on a file system every node sees.
# Frames are written atomically and complete ones are skipped, so after a
# failure the same array is simply submitted again: each task renders only
# what is missing. Set MARCHSTUDIO to the binary when it is not on PATH.
#SBATCH --job-name=marchstudio
#SBATCH --ntasks=1
#SBATCH --requeue
set -euo pipefail

if [ $# -lt 3 ]; then
  echo "usage: sbatch --array=0-N $0 SCENE A..B OUT_PATTERN [render flags...]" >&2
  exit 2
fi
if [ -z "${SLURM_ARRAY_TASK_ID:-}" ] || [ -z "${SLURM_ARRAY_TASK_COUNT:-}" ]; then
  echo "$0: not a Slurm array task (SLURM_ARRAY_TASK_ID/COUNT unset); submit with sbatch --array=0-N" >&2
  exit 2
fi

# Index within the array from 0, also for --array=1-8 or --array=0-30:2.
min=${SLURM_ARRAY_TASK_MIN:-0}
step=${SLURM_ARRAY_TASK_STEP:-1}
index=$(( (SLURM_ARRAY_TASK_ID - min) / step ))
count=$SLURM_ARRAY_TASK_COUNT

scene=$1 frames=$2 pattern=$3
shift 3
echo "marchstudio shard $index/$count of frames $frames on $(hostname)" >&2
exec "${MARCHSTUDIO:-marchstudio}" render "$scene" --frames "$frames" -o "$pattern" --shard "$index/$count" "$@"
