#!/usr/bin/env bash
# The window's screenshots at exact sample counts, under Xvfb: with --spp 4096 --snapshots
# 1,7,...,4096 the window stops a frame at each count and writes what it shows, as P does;
# each PNG must name its count and equal, byte for byte, both headless --spp K and the
# headless command printed with it. The counts are reached by the window's own frames, not
# by waiting some seconds, so a slow machine and a fast one test the same images. 255, 256
# and 257 straddle a frame's usual end (64 samples a frame at most); 1 is the window's
# first frame, the pixel centre, and 7 its sum started afresh after it. Then a 2000-triangle
# knot with --accel none at 8x8, whose frames lavapipe cuts short once they reach 8 samples
# (docs/design.md, the CPU driver's loop limit; frames grow while they take under 20 ms, as
# they do here): the window traces them again in smaller passes, the series goes on, and
# its snapshots are headless --spp K all the same. (Where frames stayed smaller, nothing is
# cut and the same checks hold.)
#
# usage: window_snapshots_test.sh RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

readonly WIDTH=64 HEIGHT=48 SPP=4096
readonly COUNTS=(1 7 64 255 256 257 1000 4096)
readonly CAMERA=(--camera-pos 3,4,2 --camera-target 0,0,-8 --camera-up 0,1,0.2)

run_inside_xvfb() {
    cd "$output_dir"
    local log=window.log name id list
    name=$(basename "$scene")
    list=$(IFS=,; echo "${COUNTS[*]}")
    timeout 600 "$raytracer" "$scene" --validate --width $WIDTH --height $HEIGHT --spp $SPP \
        --snapshots "$list" "${CAMERA[@]}" > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$name" 90) || { fail "no window (log $log)"; cat "$log"; exit 1; }
    # The last snapshot comes with the last sample: the window is then done refining.
    if ! wait_for_log "$pid" "$log" "Screenshot: wrote" ${#COUNTS[@]} 480; then
        fail "the window wrote $(grep -cF "Screenshot: wrote" "$log" || true) of ${#COUNTS[@]} snapshots (log $log)"
    fi
    local k line shot replay
    for k in "${COUNTS[@]}"; do
        line=$(grep -F "Screenshot: wrote" "$log" | grep -F -- "-${k}spp.png (" | head -n 1 || true)
        if [[ -z $line ]]; then
            fail "no snapshot at $k samples per pixel (log $log)"
            continue
        fi
        shot=$(sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/' <<< "$line")
        if ! grep -qF "(${WIDTH}x${HEIGHT}, $k samples per pixel" <<< "$line"; then
            fail "snapshot $k: the line names another count: $line"
            continue
        fi
        headless "headless-$k.png" "${CAMERA[@]}" --spp "$k"
        if "$image_diff" "headless-$k.png" "$shot" --tolerance 0 --min-match 100 > "diff-$k.txt" 2>&1; then
            pass "at $k samples per pixel the window wrote $shot, identical to headless --spp $k"
        else
            fail "at $k samples per pixel $shot differs from headless --spp $k: $(cat "diff-$k.txt")"
        fi
        # The headless command printed with it, run as a shell would, renders the same bytes.
        replay=$(sed -E 's/^.*the same image headless: Raytracer //; s/ -o OUT\.png / -o replayed-'"$k"'.png /' <<< "$line")
        if eval "env -u DISPLAY timeout 300 \"\$raytracer\" $replay" > "replayed-$k.log" 2>&1 &&
            cmp -s "headless-$k.png" "replayed-$k.png"; then
            pass "the command printed with snapshot $k renders the same PNG"
        else
            fail "the command printed with snapshot $k ($replay) renders another image (log replayed-$k.log)"
        fi
    done
    expect_clean_quit "$pid" "$id" q "$log"
    cut_short_frames
    echo "window snapshots test: $passed passed, $failed failed (files in $output_dir)"
    ((failed == 0))
}

# The knot's window: every snapshot of the series is written, each headless --spp K.
cut_short_frames() {
    local log=window-knot.log model=knot.scene id k shot
    python3 "$(dirname "${BASH_SOURCE[0]}")/../../tools/make_mesh.py" --triangles 2000 --out "$model" > /dev/null ||
        { fail "tools/make_mesh.py wrote no knot"; return; }
    timeout 400 "$raytracer" "$model" --validate --accel none --width 8 --height 8 --spp 256 \
        --snapshots 1,100,256 > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$model" 90) || { fail "no knot window (log $log)"; return; }
    wait_for_log "$pid" "$log" "Screenshot: wrote" 3 300 || fail "the knot's window wrote $(grep -cF "Screenshot: wrote" "$log" || true) of 3 snapshots (log $log)"
    for k in 1 100 256; do
        shot=$(grep -F "Screenshot: wrote" "$log" | grep -F -- "-${k}spp.png (" | sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/' | head -n 1 || true)
        env -u DISPLAY timeout 300 "$raytracer" "$model" --accel none --width 8 --height 8 --spp "$k" \
            -o "knot-$k.png" > "knot-$k.log" 2>&1 || fail "headless knot --spp $k (log knot-$k.log)"
        if [[ -n $shot ]] && "$image_diff" "knot-$k.png" "$shot" --tolerance 0 --min-match 100 > "knot-diff-$k.txt" 2>&1; then
            pass "frames cut short and traced again: the knot at $k samples per pixel is headless --spp $k"
        else
            fail "the knot's snapshot at $k ($shot) differs from headless --spp $k: $(cat "knot-diff-$k.txt" 2>/dev/null)"
        fi
    done
    grep -qF "Snapshots: the view changed" "$log" && fail "a frame traced again ended the series (log $log)"
    expect_clean_quit "$pid" "$id" q "$log"
}

window_test_main "$0" "$@"
