#!/usr/bin/env bash
# The interactive window under Xvfb: it must show exactly the pixels of the headless
# PNG (tolerance 0), for two scenes and a textured model, re-render at the new size after a resize, quit on Escape or Q
# with status 0, close cleanly on a window manager's close request while refining, and
# keep the validation layer silent throughout.
#
# usage: window_test.sh RAYTRACER SCENES_DIR OUTPUT_DIR IMAGE_DIFF
# Needs xvfb-run, xauth, xwininfo (x11-utils), xwd (x11-apps), xdotool and python3
# (tools/build/install_deps.sh). The window is captured with xwd and converted to PNG by a
# small python3 reader below, so ImageMagick is not needed.
set -euo pipefail

readonly WIDTH=320 HEIGHT=240               # the window as opened
readonly RESIZED_WIDTH=400 RESIZED_HEIGHT=300 # after `xdotool windowsize`
readonly WINDOW_DEADLINE=90 # seconds for the first frame (lavapipe with validation starts slowly)

# xwd_to_png and find_window come from window_lib.sh, shared with the other window tests.
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

# Waits for the window of NAME at WxH, then captures it until it equals EXPECTED.PNG.
# The present may reach the X server a moment after the title changes, so a few
# captures are allowed; a wrong pixel stays wrong in all of them.
check_window_shows() { # PID NAME W H EXPECTED.PNG PREFIX
    local pid=$1 name=$2 width=$3 height=$4 expected=$5 prefix=$6 id="" deadline=$((SECONDS + WINDOW_DEADLINE))
    while [[ -z $id ]]; do
        if ! kill -0 "$pid" 2>/dev/null; then fail "$prefix: the program ended before showing ${width}x${height}"; return 1; fi
        if ((SECONDS > deadline)); then fail "$prefix: no window titled '$name - ${width}x${height} - 1/1 spp - ...' within ${WINDOW_DEADLINE} s"; return 1; fi
        sleep 0.5
        id=$(find_window "$name" "$width" "$height")
    done
    WINDOW_ID=$id
    local size
    for _ in 1 2 3 4 5 6; do
        sleep 0.5
        timeout 10 xwd -id "$id" -silent > "$prefix.xwd" || true
        size=$(xwd_to_png "$prefix.xwd" "$prefix.png") || size="unreadable (see $prefix.xwd)"
        if [[ $size != "${width}x${height}" ]]; then
            fail "$prefix: the window's client area is $size, expected ${width}x${height}"
            return 1
        fi
        if timeout 30 "$image_diff" "$expected" "$prefix.png" --tolerance 0 --min-match 100 \
            --diff "$prefix-diff.png" > "$prefix-diff.txt"; then
            pass "$prefix: the window shows the headless pixels exactly ($(cat "$prefix-diff.txt"))"
            return 0
        fi
    done
    fail "$prefix: the window differs from the headless render: $(cat "$prefix-diff.txt")" \
         "(headless $expected, window $prefix.png, diff $prefix-diff.png)"
    return 1
}

# Sends KEY to the window and expects a clean exit (status 0, no validation message) and
# the help line on stderr.
check_quits() { # PID KEY LOG PREFIX
    local pid=$1 key=$2 log=$3 prefix=$4 status=0
    quit_with_key "$pid" "$WINDOW_ID" "$key" || status=$?
    judge_exit "$status" "$log" "$prefix" "the $key key" || return 0
    if ! grep -qF "Window: Esc or Q quits" "$log"; then
        fail "$prefix: no help line on stderr (log $log)"
    else
        pass "$prefix: $key quit the window cleanly, validation silent"
    fi
}

# The window manager's close button while frames are being traced: the progressive view of
# SCENE at 640x480 refines towards 1024 samples, so a frame is in flight when the request
# comes; the program must finish that frame, release everything and exit with status 0.
check_close_mid_frame() { # SCENE
    local scene=$1 name pid id status=0 log=close-window.log deadline
    name=$(basename "$scene")
    timeout 120 "$raytracer" "$scene" --validate --width 640 --height 480 > "$log" 2>&1 &
    pid=$!
    if ! id=$(wait_for_window "$pid" "$name" "$WINDOW_DEADLINE"); then
        fail "close-window: no window for $name (log $log)"
        kill "$pid" 2>/dev/null || true; wait "$pid" || true
        return
    fi
    # Once the first frame is shown (its title names the size), a moment later: a few
    # samples in, far from 1024, so the device is busy.
    deadline=$((SECONDS + WINDOW_DEADLINE))
    while ! timeout 10 xwininfo -root -tree | grep -qF "\"$name - 640x480 - "; do
        if ! kill -0 "$pid" 2>/dev/null || ((SECONDS > deadline)); then
            fail "close-window: no frame shown (log $log)"
            kill "$pid" 2>/dev/null || true; wait "$pid" || true
            return
        fi
        sleep 0.3
    done
    sleep 1
    if ! request_close "$id"; then
        fail "close-window: the WM_DELETE_WINDOW message could not be sent"
        kill "$pid" 2>/dev/null || true; wait "$pid" || true
        return
    fi
    wait_for_exit "$pid" || status=$?
    judge_exit "$status" "$log" close-window "the close request" &&
        pass "close-window: the close request mid-refinement ended the program with status 0, validation silent"
}

# Headless renders of SCENE at WxH (no display at all, as a user without one would run it).
render_headless() { # SCENE W H OUT.PNG
    env -u DISPLAY timeout 120 "$raytracer" "$1" --validate -o "$4" --width "$2" --height "$3" \
        > "$4.log" 2>&1 || { fail "headless render of $1 at $2x$3 failed (log $4.log)"; return 1; }
}

# One scene: headless renders, then the window, a resize (for the first scene) and a quit.
test_scene() { # SCENE KEY RESIZE(yes|no)
    local scene=$1 key=$2 resize=$3 name stem pid
    name=$(basename "$scene")
    stem=${name%.scene}
    render_headless "$scene" "$WIDTH" "$HEIGHT" "$stem-headless.png" || return 0
    if [[ $resize == yes ]]; then
        render_headless "$scene" "$RESIZED_WIDTH" "$RESIZED_HEIGHT" "$stem-headless-resized.png" || return 0
    fi
    # --spp 1: refinement stops at the headless default of one sample per pixel.
    timeout 120 "$raytracer" "$scene" --validate --spp 1 --width "$WIDTH" --height "$HEIGHT" > "$stem-window.log" 2>&1 &
    pid=$!
    if ! check_window_shows "$pid" "$name" "$WIDTH" "$HEIGHT" "$stem-headless.png" "$stem-window"; then
        kill "$pid" 2>/dev/null || true
        wait "$pid" || true
        return 0
    fi
    if [[ $resize == yes ]]; then
        # Several sizes in a row: swapchain recreation under pressure, ending at one size.
        timeout 10 xdotool windowsize "$WINDOW_ID" 240 180 windowsize "$WINDOW_ID" 520 390 \
            windowsize "$WINDOW_ID" "$RESIZED_WIDTH" "$RESIZED_HEIGHT" || fail "$stem: xdotool windowsize failed"
        check_window_shows "$pid" "$name" "$RESIZED_WIDTH" "$RESIZED_HEIGHT" \
            "$stem-headless-resized.png" "$stem-window-resized" || true
    fi
    check_quits "$pid" "$key" "$stem-window.log" "$stem-window"
}

# A textured model (a quad with a checkerboard map_Kd, written here): the window samples
# its texture as the headless render does.
write_textured_model() { # OUT.obj
    PYTHONPATH="$(dirname "$(absolute "$0")")/../../tools/lib" python3 - "$1" <<'PYTHON'
import os, sys
from png_write import write_png
obj = sys.argv[1]
base = os.path.splitext(obj)[0]
rows = [[(220, 60, 40) if (x // 4 + y // 4) % 2 else (40, 90, 200) for x in range(32)] for y in range(32)]
write_png(base + ".png", 32, 32, rows)
with open(base + ".mtl", "w") as out:
    out.write("newmtl board\nKd 0.5 0.5 0.5\nmap_Kd %s.png\n" % os.path.basename(base))
with open(obj, "w") as out:
    out.write("mtllib %s.mtl\nusemtl board\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n" % os.path.basename(base))
PYTHON
}

# Inside Xvfb: everything runs in OUTPUT_DIR, which keeps the images and logs.
run_inside_xvfb() {
    cd "$output_dir"
    local scenes=() first
    [[ -f $scenes_dir/showcase.scene ]] && scenes+=("$scenes_dir/showcase.scene")
    for first in "$scenes_dir"/*.scene; do
        [[ -f $first && ${#scenes[@]} -lt 2 && $first != "${scenes[0]-}" ]] && scenes+=("$first")
    done
    if ((${#scenes[@]} == 0)); then
        echo "window test: no *.scene in $scenes_dir"
        exit 1
    fi
    test_scene "${scenes[0]}" Escape yes
    [[ ${#scenes[@]} -gt 1 ]] && test_scene "${scenes[1]}" q no
    write_textured_model "$output_dir/textured.obj"
    test_scene "$output_dir/textured.obj" q no
    check_close_mid_frame "${scenes[0]}"
    echo "window test: $passed passed, $failed failed (images and logs in $output_dir)"
    ((failed == 0))
}

if [[ $# == 5 && $1 == --inside-xvfb ]]; then
    shift
    raytracer=$1 scenes_dir=$2 output_dir=$3 image_diff=$4
    run_inside_xvfb
    exit
fi

if (($# != 4)); then
    echo "usage: $0 RAYTRACER SCENES_DIR OUTPUT_DIR IMAGE_DIFF" >&2
    exit 2
fi
require_window_tools
mkdir -p "$3"
raytracer=$(absolute "$1") scenes_dir=$(absolute "$2") output_dir=$(absolute "$3") image_diff=$(absolute "$4")
rm -f "$output_dir"/*.png "$output_dir"/*.xwd "$output_dir"/*.log "$output_dir"/*.txt
# One X server for the whole test.
run_in_xvfb 280 1024x768x24 "$(absolute "$0")" --inside-xvfb "$raytracer" "$scenes_dir" "$output_dir" "$image_diff"
