#!/usr/bin/env bash
# The overlay (H, --overlay) under Xvfb: shown, it is on the window (the window's pixels
# differ from headless) but never in P's screenshot (equal to headless --spp N, tolerance
# 0), and it covers at most 15% of a 640x480 view; hidden with H, the window shows the
# headless pixels exactly; shown again, a real click on its "grid" sampler button
# re-specialises the kernel, and the next refined P screenshot equals headless --sampler
# grid; a resize with it shown refines again; Q quits with status 0 and the validation
# layer stays silent throughout.
#
# usage: window_overlay_test.sh RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

readonly WIDTH=320 HEIGHT=240 SPP=4
# Where ImGui's default style (font 13 px, padding 8, frame padding 4x3, spacing 8x4) puts
# the label of the "grid" radio button of the panel at (8, 8): the first row after the three
# lines of figures and a separator, after the "sampler" label (window coordinates).
# The folded "kernel" section's header, and the "grid" sampler button once it is unfolded.
readonly KERNEL_X=60 KERNEL_Y=59 GRID_X=90 GRID_Y=82

# The folded overlay's panel covers at most this share (%) of a 640x480 view: its size in
# pixels does not depend on the window's.
readonly MAX_SHARE=15
TOOLS_LIB=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../tools/lib" && pwd)
readonly TOOLS_LIB

# "W H": the box around the pixels of SHOWN.PNG that differ from HEADLESS.PNG (the panel).
overlay_box() { # HEADLESS.PNG SHOWN.PNG
    python3 - "$1" "$2" "$TOOLS_LIB" <<'EOF'
import sys
sys.path.insert(0, sys.argv[3])
from png_read import read_png
_w, _h, plain = read_png(sys.argv[1])
width, height, shown = read_png(sys.argv[2])
differ = [(x, y) for y in range(min(height, len(plain))) for x in range(min(width, len(plain[0])))
          if shown[y][x][:3] != plain[y][x][:3]]
if not differ:
    sys.exit(1)
xs, ys = [x for x, _y in differ], [y for _x, y in differ]
print(max(xs) - min(xs) + 1, max(ys) - min(ys) + 1)
EOF
}

# The path of the COUNTth screenshot that LOG reports.
screenshot_path() { # LOG COUNT
    grep -F "Screenshot: wrote" "$1" | sed -n "$2p" | sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/'
}

# P, then the COUNTth screenshot compared with EXPECTED.PNG at tolerance 0.
p_matches() { # PID ID LOG COUNT EXPECTED.PNG WHAT
    local pid=$1 id=$2 log=$3 count=$4 expected=$5 what=$6 shot
    press_key "$id" p
    if ! wait_for_log "$pid" "$log" "Screenshot: wrote" "$count" 30; then
        fail "$what: P wrote no screenshot (log $log)"
        return
    fi
    shot=$(screenshot_path "$log" "$count")
    if [[ -f $shot ]] && "$image_diff" "$expected" "$shot" --tolerance 0 --min-match 100 > "shot-$count-diff.txt" 2>&1; then
        pass "$what: P wrote $shot, identical to $expected ($(cat "shot-$count-diff.txt"))"
    else
        fail "$what: P's $shot differs from $expected: $(cat "shot-$count-diff.txt" 2>/dev/null)"
    fi
}

run_inside_xvfb() {
    cd "$output_dir"
    headless r2.png
    headless grid.png --sampler grid
    if "$image_diff" r2.png grid.png --tolerance 0 --min-match 100 > samplers-diff.txt 2>&1; then
        fail "the r2 and grid renders are equal: the click could not be told apart"
    fi
    local log=window.log name id
    name=$(basename "$scene")
    timeout 400 "$raytracer" "$scene" --validate --overlay --width $WIDTH --height $HEIGHT --spp $SPP \
        > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$name" 90) || { fail "no window (log $log)"; cat "$log"; exit 1; }
    wait_for_log "$pid" "$log" "Refined: $SPP samples" 1 60 || fail "the window never refined (log $log)"

    # Shown: on the window, not in P.
    sleep 0.5
    if window_matches "$id" r2.png shown-window 4; then
        fail "--overlay: the window shows no overlay (it equals the headless render)"
    else
        pass "--overlay: the overlay is on the window ($(cat shown-window-diff.txt | head -c 200))"
    fi
    local box box_w box_h
    if box=$(overlay_box r2.png shown-window.png) && read -r box_w box_h <<< "$box" &&
        ((box_w * box_h * 100 <= MAX_SHARE * 640 * 480)); then
        pass "the folded overlay is ${box_w}x$box_h pixels: at most $MAX_SHARE% of a 640x480 view"
    else
        fail "the folded overlay covers ${box:-nothing measurable}: more than $MAX_SHARE% of a 640x480 view"
    fi
    p_matches "$pid" "$id" "$log" 1 r2.png "overlay shown"

    # Hidden: the window's pixels are the headless pixels.
    press_key "$id" h
    if window_matches "$id" r2.png hidden-window; then
        pass "H hid the overlay: the window equals headless ($(cat hidden-window-diff.txt))"
    else
        fail "H: the window differs from headless with the overlay hidden: $(cat hidden-window-diff.txt)"
    fi

    # Shown again, a click unfolds "kernel" and a real click on "grid" rebuilds the kernel
    # with --sampler grid.
    press_key "$id" h
    timeout 10 xdotool windowfocus --sync "$id" || true
    timeout 10 xdotool mousemove --window "$id" $KERNEL_X $KERNEL_Y || true
    sleep 1
    timeout 10 xdotool mousedown 1 || true
    sleep 0.5
    timeout 10 xdotool mouseup 1 || true
    sleep 1
    timeout 10 xdotool mousemove --window "$id" $GRID_X $GRID_Y || true
    sleep 1
    timeout 10 xdotool mousedown 1 || true
    sleep 0.5
    timeout 10 xdotool mouseup 1 || true
    if wait_for_log "$pid" "$log" "Refined: $SPP samples" 2 60; then
        p_matches "$pid" "$id" "$log" 2 grid.png "a click on the overlay's grid sampler"
        if grep -F "Screenshot: wrote" "$log" | sed -n 2p | grep -qF -- "--sampler grid"; then
            pass "the screenshot's headless command names --sampler grid"
        else
            fail "the screenshot's headless command does not name --sampler grid (log $log)"
        fi
    else
        fail "the click on grid did not restart refinement (log $log)"
    fi
    # A resize with the overlay shown: its framebuffers follow the new swapchain.
    timeout 10 xdotool windowsize "$id" 400 300 || true
    if wait_for_log "$pid" "$log" "Refined: $SPP samples per pixel at 400x300" 1 60; then
        pass "resized with the overlay shown: refined again at 400x300"
    else
        fail "no refined frame at 400x300 after the resize (log $log)"
    fi
    expect_clean_quit "$pid" "$id" q "$log"
    echo "window overlay test: $passed passed, $failed failed (files in $output_dir)"
    ((failed == 0))
}

window_test_main "$0" "$@"
