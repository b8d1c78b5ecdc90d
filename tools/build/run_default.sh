#!/usr/bin/env bash
# Usage: tools/build/run_default.sh RAYTRACER SCENE
#
# `make run`: shows a scene in a window, or renders it headless to out/ when there
# is no display, and says where the image went.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
if [[ ${1:-} == -h || ${1:-} == --help ]]; then usage; exit 0; fi
if (($# != 2)); then usage >&2; exit 2; fi
binary=$1
scene=$2

if [[ -n ${DISPLAY:-} || -n ${WAYLAND_DISPLAY:-} ]]; then
    exec "$binary" "$scene"
fi
mkdir -p out
output="out/$(basename "${scene%.scene}").png"
"$binary" "$scene" -o "$output"
echo "No display: rendered $scene headless to $(realpath "$output")"
