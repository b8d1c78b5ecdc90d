#!/usr/bin/env bash
# usage: tools/farm/render_task.sh TASK OUTDIR SCENE [RAYTRACER_OPTION...]
#
# Renders one task of a farm job (a line of tools/farm/tasks.sh), the one command line that
# GNU parallel and tools/farm/slurm_array.sh both run on each machine (docs/batches.md):
#   tile:X,Y,W,H   Raytracer SCENE OPTIONS --crop X,Y,W,H -o OUTDIR/part-X-Y.png
#   frame:K        Raytracer SCENE OPTIONS --frames K -o OUTDIR/frame-{frame:04}.png
#                  (OPTIONS then hold --turntable N or --camera-path FILE)
# OUTDIR is made when missing. The program is $RAYTRACER, else Raytracer on the PATH.
# Exits with Raytracer's status (2 for a task it does not understand).
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
case "${1:-}" in -h | --help) usage; exit 0 ;; esac
(($# >= 3)) || { usage >&2; exit 2; }

task=$1 outdir=$2 scene=$3
shift 3
raytracer=${RAYTRACER:-Raytracer}
mkdir -p "$outdir"
if [[ $task =~ ^tile:([0-9]+),([0-9]+),([0-9]+),([0-9]+)$ ]]; then
    exec "$raytracer" "$scene" "$@" --crop "${task#tile:}" \
        -o "$outdir/part-${BASH_REMATCH[1]}-${BASH_REMATCH[2]}.png"
elif [[ $task =~ ^frame:([0-9]+)$ ]]; then
    exec "$raytracer" "$scene" "$@" --frames "${BASH_REMATCH[1]}" -o "$outdir/frame-{frame:04}.png"
fi
echo "render_task.sh: '$task' is no task (tile:X,Y,W,H or frame:K)" >&2
exit 2
