#!/usr/bin/env bash
# `make run`: shows a scene in a window, or renders it headless to out/ when there
# is no display, and says where the image went.
set -euo pipefail
binary=$1
scene=$2

if [[ -n ${DISPLAY:-} || -n ${WAYLAND_DISPLAY:-} ]]; then
    exec "$binary" "$scene"
fi
mkdir -p out
output="out/$(basename "${scene%.scene}").png"
"$binary" "$scene" -o "$output"
echo "No display: rendered $scene headless to $(realpath "$output")"
