#!/usr/bin/env bash
# Soak: the window traces every frame (hidden --redraw-continuously) and is resized
# every few seconds, under Xvfb, for SECONDS (default 60). After a warm-up, its resident
# memory (VmRSS) must not grow by more than RSS_BOUND_KB, it must really be rendering
# (CPU time used), and Q must still end it with status 0.
#
# usage: soak_test.sh RAYTRACER SCENE OUTPUT_DIR [SECONDS]
# Needs xvfb-run, xauth, xdotool (tools/build/install_deps.sh).
set -euo pipefail

readonly RSS_BOUND_KB=${RSS_BOUND_KB:-8192} # growth allowed after the warm-up
readonly RESIZE_EVERY=3                      # seconds between resizes

if [[ $# == 5 && $1 == --inside-xvfb ]]; then
    raytracer=$2 scene=$3 output_dir=$4 seconds=$5
    warmup=$((seconds / 4 > 5 ? seconds / 4 : 5))
    log=$output_dir/soak.log
    "$raytracer" "$scene" --window --redraw-continuously --width 160 --height 120 > "$log" 2>&1 &
    pid=$!
    name=$(basename "$scene")
    window=""
    for _ in $(seq 1 120); do # up to 60 s for the first frame
        window=$(xdotool search --name "^$name - " 2>/dev/null | head -n 1 || true)
        [[ -n $window ]] && break
        kill -0 "$pid" 2>/dev/null || { echo "FAIL: the program ended early (log $log)"; cat "$log"; exit 1; }
        sleep 0.5
    done
    [[ -n $window ]] || { echo "FAIL: no window (log $log)"; kill "$pid"; exit 1; }
    rss() { awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status"; }
    cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$pid/stat"; }
    sizes=("160 120" "240 180")
    start=$SECONDS baseline="" peak=0 resizes=0 ticks_at_baseline=0
    while ((SECONDS - start < seconds)); do
        kill -0 "$pid" 2>/dev/null || { echo "FAIL: the program ended during the soak (log $log)"; cat "$log"; exit 1; }
        elapsed=$((SECONDS - start))
        if ((elapsed % RESIZE_EVERY == 0)); then
            xdotool windowsize "$window" ${sizes[resizes % 2]} 2>/dev/null || true
            resizes=$((resizes + 1))
        fi
        now=$(rss)
        if [[ -z $baseline ]] && ((elapsed >= warmup)); then
            baseline=$now ticks_at_baseline=$(cpu_ticks)
            echo "after the ${warmup} s warm-up: VmRSS ${baseline} kB"
        elif [[ -n $baseline ]] && ((now > peak)); then
            peak=$now
        fi
        sleep 1
    done
    final=$(rss) busy=$(( $(cpu_ticks) - ticks_at_baseline )) # clock ticks, 100 per second
    xdotool key --window "$window" q 2>/dev/null || true
    status=0
    for _ in $(seq 1 60); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    if kill -0 "$pid" 2>/dev/null; then kill "$pid"; echo "FAIL: Q did not end the program"; exit 1; fi
    wait "$pid" || status=$?
    growth=$((peak - baseline))
    echo "soak: ${seconds} s, ${resizes} resizes, VmRSS ${baseline} kB after warm-up, peak ${peak} kB," \
         "final ${final} kB (growth ${growth} kB, bound ${RSS_BOUND_KB} kB), CPU $((busy / 100)) s"
    failed=0
    ((status == 0)) || { echo "FAIL: exit status $status (log $log)"; cat "$log"; failed=1; }
    ((growth <= RSS_BOUND_KB)) || { echo "FAIL: memory grew by ${growth} kB"; failed=1; }
    # Continuous tracing keeps a core busy; an idle window would use almost nothing.
    ((busy >= (seconds - warmup) * 100 / 4)) || { echo "FAIL: only $((busy / 100)) s of CPU: not rendering"; failed=1; }
    ((failed == 0)) && echo "PASS: soak"
    exit "$failed"
fi

if (($# < 3)); then
    echo "usage: $0 RAYTRACER SCENE OUTPUT_DIR [SECONDS]" >&2
    exit 2
fi
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"
mkdir -p "$3"
seconds=${4:-60}
run_in_xvfb $((seconds + 120)) 1024x768x24 "$(absolute "$0")" --inside-xvfb "$(absolute "$1")" "$(absolute "$2")" "$(absolute "$3")" "$seconds"
