#!/usr/bin/env bash
# A CPU benchmark peer (tools/peers) must render the model of docs/model.md, or its timings in
# tools/bench compare Raytracer with something else: its image of a few classic scenes
# must match the double-precision CPU reference as the GPU renderer's must (at least
# 99.5% of pixels within 2/255; conformance_test explains the tolerance).
#   spheres: spheres and triangles, mirrors; table: a reflective triangle mesh;
#   snow: triangles from 1e-4 to 1e5 in area, the test of the self-intersection offset.
#
# usage: peers_test.sh PEER REFERENCE_RENDER IMAGE_DIFF SCENES_DIR OUTPUT_DIR
set -euo pipefail

readonly peer=$1 reference=$2 image_diff=$3 scenes=$4
readonly size=(--width 160 --height 120)
name=$(basename "$peer")
readonly output=$5/$name # one folder per peer: the peers' tests may run at the same time
mkdir -p "$output"

failed=0
for scene in spheres table snow; do
    for depth in 0 5; do
        ref="$output/$scene-d$depth-reference.png"
        out="$output/$scene-d$depth-peer.png"
        "$reference" "$scenes/$scene.scene" -o "$ref" "${size[@]}" --depth "$depth" --threads 2 2>/dev/null
        "$peer" "$scenes/$scene.scene" -o "$out" "${size[@]}" --depth "$depth" --threads 2
        if result=$("$image_diff" "$out" "$ref" --diff "$output/$scene-d$depth-diff.png"); then
            echo "$name $scene depth $depth: $result"
            rm -f "$output/$scene-d$depth-diff.png"
        else
            echo "$name $scene depth $depth: FAILED: $result (images kept in $output)"
            failed=1
        fi
    done
done
exit $failed
