#!/usr/bin/env bash
# usage: sbatch --array=0-$(($(wc -l < TASKS) - 1)) tools/farm/slurm_array.sh TASKS OUTDIR SCENE [RAYTRACER_OPTION...]
#
# A Slurm job array over the lines of TASKS (made by tools/farm/tasks.sh): array task I
# runs line I+1 with tools/farm/render_task.sh, the same command line as the GNU parallel
# recipe of docs/batches.md. Submit it from the checkout (Slurm runs a copy of this file,
# so render_task.sh is found from $SLURM_SUBMIT_DIR, or $RAYTRACER_FARM when set), with
# OUTDIR on a file system all nodes share; then stitch the parts (tools/stitch) or join
# the frames (tools/make_video.sh). Set $RAYTRACER when Raytracer is not on the PATH.
#SBATCH --job-name=raytracer
#SBATCH --cpus-per-task=4
#SBATCH --output=raytracer-%A_%a.log
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
case "${1:-}" in -h | --help) usage; exit 0 ;; esac
(($# >= 3)) || { usage >&2; exit 2; }
[[ -n ${SLURM_ARRAY_TASK_ID:-} ]] || { echo "slurm_array.sh: SLURM_ARRAY_TASK_ID is not set (submit with sbatch --array)" >&2; exit 2; }

tasks=$1
shift
task=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" "$tasks")
[[ -n $task ]] || { echo "slurm_array.sh: $tasks has no line $((SLURM_ARRAY_TASK_ID + 1))" >&2; exit 2; }
farm=${RAYTRACER_FARM:-${SLURM_SUBMIT_DIR:-.}/tools/farm}
exec "$farm/render_task.sh" "$task" "$@"
