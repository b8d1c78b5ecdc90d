#!/usr/bin/env bash
# The render-farm recipes of docs/batches.md on local processes: GNU parallel spreads the
# regions of one image and the frames of a turntable over processes through
# tools/farm/render_task.sh; the regions stitched (tools/stitch) are the single-process
# render byte for byte, and each frame is the one-process batch's frame. The Slurm array
# script is valid bash and, run here with each array index, runs the same task command:
# its stitched image is the same file too.
#
#   farm_test.sh SOURCE_DIR RAYTRACER STITCH
# Exit status 77 (ctest: skipped) when GNU parallel is not installed.
set -euo pipefail
(($# == 3)) || { echo "usage: $0 SOURCE_DIR RAYTRACER STITCH" >&2; exit 2; }
root=$(cd "$1" && pwd)
export RAYTRACER=$2
stitch=$3
farm=$root/tools/farm
command -v parallel > /dev/null || { echo "SKIP: GNU parallel is not installed (tools/build/install_deps.sh)"; exit 77; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
scene=$root/scenes/showcase.scene
options=(--width 80 --height 60 --spp 3 --validate)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
same() { cmp -s "$1" "$2" && echo "ok: $2 is $1 byte for byte" || fail "$2 differs from $1"; }

"$RAYTRACER" "$scene" "${options[@]}" -o full.png 2> /dev/null

# Regions through GNU parallel, then stitched.
"$farm/tasks.sh" tiles 80 60 32 > tiles.txt
(($(wc -l < tiles.txt) == 6)) || fail "tasks.sh tiles 80 60 32 gave $(wc -l < tiles.txt) tiles, not 6"
parallel --will-cite -j 2 --halt now,fail=1 "$farm/render_task.sh" {} parts "$scene" "${options[@]}" \
    :::: tiles.txt 2> parallel.log || fail "parallel: $(tail -n 3 parallel.log)"
"$stitch" -o stitched.png parts/part-*.png
same full.png stitched.png

# Frames through GNU parallel, each task one frame (--frames K), against one process.
mkdir batch
"$RAYTRACER" "$scene" "${options[@]}" --turntable 3 -o 'batch/frame-{frame:04}.png' 2> /dev/null
"$farm/tasks.sh" frames 3 |
    parallel --will-cite -j 2 --halt now,fail=1 "$farm/render_task.sh" {} frames "$scene" \
        "${options[@]}" --turntable 3 2> parallel.log || fail "parallel: $(tail -n 3 parallel.log)"
for k in 0000 0001 0002; do same "batch/frame-$k.png" "frames/frame-$k.png"; done

# The Slurm array: valid bash, and each array task runs the same task command.
bash -n "$farm/slurm_array.sh" && echo "ok: slurm_array.sh is valid bash" || fail "slurm_array.sh is not valid bash"
for ((id = 0; id < $(wc -l < tiles.txt); ++id)); do
    SLURM_ARRAY_TASK_ID=$id SLURM_SUBMIT_DIR=$root bash "$farm/slurm_array.sh" tiles.txt slurm-parts \
        "$scene" "${options[@]}" 2> /dev/null || fail "slurm_array.sh task $id"
done
"$stitch" -o slurm-stitched.png slurm-parts/part-*.png
same full.png slurm-stitched.png

if ((failures)); then
    echo "$failures failures"
    exit 1
fi
echo "the farm recipes give the single-process images"
