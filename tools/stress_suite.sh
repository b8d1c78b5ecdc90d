#!/usr/bin/env bash
# Usage: tools/stress_suite.sh [--rounds N] [--lp-threads "1 8"] [--hogs N] [BUILD_DIR]
#
# Runs the built test suite (ctest -j 2, as make test does) again and again on a machine
# made slow and a machine made fast, to show that no test depends on how fast it is:
# ROUNDS rounds (default 3) for each lavapipe thread count of --lp-threads (default
# "1 8": LP_NUM_THREADS=1 is a slow device, 8 more threads than this machine's cores),
# each round with HOGS busy loops beside it (default: one per core), so that every test
# also shares the cores with a load it does not control. Prints one line per round and a
# table; exits 1 if any round failed (its log is kept in BUILD_DIR/stress/).
#   tools/stress_suite.sh build                       3 rounds at 1 and at 8 threads
#   tools/stress_suite.sh --rounds 1 --lp-threads 8   one round at 8 threads
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }

rounds=3 lp_threads="1 8" hogs=$(nproc) build=build
while (($#)); do
    case $1 in
        --rounds) rounds=$2; shift 2 ;;
        --lp-threads) lp_threads=$2; shift 2 ;;
        --hogs) hogs=$2; shift 2 ;;
        -h | --help) usage; exit 0 ;;
        -*) usage >&2; exit 2 ;;
        *) build=$1; shift ;;
    esac
done
[[ $rounds =~ ^[1-9][0-9]*$ && $hogs =~ ^[0-9]+$ ]] || { usage >&2; exit 2; }
[[ -f $build/CTestTestfile.cmake ]] || { echo "stress_suite: $build holds no built suite (make test builds it)" >&2; exit 2; }
build=$(cd "$build" && pwd)
mkdir -p "$build/stress"

hog_pids=()
start_hogs() {
    local i
    for ((i = 0; i < hogs; i++)); do
        bash -c 'while :; do :; done' &
        hog_pids+=($!)
    done
}
stop_hogs() {
    ((${#hog_pids[@]})) && kill "${hog_pids[@]}" 2>/dev/null || true
    hog_pids=()
}
trap stop_hogs EXIT

failed=0
summary=()
for threads in $lp_threads; do
    for ((round = 1; round <= rounds; round++)); do
        log=$build/stress/lp$threads-round$round.log
        start_hogs
        begin=$SECONDS
        status=0
        (cd "$build" && LP_NUM_THREADS=$threads ctest -j 2 --timeout 900 > "$log" 2>&1) || status=$?
        seconds=$((SECONDS - begin))
        stop_hogs
        result=$(grep -E "tests passed|tests failed" "$log" | tail -n 1 || true)
        line="LP_NUM_THREADS=$threads round $round ($hogs busy loops): ${result:-no result} in $seconds s"
        echo "$line"
        summary+=("| $threads | $round | $hogs | ${result:-no result} | $seconds |")
        if ((status != 0)); then
            failed=1
            grep -A 30 "The following tests FAILED" "$log" || true
        fi
    done
done
echo
echo "| LP_NUM_THREADS | round | busy loops | result | seconds |"
echo "|---:|---:|---:|---|---:|"
printf '%s\n' "${summary[@]}"
exit "$failed"
