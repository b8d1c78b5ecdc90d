#!/usr/bin/env bash
# usage: tools/farm/tasks.sh tiles W H SIDE | frames N
#
# Prints the tasks of a farm job, one a line, for tools/farm/render_task.sh (through GNU
# parallel or tools/farm/slurm_array.sh; docs/batches.md):
#   tiles W H SIDE   "tile:X,Y,W,H" for SIDE x SIDE regions covering a W x H image (the last
#                    column and row narrower), left to right, top to bottom
#   frames N         "frame:K" for K = 0 .. N-1
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
whole() { [[ $1 =~ ^[0-9]+$ ]] && (($1 > 0)); }

case "${1:-}" in
    -h | --help) usage; exit 0 ;;
    tiles)
        (($# == 4)) && whole "$2" && whole "$3" && whole "$4" || { usage >&2; exit 2; }
        for ((y = 0; y < $3; y += $4)); do
            for ((x = 0; x < $2; x += $4)); do
                echo "tile:$x,$y,$(($4 < $2 - x ? $4 : $2 - x)),$(($4 < $3 - y ? $4 : $3 - y))"
            done
        done
        ;;
    frames)
        (($# == 2)) && whole "$2" || { usage >&2; exit 2; }
        for ((k = 0; k < $2; ++k)); do echo "frame:$k"; done
        ;;
    *) usage >&2; exit 2 ;;
esac
