#!/usr/bin/env bash
# Hot reload and robustness of the window under Xvfb, with the shaders copied out by
# --dump-shaders and compiled from there (--shader-dir):
#   saving the scene re-renders it (the window equals the new headless render exactly);
#   a scene with a parse error prints FILE:LINE and keeps the last good image;
#   R reloads; editing trace.comp recompiles (the window equals a headless render with the
#   same --shader-dir); a shader syntax error prints glslang's log with file and line,
#   the program keeps running and keeps the last good kernel;
#   a resize storm (sizes down to 1x1) is survived and ends in the exact image, as does
#   hiding and showing the window (unmap, map);
#   Escape quits with status 0 and the validation layer stays silent.
#
# usage: window_reload_test.sh RAYTRACER OUTPUT_DIR IMAGE_DIFF
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

readonly WIDTH=160 HEIGHT=120 FINAL_WIDTH=180 FINAL_HEIGHT=130
readonly RELOAD_SECONDS=20 # generous: lavapipe shares two cores with other tests

scene_text() { # DIFFUSE of the first sphere
    printf '3\namb: 0.1 0.1 0.1\nsphere\npos: 0 0 -4\nrad: 1\ndif: %s\nspe: 0.3 0.3 0.3\nshi: 20\n' "$1"
    printf 'sphere\npos: 1.5 0.5 -5\nrad: 0.8\ndif: 0.2 0.7 0.3\nspe: 0 0 0\nshi: 1\n'
    printf 'light\npos: 3 3 0\ncol: 1 1 1\n'
}

headless() { # OUT.PNG W H
    env -u DISPLAY timeout 120 "$raytracer" scene.scene -o "$1" --width "$2" --height "$3" --shader-dir shaders \
        > "$1.log" 2>&1 || { echo "FAIL: headless render $1 (log $1.log)"; exit 1; }
}

run_inside_xvfb() {
    cd "$output_dir"
    rm -rf shaders
    "$raytracer" --dump-shaders shaders > dump.log 2>&1 || { fail "--dump-shaders failed (log dump.log)"; exit 1; }
    [[ -f shaders/trace.comp && -f shaders/shared.h ]] || { fail "--dump-shaders wrote no trace.comp/shared.h"; exit 1; }
    scene_text "0.8 0.2 0.2" > scene.scene
    headless first.png $WIDTH $HEIGHT

    local log=window.log id reloads=0
    timeout 400 "$raytracer" scene.scene --validate --spp 1 --width $WIDTH --height $HEIGHT --shader-dir shaders \
        > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" scene.scene 90) || { fail "no window (log $log)"; cat "$log"; exit 1; }
    if wait_for_log "$pid" "$log" "Refined:" 1 60 && window_matches "$id" first.png first-window; then
        pass "--shader-dir: the window equals the headless render"
    else
        fail "the first image differs from first.png (log $log)"
    fi

    # Save a changed scene.
    scene_text "0.2 0.3 0.9" > scene.scene.new
    mv scene.scene.new scene.scene # as editors save: a new file renamed over the old
    headless edited.png $WIDTH $HEIGHT
    if wait_for_log "$pid" "$log" "Reloaded $(pwd)/scene.scene" 1 $RELOAD_SECONDS ||
        wait_for_log "$pid" "$log" "Reloaded scene.scene" 1 1; then
        reloads=1
        if window_matches "$id" edited.png edited-window; then pass "a saved scene is re-rendered exactly"
        else fail "after the scene edit the window differs from edited.png"; fi
    else
        fail "the scene edit was not picked up within ${RELOAD_SECONDS} s (log $log)"
    fi

    # A parse error: message with file and line, the last good image stays.
    scene_text "0.2 0.3 0.9" | sed 's/^rad: 1$/rad: x/' > scene.scene
    if wait_for_log "$pid" "$log" "scene.scene:5: error:" 1 $RELOAD_SECONDS &&
        wait_for_log "$pid" "$log" "Keeping the last good scene" 1 5 && window_matches "$id" edited.png broken-scene-window; then
        pass "a scene parse error names scene.scene:5 and keeps showing the last good scene"
    else
        fail "no 'scene.scene:5: error:' or the image changed (log $log)"
    fi
    scene_text "0.2 0.3 0.9" > scene.scene
    wait_for_log "$pid" "$log" "Reloaded" $((reloads + 1)) $RELOAD_SECONDS || fail "the repaired scene was not reloaded"
    reloads=$((reloads + 1))

    press_key "$id" r
    if wait_for_log "$pid" "$log" "Reloaded" $((reloads + 1)) $RELOAD_SECONDS; then pass "R reloads"
    else fail "R did not reload (log $log)"; fi

    # Edit the kernel: invert the output.
    local store='imageStore(outputImage, ivec2(place), vec4(level / 255.0, 1.0));'
    if grep -qF "$store" shaders/trace.comp; then
        sed -i 's|vec4(level / 255.0, 1.0));|vec4(1.0 - level / 255.0, 1.0));|' shaders/trace.comp
        headless inverted.png $WIDTH $HEIGHT
        if wait_for_log "$pid" "$log" "Reloaded the shaders" 1 $RELOAD_SECONDS && window_matches "$id" inverted.png inverted-window; then
            pass "a saved shader is recompiled: the window equals headless with the same --shader-dir"
        else
            fail "the shader edit did not show (log $log)"
        fi
    else
        fail "trace.comp no longer holds '$store'; update this test"
    fi

    # A syntax error: glslang's log with file and line, the program goes on with the last kernel.
    cp shaders/camera.glsl camera.glsl.good
    printf 'this is not glsl\n' >> shaders/camera.glsl
    if wait_for_log "$pid" "$log" "camera.glsl:" 1 $RELOAD_SECONDS && grep -qE "ERROR: .*camera\.glsl:[0-9]+:" "$log" &&
        wait_for_log "$pid" "$log" "Keeping the last good kernel" 1 5 && kill -0 "$pid" &&
        window_matches "$id" inverted.png broken-shader-window; then
        pass "a shader syntax error prints '$(grep -m1 -E "ERROR: .*camera\.glsl" "$log")' and keeps the last kernel"
    else
        fail "no glslang error with file and line, or the program stopped (log $log)"
    fi
    cp camera.glsl.good shaders/camera.glsl
    wait_for_log "$pid" "$log" "Reloaded the shaders" 2 $RELOAD_SECONDS || fail "the repaired shader was not reloaded"

    # Resize storm, down to 1x1, ending at the final size.
    local sizes=(1 1 300 200 40 30 1 1 500 400 90 60 260 190 2 3 350 120 120 350)
    for ((k = 0; k < ${#sizes[@]}; k += 2)); do
        timeout 5 xdotool windowsize "$id" "${sizes[k]}" "${sizes[k + 1]}" 2>/dev/null || true
        sleep 0.05
    done
    timeout 5 xdotool windowsize "$id" $FINAL_WIDTH $FINAL_HEIGHT || true
    headless final.png $FINAL_WIDTH $FINAL_HEIGHT
    local deadline=$((SECONDS + 60)) found=""
    while [[ -z $found ]] && ((SECONDS < deadline)) && kill -0 "$pid" 2>/dev/null; do
        sleep 0.3
        found=$(find_window scene.scene $FINAL_WIDTH $FINAL_HEIGHT 1)
    done
    if [[ -n $found ]] && window_matches "$id" final.png final-window; then
        pass "survived a resize storm of $((${#sizes[@]} / 2)) sizes and shows the exact image at ${FINAL_WIDTH}x${FINAL_HEIGHT}"
    else
        fail "after the resize storm: running $(kill -0 "$pid" 2>/dev/null && echo yes || echo no), image differs or wrong size (log $log)"
    fi

    # Hidden and shown again (what minimise and restore do without a window manager): the
    # exposed window is presented again, still exact.
    timeout 5 xdotool windowunmap "$id" || true
    sleep 1
    timeout 5 xdotool windowmap "$id" || true
    if kill -0 "$pid" 2>/dev/null && window_matches "$id" final.png remapped-window; then
        pass "unmapped and mapped again: still running, the exact image is shown again"
    else
        fail "after unmap/map the program stopped or the image differs (log $log)"
    fi

    expect_clean_quit "$pid" "$id" Escape "$log"
    echo "window reload test: $passed passed, $failed failed (files in $output_dir)"
    ((failed == 0))
}

if [[ $# == 4 && $1 == --inside-xvfb ]]; then
    raytracer=$2 output_dir=$3 image_diff=$4
    run_inside_xvfb
    exit
fi
if (($# != 3)); then
    echo "usage: $0 RAYTRACER OUTPUT_DIR IMAGE_DIFF" >&2
    exit 2
fi
require_window_tools
mkdir -p "$2"
rm -rf "$2"/*.png "$2"/*.xwd "$2"/*.log "$2"/*.txt "$2"/shaders
run_in_xvfb 280 1024x768x24 "$(absolute "$0")" --inside-xvfb "$(absolute "$1")" "$(absolute "$2")" "$(absolute "$3")"
