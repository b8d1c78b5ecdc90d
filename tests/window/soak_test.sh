#!/usr/bin/env bash
# Soak: the window traces every frame (hidden --redraw-continuously) and is resized RESIZES
# times (default 40), each time until its title reports a frame traced at the new size, and
# then for another second. After a warm-up (the first quarter of the resizes) its resident
# memory (VmRSS) must not grow by more than RSS_BOUND_KB, and Q must still end it with
# status 0. The soak is counted in frames at new sizes, not in seconds: a slow machine soaks
# as many frames as a fast one, only for longer.
#
# usage: soak_test.sh RAYTRACER SCENE OUTPUT_DIR [RESIZES]
# Needs xvfb-run, xauth, xdotool (tools/build/install_deps.sh).
set -euo pipefail

readonly RSS_BOUND_KB=${RSS_BOUND_KB:-8192} # growth allowed after the warm-up

if [[ $# == 5 && $1 == --inside-xvfb ]]; then
    raytracer=$2 scene=$3 output_dir=$4 resizes=$5
    warmup=$((resizes / 4 > 2 ? resizes / 4 : 2))
    log=$output_dir/soak.log
    "$raytracer" "$scene" --window --redraw-continuously --width 160 --height 120 > "$log" 2>&1 &
    pid=$!
    name=$(basename "$scene")
    window=""
    for _ in $(seq 1 240); do # up to 120 s for the first frame
        window=$(xdotool search --name "^$name - " 2>/dev/null | head -n 1 || true)
        [[ -n $window ]] && break
        kill -0 "$pid" 2>/dev/null || { echo "FAIL: the program ended early (log $log)"; cat "$log"; exit 1; }
        sleep 0.5
    done
    [[ -n $window ]] || { echo "FAIL: no window (log $log)"; kill "$pid"; exit 1; }
    rss() { awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status"; }
    # Waits up to 120 s for the title to report a frame traced at W x H.
    traced_at() { # W H
        for _ in $(seq 1 600); do
            xdotool getwindowname "$window" 2>/dev/null | grep -qF "$name - $1x$2 - " && return 0
            kill -0 "$pid" 2>/dev/null || return 1
            sleep 0.2
        done
        return 1
    }
    sizes=("240 180" "160 120")
    baseline="" peak=0 failed=0
    for ((i = 0; i < resizes; i++)); do
        read -r w h <<< "${sizes[i % 2]}"
        xdotool windowsize "$window" "$w" "$h" 2>/dev/null || true
        if ! traced_at "$w" "$h"; then
            echo "FAIL: no frame at ${w}x${h} after resize $((i + 1)) (log $log)"
            failed=1
            break
        fi
        sleep 1 # frames at this size
        now=$(rss)
        if ((i + 1 == warmup)); then
            baseline=$now
            echo "after ${warmup} resizes (warm-up): VmRSS ${baseline} kB"
        elif [[ -n $baseline ]] && ((now > peak)); then
            peak=$now
        fi
    done
    final=$(rss)
    xdotool key --window "$window" q 2>/dev/null || true
    status=0
    for _ in $(seq 1 120); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    if kill -0 "$pid" 2>/dev/null; then kill "$pid"; echo "FAIL: Q did not end the program"; exit 1; fi
    wait "$pid" || status=$?
    if ((failed == 0)); then
        growth=$((peak - baseline))
        echo "soak: ${resizes} resizes, each traced, VmRSS ${baseline} kB after warm-up, peak ${peak} kB," \
             "final ${final} kB (growth ${growth} kB, bound ${RSS_BOUND_KB} kB)"
        ((growth <= RSS_BOUND_KB)) || { echo "FAIL: memory grew by ${growth} kB"; failed=1; }
    fi
    ((status == 0)) || { echo "FAIL: exit status $status (log $log)"; cat "$log"; failed=1; }
    ((failed == 0)) && echo "PASS: soak"
    exit "$failed"
fi

if (($# < 3)); then
    echo "usage: $0 RAYTRACER SCENE OUTPUT_DIR [RESIZES]" >&2
    exit 2
fi
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"
mkdir -p "$3"
resizes=${4:-40}
run_in_xvfb 850 1024x768x24 "$(absolute "$0")" --inside-xvfb "$(absolute "$1")" "$(absolute "$2")" "$(absolute "$3")" "$resizes"
