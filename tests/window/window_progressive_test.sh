#!/usr/bin/env bash
# The progressive view under Xvfb: with --spp N the window refines to exactly the headless
# --spp N image (tolerance 0), also from a moved camera; P writes a PNG identical to it and
# prints a headless command that renders it again; Shift+P once refined writes the same; O
# prints the camera as options; mid-refinement (a second window), P writes what is shown
# with its sample count K in its name, equal to headless --spp K, Shift+P waits, says when a
# camera move retargets it and that it was dropped when the window closes first;
# I prints the story of the pixel under the mouse, the JSON of headless --pixel, and so does a
# left click with I held for the clicked pixel, without orbiting;
# V recreates the swapchain; a mouse drag moves the camera and C and Home reset it to the
# default camera; Q quits with status 0 and the validation layer stays silent; an OBJ model's
# light rig follows an orbit (the window equals the headless render of that camera).
#
# usage: window_progressive_test.sh RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

readonly WIDTH=200 HEIGHT=150 SPP=4
readonly CAMERA=(--camera-pos 3,4,2 --camera-target 0,0,-8 --camera-up 0,1,0.2)

run_inside_xvfb() {
    cd "$output_dir"
    headless moved.png "${CAMERA[@]}"
    headless spec.png
    local log=window.log name id
    name=$(basename "$scene")
    timeout 400 "$raytracer" "$scene" --validate --width $WIDTH --height $HEIGHT --spp $SPP "${CAMERA[@]}" \
        > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$name" 90) || { fail "no window (log $log)"; cat "$log"; exit 1; }

    if wait_for_log "$pid" "$log" "Refined: $SPP samples" 1 60 && window_matches "$id" moved.png moved-window; then
        pass "moved camera: after $SPP samples the window equals headless --spp $SPP ($(cat moved-window-diff.txt))"
    else
        fail "moved camera: the window differs from moved.png (see moved-window.png, $(cat moved-window-diff.txt 2>/dev/null))"
    fi

    press_key "$id" p
    if wait_for_log "$pid" "$log" "Screenshot: wrote" 1 30; then
        local shot
        shot=$(grep -F "Screenshot: wrote" "$log" | head -n 1 | sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/')
        if [[ -f $shot ]] && "$image_diff" moved.png "$shot" --tolerance 0 --min-match 100 > shot-diff.txt 2>&1; then
            pass "P wrote $shot, identical to the headless render ($(cat shot-diff.txt))"
        else
            fail "P: $shot differs from moved.png: $(cat shot-diff.txt 2>/dev/null)"
        fi
        # The command printed with it, run as a shell would, renders the same PNG.
        local replay
        replay=$(grep -F "Screenshot: wrote" "$log" | head -n 1 |
            sed -E 's/^.*; the same image headless: Raytracer //; s/ -o OUT\.png / -o replayed.png /')
        if eval "env -u DISPLAY timeout 120 \"\$raytracer\" $replay" > replayed.log 2>&1 &&
            "$image_diff" moved.png replayed.png --tolerance 0 --min-match 100 > replay-diff.txt 2>&1; then
            pass "P's headless command renders the same PNG ($(cat replay-diff.txt))"
        else
            fail "P's headless command ($replay) differs from moved.png: $(cat replay-diff.txt 2>/dev/null) (log replayed.log)"
        fi
    else
        fail "P wrote no screenshot (log $log)"
    fi

    # Shift+P once refinement is done writes at once: the same image again.
    press_key "$id" shift+p
    if wait_for_log "$pid" "$log" "Screenshot: wrote" 2 30; then
        local second
        second=$(grep -F "Screenshot: wrote" "$log" | sed -n 2p | sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/')
        if [[ $second == *-screenshot-2-${SPP}spp.png ]] && "$image_diff" moved.png "$second" --tolerance 0 --min-match 100 > shot2-diff.txt 2>&1; then
            pass "Shift+P once refined wrote $second at once, identical to the headless render"
        else
            fail "Shift+P: $second is misnamed or differs from moved.png: $(cat shot2-diff.txt 2>/dev/null)"
        fi
    else
        fail "Shift+P wrote no screenshot (log $log)"
    fi

    # O prints the camera as options, word for word.
    press_key "$id" o
    if wait_for_log "$pid" "$log" "Camera: --camera-pos 3,4,2 --camera-target 0,0,-8 --camera-up 0,1,0.2 --fov 60" 1 20; then
        pass "O printed the camera as options"
    else
        fail "O: no 'Camera: --camera-pos 3,4,2 ...' line (log $log)"
    fi

    # I prints the story of the pixel under the mouse (docs/pixel_story.md): the very JSON
    # that headless --pixel prints for that pixel at the same settings.
    env -u DISPLAY timeout 120 "$raytracer" "$scene" --pixel 50,40 --width $WIDTH --height $HEIGHT --spp $SPP \
        "${CAMERA[@]}" > story-headless.json 2> story-headless.log || fail "headless --pixel 50,40 (log story-headless.log)"
    timeout 10 xdotool mousemove --window "$id" 50 40 || true
    sleep 0.3
    press_key "$id" i
    if wait_for_log "$pid" "$log" "Pixel story: pixel 50,40 printed on stdout" 1 30; then
        sed -n '/^{"renderer": "gpu"/,/"pixel_8bit"/p' "$log" > story-window.json
        if [[ -s story-headless.json ]] && cmp -s story-headless.json story-window.json; then
            pass "I printed the story of pixel 50,40, identical to headless --pixel 50,40"
        else
            fail "I: the window's story (story-window.json) differs from headless --pixel (story-headless.json)"
        fi
    else
        fail "I printed no story of pixel 50,40 (log $log)"
    fi

    # A left click with I held prints the story of the clicked pixel, not the one under the
    # mouse when I went down, and starts no orbit (the view stays the headless image).
    env -u DISPLAY timeout 120 "$raytracer" "$scene" --pixel 120,90 --width $WIDTH --height $HEIGHT --spp $SPP \
        "${CAMERA[@]}" > story-click-headless.json 2> story-click-headless.log || fail "headless --pixel 120,90 (log story-click-headless.log)"
    timeout 10 xdotool keydown --window "$id" i sleep 0.3 mousemove --window "$id" 120 90 sleep 0.3 click 1 \
        sleep 0.3 keyup --window "$id" i || true
    if wait_for_log "$pid" "$log" "Pixel story: clicked pixel 120,90 printed on stdout" 1 30; then
        # The last story in the log is the click's.
        awk '/^\{"renderer": "gpu"/ { story = ""; inside = 1 } inside { story = story $0 "\n" }
             /"pixel_8bit"/ { if (inside) last = story; inside = 0 } END { printf "%s", last }' "$log" > story-click-window.json
        if [[ -s story-click-headless.json ]] && cmp -s story-click-headless.json story-click-window.json; then
            pass "I held + left click printed the story of pixel 120,90, identical to headless --pixel 120,90"
        else
            fail "I + click: the window's story (story-click-window.json) differs from headless --pixel (story-click-headless.json)"
        fi
    else
        fail "I + click printed no story of the clicked pixel 120,90 (log $log)"
    fi
    if window_matches "$id" moved.png click-window; then
        pass "I + click started no orbit: the view is unchanged"
    else
        fail "I + click moved the camera (see click-window.png)"
    fi

    press_key "$id" v
    if wait_for_log "$pid" "$log" "Vsync off" 1 20 && window_matches "$id" moved.png vsync-window; then
        pass "V: swapchain recreated without vsync, the image is still exact"
    else
        fail "V: no 'Vsync off' or the image changed (log $log)"
    fi

    press_key "$id" c
    if wait_for_log "$pid" "$log" "Refined: $SPP samples" 2 60 && window_matches "$id" spec.png spec-window; then
        pass "C: reset to the default camera, equals the default headless render"
    else
        fail "C: the window differs from spec.png (see spec-window.png)"
    fi

    # Each camera move below must change the view; each reset must restore the default view
    # exactly. A move may finish several refinements, so the log is counted afresh each time.
    local x=$((WIDTH / 2)) y=$((HEIGHT / 2))
    moved_view() { # LABEL PREFIX: waits for a new refinement, expects a view unlike spec.png
        if wait_for_log "$pid" "$log" "Refined: $SPP samples" $((refined + 1)) 60 && ! window_matches "$id" spec.png "$2" 4; then
            pass "$1 moves the camera (the view changed)"
        else
            fail "$1 did not move the camera"
        fi
        sleep 1
    }
    reset_view() { # KEY PREFIX
        refined=$(grep -cF "Refined: $SPP samples" "$log")
        press_key "$id" "$1"
        if wait_for_log "$pid" "$log" "Refined: $SPP samples" $((refined + 1)) 60 && window_matches "$id" spec.png "$2"; then
            pass "$1: back to the default camera exactly"
        else
            fail "$1: the window differs from spec.png (see $2.png)"
        fi
    }
    local refined
    refined=$(grep -cF "Refined: $SPP samples" "$log")
    timeout 10 xdotool mousemove --window "$id" $x $y mousedown 1 mousemove --window "$id" $((x + 30)) $((y + 10)) \
        sleep 0.2 mousemove --window "$id" $((x + 60)) $((y + 20)) sleep 0.2 mouseup 1 || true
    moved_view "a left drag (orbit)" orbit-window
    reset_view Home home-window
    refined=$(grep -cF "Refined: $SPP samples" "$log")
    timeout 10 xdotool mousemove --window "$id" $x $y click 4 click 4 || true
    moved_view "the wheel (dolly)" dolly-window
    reset_view c c-after-dolly-window
    refined=$(grep -cF "Refined: $SPP samples" "$log")
    hold_key_until_moved "$pid" "$id" w "$log" 60 || true
    moved_view "holding W (fly)" fly-window
    reset_view Home home-after-fly-window
    refined=$(grep -cF "Refined: $SPP samples" "$log")
    hold_key_until_moved "$pid" "$id" Up "$log" 60 || true
    moved_view "holding Up (fly, as W)" up-window
    reset_view Home home-after-up-window

    expect_clean_quit "$pid" "$id" q "$log"
    mid_refinement
    model_rig
    echo "window progressive test: $passed passed, $failed failed (files in $output_dir)"
    ((failed == 0))
}

# A window that never finishes refining (--spp 65536): P writes what is shown, K samples
# per pixel, equal to headless --spp K (the r2 sampler's sample s does not depend on the
# count); Shift+P waits; a camera move retargets it, saying so; Q drops it, saying so.
mid_refinement() {
    local log=window-mid.log name id shot samples
    name=$(basename "$scene")
    timeout 400 "$raytracer" "$scene" --validate --width $WIDTH --height $HEIGHT --spp 65536 "${CAMERA[@]}" \
        > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$name" 90) || { fail "no second window (log $log)"; cat "$log"; return; }
    # P at whatever count the window has reached once it has traced something: the count it
    # names must be the image it writes (tests/window/window_snapshots_test.sh checks
    # chosen counts exactly).
    wait_for_samples "$pid" "$name" 1 60 || fail "the title never showed a sample (log $log)"
    press_key "$id" p
    if wait_for_log "$pid" "$log" "Screenshot: wrote" 1 30; then
        local line
        line=$(grep -F "Screenshot: wrote" "$log" | head -n 1)
        shot=$(sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/' <<< "$line")
        samples=$(sed -E 's/^.*, ([0-9]+) samples per pixel of 65536, still refining\).*$/\1/' <<< "$line")
        if [[ $samples =~ ^[0-9]+$ && $shot == *-${samples}spp.png ]]; then
            headless mid.png "${CAMERA[@]}" --spp "$samples"
            if "$image_diff" mid.png "$shot" --tolerance 0 --min-match 100 > mid-diff.txt 2>&1; then
                pass "P mid-refinement wrote $shot ($samples of 65536 samples), identical to headless --spp $samples"
            else
                fail "P mid-refinement: $shot differs from headless --spp $samples: $(cat mid-diff.txt)"
            fi
        else
            fail "P mid-refinement: unexpected line: $line"
        fi
    else
        fail "P mid-refinement wrote nothing (log $log)"
    fi
    press_key "$id" shift+p
    wait_for_log "$pid" "$log" "Screenshot: written once all 65536 samples per pixel are in (" 1 20 &&
        pass "Shift+P mid-refinement waits, and says so" || fail "Shift+P: no waiting message (log $log)"
    local x=$((WIDTH / 2)) y=$((HEIGHT / 2))
    timeout 10 xdotool mousemove --window "$id" $x $y mousedown 1 mousemove --window "$id" $((x + 30)) $((y + 10)) \
        sleep 0.2 mousemove --window "$id" $((x + 60)) $((y + 20)) sleep 0.2 mouseup 1 || true
    wait_for_log "$pid" "$log" "Screenshot: the view moved before its 65536 samples per pixel were in; the request now waits for the new view" 1 20 &&
        pass "a camera move after Shift+P retargets the request, and says so" ||
        fail "no message when the view moved after Shift+P (log $log)"
    expect_clean_quit "$pid" "$id" q "$log"
    if grep -qE "^Screenshot: dropped, the window closed at [0-9]+ of 65536 samples per pixel; the same image headless: Raytracer " "$log"; then
        pass "closing the window with Shift+P waiting says it was dropped, with the headless command"
    else
        fail "no 'Screenshot: dropped' line on closing (log $log)"
    fi
}

# An OBJ model's light rig follows the window's camera: after an orbit the window equals the
# headless render of the camera that O prints (tolerance 0), whose rig is placed for it.
model_rig() {
    local log=window-model.log id model=rig_cube.obj
    printf 'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n%s\n' \
        'f 1 4 3 2
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
f 5 6 7 8' > "$model"
    timeout 400 "$raytracer" "$model" --validate --width $WIDTH --height $HEIGHT --spp $SPP > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$model" 90) || { fail "no model window (log $log)"; cat "$log"; return; }
    wait_for_log "$pid" "$log" "Refined: $SPP samples" 1 60 || fail "the model window never refined (log $log)"
    local x=$((WIDTH / 2)) y=$((HEIGHT / 2)) refined
    refined=$(grep -cF "Refined: $SPP samples" "$log")
    timeout 10 xdotool mousemove --window "$id" $x $y mousedown 1 mousemove --window "$id" $((x + 80)) $((y + 10)) \
        sleep 0.2 mousemove --window "$id" $((x + 160)) $((y + 20)) sleep 0.2 mouseup 1 || true
    wait_for_log "$pid" "$log" "Refined: $SPP samples" $((refined + 1)) 60 || fail "no refinement after the orbit (log $log)"
    sleep 1
    press_key "$id" o
    if ! wait_for_log "$pid" "$log" "Camera: --camera-pos" 1 20; then
        fail "O printed no camera for the model (log $log)"
        expect_clean_quit "$pid" "$id" q "$log"
        return
    fi
    local -a camera
    read -r -a camera <<< "$(grep -F "Camera: --camera-pos" "$log" | tail -n 1 | sed -E 's/^Camera: //')"
    local scene=$model # headless renders $scene
    headless orbited-model.png "${camera[@]}"
    if window_matches "$id" orbited-model.png orbited-model-window; then
        pass "model rig: after an orbit the window equals the headless render of that camera (${camera[*]})"
    else
        fail "model rig: the orbited window differs from headless ${camera[*]} (see orbited-model-window.png)"
    fi
    # Lights fixed in the world (the default camera's scene, saved) light that view otherwise:
    # the match above is the rig following, not a rig that never moved.
    env -u DISPLAY timeout 60 "$raytracer" "$model" --save-scene rig_cube.scene > rig-save.log 2>&1 ||
        fail "--save-scene of the model (log rig-save.log)"
    scene=rig_cube.scene headless fixed-lights-model.png "${camera[@]}"
    if ! "$image_diff" orbited-model.png fixed-lights-model.png --tolerance 0 --min-match 100 > fixed-diff.txt 2>&1; then
        pass "model rig: the default camera's lights, fixed in the world, would light that view otherwise"
    else
        fail "model rig: the fixed lights give the same image, so the test shows nothing"
    fi
    expect_clean_quit "$pid" "$id" q "$log"
}

window_test_main "$0" "$@"
