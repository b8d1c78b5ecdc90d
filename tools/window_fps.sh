#!/usr/bin/env bash
# Usage: tools/window_fps.sh RAYTRACER [FRAMES] [WIDTHxHEIGHT] [SCENE...]
#
# Frames per second of the window's progressive view (one sample per pixel per frame),
# per scene, under Xvfb on lavapipe: the same device the tests use, so the figures say
# what a user without a GPU sees; on a real GPU run it on the real display instead.
#
# Default: 30 frames at 640x480 over ../shared/scenes/*.scene beside the checkout (the classic scenes).
# Prints one JSON line per scene (--bench-window) and a table at the end.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }

if [[ ${1:-} == -h || ${1:-} == --help ]]; then usage; exit 0; fi
if (($# < 1)); then usage >&2; exit 2; fi
raytracer=$(realpath "$1")
frames=${2:-30}
size=${3:-640x480}
shift $(($# < 3 ? $# : 3))
scenes=("$@")
if ((${#scenes[@]} == 0)); then
    scenes=("$(dirname "$0")"/../../shared/scenes/*.scene)
fi
width=${size%x*} height=${size#*x}
icd=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json

if [[ ${WINDOW_FPS_INSIDE_XVFB:-} != 1 ]]; then
    command -v xvfb-run > /dev/null || { echo "xvfb-run is missing (tools/build/install_deps.sh)" >&2; exit 1; }
    WINDOW_FPS_INSIDE_XVFB=1 exec xvfb-run -a -s "-screen 0 1920x1080x24" "$0" "$raytracer" "$frames" "$size" \
        "${scenes[@]}"
fi

results=()
for scene in "${scenes[@]}"; do
    line=$(VK_ICD_FILENAMES=$icd VK_DRIVER_FILES=$icd timeout 600 "$raytracer" "$scene" --window \
        --bench-window "$frames" --width "$width" --height "$height" 2>/dev/null | tail -n 1) ||
        line="{\"scene\": \"$(basename "$scene")\", \"error\": \"failed\"}"
    echo "$line"
    results+=("$line")
done
echo
printf '%-20s %10s %14s\n' scene fps "Msamples/s"
for line in "${results[@]}"; do
    python3 - "$line" <<'PY'
import json, sys
r = json.loads(sys.argv[1])
print("%-20s %10.2f %14.2f" % (r["scene"], r.get("fps", float("nan")), r.get("megasamples_per_second", float("nan"))))
PY
done
